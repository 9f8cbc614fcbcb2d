//! The lognormal fragility fitted by maximum likelihood over stripes (Baker
//! 2015, "Efficient analytical fragility function fitting using dynamic
//! structural analysis", Earthquake Spectra 31(1), eq. 11–12).
//!
//! At level `x_j`, `z_j` of `n_j` cases exceed the limit state. With
//! `P(x) = Φ(ln(x/θ) / β)` the likelihood of the stripes is
//! `Π_j C(n_j, z_j) P(x_j)^z_j (1 − P(x_j))^(n_j − z_j)`; `θ` (the median) and
//! `β` maximise its logarithm. The maximum exists only when exceeded and
//! non-exceeded cases overlap in level: with none exceeded, all exceeded, or a
//! level below which none and from which all exceed, the likelihood grows
//! without bound as `β → 0` (or `θ → 0, ∞`), and no fit is reported.
//!
//! Φ is statrs's; the maximisation is argmin's Nelder–Mead over
//! `(ln θ, ln β)` (the logarithm keeps β positive without a constraint),
//! restarted once from its optimum as is usual with Nelder–Mead.

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;
use statrs::distribution::{ContinuousCDF, Normal};
use std::sync::atomic::{AtomicBool, Ordering};

/// The cases of one limit state at one level.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Stripe {
    /// The intensity level (units of the measure, > 0).
    pub level: f64,
    /// Cases that ran at this level.
    pub cases: u64,
    /// Of those, the cases that exceeded the limit state.
    pub exceeded: u64,
}

/// A fitted fragility (or why there is none).
#[derive(Debug, Clone, PartialEq)]
pub struct Fit {
    /// The median θ (units of the measure); `None` when no fit exists.
    pub median: Option<f64>,
    /// The logarithmic standard deviation β; `None` when no fit exists.
    pub beta: Option<f64>,
    /// Cases that ran, over every level.
    pub cases: u64,
    /// Of those, the cases that exceeded.
    pub exceeded: u64,
    /// How the fit was made, or why there is none.
    pub method: String,
}

/// The `method` of a fit that exists.
pub const METHOD: &str = "binomial maximum likelihood (Baker 2015)";

/// The fragility `P(x) = Φ(ln(x/θ) / β)`: the probability of exceeding at level `level`.
pub fn probability(level: f64, median: f64, beta: f64) -> f64 {
    Normal::standard().cdf((level / median).ln() / beta)
}

/// `ln Φ(z)`, accurate far in the lower tail (where `Φ(z)` underflows).
fn ln_cdf(z: f64) -> f64 {
    if z > -30.0 {
        Normal::standard().cdf(z).ln()
    } else {
        // Mills ratio: Φ(z) = φ(z)/|z| (1 − 1/z² + 3/z⁴ − …); at |z| >= 30 the
        // series after its first two terms is below 4e-6 relative.
        -0.5 * z * z - (-z).ln() - 0.5 * (2.0 * std::f64::consts::PI).ln() + (1.0 - 1.0 / (z * z)).ln()
    }
}

/// The binomial log-likelihood of the stripes for median `median` and β
/// `beta`, without the constant `Σ ln C(n_j, z_j)`.
pub fn log_likelihood(stripes: &[Stripe], median: f64, beta: f64) -> f64 {
    stripes
        .iter()
        .filter(|s| s.cases > 0)
        .map(|s| {
            let z = (s.level / median).ln() / beta;
            let (k, n) = (s.exceeded as f64, s.cases as f64);
            let mut l = 0.0;
            if s.exceeded > 0 {
                l += k * ln_cdf(z);
            }
            if s.exceeded < s.cases {
                // 1 − Φ(z) = Φ(−z)
                l += (n - k) * ln_cdf(-z);
            }
            l
        })
        .sum()
}

/// The negative log-likelihood over `(ln θ, ln β)`, for argmin (which
/// minimises); once `cancel` is set, a flat function, on which Nelder–Mead
/// stops at once (its simplex's values agree). An error would not do: argmin's
/// Nelder–Mead unwraps the cost of its shrink step.
struct NegLogLikelihood<'a> {
    stripes: &'a [Stripe],
    cancel: &'a AtomicBool,
}

impl CostFunction for NegLogLikelihood<'_> {
    type Param = Vec<f64>;
    type Output = f64;
    fn cost(&self, p: &Self::Param) -> Result<f64, argmin::core::Error> {
        if self.cancel.load(Ordering::Relaxed) {
            return Ok(f64::MAX);
        }
        let l = -log_likelihood(self.stripes, p[0].exp(), p[1].exp());
        // Far from the optimum a tail may round to −∞: a large finite value keeps the simplex ordered.
        Ok(if l.is_finite() { l } else { f64::MAX })
    }
}

