//! A masonry of finite compressive strength (issue 46, item 6): the tests'
//! tower (4 m × 12 m, 150 t) with `compressive_strength = 2.0` MPa at
//! knowledge level LC2. By hand: FC = 1.2 (LC2), f_d = 2 / 1.2 = 1.666667 MPa;
//! N = 1.5e5 kg × 9.81 = 1.4715e6 N; the strip along the edge that carries N
//! at 0.85 f_d is t = N / (0.85 f_d D) = 0.2596765 m wide (D = 4 m), the hinge
//! t/2 = 0.1298382 m in; b' = 2 − 0.1298382 = 1.870162 m, h = 6 m;
//! α0 = b'/h = 0.3116936 (0.3333333 on the edge: 6.5% less);
//! a0* = α0 g / (e* FC) = 2.548095 m/s². Tolerance 1e-6: the 7 digits kept.

use approx::assert_relative_eq;
use rocking_assess::AssessmentInput;
use std::path::Path;

const FIXTURE: &str = include_str!("data/tower_on_b.toml");

fn input(text: &str) -> AssessmentInput {
    AssessmentInput::from_toml_str(text, Path::new("tower.toml")).unwrap_or_else(|e| panic!("{e}"))
}

fn with_strength() -> String {
    FIXTURE
        .replace("mass = 1.5e5\n", "mass = 1.5e5\ncompressive_strength = 2.0\n")
        .replace("confidence_factor = 1.35\n", "knowledge_level = \"LC2\"\n")
}

#[test]
fn the_hinge_moves_in_and_the_capacity_falls() {
    let input = input(&with_strength());
    assert_relative_eq!(input.file.confidence_factor, 1.2, max_relative = 1e-15);
    let capacity = input.capacity().unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(capacity.alpha0, 0.3116936, max_relative = 1e-6);
    assert_relative_eq!(capacity.a0_star, 2.548095, max_relative = 1e-6);
    // The dynamic model rocks on the same hinge: the tower of every run has the capacity's α and R.
    let tower = input.model().tower().copied().unwrap_or_else(|| panic!("no tower"));
    assert_relative_eq!(tower.alpha(), capacity.alpha, max_relative = 1e-15);
    assert_relative_eq!(tower.radius(), capacity.radius, max_relative = 1e-15);
    assert_relative_eq!(tower.radius(), (1.870162f64.powi(2) + 36.0).sqrt(), max_relative = 1e-6);
}

#[test]
fn without_a_strength_the_tower_rocks_on_its_edges() {
    let input = input(&FIXTURE.replace("confidence_factor = 1.35\n", "knowledge_level = \"LC2\"\n"));
    let capacity = input.capacity().unwrap_or_else(|e| panic!("{e}"));
    // α0 = b/h = 2/6; a0* = α0 g / FC with FC = 1.2 (LC2).
    assert_relative_eq!(capacity.alpha0, 1.0 / 3.0, max_relative = 1e-14);
    assert_relative_eq!(capacity.a0_star, 9.81 / 3.0 / 1.2, max_relative = 1e-14);
}

#[test]
fn a_given_confidence_factor_wins_over_the_knowledge_level() {
    let text = FIXTURE.replace("confidence_factor = 1.35\n", "confidence_factor = 1.35\nknowledge_level = \"LC3\"\n");
    assert_relative_eq!(input(&text).file.confidence_factor, 1.35, max_relative = 1e-15);
    let bad = FIXTURE.replace("confidence_factor = 1.35\n", "knowledge_level = \"LC4\"\n");
    let e = AssessmentInput::from_toml_str(&bad, Path::new("tower.toml"))
        .map(|_| ())
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("tower.toml: assessment.knowledge_level: "), "{e}");
}
