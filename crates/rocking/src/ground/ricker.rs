//! The Ricker wavelet: `a_g = A (1 − 2π² f² τ²) exp(−π² f² τ²)`, `τ = t − t0`,
//! for `0 <= t <= 2 t0`, then zero (`t0 = 1.5/f` by default).

use super::{Piece, Segment};
use crate::error::{finite, positive, Error, Parameter};
use std::f64::consts::PI;

/// A Ricker wavelet of peak `A` at `t0`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ricker {
    amplitude: f64,
    frequency: f64,
    t0: f64,
}

impl Ricker {
    /// Peak `A` (m/s², any sign), central frequency `f` (Hz, > 0), centre `t0` (s, > 0;
    /// default `1.5/f`).
    pub fn new(amplitude: f64, frequency: f64, t0: Option<f64>) -> Result<Self, Error> {
        let frequency = positive(Parameter::GroundFrequency, frequency)?;
        let t0 = positive(Parameter::GroundRickerCentre, t0.unwrap_or(1.5 / frequency))?;
        Ok(Self {
            amplitude: finite(Parameter::GroundAmplitude, amplitude)?,
            frequency,
            t0,
        })
    }
    /// The wavelet ends at `2 t0` (s).
    pub fn duration(&self) -> f64 {
        2.0 * self.t0
    }

    pub(super) fn segment(&self, t: f64) -> Option<Segment> {
        if t >= self.duration() {
            return None;
        }
        // Extrema: τ = 0 and τ = ±sqrt(3/2)/(π f).
        let side = 1.5f64.sqrt() / (PI * self.frequency);
        let end = [self.t0 - side, self.t0, self.t0 + side]
            .into_iter()
            .find(|&e| e > t && e < self.duration())
            .unwrap_or(self.duration());
        Some(Segment {
            piece: Piece::Ricker {
                amplitude: self.amplitude,
                pi_f: PI * self.frequency,
                t0: self.t0,
            },
            end,
            kink: self.duration(),
        })
    }
}
