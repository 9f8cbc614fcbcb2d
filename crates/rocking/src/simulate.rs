//! The event-driven run: integrate the smooth motion of one regime, locate the
//! instant a transition condition is met by root finding on the dense output,
//! switch, and go on (model.md, "Regimes").
//!
//! Conditions are written as functions that are negative while the regime
//! holds and cross zero upwards when it must change. Two of them (impact,
//! `θ = 0`, and the end of a slip, `u̇ = 0`) start a regime exactly on zero and
//! move away from it: those are armed only once the motion has actually left
//! zero, which a search towards the start of the step finds. A condition that
//! already holds (is positive) when a regime is entered switches at once.

use crate::error::{positive, Error, Parameter};
use crate::event::{Event, EventKind};
use crate::ground::{GroundMotion, Segment};
use crate::integrator::{find_crossing, find_crossing_newton, DenseOutput, Dop853, StepFailure};
use crate::model::{Kernel, Model};
use crate::observer::{Interpolant, Observer, Step};
use crate::regime::{BuildingRegime, Pivot, Regime, SlipDirection, State, TowerRegime};
use crate::response::{EndReason, Summary, Tracker};
use std::f64::consts::FRAC_PI_2;

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
        run::<_, 4>(kernel, ground, settings, tower, initial, observer)
    } else {
        run::<_, 2>(kernel, ground, settings, tower, initial, observer)
    }
}

fn run<O: Observer, const N: usize>(
    kernel: Kernel,
    ground: &GroundMotion,
    settings: &Settings,
    tower: TowerRegime,
    initial: Initial,
    observer: &mut O,
) -> Result<Summary, Error> {
    let run = Run::<O, N> {
        kernel,
        ground,
        end: settings.duration,
        regime: Regime {
            tower,
            building: BuildingRegime::Stick,
        },
        t: 0.0,
        y: [initial.theta, initial.theta_dot, 0.0, 0.0],
        segment: ground.segment(0.0),
        stepper: Dop853::new(settings.rtol, settings.atol),
        restart: true,
        values: [0.0; MAX_CONDITIONS],
        tracker: Tracker::new(),
        observer,
        switches: 0,
        switch_time: f64::NAN,
        finished: false,
    };
    run.execute()
}

/// A condition for leaving the current regime.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Condition {
    /// The pivot line accelerates beyond `g tan α` towards `+x`: rock on the `−x` corner.
    UpliftNegative,
    /// … towards `−x`: rock on the `+x` corner.
    UpliftPositive,
    /// `θ` returns to zero.
    Impact,
    /// `|θ|` reaches `π/2`.
    Overturn,
    /// The stick demand exceeds `μs N` towards `+x`: slip towards `−x`.
    SlipNegative,
    /// … towards `−x`: slip towards `+x`.
    SlipPositive,
    /// The slip velocity returns to zero.
    SlipStop,
}

const MAX_CONDITIONS: usize = 4;

/// The conditions that can end `regime`, at most four.
fn conditions(kernel: &Kernel, regime: Regime) -> ([Condition; MAX_CONDITIONS], usize) {
    let mut list = [Condition::Impact; MAX_CONDITIONS];
    let mut n = 0;
    let mut push = |c| {
        list[n] = c;
        n += 1;
    };
    if kernel.has_tower {
        match regime.tower {
            TowerRegime::Rest => {
                push(Condition::UpliftNegative);
                push(Condition::UpliftPositive);
            }
            TowerRegime::Rocking(_) => {
                push(Condition::Overturn);
                push(Condition::Impact);
            }
        }
    }
    if kernel.has_building {
        match regime.building {
            BuildingRegime::Stick => {
                push(Condition::SlipNegative);
                push(Condition::SlipPositive);
            }
            BuildingRegime::Slip(_) => push(Condition::SlipStop),
        }
    }
    (list, n)
}

/// The value of `condition` in `regime`: negative while the regime holds.
#[inline]
fn condition_value(kernel: &Kernel, condition: Condition, regime: Regime, a_g: f64, y: &[f64; 4]) -> f64 {
    let s = pivot_sign(regime);
    match condition {
        Condition::UpliftNegative => kernel.pivot_acceleration_at_rest(regime.building, a_g) - kernel.g * kernel.tan_alpha,
        Condition::UpliftPositive => -kernel.pivot_acceleration_at_rest(regime.building, a_g) - kernel.g * kernel.tan_alpha,
        Condition::Impact => -s * y[0],
        Condition::Overturn => s * y[0] - FRAC_PI_2,
        Condition::SlipNegative | Condition::SlipPositive => {
            let (force, normal) = kernel.stick_demand(regime.tower, a_g, y);
            let force = if condition == Condition::SlipNegative { force } else { -force };
            force - kernel.mu_s * normal
        }
        Condition::SlipStop => match regime.building {
            BuildingRegime::Slip(dir) => -dir.sign() * y[3],
            BuildingRegime::Stick => -1.0,
        },
    }
}

