//! The event-driven run: integrate the smooth motion of one regime, locate the
//! instant a transition condition is met by root finding on the dense output,
//! switch, and go on (docs/src/model.md, "Regimes and transitions").
//!
//! Conditions (`condition.rs`) are negative while the regime holds and cross
//! zero upwards when it must change. The signs of a condition at the two ends
//! of a step prove nothing about what it did in between, so each step is
//! examined whole:
//!
//! - conditions on `θ` (impact, overturn) and on `u̇` (end of a slip) are
//!   components of the state, polynomials on the dense output: their roots,
//!   and the roots of `θ̇` (the extremes of `θ`), are all isolated in the
//!   Bernstein form (`integrator/bernstein.rs`). On a stuck building, a bound
//!   of `|θ̈|` over the step proves most steps free of any root of `θ̇` without
//!   building the dense output; likewise `|ü|` for a sliding building with
//!   the tower standing;
//! - the friction demand of a stuck building under a rocking tower is not a
//!   polynomial: its extrema inside the step are located on its exact time
//!   derivative (`extrema.rs`), and the demand is checked at each.
//!
//! A condition that is zero when a regime is entered and grows (positive time
//! derivative) switches at once, as does one that is already positive. Two
//! conditions start a regime on zero and move away from it (impact, `θ = 0`;
//! end of a slip, `u̇ = 0`): those are armed once the motion has left zero.
//!
//! The peaks the summary reports are located the same way: `θ` at the roots
//! of `θ̇`, the top acceleration and the pivot reactions at the roots of their
//! exact derivatives.

use crate::cascade::Flight;
use crate::condition::{conditions, pivot_sign, Condition, MAX_CONDITIONS};
use crate::equations::{Accelerations, Kernel};
use crate::error::{positive, Error, Parameter};
use crate::event::{Event, EventKind};
use crate::extrema::{hermite_range_reaches, interior_extrema, matters_on_step, may_have_extremum, taylor_enclosure};
use crate::ground::{sine, GroundMotion, Piece, Segment};
use crate::integrator::bernstein;
use crate::integrator::{find_crossing, find_crossing_newton, DenseOutput, Dop853, StepFailure};
use crate::jet::Jet;
use crate::model::Model;
use crate::observer::{Interpolant, Observer, Step};
use crate::regime::{BuildingRegime, Pivot, Regime, SlipDirection, State, TowerRegime};
use crate::response::{free_motion_overturns, EndState};
use crate::response::{EndReason, Summary, Tracker};
use arrayvec::ArrayVec;
use std::f64::consts::FRAC_PI_2;
use std::ops::ControlFlow;

/// Angular velocity (rad/s) below which an impact ends the rocking: the
/// cascade of ever smaller impacts is cut there, in finite time.
pub const REST_ANGULAR_VELOCITY: f64 = 1e-9;

/// Regime switches at one instant beyond which the run reports chattering.
const MAX_SWITCHES_AT_ONE_INSTANT: u32 = 64;

/// How long and how accurately to integrate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Total simulated time (s), > 0.
    pub duration: f64,
    /// Relative tolerance of the integrator (default `1e-8`).
    pub rtol: f64,
    /// Absolute tolerance (rad, rad/s, m, m/s; default `1e-10`).
    pub atol: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            duration: 20.0,
            rtol: 1e-8,
            atol: 1e-10,
        }
    }
}

/// Tightest relative tolerance: 100 machine epsilons (SciPy's floor for its
/// DOP853); below it the error estimate is rounding noise.
pub const MIN_RTOL: f64 = 100.0 * f64::EPSILON;
/// Loosest relative tolerance. Measured on `examples/tower-on-church.toml`
/// (210 impacts): rtol 1e-6 gives the max θ/α of 1e-8 to 6 digits, 3e-6 is
/// already 46% off and 1e-4 twice as large; a looser run is not an answer.
pub const MAX_RTOL: f64 = 1e-6;
/// Tightest absolute tolerance (rad, rad/s, m, m/s): far below any motion of
/// a body of metres, and above the range where the error scale of a state at
/// rest (`atol` alone) underflows the error estimate.
pub const MIN_ATOL: f64 = 1e-30;
/// Loosest absolute tolerance: a micro-radian (or micrometre) of error per
/// step is already the size of the rotations an impact cascade leaves.
pub const MAX_ATOL: f64 = 1e-6;

impl Settings {
    /// Checks the settings: `duration > 0`, `rtol` in [[`MIN_RTOL`], [`MAX_RTOL`]],
    /// `atol` in [[`MIN_ATOL`], [`MAX_ATOL`]] (where DOP853's error control means
    /// something). [`simulate`] calls it; a front end may call it earlier.
    pub fn validate(&self) -> Result<(), Error> {
        positive(Parameter::Duration, self.duration)?;
        let rtol = positive(Parameter::RelativeTolerance, self.rtol)?;
        let atol = positive(Parameter::AbsoluteTolerance, self.atol)?;
        if !(MIN_RTOL..=MAX_RTOL).contains(&rtol) {
            return Err(Error::InvalidParameter {
                parameter: Parameter::RelativeTolerance,
                reason: format!(
                    "must be between {MIN_RTOL:.1e} (100 machine epsilons, below which the error estimate is rounding noise) and {MAX_RTOL:.0e} (beyond which impacts and slips are misplaced), got {rtol:e}"
                ),
            });
        }
        if !(MIN_ATOL..=MAX_ATOL).contains(&atol) {
            return Err(Error::InvalidParameter {
                parameter: Parameter::AbsoluteTolerance,
                reason: format!(
                    "must be between {MIN_ATOL:.0e} and {MAX_ATOL:.0e} (rad, rad/s, m, m/s; outside it the error control either cannot be met or no longer controls anything), got {atol:e}"
                ),
            });
        }
        Ok(())
    }
}

/// Initial rotation and angular velocity of the tower; the building starts at rest.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Initial {
    /// `θ(0)` (rad), `|θ| < π/2`.
    pub theta: f64,
    /// `θ̇(0)` (rad/s).
    pub theta_dot: f64,
}

/// Runs `model` under `ground` from `initial` and reports to `observer`.
pub fn simulate(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings, observer: &mut impl Observer) -> Result<Summary, Error> {
    simulate_with_vertical(model, ground, None, initial, settings, observer)
}

/// No vertical ground motion.
static NO_MOTION: GroundMotion = GroundMotion::None;

/// Runs `model` under the horizontal `ground` and, if given, the vertical
/// ground acceleration `vertical` (`a_v`, positive upwards: the effective
/// gravity is `g + a_v`, docs/src/model.md, "Vertical ground acceleration"). Where
/// `g + a_v <= 0` the run stops with [`Error::FreeFall`] at that instant.
pub fn simulate_with_vertical(
    model: &Model,
    ground: &GroundMotion,
    vertical: Option<&GroundMotion>,
    initial: Initial,
    settings: &Settings,
    observer: &mut impl Observer,
) -> Result<Summary, Error> {
    settings.validate()?;
    crate::error::finite(Parameter::InitialTheta, initial.theta)?;
    crate::error::finite(Parameter::InitialThetaDot, initial.theta_dot)?;
    if initial.theta.abs() >= FRAC_PI_2 {
        return Err(Error::InvalidParameter {
            parameter: Parameter::InitialTheta,
            reason: format!("|θ| must be below π/2 (overturned), got {}", initial.theta),
        });
    }
    let kernel = Kernel::new(model);
    if !kernel.has_tower && (initial.theta != 0.0 || initial.theta_dot != 0.0) {
        return Err(Error::InvalidParameter {
            parameter: Parameter::InitialTheta,
            reason: "an initial rotation needs a [tower]".into(),
        });
    }
    let tower = if initial.theta != 0.0 {
        TowerRegime::Rocking(Pivot::of_sign(initial.theta))
    } else if initial.theta_dot != 0.0 {
        TowerRegime::Rocking(Pivot::of_sign(initial.theta_dot))
    } else {
        TowerRegime::Rest
    };
    // Without a building the slip stays zero: integrate (θ, θ̇) only, which
    // halves the linear algebra of every step.
    if kernel.has_building {
        run::<_, 4>(&kernel, ground, vertical, settings, tower, initial, observer)
    } else {
        run::<_, 2>(&kernel, ground, vertical, settings, tower, initial, observer)
    }
}

