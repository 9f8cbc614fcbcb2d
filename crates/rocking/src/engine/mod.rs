//! The engine: the event-driven run. Integrate the smooth motion of one regime, locate the
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

//!
//! The path of one step, in the order of [`Run::execute`] and
//! `Run::advance_dynamic_with` (`step.rs`):
//!
//! 1. `rhs.rs`: the right-hand side of the regime under the inputs' pieces;
//! 2. the integrator takes one step (`integrator/`);
//! 3. `watch.rs`: what is watched at the step's end;
//! 4. `screen.rs`: which searches inside the step its ends cannot rule out;
//! 5. `crossing.rs`: the extremes of θ and the first transition inside;
//! 6. `peaks.rs`: the peaks inside, up to that transition, to the summary;
//! 7. `transition.rs`: the transition applied (a switch of regime, the
//!    impact law) and the conditions that then hold at once.
//!
//! Beside it: `static_phase.rs` (nothing moves relative to the ground),
//! `flight.rs` (the end of an impact cascade in closed form), `input.rs`
//! (the inputs' segments and the effective gravity).

pub(crate) mod crossing;
mod flight;
mod input;
mod peaks;
mod rhs;
pub(crate) mod screen;
mod static_phase;
mod step;
mod transition;
mod watch;

use crate::equations::{Accelerations, Kernel};
use crate::error::Error;
use crate::ground::{GroundMotion, Piece};
use crate::integrator::{Dop853, StepFailure};
use crate::observer::{Interpolant, Observer, Step};
use crate::regime::{BuildingRegime, Regime, State, TowerRegime};
use crate::response::{free_motion_overturns, Closing, EndState, Summary, Tracker};
use crate::simulate::{Initial, Settings};
use flight::Deferred;
use input::Input;
use std::ops::ControlFlow;
use watch::Watched;

/// No vertical ground motion.
static NO_MOTION: GroundMotion = GroundMotion::None;

/// A run; the integrator carries the first `N` components of `(θ, θ̇, u, u̇)`
/// (2 on a fixed base, 4 on a building).
struct Run<'a, O: Observer, const N: usize> {
    /// Borrowed, not owned: the step copies it out for its closures, and a
    /// reference is one word where the kernel is two dozen.
    kernel: &'a Kernel,
    input: Input<'a>,
    integ: Integration<N>,
    regime: Regime,
    switches: Switches,
    cache: Cache,
    report: Report<'a, O>,
    /// The run has ended (the tower overturned).
    finished: bool,
    /// An event was emitted at the current instant whose response is not
    /// yet recorded: it is, once `settle` has applied every switch due
    /// there, in the regime that holds after them (a regime that another
    /// event ends at once lasts no time, and its response is no peak).
    instant_due: bool,
}

/// The integrator's state: the time, the state and the stepper.
struct Integration<const N: usize> {
    t: f64,
    y: State,
    stepper: Dop853<N>,
    /// The relative tolerance (it bounds the flights taken in closed form).
    rtol: f64,
    /// Whether the stepper must restart at `(t, y)` (after an event or a kink).
    restart: bool,
}

/// Switches at one instant, to stop chattering.
struct Switches {
    count: u32,
    time: f64,
    /// The last instant the tower fell straight back after lifting
    /// (`Run::fall_straight_back`): its uplift is not taken again there.
    fell_back: f64,
}

/// What is kept from one instant to the next so as not to compute it twice.
struct Cache {
    /// The watched quantities at `(t, y)`.
    watch: Watched,
    /// Set when `settle` leaves `watch` computed at the current instant (see [`Settled`]).
    settled: Option<Settled>,
    /// Whether [`Cache::settled`] is used; only the test that compares the
    /// reuse with recomputation switches it off.
    reuse_settled: bool,
}

#[cfg(test)]
thread_local! {
    /// [`Cache::reuse_settled`] of the runs of this thread, for that test.
    static REUSE_SETTLED: std::cell::Cell<bool> = const { std::cell::Cell::new(true) };
}

