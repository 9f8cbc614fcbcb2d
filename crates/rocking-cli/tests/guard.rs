//! The output never overwrites an input: not the scenario, not the record.

use crate::util::{arg, read, rocking, tempdir, write, SCENARIO};

#[test]
fn the_scenario_is_never_overwritten() {
    let dir = tempdir();
    // A scenario saved under the name of an output file, in the output folder.
    let file = write(dir.path(), "summary.json", SCENARIO);
    let r = rocking(&["run", arg(&file), "--out", arg(dir.path())]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("refusing to write"), "{r:?}");
    assert_eq!(read(&file), SCENARIO, "the scenario was changed");
    assert!(!dir.path().join("history.csv").exists(), "outputs were written anyway");
}

#[test]
fn the_scenario_is_protected_under_another_spelling_of_its_path() {
    let dir = tempdir();
    let sub = dir.path().join("sub");
    std::fs::create_dir(&sub).unwrap_or_else(|e| panic!("{e}"));
    let file = write(dir.path(), "history.csv", SCENARIO);
    // --out sub/.. is the scenario's own folder.
    let r = rocking(&["run", arg(&file), "--out", arg(&sub.join(".."))]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(read(&file), SCENARIO);
}

#[test]
fn the_record_is_never_overwritten() {
    let dir = tempdir();
    let record = "time,acceleration\n0.0,0.0\n0.1,0.5\n0.2,0.0\n";
    write(dir.path(), "events.csv", record);
    let text = SCENARIO.split("[ground]").next().unwrap_or_default().to_string() + "[ground]\ntype = \"record\"\nfile = \"events.csv\"\n";
    let file = write(dir.path(), "s.toml", &text);
    let r = rocking(&["run", arg(&file), "--out", arg(dir.path())]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("refusing to write") && r.stderr.contains("events.csv"), "{r:?}");
    assert_eq!(read(&dir.path().join("events.csv")), record);
    // Elsewhere it runs.
    let r = rocking(&["run", arg(&file), "--out", arg(&dir.path().join("o"))]);
    assert_eq!(r.code, Some(0), "{r:?}");
}
