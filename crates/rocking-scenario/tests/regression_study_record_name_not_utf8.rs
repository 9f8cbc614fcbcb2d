//! Regression: a record file whose name is not UTF-8 was dropped from a
//! study without a word (the glob crate skips such names). It is now an
//! error naming the file.

#![cfg(target_os = "linux")]

mod support;

use rocking_scenario::Study;
use std::ffi::OsStr;
use std::os::unix::ffi::OsStrExt;

#[test]
fn a_record_whose_name_is_not_utf8_is_named_in_an_error() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("good.AT2"), support::at2(0.3)).expect("good.AT2");
    // "caf\xe9.AT2": Latin-1, not UTF-8.
    let name = OsStr::from_bytes(b"caf\xe9.AT2");
    std::fs::write(dir.path().join(name), support::at2(0.3)).expect("a Latin-1 name");
    let path = dir.path().join("study.toml");
    let e = Study::from_toml_str(&support::study(r#""*.AT2""#, "max_theta_over_alpha", ""), &path).expect_err("the Latin-1 name is refused, not skipped");
    let line = e.to_string();
    assert!(line.contains("study.records"), "{line}");
    assert!(line.contains("caf\u{fffd}.AT2") && line.contains("not UTF-8"), "{line}");
}
