//! Intensity measures of a record as the engine sees it: linearly
//! interpolated between its samples, zero before the first and after the last
//! (README, "Fragility studies").
//!
//! - PGA: the peak `|a_g|`, at a sample (a linear interpolant peaks at its ends).
//! - PGV: the peak `|v|` of `v(t) = ∫₀ᵗ a_g dt`. On a sample interval
//!   `[t_k, t_k + h]` the acceleration is `a_k + s τ`, so
//!   `v = v_k + a_k τ + s τ² / 2` exactly; its extremes are at the interval's
//!   ends or where `a` crosses zero inside it (`τ* = −a_k / s`). The peak is
//!   the largest `|v|` over those points: exact, no quadrature error.
//! - `pga_ratio`: PGA / (g tan α), the tower's uplift threshold as unit.

use rocking::Record;

/// The intensity measure a study scales its records to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Measure {
    /// Peak ground acceleration, in g.
    Pga,
    /// Peak ground velocity, in m/s.
    Pgv,
    /// PGA over the tower's uplift acceleration `g tan α` (dimensionless).
    PgaRatio,
}

impl Measure {
    /// The measures and their names in a study file.
    pub const ALL: [(&'static str, Measure); 3] = [("pga", Measure::Pga), ("pgv", Measure::Pgv), ("pga_ratio", Measure::PgaRatio)];

    /// The name in a study file.
    pub fn as_str(self) -> &'static str {
        match self {
            Measure::Pga => "pga",
            Measure::Pgv => "pgv",
            Measure::PgaRatio => "pga_ratio",
        }
    }

    /// The unit of the measure, for labels.
    pub fn unit(self) -> &'static str {
        match self {
            Measure::Pga => "g",
            Measure::Pgv => "m/s",
            Measure::PgaRatio => "",
        }
    }

    /// The measure of `record` (m/s²): `g` (m/s²) converts PGA to g,
    /// `tan_alpha` is the tower's (needed by `pga_ratio` only; `None` gives NaN).
    pub fn of(self, record: &Record, g: f64, tan_alpha: Option<f64>) -> f64 {
        match self {
            Measure::Pga => pga(record) / g,
            Measure::Pgv => pgv(record),
            Measure::PgaRatio => tan_alpha.map_or(f64::NAN, |t| pga(record) / (g * t)),
        }
    }
}

/// Peak `|a_g|` of the record (m/s²).
pub fn pga(record: &Record) -> f64 {
    record.values().iter().fold(0.0f64, |m, a| m.max(a.abs()))
}

/// Peak `|v|` (m/s) of `v(t) = ∫₀ᵗ a_g dt` for the linearly interpolated
/// record (zero before its first sample and after its last), exact.
pub fn pgv(record: &Record) -> f64 {
    let (times, values) = (record.times(), record.values());
    let mut v = 0.0f64;
    let mut peak = 0.0f64;
    for k in 0..times.len().saturating_sub(1) {
        let h = times[k + 1] - times[k];
        let (a0, a1) = (values[k], values[k + 1]);
        let slope = (a1 - a0) / h;
        // a crosses zero strictly inside the interval: v has an extremum there.
        if (a0 < 0.0 && a1 > 0.0) || (a0 > 0.0 && a1 < 0.0) {
            let tau = -a0 / slope;
            peak = peak.max((v + a0 * tau + 0.5 * slope * tau * tau).abs());
        }
        // The trapezoid is the exact integral of the linear piece.
        v += 0.5 * (a0 + a1) * h;
        peak = peak.max(v.abs());
    }
    peak
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use std::f64::consts::PI;

    /// `a sin(ω t)` sampled `n` times per period over `periods` whole periods.
    fn sine(a: f64, omega: f64, n: usize, periods: usize) -> Record {
        let h = 2.0 * PI / omega / n as f64;
        let values = (0..=n * periods).map(|k| a * (omega * k as f64 * h).sin()).collect();
        Record::uniform(h, values).expect("a valid record")
    }

    #[test]
    fn pga_of_a_scaled_record_is_the_scale_times_the_peak_sample() {
        let record = Record::from_samples(vec![0.0, 0.01, 0.03, 0.04], vec![0.5, -2.5, 1.0, 0.0]).expect("valid");
        // Peak sample |−2.5|; scaling by 0.37 multiplies every sample, one rounding each.
        assert_relative_eq!(pga(&record.scaled(0.37)), 0.37 * 2.5, max_relative = f64::EPSILON);
        assert_relative_eq!(Measure::Pga.of(&record, 9.81, None), 2.5 / 9.81, max_relative = f64::EPSILON);
    }

    #[test]
    fn pga_ratio_is_pga_over_g_tan_alpha() {
        let record = sine(3.0, 2.0 * PI, 40, 2);
        let (g, tan_alpha) = (9.81, 1.0 / 3.0);
        let expected = pga(&record) / (g * tan_alpha);
        assert_relative_eq!(Measure::PgaRatio.of(&record, g, Some(tan_alpha)), expected, max_relative = f64::EPSILON);
        assert!(Measure::PgaRatio.of(&record, g, None).is_nan());
    }

    /// By hand: with `n = 2M` samples per period, `θ = ω h`, the trapezoid sum
    /// up to the zero crossing at `t = π/ω` (sample `M`, where v peaks) is
    /// `a h Σ_{j=1}^{M−1} sin(j π / M) = a h cot(θ/2)`; the record's `v` is
    /// that piecewise-linear integral, and it tends to `2a/ω` as `h → 0`
    /// (`v = (a/ω)(1 − cos ω t)`: the velocity swings by `a/ω` about its mean `a/ω`).
    #[test]
    fn pgv_of_a_sampled_sine_is_the_exact_piecewise_linear_integral() {
        let (a, omega) = (2.0, 3.0);
        for n in [8usize, 16, 64, 512] {
            let h = 2.0 * PI / omega / n as f64;
            let exact = a * h / (omega * h / 2.0).tan();
            let record = sine(a, omega, n, 3);
            // Rounding of a few hundred additions of terms of size a h.
            assert_relative_eq!(pgv(&record), exact, max_relative = 1e-12);
            // The trapezoid rule's error: x cot x = 1 − x²/3 − x⁴/45 − …, x = ω h / 2, so
            // relative (ω h)²/12 (1 + (ω h)²/60 + …): within 5 % of (ω h)²/12 for ω h <= π/4.
            let continuous = 2.0 * a / omega;
            assert_relative_eq!(pgv(&record), continuous, max_relative = 1.05 * (omega * h).powi(2) / 12.0);
        }
    }

    /// A triangle that crosses zero inside an interval: the extremum is there, not at a sample.
    #[test]
    fn pgv_finds_an_extremum_between_samples() {
        // a = 1 on [0, 1], then linear from 1 to −1 over [1, 2]: zero at t = 1.5.
        let record = Record::from_samples(vec![0.0, 1.0, 2.0], vec![1.0, 1.0, -1.0]).expect("valid");
        // v(1) = 1, v(1.5) = 1 + 0.5·1 − 0.5·2·0.25/… = 1 + ∫₁^1.5 (1 − 2(t−1)) dt = 1.25, v(2) = 1.
        assert_relative_eq!(pgv(&record), 1.25, max_relative = 4.0 * f64::EPSILON);
    }
}
