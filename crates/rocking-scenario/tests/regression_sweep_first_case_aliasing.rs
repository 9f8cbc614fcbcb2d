//! Regression (issue 48, item 6): a valid sweep of more than 10⁶ cases was
//! refused when its fastest axis's first value was invalid. The search for a
//! first case that builds tried every `len/10⁶`-th case, and when that stride
//! was a multiple of the fastest axis's length it never left the invalid
//! value: 10⁶ amplitudes × the frequencies [-1, 2] (stride 2) tried only
//! frequency -1 and refused the sweep with its error. The stride is now
//! coprime with the number of cases, hence with every axis's length.

use rocking_scenario::Sweep;
use std::path::Path;

#[test]
fn a_valid_sweep_whose_fastest_axis_begins_with_an_invalid_value_is_accepted() {
    let church = include_str!("data/church.toml");
    let text = church.to_string()
        + r#"
[ground]
type = "harmonic"
amplitude = 0.5
frequency = 2.0
[sweep]
max_cases = 2000000
"ground.amplitude" = { from = 0.1, to = 0.9, steps = 1000000 }
"ground.frequency" = [-1.0, 2.0]
"#;
    let sweep = Sweep::from_toml_str(&text, Path::new("aliased.toml")).unwrap_or_else(|e| panic!("half the cases are valid: {e}"));
    assert_eq!(sweep.len(), 2_000_000);
    // The first case is the invalid one: the sweep is accepted, and that case's row says why.
    let row = sweep.run_case(0);
    assert!(row.error().is_some_and(|e| e.contains("ground.frequency")), "{row:?}");
}
