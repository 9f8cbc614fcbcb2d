//! The summary of a run: peaks located on the dense output, counts and times.

use crate::equations::Kernel;
use crate::event::{Event, EventKind};
use crate::regime::{Motion, Regime, State, TowerRegime};

/// Why a run ended (diffsol's `OdeSolverStopReason`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EndReason {
    /// The requested duration was reached.
    EndOfDuration,
    /// The tower overturned (`|θ| = π/2`).
    Overturned,
}

/// The tower at the end of a run.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum EndState {
    /// At rest on its base (`θ = 0`, `θ̇ = 0`), or no tower.
    Rest,
    /// Rocking within its stability limit (`|θ| <= α`).
    Rocking,
    /// Beyond its stability limit, `|θ| > α`: its centre of mass is past the pivot.
    BeyondStabilityLimit,
    /// Overturned (`|θ| = π/2`).
    Overturned,
}

impl EndState {
    /// The name in `summary.json`: `rest`, `rocking`, `beyond_stability_limit`, `overturned`.
    pub fn as_str(self) -> &'static str {
        match self {
            EndState::Rest => "rest",
            EndState::Rocking => "rocking",
            EndState::BeyondStabilityLimit => "beyond_stability_limit",
            EndState::Overturned => "overturned",
        }
    }
}

/// Whether a tower rocking freely from `θ`, `θ̇` (no ground motion, a base
/// that stays put) overturns, in closed form from its energy.
///
/// With `e = θ̇² / (2p²) + cos(α − |θ|)` (the energy `½ I_O θ̇² + m g R cos(α − |θ|)`
/// over `m g R`), the barrier is `e = 1`, at `|θ| = α`, and the motion between
/// impacts conserves `e`:
///
/// - moving outward (`θ θ̇ > 0`) it passes the barrier, and falls, if `e > 1`
///   (beyond it, `|θ| > α`, it falls whatever `e`);
/// - moving inward from beyond the barrier (or still there) it falls back
///   unless `e > 1`, and then goes on as below;
/// - otherwise it reaches `θ = 0` with `θ̇² / (2p²) = e − cos α`; the impact
///   multiplies `θ̇` by `r`, and the tower falls if the flight on the other
///   side clears the barrier, `r² (e − cos α) > 1 − cos α`. Each later flight
///   starts slower (`r < 1`), so it is the last chance.
///
/// A tower that rests (`θ = 0`, `θ̇ = 0`) stays.
pub fn free_motion_overturns(alpha: f64, p: f64, restitution: f64, theta: f64, theta_dot: f64) -> bool {
    let lean = theta.abs();
    let outward = theta * theta_dot > 0.0;
    let e = theta_dot * theta_dot / (2.0 * p * p) + (alpha - lean).cos();
    if lean > alpha && (outward || e <= 1.0) {
        return true;
    }
    if outward && lean <= alpha {
        return e > 1.0;
    }
    restitution * restitution * (e - alpha.cos()) > 1.0 - alpha.cos()
}

/// What a run found. Angles in rad, lengths in m, times in s, accelerations in m/s².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Summary {
    /// Largest and smallest `θ` (rad).
    pub theta_range: (f64, f64),
    /// Peak `|u|` (m).
    pub max_abs_slip: f64,
    /// `u` at the end of the run (m).
    pub final_slip: f64,
    /// Number of impacts.
    pub impacts: u64,
    /// When the tower overturned, if it did.
    pub overturn_time: Option<f64>,
    /// First uplift of the tower.
    pub first_uplift_time: Option<f64>,
    /// First slip of the building.
    pub first_slip_time: Option<f64>,
    /// Peak `|top_dx|`, horizontal displacement of the top centre relative to the building (m).
    pub max_top_displacement: f64,
    /// Peak absolute horizontal acceleration of the top centre (m/s²).
    pub max_top_abs_acceleration: f64,
    /// Peak `|f_x| / f_y` at the pivot (Shenton's demand on the tower's own
    /// friction); infinite once `f_y` reached zero ([`Summary::tower_uplift_detected`]).
    pub max_pivot_friction_demand: f64,
    /// Whether the vertical pivot reaction `f_y` became negative (the tower would fly).
    pub tower_uplift_detected: bool,
    /// Time spent in each [`Motion`], indexed by [`Motion::index`] (s).
    pub time_in_motion: [f64; 4],
    /// End of the run (s).
    pub end_time: f64,
    /// Why it ended.
    pub end_reason: EndReason,
    /// Number of regime changes.
    pub events: u64,
    /// Right-hand side evaluations.
    pub evaluations: u64,
    /// The least effective gravity `g + a_v` over the run (m/s²), with a vertical input.
    pub min_effective_gravity: Option<f64>,
    /// The tower at the end of the run.
    pub end_state: EndState,
    /// What the free motion from the end does ([`free_motion_overturns`]):
    /// `None` while ground motion remains after the end or the building slides.
    pub will_overturn: Option<bool>,
    /// What a stacked run found of the blocks above the tower; `None` without them.
    pub stack: Option<crate::stack::StackSummary>,
}