/// The `method` of a fit given up because `cancel` was set ([`fit_until`]).
pub const INTERRUPTED: &str = "no fit: interrupted";

/// Fits the lognormal fragility to `stripes` (any order; levels > 0).
pub fn fit(stripes: &[Stripe]) -> Fit {
    fit_until(stripes, &AtomicBool::new(false))
}

/// Fits as [`fit`] does, giving up (method [`INTERRUPTED`]) once `cancel` is
/// set: it is looked at before every evaluation of the likelihood, so a fit
/// over many levels stops at once on Ctrl-C.
pub fn fit_until(stripes: &[Stripe], cancel: &AtomicBool) -> Fit {
    let cases: u64 = stripes.iter().map(|s| s.cases).sum();
    let exceeded: u64 = stripes.iter().map(|s| s.exceeded).sum();
    let none = |method: String| Fit {
        median: None,
        beta: None,
        cases,
        exceeded,
        method,
    };
    if cases == 0 {
        return none("no fit: no case ran".into());
    }
    if exceeded == 0 {
        return none("no fit: no case exceeded".into());
    }
    if exceeded == cases {
        return none("no fit: every case exceeded".into());
    }
    // The highest level with a case that did not exceed, the lowest with one that did.
    let below = stripes
        .iter()
        .filter(|s| s.exceeded < s.cases)
        .map(|s| s.level)
        .fold(f64::NEG_INFINITY, f64::max);
    let above = stripes.iter().filter(|s| s.exceeded > 0).map(|s| s.level).fold(f64::INFINITY, f64::min);
    if below <= above {
        return none(format!(
            "no fit: {}: the likelihood has no maximum (beta -> 0)",
            separation(stripes, below, above)
        ));
    }
    let optimum = maximise(stripes, (below * above).sqrt(), cancel);
    if cancel.load(Ordering::Relaxed) {
        return none(INTERRUPTED.into());
    }
    match optimum {
        Some((median, beta)) if beta < 1e3 => Fit {
            median: Some(median),
            beta: Some(beta),
            cases,
            exceeded,
            method: METHOD.into(),
        },
        Some(_) => none("no fit: the exceedances do not grow with the level (beta -> infinity)".into()),
        None => none("no fit: the maximisation did not converge".into()),
    }
}

/// How the exceedances are separated by level, in words, when `below` (the
/// highest level with a case that did not exceed) is at most `above` (the
/// lowest with one that did). When they are equal, that level is the only one
/// with both kinds of case, and its counts are given.
fn separation(stripes: &[Stripe], below: f64, above: f64) -> String {
    if below < above {
        return format!("the exceedances are separated by level (none exceeded up to {below}, all exceeded from {above})");
    }
    let (cases, exceeded) = stripes
        .iter()
        .filter(|s| s.level.total_cmp(&below).is_eq())
        .fold((0, 0), |(n, k), s| (n + s.cases, k + s.exceeded));
    format!("the exceedances are separated by level (none exceeded below {below}, {exceeded} of {cases} exceeded at {below}, all exceeded above it)")
}