/// The state of a run; the integrator carries the first `N` components of
/// `(θ, θ̇, u, u̇)` (2 on a fixed base, 4 on a building).
struct Run<'a, O: Observer, const N: usize> {
    kernel: Kernel,
    ground: &'a GroundMotion,
    end: f64,
    regime: Regime,
    t: f64,
    y: [f64; 4],
    /// The ground's segment that holds `t` (right-continuous).
    segment: Segment,
    stepper: Dop853<N>,
    /// Whether the stepper must restart at `(t, y)` (after an event or a kink).
    restart: bool,
    /// Condition values at `(t, y)`, in the order of `conditions`.
    values: [f64; MAX_CONDITIONS],
    tracker: Tracker,
    observer: &'a mut O,
    /// Switches at `switch_time`, to stop chattering.
    switches: u32,
    switch_time: f64,
    finished: bool,
}

/// `(θ, θ̇, u, u̇)` from the integrated components (the others are zero).
#[inline(always)]
fn wide<const N: usize>(y: &[f64; N]) -> [f64; 4] {
    std::array::from_fn(|i| if i < N { y[i] } else { 0.0 })
}

/// The integrated components of `(θ, θ̇, u, u̇)`.
#[inline(always)]
fn narrow<const N: usize>(y: [f64; 4]) -> [f64; N] {
    std::array::from_fn(|i| y[i])
}

