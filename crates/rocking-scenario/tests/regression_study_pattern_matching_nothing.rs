//! Regression: a study's record pattern that matched nothing was ignored
//! without a word when another pattern matched (a typo lost a part of the
//! suite). Each pattern must now match a file.

mod support;

use rocking_scenario::Study;

#[test]
fn a_pattern_that_matches_nothing_among_others_is_an_error() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    let path = dir.path().join("study.toml");
    let e = Study::from_toml_str(&support::study(r#""a.AT2", "recrods/*.AT2""#, "max_theta_over_alpha", ""), &path)
        .expect_err("the second pattern matches nothing");
    let line = e.to_string();
    assert!(line.contains("study.records[1]"), "{line}");
    assert!(line.contains("no file matches \"recrods/*.AT2\""), "{line}");
    // Each alone: the first is a study, the second the same error under its own key.
    assert!(Study::from_toml_str(&support::study(r#""a.AT2""#, "max_theta_over_alpha", ""), &path).is_ok());
}