fn run<O: Observer, const N: usize>(
    kernel: &Kernel,
    ground: &GroundMotion,
    vertical: Option<&GroundMotion>,
    settings: &Settings,
    tower: TowerRegime,
    initial: Initial,
    observer: &mut O,
) -> Result<Summary, Error> {
    let mut run = Run::<O, N> {
        kernel,
        ground,
        vertical: vertical.unwrap_or(&NO_MOTION),
        has_vertical: vertical.is_some_and(|v| !matches!(v, GroundMotion::None)),
        vertical_given: vertical.is_some(),
        end: settings.duration,
        regime: Regime {
            tower,
            building: BuildingRegime::Stick,
        },
        t: 0.0,
        y: State {
            theta: initial.theta,
            theta_dot: initial.theta_dot,
            ..State::default()
        },
        segment: ground.segment(0.0),
        vsegment: NO_MOTION.segment(0.0),
        free_fall: f64::INFINITY,
        stepper: Dop853::new(settings.rtol, settings.atol),
        rtol: settings.rtol,
        restart: true,
        watch: Watched::default(),
        settled: None,
        tracker: Tracker::new(),
        observer,
        switches: 0,
        switch_time: f64::NAN,
        finished: false,
        deferring: false,
        deferred: Deferred::default(),
    };
    run.enter_vertical();
    run.execute()
}

/// The quantities examined over a step, at one instant, each with its exact
/// time derivative along the solution.
#[derive(Debug, Clone, Copy, Default)]
struct Watched {
    /// The conditions of the regime, in the order of [`conditions`].
    conditions: [Jet; MAX_CONDITIONS],
    /// Absolute horizontal acceleration of the top centre (m/s²), while rocking.
    top: Jet,
    /// Pivot reactions per unit tower mass `(f_x, f_y) / m2` (m/s²), while rocking.
    fx: Jet,
    fy: Jet,
}

/// [`Watched`] at `(t, y)`; `acc`, the accelerations there, if known (a
/// rocking tower on a stuck building does not need them: its `θ̈` does not
/// depend on `θ̇`).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
fn watched(kernel: &Kernel, regime: Regime, piece: &Piece, vpiece: &Piece, list: &[Condition], t: f64, y: &State, acc: Option<Accelerations<f64>>) -> Watched {
    let a_g = piece.eval_jet(t);
    // No vertical input (a constant piece) spares a call per instant.
    let g_e = match *vpiece {
        Piece::Constant(a_v) => Jet::from(kernel.g + a_v),
        _ => Jet::from(kernel.g) + vpiece.eval_jet(t),
    };
    let mut w = Watched::default();
    let TowerRegime::Rocking(pivot) = regime.tower else {
        let acc = acc.unwrap_or_else(|| kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot));
        let yj = y.jets(acc);
        for (slot, c) in w.conditions.iter_mut().zip(list) {
            *slot = c.value(kernel, regime, a_g, g_e, &yj);
        }
        return w;
    };
    let s = pivot.sign();
    let lean = kernel.lean(s, Jet::new(y.theta, y.theta_dot));
    let mut yj;
    let (theta_ddot, acc_pivot) = match regime.building {
        BuildingRegime::Stick => {
            let theta_ddot = kernel.tower_equation(lean, a_g, g_e);
            yj = y.jets(Accelerations {
                theta: theta_ddot.v,
                slip: 0.0,
            });
            (theta_ddot, a_g)
        }
        BuildingRegime::Slip(dir) => {
            let acc = acc.unwrap_or_else(|| kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot));
            yj = y.jets(acc);
            kernel.rocking_on_sliding_building(lean, dir.sign(), yj.theta_dot, g_e)
        }
    };
    yj.theta = Jet::new(y.theta, y.theta_dot);
    let demand = (!list.is_empty() && regime.building == BuildingRegime::Stick && kernel.has_building)
        .then(|| kernel.rocking_stick_demand(lean, yj.theta_dot, theta_ddot, a_g, g_e));
    for (slot, &c) in w.conditions.iter_mut().zip(list) {
        *slot = match (c, demand) {
            // What `value` gives, without its call (not inlined: inlining it
            // everywhere cost 7 M instructions of the sweep, the call here 2.7 M).
            (Condition::Impact | Condition::Overturn, _) => c.theta_margin(s, yj.theta),
            (Condition::SlipNegative | Condition::SlipPositive, Some((force, normal))) => c.slip_margin(force, normal, kernel.mu_s),
            _ => c.value(kernel, regime, a_g, g_e, &yj),
        };
    }
    w.top = kernel
        .point_kinematics(Some(s), (0.0, kernel.height), kernel.rotation(lean), yj.theta_dot, theta_ddot, acc_pivot)
        .1;
    (w.fx, w.fy) = kernel.pivot_reactions(Some(lean), yj.theta_dot, theta_ddot, acc_pivot, g_e);
    w
}

/// [`Watched`] at `t` on a step's dense output.
#[inline]
fn watched_on<const N: usize>(kernel: &Kernel, regime: Regime, pieces: (&Piece, &Piece), list: &[Condition], d: &DenseOutput<N>, t: f64) -> Watched {
    watched(kernel, regime, pieces.0, pieces.1, list, t, &State::from_components(&d.state(t)), None)
}

/// The one condition `c` with its time derivative at `t` on a step's dense
/// output (root finding on it needs nothing else [`watched`] computes).
#[inline]
fn condition_on<const N: usize>(kernel: &Kernel, regime: Regime, pieces: (&Piece, &Piece), c: Condition, d: &DenseOutput<N>, t: f64) -> Jet {
    let y = State::from_components(&d.state(t));
    let a_g = pieces.0.eval_jet(t);
    let g_e = Jet::from(kernel.g) + pieces.1.eval_jet(t);
    let acc = kernel.accelerations(regime, a_g.v, g_e.v, y.theta, y.theta_dot);
    c.value(kernel, regime, a_g, g_e, &y.jets(acc))
}

/// The accelerations in a right-hand side `f = (θ̇, θ̈, u̇, ü)`.
#[inline(always)]
fn accelerations_of(f: &State) -> Accelerations<f64> {
    Accelerations {
        theta: f.theta_dot,
        slip: f.slip_vel,
    }
}

/// Whether a velocity `v` (θ̇ or u̇) with end values and exact slopes `v0`,
/// `v1` on a step of length `h`, `|v̇| <= rate_bound` and `|v̈| <=
/// curvature_bound` on it, is proved to keep one sign inside: the ends have
/// one sign and either
/// - the rate cannot take it to zero from both ends: `|v0| + |v1| > max|v̇| h`; or
/// - it stays off the chord between its end values by at most
///   `(t − t0)(t1 − t) max|v̈| / 2 <= h² max|v̈| / 8` (the linear
///   interpolant's error), less than its smaller end value; or
/// - it stays off the tangent at the nearer end by at most `τ² max|v̈| / 2`
///   (Taylor's remainder, `τ <= h / 2` from that end), and each end's
///   tangent, less that, keeps the ends' sign up to mid-step (a concave
///   lower bound: its least value on `[0, h/2]` is at one of the two ends,
///   `v0` itself or `v0 + v̇0 h/2 − max|v̈| h²/8`).
///
/// The chord is the sharper on short steps, the tangents where `v` moves
/// away from zero; all are proofs (the factor `1 + 1e-9` covers the rounding
/// of the bounds, the `4 ε` that of the tangents' sums).
fn free_of_roots(v0: Jet, v1: Jet, h: f64, rate_bound: f64, curvature_bound: f64) -> bool {
    if v0.v * v1.v <= 0.0 {
        return false;
    }
    let dip = 0.125 * curvature_bound * h * h * (1.0 + 1e-9);
    let sign = v0.v.signum();
    let tangent_clear = |v: f64, toward_middle: f64| sign * (v + toward_middle) > dip + 4.0 * f64::EPSILON * (v.abs() + toward_middle.abs());
    v0.v.abs() + v1.v.abs() > rate_bound * h * (1.0 + 1e-9)
        || v0.v.abs().min(v1.v.abs()) > dip
        || (tangent_clear(v0.v, 0.5 * h * v0.d) && tangent_clear(v1.v, -0.5 * h * v1.d))
}

/// Whether θ, known to stay in `(lo, hi)` over a step, is proved to stay
/// inside the range `kept` so far and to keep every condition of θ in `list`
/// negative on pivot `s` (each is monotone in θ, so the ends of the range
/// tell): then no turning point inside the step can change anything. Every
/// comparison must hold, so that a NaN bound proves nothing.
fn theta_proved_inside((lo, hi): (f64, f64), kept: (f64, f64), list: &[Condition], s: f64) -> bool {
    let negative = |c: &Condition| !c.of_theta() || (c.theta_margin(s, lo) < 0.0 && c.theta_margin(s, hi) < 0.0);
    lo >= kept.0 && hi <= kept.1 && list.iter().all(negative)
}

