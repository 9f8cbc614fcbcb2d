//! One-cycle pulses: `a_g = A sin(2π f t)` or `A cos(2π f t)` for `0 <= t <= 1/f`,
//! and the rectangular pulse `a_g = A` for `0 <= t < duration`, then zero.

use super::{Piece, Segment};
use crate::error::{finite, positive, Error, Parameter};
use std::f64::consts::PI;

/// The shape of a [`Pulse`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PulseShape {
    /// One full sine cycle.
    Sine,
    /// One full cosine cycle (a jump to `A` at `t = 0` and from `A` to 0 at its end).
    Cosine,
    /// A constant acceleration (jumps at both ends).
    Rectangular,
}

/// A single pulse of ground acceleration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pulse {
    shape: PulseShape,
    amplitude: f64,
    duration: f64,
}

impl Pulse {
    /// A sine or cosine pulse of amplitude `A` (m/s², any sign) and frequency `f` (Hz, > 0):
    /// it lasts `1/f`.
    pub fn cycle(shape: PulseShape, amplitude: f64, frequency: f64) -> Result<Self, Error> {
        let frequency = positive(Parameter::GroundFrequency, frequency)?;
        Ok(Self {
            shape,
            amplitude: finite(Parameter::GroundAmplitude, amplitude)?,
            duration: 1.0 / frequency,
        })
    }
    /// A rectangular pulse of amplitude `A` (m/s², any sign) lasting `duration` (s, > 0).
    pub fn rectangular(amplitude: f64, duration: f64) -> Result<Self, Error> {
        Ok(Self {
            shape: PulseShape::Rectangular,
            amplitude: finite(Parameter::GroundAmplitude, amplitude)?,
            duration: positive(Parameter::GroundDuration, duration)?,
        })
    }
    /// Duration of the pulse (s).
    pub fn duration(&self) -> f64 {
        self.duration
    }

    pub(super) fn segment(&self, t: f64) -> Option<Segment> {
        if t >= self.duration {
            return None;
        }
        let omega = 2.0 * PI / self.duration;
        let (piece, inner): (Piece, &[f64]) = match self.shape {
            PulseShape::Sine => (
                Piece::Sine {
                    amplitude: self.amplitude,
                    omega,
                    phase: 0.0,
                },
                &[0.25, 0.75],
            ),
            PulseShape::Cosine => (
                Piece::Sine {
                    amplitude: self.amplitude,
                    omega,
                    phase: PI / 2.0,
                },
                &[0.5],
            ),
            PulseShape::Rectangular => (Piece::Constant(self.amplitude), &[]),
        };
        let end = inner.iter().map(|x| x * self.duration).find(|&e| e > t).unwrap_or(self.duration);
        Some(Segment {
            piece,
            end,
            kink: self.duration,
        })
    }
}
