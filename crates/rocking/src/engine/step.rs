//! One accepted step of the integrator, examined whole (module docs of
//! `engine`) and cut short at the first transition in it.

use super::input::Input;
use super::rhs::{self, Rhs, Selected};
use super::screen::{self, Ends};
use super::watch::{accelerations_of, watched, Watched};
use super::{crossing, peaks, step_error, Run, Settled};
use crate::condition::{conditions, Condition};
use crate::equations::Kernel;
use crate::error::Error;
use crate::integrator::{DenseOutput, Dop853};
use crate::observer::{Interpolant, Observer};
use crate::regime::{Regime, State};

impl<O: Observer, const N: usize> Run<'_, O, N> {
    /// One step of the dynamic motion, with the right-hand side of the
    /// current regime and inputs (`rhs.rs`).
    pub(super) fn advance_dynamic(&mut self) -> Result<(), Error> {
        let (piece, vpiece) = (self.input.segment.piece, self.input.vsegment.piece);
        match rhs::select(self.kernel, self.regime, piece, vpiece, self.input.has_vertical) {
            Selected::HarmonicRocking(f) => self.advance_dynamic_with(f),
            Selected::Horizontal(f) => self.advance_dynamic_with(f),
            Selected::General(f) => self.advance_dynamic_with(f),
        }
    }

    /// [`Self::advance_dynamic`] with the accelerations `f` of the regime:
    /// restart if needed, step, screen the step from its ends, search what
    /// the screen could not rule out, feed the peaks, and either stop at the
    /// first transition or go on from the step's end.
    #[inline(always)]
    fn advance_dynamic_with(&mut self, f: impl Rhs) -> Result<(), Error> {
        let mut rhs = |t: f64, y: &[f64; N]| {
            let y = State::from_components(y);
            y.rate(f.accelerations(t, y.theta, y.theta_dot)).components()
        };
        let list = conditions(self.kernel, self.regime);
        if self.integ.restart {
            self.restart(&mut rhs, list);
        }
        self.integ
            .stepper
            .step(&mut rhs, self.input.step_bound())
            .map_err(|e| step_error(e, self.kernel.dynamic))?;
        let w1 = watched_at_end(self.kernel, self.regime, &self.input, &self.integ.stepper, list);
        let ends = ends(self.kernel, self.regime, &self.input, &self.integ.stepper, (&self.cache.watch, &w1), list);
        let screen = screen::screen(&ends, self.report.tracker.kept(), self.report.observer.wants_steps());
        let dense = screen.needs_dense().then(|| self.integ.stepper.dense(&mut rhs));
        let theta_points = match (&dense, screen.theta_roots) {
            (Some(d), true) => crossing::theta_extremes(d, ends.t0, ends.t1),
            _ => crossing::Points::default(),
        };
        let first = crossing::first_transition(&ends, &screen, dense.as_ref(), &theta_points, self.fell_back_now());
        let t_stop = first.map_or(ends.t1, |(tb, _)| tb);
        peaks::inside(&ends, &screen, dense.as_ref(), &theta_points, t_stop, &mut self.report.tracker);
        // The step's end, out of `ends`, which borrows the run.
        let (t1, y1, rocking) = (ends.t1, ends.y1, ends.rocking());
        // Built only for an observer that wants it (a copy of the polynomial otherwise spent).
        let interpolant = || match &dense {
            Some(d) => Interpolant::Dense(d.widen()),
            None => Interpolant::Constant(y1),
        };
        self.emit_step(interpolant, t_stop)?;
        match (first, &dense) {
            (Some((tb, c)), Some(d)) => self.stop_inside(t1, y1, d, tb, c),
            _ => self.go_on(t1, y1, &w1, rocking),
        }
    }

    /// Restarts the stepper at the current instant, with the right-hand side
    /// and the watched quantities `settle` left there when they are bit for
    /// bit those of this instant, state, regime and pieces ([`Settled`]).
    #[inline(always)]
    fn restart(&mut self, rhs: &mut impl FnMut(f64, &[f64; N]) -> [f64; N], list: &[Condition]) {
        let (kernel, regime, piece, vpiece) = (self.kernel, self.regime, self.input.segment.piece, self.input.vsegment.piece);
        let (t, y) = (self.integ.t, self.integ.y);
        let same = |c: &Settled| c.t.to_bits() == t.to_bits() && c.y.same_bits(y) && c.regime == regime && c.pieces == (piece, vpiece);
        match self.cache.settled.take().filter(|c| self.cache.reuse_settled && same(c)) {
            // `settle` left `watch` computed there.
            Some(c) => self
                .integ
                .stepper
                .restart_with(rhs, t, y.components(), y.rate(c.acc).components(), self.input.end),
            None => {
                self.integ.stepper.restart(rhs, t, y.components(), self.input.end);
                let f = State::from_components(&self.integ.stepper.f);
                self.cache.watch = watched(kernel, regime, (&piece, &vpiece), list, t, &y, Some(accelerations_of(&f)));
            }
        }
        self.integ.restart = false;
    }

    /// The step, ending at `(t1, y1)`, ends at its first transition, `c` at
    /// `tb`: the state there, the switch, and the conditions that then hold.
    fn stop_inside(&mut self, t1: f64, y1: State, d: &DenseOutput<N>, tb: f64, c: Condition) -> Result<(), Error> {
        self.integ.t = tb;
        self.integ.y = if tb >= t1 { y1 } else { State::from_components(&d.state(tb)) };
        self.integ.restart = true;
        self.record_instant();
        self.switch(c)?;
        self.next_instant()
    }

    /// The step is taken whole: its end `(t1, y1)`, where `w1` is watched,
    /// is the current instant, its end's values go to the summary.
    #[inline(always)]
    fn go_on(&mut self, t1: f64, y1: State, w1: &Watched, rocking: bool) -> Result<(), Error> {
        self.integ.t = t1;
        self.integ.y = y1;
        self.cache.watch = *w1;
        let tracker = &mut self.report.tracker;
        tracker.displacement(y1.theta, y1.slip);
        if rocking {
            tracker.top(w1.top.v);
            tracker.pivot(w1.fx.v, w1.fy.v);
        }
        // Within a segment the conditions were just checked on the step; only a
        // new segment (a kink or jump of the input) can make one hold at once.
        if self.input.reached_kink(self.integ.t) {
            self.next_instant()?;
        }
        Ok(())
    }
}