impl<O: Observer, const N: usize> Run<'_, O, N> {
    fn execute(mut self) -> Result<Summary, Error> {
        self.settle()?;
        self.record_instant();
        while !self.finished && self.t < self.end {
            if self.is_static() {
                self.advance_static()?;
            } else {
                self.advance_dynamic()?;
            }
        }
        self.tracker.summary.evaluations = self.stepper.evaluations;
        Ok(self.tracker.finish(&self.kernel, self.t, &self.y))
    }

    /// Nothing moves relative to the ground: the state is constant and every
    /// condition depends on `a_g` alone.
    fn is_static(&self) -> bool {
        self.regime.tower == TowerRegime::Rest && self.regime.building == BuildingRegime::Stick
    }

    fn a_g(&self, t: f64) -> f64 {
        self.segment.piece.eval(t)
    }

    /// Moves to the next segment end, or to the first instant on the way where a
    /// condition is met (root finding on `a_g`, monotone on the segment).
    fn advance_static(&mut self) -> Result<(), Error> {
        // The next extremum of a_g may lie beyond the current segment's end if the
        // run was rocking or sliding until now: take the segment from here.
        self.segment = self.ground.segment(self.t);
        let t1 = self.segment.end.min(self.end);
        let (list, n) = conditions(&self.kernel, self.regime);
        let (regime, y, piece) = (self.regime, self.y, self.segment.piece);
        let value = |c: Condition, t: f64| condition_value(&self.kernel, c, regime, piece.eval(t), &y);
        let mut first: Option<(f64, Condition)> = None;
        for &c in &list[..n] {
            let (v0, v1) = (value(c, self.t), value(c, t1));
            if v0 < 0.0 && v1 >= 0.0 {
                let tb = find_crossing(|t| value(c, t), self.t, v0, t1, v1, 0.0).tb;
                if first.is_none_or(|(tf, _)| tb < tf) {
                    first = Some((tb, c));
                }
            }
        }
        let t_stop = first.map_or(t1, |(tb, _)| tb);
        self.emit_step(Interpolant::Constant(self.y), t_stop);
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
        self.settle()
    }

    /// One accepted step of the integrator, cut short at the first transition in it.
    fn advance_dynamic(&mut self) -> Result<(), Error> {
        let (kernel, regime, piece) = (self.kernel, self.regime, self.segment.piece);
        let mut rhs = |t: f64, y: &[f64; N]| {
            let y = wide(y);
            let acc = kernel.accelerations(regime, piece.eval(t), &y);
            narrow([y[1], acc.theta, y[3], acc.slip])
        };
        let (list, n) = conditions(&kernel, regime);
        if self.restart {
            self.stepper.restart(&mut rhs, self.t, narrow(self.y), self.end);
            for (i, &c) in list[..n].iter().enumerate() {
                self.values[i] = condition_value(&kernel, c, regime, piece.eval(self.t), &self.y);
            }
            self.restart = false;
        }
        // Steps land on kinks and jumps of the input; its extrema matter only
        // while nothing moves (`advance_static`).
        let bound = self.segment.kink.min(self.end);
        self.stepper.step(&mut rhs, bound).map_err(|e| match e {
            StepFailure::StepSizeTooSmall { time } => Error::StepSizeTooSmall { time },
            // Only the dynamic normal force can make the coupled system
            // singular; otherwise a non-finite value is an overflow.
            StepFailure::NonFinite { time } if kernel.dynamic => Error::Singular {
                time,
                reason: "the equations of motion have no solution (with the dynamic normal force, a building this light cannot carry this friction: Painlevé's paradox)".into(),
            },
            StepFailure::NonFinite { time } => Error::Singular {
                time,
                reason: "the motion became non-finite (an overflow: the inputs' scales are out of proportion)".into(),
            },
        })?;
        let (t0, t1, y1) = (self.stepper.t_old, self.stepper.t, wide(&self.stepper.y));
        let a1 = piece.eval(t1);
        let mut dense: Option<DenseOutput<N>> = None;
        let mut first: Option<(f64, Condition)> = None;
        let mut new_values = [0.0; MAX_CONDITIONS];
        for (i, &c) in list[..n].iter().enumerate() {
            let v1 = condition_value(&kernel, c, regime, a1, &y1);
            new_values[i] = v1;
            let v0 = self.values[i];
            if v1 < 0.0 || (v0 >= 0.0 && v1 <= 0.0) {
                continue;
            }
            let d = *dense.get_or_insert_with(|| self.stepper.dense(&mut rhs));
            let ground = c.uses_ground();
            let value = |t: f64| condition_value(&kernel, c, regime, if ground { piece.eval(t) } else { 0.0 }, &wide(&d.state(t)));
            // Started on zero (an impact or a slip start): find where the motion left it.
            let start = if v0 < 0.0 { Some((t0, v0)) } else { leaving_point(&value, t0, t1) };
            let tb = match start {
                // θ = 0: the dense output gives the derivative θ̇ with θ, for Newton.
                Some((ta, va)) if c == Condition::Impact => {
                    let s = pivot_sign(regime);
                    let with_slope = |t: f64| {
                        let y = d.state(t);
                        (-s * y[0], -s * y[1])
                    };
                    find_crossing_newton(with_slope, ta, va, t1, v1).tb
                }
                Some((ta, va)) => find_crossing(value, ta, va, t1, v1, 0.0).tb,
                None => t0,
            };
            if first.is_none_or(|(tf, _)| tb < tf) {
                first = Some((tb, c));
            }
        }
        let t_stop = first.map_or(t1, |(tb, _)| tb);
        // Extremes of θ inside the step, where θ̇ changes sign.
        if matches!(regime.tower, TowerRegime::Rocking(_)) && self.stepper.y_old[1] * y1[1] < 0.0 {
            let d = *dense.get_or_insert_with(|| self.stepper.dense(&mut rhs));
            let w0 = self.stepper.y_old[1];
            // θ̇ and its derivative come from the same polynomial: Newton.
            let rate = |t: f64| {
                let (y, dy) = d.state_and_rate(t);
                (-w0.signum() * y[1], -w0.signum() * dy[1])
            };
            let peak = find_crossing_newton(rate, t0, -w0.abs(), t1, -w0.signum() * y1[1]).tb;
            if peak <= t_stop {
                let yp = wide(&d.state(peak));
                self.tracker.displacement(yp[0], yp[2]);
            }
        }
        let interpolant = if first.is_some() || self.observer.wants_steps() {
            Interpolant::Dense(dense.get_or_insert_with(|| self.stepper.dense(&mut rhs)).widen())
        } else {
            Interpolant::Constant(y1)
        };
        self.emit_step(interpolant, t_stop);
        if let (Some((tb, c)), Interpolant::Dense(d)) = (first, interpolant) {
            self.t = tb;
            self.y = if tb >= t1 { y1 } else { d.state(tb) };
            self.restart = true;
            self.record_instant();
            self.switch(c)?;
            return self.next_instant();
        }
        self.t = t1;
        self.y = y1;
        self.values = new_values;
        let f = wide(&self.stepper.f);
        let acc = crate::model::Accelerations { theta: f[1], slip: f[3] };
        self.tracker.instant(&kernel, regime, a1, &y1, acc);
        // Within a segment the conditions were just checked on the step; only a
        // new segment (a kink or jump of the input) can make one hold at once.
        if self.t >= self.segment.kink {
            self.next_instant()?;
        }
        Ok(())
    }

    /// Tells the observer about the stretch from the current time to `t1`, and
    /// accumulates the time spent in the regime.
    fn emit_step(&mut self, interpolant: Interpolant, t1: f64) {
        self.tracker.time(self.regime.motion(), t1 - self.t);
        if self.observer.wants_steps() {
            let step = Step {
                kernel: &self.kernel,
                piece: self.segment.piece,
                interpolant,
                t0: self.t,
                t1,
                regime: self.regime,
            };
            self.observer.on_step(&step);
        }
    }

    /// Feeds the tracker the response at the current instant.
    fn record_instant(&mut self) {
        let a_g = self.a_g(self.t);
        let acc = self.kernel.accelerations(self.regime, a_g, &self.y);
        self.tracker.instant(&self.kernel, self.regime, a_g, &self.y, acc);
    }

    /// Applies every condition that already holds at the current instant.
    fn settle(&mut self) -> Result<(), Error> {
        while !self.finished {
            let a_g = self.a_g(self.t);
            let (list, n) = conditions(&self.kernel, self.regime);
            let Some(&c) = list[..n].iter().find(|&&c| condition_value(&self.kernel, c, self.regime, a_g, &self.y) > 0.0) else {
                return Ok(());
            };
            self.switch(c)?;
        }
        Ok(())
    }

    /// Performs the transition of `condition` at the current instant.
    fn switch(&mut self, condition: Condition) -> Result<(), Error> {
        if self.t.to_bits() == self.switch_time.to_bits() {
            self.switches += 1;
            if self.switches > MAX_SWITCHES_AT_ONE_INSTANT {
                return Err(Error::Chattering {
                    time: self.t,
                    last: condition.name(),
                });
            }
        } else {
            self.switch_time = self.t;
            self.switches = 1;
        }
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
                self.y[3] = 0.0;
                let (force, normal) = self.kernel.stick_demand(self.regime.tower, a_g, &self.y);
                let old = self.regime.building;
                if force.abs() <= self.kernel.mu_s * normal {
                    self.regime.building = BuildingRegime::Stick;
                    EventKind::Stick
                } else {
                    let dir = Kernel::slip_direction(force);
                    self.regime.building = BuildingRegime::Slip(dir);
                    if old == BuildingRegime::Slip(dir) {
                        return Ok(());
                    }
                    EventKind::Reverse
                }
            }
        };
        self.emit(kind, before);
        Ok(())
    }

    /// `θ̇⁺ = r θ̇⁻`, the pivot flips; below [`REST_ANGULAR_VELOCITY`] the tower
    /// stands, unless the pivot line accelerates enough to lift it at once.
    fn impact(&mut self) -> Result<(), Error> {
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return Ok(()) };
        let before = self.y;
        self.y[0] = 0.0;
        self.y[1] *= self.kernel.restitution;
        self.tracker.summary.impacts += 1;
        self.regime.tower = TowerRegime::Rocking(pivot.flipped());
        self.emit(EventKind::Impact, before);
        if self.y[1].abs() < REST_ANGULAR_VELOCITY {
            let before = self.y;
            self.y[1] = 0.0;
            self.regime.tower = TowerRegime::Rest;
            let acc = self.kernel.pivot_acceleration_at_rest(self.regime.building, self.a_g(self.t));
            // If it would lift at once, `settle` switches to rocking: no rest in between.
            if self.kernel.uplift_margin(acc) <= 0.0 {
                self.emit(EventKind::Rest, before);
            }
        }
        Ok(())
    }

    fn emit(&mut self, kind: EventKind, before: [f64; 4]) {
        self.tracker.summary.events += 1;
        let event = Event {
            time: self.t,
            kind,
            before: State::from_array(before),
            after: State::from_array(self.y),
            regime: self.regime,
        };
        self.observer.on_event(&event);
        self.record_instant();
    }
}

impl Condition {
    /// Whether the condition depends on the ground acceleration (else it is
    /// evaluated without computing `a_g`, which saves a sine in root finding).
    fn uses_ground(self) -> bool {
        !matches!(self, Condition::Impact | Condition::Overturn | Condition::SlipStop)
    }

    fn name(self) -> &'static str {
        match self {
            Condition::UpliftNegative | Condition::UpliftPositive => "uplift",
            Condition::Impact => "impact",
            Condition::Overturn => "overturn",
            Condition::SlipNegative | Condition::SlipPositive => "slip",
            Condition::SlipStop => "slip stop",
        }
    }
}

/// `s = ±1` of a rocking tower (0 at rest).
fn pivot_sign(regime: Regime) -> f64 {
    match regime.tower {
        TowerRegime::Rocking(p) => p.sign(),
        TowerRegime::Rest => 0.0,
    }
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