/// The first instant in `points` (ordered, the condition monotone between
/// consecutive ones) where a condition reaches zero: `locate(ta, va, tb, vb)`
/// narrows a bracket `va < 0 <= vb`; `leaving(ta, tb)` finds where a
/// condition that starts on zero has become negative.
fn first_crossing(points: &[(f64, f64)], mut locate: impl FnMut(f64, f64, f64, f64) -> f64, leaving: impl Fn(f64, f64) -> Option<(f64, f64)>) -> Option<f64> {
    for k in 1..points.len() {
        let (tb, vb) = points[k];
        if vb < 0.0 {
            continue;
        }
        let (ta, va) = points[k - 1];
        if va < 0.0 {
            return Some(locate(ta, va, tb, vb));
        }
        // Only the start can be on zero (any later point at or above zero
        // would have ended the search): find where the motion left it. If it
        // never did, the condition grew from zero: a transition at once.
        return Some(match leaving(ta, tb) {
            Some((tl, vl)) => locate(tl, vl, tb, vb),
            None => ta,
        });
    }
    None
}

/// A step is searched for a peak of the top acceleration or of the pivot
/// friction demand only if the cubic Hermite interpolant of the exact end
/// values and slopes comes within this fraction of the running maximum (or
/// `f_y` within this fraction of `g_e` of zero). The interpolant's error is
/// `h⁴/384 max|q⁗|`, below 1e-3 of the quantity for the steps DOP853 takes
/// on these smooth quantities (ten or more per period of the input or of the
/// rocking), so a step it keeps 5% below cannot hold the peak. Transition
/// conditions are never pruned this way.
const PEAK_MARGIN: f64 = 0.05;

/// The most roots a component of the dense output (a polynomial of degree 7) can have.
const MAX_ROOTS: usize = 7;

/// Room for a step's ends and, between them, a bracket (two points) around
/// each root: what a condition's points can hold.
const MAX_POINTS: usize = 2 * MAX_ROOTS + 2;

/// Instants inside a step with a value each, in time order: a condition's
/// ends and extrema, or the extremes of θ. Never more than [`MAX_POINTS`]
/// can exist (one beyond would be dropped). On the stack and not zeroed when
/// made: no allocation and no fill in the inner loop.
#[derive(Default)]
struct Points(ArrayVec<(f64, f64), MAX_POINTS>);

impl Points {
    #[inline]
    fn push(&mut self, p: (f64, f64)) {
        let _ = self.0.try_push(p);
    }

    #[inline]
    fn as_slice(&self) -> &[(f64, f64)] {
        &self.0
    }
}

/// The state of a run; the integrator carries the first `N` components of
/// `(θ, θ̇, u, u̇)` (2 on a fixed base, 4 on a building).
struct Run<'a, O: Observer, const N: usize> {
    /// Borrowed, not owned: the step copies it out for its closures, and a
    /// reference is one word where the kernel is two dozen.
    kernel: &'a Kernel,
    ground: &'a GroundMotion,
    /// The vertical ground acceleration (`GroundMotion::None` without one).
    vertical: &'a GroundMotion,
    has_vertical: bool,
    /// A vertical input was given, `GroundMotion::None` included (the summary
    /// then reports the least effective gravity).
    vertical_given: bool,
    end: f64,
    regime: Regime,
    t: f64,
    y: State,
    /// The ground's segment that holds `t` (right-continuous).
    segment: Segment,
    /// The vertical input's segment that holds `t`.
    vsegment: Segment,
    /// The first instant, before the end of `vsegment`'s piece, where
    /// `g + a_v <= 0` (`+∞` if none).
    free_fall: f64,
    stepper: Dop853<N>,
    /// The relative tolerance (it bounds the flights taken in closed form).
    rtol: f64,
    /// Whether the stepper must restart at `(t, y)` (after an event or a kink).
    restart: bool,
    /// The watched quantities at `(t, y)`.
    watch: Watched,
    /// Set when `settle` leaves `watch` computed at the current instant (see [`Settled`]).
    settled: Option<Settled>,
    tracker: Tracker,
    observer: &'a mut O,
    /// Switches at `switch_time`, to stop chattering.
    switches: u32,
    switch_time: f64,
    finished: bool,
    /// Inside an impact cascade jumped in closed form: instants go to
    /// `deferred` instead of the tracker.
    deferring: bool,
    deferred: Deferred,
}

/// What `settle` computed [`Run::watch`] from, with the accelerations there.
/// The restart that follows at the same instant needs exactly these (the
/// right-hand side at `(t, y)` and `watched` with the regime's conditions):
/// at every kink of a recorded input both were computed twice.
#[derive(Debug, Clone, Copy)]
struct Settled {
    t: f64,
    y: State,
    regime: Regime,
    pieces: (Piece, Piece),
    acc: Accelerations<f64>,
}

/// An instant for the tracker: regime, `a_g`, `g_e` and state.
type Instant = (Regime, f64, f64, State);

/// Feeds `tracker` the response at `instant`.
fn track(tracker: &mut Tracker, kernel: &Kernel, (regime, a_g, g_e, y): Instant) {
    tracker.instant(kernel, regime, a_g, g_e, &y);
}

/// The last instants of a cascade jumped in closed form, waiting for the
/// tracker. Two flights leave at most eight: an apex, the arrival and the
/// departure of each, and after the last impact a building's change of regime
/// and the rest; the oldest are overwritten.
#[derive(Default)]
struct Deferred {
    items: [Option<Instant>; 8],
    next: usize,
}

impl Deferred {
    fn push(&mut self, item: Instant) {
        self.items[self.next] = Some(item);
        self.next = (self.next + 1) % self.items.len();
    }

    /// The instants kept, emptied.
    fn drain(&mut self) -> impl Iterator<Item = Instant> + '_ {
        self.next = 0;
        self.items.iter_mut().filter_map(Option::take)
    }
}

/// The error of a failed step; `dynamic`: the building has the dynamic normal force.
fn step_error(e: StepFailure, dynamic: bool) -> Error {
    match e {
        StepFailure::StepSizeTooSmall { time } => Error::StepSizeTooSmall { time },
        // Only the dynamic normal force can make the coupled system singular;
        // otherwise a non-finite value is an overflow.
        StepFailure::NonFinite { time } if dynamic => Error::Singular {
            time,
            reason:
                "the equations of motion have no solution (with the dynamic normal force, a building this light cannot carry this friction: Painlevé's paradox)"
                    .into(),
        },
        StepFailure::NonFinite { time } => Error::Singular {
            time,
            reason: "the motion became non-finite (an overflow: the inputs' scales are out of proportion)".into(),
        },
    }
}