/// Where the run reports: the summary being kept and the observer.
struct Report<'a, O> {
    tracker: Tracker,
    observer: &'a mut O,
    /// Inside an impact cascade jumped in closed form: instants go to
    /// `deferred` instead of the tracker.
    deferring: bool,
    deferred: Deferred,
}

/// What `settle` computed [`Cache::watch`] from, with the accelerations there.
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

/// Runs `kernel` under the inputs from `initial`, the tower in `tower`.
pub(crate) fn run<O: Observer, const N: usize>(
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
        input: Input {
            ground,
            vertical: vertical.unwrap_or(&NO_MOTION),
            has_vertical: vertical.is_some_and(|v| !matches!(v, GroundMotion::None)),
            vertical_given: vertical.is_some(),
            end: settings.duration,
            segment: ground.segment(0.0),
            vsegment: NO_MOTION.segment(0.0),
            free_fall: f64::INFINITY,
        },
        integ: Integration {
            t: 0.0,
            y: State {
                theta: initial.theta,
                theta_dot: initial.theta_dot,
                ..State::default()
            },
            stepper: Dop853::new(settings.rtol, settings.atol),
            rtol: settings.rtol,
            restart: true,
        },
        regime: Regime {
            tower,
            building: BuildingRegime::Stick,
        },
        switches: Switches {
            count: 0,
            time: f64::NAN,
            fell_back: f64::NAN,
        },
        cache: Cache {
            watch: Watched::default(),
            settled: None,
            #[cfg(not(test))]
            reuse_settled: true,
            #[cfg(test)]
            reuse_settled: REUSE_SETTLED.with(std::cell::Cell::get),
        },
        report: Report {
            tracker: Tracker::new(),
            observer,
            deferring: false,
            deferred: Deferred::default(),
        },
        finished: false,
        instant_due: false,
    };
    run.enter_vertical();
    run.execute()
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
        while !self.finished && self.integ.t < self.input.end {
            if self.is_static() {
                self.advance_static()?;
            } else if let Some(flight) = self.free_flight() {
                self.advance_free_flight(flight)?;
            } else {
                self.advance_dynamic()?;
            }
        }
        let (end_state, will_overturn) = self.end_verdict();
        let min_effective_gravity = if self.input.has_vertical {
            Some(self.min_effective_gravity(self.integ.t))
        } else {
            // A vertical input of `GroundMotion::None`: g throughout.
            self.input.vertical_given.then_some(self.kernel.g)
        };
        let closing = Closing {
            evaluations: self.integ.stepper.evaluations,
            end_state,
            will_overturn,
            min_effective_gravity,
        };
        Ok(self.report.tracker.finish(self.kernel, self.integ.t, &self.integ.y, closing))
    }

    /// The tower's state at the end and what its free motion will do
    /// ([`free_motion_overturns`]; unknown while input remains or the building slides).
    fn end_verdict(&self) -> (EndState, Option<bool>) {
        let k = self.kernel;
        let (theta, theta_dot) = (self.integ.y.theta, self.integ.y.theta_dot);
        let state = match self.regime.tower {
            _ if self.report.tracker.overturned() => EndState::Overturned,
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
            _ if !over(self.integ.t, self.input.ground) || !over(self.integ.t, self.input.vertical) || self.regime.building != BuildingRegime::Stick => None,
            EndState::Rest => Some(false),
            _ => Some(free_motion_overturns(k.alpha, k.free_rocking_p2().sqrt(), k.restitution, theta, theta_dot)),
        };
        (state, verdict)
    }

    /// Nothing moves relative to the ground: the state is constant and every
    /// condition depends on `a_g` alone.
    fn is_static(&self) -> bool {
        self.regime.tower == TowerRegime::Rest && self.regime.building == BuildingRegime::Stick
    }

    /// The accelerations at the current instant.
    fn accelerations_now(&self) -> Accelerations<f64> {
        self.kernel.accelerations(
            self.regime,
            self.a_g(self.integ.t),
            self.g_e(self.integ.t),
            self.integ.y.theta,
            self.integ.y.theta_dot,
        )
    }

    /// After reaching a new instant: enter the next segment of the input if its
    /// end was reached, then apply every condition that already holds.
    fn next_instant(&mut self) -> Result<(), Error> {
        if self.integ.t >= self.input.segment.kink {
            // A kink or jump of the input: new expression, conditions re-checked at once.
            self.input.segment = self.input.ground.segment(self.integ.t);
            self.integ.restart = true;
        }
        if self.integ.t >= self.input.vsegment.kink {
            self.enter_vertical();
            self.integ.restart = true;
        }
        self.check_free_fall()?;
        self.settle()
    }

    /// Tells the observer about the stretch from the current time to `t1`, and
    /// accumulates the time spent in the regime.
    fn emit_step(&mut self, interpolant: impl FnOnce() -> Interpolant, t1: f64) -> Result<(), Error> {
        self.report.tracker.time(self.regime.motion(), t1 - self.integ.t);
        if self.report.observer.wants_steps() {
            let step = Step {
                kernel: self.kernel,
                piece: self.input.segment.piece,
                vpiece: self.input.vsegment.piece,
                interpolant: interpolant(),
                t0: self.integ.t,
                t1,
                regime: self.regime,
                stack: None,
            };
            if let ControlFlow::Break(halt) = self.report.observer.on_step(&step) {
                return Err(Error::halted(halt, self.integ.t));
            }
        }
        Ok(())
    }

    /// Feeds the tracker the response at the current instant.
    pub(super) fn record_instant(&mut self) {
        self.note_instant(self.a_g(self.integ.t), self.g_e(self.integ.t), self.integ.y);
    }
}

