//! Observers: how a run reports its steps and events without knowing about
//! files, plots or progress bars (argmin's `Observe` pattern). Like argmin's
//! observers, each call returns whether the run goes on: an observer stops a
//! run (Ctrl-C) or fails it (a file that cannot be written) with
//! `ControlFlow::Break`, and [`crate::simulate`] returns
//! [`crate::Error::Stopped`] or [`crate::Error::Observer`].

use crate::cascade::Flight;
use crate::equations::Kernel;
use crate::event::Event;
use crate::ground::Piece;
use crate::integrator::DenseOutput;
use crate::regime::{Motion, Pivot, Regime, State, TowerRegime};
use crate::stack::StackState;
use std::ops::ControlFlow;

/// Why an observer ends a run.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Halt {
    /// Stop here, as asked (an interruption): not a failure of the model.
    Stop,
    /// The observer failed (its one-line message, e.g. a write that failed).
    Fail(String),
}

/// What an observer returns: go on, or end the run.
pub type Flow = ControlFlow<Halt>;

/// Receives the steps and events of a run. Every method has a no-op default.
pub trait Observer {
    /// Whether [`Observer::on_step`] is wanted; when false the run skips building
    /// the dense output it would need.
    fn wants_steps(&self) -> bool {
        false
    }
    /// One stretch `[t0, t1]` of smooth motion in one regime.
    fn on_step(&mut self, _step: &Step<'_>) -> Flow {
        Flow::Continue(())
    }
    /// A regime change.
    fn on_event(&mut self, _event: &Event) -> Flow {
        Flow::Continue(())
    }
}

/// The observer that observes nothing.
impl Observer for () {}

impl<A: Observer, B: Observer> Observer for (A, B) {
    fn wants_steps(&self) -> bool {
        self.0.wants_steps() || self.1.wants_steps()
    }
    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        self.0.on_step(step)?;
        self.1.on_step(step)
    }
    fn on_event(&mut self, event: &Event) -> Flow {
        self.0.on_event(event)?;
        self.1.on_event(event)
    }
}

impl<O: Observer + ?Sized> Observer for &mut O {
    fn wants_steps(&self) -> bool {
        (**self).wants_steps()
    }
    fn on_step(&mut self, step: &Step<'_>) -> Flow {
        (**self).on_step(step)
    }
    fn on_event(&mut self, event: &Event) -> Flow {
        (**self).on_event(event)
    }
}

/// How a step's states are evaluated. Lives on the stack for one call, so the
/// size difference of the variants costs nothing.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, Copy)]
pub(crate) enum Interpolant {
    Constant(State),
    Dense(DenseOutput<4>),
    /// A free flight of the impact cascade in closed form (`cascade.rs`).
    Flight(Flight),
}

/// A stretch of smooth motion: evaluate the response anywhere in `[t0, t1]`.
#[derive(Debug, Clone, Copy)]
pub struct Step<'a> {
    pub(crate) kernel: &'a Kernel,
    pub(crate) piece: Piece,
    /// The vertical input's piece (`Constant(0.0)` without one).
    pub(crate) vpiece: Piece,
    pub(crate) interpolant: Interpolant,
    /// Start (s).
    pub t0: f64,
    /// End (s).
    pub t1: f64,
    /// Regime throughout the step (of the tower and the building in a stacked run).
    pub regime: Regime,
    /// In a stacked run, the response of the whole stack ([`Sample::stack`]).
    pub(crate) stack: Option<StackSampler<'a>>,
}

/// The response of a stacked run at an instant of a step.
#[derive(Clone, Copy)]
pub(crate) struct StackSampler<'a>(pub(crate) &'a dyn Fn(f64) -> Sample);

impl std::fmt::Debug for StackSampler<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("StackSampler")
    }
}

/// The response at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sample {
    /// Time (s).
    pub t: f64,
    /// Ground acceleration (m/s²).
    pub ground_acc: f64,
    /// Vertical ground acceleration (m/s², positive upwards; 0 without one).
    pub ground_acc_v: f64,
    /// Rotation, angular velocity, slip and slip velocity.
    pub state: State,
    /// `θ̈` (rad/s²).
    pub theta_ddot: f64,
    /// `ü` (m/s²).
    pub slip_acc: f64,
    /// Horizontal displacement of the top centre relative to the building (m).
    pub top_dx: f64,
    /// Absolute horizontal acceleration of the top centre (m/s²).
    pub top_abs_acc: f64,
    /// Combined motion.
    pub motion: Motion,
    /// In a stacked run, every interface's rotation and angular velocity
    /// (index 0 the tower, as `state`; `k` the block `k + 1`) and the slip.
    pub stack: Option<StackState>,
    pub(crate) pivot: Option<Pivot>,
}

impl Step<'_> {
    /// The response at `t` in `[t0, t1]`.
    pub fn sample(&self, t: f64) -> Sample {
        if let Some(StackSampler(at)) = self.stack {
            return at(t);
        }
        let y = match self.interpolant {
            Interpolant::Constant(y) => y,
            Interpolant::Dense(d) => State::from_components(&d.state(t)),
            Interpolant::Flight(f) => f.state(t),
        };
        let a_g = self.piece.eval(t);
        let a_v = self.vpiece.eval(t);
        let acc = self.kernel.accelerations(self.regime, a_g, self.kernel.g + a_v, y.theta, y.theta_dot);
        let pivot = match self.regime.tower {
            TowerRegime::Rest => None,
            TowerRegime::Rocking(p) => Some(p),
        };
        let (top_dx, top_abs_acc) = self
            .kernel
            .top_kinematics(pivot.map(Pivot::sign), crate::trig::sin_cos(y.theta), y.theta_dot, acc.theta, a_g + acc.slip);
        Sample {
            t,
            ground_acc: a_g,
            ground_acc_v: a_v,
            state: y,
            theta_ddot: acc.theta,
            slip_acc: acc.slip,
            top_dx,
            top_abs_acc,
            motion: self.regime.motion(),
            stack: None,
            pivot,
        }
    }

    /// Displacement relative to the building (m) and absolute horizontal
    /// acceleration (m/s²) of the tower point `(x, y)` (m, origin at the base
    /// centre) in `sample`, which must come from this step.
    pub fn point(&self, sample: &Sample, x: f64, y: f64) -> (f64, f64) {
        let st = sample.state;
        self.kernel.point_kinematics(
            sample.pivot.map(Pivot::sign),
            (x, y),
            crate::trig::sin_cos(st.theta),
            st.theta_dot,
            sample.theta_ddot,
            sample.ground_acc + sample.slip_acc,
        )
    }
}
