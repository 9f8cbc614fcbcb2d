//! The inputs over a run: the ground's segment (a piece of the horizontal
//! input, monotone up to its end, smooth up to its kink) that holds the
//! current instant, the vertical input's, and where the effective gravity
//! `g + a_v` reaches zero.

use super::Run;
use crate::error::Error;
use crate::ground::{GroundMotion, Segment};
use crate::integrator::find_crossing;
use crate::observer::Observer;

/// The inputs and where the run is in them.
pub(super) struct Input<'a> {
    pub(super) ground: &'a GroundMotion,
    /// The vertical ground acceleration (`GroundMotion::None` without one).
    pub(super) vertical: &'a GroundMotion,
    pub(super) has_vertical: bool,
    /// A vertical input was given, `GroundMotion::None` included (the summary
    /// then reports the least effective gravity).
    pub(super) vertical_given: bool,
    /// The end of the run (s).
    pub(super) end: f64,
    /// The ground's segment that holds `t` (right-continuous).
    pub(super) segment: Segment,
    /// The vertical input's segment that holds `t`.
    pub(super) vsegment: Segment,
    /// The first instant, before the end of `vsegment`'s piece, where
    /// `g + a_v <= 0` (`+∞` if none).
    pub(super) free_fall: f64,
}

impl Input<'_> {
    /// Where the next step must end at the latest: kinks and jumps of both
    /// inputs, the instant `g + a_v` reaches zero, the end of the run.
    pub(super) fn step_bound(&self) -> f64 {
        self.segment.kink.min(self.vsegment.kink).min(self.free_fall).min(self.end)
    }

    /// Whether `t` has reached a kink or jump of an input, or free fall.
    pub(super) fn reached_kink(&self, t: f64) -> bool {
        t >= self.segment.kink || t >= self.vsegment.kink || t >= self.free_fall
    }
}

impl<O: Observer, const N: usize> Run<'_, O, N> {
    /// The effective gravity `g + a_v` (m/s²) at `t` in the current vertical segment.
    #[inline(always)]
    pub(super) fn g_e(&self, t: f64) -> f64 {
        self.kernel.g + self.input.vsegment.piece.eval(t)
    }

    pub(super) fn a_g(&self, t: f64) -> f64 {
        self.input.segment.piece.eval(t)
    }

    /// Enters the vertical input's segment at the current time and locates the
    /// first instant before its next kink where `g + a_v <= 0`: on each
    /// monotone part the least value is at an end, so the crossing is
    /// bracketed there and located by root finding.
    pub(super) fn enter_vertical(&mut self) {
        self.input.vsegment = self.input.vertical.segment(self.integ.t);
        self.input.free_fall = f64::INFINITY;
        if !self.input.has_vertical {
            return;
        }
        let g = self.kernel.g;
        let stop = self.input.vsegment.kink.min(self.input.end);
        let mut t = self.integ.t;
        loop {
            let segment = self.input.vertical.segment(t);
            let (piece, tb) = (segment.piece, segment.end.min(stop));
            let value = |t: f64| -(g + piece.eval(t));
            let (va, vb) = (value(t), value(tb));
            if va >= 0.0 {
                self.input.free_fall = t;
                return;
            }
            if vb >= 0.0 {
                self.input.free_fall = find_crossing(value, t, va, tb, vb, 0.0).tb;
                return;
            }
            if tb >= stop {
                return;
            }
            t = tb;
        }
    }

    /// Stops the run where the effective gravity has reached zero.
    pub(super) fn check_free_fall(&self) -> Result<(), Error> {
        if self.integ.t >= self.input.free_fall {
            return Err(Error::FreeFall { time: self.input.free_fall });
        }
        Ok(())
    }

    /// The least `g + a_v` on `[0, t_end]` (m/s²): on each monotone segment
    /// of the input it is at an end.
    pub(super) fn min_effective_gravity(&self, t_end: f64) -> f64 {
        let mut least = self.kernel.g + self.input.vertical.segment(0.0).piece.eval(0.0);
        let mut t = 0.0;
        while t < t_end {
            let s = self.input.vertical.segment(t);
            let tb = s.end.min(t_end);
            least = least.min(self.kernel.g + s.piece.eval(t)).min(self.kernel.g + s.piece.eval(tb));
            t = tb;
        }
        least
    }
}
