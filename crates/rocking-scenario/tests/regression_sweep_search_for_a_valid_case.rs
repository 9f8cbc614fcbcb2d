//! Regression: a sweep whose every case is invalid is refused with the first
//! case's error once no case builds, but the search tried every case: with
//! `max_cases` raised to 10⁹, about two hours without a word. It now tries at
//! most 1,000,000 cases, spread evenly over the sweep (a few seconds).

use rocking_scenario::Sweep;
use std::path::Path;

#[test]
fn a_billion_invalid_cases_are_refused_after_a_bounded_search() {
    // mu_kinetic 2 > mu_static 1.25 in the base: every case fails to build.
    let church = include_str!("data/church.toml");
    assert!(church.contains("mu_static = 1.25\nmu_kinetic = 1.0\n"), "the shared bodies changed: {church}");
    let bodies = church.replace("mu_kinetic = 1.0", "mu_kinetic = 2.0");
    let text = bodies
        + r#"
[ground]
type = "harmonic"
amplitude = 0.5
frequency = 2.0
[sweep]
max_cases = 1000000000
"ground.frequency" = { from = 1.0, to = 9.0, steps = 100000 }
"ground.amplitude" = { from = 0.1, to = 0.9, steps = 10000 }
"#;
    let e = Sweep::from_toml_str(&text, Path::new("billion.toml")).expect_err("no case can run");
    let line = e.to_string();
    assert!(line.starts_with("billion.toml: building.mu_kinetic: 2 exceeds mu_static = 1.25"), "{line}");
}