impl Summary {
    /// Peak `|θ|` (rad), from the extremes of θ located where `θ̇ = 0`.
    pub fn max_abs_theta(&self) -> f64 {
        self.theta_range.0.abs().max(self.theta_range.1.abs())
    }
    /// Whether the tower overturned.
    pub fn overturned(&self) -> bool {
        self.end_reason == EndReason::Overturned
    }
    /// Time in one motion (s).
    pub fn time_in(&self, motion: Motion) -> f64 {
        self.time_in_motion[motion.index()]
    }
}

/// The peaks kept so far, as the step's screening reads them: a search
/// inside a step is needed only where it could raise one of them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kept {
    /// Largest and smallest `θ` (rad).
    pub(crate) theta_range: (f64, f64),
    /// Peak absolute horizontal acceleration of the top centre (m/s²).
    pub(crate) max_top_abs_acceleration: f64,
    /// Peak `|f_x| / f_y` at the pivot.
    pub(crate) max_pivot_friction_demand: f64,
    /// Whether `f_y` has reached zero.
    pub(crate) tower_uplift_detected: bool,
}

/// What the run tells the summary when it ends.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Closing {
    /// Right-hand side evaluations.
    pub(crate) evaluations: u64,
    /// The tower at the end.
    pub(crate) end_state: EndState,
    /// What its free motion from there does, if known.
    pub(crate) will_overturn: Option<bool>,
    /// The least `g + a_v`, with a vertical input.
    pub(crate) min_effective_gravity: Option<f64>,
}

/// Accumulates the summary during a run: the engine's observer. Its counts
/// and first instants come from the events ([`Tracker::event`]), its peaks
/// from the instants and the peaks located inside steps; the screening reads
/// the peaks kept so far through [`Tracker::kept`].
#[derive(Debug, Clone)]
pub(crate) struct Tracker {
    pub(crate) summary: Summary,
}

impl Tracker {
    pub(crate) fn new() -> Self {
        Self {
            summary: Summary {
                theta_range: (0.0, 0.0),
                max_abs_slip: 0.0,
                final_slip: 0.0,
                impacts: 0,
                overturn_time: None,
                first_uplift_time: None,
                first_slip_time: None,
                max_top_displacement: 0.0,
                max_top_abs_acceleration: 0.0,
                max_pivot_friction_demand: 0.0,
                tower_uplift_detected: false,
                time_in_motion: [0.0; 4],
                end_time: 0.0,
                end_reason: EndReason::EndOfDuration,
                events: 0,
                evaluations: 0,
                min_effective_gravity: None,
                end_state: EndState::Rest,
                will_overturn: None,
                stack: None,
            },
        }
    }

    /// The peaks kept so far.
    #[inline]
    pub(crate) fn kept(&self) -> Kept {
        let s = &self.summary;
        Kept {
            theta_range: s.theta_range,
            max_top_abs_acceleration: s.max_top_abs_acceleration,
            max_pivot_friction_demand: s.max_pivot_friction_demand,
            tower_uplift_detected: s.tower_uplift_detected,
        }
    }

    /// An event of the run: the number of events and impacts, the first
    /// uplift and slip, and the overturning are read off the events alone.
    #[inline]
    pub(crate) fn event(&mut self, event: &Event) {
        let s = &mut self.summary;
        s.events += 1;
        match event.kind {
            EventKind::Impact => s.impacts += 1,
            EventKind::Uplift => {
                s.first_uplift_time.get_or_insert(event.time);
            }
            EventKind::Slip => {
                s.first_slip_time.get_or_insert(event.time);
            }
            EventKind::Overturn => {
                s.overturn_time = Some(event.time);
                s.end_reason = EndReason::Overturned;
            }
            EventKind::Rest | EventKind::Stick | EventKind::Reverse => {}
        }
    }

