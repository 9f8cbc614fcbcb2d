//! Harmonic ground acceleration, the paper's excitation: `a_g = A sin(2π f t + φ)`
//! for `0 <= t < duration`, then zero.

use super::{next_periodic, Piece, Segment};
use crate::error::{finite, positive, Error};
use std::f64::consts::PI;

/// `a_g = A sin(2π f t + φ)` during `duration`, zero afterwards.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    amplitude: f64,
    frequency: f64,
    duration: f64,
    phase: f64,
}

impl Harmonic {
    /// Amplitude `A` (m/s², any sign: a negative one mirrors the motion),
    /// frequency `f` (Hz, > 0), duration (s, > 0), phase `φ` (rad).
    pub fn new(amplitude: f64, frequency: f64, duration: f64, phase: f64) -> Result<Self, Error> {
        Ok(Self {
            amplitude: finite("ground.amplitude", amplitude)?,
            frequency: positive("ground.frequency", frequency)?,
            duration: positive("ground.duration", duration)?,
            phase: finite("ground.phase", phase)?,
        })
    }
    /// Amplitude (m/s²).
    pub fn amplitude(&self) -> f64 {
        self.amplitude
    }
    /// Frequency (Hz).
    pub fn frequency(&self) -> f64 {
        self.frequency
    }
    /// Duration of the shaking (s).
    pub fn duration(&self) -> f64 {
        self.duration
    }

    pub(super) fn segment(&self, t: f64) -> Option<Segment> {
        if t >= self.duration {
            return None;
        }
        let omega = 2.0 * PI * self.frequency;
        // Extrema where ω t + φ = (k + ½) π, i.e. t = (k + ½ − φ/π) · (1/2f).
        let half_period = 0.5 / self.frequency;
        let extremum = next_periodic(t, half_period, 0.5 - self.phase / PI);
        Some(Segment {
            piece: Piece::Sine {
                amplitude: self.amplitude,
                omega,
                phase: self.phase,
            },
            end: extremum.min(self.duration),
            kink: self.duration,
        })
    }
}
