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
//! Peaks are located as the tower's are: the extremes of every `θ_k` at the
//! roots of `θ̇_k` isolated on the dense output (`run.rs`, the engine's
//! search); the top's acceleration and each interface's friction demand at
//! the ends of every step (an event's instant where the step of the regime
//! that holds after it starts: a regime that another event ends at the same
//! instant is never read), and at the extrema inside a step
//! located on their exact time derivatives (Kane's equations solved on jets,
//! [`Instant`](super::run::Instant)), searched only where the cubic Hermite interpolant of the
//! ends comes near the running maximum ([`PEAK_MARGIN`]) or, for the demand,
//! where the interface's normal force falls low; the slip at the ends of
//! every step and at every event (its extremes are the ends of a slip).

use super::dynamics::{InterfaceLoad, Snapshot};
use super::geometry::Coordinates;
use super::run::{run_with, BlockSummary, Hook, RunSettings, StackEvent, StackEventKind, Stretch};
use super::{Interface, Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::equations::Kernel;
use crate::error::{Error, Parameter};
use crate::event::{Event, EventKind};
use crate::extrema::{above, hermite_range_reaches, interior_extrema, may_have_extremum, near_peak, PEAK_MARGIN};
use crate::ground::{GroundMotion, Piece};
use crate::jet::{Jet, Real};
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
    // Once, at the start: its size is immaterial.
    reporter.instant::<MAX_BLOCKS>(&regime, &start, 0.0);
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
/// `a_g`: the ground's acceleration there; `coords`: the regime's coordinates.
fn sample(stack: &Stack, kernel: &Kernel, a_g: f64, coords: &Coordinates, regime: &StackRegime, state: &StackState, t: f64) -> Sample {
    let (theta_ddot, slip_acc) = stack.accelerations_in(coords, regime, state, a_g, stack.gravity());
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

/// What the summary reads of the motion at an instant (on plain numbers, or
/// on jets for the slopes): the tower's top acceleration and the load each
/// interface carries.
struct Peaks<T, const N: usize> {
    top: T,
    loads: [InterfaceLoad<T>; N],
}

impl<T: Real, const N: usize> Peaks<T, N> {
    /// The peaks of `snap`, Kane's equations solved in `regime`.
    fn of(stack: &Stack, kernel: &Kernel, regime: &StackRegime, snap: &Snapshot<T, N>) -> Self {
        let pose = &snap.pose;
        let (_, top) = kernel.point_kinematics(
            regime.interfaces[0].pivot().map(Pivot::sign),
            (0.0, kernel.height),
            pose.phi[0].sin_cos(),
            pose.phi_dot[0],
            snap.theta_ddot[0],
            snap.a_g + snap.slip_acc,
        );
        let zero = T::from(0.0);
        let mut loads = [InterfaceLoad {
            tangential: zero,
            normal: zero,
            moment: zero,
        }; N];
        for (k, load) in loads.iter_mut().enumerate().take(stack.len()) {
            *load = stack.interface_load(snap, k);
        }
        Self { top, loads }
    }
}

impl<O: Observer> Reporter<'_, O> {
    /// The peaks at one instant: the tower's rotation and top acceleration,
    /// the slip, and every interface's friction demand (of a stack of `N`
    /// blocks).
    fn instant<const N: usize>(&mut self, regime: &StackRegime, state: &StackState, t: f64) {
        let snap = self
            .stack
            .snapshot_of::<f64, N>(regime, &state.theta, &state.theta_dot, self.ground.acceleration(t), self.stack.gravity());
        self.tracker.displacement(state.theta[0], state.slip);
        self.read(&Peaks::of(self.stack, self.kernel, regime, &snap));
    }

    /// Keeps the peaks of one instant.
    fn read<const N: usize>(&mut self, peaks: &Peaks<f64, N>) {
        self.tracker.top(peaks.top);
        for k in 0..self.stack.len() {
            let load = peaks.loads[k];
            if k == 0 {
                self.tracker.pivot(load.tangential, load.normal);
            }
            self.demand[k] = self.demand[k].max(load.friction_demand());
        }
    }

    /// The values of `peaks` on jets.
    fn values<const N: usize>(peaks: &Peaks<Jet, N>) -> Peaks<f64, N> {
        Peaks {
            top: peaks.top.v,
            loads: std::array::from_fn(|k| peaks.loads[k].values()),
        }
    }

    /// The peaks inside a step whose ends' peaks are `p0`, `p1`, up to
    /// where its motion holds: each quantity's extrema located on its exact
    /// slopes where one could raise what is kept (the tower's rule,
    /// `engine::peaks`).
    fn inside<const N: usize>(&mut self, regime: &StackRegime, stretch: &Stretch<N>, p0: &Peaks<Jet, N>, p1: &Peaks<Jet, N>) {
        let (t0, t1, reached) = (stretch.t0, stretch.t1, stretch.reached);
        let h = t1 - t0;
        let (stack, kernel) = (self.stack, self.kernel);
        let at = |t: f64| Peaks::of(stack, kernel, regime, &(stretch.inside)(t).snap);
        let kept = self.tracker.summary.max_top_abs_acceleration;
        if near_peak(p0.top, p1.top, h, kept) {
            interior_extrema(t0, p0.top, t1, p1.top, &mut |t| at(t).top, above(kept), &mut |t, v| {
                if t <= reached {
                    self.tracker.top(v);
                }
            });
        }
        for k in 0..stack.len() {
            if self.demand[k] == f64::INFINITY {
                // The blocks above have lost contact: the demand has no finite maximum.
                continue;
            }
            let weight = self.stack.gravity() * stack.blocks()[k..].iter().map(|b| b.mass()).sum::<f64>();
            let (n0, n1) = (p0.loads[k].normal, p1.loads[k].normal);
            let mut lost = false;
            if hermite_range_reaches(n0, n1, h, |(lo, _)| lo <= PEAK_MARGIN * weight) {
                interior_extrema(t0, n0, t1, n1, &mut |t| at(t).loads[k].normal, |(lo, _)| lo <= 0.0, &mut |t, v| {
                    lost |= t <= reached && v <= 0.0;
                });
            }
            if lost {
                self.demand[k] = f64::INFINITY;
                if k == 0 {
                    self.tracker.reaction_lost();
                }
                continue;
            }
            if n0.v <= 0.0 || n1.v <= 0.0 {
                continue;
            }
            // Near N = 0 the demand has a pole close by: every extremum matters there.
            let low = n0.v.min(n1.v) < 0.5 * weight;
            let ratio = |l: &InterfaceLoad<Jet>| l.tangential / l.normal;
            let (r0, r1) = (ratio(&p0.loads[k]), ratio(&p1.loads[k]));
            let kept = self.demand[k];
            let searched = if low { may_have_extremum(r0, r1, h) } else { near_peak(r0, r1, h, kept) };
            if searched {
                let mut found = arrayvec::ArrayVec::<f64, 4>::new();
                interior_extrema(
                    t0,
                    r0,
                    t1,
                    r1,
                    &mut |t| ratio(&at(t).loads[k]),
                    |range| low || above(kept)(range),
                    &mut |t, _| {
                        if t <= reached && !found.is_full() {
                            found.push(t);
                        }
                    },
                );
                for t in found {
                    let load = at(t).loads[k].values();
                    if k == 0 {
                        self.tracker.pivot(load.tangential, load.normal);
                    }
                    self.demand[k] = self.demand[k].max(load.friction_demand());
                }
            }
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

impl<O: Observer, const N: usize> Hook<N> for Reporter<'_, O> {
    fn wants_instants(&self) -> bool {
        true
    }

    fn step(&mut self, regime: &StackRegime, stretch: &Stretch<N>) -> Flow {
        let (t0, reached) = (stretch.t0, stretch.reached);
        self.tracker.time(project(regime).motion(), reached - t0);
        if let Some((start, end)) = stretch.ends {
            let (p0, p1) = (
                Peaks::of(self.stack, self.kernel, regime, &start.snap),
                Peaks::of(self.stack, self.kernel, regime, &end.snap),
            );
            // The step's start, in the regime that holds from there: the
            // instant after an event is read here, not at the event, where
            // a regime that another event ends at the same instant (an
            // impact that sets the building sliding and lifts a seated
            // block) would count loads the contacts never carry.
            if reached > t0 {
                self.read(&Self::values(&p0));
            }
            self.inside(regime, stretch, &p0, &p1);
            if reached >= stretch.t1 {
                self.tracker.displacement(end.state.theta[0], end.state.slip);
                self.read(&Self::values(&p1));
            }
        }
        if reached < stretch.t1 {
            // The motion ends at a transition inside the step: its last instant.
            self.instant::<N>(regime, &stretch.last, reached);
        }
        self.last = (reached, *regime, stretch.last);
        if self.observer.wants_steps() {
            let (stack, kernel, ground, segment) = (self.stack, self.kernel, self.ground, self.ground.segment(t0));
            let coords = Coordinates::of(stack, regime);
            // The step's piece of the input holds up to its next kink, where
            // the input's next piece starts (and a jump takes its value).
            let a_g = |t: f64| if t < segment.kink { segment.piece.eval(t) } else { ground.acceleration(t) };
            let sampler = |t: f64| sample(stack, kernel, a_g(t), &coords, regime, &(stretch.at)(t), t);
            let step = Step {
                kernel: self.kernel,
                piece: segment.piece,
                vpiece: Piece::Constant(0.0),
                interpolant: Interpolant::Constant(State::default()),
                t0,
                t1: reached,
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
            // As the tower's that falls straight back: a rest, no impact.
            StackEventKind::SetDown(k) => events.push(one(EventKind::Rest, k, &event.before, &event.after)),
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
        // The regime's loads are read where its step starts ([`Hook::step`]).
        self.tracker.displacement(event.after.theta[0], event.after.slip);
        self.last = (t, event.regime, event.after);
        ControlFlow::Continue(())
    }
}
