//! Horizontal ground accelerations `a_g(t)` (m/s², positive towards `+x`).
//!
//! Every motion is split into *segments* on which it is smooth and monotone:
//! the integrator steps exactly onto segment ends (the kinks and jumps of the
//! input, and its extrema), so a condition that depends on `a_g` alone crosses
//! its threshold at most once per segment and is located exactly, and a jump
//! (the end of a harmonic, a cosine pulse, a record step) is seen at once.

mod harmonic;
mod pulse;
mod record;
mod ricker;

pub use harmonic::Harmonic;
pub use pulse::{Pulse, PulseShape};
pub use record::{AccelerationUnit, CsvOptions, Record, RecordError, RecordFormat};
pub use ricker::Ricker;

use crate::jet::Jet;

/// A horizontal ground motion, zero for `t < 0` and after it ends.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum GroundMotion {
    /// No ground motion (free rocking, free sliding).
    None,
    /// `A sin(2π f t + φ)` for `0 <= t < duration`.
    Harmonic(Harmonic),
    /// One cycle of a sine, a cosine, or a rectangular pulse.
    Pulse(Pulse),
    /// A Ricker wavelet.
    Ricker(Ricker),
    /// A recorded accelerogram, linearly interpolated.
    Record(Record),
}

/// The smooth expression of `a_g` on one segment; evaluating it at the
/// segment's right end gives the left limit there.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum Piece {
    /// A constant (m/s²).
    Constant(f64),
    /// `amplitude sin(omega t + phase)`.
    Sine { amplitude: f64, omega: f64, phase: f64 },
    /// `a0 + slope (t − t0)`.
    Linear { t0: f64, a0: f64, slope: f64 },
    /// `amplitude (1 − 2 (π f τ)²) exp(−(π f τ)²)`, `τ = t − t0`.
    Ricker { amplitude: f64, pi_f: f64, t0: f64 },
}

/// `amplitude sin(omega t + phase)`: [`Piece::Sine`] at `t`.
#[inline(always)]
pub(crate) fn sine(amplitude: f64, omega: f64, phase: f64, t: f64) -> f64 {
    amplitude * crate::trig::sin(omega * t + phase)
}

impl Piece {
    /// `a_g(t)` (m/s²).
    #[inline(always)]
    pub(crate) fn eval(&self, t: f64) -> f64 {
        match *self {
            Piece::Constant(a) => a,
            Piece::Sine { amplitude, omega, phase } => sine(amplitude, omega, phase, t),
            Piece::Linear { t0, a0, slope } => a0 + slope * (t - t0),
            Piece::Ricker { amplitude, pi_f, t0 } => {
                let x = (pi_f * (t - t0)).powi(2);
                amplitude * (1.0 - 2.0 * x) * libm::exp(-x)
            }
        }
    }
}

impl Piece {
    /// `a_g(t)` and its time derivative (m/s², m/s³).
    #[inline]
    pub(crate) fn eval_jet(&self, t: f64) -> Jet {
        match *self {
            Piece::Constant(a) => Jet::new(a, 0.0),
            Piece::Sine { amplitude, omega, phase } => {
                let (s, c) = crate::trig::sin_cos(omega * t + phase);
                Jet::new(amplitude * s, amplitude * omega * c)
            }
            Piece::Linear { t0, a0, slope } => Jet::new(a0 + slope * (t - t0), slope),
            Piece::Ricker { amplitude, pi_f, t0 } => {
                let tau = t - t0;
                let x = (pi_f * tau).powi(2);
                let e = libm::exp(-x);
                // d/dx [(1 − 2x) e^−x] = (2x − 3) e^−x, dx/dt = 2 (π f)² τ.
                Jet::new(amplitude * (1.0 - 2.0 * x) * e, amplitude * (2.0 * x - 3.0) * e * 2.0 * pi_f * pi_f * tau)
            }
        }
    }

    /// An upper bound of `|ȧ_g|` over the whole piece (m/s³).
    #[inline]
    pub(crate) fn max_abs_rate(&self) -> f64 {
        match *self {
            Piece::Constant(_) => 0.0,
            Piece::Sine { amplitude, omega, .. } => (amplitude * omega).abs(),
            Piece::Linear { slope, .. } => slope.abs(),
            // ȧ_g = A 2πf u (2u² − 3) e^−u², u = π f τ: the factor's largest
            // magnitude is 0.976, at u² = (3 − √6)/2 (where its derivative
            // (−4u⁴ + 12u² − 3) e^−u² vanishes); bounded here by 1.
            Piece::Ricker { amplitude, pi_f, .. } => 2.0 * (amplitude * pi_f).abs(),
        }
    }

    /// An upper bound of `|a_g|` on `[t0, t1]` (m/s²).
    #[inline]
    pub(crate) fn max_abs(&self, t0: f64, t1: f64) -> f64 {
        match *self {
            Piece::Constant(a) => a.abs(),
            // |sin| <= 1; |(1 − 2x) e^−x| <= 1 for x >= 0.
            Piece::Sine { amplitude, .. } | Piece::Ricker { amplitude, .. } => amplitude.abs(),
            Piece::Linear { .. } => self.eval(t0).abs().max(self.eval(t1).abs()),
        }
    }
}