impl<O: Observer, const N: usize> Run<'_, O, N> {
    fn execute(mut self) -> Result<Summary, Error> {
        self.check_free_fall()?;
        self.settle()?;
        self.record_instant();
        while !self.finished && self.t < self.end {
            if self.is_static() {
                self.advance_static()?;
            } else if let Some(flight) = self.free_flight() {
                self.advance_free_flight(flight)?;
            } else {
                self.advance_dynamic()?;
            }
        }
        self.tracker.summary.evaluations = self.stepper.evaluations;
        (self.tracker.summary.end_state, self.tracker.summary.will_overturn) = self.end_verdict();
        if self.has_vertical {
            self.tracker.summary.min_effective_gravity = Some(self.min_effective_gravity(self.t));
        } else if self.vertical_given {
            // A vertical input of `GroundMotion::None`: g throughout.
            self.tracker.summary.min_effective_gravity = Some(self.kernel.g);
        }
        Ok(self.tracker.finish(self.kernel, self.t, &self.y))
    }

    /// The tower's state at the end and what its free motion will do
    /// ([`free_motion_overturns`]; unknown while input remains or the building slides).
    fn end_verdict(&self) -> (EndState, Option<bool>) {
        let k = self.kernel;
        let (theta, theta_dot) = (self.y.theta, self.y.theta_dot);
        let state = match self.regime.tower {
            _ if self.tracker.summary.end_reason == EndReason::Overturned => EndState::Overturned,
            _ if !k.has_tower => EndState::Rest,
            _ if theta.abs() > k.alpha => EndState::BeyondStabilityLimit,
            TowerRegime::Rest => EndState::Rest,
            TowerRegime::Rocking(_) => EndState::Rocking,
        };
        let over = |t: f64, ground: &GroundMotion| {
            let segment = ground.segment(t);
            segment.kink == f64::INFINITY && matches!(segment.piece, Piece::Constant(a) if a == 0.0)
        };
        let verdict = match state {
            _ if !k.has_tower => None,
            EndState::Overturned => Some(true),
            _ if !over(self.t, self.ground) || !over(self.t, self.vertical) || self.regime.building != BuildingRegime::Stick => None,
            EndState::Rest => Some(false),
            _ => Some(free_motion_overturns(k.alpha, (k.k * k.g).sqrt(), k.restitution, theta, theta_dot)),
        };
        (state, verdict)
    }

    /// The effective gravity `g + a_v` (m/s²) at `t` in the current vertical segment.
    #[inline(always)]
    fn g_e(&self, t: f64) -> f64 {
        self.kernel.g + self.vsegment.piece.eval(t)
    }

    /// Enters the vertical input's segment at the current time and locates the
    /// first instant before its next kink where `g + a_v <= 0`: on each
    /// monotone part the least value is at an end, so the crossing is
    /// bracketed there and located by root finding.
    fn enter_vertical(&mut self) {
        self.vsegment = self.vertical.segment(self.t);
        self.free_fall = f64::INFINITY;
        if !self.has_vertical {
            return;
        }
        let g = self.kernel.g;
        let stop = self.vsegment.kink.min(self.end);
        let mut t = self.t;
        loop {
            let segment = self.vertical.segment(t);
            let (piece, tb) = (segment.piece, segment.end.min(stop));
            let value = |t: f64| -(g + piece.eval(t));
            let (va, vb) = (value(t), value(tb));
            if va >= 0.0 {
                self.free_fall = t;
                return;
            }
            if vb >= 0.0 {
                self.free_fall = find_crossing(value, t, va, tb, vb, 0.0).tb;
                return;
            }
            if tb >= stop {
                return;
            }
            t = tb;
        }
    }

    /// Stops the run where the effective gravity has reached zero.
    fn check_free_fall(&self) -> Result<(), Error> {
        if self.t >= self.free_fall {
            return Err(Error::FreeFall { time: self.free_fall });
        }
        Ok(())
    }

    /// The least `g + a_v` on `[0, t_end]` (m/s²): on each monotone segment
    /// of the input it is at an end.
    fn min_effective_gravity(&self, t_end: f64) -> f64 {
        let mut least = self.kernel.g + self.vertical.segment(0.0).piece.eval(0.0);
        let mut t = 0.0;
        while t < t_end {
            let s = self.vertical.segment(t);
            let tb = s.end.min(t_end);
            least = least.min(self.kernel.g + s.piece.eval(t)).min(self.kernel.g + s.piece.eval(tb));
            t = tb;
        }
        least
    }

    /// Nothing moves relative to the ground: the state is constant and every
    /// condition depends on `a_g` alone.
    fn is_static(&self) -> bool {
        self.regime.tower == TowerRegime::Rest && self.regime.building == BuildingRegime::Stick
    }

    fn a_g(&self, t: f64) -> f64 {
        self.segment.piece.eval(t)
    }

    /// The accelerations at the current instant.
    fn accelerations_now(&self) -> Accelerations<f64> {
        self.kernel
            .accelerations(self.regime, self.a_g(self.t), self.g_e(self.t), self.y.theta, self.y.theta_dot)
    }

    /// Moves to the next segment end, or to the first instant on the way where a
    /// condition is met (root finding on `a_g`, monotone on the segment).
    fn advance_static(&mut self) -> Result<(), Error> {
        // The next extremum of a_g may lie beyond the current segment's end if the
        // run was rocking or sliding until now: take the segment from here.
        self.segment = self.ground.segment(self.t);
        self.vsegment = self.vertical.segment(self.t);
        let t1 = self.segment.end.min(self.vsegment.end).min(self.free_fall).min(self.end);
        let (list, n) = conditions(self.kernel, self.regime);
        let (kernel, regime, y, piece, vpiece) = (self.kernel, self.regime, self.y, self.segment.piece, self.vsegment.piece);
        let value = |c: Condition, t: f64| c.value(kernel, regime, piece.eval(t), kernel.g + vpiece.eval(t), &y);
        let mut first: Option<(f64, Condition)> = None;
        for &c in &list[..n] {
            let (v0, v1) = (value(c, self.t), value(c, t1));
            let tb = if self.has_vertical {
                // Both inputs are monotone on the stretch, but a condition on
                // `a_g` and `g + a_v` together need not be: its extrema, located
                // on the exact derivatives of both pieces, split it into
                // monotone parts.
                let yj = y.jets(Accelerations::default());
                let jet = |t: f64| c.value(kernel, regime, piece.eval_jet(t), Jet::from(kernel.g) + vpiece.eval_jet(t), &yj);
                let mut points = Points::default();
                points.push((self.t, v0));
                interior_extrema(self.t, jet(self.t), t1, jet(t1), &mut |t| jet(t), |_| true, &mut |t, v| points.push((t, v)));
                points.push((t1, v1));
                let hit = first_crossing(
                    points.as_slice(),
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
                find_crossing(|t| value(c, t), self.t, v0, t1, v1, 0.0).tb
            } else if v0 >= 0.0 && v1 > 0.0 {
                self.t
            } else {
                continue;
            };
            if first.is_none_or(|(tf, _)| tb < tf) {
                first = Some((tb, c));
            }
        }
        let t_stop = first.map_or(t1, |(tb, _)| tb);
        let y = self.y;
        self.emit_step(|| Interpolant::Constant(y), t_stop)?;
        self.t = t_stop;
        self.restart = true;
        self.record_instant();
        if let Some((_, c)) = first {
            self.switch(c)?;
        }
        self.next_instant()
    }

    /// After reaching a new instant: enter the next segment of the input if its
    /// end was reached, then apply every condition that already holds.
    fn next_instant(&mut self) -> Result<(), Error> {
        if self.t >= self.segment.kink {
            // A kink or jump of the input: new expression, conditions re-checked at once.
            self.segment = self.ground.segment(self.t);
            self.restart = true;
        }
        if self.t >= self.vsegment.kink {
            self.enter_vertical();
            self.restart = true;
        }
        self.check_free_fall()?;
        self.settle()
    }

    /// One accepted step of the integrator, examined whole (module docs) and
    /// cut short at the first transition in it.
    fn advance_dynamic(&mut self) -> Result<(), Error> {
        // The right-hand side is the inner loop. Without a vertical input it
        // takes the constant g, not `g + 0` evaluated at every call (the same
        // number; 2.4% fewer instructions over a 100-case sweep). The
        // commonest case, a tower rocking on a fixed base or a stuck building
        // under a harmonic input, is composed directly of (T) and the sine,
        // with no match on the input's piece or the regime at every call (the
        // same numbers as `Kernel::accelerations`; 5% fewer instructions over
        // a 100-case sweep).
        let (kernel, piece, g) = (self.kernel, self.segment.piece, self.kernel.g);
        match (self.has_vertical, piece, self.regime.tower, self.regime.building) {
            (false, Piece::Sine { amplitude, omega, phase }, TowerRegime::Rocking(pivot), BuildingRegime::Stick) => {
                let s = pivot.sign();
                self.advance_dynamic_with(move |t, theta, _| Accelerations {
                    theta: kernel.tower_equation(kernel.lean(s, theta), sine(amplitude, omega, phase, t), g),
                    slip: 0.0,
                })
            }
            (true, ..) => {
                let (regime, vpiece) = (self.regime, self.vsegment.piece);
                self.advance_dynamic_with(move |t, theta, theta_dot| kernel.accelerations(regime, piece.eval(t), g + vpiece.eval(t), theta, theta_dot))
            }
            (false, ..) => {
                let regime = self.regime;
                self.advance_dynamic_with(move |t, theta, theta_dot| kernel.accelerations(regime, piece.eval(t), g, theta, theta_dot))
            }
        }
    }

    /// [`Self::advance_dynamic`] with the accelerations `(θ̈, ü)` of the
    /// regime at `(t, θ, θ̇)`: the right-hand side.
    #[inline(always)]
    fn advance_dynamic_with(&mut self, accelerations: impl Fn(f64, f64, f64) -> Accelerations<f64> + Copy) -> Result<(), Error> {
        let (kernel, regime, piece, vpiece) = (self.kernel, self.regime, self.segment.piece, self.vsegment.piece);
        let g = kernel.g;
        let mut rhs = |t: f64, y: &[f64; N]| {
            let y = State::from_components(y);
            y.rate(accelerations(t, y.theta, y.theta_dot)).components()
        };
        let (list, n) = conditions(kernel, regime);
        let list = &list[..n];
        if self.restart {
            // Bit for bit what `settle` saw, or nothing is reused.
            let same = |c: &Settled| c.t.to_bits() == self.t.to_bits() && c.y.same_bits(self.y) && c.regime == regime && c.pieces == (piece, vpiece);
            match self.settled.take().filter(same) {
                Some(c) => {
                    // `settle` left `watch` computed there.
                    let y = self.y;
                    self.stepper
                        .restart_with(&mut rhs, self.t, y.components(), y.rate(c.acc).components(), self.end);
                }
                None => {
                    self.stepper.restart(&mut rhs, self.t, self.y.components(), self.end);
                    let f = State::from_components(&self.stepper.f);
                    self.watch = watched(kernel, regime, &piece, &vpiece, list, self.t, &self.y, Some(accelerations_of(&f)));
                }
            }
            self.restart = false;
        }
        // Steps land on kinks and jumps of both inputs, and where `g + a_v` reaches zero.
        let bound = self.segment.kink.min(self.vsegment.kink).min(self.free_fall).min(self.end);
        self.stepper.step(&mut rhs, bound).map_err(|e| step_error(e, kernel.dynamic))?;
        let (t0, t1) = (self.stepper.t_old, self.stepper.t);
        let (y0, y1) = (State::from_components(&self.stepper.y_old), State::from_components(&self.stepper.y));
        // The right-hand side at both ends: the velocities' exact slopes.
        let (f0, f1) = (State::from_components(&self.stepper.f_old()), State::from_components(&self.stepper.f));
        let h = t1 - t0;
        let w0 = self.watch;
        let w1 = watched(kernel, regime, &piece, &vpiece, list, t1, &y1, Some(accelerations_of(&f1)));
        let rocking = matches!(regime.tower, TowerRegime::Rocking(_));

        // What needs the inside of the step: see `free_of_roots`.
        let a_max = piece.max_abs(t0, t1);
        let a_rate = piece.max_abs_rate();
        // Upper bounds of g + a_v and of its rate on the step.
        let g_e = g + vpiece.max_abs(t0, t1);
        let g_rate = vpiece.max_abs_rate();
        let s = pivot_sign(regime);
        let theta_roots = rocking
            && match regime.building {
                // (T) on a stuck building: |θ̈| = k |s g_e sin φ + a_g cos φ| <= k sqrt(g_e² + a_g²), and
                // θ⃛ = −k [(s ġ_e sin φ + ȧ_g cos φ) + θ̇ (s a_g sin φ − g_e cos φ)], so that
                // |θ⃛| <= k [sqrt(ġ_e² + ȧ_g²) + max|θ̇| sqrt(g_e² + a_g²)] with
                // max|θ̇| <= (|θ̇0| + |θ̇1| + max|θ̈| h) / 2.
                //
                // A root of θ̇ is located for θ's value there: a peak of θ, or
                // a point of the conditions of θ between the ends. With the
                // same bound on |θ⃛|, θ over the whole step lies in
                // `taylor_enclosure`; if that range is inside the peaks kept
                // so far and keeps every condition of θ negative (each is
                // monotone in θ, so its ends tell), the root changes nothing
                // and is not located (half the steps that hold one in the
                // 100-case sweep, each a dense output, a Bernstein isolation
                // and a Newton solve). The two ends are the step's solution,
                // which the dense output also interpolates: the enclosure is
                // that of the computed motion, to the step's local error.
                BuildingRegime::Stick => {
                    let (rate_bound, reach) = kernel.tower_acceleration_bound(g_e, a_max);
                    let w_max = 0.5 * (y0.theta_dot.abs() + y1.theta_dot.abs() + rate_bound * h);
                    let third_bound = kernel.tower_jerk_bound(reach, g_rate, a_rate, w_max);
                    !free_of_roots(
                        Jet::new(y0.theta_dot, f0.theta_dot),
                        Jet::new(y1.theta_dot, f1.theta_dot),
                        h,
                        rate_bound,
                        third_bound,
                    ) && !theta_proved_inside(
                        taylor_enclosure([y0.theta, y0.theta_dot, f0.theta_dot], [y1.theta, y1.theta_dot, f1.theta_dot], h, third_bound),
                        self.tracker.summary.theta_range,
                        list,
                        s,
                    )
                }
                BuildingRegime::Slip(_) => true,
            };
        let slip_roots = N == 4
            && match (regime.tower, regime.building) {
                // The complex slides as one body: ü = −μk σ g_e − a_g, so
                // |ü| <= μk g_e + max|a_g| and |u⃛| <= μk max|ġ_e| + max|ȧ_g|.
                (TowerRegime::Rest, BuildingRegime::Slip(_)) => {
                    let (rate_bound, curvature_bound) = kernel.resting_slide_bounds(g_e, g_rate, a_max, a_rate);
                    !free_of_roots(
                        Jet::new(y0.slip_vel, f0.slip_vel),
                        Jet::new(y1.slip_vel, f1.slip_vel),
                        h,
                        rate_bound,
                        curvature_bound,
                    )
                }
                (TowerRegime::Rocking(_), BuildingRegime::Slip(_)) => true,
                (_, BuildingRegime::Stick) => false,
            };
        let stick_examined = rocking && regime.building == BuildingRegime::Stick && kernel.has_building;
        let crossing_at_end = w1.conditions[..n].iter().any(|c| c.v >= 0.0);
        // Summary peaks that the step may raise (see PEAK_MARGIN).
        let summary = &self.tracker.summary;
        let near = |q0: Jet, q1: Jet, peak: f64| hermite_range_reaches(q0, q1, h, |(lo, hi)| lo.abs().max(hi.abs()) >= (1.0 - PEAK_MARGIN) * peak);
        let ratio = |w: &Watched| w.fx / w.fy;
        // The demand |f_x| / f_y grows without bound as f_y falls towards zero (a
        // tower about to fly or overturn): no pruning where f_y is below g / 2.
        let low_fy = w0.fy.v.min(w1.fy.v) < 0.5 * g;
        // An extremum matters if it can raise the maximum kept before the step
        // (one kept during it is at least as high) or, for f_y, reach zero. Near
        // f_y = 0 the ratio has a pole close by and need not be concave between
        // samples: every extremum of it matters there. Asked here as well as
        // inside `interior_extrema` (which keeps its own contract for every
        // caller): a step ruled out by its ends needs no dense output (1.5 M
        // of the sweep's 178 M instructions).
        let above = |peak: f64| move |(lo, hi): (f64, f64)| lo.abs().max(hi.abs()) > peak;
        let top_matters = above(summary.max_top_abs_acceleration);
        let demand_above = above(summary.max_pivot_friction_demand);
        let demand_matters = move |range| low_fy || demand_above(range);
        let fy_matters = |(lo, _): (f64, f64)| lo <= 0.0;
        let top_inside = rocking && near(w0.top, w1.top, summary.max_top_abs_acceleration) && matters_on_step(t0, w0.top, t1, w1.top, top_matters);
        // Once f_y has reached zero the demand is unbounded and the uplift
        // known: neither can change any more.
        let reaction_open = rocking && !summary.tower_uplift_detected;
        let ratio_inside = reaction_open
            && w0.fy.v > 0.0
            && w1.fy.v > 0.0
            && (if low_fy {
                may_have_extremum(ratio(&w0), ratio(&w1), h)
            } else {
                near(ratio(&w0), ratio(&w1), summary.max_pivot_friction_demand)
            })
            && matters_on_step(t0, ratio(&w0), t1, ratio(&w1), demand_matters);
        let fy_inside =
            reaction_open && hermite_range_reaches(w0.fy, w1.fy, h, |(lo, _)| lo <= PEAK_MARGIN * g) && matters_on_step(t0, w0.fy, t1, w1.fy, fy_matters);
        let stick_inside = stick_examined && (0..n).any(|i| !list[i].of_theta() && may_have_extremum(w0.conditions[i], w1.conditions[i], h));
        let watched_inside = top_inside || ratio_inside || fy_inside || stick_inside;
        let need_dense = theta_roots || slip_roots || crossing_at_end || watched_inside || self.observer.wants_steps();
        let dense: Option<DenseOutput<N>> = need_dense.then(|| self.stepper.dense(&mut rhs));

        // The extremes of θ inside the step: the roots of θ̇.
        let mut theta_points = Points::default();
        if let (true, Some(d)) = (theta_roots, &dense) {
            bernstein::isolate(&bernstein::coefficients(d, 1, 0.0), &mut |xa, xb| {
                let (ta, tb) = (t0 + xa * h, (t0 + xb * h).min(t1));
                let sign = if d.state(ta)[1] < 0.0 { 1.0 } else { -1.0 };
                let rate = |t: f64| {
                    let (y, dy) = d.state_and_rate(t);
                    (sign * y[1], sign * dy[1])
                };
                let (va, vb) = (rate(ta).0, rate(tb).0);
                let root = if va < 0.0 && vb >= 0.0 {
                    find_crossing_newton(rate, ta, va, tb, vb).tb
                } else {
                    0.5 * (ta + tb)
                };
                theta_points.push((root, d.state(root)[0]));
            });
        }

        // The first transition in the step. A step without its dense output
        // has none to search: every condition ends it negative and none can
        // have come back inside (or the dense output would have been built).
        let mut first: Option<(f64, Condition)> = None;
        let searched = if dense.is_some() { list } else { &[] };
        for (i, &c) in searched.iter().enumerate() {
            let (v0, v1) = (w0.conditions[i].v, w1.conditions[i].v);
            let mut points = Points::default();
            points.push((t0, v0));
            let hit = if c.of_theta() {
                for &(t, theta) in theta_points.as_slice() {
                    points.push((t, c.theta_margin(s, theta)));
                }
                points.push((t1, v1));
                first_crossing(
                    points.as_slice(),
                    |ta, va, tb, vb| {
                        let Some(d) = &dense else { return tb };
                        // With its derivative (θ̇ from the same dense output) for Newton.
                        let f = |t: f64| {
                            let y = d.state(t);
                            let m = c.theta_margin(s, Jet::new(y[0], y[1]));
                            (m.v, m.d)
                        };
                        find_crossing_newton(f, ta, va, tb, vb).tb
                    },
                    |ta, tb| dense.as_ref().and_then(|d| leaving_point(&|t| c.theta_margin(s, d.state(t)[0]), ta, tb)),
                )
            } else {
                let value = |t: f64| {
                    dense.as_ref().map_or(v1, |d| {
                        let y = State::from_components(&d.state(t));
                        let (a_g, g_e) = if c.uses_ground() { (piece.eval(t), g + vpiece.eval(t)) } else { (0.0, g) };
                        c.value(kernel, regime, a_g, g_e, &y)
                    })
                };
                if c == Condition::SlipStop && slip_roots {
                    if let Some(d) = &dense {
                        let mut bracket = None;
                        bernstein::isolate(&bernstein::coefficients(d, 3, 0.0), &mut |xa, xb| {
                            bracket.get_or_insert((t0 + xa * h, (t0 + xb * h).min(t1)));
                        });
                        if let Some((ta, tb)) = bracket {
                            points.push((ta, value(ta)));
                            points.push((tb, value(tb)));
                        }
                    }
                } else if stick_examined && !c.of_theta() {
                    if let Some(d) = &dense {
                        let mut eval = |t: f64| condition_on(kernel, regime, (&piece, &vpiece), c, d, t);
                        interior_extrema(t0, w0.conditions[i], t1, w1.conditions[i], &mut eval, |_| true, &mut |t, v| points.push((t, v)));
                    }
                }
                points.push((t1, v1));
                first_crossing(
                    points.as_slice(),
                    |ta, va, tb, vb| find_crossing(value, ta, va, tb, vb, 0.0).tb,
                    |ta, tb| dense.as_ref().and_then(|_| leaving_point(&value, ta, tb)),
                )
            };
            if let Some(tb) = hit {
                if first.is_none_or(|(tf, _)| tb < tf) {
                    first = Some((tb, c));
                }
            }
        }
        let t_stop = first.map_or(t1, |(tb, _)| tb);

        // Peaks inside the step, up to the transition.
        for &(t, theta) in theta_points.as_slice() {
            if t <= t_stop {
                self.tracker.theta(theta);
            }
        }
        if let Some(d) = &dense {
            // The peaks alone: no condition is evaluated (an empty list).
            let at = |t: f64| watched_on(kernel, regime, (&piece, &vpiece), &[], d, t);
            let tracker = &mut self.tracker;
            if top_inside {
                interior_extrema(t0, w0.top, t1, w1.top, &mut |t| at(t).top, top_matters, &mut |t, v| {
                    if t <= t_stop {
                        tracker.top(v);
                    }
                });
            }
            if fy_inside {
                interior_extrema(t0, w0.fy, t1, w1.fy, &mut |t| at(t).fy, fy_matters, &mut |t, v| {
                    if t <= t_stop && v <= 0.0 {
                        tracker.reaction_lost();
                    }
                });
            }
            if ratio_inside {
                interior_extrema(t0, ratio(&w0), t1, ratio(&w1), &mut |t| ratio(&at(t)), demand_matters, &mut |t, _| {
                    if t <= t_stop {
                        let w = at(t);
                        tracker.pivot(w.fx.v, w.fy.v);
                    }
                });
            }
        }

        // Built only for an observer that wants it (a copy of the polynomial otherwise spent).
        let interpolant = || match &dense {
            Some(d) => Interpolant::Dense(d.widen()),
            None => Interpolant::Constant(y1),
        };
        self.emit_step(interpolant, t_stop)?;
        if let (Some((tb, c)), Some(d)) = (first, dense) {
            self.t = tb;
            self.y = if tb >= t1 { y1 } else { State::from_components(&d.state(tb)) };
            self.restart = true;
            self.record_instant();
            self.switch(c)?;
            return self.next_instant();
        }
        self.t = t1;
        self.y = y1;
        self.watch = w1;
        self.tracker.displacement(y1.theta, y1.slip);
        if rocking {
            self.tracker.top(w1.top.v);
            self.tracker.pivot(w1.fx.v, w1.fy.v);
        }
        // Within a segment the conditions were just checked on the step; only a
        // new segment (a kink or jump of the input) can make one hold at once.
        if self.t >= self.segment.kink || self.t >= self.vsegment.kink || self.t >= self.free_fall {
            self.next_instant()?;
        }
        Ok(())
    }

    /// The free flight that starts now, if the cascade's closed form applies
    /// (`cascade.rs`, "When it does not apply"): the tower has just left
    /// `θ = 0`, no ground motion is left to come, the building is absent or
    /// stuck with a margin at both ends of the flight, the flight is small
    /// (`ψm <= 0.1 √rtol`) and ends within the run. Inlined: its first test,
    /// that the integrator restarts (a flight starts only at an event), ends
    /// it at every other step of the run.
    #[inline(always)]
    fn free_flight(&self) -> Option<Flight> {
        if !self.restart {
            return None;
        }
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return None };
        let s = pivot.sign();
        let omega = s * self.y.theta_dot;
        let input_over = |segment: &Segment| segment.kink == f64::INFINITY && matches!(segment.piece, Piece::Constant(a) if a == 0.0);
        if self.y.theta != 0.0 || omega <= 0.0 || !input_over(&self.segment) || !input_over(&self.vsegment) {
            return None;
        }
        let flight = self.kernel.free_flight(s, self.t, omega, self.y.slip, 0.1 * self.rtol.sqrt())?;
        if self.t + flight.duration >= self.end {
            return None;
        }
        if self.kernel.has_building {
            if self.regime.building != BuildingRegime::Stick {
                return None;
            }
            // The stick demand at the impact (the same on arrival, `θ̇²` being
            // equal) and at the apex, with a margin of 1e-6 μs M g: the
            // demand inside departs from these by a relative `ψm² / 8`.
            let margin = 1e-6 * self.kernel.mu_s * self.kernel.total * self.kernel.g;
            let (list, n) = conditions(self.kernel, self.regime);
            let apex = State {
                theta: s * flight.apex,
                theta_dot: 0.0,
                slip: self.y.slip,
                slip_vel: 0.0,
            };
            let ends = [self.y, apex];
            let holds = ends.iter().all(|y| {
                list[..n]
                    .iter()
                    .filter(|c| !c.of_theta())
                    .all(|c| c.value(self.kernel, self.regime, 0.0, self.kernel.g, y) < -margin)
            });
            if !holds {
                return None;
            }
        }
        Some(flight)
    }

    /// The rest of an impact cascade, jumped in closed form flight after
    /// flight for as long as [`Self::free_flight`] applies: each flight is
    /// given to the observer, and the impact at its end applied as any
    /// impact (its event, the count, the rest below the threshold).
    ///
    /// The peaks along the cascade are read at the first two flights (one on
    /// each pivot) and at the last two, not at every flight in between: with
    /// no ground motion, each quantity the tracker follows is, at an impact
    /// (`θ = 0`), an affine function of `θ̇²` (or a ratio of two such, the
    /// pivot's friction demand), and at an apex (`θ̇ = 0`) a smooth function
    /// of the apex `ψm`. Both `θ̇²` and `ψm` fall monotonically from flight to
    /// flight on each pivot, so the impacts' values are monotone along the
    /// cascade and bounded by its ends, and the apexes' depart from
    /// monotone by at most `max|q''| Δψm² / 8` (the bound the module docs of
    /// `cascade.rs` give for the inside of one flight, `Δψm <= ψm`). The
    /// instants of the flights in between are not evaluated: the tracker's
    /// evaluations at two impacts and an apex were two thirds of the
    /// cascade's cost.
    fn advance_free_flight(&mut self, first: Flight) -> Result<(), Error> {
        let mut flight = first;
        let mut jumped = 0u32;
        let result = loop {
            // From the third flight on, instants wait in `deferred`; the
            // last few are fed to the tracker when the cascade ends.
            self.deferring = jumped >= 2;
            let t1 = flight.t0 + flight.duration;
            if let Err(e) = self.emit_step(|| Interpolant::Flight(flight), t1) {
                break Err(e);
            }
            let apex = State {
                theta: flight.s * flight.apex,
                theta_dot: 0.0,
                slip: flight.slip,
                slip_vel: 0.0,
            };
            self.note_instant(0.0, self.kernel.g, apex);
            self.t = t1;
            self.y = State {
                theta: 0.0,
                theta_dot: -flight.s * flight.omega,
                slip: flight.slip,
                slip_vel: 0.0,
            };
            self.restart = true;
            self.note_instant(self.a_g(self.t), self.g_e(self.t), self.y);
            if let Err(e) = self.switch(Condition::Impact).and_then(|()| self.next_instant()) {
                break Err(e);
            }
            jumped += 1;
            match self.free_flight() {
                Some(next) if !self.finished => flight = next,
                _ => break Ok(()),
            }
        };
        self.deferring = false;
        for instant in self.deferred.drain() {
            track(&mut self.tracker, self.kernel, instant);
        }
        result
    }

    /// Feeds the tracker the response at `y` in the current regime, or keeps
    /// it among the last instants of a cascade (see [`Self::advance_free_flight`]).
    fn note_instant(&mut self, a_g: f64, g_e: f64, y: State) {
        let instant = (self.regime, a_g, g_e, y);
        if self.deferring {
            self.deferred.push(instant);
        } else {
            track(&mut self.tracker, self.kernel, instant);
        }
    }

    /// Tells the observer about the stretch from the current time to `t1`, and
    /// accumulates the time spent in the regime.
    fn emit_step(&mut self, interpolant: impl FnOnce() -> Interpolant, t1: f64) -> Result<(), Error> {
        self.tracker.time(self.regime.motion(), t1 - self.t);
        if self.observer.wants_steps() {
            let step = Step {
                kernel: self.kernel,
                piece: self.segment.piece,
                vpiece: self.vsegment.piece,
                interpolant: interpolant(),
                t0: self.t,
                t1,
                regime: self.regime,
            };
            if let ControlFlow::Break(halt) = self.observer.on_step(&step) {
                return Err(Error::halted(halt, self.t));
            }
        }
        Ok(())
    }

    /// Feeds the tracker the response at the current instant.
    fn record_instant(&mut self) {
        self.note_instant(self.a_g(self.t), self.g_e(self.t), self.y);
    }

    /// Applies every condition that already holds at the current instant, or
    /// that is zero and growing (its time derivative positive).
    fn settle(&mut self) -> Result<(), Error> {
        while !self.finished {
            if self.falls_back() {
                self.set_down()?;
                continue;
            }
            let (list, n) = conditions(self.kernel, self.regime);
            let conditions = if list[..n].iter().all(|c| c.of_theta()) {
                // Conditions on θ alone (a rocking tower on a fixed base): the
                // value is θ's and the derivative θ̇'s, with no ground motion,
                // lean or acceleration to evaluate (one of these per impact).
                let (s, theta) = (pivot_sign(self.regime), Jet::new(self.y.theta, self.y.theta_dot));
                let mut conditions = [Jet::default(); MAX_CONDITIONS];
                for (slot, c) in conditions.iter_mut().zip(&list[..n]) {
                    *slot = c.theta_margin(s, theta);
                }
                conditions
            } else {
                let acc = self.accelerations_now();
                self.watch = watched(
                    self.kernel,
                    self.regime,
                    &self.segment.piece,
                    &self.vsegment.piece,
                    &list[..n],
                    self.t,
                    &self.y,
                    Some(acc),
                );
                self.settled = Some(Settled {
                    t: self.t,
                    y: self.y,
                    regime: self.regime,
                    pieces: (self.segment.piece, self.vsegment.piece),
                    acc,
                });
                self.watch.conditions
            };
            let holds = |i: usize| match (list[i], conditions[i].v) {
                // At u̇ = 0 the relative acceleration does not decide (it is
                // zero when μk = μs): Coulomb's law does.
                (Condition::SlipStop, 0.0) => !self.slides_on(),
                _ => holds_now(conditions[i]),
            };
            let Some(i) = (0..n).find(|&i| holds(i)) else {
                return Ok(());
            };
            self.switch(list[i])?;
        }
        Ok(())
    }

    /// Coulomb's law at `u̇ = 0` for a building in `slip σ`: it slides on only
    /// where the friction demand of the building held stuck exceeds `μs N`
    /// towards its slip, or reaches it and grows. That is the condition that
    /// starts the slip, evaluated as `settle` evaluates it on the stuck
    /// building, so the two decisions cannot disagree at one instant (they
    /// did when the relative acceleration decided: with `μk = μs` a slip
    /// starts with `σ ü` zero to rounding, and its sign flipped the building
    /// between stick and slip until the run gave up). With `μk = μs`, `σ ü`
    /// and `σ u⃛` at `u̇ = 0` are the demand's margin over `μs N` and its
    /// rate, divided by the building's effective mass: this is the decision
    /// of the next derivative.
    fn slides_on(&self) -> bool {
        let BuildingRegime::Slip(dir) = self.regime.building else { return false };
        let starts = match dir {
            SlipDirection::Negative => Condition::SlipNegative,
            SlipDirection::Positive => Condition::SlipPositive,
        };
        let stuck = Regime {
            building: BuildingRegime::Stick,
            ..self.regime
        };
        let w = watched(self.kernel, stuck, &self.segment.piece, &self.vsegment.piece, &[starts], self.t, &self.y, None);
        holds_now(w.conditions[0])
    }

    /// Counts a regime switch at the current instant; beyond
    /// [`MAX_SWITCHES_AT_ONE_INSTANT`] the run reports chattering, `last` the
    /// name of the switch that went beyond.
    fn count_switch(&mut self, last: &'static str) -> Result<(), Error> {
        if self.t.to_bits() == self.switch_time.to_bits() {
            self.switches += 1;
            if self.switches > MAX_SWITCHES_AT_ONE_INSTANT {
                return Err(Error::Chattering { time: self.t, last });
            }
        } else {
            self.switch_time = self.t;
            self.switches = 1;
        }
        Ok(())
    }

    /// Whether the tower, rocking but still at `θ = 0` with `θ̇ = 0` (it has
    /// just lifted), no longer meets the uplift condition of its pivot on the
    /// building as it now moves: then it would be driven back across `θ = 0`,
    /// about a corner into the building, and it stands instead. This happens
    /// where the building starts to slide at the instant the tower lifts and,
    /// sliding, carries it at less than `g tan α`. The condition is the one
    /// that lifts a standing tower, evaluated as `settle` evaluates it, so
    /// that lifting and setting down cannot both hold at one instant (at an
    /// uplift located on the input, `θ̈` is zero to rounding).
    fn falls_back(&self) -> bool {
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return false };
        if self.y.theta != 0.0 || self.y.theta_dot != 0.0 {
            return false;
        }
        let lifts = match pivot {
            Pivot::Negative => Condition::UpliftNegative,
            Pivot::Positive => Condition::UpliftPositive,
        };
        let standing = Regime {
            tower: TowerRegime::Rest,
            ..self.regime
        };
        let w = watched(
            self.kernel,
            standing,
            &self.segment.piece,
            &self.vsegment.piece,
            &[lifts],
            self.t,
            &self.y,
            None,
        );
        !holds_now(w.conditions[0])
    }

    /// Puts a tower that [`Self::falls_back`] at rest: a rest event, no impact.
    fn set_down(&mut self) -> Result<(), Error> {
        self.count_switch("rest")?;
        self.restart = true;
        self.regime.tower = TowerRegime::Rest;
        let at = self.y;
        self.emit(EventKind::Rest, at)
    }

    /// Performs the transition of `condition` at the current instant.
    fn switch(&mut self, condition: Condition) -> Result<(), Error> {
        self.count_switch(condition.name())?;
        self.restart = true;
        let before = self.y;
        let a_g = self.a_g(self.t);
        let kind = match condition {
            Condition::UpliftNegative | Condition::UpliftPositive => {
                let pivot = if condition == Condition::UpliftNegative {
                    Pivot::Negative
                } else {
                    Pivot::Positive
                };
                self.regime.tower = TowerRegime::Rocking(pivot);
                self.tracker.summary.first_uplift_time.get_or_insert(self.t);
                EventKind::Uplift
            }
            Condition::Impact => return self.impact(),
            Condition::Overturn => {
                self.finished = true;
                self.tracker.summary.overturn_time = Some(self.t);
                self.tracker.summary.end_reason = EndReason::Overturned;
                EventKind::Overturn
            }
            Condition::SlipNegative | Condition::SlipPositive => {
                let dir = if condition == Condition::SlipNegative {
                    SlipDirection::Negative
                } else {
                    SlipDirection::Positive
                };
                self.regime.building = BuildingRegime::Slip(dir);
                self.tracker.summary.first_slip_time.get_or_insert(self.t);
                EventKind::Slip
            }
            Condition::SlipStop => {
                self.y.slip_vel = 0.0;
                let (force, normal) = self
                    .kernel
                    .stick_demand(self.regime.tower, a_g, self.g_e(self.t), self.y.theta, self.y.theta_dot);
                let old = self.regime.building;
                if force.abs() <= self.kernel.mu_s * normal {
                    self.regime.building = BuildingRegime::Stick;
                    EventKind::Stick
                } else {
                    let dir = SlipDirection::of_sign(-force);
                    self.regime.building = BuildingRegime::Slip(dir);
                    if old == BuildingRegime::Slip(dir) {
                        return Ok(());
                    }
                    EventKind::Reverse
                }
            }
        };
        self.emit(kind, before)?;
        Ok(())
    }

    /// The impact law (`impact.rs`): the pivot flips, `θ̇` and `u̇` jump; a
    /// building that starts or stops sliding through the impact is an event of
    /// its own at the same instant. Below [`REST_ANGULAR_VELOCITY`] the tower
    /// stands, unless the pivot line accelerates enough to lift it at once.
    fn impact(&mut self) -> Result<(), Error> {
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return Ok(()) };
        let before = self.y;
        let after = self.kernel.impact_law(pivot.sign(), self.y.theta_dot, self.y.slip_vel, self.regime.building);
        self.y.theta = 0.0;
        self.y.theta_dot = after.theta_dot;
        self.y.slip_vel = after.slip_vel;
        self.tracker.summary.impacts += 1;
        self.regime.tower = TowerRegime::Rocking(pivot.flipped());
        let old = self.regime.building;
        self.regime.building = after.building;
        self.emit(EventKind::Impact, before)?;
        if after.building != old {
            let kind = match (old, after.building) {
                (_, BuildingRegime::Stick) => EventKind::Stick,
                (BuildingRegime::Stick, BuildingRegime::Slip(_)) => {
                    self.tracker.summary.first_slip_time.get_or_insert(self.t);
                    EventKind::Slip
                }
                (BuildingRegime::Slip(_), BuildingRegime::Slip(_)) => EventKind::Reverse,
            };
            let at = self.y;
            self.emit(kind, at)?;
        }
        if self.y.theta_dot.abs() < REST_ANGULAR_VELOCITY {
            let before = self.y;
            self.y.theta_dot = 0.0;
            self.regime.tower = TowerRegime::Rest;
            let g_e = self.g_e(self.t);
            let acc_pivot = self.kernel.pivot_acceleration_at_rest(self.regime.building, self.a_g(self.t), g_e);
            // If it would lift at once, `settle` switches to rocking: no rest in between.
            if acc_pivot.abs() <= self.kernel.uplift_threshold(g_e) {
                self.emit(EventKind::Rest, before)?;
            }
        }
        Ok(())
    }

    fn emit(&mut self, kind: EventKind, before: State) -> Result<(), Error> {
        self.tracker.summary.events += 1;
        let event = Event {
            time: self.t,
            kind,
            before,
            after: self.y,
            regime: self.regime,
        };
        if let ControlFlow::Break(halt) = self.observer.on_event(&event) {
            return Err(Error::halted(halt, self.t));
        }
        self.record_instant();
        Ok(())
    }
}

