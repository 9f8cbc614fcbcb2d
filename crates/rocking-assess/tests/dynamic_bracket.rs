//! The non-linear dynamic check's capacity, verified by running the records
//! at λ just below and just above it through the scenario files' own path (a
//! `[ground]` record with `scale`, as `rocking run` reads it), independently
//! of the check's reuse of one built case per record: just below, no record
//! reaches d0 and the largest response (3 records) is within d_SLV; just
//! above, one of the two fails.

#![allow(clippy::unwrap_used)]

use rocking_assess::{dynamic_check, AssessmentInput, RecordSet, Role, LAMBDA_TOLERANCE};
use rocking_scenario::{RunOptions, Scenario};
use std::path::{Path, PathBuf};

/// The tests' site (tests/data/tower_on_b.toml) with a small slender block
/// (1 m × 5 m, fixed base) in place of its tower, on subsoil C, and three
/// synthetic records.
fn file() -> String {
    let mut file = std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/tower_on_b.toml")).unwrap();
    for (from, to) in [
        ("width = 4.0\nheight = 12.0\nmass = 1.5e5\n", "width = 1.0\nheight = 5.0\nmass = 1.0e4\n"),
        ("soil = \"B\"", "soil = \"C\""),
    ] {
        assert!(file.contains(from), "tower_on_b.toml has no {from:?}");
        file = file.replace(from, to);
    }
    // [assessment] is the file's last table.
    file + "records = [\"records/synthetic/kt_01.AT2\", \"records/synthetic/kt_02.AT2\", \"records/synthetic/kt_03.AT2\"]\nfree_after = 5.0\nlambda = { from = 0.25, to = 6.0, step = 0.25 }\n"
}

fn origin() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/assess.toml")
}

/// The largest d* (m) of the three records at `lambda` times their scales, run
/// from scenario text; `None` in place of a record that overturned.
fn responses(lambda: f64, scales: &[f64], alpha: f64, radius: f64) -> Vec<Option<f64>> {
    let files = ["kt_01", "kt_02", "kt_03"];
    files
        .iter()
        .zip(scales)
        .map(|(f, s)| {
            let record = rocking::Record::parse(
                &std::fs::read_to_string(origin().parent().unwrap().join(format!("records/synthetic/{f}.AT2"))).unwrap(),
                None,
                &rocking::CsvOptions::default(),
                9.81,
            )
            .unwrap();
            let text = format!(
                "[tower]\nwidth = 1.0\nheight = 5.0\nmass = 1.0e4\n[ground]\ntype = \"record\"\nfile = \"records/synthetic/{f}.AT2\"\nscale = {}\n[simulation]\nduration = {}\n",
                lambda * s,
                record.duration() + 5.0
            );
            let outcome = Scenario::from_toml_str(&text, &origin()).unwrap().build().unwrap().run(RunOptions::SUMMARY).unwrap();
            let theta = outcome.summary.max_abs_theta();
            (!outcome.summary.overturned()).then(|| radius * (alpha.sin() - (alpha - theta).sin()))
        })
        .collect()
}

#[test]
fn the_records_hold_just_below_the_capacity_and_fail_just_above() {
    let input = AssessmentInput::from_toml_str(&file(), &origin()).unwrap();
    let capacity = input.capacity().unwrap();
    let set = RecordSet::read(&input, capacity.t_slc).unwrap();
    let check = dynamic_check(&input, &set, &capacity, Role::LifeSafety).unwrap();
    let (lo, hi) = check.bracket.expect("the block fails within λ ≤ 6");
    assert!(hi - lo <= LAMBDA_TOLERANCE && hi > lo, "{lo} {hi}");
    let verdict = check.check.unwrap();
    // ζ_E is the λ that holds: a_g,capacity = λ ag.
    assert!((verdict.ag_capacity.value() - lo * 0.155).abs() < 1e-15);
    assert!((verdict.zeta_e - lo).abs() < 1e-12);

    let (alpha, radius, d0, d_slv) = (capacity.alpha, capacity.radius, capacity.d0, capacity.d_slv);
    // d* of the block: R (sin α − sin(α − θ)) with R = √(0.5² + 2.5²), α = atan(0.2); d0 = b = 0.5 m.
    assert!((d0 - 0.5).abs() < 1e-12 && (radius - 6.5f64.sqrt()).abs() < 1e-12);
    let largest = |r: &[Option<f64>]| r.iter().map(|d| d.unwrap_or(d0)).fold(0.0, f64::max);
    let below = responses(lo, &check.fitted.scales, alpha, radius);
    assert!(below.iter().all(|d| d.is_some_and(|d| d < d0)), "{below:?}");
    assert!(largest(&below) <= d_slv, "at λ = {lo}: {below:?} against d_SLV = {d_slv}");
    let above = responses(hi, &check.fitted.scales, alpha, radius);
    assert!(
        above.iter().any(|d| d.is_none_or(|d| d >= d0)) || largest(&above) > d_slv,
        "at λ = {hi}: {above:?}"
    );
    // Every λ of the scan below the bracket held: the first failure is the one reported.
    assert!(check.scan.iter().filter(|p| p.lambda <= lo).all(|p| p.holds));
}