/// A segment `[start, end]` of the motion on which it is smooth and monotone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Segment {
    pub(crate) piece: Piece,
    /// The next instant where the motion has a kink, a jump or an extremum (`+∞` if none).
    pub(crate) end: f64,
    /// The next kink or jump (`>= end`): the piece holds up to here.
    pub(crate) kink: f64,
}

/// The first of a periodic family of instants `(k + offset) period` strictly after `t`
/// (by more than rounding), used for the extrema of harmonic signals.
pub(crate) fn next_periodic(t: f64, period: f64, offset: f64) -> f64 {
    let k = (t / period - offset).floor() + 1.0;
    let mut next = (k + offset) * period;
    if next <= t + 4.0 * f64::EPSILON * t.abs().max(period) {
        next += period;
    }
    next
}

impl GroundMotion {
    /// The segment that starts at (or contains) `t >= 0`; its piece is the
    /// right-continuous expression at `t`.
    pub(crate) fn segment(&self, t: f64) -> Segment {
        let zero = Segment {
            piece: Piece::Constant(0.0),
            end: f64::INFINITY,
            kink: f64::INFINITY,
        };
        match self {
            GroundMotion::None => zero,
            GroundMotion::Harmonic(h) => h.segment(t).unwrap_or(zero),
            GroundMotion::Pulse(p) => p.segment(t).unwrap_or(zero),
            GroundMotion::Ricker(r) => r.segment(t).unwrap_or(zero),
            GroundMotion::Record(r) => r.segment(t).unwrap_or(zero),
        }
    }

    /// `a_g(t)` (m/s²), right-continuous at jumps.
    pub fn acceleration(&self, t: f64) -> f64 {
        if t < 0.0 {
            return 0.0;
        }
        self.segment(t).piece.eval(t)
    }

    /// The time after which the motion is zero (s); `0` for no motion.
    pub fn end_time(&self) -> f64 {
        match self {
            GroundMotion::None => 0.0,
            GroundMotion::Harmonic(h) => h.duration(),
            GroundMotion::Pulse(p) => p.duration(),
            GroundMotion::Ricker(r) => r.duration(),
            GroundMotion::Record(r) => r.duration(),
        }
    }

    /// Peak `|a_g|` (m/s²) and its time (s).
    pub fn peak(&self) -> (f64, f64) {
        match self {
            GroundMotion::None => (0.0, 0.0),
            GroundMotion::Record(r) => r.peak(),
            _ => {
                // Analytic motions: the peak sits at a segment end (an extremum) or a segment start.
                let mut best = (0.0, 0.0);
                let mut t = 0.0;
                while t < self.end_time() {
                    let s = self.segment(t);
                    for tt in [t, s.end.min(self.end_time())] {
                        let a = s.piece.eval(tt).abs();
                        if a > best.0 {
                            best = (a, tt);
                        }
                    }
                    t = s.end;
                }
                best
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn next_periodic_is_strictly_after() {
        assert!((next_periodic(0.0, 1.0, 0.25) - 0.25).abs() < 1e-15);
        assert!((next_periodic(0.25, 1.0, 0.25) - 1.25).abs() < 1e-15);
        assert!((next_periodic(0.3, 1.0, 0.25) - 1.25).abs() < 1e-15);
        assert!((next_periodic(1.2, 0.5, 0.5) - 1.25).abs() < 1e-15);
    }

    /// `max_abs_rate` bounds `|ȧ_g|` as sampled on the pieces' exact
    /// derivatives, and is attained to the stated fraction: all of it for a
    /// sine and a line; for the Ricker wavelet the factor `|u (2u² − 3) e^−u²|`
    /// at its peak `u² = (3 − √6)/2`, which the bound rounds up to 1.
    /// 2·10⁵ samples on 1.5 s fall within 3.75e-6 s of each maximum, where
    /// the sampled value is low by `|q̈| δt² / 2|q|` at most: 3.4e-10 relative
    /// for the sine (`ω² δt² / 2`), 2.2e-9 for the wavelet (`|q̈/q|` = 316 s⁻²
    /// there), hence 1e-8.
    #[test]
    fn rate_bound_holds_and_is_sharp() {
        let u2 = (3.0 - 6f64.sqrt()) / 2.0;
        let ricker_peak = (u2.sqrt() * (2.0 * u2 - 3.0) * (-u2).exp()).abs();
        let pieces = [
            (
                Piece::Sine {
                    amplitude: -3.0,
                    omega: 7.0,
                    phase: 0.4,
                },
                1.0,
            ),
            (Piece::Linear { t0: 1.0, a0: 2.0, slope: -5.0 }, 1.0),
            (
                Piece::Ricker {
                    amplitude: 4.0,
                    pi_f: std::f64::consts::PI * 2.0,
                    t0: 0.75,
                },
                ricker_peak,
            ),
            (Piece::Constant(9.0), 1.0),
        ];
        for (piece, sharpness) in pieces {
            let bound = piece.max_abs_rate();
            let sampled = (0..=200_000).map(|i| piece.eval_jet(1.5 * i as f64 / 200_000.0).d.abs()).fold(0.0, f64::max);
            assert!(sampled <= bound * (1.0 + 1e-12), "{piece:?}: {sampled} > {bound}");
            assert!(sampled >= sharpness * bound * (1.0 - 1e-8), "{piece:?}: {sampled} << {sharpness} · {bound}");
        }
    }
}
