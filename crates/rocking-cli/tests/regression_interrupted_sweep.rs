//! Regression: the first Ctrl-C of `rocking sweep` stopped no case under way:
//! the sweep went on until they ended (minutes for a long case), and a second
//! Ctrl-C exited 130 leaving its `.rocking-partial-…` folder; SIGTERM left the
//! folder too. The first SIGINT or SIGTERM now stops the cases under way at
//! their next event: the sweep exits 130 at once with the rows finished
//! (none here), and no staging folder is left.

use crate::util::{arg, interrupted, read, tempdir, write};
use std::path::Path;
use std::time::Duration;

/// A building sliding under 1.5 g (μs = 1.25) for 150,000 s: two slip events
/// a cycle, tens of seconds of computing a case; four of them.
pub const LONG: &str = r#"
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
fn interrupted_by(signal: &str, status: i32) {
    let dir = tempdir();
    let file = write(dir.path(), "long.toml", LONG);
    let out = dir.path().join("out");
    // Interrupted once the header is written, when the cases start.
    let header = |staging: &Path| std::fs::metadata(staging.join("sweep.csv")).is_ok_and(|m| m.len() > 0);
    let r = interrupted(&["sweep", arg(&file), "--out", arg(&out), "--threads", "2"], &out, signal, LIMIT, header);
    let (stderr, partial) = (r.stderr, r.staging.join("sweep.csv"));
    // 128 plus the signal's number, as a shell reports a process that signal ended.
    assert_eq!(r.code, Some(status), "{signal}: {stderr}");
    // No case could have ended: the rows finished are none, the file its header.
    assert!(stderr.starts_with("interrupted: wrote 0 of 4 cases"), "{signal}: {stderr}");
    assert_eq!(read(&out.join("sweep.csv")).lines().count(), 1);
    assert!(!partial.exists(), "{signal}: the staging folder is left");
    assert_eq!(crate::folder::names(&out), ["sweep.csv"], "{signal}");
}

#[cfg(unix)]
#[test]
fn the_first_ctrl_c_stops_the_cases_under_way() {
    interrupted_by("-INT", 130);
}

#[cfg(unix)]
#[test]
fn sigterm_stops_the_sweep_and_leaves_no_staging_folder() {
    interrupted_by("-TERM", 143);
}