    /// A value of `θ` and `u` reached (at a step end, an extremum or an event).
    #[inline]
    pub(crate) fn displacement(&mut self, theta: f64, slip: f64) {
        self.theta(theta);
        self.summary.max_abs_slip = self.summary.max_abs_slip.max(slip.abs());
    }

    /// A value of `θ` reached.
    #[inline]
    pub(crate) fn theta(&mut self, theta: f64) {
        let s = &mut self.summary;
        s.theta_range = (s.theta_range.0.min(theta), s.theta_range.1.max(theta));
    }

    /// A value of the top centre's absolute horizontal acceleration (m/s²).
    #[inline]
    pub(crate) fn top(&mut self, acceleration: f64) {
        let s = &mut self.summary;
        s.max_top_abs_acceleration = s.max_top_abs_acceleration.max(acceleration.abs());
    }

    /// Pivot reactions per unit tower mass `(f_x, f_y) / m2` (m/s²).
    #[inline]
    pub(crate) fn pivot(&mut self, fx: f64, fy: f64) {
        let s = &mut self.summary;
        if fy > 0.0 {
            s.max_pivot_friction_demand = s.max_pivot_friction_demand.max(fx.abs() / fy);
        } else {
            self.reaction_lost();
        }
    }

    /// The vertical pivot reaction reached zero: the tower would fly, and the
    /// demand `|f_x| / f_y` grew without bound on the way (`f_x` does not
    /// vanish with `f_y`), so it has no finite maximum.
    #[inline]
    pub(crate) fn reaction_lost(&mut self) {
        self.summary.tower_uplift_detected = true;
        self.summary.max_pivot_friction_demand = f64::INFINITY;
    }

    /// The response at an instant (an event or the start): displacements, top
    /// acceleration and pivot reactions.
    #[inline]
    pub(crate) fn instant(&mut self, kernel: &Kernel, regime: Regime, a_g: f64, g_e: f64, y: &State) {
        self.displacement(y.theta, y.slip);
        if !kernel.has_tower {
            return;
        }
        let s = match regime.tower {
            TowerRegime::Rest => None,
            TowerRegime::Rocking(p) => Some(p.sign()),
        };
        let lean = s.map(|s| kernel.lean(s, y.theta));
        let acc = kernel.accelerations_leaning(regime.building, lean, a_g, g_e, y.theta_dot);
        let acc_pivot = a_g + acc.slip;
        let rotation = lean.map_or((0.0, 1.0), |lean| kernel.rotation(lean));
        let top = kernel.top_kinematics(s, rotation, y.theta_dot, acc.theta, acc_pivot).1;
        let (fx, fy) = kernel.pivot_reactions(lean, y.theta_dot, acc.theta, acc_pivot, g_e);
        self.top(top);
        self.pivot(fx, fy);
    }

    /// Time spent in one motion.
    #[inline]
    pub(crate) fn time(&mut self, motion: Motion, dt: f64) {
        self.summary.time_in_motion[motion.index()] += dt;
    }

    /// Whether an overturn event came.
    pub(crate) fn overturned(&self) -> bool {
        self.summary.overturned()
    }

    /// Closes the summary at the end of the run, at `t` in state `y`.
    pub(crate) fn finish(mut self, kernel: &Kernel, t: f64, y: &State, closing: Closing) -> Summary {
        self.displacement(y.theta, y.slip);
        let s = &mut self.summary;
        s.evaluations = closing.evaluations;
        s.end_state = closing.end_state;
        s.will_overturn = closing.will_overturn;
        s.min_effective_gravity = closing.min_effective_gravity;
        s.end_time = t;
        s.final_slip = y.slip;
        // The top displacement relative to the building grows monotonically with θ
        // for |θ| < π/2, so its peaks are at the extremes of θ.
        let top = |theta: f64| {
            let s = (theta != 0.0).then(|| theta.signum());
            kernel.top_kinematics(s, crate::trig::sin_cos(theta), 0.0, 0.0, 0.0).0
        };
        s.max_top_displacement = top(s.theta_range.0).abs().max(top(s.theta_range.1).abs());
        self.summary
    }
}
