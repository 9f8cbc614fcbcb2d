//! Both principal directions (issue 46, item 5): a tower 5 m wide and 3 m
//! deep was assessed rocking across its width alone, ζ_E of one direction
//! with no word of the other. It is now assessed in both, and the verdict is
//! the worse. Checked against a second computation: the assessment of the
//! same tower written 3 m wide and 5 m deep, whose checks the turned
//! direction's must equal exactly (the same arithmetic on the same numbers),
//! and the capacities by hand: α0 = b/h = 2.5/6 and 1.5/6.

use approx::assert_relative_eq;
use rocking_assess::{Assessment, AssessmentInput, Direction};
use std::path::Path;

const FIXTURE: &str = include_str!("data/tower_on_b.toml");

fn assess(width: f64, depth: f64) -> (AssessmentInput, Assessment) {
    let text = FIXTURE.replace("width = 4.0\n", &format!("width = {width:?}\ndepth = {depth:?}\n"));
    let input = AssessmentInput::from_toml_str(&text, Path::new("tower.toml")).unwrap_or_else(|e| panic!("{e}"));
    let done = Assessment::run(&input).unwrap_or_else(|e| panic!("{e}"));
    (input, done)
}

#[test]
fn a_tower_deeper_one_way_is_checked_both_ways_and_the_worse_governs() {
    let (input, done) = assess(5.0, 3.0);
    let turned = done.turned.as_deref().unwrap_or_else(|| panic!("no other direction"));
    assert_eq!((done.direction, turned.direction), (Direction::Width, Direction::Depth));
    // b/h by hand: 2.5/6 across the width, 1.5/6 across the depth.
    assert_relative_eq!(done.capacity.alpha0, 2.5 / 6.0, max_relative = 1e-14);
    assert_relative_eq!(turned.capacity.alpha0, 1.5 / 6.0, max_relative = 1e-14);
    // The turned direction is the tower written 3 m wide and 5 m deep, check by check.
    let (_, written) = assess(3.0, 5.0);
    let zetas = |a: &Assessment| a.checks.iter().map(|c| (c.limit_state, c.method, c.zeta_e)).collect::<Vec<_>>();
    assert_eq!(zetas(turned), zetas(&written));
    // The verdict is the worse of the two: the slenderer direction's, and said so.
    let (m, v) = done.governing_verdict().unwrap_or_else(|| panic!("no verdict"));
    let width_only = done.mechanisms()[0].verdict(done.verdict_method).map(|v| v.check.zeta_e).unwrap_or(f64::NAN);
    let depth_only = turned.mechanisms()[0]
        .verdict(turned.verdict_method)
        .map(|v| v.check.zeta_e)
        .unwrap_or(f64::NAN);
    assert!(depth_only < width_only, "{depth_only} {width_only}");
    assert_eq!(m.direction, Direction::Depth);
    assert_eq!(v.check.zeta_e.to_bits(), depth_only.to_bits());
    let json = done.json(&input);
    assert_eq!(json["direction"], "width");
    assert_eq!(json["governing"]["direction"], "depth");
    assert_eq!(json["governing"]["zeta_E"].as_f64(), Some(depth_only));
    assert_eq!(json["other_direction"]["capacity"]["alpha0"].as_f64(), Some(turned.capacity.alpha0));
}

#[test]
fn a_square_tower_has_one_direction_and_its_outputs_as_before() {
    let (input, done) = assess(4.0, 4.0);
    assert!(done.turned.is_none());
    let json = done.json(&input);
    assert!(json.get("direction").is_none() && json.get("other_direction").is_none(), "{json}");
}
