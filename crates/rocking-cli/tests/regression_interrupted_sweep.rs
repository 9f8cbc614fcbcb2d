//! Regression: the first Ctrl-C of `rocking sweep` stopped no case under way:
//! the sweep went on until they ended (minutes for a long case), and a second
//! Ctrl-C exited 130 leaving its `.rocking-partial-…` folder; SIGTERM left the
//! folder too. The first SIGINT or SIGTERM now stops the cases under way at
//! their next event: the sweep exits 130 at once with the rows finished
//! (none here), and no staging folder is left.

use crate::util::{arg, read, staging_folder, tempdir, write};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// A building sliding under 1.5 g (μs = 1.25) for 150,000 s: two slip events
/// a cycle, tens of seconds of computing a case; four of them.
const LONG: &str = r#"
name = "long"
[building]
mass = 2.0e6
mu_static = 1.25
mu_kinetic = 1.0
[ground]
type = "harmonic"
amplitude = 1.5
frequency = 5.0
[simulation]
duration = 150000.0
output_dt = 0.1
[sweep]
"ground.frequency" = [4.0, 4.5, 5.0, 5.5]
"#;

/// Longest wait for the process to end after the signal: a case it did not
/// stop would run far longer.
const LIMIT: Duration = Duration::from_secs(60);

#[cfg(unix)]
fn interrupted_by(signal: &str) {
    let dir = tempdir();
    let file = write(dir.path(), "long.toml", LONG);
    let out = dir.path().join("out");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args(["sweep", arg(&file), "--out", arg(&out), "--threads", "2"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("{e}"));
    // The header is written when the cases start.
    let partial = staging_folder(&out, LIMIT).expect("no staging folder").join("sweep.csv");
    let start = Instant::now();
    while std::fs::metadata(&partial).map_or(true, |m| m.len() == 0) && start.elapsed() < LIMIT {
        std::thread::sleep(Duration::from_millis(20));
    }
    let kill = Command::new("kill").args([signal, &child.id().to_string()]).status();
    assert!(kill.is_ok_and(|s| s.success()), "cannot send {signal}");
    let start = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().unwrap_or_else(|e| panic!("{e}")) {
            break status;
        }
        if start.elapsed() > LIMIT {
            child.kill().unwrap_or_default();
            panic!("{signal}: the sweep did not stop its cases");
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let mut stderr = String::new();
    if let Some(mut pipe) = child.stderr.take() {
        std::io::Read::read_to_string(&mut pipe, &mut stderr).unwrap_or_default();
    }
    assert_eq!(status.code(), Some(130), "{signal}: {stderr}");
    // No case could have ended: the rows finished are none, the file its header.
    assert!(stderr.starts_with("interrupted: wrote 0 of 4 cases"), "{signal}: {stderr}");
    assert_eq!(read(&out.join("sweep.csv")).lines().count(), 1);
    assert!(!partial.exists(), "{signal}: the staging folder is left");
    assert_eq!(crate::folder::names(&out), ["sweep.csv"], "{signal}");
}

#[cfg(unix)]
#[test]
fn the_first_ctrl_c_stops_the_cases_under_way() {
    interrupted_by("-INT");
}

#[cfg(unix)]
#[test]
fn sigterm_stops_the_sweep_and_leaves_no_staging_folder() {
    interrupted_by("-TERM");
}
