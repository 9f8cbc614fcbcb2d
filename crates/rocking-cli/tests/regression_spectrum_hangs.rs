//! Regression (issue 48, item 4): `rocking spectrum three.csv --periods
//! 0.02,1e12,2` never ended, and in `rocking assess` a `period_range = [1e-300,
//! 1e300]` never ended either: the free tail after the record ran `2T/dt`
//! steps, unbounded. Both are now refused at once with one line naming the
//! record, or the key.

use crate::util::{arg, rocking, tempdir, write};

#[test]
fn a_period_far_beyond_the_record_is_refused_with_one_line() {
    let dir = tempdir();
    let record = write(dir.path(), "three.csv", "time,acceleration\n0,0\n0.01,0.3\n0.02,0\n");
    let r = rocking(&["spectrum", arg(&record), "--periods", "0.02,1e12,2", "--out", arg(&dir.path().join("out"))]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("three.csv: periods:") && r.stderr.contains("more than 2e9"), "{r:?}");
}

#[test]
fn an_assessment_period_range_beyond_the_limit_is_refused_naming_the_key() {
    let dir = tempdir();
    crate::assess::synthetic_records(dir.path(), "records");
    let text = crate::assess::tower_on_b() + "records = [\"records/*.AT2\"]\nperiod_range = [1e-300, 1e300]\n";
    let file = write(dir.path(), "assess.toml", &text);
    let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("out"))]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("assessment.period_range"), "{r:?}");
    assert!(!dir.path().join("out").exists());
}
