//! The static phase: nothing moves relative to the ground, so the state is
//! constant and every condition depends on the inputs alone; the run moves
//! from one monotone stretch of the inputs to the next, or to the first
//! instant where a condition is met.

use super::crossing::{first_crossing, leaving_point, OnZero, Points};
use super::Run;
use crate::condition::{conditions, Condition};
use crate::equations::Accelerations;
use crate::error::Error;
use crate::extrema::interior_extrema;
use crate::integrator::find_crossing;
use crate::jet::Jet;
use crate::observer::{Interpolant, Observer};

impl<O: Observer, const N: usize> Run<'_, O, N> {
    /// Moves to the next segment end, or to the first instant on the way where a
    /// condition is met (root finding on `a_g`, monotone on the segment).
    pub(super) fn advance_static(&mut self) -> Result<(), Error> {
        // The next extremum of a_g may lie beyond the current segment's end if the
        // run was rocking or sliding until now: take the segment from here.
        self.input.segment = self.input.ground.segment(self.integ.t);
        self.input.vsegment = self.input.vertical.segment(self.integ.t);
        let t1 = self
            .input
            .segment
            .end
            .min(self.input.vsegment.end)
            .min(self.input.free_fall)
            .min(self.input.end);
        let list = conditions(self.kernel, self.regime);
        let (kernel, regime, y, piece, vpiece) = (self.kernel, self.regime, self.integ.y, self.input.segment.piece, self.input.vsegment.piece);
        let value = |c: Condition, t: f64| c.value(kernel, regime, piece.eval(t), kernel.g + vpiece.eval(t), &y);
        let fell_back = self.fell_back_now();
        let mut first: Option<(f64, Condition)> = None;
        for &c in list {
            let on_zero = OnZero::of(c, fell_back);
            let (v0, v1) = (value(c, self.integ.t), value(c, t1));
            let tb = if self.input.has_vertical {
                // Both inputs are monotone on the stretch, but a condition on
                // `a_g` and `g + a_v` together need not be: its extrema, located
                // on the exact derivatives of both pieces, split it into
                // monotone parts.
                let yj = y.jets(Accelerations::default());
                let jet = |t: f64| c.value(kernel, regime, piece.eval_jet(t), Jet::from(kernel.g) + vpiece.eval_jet(t), &yj);
                let mut points = Points::default();
                points.push((self.integ.t, v0));
                interior_extrema(self.integ.t, jet(self.integ.t), t1, jet(t1), &mut |t| jet(t), |_| true, &mut |t, v| {
                    points.push((t, v))
                });
                points.push((t1, v1));
                let hit = first_crossing(
                    points.as_slice(),
                    on_zero,
                    |ta, va, tb, vb| find_crossing(|t| value(c, t), ta, va, tb, vb, 0.0).tb,
                    |ta, tb| leaving_point(&|t| value(c, t), ta, tb),
                );
                match hit {
                    Some(tb) => tb,
                    None => continue,
                }
            } else if v0 < 0.0 && v1 >= 0.0 {
                // Monotone on the segment: zero at the start and positive at the end
                // is positive just after the start.
                find_crossing(|t| value(c, t), self.integ.t, v0, t1, v1, 0.0).tb
            } else if v0 >= 0.0 && v1 > 0.0 && on_zero != OnZero::Waits {
                self.integ.t
            } else {
                continue;
            };
            if first.is_none_or(|(tf, _)| tb < tf) {
                first = Some((tb, c));
            }
        }
        let t_stop = first.map_or(t1, |(tb, _)| tb);
        let y = self.integ.y;
        self.emit_step(|| Interpolant::Constant(y), t_stop)?;
        self.integ.t = t_stop;
        self.integ.restart = true;
        self.record_instant();
        if let Some((_, c)) = first {
            self.switch(c)?;
        }
        self.next_instant()
    }
}
