//! A stacked model through the library's entry points: [`crate::simulate`]
//! hands a model with blocks here, and the run reports as the tower's does.
//!
//! The tower's quantities of the [`Summary`] are those of block 1 (its
//! rotation, its top, the reaction of the building under it), kept by the
//! engine's own [`Tracker`]; the blocks above add a [`StackSummary`]. The
//! observer receives the usual [`Step`]s, whose samples carry every
//! interface's state in [`Sample::stack`], and the usual [`Event`]s, each
//! saying whose it is in [`Event::block`].
//!
//! Peaks are located as follows: the extremes of every `θ_k` at the roots of
//! `θ̇_k` isolated on the dense output (`run.rs`, the engine's search); the
//! top's acceleration, each interface's friction demand and the slip at the
//! ends of the 16 equal parts of every step (Kane's equations solved there
//! once, for these and the conditions read there, [`Instant`]) and at every
//! event (a peak between two of those points is read lower by the curvature
//! over a sixteenth of a step).

use super::dynamics::Snapshot;
use super::run::{part, run_with, BlockSummary, Hook, Instant, RunSettings, StackEvent, StackEventKind, PARTS};
use super::{Interface, Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::equations::Kernel;
use crate::error::{Error, Parameter};
use crate::event::{Event, EventKind};
use crate::ground::{GroundMotion, Piece};
use crate::model::Model;
use crate::observer::{Flow, Interpolant, Observer, Sample, StackSampler, Step};
use crate::regime::{BuildingRegime, Pivot, Regime, State, TowerRegime};
use crate::response::{Closing, EndState, Summary, Tracker};
use crate::simulate::{Initial, Settings};
use std::ops::ControlFlow;

/// What a stacked run found of its blocks, beyond the tower's quantities of
/// the [`Summary`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StackSummary {
    /// Every block's summary, the tower first.
    all: [BlockSummary; MAX_BLOCKS],
    /// The number of blocks, the tower included.
    len: usize,
    /// The largest `|M_imp| / (V_imp B_j / 2)` of a seated interface through
    /// an impact elsewhere (0 without such impacts): above 1 the model's
    /// assumption that it stays seated is violated (docs/src/model.md).
    pub max_seat_impulse_ratio: f64,
    /// The block that overturned: 0 the tower, `k` the `k`-th block above it.
    pub overturned_block: Option<usize>,
}

impl StackSummary {
    /// The blocks above the tower, the lowest first: index 0 is the first
    /// block above the tower.
    pub fn blocks(&self) -> &[BlockSummary] {
        &self.all[1..self.len]
    }
    /// The tower (block 1), as the stack's runner sees it.
    pub fn tower(&self) -> &BlockSummary {
        &self.all[0]
    }
}

/// The tower's and the building's regime in a regime of the stack.
fn project(regime: &StackRegime) -> Regime {
    Regime {
        tower: match regime.interfaces[0] {
            Interface::Stuck => TowerRegime::Rest,
            Interface::Rocking(p) => TowerRegime::Rocking(p),
        },
        building: regime.building,
    }
}

/// The state of interface `k` and the building as the tower's [`State`].
fn state_of(state: &StackState, k: usize) -> State {
    State {
        theta: state.theta[k],
        theta_dot: state.theta_dot[k],
        slip: state.slip,
        slip_vel: state.slip_vel,
    }
}

