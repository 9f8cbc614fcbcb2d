//! Regression: the fit's message stated the opposite of its data. With 0 of 3
//! cases exceeded at 0.1, 2 of 3 at 0.5 and 3 of 3 at 1.0 it said "none
//! exceeded above 0.5, all exceeded from 0.5". The message now says what the
//! stripes hold: none exceeded below 0.5, 2 of 3 at 0.5, all above it.

use rocking_scenario::{fit_fragility, Stripe};

fn stripe(level: f64, cases: u64, exceeded: u64) -> Stripe {
    Stripe { level, cases, exceeded }
}

#[test]
fn one_level_holding_both_kinds_of_case_is_named_with_its_counts() {
    let fit = fit_fragility(&[stripe(0.1, 3, 0), stripe(0.5, 3, 2), stripe(1.0, 3, 3)]);
    assert_eq!(fit.median, None);
    assert_eq!(
        fit.method,
        "no fit: the exceedances are separated by level (none exceeded below 0.5, 2 of 3 exceeded at 0.5, all exceeded above it): \
         the likelihood has no maximum (beta -> 0)"
    );
}

#[test]
fn a_gap_between_the_levels_is_named_by_its_two_ends() {
    // Stripes in any order: none exceeded at 0.1 and 0.2, all at 0.3 and 0.4.
    let fit = fit_fragility(&[stripe(0.3, 2, 2), stripe(0.1, 2, 0), stripe(0.4, 2, 2), stripe(0.2, 2, 0)]);
    assert_eq!(fit.median, None);
    assert!(fit.method.contains("(none exceeded up to 0.2, all exceeded from 0.3)"), "{}", fit.method);
}
