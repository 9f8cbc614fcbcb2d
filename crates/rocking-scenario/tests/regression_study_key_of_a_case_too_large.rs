//! Regression (issue 48, item 6): a study's key that made its cases
//! impossible was refused under another key's name: `free_after = 1e9` as
//! "simulation.output_dt: 0.01 s over a duration of 1000000031 s gives 1e11
//! history rows", a key the file may not even have; `levels = [1e308]` as
//! "study.records: must be a finite number, got inf". Each is now refused
//! naming the key that is wrong, with what it gives.

mod support;

use rocking_scenario::Study;

fn refusal(text: &str) -> String {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    Study::from_toml_str(text, &dir.path().join("study.toml")).expect_err("refused").to_string()
}

#[test]
fn a_free_after_beyond_the_history_is_refused_as_free_after() {
    let text = support::study(r#""a.AT2""#, "max_theta_over_alpha", "").replace("free_after = 0.1", "free_after = 1e9");
    let line = refusal(&text);
    assert!(line.contains("study.free_after: 1000000000 s after each record"), "{line}");
    assert!(line.contains("history rows"), "{line}");
}

#[test]
fn a_level_no_record_can_be_scaled_to_is_refused_as_levels() {
    let text = support::study(r#""a.AT2""#, "max_theta_over_alpha", "").replace("levels = [0.2, 0.4]", "levels = [1e308]");
    let line = refusal(&text);
    // The record's PGA is 0.3 g: 1e308 / 0.3 overflows.
    assert!(line.contains("study.levels: 1e308 over the pga 0.3"), "{line}");
    assert!(line.contains("a scale of inf"), "{line}");
}
