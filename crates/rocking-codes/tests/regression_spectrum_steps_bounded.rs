//! Regression (issue 48, item 4): the response spectrum's free tail ran
//! `2T/dt` steps with neither bounded: a three-sample record at a period of
//! 10¹² s never ended, and one sampled 10⁻⁹ s apart took hours at the
//! default periods. The steps of a spectrum (the record's samples and the
//! tail at each period) are counted before the first is taken and refused
//! past `MAX_STEPS` (2·10⁹) with one line naming the periods.

use rocking::Record;
use rocking_codes::{pseudo_acceleration, response_spectrum, PeriodGrid, DEFAULT_PERIODS};

fn three_samples(dt: f64) -> Record {
    Record::uniform(dt, vec![0.0, 1.0, 0.0]).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn a_tail_past_the_limit_is_refused_before_a_step() {
    let periods = PeriodGrid {
        from: 0.02,
        to: 1e12,
        count: 2,
    }
    .periods()
    .unwrap_or_else(|e| panic!("{e}"));
    let e = response_spectrum(&three_samples(0.01), &periods, 5.0).expect_err("2e14 steps");
    let line = e.to_string();
    assert!(
        line.starts_with("periods: a record of 3 samples 0.01 s apart over the periods up to 1000000000000 s"),
        "{line}"
    );
    assert!(line.contains(&format!("more than {:.0e}", rocking_codes::MAX_STEPS)), "{line}");
    // 10⁻⁹ s apart at the default periods (to 4 s): 2·4/1e-9 = 8e9 steps at the longest alone.
    let default = DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    assert!(response_spectrum(&three_samples(1e-9), &default, 5.0).is_err());
    assert!(pseudo_acceleration(&three_samples(1e-9), 4.0, 5.0).is_err());
}

#[test]
fn a_spectrum_within_the_limit_is_computed_as_before() {
    // At T = 1 s after a record of 0.01 s: 3 samples and a tail of 2/0.01 = 200 steps, far below the limit.
    // The record's area is 0.01 m/s: an impulse to an oscillator at rest, whose
    // free peak is about ω·(0.01)/ω² = 0.01/ω, so PSA = ω² x ≈ 0.01 ω (5% damping
    // lowers it by a few percent, the sampling of the peak by less).
    let omega = 2.0 * std::f64::consts::PI;
    let psa = pseudo_acceleration(&three_samples(0.01), 1.0, 5.0).unwrap_or_else(|e| panic!("{e}"));
    assert!((psa / (0.01 * omega) - 1.0).abs() < 0.1, "{psa}");
}
