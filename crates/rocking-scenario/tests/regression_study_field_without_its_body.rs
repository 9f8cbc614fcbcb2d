//! Regression: a building-only study with a limit state on a tower's field
//! reported "0 exceeded, no fit" for a field that no case can have. It is
//! now an error naming the limit state's field; so is a slip without a building.

mod support;

use rocking_scenario::Study;

#[test]
fn a_tower_field_without_a_tower_is_an_error() {
    let dir = tempfile::tempdir().expect("a temporary folder");
    std::fs::write(dir.path().join("a.AT2"), support::at2(0.3)).expect("a.AT2");
    let path = dir.path().join("study.toml");
    let with_tower = support::study(r#""a.AT2""#, "max_theta_over_alpha", "");
    assert!(Study::from_toml_str(&with_tower, &path).is_ok());
    // The same study without [tower].
    let building_only = with_tower.replace("[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n", "");
    let e = Study::from_toml_str(&building_only, &path).expect_err("no tower: no rotation");
    let line = e.to_string();
    assert!(line.contains("study.limit_state[0].field"), "{line}");
    assert!(
        line.contains("\"max_theta_over_alpha\" is a field of the tower") && line.contains("no [tower]"),
        "{line}"
    );
    // A tower on a fixed base has no slip.
    let fixed = support::study(r#""a.AT2""#, "max_abs_slip_m", "").replace("[building]\nmass = 2.0e6\nmu_static = 1.25\nmu_kinetic = 1.0\n", "");
    let e = Study::from_toml_str(&fixed, &path).expect_err("no building: no slip");
    assert!(e.to_string().contains("no [building]"), "{e}");
}
