//! A record set fitted to a target spectrum over a period range, and its
//! compatibility with the code (NTC 2018 §3.2.3.6).
//!
//! Each record gets its own linear scale factor `f`, the one that minimises
//! `Σ_T (ln(f·PSA_i(T)) − ln Se(T))²` over the periods of the range: `ln f` is the
//! mean of `ln Se − ln PSA_i`. The set is compatible when the mean spectrum of the
//! scaled records lies between 0.90 and 1.30 times the target at every period of
//! the range.

use crate::error::Error;

/// The least ratio of the set's mean spectrum to the target that NTC 2018 §3.2.3.6 accepts.
pub const COMPATIBILITY_LOWER: f64 = 0.90;
/// The greatest ratio it accepts.
pub const COMPATIBILITY_UPPER: f64 = 1.30;

/// The fewest records from which the checks use the set's mean response (NTC 2018 §7.3.5).
pub const RECORDS_FOR_MEAN: usize = 7;
/// The fewest records of a set at all (NTC 2018 §7.3.5: with 3 to 6, the largest response).
pub const MIN_RECORDS: usize = 3;

/// The default lower end of the fitting range (s): the code's 0.15 s.
pub const DEFAULT_RANGE_FROM: f64 = 0.15;
/// The least upper end of the default fitting range (s): the code's 2.0 s.
pub const DEFAULT_RANGE_TO: f64 = 2.0;

/// The default fitting range `[0.15 s, max(2.0 s, T_SLC)]`: the code's 0.15–2 s,
/// stretched to the secant period at collapse of the structure when one is given
/// (the periods that govern a rocking tower).
pub fn default_period_range(t_slc: Option<f64>) -> (f64, f64) {
    (DEFAULT_RANGE_FROM, t_slc.map_or(DEFAULT_RANGE_TO, |t| t.max(DEFAULT_RANGE_TO)))
}

/// How the checks combine the responses of a set (NTC 2018 §7.3.5).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SetRule {
    /// At least 7 records: the mean response.
    Mean,
    /// 3 to 6 records: the largest response.
    Largest,
}

/// The rule for a set of `count` records; fewer than 3 is an error.
pub fn set_rule(count: usize) -> Result<SetRule, Error> {
    if count >= RECORDS_FOR_MEAN {
        Ok(SetRule::Mean)
    } else if count >= MIN_RECORDS {
        Ok(SetRule::Largest)
    } else {
        Err(Error::Fit(format!(
            "a record set needs at least {MIN_RECORDS} records (7 for the mean response to be used), got {count}"
        )))
    }
}

/// The linear scale `f` of one record that minimises `Σ (ln(f·psa) − ln target)²`
/// over the given periods: `ln f = mean(ln target − ln psa)` (a log least-squares
/// fit, closed form). Both slices hold the spectra at the same periods, all > 0.
pub fn fitted_scale(psa: &[f64], target: &[f64]) -> f64 {
    let sum: f64 = psa.iter().zip(target).map(|(p, s)| libm::log(*s) - libm::log(*p)).sum();
    libm::exp(sum / psa.len() as f64)
}

/// The compatibility of a mean spectrum with a target over the same periods (NTC
/// 2018 §3.2.3.6): the least and greatest ratio `mean / target`, and whether
/// every ratio lies in [0.90, 1.30].
pub fn compatibility(mean: &[f64], target: &[f64]) -> Compatibility {
    let ratios = mean.iter().zip(target).map(|(m, t)| m / t);
    let (least, greatest) = ratios.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| (lo.min(r), hi.max(r)));
    Compatibility {
        least_ratio: least,
        greatest_ratio: greatest,
        holds: least >= COMPATIBILITY_LOWER && greatest <= COMPATIBILITY_UPPER,
    }
}

/// The mean spectrum of the set over the range against the target's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compatibility {
    /// The least ratio of the mean to the target over the range.
    pub least_ratio: f64,
    /// The greatest ratio.
    pub greatest_ratio: f64,
    /// Whether every ratio lies in [0.90, 1.30].
    pub holds: bool,
}

