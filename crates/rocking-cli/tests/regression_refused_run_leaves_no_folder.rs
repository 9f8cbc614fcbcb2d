//! Regression: a run refused after its output folder was made left that folder
//! behind, empty: `rocking assess` whose record set holds an empty record (or
//! one with a NaN), read only once the assessment starts; `rocking run` whose
//! vertical motion exceeds gravity, found only by the run; `rocking merge`
//! with a truncated shard; and a second Ctrl-C, which ends the process at
//! once. The output folder a run creates, and any parent it
//! had to create, are now removed again when it fails (if still empty); a
//! folder that was there before is left as it was, with its files.

use crate::assess::{synthetic_records, tower_on_b};
use crate::shard::{shard, sweep_file};
use crate::util::{arg, merge, read, rocking, tempdir, write, Output};
use std::path::Path;

/// The one line of a refused run: exit code 1, no panic, naming each of `needles`.
fn refused(r: &Output, needles: &[&str]) {
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.trim_end().lines().count(), 1, "one line: {:?}", r.stderr);
    assert!(!r.stderr.contains("panicked"), "{}", r.stderr);
    for n in needles {
        assert!(r.stderr.contains(n), "{n:?} not in {:?}", r.stderr);
    }
}

/// The names in `dir`, sorted.
fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.unwrap_or_else(|e| panic!("{e}")).file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn a_refused_assessment_leaves_no_output_folder() {
    let dir = tempdir();
    synthetic_records(dir.path(), "records");
    let text = tower_on_b() + "records = [\"records/*.AT2\"]\nlambda = { from = 0.5, to = 1.0, step = 0.5 }\n";
    let file = write(dir.path(), "assess.toml", &text);
    // Each bad record: an empty file, and kt_01 with a NaN on its first line of values.
    let kt_01 = read(&dir.path().join("records/kt_01.AT2"));
    let mut lines: Vec<String> = kt_01.lines().map(String::from).collect();
    let first = lines[4]
        .split_whitespace()
        .next()
        .unwrap_or_else(|| panic!("kt_01.AT2 has no values"))
        .to_string();
    lines[4] = lines[4].replacen(&first, "NaN", 1);
    let with_nan = lines.join("\n") + "\n";
    for (name, text, needle) in [
        ("empty.AT2", String::new(), "records/empty.AT2"),
        ("nan.AT2", with_nan, "\"NaN\" is not a number"),
    ] {
        let bad = write(dir.path(), &format!("records/{name}"), &text);
        // A folder two levels deep, neither level there before.
        let out = dir.path().join("new/out");
        let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
        refused(&r, &["assess.toml", "assessment.records", needle]);
        assert!(!dir.path().join("new").exists(), "{name}: {:?}", names(dir.path()));

        // A folder of the user's: kept, with its file and nothing else.
        let mine = dir.path().join("mine");
        std::fs::create_dir_all(&mine).unwrap_or_else(|e| panic!("{e}"));
        write(&mine, "notes.txt", "mine\n");
        refused(&rocking(&["assess", arg(&file), "--out", arg(&mine)]), &[needle]);
        assert_eq!(names(&mine), ["notes.txt"]);
        assert_eq!(read(&mine.join("notes.txt")), "mine\n");
        std::fs::remove_file(bad).unwrap_or_else(|e| panic!("{e}"));
    }
    // The same file with the good records only: the folder is made and filled.
    let out = dir.path().join("new/out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(out.join("records.csv").is_file());
}

#[test]
fn a_run_refused_by_its_motion_leaves_no_output_folder() {
    let dir = tempdir();
    // A vertical motion of 1.5 g amplitude: g + a_v reaches 0 at the first
    // time sin(2π f t) = −1/1.5 (t = 0.308 s at 2 Hz), found by the run only.
    let scenario = write(
        dir.path(),
        "lift.toml",
        "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n\n\
         [ground]\ntype = \"harmonic\"\namplitude = 0.8\nfrequency = 2.0\nduration = 6.0\n\n\
         [ground.vertical]\ntype = \"harmonic\"\namplitude = 1.5\nfrequency = 2.0\nduration = 6.0\n",
    );
    let out = dir.path().join("out");
    refused(
        &rocking(&["run", arg(&scenario), "--out", arg(&out)]),
        &["lift.toml", "ground.vertical", "g + a_v <= 0"],
    );
    assert!(!out.exists(), "{:?}", names(dir.path()));
}

#[test]
fn a_refused_merge_leaves_no_output_folder() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "");
    let parts = dir.path().join("parts");
    let (one, two) = (shard(&file, &parts, 1, 2), shard(&file, &parts, 2, 2));
    // The second shard's rows cut in the middle of its last line.
    let rows = read(&two.join("sweep.csv"));
    write(&two, "sweep.csv", &rows[..rows.len() - 3]);
    let out = dir.path().join("merged");
    refused(&merge(&[&one, &two], &out), &["sweep.csv", "truncated"]);
    assert!(!out.exists(), "{:?}", names(dir.path()));
}

/// A second signal ends the process at once: its staging folder was removed,
/// the output folder it had made was left, empty. Both go now. Told without
/// a clock: the sweep is stopped (SIGSTOP) while SIGINT and SIGTERM are sent,
/// so that both are pending when it goes on (SIGCONT) and its handler reads
/// them one after the other, before the cases the first one stops can end.
#[cfg(unix)]
#[test]
fn a_second_signal_leaves_no_output_folder() {
    use std::process::{Command, Stdio};
    use std::time::Duration;
    let dir = tempdir();
    let file = write(dir.path(), "long.toml", crate::regression_interrupted_sweep::LONG);
    let out = dir.path().join("new/out");
    let mut child = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args(["sweep", arg(&file), "--out", arg(&out), "--threads", "2"])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap_or_else(|e| panic!("cannot start rocking: {e}"));
    let limit = Duration::from_secs(60);
    assert!(crate::util::staging_folder(&out, limit).is_some(), "no staging folder in {limit:?}");
    for signal in ["-STOP", "-INT", "-TERM", "-CONT"] {
        let kill = Command::new("kill").args([signal, &child.id().to_string()]).status();
        assert!(kill.is_ok_and(|s| s.success()), "cannot send {signal}");
    }
    let (code, stderr) = crate::util::wait_exit(&mut child, limit, "SIGINT and SIGTERM");
    // The status of the first signal: pending signals are delivered lowest number first (SIGINT, 2).
    assert_eq!(code, Some(130), "{stderr}");
    assert!(stderr.contains("interrupted twice: stopping now, nothing written"), "{stderr}");
    assert!(!dir.path().join("new").exists(), "{:?}", names(dir.path()));
}
