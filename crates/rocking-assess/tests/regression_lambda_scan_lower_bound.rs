//! Regression (issue 48, item 3): with `lambda = { from = 0.1, to = 0.5,
//! step = 0.1 }` on a tower that does not even rock at the site, both dynamic
//! checks said "ζ_E ≥ 0.5 FAILS" and the SLV one governed: a scan that ends
//! without a failure was taken for one. It now reports a lower bound that
//! holds; when the set fails at the site (λ = 1) above the scan, the gap up
//! to 1 is bisected and ζ_E < 1 fails as found. λ was also rounded to 12
//! decimals (1e-13 became 0, and 1e300 overflowed to ∞); it is now kept as
//! computed, and a scan that cannot be represented is refused naming its key.

#![allow(clippy::unwrap_used)]

use rocking_assess::{dynamic_check, Assessment, AssessmentInput, RecordSet, Role};
use std::path::{Path, PathBuf};

/// The tests' tower (4 m × 12 m on subsoil B), three synthetic records, and `lambda`.
fn file(tower: Option<&str>, lambda: &str) -> String {
    let mut file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    if let Some(tower) = tower {
        let from = "width = 4.0\nheight = 12.0\nmass = 1.5e5\n";
        assert!(file.contains(from), "tower_on_b.toml has no {from:?}");
        file = file.replace(from, tower);
    }
    file + &format!(
        "records = [\"records/synthetic/kt_01.AT2\", \"records/synthetic/kt_02.AT2\", \"records/synthetic/kt_03.AT2\"]\nfree_after = 5.0\nlambda = {lambda}\n"
    )
}

fn origin() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/assess.toml")
}

#[test]
fn a_scan_without_a_failure_is_a_lower_bound_that_holds() {
    let input = AssessmentInput::from_toml_str(&file(None, "{ from = 0.1, to = 0.5, step = 0.1 }"), &origin()).unwrap();
    let done = Assessment::run(&input).unwrap();
    for d in &done.dynamic {
        // The tower does not rock at the site: no displacement at λ = 1 (θ stays exactly 0).
        assert!(d.at_one.combined.abs() <= 0.0 && d.at_one.holds, "{:?}", d.at_one.combined);
        let check = d.check.unwrap();
        assert!(check.ag_capacity.is_lower_bound(), "{check:?}");
        // ζ_E ≥ the scan's last λ, 0.1 + 4 × 0.1 = 0.5 exactly in binary.
        assert!((check.zeta_e - 0.5).abs() < 1e-12, "{check:?}");
        assert!(check.holds, "a bound that holds reported as a failure: {check:?}");
    }
}

#[test]
fn a_set_failing_at_the_site_above_the_scan_is_bisected_below_one() {
    // A small slender block (1 m × 5 m) on subsoil C: whatever it does at λ = 1,
    // the verdict agrees with the set's response there.
    let input = AssessmentInput::from_toml_str(
        &file(Some("width = 1.0\nheight = 5.0\nmass = 1.0e4\n"), "{ from = 0.1, to = 0.3, step = 0.1 }").replace("soil = \"B\"", "soil = \"C\""),
        &origin(),
    )
    .unwrap();
    let capacity = input.capacity().unwrap();
    let set = RecordSet::read(&input, capacity.t_slc).unwrap();
    for role in [Role::LifeSafety, Role::Collapse] {
        let d = dynamic_check(&input, &set, &capacity, role).unwrap();
        let check = d.check.unwrap();
        assert_eq!(check.holds, d.at_one.holds, "{check:?}");
        if !d.at_one.holds {
            let (lo, hi) = d.bracket.unwrap();
            assert!(lo >= 0.3 - 1e-12 && hi <= 1.0 && !check.ag_capacity.is_lower_bound(), "{lo} {hi}");
            assert!(check.zeta_e < 1.0);
        }
    }
}

#[test]
fn lambda_is_kept_as_computed() {
    let input = AssessmentInput::from_toml_str(&file(None, "{ from = 1e-13, to = 3e-13, step = 1e-13 }"), &origin()).unwrap();
    let values = input.lambda.values();
    assert_eq!(values.len(), 3);
    // from + k·step in binary: 1e-13, 2e-13, 1e-13 + 2e-13 (within an ulp of 3e-13).
    for (v, k) in values.iter().zip([1.0, 2.0, 3.0]) {
        assert!((v / (k * 1e-13) - 1.0).abs() < 1e-15, "{values:?}");
    }
}

#[test]
fn a_scan_that_cannot_be_represented_is_refused_naming_its_key() {
    for (lambda, key) in [
        ("{ from = 1e300, to = 2e300, step = 1e300 }", "assessment.lambda.to: 2e300 is above 1e4"),
        ("{ from = 1.0, to = 1.0000000000000002, step = 1e-16 }", "assessment.lambda.step: 1e-16 is lost"),
        ("{ from = 1e-300, to = 1.0, step = 1e-300 }", "assessment.lambda: 1.0000e300 values of λ"),
    ] {
        let e = AssessmentInput::from_toml_str(&file(None, lambda), &origin()).expect_err(lambda).to_string();
        assert!(e.contains(key), "{lambda}: {e}");
    }
}
