//! Regression: Ctrl-C during a long fragility fit was ignored (the fit ran to
//! its end, and the command exited 0 seconds later). The fit now looks at a
//! cancel flag before every evaluation of the likelihood and gives up when it
//! is set; `rocking fragility` sets it on Ctrl-C and exits 130.

use rocking_scenario::{fit_fragility, fit_fragility_until, Stripe, FIT_INTERRUPTED, FIT_METHOD};
use std::sync::atomic::AtomicBool;

/// Exceedances that overlap in level: a fit exists.
fn stripes() -> Vec<Stripe> {
    [(0.1, 0), (0.2, 1), (0.3, 2), (0.4, 4), (0.5, 5)]
        .iter()
        .map(|&(level, exceeded)| Stripe { level, cases: 5, exceeded })
        .collect()
}

#[test]
fn a_fit_gives_up_once_cancelled() {
    let fitted = fit_fragility_until(&stripes(), &AtomicBool::new(false));
    assert_eq!(fitted.method, FIT_METHOD);
    assert_eq!(fitted, fit_fragility(&stripes()), "the same fit without a flag");
    let given_up = fit_fragility_until(&stripes(), &AtomicBool::new(true));
    assert_eq!((given_up.median, given_up.beta, given_up.method.as_str()), (None, None, FIT_INTERRUPTED));
    // The counts are still the stripes'.
    assert_eq!((given_up.cases, given_up.exceeded), (25, 12));
}
