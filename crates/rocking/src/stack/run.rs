//! A time-stepper for the stack: DOP853 over the regimes of the stack, each
//! regime change located by root finding on the dense output.
//!
//! Between events the state `(θ_1 … θ_N, θ̇_1 … θ̇_N, u, u̇)` follows Kane's
//! equations of the current regime ([`Stack::snapshot`]); a stuck interface's
//! `θ_k` and a sticking building's `u̇` stay 0. The conditions watched in a
//! regime, each a function that turns from negative to non-negative when its
//! transition is due:
//!
//! | regime | function | transition |
//! |---|---|---|
//! | interface `k` rocking on `s_k` | `−s_k θ_k` | impact ([`Stack::impact`]) |
//! | interface `k` rocking | `|θ_k| − π/2` | overturning: the run stops |
//! | interface `k` stuck | `|M_k| − N_k B_k/2` | uplift on `s_k = sgn M_k` |
//! | building sticking | `|F_req| − μs N` | slip, `σ = −sgn F_req` |
//! | building slipping `σ` | `−σ u̇` | stick, or slip reversed |
//!
//! A condition that already holds when a regime is entered switches at once.
//! An impact that leaves its interface turning slower than
//! [`REST_ANGULAR_VELOCITY`](crate::REST_ANGULAR_VELOCITY) seats it (the end of an accumulation of ever
//! smaller impacts), as the tower's.
//!
//! Transitions are located by the engine's search (`engine::crossing`):
//! the conditions of `θ_k` (impact, overturning) are monotone between the
//! extremes of `θ_k`, the roots of `θ̇_k` isolated on the dense output, and
//! the end of a slip is bracketed by the first root of `u̇`; the uplift of a
//! stuck interface and the slip of a sticking building, which need Kane's
//! equations, are split into monotone parts at their extrema inside the
//! step, located on their exact time derivatives (Kane's equations solved
//! on jets, [`Instant`]) as the tower's stuck building's demand is (the
//! search starts from the cubic Hermite interpolant of the exact end values
//! and slopes, and a step where it shows no interior extremum is not
//! searched). The first bracket is narrowed by root finding; a condition on
//! zero at the step's start (an impact, a stop of the slip) is armed where
//! the motion has left it. The same extremes of `θ_k` give each block's
//! peaks. Every step ends at the next kink of the ground motion.
//!
//! The dense output is built only when a search inside the step asks for
//! it. Where one interface alone rocks on a sticking building or a fixed
//! base, the bounds of its body's `|θ̈_k|` and `|θ⃛_k|`
//! ([`Stack::one_rocking_acceleration_bound`]) may prove, as the tower's
//! screen does, that `θ̇_k` keeps its sign over the step: `θ_k` is then
//! monotone, its extremes are the step's ends, and a step whose conditions
//! show nothing at its ends builds none.

use super::dynamics::Snapshot;
use super::geometry::Coordinates;
use super::{Interface, Stack, StackRegime, StackState, MAX_BLOCKS};
use crate::condition::Condition;
use crate::engine::crossing::{extremes, first_crossing, first_root, leaving_point, OnZero, Points};
use crate::engine::screen::free_of_roots;
use crate::error::Error;
use crate::extrema::interior_extrema;
use crate::ground::{GroundMotion, Piece};
use crate::integrator::{find_crossing, find_crossing_newton, DenseOutput, Dop853, StepFailure};
use crate::jet::{Jet, Real};
use crate::observer::Flow;
use crate::regime::{BuildingRegime, Pivot, SlipDirection};
use crate::simulate::impact_ends_at_rest;
use std::cell::LazyCell;
use std::ops::{ControlFlow, Deref};

/// How a stack is run.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RunSettings {
    /// Duration (s).
    pub duration: f64,
    /// Relative tolerance of the integrator.
    pub rtol: f64,
    /// Absolute tolerance of the integrator.
    pub atol: f64,
    /// Spacing of the recorded samples (s).
    pub sample_interval: f64,
}

impl Default for RunSettings {
    fn default() -> Self {
        Self {
            duration: 10.0,
            rtol: 1e-10,
            atol: 1e-12,
            sample_interval: 0.01,
        }
    }
}

/// What happened at an event.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StackEventKind {
    /// Interface `k` (0-based) started rocking.
    Uplift(usize),
    /// Interface `k` landed on its other corner.
    Impact(usize),
    /// Interface `k` came to rest: an impact left it seated.
    Rest(usize),
    /// Interface `k` was set down without an impact: it lifted and fell
    /// straight back, never leaving `θ_k = 0` by more than rounding (a
    /// grazing uplift, the uplift condition met at its peak), as the tower's.
    /// Its uplift is not taken again until its condition has been negative.
    SetDown(usize),
    /// Block `k` overturned; the run stopped.
    Overturn(usize),
    /// The building started slipping (or reversed).
    Slip,
    /// The building stuck.
    Stick,
}

/// One regime change.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StackEvent {
    /// Time (s).
    pub time: f64,
    /// What happened.
    pub kind: StackEventKind,
    /// The regime before it.
    pub regime_before: StackRegime,
    /// The state just before it.
    pub before: StackState,
    /// The regime after it.
    pub regime: StackRegime,
    /// The state just after it.
    pub after: StackState,
    /// For an impact, the largest impulse ratio of a seated interface through it.
    pub seat_impulse_ratio: f64,
}

/// The state at one sampling instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StackSample {
    /// Time (s).
    pub time: f64,
    /// The state.
    pub state: StackState,
    /// The regime.
    pub regime: StackRegime,
}

/// What a run says of one block.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BlockSummary {
    /// The largest `|θ_k|` (rad), located where `θ̇_k` changes sign inside a
    /// step (by root finding on the dense output) or at an event.
    pub max_abs_theta: f64,
    /// The least and the largest `θ_k` (rad), located as `max_abs_theta`.
    pub theta_range: (f64, f64),
    /// The largest friction demand `|T'| / N'` of the interface under the
    /// block ([`super::dynamics::InterfaceLoad::friction_demand`]; infinite
    /// where the blocks above lost contact): kept by [`crate::simulate`], 0
    /// from [`run`].
    pub max_friction_demand: f64,
    /// Impacts of the interface (those that seat it included).
    pub impacts: usize,
    /// The time (s) of the interface's first uplift, if one happened.
    pub first_uplift_time: Option<f64>,
}

impl BlockSummary {
    /// A value of `θ_k` reached.
    fn reach(&mut self, theta: f64) {
        self.theta_range = (self.theta_range.0.min(theta), self.theta_range.1.max(theta));
        self.max_abs_theta = self.max_abs_theta.max(theta.abs());
    }
}

/// What a run leaves.
#[derive(Debug, Clone, PartialEq)]
pub struct StackRun {
    /// Each block's summary, block 1 first.
    pub blocks: Vec<BlockSummary>,
    /// The states every `sample_interval` (and at the end).
    pub samples: Vec<StackSample>,
    /// Every regime change, in order.
    pub events: Vec<StackEvent>,
    /// The block that overturned (0-based), if one did.
    pub overturned: Option<usize>,
    /// The largest `|M_imp| / (V_imp B_j / 2)` of a seated interface through
    /// an impact elsewhere over the run (0 without such impacts).
    pub max_seat_impulse_ratio: f64,
    /// Right-hand side evaluations of the stepping (not of event location).
    pub evaluations: u64,
}

