//! Regression: an assessment file of valid but extreme numbers was assessed
//! into numbers that are not numbers. Each key was in its range (> 0, finite),
//! but their products left the floating-point range: `simulation.g = 5e-324`
//! made a0* = α0 g / FC vanish and the secant periods infinite; an `ag` of
//! 5e-324 g made ζ_E = a_g,capacity / a_g infinite; `q = 1.7e308` made the
//! linear check's capacity q · a_g,capacity(SLD) and its ζ_E overflow; `F0 =
//! 1.7e308` made the non-linear check's demand infinite. `assessment.json`
//! wrote them as `null`, the check "held". Each is now refused with one line
//! naming the file and the key at fault (found by the extremes of each key,
//! tried beside fuzzing the assessment file, whose target asks for finite numbers).

use rocking_assess::{Assessment, AssessmentInput};
use std::path::Path;

/// The error of the tests' tower (tests/data/tower_on_b.toml) with `from` replaced by `to`.
fn refused(from: &str, to: &str) -> String {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap_or_else(|e| panic!("{e}"));
    let text = file.replacen(from, to, 1);
    assert_ne!(text, file, "tower_on_b.toml has no {from}");
    match AssessmentInput::from_toml_str(&text, Path::new("assess.toml")).and_then(|input| Assessment::run(&input)) {
        Ok(done) => panic!("{to} should be refused, got {:?}", done.checks),
        Err(e) => e.to_string(),
    }
}

#[test]
fn a_gravity_whose_capacity_vanishes_is_refused() {
    // α0 g / FC = (1/3)(5e-324)/1.35 rounds to 0: no activation, infinite periods.
    let e = refused("[tower]", "[simulation]\ng = 5e-324\n\n[tower]");
    assert!(e.starts_with("assess.toml: tower: capacity: out of the floating-point range"), "{e}");
    assert!(e.contains("a0* = 0.0 m/s²") && e.contains("T_SLV = inf s"), "{e}");
}

#[test]
fn an_ag_whose_ratio_overflows_is_refused() {
    // The SLD's activation capacity is 0.207 g (the unchanged tower), over 5e-324 g: ζ_E = ∞.
    let e = refused("ag = 0.062", "ag = 5e-324");
    assert!(
        e.starts_with("assess.toml: site.SLD.ag: the SLD activation check leaves the floating-point range"),
        "{e}"
    );
    assert!(e.contains("ζ_E inf, at ag = 5e-324 g"), "{e}");
    let e = refused("ag = 0.155", "ag = 5e-324");
    assert!(e.starts_with("assess.toml: site.SLV.ag: the SLV linear_kinematic check"), "{e}");
}

#[test]
fn a_q_whose_capacity_overflows_is_refused() {
    // q times 0.207 g over 0.155 g exceeds the largest double: q's fault, as q = 1 would be finite.
    let e = refused("q = 2.0", "q = 1.7e308");
    assert!(
        e.starts_with("assess.toml: assessment.q: the SLV linear_kinematic check leaves the floating-point range"),
        "{e}"
    );
    assert!(e.ends_with("ζ_E inf, at ag = 0.155 g (q = 1.7e308)"), "{e}");
}

#[test]
fn an_f0_whose_demand_overflows_is_refused() {
    let e = refused("F0 = 2.47", "F0 = 1.7e308");
    assert!(
        e.starts_with("assess.toml: site.SLV: the SLV nonlinear_kinematic check leaves the floating-point range: demand inf m"),
        "{e}"
    );
}