/// Runs `model` (which has blocks: [`Model::stack`] is `Some`) under `ground`.
pub(crate) fn simulate(
    model: &Model,
    stack: &Stack,
    ground: &GroundMotion,
    vertical: Option<&GroundMotion>,
    initial: Initial,
    settings: &Settings,
    observer: &mut impl Observer,
) -> Result<Summary, Error> {
    if vertical.is_some_and(|v| !matches!(v, GroundMotion::None)) {
        return Err(Error::InvalidParameter {
            parameter: Parameter::Blocks,
            reason: "a vertical ground motion is not taken with blocks stacked on the tower".into(),
        });
    }
    let kernel = Kernel::new(model);
    let mut start = StackState::default();
    start.theta[0] = initial.theta;
    start.theta_dot[0] = initial.theta_dot;
    let run_settings = RunSettings {
        duration: settings.duration,
        rtol: settings.rtol,
        atol: settings.atol,
        // The runner's own samples are not used here: the observer samples the steps.
        sample_interval: settings.duration,
    };
    let regime = super::run::initial_regime(stack, &start);
    let mut reporter = Reporter {
        stack,
        kernel: &kernel,
        ground,
        observer,
        tracker: Tracker::new(),
        demand: [0.0; MAX_BLOCKS],
        last: (0.0, regime, start),
    };
    reporter.instant(&regime, &start, 0.0);
    let out = run_with(stack, ground, &start, &run_settings, &mut reporter)?;
    let Reporter { mut tracker, demand, last, .. } = reporter;
    let (t_end, end_regime, end) = last;
    let tower = &out.blocks[0];
    tracker.theta(tower.theta_range.0);
    tracker.theta(tower.theta_range.1);
    let end_state = match end_regime.interfaces[0] {
        _ if out.overturned == Some(0) => EndState::Overturned,
        _ if end.theta[0].abs() > kernel.alpha => EndState::BeyondStabilityLimit,
        Interface::Stuck => EndState::Rest,
        Interface::Rocking(_) => EndState::Rocking,
    };
    let closing = Closing {
        evaluations: out.evaluations,
        end_state,
        // The closed form is the tower's alone.
        will_overturn: None,
        min_effective_gravity: vertical.map(|_| model.gravity()),
    };
    let mut summary = tracker.finish(&kernel, t_end, &state_of(&end, 0), closing);
    let mut all = [BlockSummary::default(); MAX_BLOCKS];
    for (k, block) in out.blocks.iter().enumerate() {
        all[k] = BlockSummary {
            max_friction_demand: demand[k],
            ..*block
        };
    }
    summary.stack = Some(StackSummary {
        all,
        len: stack.len(),
        max_seat_impulse_ratio: out.max_seat_impulse_ratio,
        overturned_block: out.overturned,
    });
    Ok(summary)
}

/// The hook of a stacked run: keeps the tower's summary and tells the observer.
struct Reporter<'a, O: Observer> {
    stack: &'a Stack,
    kernel: &'a Kernel,
    ground: &'a GroundMotion,
    observer: &'a mut O,
    tracker: Tracker,
    /// Each interface's largest friction demand so far.
    demand: [f64; MAX_BLOCKS],
    /// The latest instant reached: time, regime, state.
    last: (f64, StackRegime, StackState),
}

/// The response at `t` in `regime` and `state`, as the tower's sample with
/// every interface's state.
fn sample(stack: &Stack, kernel: &Kernel, ground: &GroundMotion, regime: &StackRegime, state: &StackState, t: f64) -> Sample {
    let a_g = ground.acceleration(t);
    let (theta_ddot, slip_acc) = stack.accelerations(regime, state, a_g, stack.gravity());
    let pivot = regime.interfaces[0].pivot();
    let (top_dx, top_abs_acc) = kernel.point_kinematics(
        pivot.map(Pivot::sign),
        (0.0, kernel.height),
        crate::trig::sin_cos(state.theta[0]),
        state.theta_dot[0],
        theta_ddot[0],
        a_g + slip_acc,
    );
    Sample {
        t,
        ground_acc: a_g,
        ground_acc_v: 0.0,
        state: state_of(state, 0),
        theta_ddot: theta_ddot[0],
        slip_acc,
        top_dx,
        top_abs_acc,
        motion: project(regime).motion(),
        stack: Some(*state),
        pivot,
    }
}

