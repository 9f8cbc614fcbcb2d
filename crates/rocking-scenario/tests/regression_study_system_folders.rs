//! Regression: `records = ["/proc/**/*.AT2"]` never returned (the walk of
//! /proc follows /proc/self/root back to / and on). /proc and /sys are never
//! walked: a pattern in them is an error at once, and a link into them from a
//! records folder is not followed.

#![cfg(target_os = "linux")]

mod support;

use rocking_scenario::Study;

#[test]
fn a_pattern_in_proc_or_sys_is_refused_at_once() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    let path = dir.path().join("study.toml");
    for (pattern, folder) in [("/proc/**/*.AT2", "/proc"), ("/sys/*/*.AT2", "/sys")] {
        let e =
            Study::from_toml_str(&support::study(&format!("\"{pattern}\""), "max_theta_over_alpha", ""), &path).expect_err("a system folder holds no records");
        let line = e.to_string();
        assert!(line.contains("study.records: ") && line.contains(&format!("searches {folder}")), "{line}");
    }
}

#[test]
fn a_link_into_proc_is_not_followed() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    std::os::unix::fs::symlink("/proc", dir.path().join("proc")).expect("a link");
    let path = dir.path().join("study.toml");
    let study = Study::from_toml_str(&support::study(r#""**/*.AT2""#, "max_theta_over_alpha", ""), &path).expect("a study");
    assert_eq!(study.records().len(), 1);
}