#[cfg(test)]
mod tests {
    //! The fast paths of the run against the general ones.

    use super::*;
    use crate::ground::Harmonic;
    use crate::reference::solid_block;
    use crate::Model;

    const G: f64 = 9.81;

    /// On a fixed base the integrator carries `(θ, θ̇)` only; carrying all
    /// four components (the slip's two stay zero) is the general path. The
    /// two are not the same steps: DOP853's error norm is a root mean square
    /// over the components carried, so with two more zeros the same error
    /// reads √2 smaller and the steps are longer. The answers agree to the
    /// tolerance asked (rtol 1e-10 here): max |θ| to 1e-7 relative, the
    /// instants of the first uplift (located on the input before any step)
    /// bit for bit, the impacts in number.
    #[test]
    fn two_components_on_a_fixed_base_agree_with_four() {
        let model = Model::new(Some(solid_block(0.5, 2.0)), None, G).unwrap_or_else(|e| panic!("{e}"));
        let kernel = Kernel::new(&model);
        let ground = GroundMotion::Harmonic(Harmonic::new(0.5 * G, 2.0, 6.0, 0.0).unwrap_or_else(|e| panic!("{e}")));
        let settings = Settings {
            duration: 8.0,
            rtol: 1e-10,
            atol: 1e-12,
        };
        let go = |four: bool| {
            let tower = TowerRegime::Rest;
            let r = if four {
                run::<(), 4>(&kernel, &ground, None, &settings, tower, Initial::default(), &mut ())
            } else {
                run::<(), 2>(&kernel, &ground, None, &settings, tower, Initial::default(), &mut ())
            };
            r.unwrap_or_else(|e| panic!("{e}"))
        };
        let (two, four) = (go(false), go(true));
        assert!(two.impacts > 10, "{}", two.impacts);
        assert_eq!(two.impacts, four.impacts);
        assert_eq!(two.first_uplift_time.map(f64::to_bits), four.first_uplift_time.map(f64::to_bits));
        let rel = (two.max_abs_theta() - four.max_abs_theta()).abs() / two.max_abs_theta();
        assert!(rel < 1e-7, "{} against {}", two.max_abs_theta(), four.max_abs_theta());
        assert_ne!(two.evaluations, four.evaluations, "not the same steps: the test compares two paths");
    }