impl<O: Observer> Reporter<'_, O> {
    /// The peaks at one instant: the tower's rotation and top acceleration,
    /// the slip, and every interface's friction demand.
    fn instant(&mut self, regime: &StackRegime, state: &StackState, t: f64) {
        let snap = self.stack.snapshot(regime, state, self.ground.acceleration(t), self.stack.gravity());
        self.instant_of(regime, state, &snap);
    }

    /// [`Reporter::instant`] with Kane's equations solved there.
    fn instant_of(&mut self, regime: &StackRegime, state: &StackState, snap: &Snapshot) {
        self.tracker.displacement(state.theta[0], state.slip);
        let (_, top) = self.kernel.point_kinematics(
            regime.interfaces[0].pivot().map(Pivot::sign),
            (0.0, self.kernel.height),
            crate::trig::sin_cos(state.theta[0]),
            state.theta_dot[0],
            snap.theta_ddot[0],
            snap.a_g + snap.slip_acc,
        );
        self.tracker.top(top);
        for k in 0..self.stack.len() {
            let load = self.stack.interface_load(snap, k);
            if k == 0 {
                self.tracker.pivot(load.tangential, load.normal);
            }
            self.demand[k] = self.demand[k].max(load.friction_demand());
        }
    }

    /// Reports one event to the tracker and the observer.
    fn report(&mut self, event: Event) -> Flow {
        if event.block == 0 || event.kind == EventKind::Overturn {
            self.tracker.event(&event);
        } else {
            self.tracker.summary.events += 1;
        }
        self.observer.on_event(&event)
    }
}

impl<O: Observer> Hook for Reporter<'_, O> {
    fn step(&mut self, regime: &StackRegime, at: &dyn Fn(f64) -> StackState, t0: f64, t1: f64, instants: Option<&[Instant]>) -> Flow {
        self.tracker.time(project(regime).motion(), t1 - t0);
        match instants {
            Some(instants) => {
                for i in instants {
                    self.instant_of(regime, &i.state, &i.snap);
                }
            }
            None => {
                for j in 1..=PARTS {
                    let t = part(t0, t1, j);
                    self.instant(regime, &at(t), t);
                }
            }
        }
        self.last = (t1, *regime, at(t1));
        if self.observer.wants_steps() {
            let (stack, kernel, ground) = (self.stack, self.kernel, self.ground);
            let sampler = |t: f64| sample(stack, kernel, ground, regime, &at(t), t);
            let step = Step {
                kernel: self.kernel,
                piece: self.ground.segment(t0).piece,
                vpiece: Piece::Constant(0.0),
                interpolant: Interpolant::Constant(State::default()),
                t0,
                t1,
                regime: project(regime),
                stack: Some(StackSampler(&sampler)),
            };
            return self.observer.on_step(&step);
        }
        ControlFlow::Continue(())
    }

    fn event(&mut self, event: &StackEvent) -> Flow {
        let (t, regime) = (event.time, project(&event.regime));
        let one = |kind: EventKind, k: usize, before: &StackState, after: &StackState| Event {
            time: t,
            kind,
            before: state_of(before, k),
            after: state_of(after, k),
            regime,
            block: k,
        };
        let building_change = match (event.regime_before.building, event.regime.building) {
            (a, b) if a == b => None,
            (_, BuildingRegime::Stick) => Some(EventKind::Stick),
            (BuildingRegime::Stick, BuildingRegime::Slip(_)) => Some(EventKind::Slip),
            (BuildingRegime::Slip(_), BuildingRegime::Slip(_)) => Some(EventKind::Reverse),
        };
        let mut events = arrayvec::ArrayVec::<Event, 3>::new();
        match event.kind {
            StackEventKind::Uplift(k) => events.push(one(EventKind::Uplift, k, &event.before, &event.after)),
            StackEventKind::Overturn(k) => events.push(one(EventKind::Overturn, k, &event.before, &event.after)),
            StackEventKind::Impact(k) | StackEventKind::Rest(k) => {
                // As the tower's: the impact, the building's change it brings, then the rest.
                events.push(one(EventKind::Impact, k, &event.before, &event.after));
                if let Some(kind) = building_change {
                    events.push(one(kind, 0, &event.after, &event.after));
                }
                if matches!(event.kind, StackEventKind::Rest(_)) {
                    events.push(one(EventKind::Rest, k, &event.after, &event.after));
                }
            }
            StackEventKind::Slip | StackEventKind::Stick => {
                if let Some(kind) = building_change {
                    events.push(one(kind, 0, &event.before, &event.after));
                }
            }
        }
        for e in events {
            self.report(e)?;
        }
        self.instant(&event.regime, &event.after, t);
        self.last = (t, event.regime, event.after);
        ControlFlow::Continue(())
    }
}