/// The regime the initial state puts the stack in: an interface leaning or
/// turning rocks on the side it leans (or turns) to; a building moving slips.
pub fn initial_regime(stack: &Stack, initial: &StackState) -> StackRegime {
    let mut regime = StackRegime::REST;
    for k in 0..stack.len() {
        let side = if initial.theta[k] != 0.0 { initial.theta[k] } else { initial.theta_dot[k] };
        if side != 0.0 {
            regime.interfaces[k] = Interface::Rocking(Pivot::of_sign(side));
        }
    }
    if stack.building.is_some() && initial.slip_vel != 0.0 {
        regime.building = BuildingRegime::Slip(SlipDirection::of_sign(initial.slip_vel));
    }
    regime
}

/// One instant of a step seen with exact time slopes: the state there and
/// Kane's equations solved on jets (`θ_k` with `θ̇_k`, `θ̇_k` with `θ̈_k`,
/// `a_g` with `ȧ_g`), so that every quantity of the motion comes with its
/// time derivative along it. The search for the transitions that need
/// Kane's equations reads their conditions here, and the [`Hook`]'s peaks
/// read the same solve. Of a stack of `N` blocks at most.
#[derive(Debug, Clone)]
pub(crate) struct Instant<const N: usize> {
    /// The state.
    pub(crate) state: StackState,
    /// The motion there, with time derivatives.
    pub(crate) snap: Snapshot<Jet, N>,
}

/// A stretch of smooth motion handed to the [`Hook`]: the accepted step
/// `[t0, t1]`, the motion holding up to `reached` (its first transition, or
/// `t1`).
pub(crate) struct Stretch<'a, const N: usize> {
    /// The step's start (s).
    pub(crate) t0: f64,
    /// The step's end (s).
    pub(crate) t1: f64,
    /// Where the motion of the regime ends in it (s).
    pub(crate) reached: f64,
    /// The state there.
    pub(crate) last: StackState,
    /// The state at any instant of the step.
    pub(crate) at: &'a dyn Fn(f64) -> StackState,
    /// The instants at the step's two ends, when the hook asked for them
    /// ([`Hook::wants_instants`]).
    pub(crate) ends: Option<(&'a Instant<N>, &'a Instant<N>)>,
    /// An instant anywhere inside the step.
    pub(crate) inside: &'a dyn Fn(f64) -> Instant<N>,
}

/// Runs `stack` under the horizontal `ground` motion from `initial`.
pub fn run(stack: &Stack, ground: &GroundMotion, initial: &StackState, settings: &RunSettings) -> Result<StackRun, Error> {
    run_with(stack, ground, initial, settings, &mut ())
}

/// What a run tells as it goes, besides what it keeps in [`StackRun`]: each
/// stretch of smooth motion and each regime change. Either may end the run
/// (an observer's `ControlFlow::Break`). Of a stack of `N` blocks: a hook
/// of every size is a [`Hooks`].
pub(crate) trait Hook<const N: usize> {
    /// Whether [`Hook::step`] reads the instants at a step's ends.
    fn wants_instants(&self) -> bool {
        false
    }
    /// The motion of `regime` over a step.
    fn step(&mut self, _regime: &StackRegime, _stretch: &Stretch<N>) -> Flow {
        Flow::Continue(())
    }
    /// A regime change.
    fn event(&mut self, _event: &StackEvent) -> Flow {
        Flow::Continue(())
    }
}

impl<const N: usize> Hook<N> for () {}

/// A [`Hook`] for a stack of any size: of the runner's two sizes of
/// instants ([`run_with`]).
pub(crate) trait Hooks: Hook<2> + Hook<MAX_BLOCKS> {}

impl<H: Hook<2> + Hook<MAX_BLOCKS>> Hooks for H {}

/// [`run`], telling `hook` the steps and events as they come. The runner's
/// state holds `S = 2n + 2` numbers for the stack's `n` blocks, and its
/// instants `N >= n` blocks: two for a stack of one or two (a belfry on its
/// shaft, the common stack), [`MAX_BLOCKS`] for more. Instants sized for
/// six blocks cost a belfry's runs under a record 5.6 % to 16 % more
/// instructions (their copies from step to step); each size is a copy of
/// the run in the binary, which for every size from one to six made the
/// page's WebAssembly 16 % larger (docs/src/performance.md).
pub(crate) fn run_with(stack: &Stack, ground: &GroundMotion, initial: &StackState, settings: &RunSettings, hook: &mut impl Hooks) -> Result<StackRun, Error> {
    macro_rules! sized {
        ($($n:literal => ($blocks:expr, $s:literal)),*) => {
            match stack.len() {
                $($n => Runner::<{ $blocks }, $s> { stack, ground, settings }.run(initial, hook),)*
                _ => unreachable!("a stack has 1 to MAX_BLOCKS blocks"),
            }
        };
    }
    sized!(1 => (2, 4), 2 => (2, 6), 3 => (MAX_BLOCKS, 8), 4 => (MAX_BLOCKS, 10), 5 => (MAX_BLOCKS, 12), 6 => (MAX_BLOCKS, 14))
}

const _: () = assert!(MAX_BLOCKS == 6, "the dispatch in `run` lists every size");

/// The watched conditions of a regime.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Watch {
    Impact(usize),
    Overturn(usize),
    Uplift(usize),
    Slip,
    Stop,
}

impl Watch {
    /// The tower's condition of the same kind (an uplift or a slip whatever
    /// its side: the stack watches `|M_k|` and `|F_req|`), whose rules it
    /// follows: which conditions are of θ alone, and which depart from zero.
    fn kind(self) -> Condition {
        match self {
            Watch::Impact(_) => Condition::Impact,
            Watch::Overturn(_) => Condition::Overturn,
            Watch::Uplift(_) => Condition::UpliftPositive,
            Watch::Slip => Condition::SlipPositive,
            Watch::Stop => Condition::SlipStop,
        }
    }

    /// The condition as one of `θ_k` alone, if it is: the tower's impact or
    /// overturning ([`Condition::theta_margin`]) on the corner `s_k` the
    /// interface rocks on.
    fn of_theta(self, regime: &StackRegime) -> Option<(usize, OfTheta)> {
        let (Watch::Impact(k) | Watch::Overturn(k)) = self else { return None };
        let s = regime.interfaces[k].pivot().map_or(0.0, Pivot::sign);
        Some((k, OfTheta { condition: self.kind(), s }))
    }

    /// Whether the condition needs Kane's equations (it is read on the
    /// [`Instant`]s of a step): neither of θ alone nor the end of a slip.
    fn sampled(self) -> bool {
        !self.kind().of_theta() && self != Watch::Stop
    }

    /// How the condition is taken on zero at a step's start: as the tower's
    /// ([`OnZero::of`]); `fell_back`: the interface set down at that instant
    /// ([`StackEventKind::SetDown`]), whose uplift waits.
    fn on_zero(self, fell_back: Option<usize>) -> OnZero {
        OnZero::of(self.kind(), matches!(self, Watch::Uplift(k) if fell_back == Some(k)))
    }
}