    /// [`Settled`]: the restart at a kink of a recorded input takes the
    /// right-hand side and the watched quantities `settle` computed there,
    /// claiming they are bit for bit those the restart would compute. A
    /// tower rocking on a sliding building under a sampled sine (a kink
    /// every 0.01 s, 400 of them; the building's conditions make `settle`
    /// compute them at each) runs the same with the reuse switched off:
    /// every event and the summary bit for bit, only the count of
    /// right-hand side evaluations lower with it.
    #[test]
    fn settled_reuse_is_recomputation() {
        use crate::{Building, EventLog, NormalForce, Record};
        let building = Building::new(5.0e3, 0.3, 0.25, NormalForce::Constant).unwrap_or_else(|e| panic!("{e}"));
        let model = Model::new(Some(solid_block(0.4, 2.0)), Some(building), G).unwrap_or_else(|e| panic!("{e}"));
        let kernel = Kernel::new(&model);
        let times: Vec<f64> = (0..=400).map(|i| 0.01 * f64::from(i)).collect();
        let values = times.iter().map(|t| 0.45 * G * (std::f64::consts::TAU * 2.0 * t).sin()).collect();
        let ground = GroundMotion::Record(Record::from_samples(times, values).unwrap_or_else(|e| panic!("{e}")));
        let settings = Settings {
            duration: 6.0,
            ..Settings::default()
        };
        let go = |reuse: bool| {
            REUSE_SETTLED.with(|r| r.set(reuse));
            let mut log = EventLog::default();
            let summary = run::<EventLog, 4>(&kernel, &ground, None, &settings, TowerRegime::Rest, Initial::default(), &mut log);
            REUSE_SETTLED.with(|r| r.set(true));
            (summary.unwrap_or_else(|e| panic!("{e}")), log.events)
        };
        let (mut with, events_with) = go(true);
        let (mut without, events_without) = go(false);
        assert!(with.impacts > 5 && with.first_slip_time.is_some(), "the case must rock and slide: {with:?}");
        assert_eq!(format!("{events_with:?}"), format!("{events_without:?}"));
        assert!(
            with.evaluations < without.evaluations,
            "{} against {}: no reuse to test",
            with.evaluations,
            without.evaluations
        );
        (with.evaluations, without.evaluations) = (0, 0);
        assert_eq!(format!("{with:?}"), format!("{without:?}"));
    }

    /// `settle` evaluates the conditions of a tower rocking on a fixed base
    /// (both of θ alone) from θ and θ̇ only; the general path is
    /// [`watch::watched`], with the input, the lean and the accelerations.
    /// Bit for bit on a grid of states, both pivots.
    #[test]
    fn settle_on_theta_alone_is_the_general_path() {
        let model = Model::new(Some(solid_block(0.5, 2.0)), None, G).unwrap_or_else(|e| panic!("{e}"));
        let kernel = Kernel::new(&model);
        let piece = GroundMotion::Harmonic(Harmonic::new(0.5 * G, 2.0, 6.0, 0.0).unwrap_or_else(|e| panic!("{e}")))
            .segment(0.1)
            .piece;
        for pivot in [crate::regime::Pivot::Negative, crate::regime::Pivot::Positive] {
            let regime = Regime {
                tower: TowerRegime::Rocking(pivot),
                building: BuildingRegime::Stick,
            };
            let list = crate::condition::conditions(&kernel, regime);
            assert!(list.iter().all(|c| c.of_theta()), "{:?}", list);
            for i in 0..40 {
                for j in [-1.0, 0.0, 0.7] {
                    let y = State {
                        theta: -1.4 + 0.07 * f64::from(i),
                        theta_dot: j,
                        ..State::default()
                    };
                    let general = watch::watched(&kernel, regime, (&piece, &Piece::Constant(0.0)), list, 0.3, &y, None);
                    for (k, c) in list.iter().enumerate() {
                        let fast = c.theta_margin(pivot.sign(), crate::jet::Jet::new(y.theta, y.theta_dot));
                        assert_eq!(
                            (fast.v.to_bits(), fast.d.to_bits()),
                            (general.conditions[k].v.to_bits(), general.conditions[k].d.to_bits()),
                            "{c:?} at {y:?}"
                        );
                    }
                }
            }
        }
    }
}
