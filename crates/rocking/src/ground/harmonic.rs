//! Harmonic ground acceleration, the paper's excitation: `a_g = A sin(2π f t + φ)`
//! for `0 <= t < duration`, then zero.

use super::{next_periodic, Piece, Segment};
use crate::error::{finite, positive, Error, Parameter};
use std::f64::consts::PI;

/// `a_g = A sin(2π f t + φ)` during `duration`, zero afterwards.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Harmonic {
    amplitude: f64,
    frequency: f64,
    duration: f64,
    phase: f64,
}

/// Most cycles of shaking a harmonic may last: a million cycles already take
/// tens of millions of right-hand-side evaluations.
pub const MAX_CYCLES: f64 = 1e6;

impl Harmonic {
    /// Amplitude `A` (m/s², any sign: a negative one mirrors the motion),
    /// frequency `f` (Hz, > 0), duration (s, > 0), phase `φ` (rad).
    pub fn new(amplitude: f64, frequency: f64, duration: f64, phase: f64) -> Result<Self, Error> {
        let frequency = positive(Parameter::GroundFrequency, frequency)?;
        let duration = positive(Parameter::GroundDuration, duration)?;
        let cycles = frequency * duration;
        if cycles > MAX_CYCLES {
            return Err(Error::InvalidParameter {
                parameter: Parameter::GroundFrequency,
                reason: format!(
                    "{frequency:e} Hz over {duration} s of shaking is {cycles:.1e} cycles, more than {MAX_CYCLES:.0e} (each takes several integration steps)"
                ),
            });
        }
        Ok(Self {
            amplitude: finite(Parameter::GroundAmplitude, amplitude)?,
            frequency,
            duration,
            phase: finite(Parameter::GroundPhase, phase)?,
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