/// A condition of `θ_k` alone: the engine's impact or overturning of a block
/// rocking on the corner `s` (the sign; 0 on none).
#[derive(Debug, Clone, Copy, PartialEq)]
struct OfTheta {
    condition: Condition,
    s: f64,
}

impl OfTheta {
    /// The condition and its rate at `θ_k`, `θ̇_k`.
    fn margin(self, theta: f64, theta_dot: f64) -> (f64, f64) {
        let m = self.condition.theta_margin(self.s, Jet::new(theta, theta_dot));
        (m.v, m.d)
    }
}

/// The interface set down at `t`, if `fell_back` (the last one set down and
/// the instant) is at `t`.
fn set_down_at(fell_back: Option<(usize, f64)>, t: f64) -> Option<usize> {
    fell_back.filter(|&(_, at)| at.to_bits() == t.to_bits()).map(|(k, _)| k)
}

/// `points` of a Kane condition (ordered, the condition monotone between
/// consecutive ones) from the last of those at its start that are zero:
/// zero at two consecutive points is zero all along (the demand of a
/// building at rest without friction, `|F| = μs N = 0`). It has not grown
/// there: the search starts where it last is zero, which the motion may
/// leave.
fn from_last_zero(points: &[(f64, f64)]) -> &[(f64, f64)] {
    let stays = points.windows(2).take_while(|w| w[0].1 == 0.0 && w[1].1 == 0.0).count();
    &points[stays..]
}

/// The regime switches counted at one instant, and within a short window.
#[derive(Debug, Default)]
struct Switches {
    /// The instant (s).
    time: f64,
    /// How many there were at it.
    count: usize,
    /// The start of the window (s).
    window: f64,
    /// How many there were in it.
    in_window: usize,
}

impl Switches {
    /// The most switches at one instant.
    const MAX: usize = 4 * MAX_BLOCKS + 4;
    /// The length of the window (s).
    const WINDOW: f64 = 1e-3;
    /// The most switches in one window: an impact cascade cut at
    /// [`REST_ANGULAR_VELOCITY`](crate::REST_ANGULAR_VELOCITY) takes a few
    /// hundred (`ln(θ̇/1e-9) / ln(1/r)`, 200 for θ̇ = 1 rad/s and r = 0.9);
    /// ten thousand in a millisecond are interfaces that lift and land again
    /// at velocities about that threshold without end (one block lifting
    /// as another lands, events some 1e-8 s apart), a motion the run would
    /// take hours to follow for nothing: it stops there.
    const MAX_IN_WINDOW: usize = 10_000;

    /// Counts a switch at `t`: an error past [`Switches::MAX`] at one instant
    /// or [`Switches::MAX_IN_WINDOW`] in one window.
    fn count(&mut self, t: f64) -> Result<(), Error> {
        if t.to_bits() == self.time.to_bits() {
            self.count += 1;
        } else {
            (self.time, self.count) = (t, 1);
        }
        if t - self.window > Self::WINDOW {
            (self.window, self.in_window) = (t, 1);
        } else {
            self.in_window += 1;
        }
        if self.count > Self::MAX || self.in_window > Self::MAX_IN_WINDOW {
            return Err(Error::Chattering {
                time: t,
                last: "stack transition",
            });
        }
        Ok(())
    }
}

/// The [`Instant`] at the start of a round and the right-hand side there,
/// computed by [`Runner::due_now`] when a condition needs them: they open
/// the regime's first step.
type Opening<const N: usize, const S: usize> = (Instant<N>, [f64; S]);

/// Where a run goes after a step or a round.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Next {
    /// The next step of the same regime.
    Step,
    /// A new round from the time reached: a transition was applied, or the
    /// input reached a kink.
    Restart,
    /// The run is over: its end, or an overturning.
    End,
}

/// What a run carries from one step to the next, of a state of `S` numbers.
struct Progress<const S: usize> {
    /// What the run leaves, as far as it went.
    out: StackRun,
    /// The regime at `t`.
    regime: StackRegime,
    /// The state at `t`.
    state: StackState,
    /// The time reached (s).
    t: f64,
    /// The index of the next sample due.
    next_sample: usize,
    /// The interface last set down and the instant ([`StackEventKind::SetDown`]).
    fell_back: Option<(usize, f64)>,
    /// The regime switches at one instant: those that hold at once and the
    /// crossings a step finds at its very start, which do not advance the
    /// time either. Beyond a few per interface they do not settle.
    switches: Switches,
    /// The integrator, its last step kept for the dense output.
    stepper: Dop853<S>,
}

/// The motion of one regime from a round's start up to its first
/// transition, the input's next kink or the run's end: what each of its
/// steps reads.
struct Phase<'a> {
    /// The regime.
    regime: StackRegime,
    /// The input's piece, which holds up to `kink`.
    piece: Piece,
    /// The input's next kink, or the run's end (s).
    kink: f64,
    /// The regime's coordinates.
    coords: &'a Coordinates,
    /// Whether a condition that needs Kane's equations is watched ([`Watch::sampled`]).
    sampled: bool,
    /// Whether the steps' ends are read as [`Instant`]s: for such a
    /// condition, or for the hook ([`Hook::wants_instants`]).
    wants_instants: bool,
}

/// One accepted step `[t0, t1]` as the search for its first crossing reads
/// it, of a stack of `N` blocks at most.
#[derive(Clone, Copy)]
struct Step<'a, D, const N: usize> {
    /// The dense output over the step (built on first use).
    dense: &'a D,
    /// `(t0, t1)` (s).
    span: (f64, f64),
    /// The states at the step's ends.
    edges: (&'a StackState, &'a StackState),
    /// The extremes of each `θ_k` inside the step.
    theta_points: &'a [Points; N],
    /// The [`Instant`]s at the step's ends, if they were computed.
    ends: Option<(&'a Instant<N>, &'a Instant<N>)>,
}

struct Runner<'a, const N: usize, const S: usize> {
    stack: &'a Stack,
    ground: &'a GroundMotion,
    settings: &'a RunSettings,
}