/// Nelder–Mead from `(start, β = 0.5)`, then once more from its optimum: `(θ, β)`.
fn maximise(stripes: &[Stripe], start: f64, cancel: &AtomicBool) -> Option<(f64, f64)> {
    let mut x = vec![start.ln(), 0.5f64.ln()];
    for _ in 0..2 {
        let simplex = vec![x.clone(), vec![x[0] + 0.2, x[1]], vec![x[0], x[1] + 0.3]];
        // Stop when the simplex's values agree to 1e-13 (the log-likelihood is O(cases)).
        let solver = NelderMead::new(simplex).with_sd_tolerance(1e-13).ok()?;
        let result = Executor::new(NegLogLikelihood { stripes, cancel }, solver)
            .configure(|state| state.max_iters(5_000))
            .run()
            .ok()?;
        x = result.state().get_best_param()?.clone();
    }
    let (median, beta) = (x[0].exp(), x[1].exp());
    (median.is_finite() && beta.is_finite()).then_some((median, beta))
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{RngExt, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    /// Stripes drawn from a known lognormal fragility: at each level, every
    /// case exceeds with probability Φ(ln(x/θ)/β).
    fn draw(median: f64, beta: f64, levels: &[f64], per_level: u64, seed: u64) -> Vec<Stripe> {
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let normal = Normal::standard();
        levels
            .iter()
            .map(|&level| {
                let p = normal.cdf((level / median).ln() / beta);
                let exceeded = (0..per_level).filter(|_| rng.random::<f64>() < p).count() as u64;
                Stripe {
                    level,
                    cases: per_level,
                    exceeded,
                }
            })
            .collect()
    }

    fn levels() -> Vec<f64> {
        (1..=20).map(|i| 0.05 * i as f64).collect()
    }

    /// Median 0.4 g, β 0.5, 2,000 cases per stripe: the estimates' standard
    /// errors (the inverse Fisher information of this design: 20 levels
    /// 0.05…1, weights n φ²/(β² p (1 − p))) are 0.0044 on ln θ and 0.0045 on
    /// β; four standard errors is the tolerance.
    #[test]
    fn recovers_a_known_fragility() {
        let stripes = draw(0.4, 0.5, &levels(), 2_000, 2015);
        let fit = fit(&stripes);
        assert_eq!(fit.method, METHOD);
        let (median, beta) = (fit.median.expect("a fit"), fit.beta.expect("a fit"));
        assert!((median / 0.4).ln().abs() < 4.0 * 0.0044, "median {median}");
        assert!((beta - 0.5).abs() < 4.0 * 0.0045, "beta {beta}");
        assert_eq!(fit.cases, 40_000);
    }

    /// Several seeds, fewer cases: the spread of the estimates matches their
    /// standard error (0.020 on ln θ and on β at 100 per stripe, as above);
    /// every estimate within 4 of them.
    #[test]
    fn recovers_it_from_smaller_samples_within_their_error() {
        for seed in 0..10 {
            let fit = fit(&draw(0.4, 0.5, &levels(), 100, seed));
            let (median, beta) = (fit.median.expect("a fit"), fit.beta.expect("a fit"));
            assert!((median / 0.4).ln().abs() < 4.0 * 0.020, "seed {seed}: median {median}");
            assert!((beta - 0.5).abs() < 4.0 * 0.020, "seed {seed}: beta {beta}");
        }
    }

    /// The optimum beats every neighbour at a relative step of 1e-3 on either
    /// parameter and on both (a maximum, not a point the simplex stalled at).
    #[test]
    fn the_likelihood_is_highest_at_the_optimum() {
        let stripes = draw(0.4, 0.5, &levels(), 20, 7);
        let fit = fit(&stripes);
        let (m, b) = (fit.median.expect("a fit"), fit.beta.expect("a fit"));
        let best = log_likelihood(&stripes, m, b);
        for (dm, db) in [
            (1.0, 0.0),
            (-1.0, 0.0),
            (0.0, 1.0),
            (0.0, -1.0),
            (1.0, 1.0),
            (-1.0, -1.0),
            (1.0, -1.0),
            (-1.0, 1.0),
        ] {
            let other = log_likelihood(&stripes, m * (1.0 + 1e-3 * dm), b * (1.0 + 1e-3 * db));
            assert!(other < best, "({dm}, {db}): {other} >= {best}");
        }
    }

    #[test]
    fn says_why_when_no_fit_exists() {
        let stripe = |level, cases, exceeded| Stripe { level, cases, exceeded };
        let none = fit(&[stripe(0.1, 5, 0), stripe(0.2, 5, 0)]);
        assert_eq!((none.median, none.beta, none.method.as_str()), (None, None, "no fit: no case exceeded"));
        let all = fit(&[stripe(0.1, 5, 5), stripe(0.2, 5, 5)]);
        assert_eq!((all.median, all.method.as_str(), all.exceeded), (None, "no fit: every case exceeded", 10));
        let step = fit(&[stripe(0.1, 5, 0), stripe(0.2, 5, 2), stripe(0.3, 5, 5)]);
        assert!(step.median.is_none() && step.method.contains("separated by level"), "{}", step.method);
        assert_eq!(fit(&[]).method, "no fit: no case ran");
    }

    /// In the far tail ln Φ follows its asymptote continuously (no jump at the switch).
    #[test]
    fn ln_cdf_is_continuous_at_the_switch() {
        let (inside, outside) = (ln_cdf(-30.0 + 1e-9), ln_cdf(-30.0 - 1e-9));
        // The dropped series terms are 3/z⁴ ≈ 4e-6 relative to Φ: that much in ln Φ.
        assert!((inside - outside).abs() < 4e-6, "{inside} vs {outside}");
    }
}
