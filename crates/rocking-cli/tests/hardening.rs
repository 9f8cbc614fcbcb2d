//! Issue 15, the input half: inputs that hung, or that were refused under a
//! key the user never wrote. Each case ends within a time limit with exit 1
//! and one line naming the key the user wrote and the real cause.
//!
//! Before the fixes: the tolerances, `g = 1e300`, the record of 1e300 g and
//! `/dev/urandom` looped (the stepper lifted every rejected step back to its
//! minimum, and the whole device was read); `frequency = 1e12` took 57 s;
//! `tower.mass = 1e308` and extreme widths blamed `tower.inertia_pivot`;
//! `atol = 1e300` with the constant normal force blamed Painlevé's paradox.

use crate::util::{scenario_with, tempdir, write};
use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

/// Generous bound on a run that must end: the real ones take well under a
/// second; a loop would never end, so the exact value does not matter.
const LIMIT: Duration = Duration::from_secs(60);

/// Runs `rocking command file` in `dir`, killed after [`LIMIT`]: the exit
/// code (`None` when killed) and stderr.
fn run_limited(dir: &Path, command: &str, file: &Path) -> (Option<i32>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args([command, file.to_str().unwrap_or_default()])
        .current_dir(dir)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start rocking: {e}"));
    let start = Instant::now();
    loop {
        if let Some(status) = child.try_wait().unwrap_or(None) {
            let mut stderr = String::new();
            if let Some(mut pipe) = child.stderr.take() {
                std::io::Read::read_to_string(&mut pipe, &mut stderr).unwrap_or_default();
            }
            return (status.code(), stderr);
        }
        if start.elapsed() > LIMIT {
            child.kill().unwrap_or_default();
            child.wait().unwrap_or_else(|e| panic!("{e}"));
            return (None, String::new());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
}

/// `run` and `check` of `text` must both end with exit 1 and one line
/// containing every one of `needles` and none of `absent`.
fn refused(text: &str, needles: &[&str], absent: &[&str]) {
    let dir = tempdir();
    write(dir.path(), "high.AT2", &at2_of(1.0e300));
    let file = write(dir.path(), "case.toml", text);
    for command in ["check", "run"] {
        let (code, stderr) = run_limited(dir.path(), command, &file);
        let context = format!("rocking {command}: {code:?} {stderr}");
        assert_eq!(code, Some(1), "{context}");
        assert_eq!(stderr.lines().count(), 1, "{context}");
        for needle in needles {
            assert!(stderr.contains(needle), "{needle:?} missing: {context}");
        }
        for word in absent {
            assert!(!stderr.contains(word), "{word:?} present: {context}");
        }
    }
}

/// A PEER AT2 file of 10 samples every 0.01 s, all equal to `value` (in g).
fn at2_of(value: f64) -> String {
    let values = vec![format!("{value:.7E}"); 10].join("  ");
    format!("TEST\ntest\nACCELERATION TIME SERIES IN UNITS OF G\nNPTS=   10, DT=   .0100 SEC,\n  {values}\n")
}

fn with_simulation(extra: &str) -> String {
    scenario_with("[simulation]\n", &format!("[simulation]\n{extra}\n"))
}

#[test]
fn unreachable_tolerances_are_refused_by_name() {
    for (tolerances, key) in [
        ("rtol = 1e-300\natol = 1e-300", "simulation.rtol"),
        ("rtol = 1e-8\natol = 1e-100", "simulation.atol"),
        ("rtol = 1e-20\natol = 1e-30", "simulation.rtol"),
    ] {
        refused(&with_simulation(tolerances), &[key, "must be between"], &[]);
    }
}

#[test]
fn a_tolerance_too_loose_for_an_answer_is_refused() {
    refused(&with_simulation("rtol = 1"), &["simulation.rtol", "must be between"], &[]);
}

#[test]
fn huge_absolute_tolerance_does_not_blame_painleve() {
    refused(&with_simulation("atol = 1e300"), &["simulation.atol"], &["Painlev"]);
}

#[test]
fn absurd_gravity_is_refused() {
    refused(&with_simulation("g = 1e300"), &["simulation.g", "at most"], &[]);
}

#[test]
fn a_million_cycles_of_shaking_is_refused_at_once() {
    refused(&scenario_with("frequency = 5.0", "frequency = 1e12"), &["ground.frequency", "cycles"], &[]);
}

#[test]
fn a_record_of_1e300_g_is_refused() {
    let text = scenario_with(
        "type = \"harmonic\"\namplitude = 0.6\nfrequency = 5.0\n",
        "type = \"record\"\nfile = \"high.AT2\"\n",
    );
    // `check` does not read the record: only `run` can see its values.
    let dir = tempdir();
    write(dir.path(), "high.AT2", &at2_of(1.0e300));
    let file = write(dir.path(), "case.toml", &text);
    let (code, stderr) = run_limited(dir.path(), "run", &file);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("ground.file") && stderr.contains("above 100 g"), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
}

#[cfg(unix)]
#[test]
fn a_device_is_not_read_as_a_record() {
    let text = scenario_with(
        "type = \"harmonic\"\namplitude = 0.6\nfrequency = 5.0\n",
        "type = \"record\"\nfile = \"/dev/urandom\"\nformat = \"csv\"\ndt = 0.01\n",
    );
    let dir = tempdir();
    let file = write(dir.path(), "case.toml", &text);
    let (code, stderr) = run_limited(dir.path(), "run", &file);
    assert_eq!(code, Some(1), "{stderr}");
    assert!(stderr.contains("/dev/urandom") && stderr.contains("not a regular file"), "{stderr}");
}

#[test]
fn out_of_scale_dimensions_are_named_not_the_inertia() {
    for (from, to, key) in [
        ("mass = 1.5e5", "mass = 1e308", "tower.mass"),
        ("width = 4.0", "width = 1e300", "tower.width"),
        ("width = 4.0", "width = 1e-300", "tower.width"),
        ("height = 12.0", "height = 1e300", "tower.height"),
        ("height = 12.0", "height = 1e-300", "tower.height"),
    ] {
        refused(&scenario_with(from, to), &[key, "must be between"], &["inertia_pivot"]);
    }
}

/// A scenario `name` with a control character, `&` and `<` made theta.svg
/// invalid XML (XML 1.0 allows no control character but tab and line ends,
/// escaped or not). Every byte of every figure must now be allowed, and the
/// markup characters must arrive escaped.
#[test]
fn names_are_escaped_in_every_figure() {
    let text = scenario_with("name = \"small\"", "name = \"bell \\u0001 tower & <church>\"");
    let dir = tempdir();
    let file = write(dir.path(), "named.toml", &text);
    let out = dir.path().join("out");
    let r = crate::util::rocking_in(
        dir.path(),
        &["run", file.to_str().unwrap_or_default(), "--out", out.to_str().unwrap_or_default(), "--plot"],
    );
    assert_eq!(r.code, Some(0), "{r:?}");
    let mut figures = 0;
    for entry in std::fs::read_dir(&out).unwrap_or_else(|e| panic!("{e}")) {
        let path = entry.unwrap_or_else(|e| panic!("{e}")).path();
        if path.extension().is_some_and(|e| e == "svg") {
            figures += 1;
            let svg = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{e}"));
            let bad = svg.chars().find(|&c| c.is_control() && !matches!(c, '\t' | '\n' | '\r'));
            assert_eq!(bad, None, "{} holds a control character", path.display());
            assert!(svg.contains("tower &amp; &lt;church&gt;"), "{} lacks the escaped name", path.display());
        }
    }
    assert!(figures >= 2, "theta.svg and slip.svg expected, found {figures} figures");
}

/// A sweep of 1e9 cases started without a word (230 GB of CSV), and one whose
/// every case was invalid tried its 1e9 cases one by one before failing. The
/// total is now capped before any case is parsed, and the message says how
/// to lift the cap knowingly.
#[test]
fn a_sweep_beyond_the_case_cap_is_refused_at_once() {
    let text = scenario_with(
        "[simulation]\n",
        "[sweep]\n\"tower.width\" = { from = -2, to = -1, steps = 1000000 }\n\"ground.frequency\" = { from = 1, to = 10, steps = 1000 }\n\n[simulation]\n",
    );
    let dir = tempdir();
    let file = write(dir.path(), "huge.toml", &text);
    let (code, stderr) = run_limited(dir.path(), "sweep", &file);
    assert_eq!(code, Some(1), "{stderr}");
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert!(stderr.contains("1000000 × 1000 values make 1000000000 cases, more than 1000000"), "{stderr}");
    assert!(stderr.contains("max_cases = 1000000000"), "{stderr}");
}

/// `max_cases` lifts the cap: the same grid, small, under a cap of its size
/// runs; one case fewer is refused.
#[test]
fn max_cases_lifts_the_cap_knowingly() {
    for (cap, code) in [(6, 0), (5, 1)] {
        let text = scenario_with(
            "[simulation]\n",
            &format!("[sweep]\nmax_cases = {cap}\n\"ground.frequency\" = [4.0, 5.0, 6.0]\n\"ground.amplitude\" = [0.5, 0.6]\n\n[simulation]\n"),
        );
        let dir = tempdir();
        let file = write(dir.path(), "capped.toml", &text);
        let (got, stderr) = run_limited(dir.path(), "sweep", &file);
        assert_eq!(got, Some(code), "max_cases = {cap}: {stderr}");
    }
}