impl<const N: usize, const S: usize> Runner<'_, N, S> {
    /// The number of blocks (`N` or fewer).
    fn n(&self) -> usize {
        (S - 2) / 2
    }

    fn pack(&self, state: &StackState) -> [f64; S] {
        let n = self.n();
        let mut y = [0.0; S];
        y[..n].copy_from_slice(&state.theta[..n]);
        y[n..2 * n].copy_from_slice(&state.theta_dot[..n]);
        y[2 * n] = state.slip;
        y[2 * n + 1] = state.slip_vel;
        y
    }

    fn unpack(&self, y: &[f64; S]) -> StackState {
        let n = self.n();
        let mut state = StackState::default();
        state.theta[..n].copy_from_slice(&y[..n]);
        state.theta_dot[..n].copy_from_slice(&y[n..2 * n]);
        state.slip = y[2 * n];
        state.slip_vel = y[2 * n + 1];
        state
    }

    /// The right-hand side of `regime` at `t`, the ground's acceleration from
    /// `piece` (the step's: every step ends at the next kink of the input),
    /// in the regime's coordinates `coords` (built once for it).
    fn rhs(&self, coords: &Coordinates, regime: &StackRegime, piece: &Piece, t: f64, y: &[f64; S]) -> [f64; S] {
        let n = self.n();
        let state = self.unpack(y);
        let (theta_ddot, slip_acc) = self.stack.accelerations_in(coords, regime, &state, piece.eval(t), self.stack.gravity);
        let mut dy = [0.0; S];
        for k in 0..n {
            if regime.interfaces[k] != Interface::Stuck {
                dy[k] = y[n + k];
                dy[n + k] = theta_ddot[k];
            }
        }
        if matches!(regime.building, BuildingRegime::Slip(_)) {
            dy[2 * n] = y[2 * n + 1];
            dy[2 * n + 1] = slip_acc;
        }
        dy
    }

    /// The [`Instant`] at `t` in the state `y`, whose rate is `rate` (the
    /// right-hand side there).
    fn instant(&self, regime: &StackRegime, piece: &Piece, t: f64, y: &[f64; S], rate: &[f64; S]) -> Instant<N> {
        let n = self.n();
        // Components `from … from + n` of the state, each with its rate.
        let jets = |from: usize| -> [Jet; N] { std::array::from_fn(|k| if k < n { Jet::new(y[from + k], rate[from + k]) } else { Jet::default() }) };
        Instant {
            state: self.unpack(y),
            snap: self
                .stack
                .snapshot_of(regime, &jets(0), &jets(n), piece.eval_jet(t), Jet::from(self.stack.gravity)),
        }
    }

    /// The [`Instant`] at `t` inside the step of `dense`.
    fn instant_on(&self, regime: &StackRegime, piece: &Piece, dense: &DenseOutput<S>, t: f64) -> Instant<N> {
        let y = dense.state(t);
        self.instant(regime, piece, t, &y, &self.rhs(&Coordinates::of(self.stack, regime), regime, piece, t, &y))
    }

    fn watches(&self, regime: &StackRegime) -> arrayvec::ArrayVec<Watch, { 2 * MAX_BLOCKS + 1 }> {
        let mut w = arrayvec::ArrayVec::new();
        for k in 0..self.n() {
            if regime.interfaces[k] == Interface::Stuck {
                w.push(Watch::Uplift(k));
            } else {
                w.push(Watch::Impact(k));
                w.push(Watch::Overturn(k));
            }
        }
        if self.stack.building.is_some() {
            w.push(match regime.building {
                BuildingRegime::Stick => Watch::Slip,
                BuildingRegime::Slip(_) => Watch::Stop,
            });
        }
        w
    }

    /// [`Stack::snapshot`] sized to the stack.
    fn snapshot(&self, regime: &StackRegime, state: &StackState, a_g: f64) -> Snapshot<f64, N> {
        self.stack.snapshot_of(regime, &state.theta, &state.theta_dot, a_g, self.stack.gravity)
    }

    /// The value of a watched condition: negative while its transition is not
    /// due. `piece`: the ground motion's piece at `t`.
    fn value(&self, regime: &StackRegime, piece: &Piece, watch: Watch, t: f64, state: &StackState) -> f64 {
        match watch {
            Watch::Impact(k) | Watch::Overturn(k) => match watch.of_theta(regime) {
                Some((_, c)) => c.margin(state.theta[k], state.theta_dot[k]).0,
                None => -1.0,
            },
            Watch::Stop => match regime.building {
                BuildingRegime::Slip(d) => -d.sign() * state.slip_vel,
                BuildingRegime::Stick => -1.0,
            },
            Watch::Uplift(_) | Watch::Slip => self.condition(watch, &self.snapshot(regime, state, piece.eval(t))),
        }
    }

    /// The value of a condition that needs Kane's equations ([`Watch::sampled`]),
    /// from their solve `snap` (on plain numbers, or on jets for its slope):
    /// the uplift of a stuck interface, else the slip of the sticking
    /// building, `|F_req| − μs N`.
    fn condition<T: Real>(&self, watch: Watch, snap: &Snapshot<T, N>) -> T {
        if let Watch::Uplift(k) = watch {
            return self.stack.uplift_margin(snap, k).0;
        }
        let demand = self.stack.friction_force(snap);
        self.stack
            .friction()
            .static_friction_margin(demand * demand.value().signum(), self.stack.normal_force(snap))
    }

    /// The building's regime at `u̇ = 0`: stuck if the friction it needs
    /// stays within `μs N`, else slipping against that need.
    fn building_at_rest(&self, regime: &StackRegime, t: f64, state: &StackState) -> BuildingRegime {
        let stuck = StackRegime {
            building: BuildingRegime::Stick,
            ..*regime
        };
        let snap = self.snapshot(&stuck, state, self.ground.acceleration(t));
        let demand = self.stack.friction_force(&snap);
        if !self.stack.friction().sticks(demand, self.stack.normal_force(&snap)) {
            BuildingRegime::Slip(SlipDirection::of_sign(-demand))
        } else {
            BuildingRegime::Stick
        }
    }

    /// The side a slip of the sticking building starts towards at `t`: the
    /// demand reached μs N, and the building slips against it, even where
    /// the root lies exactly on the equality. Where the demand itself is
    /// zero (a building without friction, μs = 0, under an input that starts
    /// from zero) its sign says nothing: the slip starts against its growth,
    /// the sign of its time derivative, as the tower's slip condition of the
    /// side it grows towards is the one that holds (`engine::transition`).
    fn slip_side(&self, regime: &StackRegime, t: f64, state: &StackState) -> SlipDirection {
        let piece = self.ground.segment(t).piece;
        let snap = self.snapshot(regime, state, self.ground.acceleration(t));
        let demand = self.stack.friction_force(&snap);
        if demand != 0.0 {
            return SlipDirection::of_sign(-demand);
        }
        let y = self.pack(state);
        let rate = self.rhs(&Coordinates::of(self.stack, regime), regime, &piece, t, &y);
        let growth = self.stack.friction_force(&self.instant(regime, &piece, t, &y, &rate).snap).d;
        SlipDirection::of_sign(-growth)
    }

    /// The transition of `watch`, due at `t`: the new regime and state, the
    /// event's kind and the seat impulse ratio of an impact.
    fn switch(&self, regime: &StackRegime, watch: Watch, t: f64, state: &StackState) -> (StackRegime, StackState, StackEventKind, f64) {
        let mut state = *state;
        match watch {
            Watch::Impact(k) if self.falls_straight_back(regime, k, t, &state) => {
                state.theta[k] = 0.0;
                state.theta_dot[k] = 0.0;
                (regime.with(k, Interface::Stuck), state, StackEventKind::SetDown(k), 0.0)
            }
            Watch::Impact(k) => {
                let out = self.stack.impact(regime, &state, k);
                let (mut regime, mut state) = (out.regime, out.state);
                let mut kind = StackEventKind::Impact(k);
                if regime.interfaces[k] != Interface::Stuck && impact_ends_at_rest(state.theta_dot[k]) {
                    regime.interfaces[k] = Interface::Stuck;
                }
                if regime.interfaces[k] == Interface::Stuck {
                    state.theta_dot[k] = 0.0;
                    kind = StackEventKind::Rest(k);
                }
                (regime, state, kind, out.seat_impulse_ratio)
            }
            Watch::Overturn(k) => (*regime, state, StackEventKind::Overturn(k), 0.0),
            Watch::Uplift(k) => {
                let snap = self.snapshot(regime, &state, self.ground.acceleration(t));
                let corner = self.stack.uplift_margin(&snap, k).1;
                state.theta[k] = 0.0;
                state.theta_dot[k] = 0.0;
                (
                    regime.with(k, Interface::Rocking(Pivot::of_sign(corner))),
                    state,
                    StackEventKind::Uplift(k),
                    0.0,
                )
            }
            Watch::Slip => {
                let building = BuildingRegime::Slip(self.slip_side(regime, t, &state));
                (regime.with_building(building), state, StackEventKind::Slip, 0.0)
            }
            Watch::Stop => {
                state.slip_vel = 0.0;
                let building = self.building_at_rest(regime, t, &state);
                let kind = if building == BuildingRegime::Stick {
                    StackEventKind::Stick
                } else {
                    StackEventKind::Slip
                };
                (regime.with_building(building), state, kind, 0.0)
            }
        }
    }

    /// Whether interface `k`, reaching `θ_k = 0` at `t`, fell straight back
    /// after its uplift rather than landing: it comes back slower than
    /// [`REST_ANGULAR_VELOCITY`](crate::REST_ANGULAR_VELOCITY), so an impact
    /// would seat it, while its uplift condition holds, so that it would lift
    /// again at once and return by the rounding of the same instant's
    /// derivatives, without end. That is the tower's grazing uplift
    /// (`fall straight back`): the block is set down, with no impact.
    fn falls_straight_back(&self, regime: &StackRegime, k: usize, t: f64, state: &StackState) -> bool {
        let seated = regime.with(k, Interface::Stuck);
        impact_ends_at_rest(state.theta_dot[k]) && self.value(&seated, &self.ground.segment(t).piece, Watch::Uplift(k), t, state) >= 0.0
    }

    /// The first watched condition that already holds at `t` (one that a
    /// regime is entered with switches at once); `fell_back`: the interface
    /// set down at this instant ([`StackEventKind::SetDown`]), whose uplift
    /// is not taken again here. The conditions that need Kane's equations
    /// read them once, in `opening`: the [`Instant`] at `t` with the
    /// right-hand side there, which open the next step if none holds (its
    /// values are those of the solve on plain numbers, bit for bit: the
    /// same operations).
    fn due_now(&self, regime: &StackRegime, t: f64, state: &StackState, fell_back: Option<usize>, opening: &mut Option<Opening<N, S>>) -> Option<Watch> {
        let piece = self.ground.segment(t).piece;
        self.watches(regime).into_iter().find(|&w| match w {
            // Crossings, not conditions: they are due only when reached from the other side.
            Watch::Impact(_) | Watch::Stop => false,
            Watch::Uplift(k) if fell_back == Some(k) => false,
            _ if w.sampled() => {
                let (instant, _) = opening.get_or_insert_with(|| {
                    let y = self.pack(state);
                    let rate = self.rhs(&Coordinates::of(self.stack, regime), regime, &piece, t, &y);
                    (self.instant(regime, &piece, t, &y, &rate), rate)
                });
                self.condition(w, &instant.snap).v > 0.0
            }
            _ => self.value(regime, &piece, w, t, state) > 0.0,
        })
    }

    /// Whether each rocking `θ̇_k` may vanish inside the step `[t0, t1]`
    /// (false for a stuck interface), from the states at the step's ends,
    /// `edges`, and their rates `rates` (the velocities' exact slopes): where
    /// interface `k` alone rocks on a sticking building or a fixed base, the
    /// bounds of the body's `|θ̈_k|` and `|θ⃛_k|` over the step
    /// ([`Stack::one_rocking_acceleration_bound`],
    /// [`Stack::one_rocking_jerk_bound`], with `max|θ̇_k| <= (|θ̇_k(t0)| +
    /// |θ̇_k(t1)| + max|θ̈_k| h) / 2`) may prove that it keeps its sign
    /// ([`free_of_roots`], the tower's proof); otherwise it is searched.
    fn theta_may_turn(
        &self,
        regime: &StackRegime,
        piece: &Piece,
        (t0, t1): (f64, f64),
        edges: (&StackState, &StackState),
        rates: (&[f64; S], &[f64; S]),
    ) -> [bool; N] {
        let n = self.n();
        let mut turns = [false; N];
        for (k, turn) in turns.iter_mut().enumerate().take(n) {
            *turn = regime.interfaces[k] != Interface::Stuck;
        }
        let Some((k, _)) = self.stack.rocking_one(regime) else { return turns };
        if matches!(regime.building, BuildingRegime::Slip(_)) {
            return turns;
        }
        let h = t1 - t0;
        let (bound, reach) = self.stack.one_rocking_acceleration_bound(k, self.stack.gravity, piece.max_abs(t0, t1));
        let (w0, w1) = (Jet::new(edges.0.theta_dot[k], rates.0[n + k]), Jet::new(edges.1.theta_dot[k], rates.1[n + k]));
        let w_max = 0.5 * (w0.v.abs() + w1.v.abs() + bound * h);
        let jerk = self.stack.one_rocking_jerk_bound(k, reach, piece.max_abs_rate(), w_max);
        turns[k] = !free_of_roots(w0, w1, h, bound, jerk);
        turns
    }

    /// The extremes of every rocking `θ_k` inside the step of `dense` (none
    /// for a stuck interface, nor where `turns` says `θ̇_k` keeps its sign):
    /// the points between which `θ_k` is monotone, shared by the search for
    /// impacts and overturning and by the peaks.
    fn theta_extremes(&self, turns: &[bool; N], dense: &impl Deref<Target = DenseOutput<S>>, t0: f64, t1: f64) -> [Points; N] {
        let n = self.n();
        let mut points: [Points; N] = std::array::from_fn(|_| Points::default());
        for (k, points) in points.iter_mut().enumerate().take(n) {
            if turns[k] {
                *points = extremes(dense, t0, t1, k, n + k);
            }
        }
        points
    }

    /// The earliest crossing of a watched condition of `phase` inside
    /// `step`; `fell_back`: the interface set down at the step's start.
    fn first_crossing<D: Deref<Target = DenseOutput<S>>>(&self, phase: &Phase<'_>, step: &Step<D, N>, fell_back: Option<usize>) -> Option<(Watch, f64)> {
        let n = self.n();
        let (regime, piece) = (&phase.regime, &phase.piece);
        let Step {
            dense,
            span: (t0, t1),
            edges,
            theta_points,
            ends,
        } = *step;
        let mut best: Option<(Watch, f64)> = None;
        for watch in self.watches(regime) {
            let value = |t: f64| self.value(regime, piece, watch, t, &self.unpack(&dense.state(t)));
            // Its values at the step's ends, where it is not read on the instants.
            let at_edges = || (self.value(regime, piece, watch, t0, edges.0), self.value(regime, piece, watch, t1, edges.1));
            let regula_falsi = |ta, va, tb, vb| find_crossing(value, ta, va, tb, vb, 0.0).tb;
            let leaving = |ta, tb| leaving_point(&value, ta, tb);
            let mut points = Points::default();
            let hit = if let Some((k, c)) = watch.of_theta(regime) {
                // Monotone between the extremes of θ_k; narrowed by Newton on
                // θ̇_k, on the dense output (built here if it was not yet).
                let narrow = |ta, va, tb, vb| {
                    let dense: &DenseOutput<S> = dense;
                    let at = |t: f64| {
                        let y = dense.state(t);
                        c.margin(y[k], y[n + k])
                    };
                    find_crossing_newton(at, ta, va, tb, vb).tb
                };
                let (start, end) = at_edges();
                points.push((t0, start));
                for &(t, theta) in theta_points[k].as_slice() {
                    points.push((t, c.margin(theta, 0.0).0));
                }
                points.push((t1, end));
                first_crossing(points.as_slice(), watch.on_zero(fell_back), narrow, leaving)
            } else if watch == Watch::Stop {
                // `−σ u̇`: of one sign up to the first root of u̇.
                let (start, end) = at_edges();
                points.push((t0, start));
                if let Some((ta, tb)) = first_root(&**dense, 2 * n + 1, t0, t1) {
                    points.push((ta, value(ta)));
                    points.push((tb, value(tb)));
                }
                points.push((t1, end));
                first_crossing(points.as_slice(), watch.on_zero(fell_back), regula_falsi, leaving)
            } else {
                // Kane's conditions: monotone between their extrema, located
                // on their exact slopes (the instants' jets). Only a maximum
                // that may reach zero can hold a crossing the ends do not
                // show: the others are not located.
                let inside = |t: f64| self.condition(watch, &self.instant_on(regime, piece, dense, t).snap);
                let (c0, c1) = match ends {
                    Some((start, end)) => (self.condition(watch, &start.snap), self.condition(watch, &end.snap)),
                    None => (inside(t0), inside(t1)),
                };
                points.push((t0, c0.v));
                interior_extrema(t0, c0, t1, c1, &mut |t| inside(t), |(_, hi)| hi >= 0.0, &mut |t, v| points.push((t, v)));
                points.push((t1, c1.v));
                first_crossing(from_last_zero(points.as_slice()), watch.on_zero(fell_back), regula_falsi, leaving)
            };
            if let Some(te) = hit {
                if best.is_none_or(|(_, tb)| te < tb) {
                    best = Some((watch, te));
                }
            }
        }
        best
    }

    fn run(&self, initial: &StackState, hook: &mut dyn Hook<N>) -> Result<StackRun, Error> {
        let mut run = self.start(initial);
        while self.round(&mut run, hook)? == Next::Restart {}
        run.out.evaluations = run.stepper.evaluations;
        Ok(run.out)
    }

    /// The run at `t = 0`: the regime the initial state puts the stack in,
    /// each block's peaks at its initial lean.
    fn start(&self, initial: &StackState) -> Progress<S> {
        let mut state = *initial;
        if self.stack.building.is_none() {
            state.slip_vel = 0.0;
        }
        let out = StackRun {
            blocks: (0..self.n())
                .map(|k| BlockSummary {
                    max_abs_theta: state.theta[k].abs(),
                    theta_range: (state.theta[k].min(0.0), state.theta[k].max(0.0)),
                    ..BlockSummary::default()
                })
                .collect(),
            samples: Vec::new(),
            events: Vec::new(),
            overturned: None,
            max_seat_impulse_ratio: 0.0,
            evaluations: 0,
        };
        Progress {
            out,
            regime: initial_regime(self.stack, initial),
            state,
            t: 0.0,
            next_sample: 0,
            fell_back: None,
            switches: Switches::default(),
            stepper: Dop853::new(self.settings.rtol, self.settings.atol),
        }
    }

    /// One round of the run from `run.t`: the transitions that hold at once
    /// (switched while one holds), then the regime they leave, at rest or
    /// integrated, up to its first transition, the input's next kink or the
    /// run's end. Says whether the run restarts from there or ends.
    fn round(&self, run: &mut Progress<S>, hook: &mut dyn Hook<N>) -> Result<Next, Error> {
        // The instant at `run.t` and the right-hand side there, if
        // `due_now` computed them for the regime that holds: they open its
        // first step. (Kept here rather than returned: it is large.)
        let mut opening = None;
        while let Some(watch) = self.due_now(&run.regime, run.t, &run.state, set_down_at(run.fell_back, run.t), &mut opening) {
            opening = None;
            if self.transition(run, watch, run.t, hook)? == Next::End {
                return Ok(Next::End);
            }
        }
        if run.t >= self.settings.duration {
            return Ok(Next::End);
        }
        if Coordinates::of(self.stack, &run.regime).is_empty() {
            // Nothing moves relative to the ground: no integration.
            return match self.at_rest(run, hook)? {
                Some(watch) => self.transition(run, watch, run.t, hook),
                None => Ok(Next::Restart),
            };
        }
        self.integrate(run, opening, hook)
    }

    /// Counts and applies the transition of `watch` at `t`; the run ends on
    /// an overturning, else restarts from `t`.
    fn transition(&self, run: &mut Progress<S>, watch: Watch, t: f64, hook: &mut dyn Hook<N>) -> Result<Next, Error> {
        run.switches.count(t)?;
        if self.apply(run, watch, t, hook)? {
            return Ok(Next::End);
        }
        if let Some(StackEventKind::SetDown(k)) = run.out.events.last().map(|e| e.kind) {
            run.fell_back = Some((k, t));
        }
        Ok(Next::Restart)
    }

    /// The regime of `run` integrated from `run.t`, step by step, up to its
    /// first transition, the input's next kink or the run's end; `opening`:
    /// the [`Instant`] at `run.t` and the right-hand side there, if
    /// computed.
    fn integrate(&self, run: &mut Progress<S>, opening: Option<Opening<N, S>>, hook: &mut dyn Hook<N>) -> Result<Next, Error> {
        let settings = self.settings;
        let y = self.pack(&run.state);
        // The input's piece holds up to its next kink, where the run restarts.
        let segment = self.ground.segment(run.t);
        // The instants at the steps' ends, for the conditions that need
        // Kane's equations and for the hook; each step's end is the next one's start.
        let sampled = self.watches(&run.regime).iter().any(|w| w.sampled());
        let coords = Coordinates::of(self.stack, &run.regime);
        let phase = Phase {
            regime: run.regime,
            piece: segment.piece,
            kink: segment.kink.min(settings.duration),
            coords: &coords,
            sampled,
            wants_instants: hook.wants_instants() || sampled,
        };
        let mut rhs = |t: f64, y: &[f64; S]| self.rhs(phase.coords, &phase.regime, &phase.piece, t, y);
        let mut start = match opening {
            Some((instant, rate)) => {
                // The right-hand side `due_now` evaluated here, counted as the restart's.
                run.stepper.evaluations += 1;
                run.stepper.restart_with(&mut rhs, run.t, y, rate, settings.duration);
                Some(instant)
            }
            None => {
                run.stepper.restart(&mut rhs, run.t, y, settings.duration);
                phase
                    .wants_instants
                    .then(|| self.instant(&phase.regime, &phase.piece, run.stepper.t, &run.stepper.y, &run.stepper.f))
            }
        };
        loop {
            match self.advance(run, &phase, &mut start, hook)? {
                Next::Step => {}
                next => return Ok(next),
            }
        }
    }

    /// One step of `phase`'s regime from `run.t`, `start` the [`Instant`]
    /// there if the phase wants them (the step's end on return): its peaks,
    /// its samples, the hook told, and the first transition inside it
    /// applied. Says whether the next step follows, or the run restarts
    /// (after a transition, at the input's kink) or ends.
    fn advance(&self, run: &mut Progress<S>, phase: &Phase<'_>, start: &mut Option<Instant<N>>, hook: &mut dyn Hook<N>) -> Result<Next, Error> {
        let mut rhs = |t: f64, y: &[f64; S]| self.rhs(phase.coords, &phase.regime, &phase.piece, t, y);
        // While a condition that needs Kane's equations is watched (a seated
        // block under a rocking one, a sticking building), steps end at the
        // input's extrema as well, so that the input is monotone on each; a
        // seated block's uplift inside one is searched on its exact slopes.
        // (A stack wholly at rest is not stepped: `at_rest`.)
        let bound = if phase.sampled {
            self.ground.segment(run.t).end.min(phase.kink)
        } else {
            phase.kink
        };
        let stepper = &mut run.stepper;
        stepper.step(&mut rhs, bound).map_err(|e| match e {
            StepFailure::StepSizeTooSmall { time } => Error::StepSizeTooSmall { time },
            StepFailure::NonFinite { time } => Error::Singular {
                time,
                reason: "the stack's equations have no solution (Painlevé's paradox of the dynamic normal force)".into(),
            },
        })?;
        let (t0, t1) = (stepper.t_old, stepper.t);
        let end = phase
            .wants_instants
            .then(|| self.instant(&phase.regime, &phase.piece, t1, &stepper.y, &stepper.f));
        let edges = (self.unpack(&stepper.y_old), self.unpack(&stepper.y));
        let turns = self.theta_may_turn(&phase.regime, &phase.piece, (t0, t1), (&edges.0, &edges.1), (&stepper.f_old(), &stepper.f));
        // Built on first use: a step that no search looks inside has none.
        let dense = LazyCell::new(|| stepper.dense(&mut rhs));
        let theta_points = self.theta_extremes(&turns, &dense, t0, t1);
        let step = Step {
            dense: &dense,
            span: (t0, t1),
            edges: (&edges.0, &edges.1),
            theta_points: &theta_points,
            ends: start.as_ref().zip(end.as_ref()),
        };
        let crossing = self.first_crossing(phase, &step, set_down_at(run.fell_back, t0));
        let reached = crossing.map_or(t1, |(_, te)| te);
        let last = match crossing {
            Some((_, te)) => self.unpack(&dense.state(te)),
            None => edges.1,
        };
        self.track_peaks(&mut run.out, &phase.regime, (&edges.0, &last), reached, &theta_points);
        let stretch = Stretch {
            t0,
            t1,
            reached,
            last,
            at: &|t| self.unpack(&dense.state(t)),
            ends: step.ends,
            inside: &|t| self.instant_on(&phase.regime, &phase.piece, &dense, t),
        };
        if let ControlFlow::Break(halt) = hook.step(&phase.regime, &stretch) {
            return Err(Error::halted(halt, t0));
        }
        self.take_samples(&mut run.out, &phase.regime, &mut run.next_sample, reached, |ts| self.unpack(&dense.state(ts)));
        run.t = reached;
        if let Some((watch, te)) = crossing {
            run.state = last;
            return self.transition(run, watch, te, hook);
        }
        run.state = edges.1;
        *start = end;
        if run.t >= self.settings.duration {
            return Ok(Next::End);
        }
        if phase.kink < self.settings.duration && run.t >= phase.kink {
            // A kink of the input: restart there (conditions may hold at once).
            return Ok(Next::Restart);
        }
        Ok(Next::Step)
    }

    /// The samples due up to `reached` (and the duration), the state at each
    /// from `at`.
    fn take_samples(&self, out: &mut StackRun, regime: &StackRegime, next_sample: &mut usize, reached: f64, at: impl Fn(f64) -> StackState) {
        let settings = self.settings;
        while (*next_sample as f64) * settings.sample_interval <= reached && (*next_sample as f64) * settings.sample_interval <= settings.duration {
            let ts = *next_sample as f64 * settings.sample_interval;
            out.samples.push(StackSample {
                time: ts,
                state: at(ts),
                regime: *regime,
            });
            *next_sample += 1;
        }
    }

    /// The stack at rest from `run.t` (every interface stuck, the building
    /// sticking or none), up to the first watched condition met, or the end
    /// of the run: nothing moves relative to the ground, so the state is
    /// constant and each condition follows the input alone. Every block
    /// moves with the ground, so `M_k`, the loads along the surfaces and
    /// `F_req` are affine in `a_g` and the normal forces constant: each
    /// interface's uplift `|M_k| − N_k B_k/2` and the building's slip
    /// `|F_req| − μs N` are convex in `a_g`. On a monotone stretch of the
    /// input such a condition is at most its larger end, and crosses zero at
    /// most once upwards. As the tower's static phase, the run moves from one
    /// stretch to the next, or to the first crossing on the way, with no
    /// integration. Leaves `run.t` where it stopped and returns the
    /// condition met there, if one was.
    fn at_rest(&self, run: &mut Progress<S>, hook: &mut dyn Hook<N>) -> Result<Option<Watch>, Error> {
        let (regime, state) = (&run.regime, &run.state);
        let mut t = run.t;
        // The interface set down at `t`, whose uplift waits.
        let mut fell_back = set_down_at(run.fell_back, t);
        let y = self.pack(state);
        let watches = self.watches(regime);
        while t < self.settings.duration {
            let segment = self.ground.segment(t);
            let (piece, t1) = (segment.piece, segment.end.min(self.settings.duration));
            let instant = |t: f64| self.instant(regime, &piece, t, &y, &[0.0; S]);
            let (start, end) = (instant(t), instant(t1));
            let mut met: Option<(Watch, f64)> = None;
            for &watch in &watches {
                let (v0, v1) = (self.condition(watch, &start.snap).v, self.condition(watch, &end.snap).v);
                // Above zero at the start (the input jumped there): met at once.
                let at_once = v0 > 0.0 && !matches!(watch, Watch::Uplift(k) if fell_back == Some(k));
                let value = |t: f64| self.value(regime, &piece, watch, t, state);
                let hit = if at_once {
                    Some(t)
                } else {
                    first_crossing(
                        from_last_zero(&[(t, v0), (t1, v1)]),
                        watch.on_zero(fell_back),
                        |ta, va, tb, vb| find_crossing(value, ta, va, tb, vb, 0.0).tb,
                        |ta, tb| leaving_point(&value, ta, tb),
                    )
                };
                if let Some(te) = hit {
                    if met.is_none_or(|(_, tb)| te < tb) {
                        met = Some((watch, te));
                    }
                }
            }
            let reached = met.map_or(t1, |(_, te)| te);
            let stretch = Stretch {
                t0: t,
                t1,
                reached,
                last: *state,
                at: &|_| *state,
                ends: Some((&start, &end)),
                inside: &instant,
            };
            if let ControlFlow::Break(halt) = hook.step(regime, &stretch) {
                return Err(Error::halted(halt, t));
            }
            self.take_samples(&mut run.out, regime, &mut run.next_sample, reached, |_| *state);
            t = reached;
            if let Some((watch, _)) = met {
                run.t = t;
                return Ok(Some(watch));
            }
            fell_back = None;
        }
        run.t = t;
        Ok(None)
    }

    /// Raises each rocking block's largest `|θ_k|` to the extremes of the
    /// step up to `t1`: its states at its start and at `t1`, `edges`, and
    /// the extremes of `θ_k` before `t1`.
    fn track_peaks(&self, out: &mut StackRun, regime: &StackRegime, edges: (&StackState, &StackState), t1: f64, theta_points: &[Points; N]) {
        for k in 0..self.n() {
            if regime.interfaces[k] == Interface::Stuck {
                continue;
            }
            out.blocks[k].reach(edges.0.theta[k]);
            out.blocks[k].reach(edges.1.theta[k]);
            for &(t, theta) in theta_points[k].as_slice() {
                if t <= t1 {
                    out.blocks[k].reach(theta);
                }
            }
        }
    }

    /// Applies the transition of `watch` at `t`, records it, and says whether
    /// the run ends (an overturning).
    fn apply(&self, run: &mut Progress<S>, watch: Watch, t: f64, hook: &mut dyn Hook<N>) -> Result<bool, Error> {
        let Progress { out, regime, state, .. } = run;
        let (next_regime, next_state, kind, ratio) = self.switch(regime, watch, t, state);
        let event = StackEvent {
            time: t,
            kind,
            regime_before: *regime,
            before: *state,
            regime: next_regime,
            after: next_state,
            seat_impulse_ratio: ratio,
        };
        out.events.push(event);
        if let ControlFlow::Break(halt) = hook.event(&event) {
            return Err(Error::halted(halt, t));
        }
        out.max_seat_impulse_ratio = out.max_seat_impulse_ratio.max(ratio);
        match kind {
            StackEventKind::Impact(k) | StackEventKind::Rest(k) => out.blocks[k].impacts += 1,
            StackEventKind::Uplift(k) => {
                out.blocks[k].first_uplift_time.get_or_insert(t);
            }
            _ => {}
        }
        for (k, block) in out.blocks.iter_mut().enumerate() {
            block.reach(state.theta[k]);
        }
        *regime = next_regime;
        *state = next_state;
        if let StackEventKind::Overturn(k) = kind {
            out.overturned = Some(k);
            return Ok(true);
        }
        Ok(false)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::stack::Block;

    /// A shaft 4 m × 12 m of 150 t carrying a belfry 3.2 m × 4.5 m of 30 t,
    /// on a fixed base.
    fn shaft_and_belfry() -> Stack {
        let shaft = Block::solid(1, 4.0, 12.0, 1.5e5).unwrap();
        let belfry = Block::solid(2, 3.2, 4.5, 3.0e4).unwrap();
        Stack::new(&[shaft, belfry], None, 9.81).unwrap()
    }

    /// A run of `duration` at rtol 1e-10.
    fn tight(duration: f64) -> RunSettings {
        RunSettings {
            duration,
            rtol: 1e-10,
            atol: 1e-12,
            sample_interval: 0.01,
        }
    }

    /// The screen's threshold by hand. The shaft (4 m × 12 m, 150 t) and
    /// belfry (3.2 m × 4.5 m, 30 t) seated on it turn as one body about the
    /// shaft's corner: `m |r| / I_O` = 180,000 × sqrt(2² + 7.375²) /
    /// 14,288,100 1/m. On a fixed base with no input, `max|θ̈| = B = (m |r| /
    /// I_O) g` and `max|θ⃛| = (m |r| / I_O) g max|θ̇|`, `max|θ̇| <= w + B h/2`.
    /// Ends with `θ̇ = w` and slopes `−B`, `+B` (a valley towards zero), `h =
    /// 0.1 s`: for small `w` neither the rate test (`2w > B h`) nor the
    /// tangents (`w − B h/2`) prove anything, and the chord proves it where
    /// `w > max|θ⃛| h²/8`, i.e. above `w* = c B h / (2 (1 − c))`, `c = (m |r|
    /// / I_O) g h²/8` (times the proof's `1 + 1e-9`). One per cent either
    /// side of `w*` decides; the body's constants wrong by more (the shaft's
    /// `I_O` alone, the belfry left out) move `w*` by far more.
    #[test]
    fn the_screen_proves_a_velocity_above_the_threshold_by_hand() {
        let (stack, settings) = (shaft_and_belfry(), tight(1.0));
        let runner = Runner::<2, 6> {
            stack: &stack,
            ground: &GroundMotion::None,
            settings: &settings,
        };
        let rate = 1.8e5 * (2.0f64 * 2.0 + 7.375 * 7.375).sqrt() / 14_288_100.0;
        let (g, h) = (9.81, 0.1);
        let b = rate * g;
        let c = rate * g * h * h / 8.0 * (1.0 + 1e-9);
        let threshold = c * b * h / (2.0 * (1.0 - c));
        let regime = StackRegime::REST.with(0, Interface::Rocking(Pivot::Positive));
        let proved = |w: f64| {
            let mut ends = (StackState::default(), StackState::default());
            (ends.0.theta_dot[0], ends.1.theta_dot[0]) = (w, w);
            let mut rates = ([0.0; 6], [0.0; 6]);
            (rates.0[2], rates.1[2]) = (-b * w.signum(), b * w.signum());
            !runner.theta_may_turn(&regime, &Piece::Constant(0.0), (0.0, h), (&ends.0, &ends.1), (&rates.0, &rates.1))[0]
        };
        assert!(proved(1.01 * threshold) && !proved(0.99 * threshold), "w* = {threshold}");
        assert!(proved(-1.01 * threshold) && !proved(-0.99 * threshold), "mirrored, w* = {threshold}");
    }

    /// A turning point the screen must leave to the search: the shaft and
    /// belfry, seated on one another, thrown outwards on a fixed base with no
    /// input (θ = 0.01, θ̇ = 0.05 rad/s), rise to the apex that their energy
    /// gives, `cos(α − θ_m) = cos(α − θ_0) + I_O θ̇_0² / (2 m g R)` with the
    /// body's `m` = 180 t, `R` = sqrt(2² + 7.375²) m, `α` = atan(2 / 7.375),
    /// `I_O` = 14,288,100 kg·m² (by hand above): θ_m = 0.015305177848577.
    /// The run's largest θ is read where θ̇ changes sign inside a step; a
    /// screen that left that step unsearched would report the larger of the
    /// step's ends, below the apex. Most of the rise and fall is screened (the
    /// velocity far from zero). 1e-8 relative: rtol 1e-10 over a second of
    /// rising, the apex found on the dense output at the root of θ̇, where θ
    /// is flat.
    #[test]
    fn the_apex_of_one_rocking_body_is_located_through_the_screen() {
        let stack = shaft_and_belfry();
        let mut state = StackState::default();
        (state.theta[0], state.theta_dot[0]) = (0.01, 0.05);
        let out = run(&stack, &GroundMotion::None, &state, &tight(3.0)).unwrap();
        assert!(
            !out.events.iter().any(|e| e.kind == StackEventKind::Uplift(1)),
            "the belfry stays seated: one body"
        );
        let apex = 0.015_305_177_848_577;
        let got = out.blocks[0].max_abs_theta;
        assert!((got - apex).abs() <= 1e-8 * apex, "apex {got} against {apex}");
        assert!(out.blocks[0].impacts >= 1, "it falls back and lands within the run");
    }
}