/// Whether a condition with its time derivative, at the current instant,
/// switches at once: it already holds, or it is zero and growing.
fn holds_now(j: Jet) -> bool {
    j.v > 0.0 || (j.v == 0.0 && j.d > 0.0)
}

/// For a condition that is zero at `t0`: a point in `(t0, t1)` where it is
/// negative, found by halving towards `t0` (the dense output's first two
/// Taylor terms are exact there, so the motion's departure shows).
fn leaving_point(value: &impl Fn(f64) -> f64, t0: f64, t1: f64) -> Option<(f64, f64)> {
    let mut dt = t1 - t0;
    for _ in 0..80 {
        dt *= 0.5;
        let t = t0 + dt;
        if t <= t0 {
            return None;
        }
        let v = value(t);
        if v < 0.0 {
            return Some((t, v));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::free_of_roots;
    use crate::jet::Jet;

    /// A velocity moving away from zero, `v = 1 + 10 t` on a step of 0.1
    /// with a curvature bound of 1000 (it has none: the bound is what the
    /// model could allow): the rate bound (100: `|v0| + |v1|` = 3 against
    /// 10) and the chord (`c h²/8` = 1.25 against the smaller end, 1)
    /// prove nothing; the tangents do (1.5 at mid-step from either end,
    /// above 1.25). With the slopes reversed (`v` falling towards zero from
    /// both ends, 0.5 at mid-step) nothing is proved.
    #[test]
    fn the_tangents_prove_a_velocity_moving_away_from_zero() {
        let (h, c) = (0.1, 1000.0);
        assert!(free_of_roots(Jet::new(1.0, 10.0), Jet::new(2.0, 10.0), h, 100.0, c));
        assert!(!free_of_roots(Jet::new(1.0, -10.0), Jet::new(2.0, 10.0), h, 100.0, c));
    }

    /// A parabola with equal end values `m` that dips by exactly
    /// `c h² / 8` at mid-step, `c` its second derivative, has roots inside
    /// when `m < c h² / 8` and none when `m > c h² / 8`: the chord bound is
    /// sharp, and `free_of_roots` must refuse the first and may accept the
    /// second (its rate bound `c h / 2` proves nothing there).
    #[test]
    fn the_chord_bound_is_sharp_on_a_parabola() {
        let (h, c) = (0.03, 40.0);
        let dip = c * h * h / 8.0;
        for m in [dip * (1.0 - 1e-6), dip * (1.0 + 1e-6)] {
            let v = |t: f64| m + 0.5 * c * t * (t - h);
            let has_root = v(0.5 * h) <= 0.0;
            assert_eq!(has_root, m < dip);
            // Slopes ∓c h/2: the tangents fall by c h²/4 to mid-step and prove nothing either.
            let (v0, v1) = (Jet::new(v(0.0), -0.5 * c * h), Jet::new(v(h), 0.5 * c * h));
            assert_eq!(free_of_roots(v0, v1, h, 0.5 * c * h, c), !has_root, "m / dip = {}", m / dip);
        }
    }

    /// `v = c + A sin(ω t + φ)` over a grid of offsets, phases and steps:
    /// wherever `free_of_roots` (with the exact bounds `A ω`, `A ω²`)
    /// claims no root, 10⁴ samples of `v` keep the ends' sign. It must also
    /// accept some steps, or the test proves nothing.
    #[test]
    fn no_claimed_step_hides_a_root() {
        let (amplitude, omega) = (1.0, 2.0 * std::f64::consts::PI * 3.0);
        let mut accepted = 0;
        for i in 0..40 {
            let offset = -1.5 + 3.0 * i as f64 / 39.0;
            for j in 0..24 {
                let phase = std::f64::consts::TAU * j as f64 / 24.0;
                for h in [0.005, 0.02, 0.05, 0.1] {
                    let v = |t: f64| Jet::new(offset + amplitude * (omega * t + phase).sin(), amplitude * omega * (omega * t + phase).cos());
                    if !free_of_roots(v(0.0), v(h), h, amplitude * omega, amplitude * omega * omega) {
                        continue;
                    }
                    accepted += 1;
                    let sign = v(0.0).v.signum();
                    assert!(
                        (0..=10_000).all(|k| v(h * k as f64 / 1e4).v * sign > 0.0),
                        "offset {offset}, phase {phase}, h {h}"
                    );
                }
            }
        }
        assert!(accepted > 1000, "{accepted}");
    }
}
