//! Regression (issue 48, item 2): `assess`, `inventory` and `spectrum`
//! removed every file of `--out` that bore one of the tool's output names,
//! whoever wrote it: `rocking spectrum rec.csv --out DIR` deleted the user's
//! `report.html`, `records.csv` and `inventory.csv`, files it never writes;
//! `rocking assess X.toml --out .` deleted the user's `records.csv`. An output
//! folder now keeps a manifest of the files its last run wrote, and only
//! those are replaced or removed; a user's file under a name the run would
//! write is refused with one line naming it, before the run starts.

use crate::folder::{names, MANIFEST};
use crate::util::{arg, read, rocking, tempdir, write};

/// A user's files under the tool's output names.
const USERS: [&str; 4] = ["report.html", "records.csv", "inventory.csv", "capacity.csv"];

/// A record of 0.3 g held for 0.4 s.
fn step_record(dir: &std::path::Path) -> std::path::PathBuf {
    let rows: String = (0..=80).map(|k| format!("{},0.3\n", 0.005 * k as f64)).collect();
    write(dir, "step.csv", &format!("time,acceleration\n{rows}"))
}

#[test]
fn spectrum_never_touches_the_names_it_does_not_write() {
    let dir = tempdir();
    let record = step_record(dir.path());
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{e}"));
    for name in USERS {
        write(&out, name, "mine");
    }
    // Twice: the second run replaces the first one's spectra.csv, and only it.
    for _ in 0..2 {
        let r = rocking(&["spectrum", arg(&record), "--periods", "0.2,0.5,3", "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{r:?}");
        for name in USERS {
            assert_eq!(read(&out.join(name)), "mine", "{name}");
        }
    }
    assert_eq!(names(&out), ["capacity.csv", "inventory.csv", "records.csv", "report.html", "spectra.csv"]);
    assert!(read(&out.join(MANIFEST)).lines().any(|l| l == "spectra.csv"));
}

#[test]
fn assess_keeps_a_records_csv_it_did_not_write_and_refuses_to_replace_a_report() {
    let dir = tempdir();
    let file = write(dir.path(), "assess.toml", &crate::assess::tower_on_b());
    let out = dir.path().join("out");
    std::fs::create_dir_all(&out).unwrap_or_else(|e| panic!("{e}"));
    write(&out, "records.csv", "mine");
    // No record set: records.csv is not written, and stays.
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(read(&out.join("records.csv")), "mine");
    // A spectrum run into the assessment's folder removes the assessment's
    // files (its manifest's) and keeps the user's.
    let record = step_record(dir.path());
    let r = rocking(&["spectrum", arg(&record), "--periods", "0.2,0.5,3", "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert_eq!(names(&out), ["records.csv", "spectra.csv"]);
    // The user's report.html in a folder no run wrote: refused before the
    // run, one line naming it, nothing written.
    let mine = dir.path().join("mine");
    std::fs::create_dir_all(&mine).unwrap_or_else(|e| panic!("{e}"));
    write(&mine, "report.html", "my report");
    let r = rocking(&["assess", arg(&file), "--out", arg(&mine)]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("report.html") && r.stderr.contains("not written by an earlier run"), "{r:?}");
    assert_eq!(read(&mine.join("report.html")), "my report");
    assert_eq!(names(&mine), ["report.html"]);
}
