//! Regression (issue "Hardening", the output folder is never a mix): a run
//! into a folder holding an earlier run's figures left them beside the new
//! results; a run that failed while writing left its `summary.json`; a sweep
//! into a run's folder left the run's files beside `sweep.csv`. A run now owns
//! its folder: its files are staged and moved into place at the end, the
//! known files of an earlier run it did not write are removed, and a failure
//! leaves the folder as it was.

use crate::util::{arg, read, rocking, tempdir, write, SCENARIO};
use std::path::Path;

/// The manifest of an output folder: the names its last run wrote.
pub const MANIFEST: &str = ".rocking-manifest";

/// The names in `dir`, sorted, the manifest aside.
pub fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.map(|e| e.file_name().to_string_lossy().into_owned()).unwrap_or_else(|e| panic!("{e}")))
        .filter(|n| n != MANIFEST)
        .collect();
    names.sort();
    names
}

#[test]
fn a_run_without_plot_removes_the_figures_of_an_earlier_run() {
    let dir = tempdir();
    let a = write(dir.path(), "a.toml", SCENARIO);
    let b = write(dir.path(), "b.toml", &SCENARIO.replace("name = \"small\"", "name = \"other\""));
    let out = dir.path().join("out");
    let r = rocking(&["run", arg(&a), "--out", arg(&out), "--plot"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(names(&out).contains(&"theta.svg".to_string()));
    let r = rocking(&["run", arg(&b), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(names(&out), ["events.csv", "history.csv", "summary.json"]);
    assert!(read(&out.join("summary.json")).contains("\"other\""));
}

#[test]
fn a_run_that_fails_while_writing_leaves_the_folder_as_it_was() {
    let dir = tempdir();
    let file = write(dir.path(), "s.toml", SCENARIO);
    let out = dir.path().join("out");
    // history.csv cannot be written: a folder holds its name.
    std::fs::create_dir_all(out.join("history.csv")).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(out.join("notes.txt"), "mine").unwrap_or_else(|e| panic!("{e}"));
    let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("history.csv"), "{r:?}");
    // Nothing of the failed run: no summary.json, no staging folder; the user's file kept.
    assert_eq!(names(&out), ["history.csv", "notes.txt"]);
}

#[test]
fn a_sweep_into_a_run_folder_removes_the_run_files_and_keeps_the_others() {
    let dir = tempdir();
    let file = write(dir.path(), "s.toml", SCENARIO);
    let sweep = write(dir.path(), "sw.toml", &format!("{SCENARIO}\n[sweep]\n\"ground.frequency\" = [4.0, 5.0]\n"));
    let out = dir.path().join("out");
    let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    std::fs::write(out.join("notes.txt"), "mine").unwrap_or_else(|e| panic!("{e}"));
    let r = rocking(&["sweep", arg(&sweep), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(names(&out), ["notes.txt", "sweep.csv"]);
    // Two cases: the header and two rows.
    assert_eq!(read(&out.join("sweep.csv")).lines().count(), 3);
}

#[cfg(unix)]
#[test]
fn ctrl_c_stops_a_run_and_leaves_the_folder_as_it_was() {
    use std::time::Duration;
    let dir = tempdir();
    // 10^6 history rows over 1000 s: far longer than the test waits.
    let text = SCENARIO
        .replace("duration = 1.0", "duration = 1000.0")
        .replace("output_dt = 0.003", "output_dt = 0.001");
    let file = write(dir.path(), "long.toml", &text);
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{e}"));
    std::fs::write(out.join("summary.json"), "earlier").unwrap_or_else(|e| panic!("{e}"));
    // An earlier run's file: its manifest names it.
    std::fs::write(out.join(MANIFEST), "summary.json\n").unwrap_or_else(|e| panic!("{e}"));
    // Interrupted once the history is being written in the staging folder.
    let history = |staging: &Path| std::fs::metadata(staging.join("history.csv")).map_or(0, |m| m.len()) >= 100_000;
    let r = crate::util::interrupted(&["run", arg(&file), "--out", arg(&out)], &out, "-INT", Duration::from_secs(60), history);
    let stderr = r.stderr;
    assert_eq!(r.code, Some(130), "{stderr}");
    assert_eq!(stderr.trim(), "interrupted: nothing written");
    assert_eq!(names(&out), ["summary.json"]);
    assert_eq!(read(&out.join("summary.json")), "earlier");
}