/// The step `stepper` just took, seen from its ends; `w`: what is watched
/// at its start and end ([`watched_at_end`]). It borrows the run's inputs
/// and watched values, not its stepper, which the dense output needs.
#[inline(always)]
fn ends<'a, const N: usize>(
    kernel: &'a Kernel,
    regime: Regime,
    input: &'a Input,
    st: &Dop853<N>,
    (w0, w1): (&'a Watched, &'a Watched),
    list: &'a [Condition],
) -> Ends<'a> {
    let (t0, t1) = (st.t_old, st.t);
    Ends {
        kernel,
        regime,
        pieces: (&input.segment.piece, &input.vsegment.piece),
        list,
        t0,
        t1,
        h: t1 - t0,
        y0: State::from_components(&st.y_old),
        y1: State::from_components(&st.y),
        f0: State::from_components(&st.f_old()),
        f1: State::from_components(&st.f),
        w0,
        w1,
    }
}

/// What is watched at the end of the step `stepper` just took.
#[inline(always)]
fn watched_at_end<const N: usize>(kernel: &Kernel, regime: Regime, input: &Input, st: &Dop853<N>, list: &[Condition]) -> Watched {
    let (y1, f1) = (State::from_components(&st.y), State::from_components(&st.f));
    watched(
        kernel,
        regime,
        (&input.segment.piece, &input.vsegment.piece),
        list,
        st.t,
        &y1,
        Some(accelerations_of(&f1)),
    )
}