/// A record set fitted to a target spectrum.
#[derive(Debug, Clone, PartialEq)]
pub struct FittedSet {
    /// Each record's scale factor, in the set's order.
    pub scales: Vec<f64>,
    /// The mean of the scaled spectra at every period (not only the range's).
    pub mean: Vec<f64>,
    /// The indices of the periods in the fitting range.
    pub in_range: std::ops::Range<usize>,
    /// The mean against the target over the range.
    pub compatibility: Compatibility,
    /// How the checks combine the set's responses.
    pub rule: SetRule,
}

/// The periods of `periods` (s, increasing) within `[from, to]`, checked: the range
/// must lie inside the periods and hold at least two of them.
pub fn periods_in_range(periods: &[f64], range: (f64, f64)) -> Result<std::ops::Range<usize>, Error> {
    let (from, to) = range;
    if !(from.is_finite() && to.is_finite() && from > 0.0 && to > from) {
        return Err(Error::Fit(format!("period_range: need 0 < from < to (s), got [{from}, {to}]")));
    }
    let (first, last) = match (periods.first(), periods.last()) {
        (Some(&a), Some(&b)) => (a, b),
        _ => return Err(Error::Fit("no periods to fit over".into())),
    };
    // The range's ends may round off the periods' by a relative 1e-9.
    let slack = 1e-9 * to;
    if from < first - slack || to > last + slack {
        return Err(Error::Fit(format!(
            "period_range: [{from}, {to}] s is outside the periods of the spectra, {first} to {last} s"
        )));
    }
    let start = periods.partition_point(|&t| t < from - slack);
    let end = periods.partition_point(|&t| t <= to + slack);
    if end < start + 2 {
        return Err(Error::Fit(format!("period_range: [{from}, {to}] s holds fewer than 2 of the periods")));
    }
    Ok(start..end)
}

/// Fits each record's spectrum (`spectra[i][k]` at `periods[k]`, in the target's
/// units) to the `target` spectrum over the periods in `range` (s): each record's
/// [`fitted_scale`], the mean of the scaled spectra and its [`compatibility`].
/// Fewer than 3 records, a range outside the periods, or a record whose spectrum
/// is zero in the range is an error (naming the record by its 1-based place).
pub fn fit_record_set(periods: &[f64], spectra: &[Vec<f64>], target: &[f64], range: (f64, f64)) -> Result<FittedSet, Error> {
    let rule = set_rule(spectra.len())?;
    let in_range = periods_in_range(periods, range)?;
    if target.len() != periods.len() || spectra.iter().any(|s| s.len() != periods.len()) {
        return Err(Error::Fit("the spectra and the target must be given at the same periods".into()));
    }
    if let Some(k) = in_range.clone().find(|&k| !(target[k].is_finite() && target[k] > 0.0)) {
        return Err(Error::Fit(format!("the target spectrum is not > 0 at T = {} s", periods[k])));
    }
    let mut scales = Vec::with_capacity(spectra.len());
    for (i, psa) in spectra.iter().enumerate() {
        if let Some(k) = in_range.clone().find(|&k| !(psa[k] > 0.0 && psa[k].is_finite())) {
            return Err(Error::Fit(format!(
                "record {}: its spectrum is {} at T = {} s, which cannot be scaled to the target",
                i + 1,
                psa[k],
                periods[k]
            )));
        }
        scales.push(fitted_scale(&psa[in_range.clone()], &target[in_range.clone()]));
    }
    let mean: Vec<f64> = (0..periods.len())
        .map(|k| spectra.iter().zip(&scales).map(|(s, f)| f * s[k]).sum::<f64>() / spectra.len() as f64)
        .collect();
    let compatibility = compatibility(&mean[in_range.clone()], &target[in_range.clone()]);
    Ok(FittedSet {
        scales,
        mean,
        in_range,
        compatibility,
        rule,
    })
}
