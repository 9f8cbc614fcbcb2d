//! A dynamic check needs a record set compatible with the code's spectrum
//! (NTC 2018 §3.2.3.6: the mean of the scaled set within 0.90–1.30 of the
//! target over the fitting range). On an incompatible set the check is
//! computed and reported "not valid", and stays out of the verdict unless
//! `assessment.accept_incompatible_set = true`.
//!
//! The tests' tower (tests/data/tower_on_b.toml: 4 m × 12 m, 150 t, FC 1.35,
//! subsoil B) with three synthetic records, whose mean strays from the
//! spectrum over the fitting range. Without them in the verdict it is the
//! most refined kinematic check's: SLC non-linear kinematic, ζ_E = 4.6767,
//! worked out by hand in tests/verdict_by_hand.rs (repeated here in closed form).

#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use rocking_assess::{Assessment, AssessmentInput, Method};
use std::f64::consts::PI;
use std::path::Path;

const G: f64 = 9.81;

/// SLC's non-linear kinematic ζ_E of the tower by hand: T_SLC beyond TE, the
/// demand just past TE, a quadratic in ag (kinematic_by_hand.rs).
fn slc_by_hand() -> f64 {
    let tc = 1.1 * 0.37f64.powf(-0.2) * 0.37;
    let k = 0.025 * G * tc * 2.50 * (10.0f64 / 15.0).sqrt();
    let slc = (-1.6 * k + ((1.6 * k).powi(2) + 4.0 * 4.0 * k * 1.2).sqrt()) / (2.0 * 4.0 * k);
    assert!(1.56 * PI * (1.2 / (0.4 * G / 3.0 / 1.35)).sqrt() > 5.0, "T_SLC beyond TE");
    slc / 0.196
}

fn run(extra: &str) -> (AssessmentInput, Assessment) {
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    let text = format!(
        "{file}records = [\"records/synthetic/kt_01.AT2\", \"records/synthetic/kt_02.AT2\", \"records/synthetic/kt_03.AT2\"]\nfree_after = 3.0\nlambda = {{ from = 0.5, to = 4.0, step = 0.5 }}\n{extra}"
    );
    let origin = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/assess.toml");
    let input = AssessmentInput::from_toml_str(&text, &origin).unwrap();
    let done = Assessment::run(&input).unwrap();
    (input, done)
}

#[test]
fn an_incompatible_set_is_not_valid_and_out_of_the_verdict() {
    let (input, done) = run("");
    assert_eq!(done.dynamic.len(), 2);
    let json = done.json(&input);
    for (d, j) in done.dynamic.iter().zip(json["dynamic"].as_array().unwrap()) {
        let c = &d.fitted.compatibility;
        // The band of §3.2.3.6, applied to the ratios reported.
        let within = c.least_ratio >= 0.9 && c.greatest_ratio <= 1.3;
        assert_eq!(d.is_valid(), within);
        assert_eq!(j["valid"], within);
        assert!(!within, "{}: the synthetic set is taken to be incompatible here: {c:?}", d.limit_state);
        // Computed all the same: its ζ_E is reported.
        assert!(d.check.is_some());
    }
    // The verdict: SLC non-linear kinematic, by hand.
    let (_, g) = done.governing_mechanism().unwrap();
    assert_eq!(g.method, Method::NonlinearKinematic);
    assert_relative_eq!(g.zeta_e, slc_by_hand(), max_relative = 1e-9);
    assert_relative_eq!(g.zeta_e, 4.6767, max_relative = 1e-4);

    // Accepted, the dynamic checks are the most refined and carry it.
    let (input, done) = run("accept_incompatible_set = true\n");
    let (_, g) = done.governing_mechanism().unwrap();
    assert_eq!(g.method, Method::NonlinearDynamic);
    let least = done.dynamic.iter().filter_map(|d| d.check).map(|c| c.zeta_e).fold(f64::INFINITY, f64::min);
    assert_eq!(g.zeta_e.to_bits(), least.to_bits());
    assert_eq!(done.json(&input)["governing"]["method"], "nonlinear_dynamic");

    // The key takes a boolean only.
    let file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    let e = AssessmentInput::from_toml_str(&format!("{file}accept_incompatible_set = \"yes\"\n"), Path::new("a.toml"))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(e.contains("assessment.accept_incompatible_set") && e.contains("true or false"), "{e}");
}
