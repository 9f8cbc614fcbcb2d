//! Regression: studies had no cap on their number of cases (records × levels),
//! as sweeps have: a study of a million levels started without a word. Above
//! `max_cases` (default 1,000,000, as a sweep's) it is refused before a record
//! is read, and `max_cases` in [study] raises the cap knowingly.

mod support;

use rocking_scenario::{Study, DEFAULT_MAX_CASES};

#[test]
fn a_study_beyond_its_cap_is_refused_before_anything_is_read() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    std::fs::write(dir.path().join("b.AT2"), support::at2(0.5)).expect("b.AT2");
    let path = dir.path().join("study.toml");
    // 2 records × 600,000 levels = 1,200,000 cases.
    let many = support::study(r#""*.AT2""#, "max_theta_over_alpha", "").replace("levels = [0.2, 0.4]", "levels = { from = 0.1, to = 2.0, steps = 600000 }");
    let e = Study::from_toml_str(&many, &path).expect_err("over the cap");
    let line = e.to_string();
    assert!(line.contains(&format!("make 1200000 cases, more than {DEFAULT_MAX_CASES}")), "{line}");
    assert!(line.contains("max_cases = 1200000"), "{line}");
    // Raised knowingly: the study is made (its cases are not run here).
    let raised = many.replace("free_after = 0.1", "free_after = 0.1\nmax_cases = 1200000");
    assert_eq!(Study::from_toml_str(&raised, &path).expect("within the raised cap").len(), 1_200_000);
    // Lowered: two records × two levels are over a cap of 3.
    let low = support::study(r#""*.AT2""#, "max_theta_over_alpha", "max_cases = 3");
    assert!(Study::from_toml_str(&low, &path).expect_err("over 3").to_string().contains("more than 3"));
}
