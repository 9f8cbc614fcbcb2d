//! Regression: a study's glob through a cycle of symbolic links counted the
//! same record 82 times (the glob followed the cycle until the paths grew too
//! long), though a file matched twice is kept once. Records are now told
//! apart by their canonical path, and a cycle is walked once.

#![cfg(unix)]

mod support;

use rocking_scenario::Study;

#[test]
fn a_record_reached_through_links_is_one_record() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let records = dir.path().join("records");
    std::fs::create_dir_all(&records).expect("records/");
    std::fs::write(records.join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    std::fs::write(records.join("b.AT2"), support::at2(0.5)).expect("b.AT2");
    // records/loop -> records: records/loop/loop/…/a.AT2 is a.AT2.
    std::os::unix::fs::symlink(&records, records.join("loop")).expect("a link");
    // And a second name for b.AT2.
    std::os::unix::fs::symlink(records.join("b.AT2"), records.join("c.AT2")).expect("a link");
    let path = dir.path().join("study.toml");
    let text = support::study(r#""records/**/*.AT2", "records/a.AT2""#, "max_theta_over_alpha", "");
    let study = Study::from_toml_str(&text, &path).expect("the study is valid");
    let names: Vec<&str> = study.records().iter().map(|r| r.path.as_str()).collect();
    assert_eq!(names, ["records/a.AT2", "records/b.AT2"]);
    // Two records × two levels.
    assert_eq!(study.len(), 4);
}
