//! Transitions at an instant: the conditions that hold at once (`settle`),
//! the switch of regime each makes, the impact law applied, and the events
//! they emit.

use super::watch::watched;
use super::{Run, Settled};
use crate::condition::{conditions, pivot_sign, Condition, MAX_CONDITIONS};
use crate::error::Error;
use crate::event::{Event, EventKind};
use crate::jet::Jet;
use crate::observer::Observer;
use crate::regime::{BuildingRegime, Pivot, Regime, SlipDirection, State, TowerRegime};
use crate::simulate::impact_ends_at_rest;
use std::ops::ControlFlow;

/// Regime switches at one instant beyond which the run reports chattering.
const MAX_SWITCHES_AT_ONE_INSTANT: u32 = 64;

impl<O: Observer, const N: usize> Run<'_, O, N> {
    /// Applies every condition that already holds at the current instant, or
    /// that is zero and growing (its time derivative positive).
    pub(super) fn settle(&mut self) -> Result<(), Error> {
        while !self.finished {
            if self.falls_back() {
                self.set_down()?;
                continue;
            }
            let list = conditions(self.kernel, self.regime);
            let conditions = if list.iter().all(|c| c.of_theta()) {
                // Conditions on θ alone (a rocking tower on a fixed base): the
                // value is θ's and the derivative θ̇'s, with no ground motion,
                // lean or acceleration to evaluate (one of these per impact).
                let (s, theta) = (pivot_sign(self.regime), Jet::new(self.integ.y.theta, self.integ.y.theta_dot));
                let mut conditions = [Jet::default(); MAX_CONDITIONS];
                for (slot, c) in conditions.iter_mut().zip(list) {
                    *slot = c.theta_margin(s, theta);
                }
                conditions
            } else {
                let acc = self.accelerations_now();
                self.cache.watch = watched(
                    self.kernel,
                    self.regime,
                    (&self.input.segment.piece, &self.input.vsegment.piece),
                    list,
                    self.integ.t,
                    &self.integ.y,
                    Some(acc),
                );
                self.cache.settled = Some(Settled {
                    t: self.integ.t,
                    y: self.integ.y,
                    regime: self.regime,
                    pieces: (self.input.segment.piece, self.input.vsegment.piece),
                    acc,
                });
                self.cache.watch.conditions
            };
            let fell_back = self.fell_back_now();
            let holds = |i: usize| match (list[i], conditions[i].v) {
                // At u̇ = 0 the relative acceleration does not decide (it is
                // zero when μk = μs): Coulomb's law does.
                (Condition::SlipStop, 0.0) => !self.slides_on(),
                // The motion has just shown that this uplift falls straight back.
                (c, _) if fell_back && c.lifts() => false,
                _ => holds_now(conditions[i]),
            };
            let Some(i) = (0..list.len()).find(|&i| holds(i)) else {
                self.record_due_instant();
                return Ok(());
            };
            self.switch(list[i])?;
        }
        self.record_due_instant();
        Ok(())
    }

    /// Records the response at the current instant if an event was emitted
    /// there ([`Self::emit`]): called where `settle` leaves the regime that
    /// holds.
    fn record_due_instant(&mut self) {
        if std::mem::take(&mut self.instant_due) {
            self.record_instant();
        }
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
    pub(super) fn slides_on(&self) -> bool {
        let BuildingRegime::Slip(dir) = self.regime.building else { return false };
        let starts = match dir {
            SlipDirection::Negative => Condition::SlipNegative,
            SlipDirection::Positive => Condition::SlipPositive,
        };
        let stuck = Regime {
            building: BuildingRegime::Stick,
            ..self.regime
        };
        let w = watched(
            self.kernel,
            stuck,
            (&self.input.segment.piece, &self.input.vsegment.piece),
            &[starts],
            self.integ.t,
            &self.integ.y,
            None,
        );
        holds_now(w.conditions[0])
    }

    /// Counts a regime switch at the current instant; beyond
    /// [`MAX_SWITCHES_AT_ONE_INSTANT`] the run reports chattering, `last` the
    /// name of the switch that went beyond.
    pub(super) fn count_switch(&mut self, last: &'static str) -> Result<(), Error> {
        if self.integ.t.to_bits() == self.switches.time.to_bits() {
            self.switches.count += 1;
            if self.switches.count > MAX_SWITCHES_AT_ONE_INSTANT {
                return Err(Error::Chattering { time: self.integ.t, last });
            }
        } else {
            self.switches.time = self.integ.t;
            self.switches.count = 1;
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
    pub(super) fn falls_back(&self) -> bool {
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return false };
        if self.integ.y.theta != 0.0 || self.integ.y.theta_dot != 0.0 {
            return false;
        }
        let lifts = match pivot {
            Pivot::Negative => Condition::UpliftNegative,
            Pivot::Positive => Condition::UpliftPositive,
        };
        !self.lifted_at_once(&[lifts])
    }

    /// Whether the tower, standing at the current instant, would be lifted
    /// at once by one of `lifts` (uplift conditions), as `settle` evaluates
    /// them.
    fn lifted_at_once(&self, lifts: &[Condition]) -> bool {
        let standing = Regime {
            tower: TowerRegime::Rest,
            ..self.regime
        };
        let w = watched(
            self.kernel,
            standing,
            (&self.input.segment.piece, &self.input.vsegment.piece),
            lifts,
            self.integ.t,
            &self.integ.y,
            None,
        );
        w.conditions[..lifts.len()].iter().any(|&c| holds_now(c))
    }

    /// Whether the tower fell straight back at the current instant.
    pub(super) fn fell_back_now(&self) -> bool {
        self.integ.t.to_bits() == self.switches.fell_back.to_bits()
    }

    /// Puts a tower that lifted and then never left `θ = 0` at rest: the
    /// impact condition, armed once the motion leaves zero, was found to
    /// grow from zero over the whole first step (`crossing::OnZero`), so the
    /// tower met `θ = 0` again with `θ̇ = 0`, having not moved. That is a
    /// grazing uplift the next derivatives say falls straight back (the
    /// ground acceleration touching `g tan α` at its peak, where the uplift
    /// condition and the rocking `θ̈` are both zero and computed with
    /// roundings of either sign): no impact, and no uplift again at this
    /// instant; the uplift is armed once its condition has been negative.
    pub(super) fn fall_straight_back(&mut self) -> Result<(), Error> {
        self.switches.fell_back = self.integ.t;
        self.set_down()
    }

    /// Puts a tower that [`Self::falls_back`] at rest: a rest event, no impact.
    pub(super) fn set_down(&mut self) -> Result<(), Error> {
        self.count_switch("rest")?;
        self.integ.restart = true;
        self.regime.tower = TowerRegime::Rest;
        let at = self.integ.y;
        self.emit(EventKind::Rest, at)
    }

    /// Performs the transition of `condition` at the current instant.
    pub(super) fn switch(&mut self, condition: Condition) -> Result<(), Error> {
        self.count_switch(condition.name())?;
        self.integ.restart = true;
        let before = self.integ.y;
        let a_g = self.a_g(self.integ.t);
        let kind = match condition {
            Condition::UpliftNegative | Condition::UpliftPositive => {
                let pivot = if condition == Condition::UpliftNegative {
                    Pivot::Negative
                } else {
                    Pivot::Positive
                };
                self.regime.tower = TowerRegime::Rocking(pivot);
                EventKind::Uplift
            }
            Condition::Impact => return self.impact(),
            Condition::Overturn => {
                self.finished = true;
                EventKind::Overturn
            }
            Condition::SlipNegative | Condition::SlipPositive => {
                let dir = if condition == Condition::SlipNegative {
                    SlipDirection::Negative
                } else {
                    SlipDirection::Positive
                };
                self.regime.building = BuildingRegime::Slip(dir);
                EventKind::Slip
            }
            Condition::SlipStop => {
                self.integ.y.slip_vel = 0.0;
                let (force, normal) = self
                    .kernel
                    .stick_demand(self.regime.tower, a_g, self.g_e(self.integ.t), self.integ.y.theta, self.integ.y.theta_dot);
                let old = self.regime.building;
                if self.kernel.friction.sticks(force, normal) {
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
    /// its own at the same instant. Below [`REST_ANGULAR_VELOCITY`](crate::REST_ANGULAR_VELOCITY) the tower
    /// stands, unless the pivot line accelerates enough to lift it at once.
    pub(super) fn impact(&mut self) -> Result<(), Error> {
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return Ok(()) };
        if self.integ.y.theta == 0.0 && self.integ.y.theta_dot == 0.0 {
            return self.fall_straight_back();
        }
        if impact_ends_at_rest(self.integ.y.theta_dot) && self.lifted_at_once(&[Condition::UpliftNegative, Condition::UpliftPositive]) {
            // Back slower than the rest threshold while the pivot line still
            // lifts it: the impact would seat it and the input lift it again
            // at this instant, returning by the rounding of the same
            // derivatives without end (a grazing uplift whose `θ̈` is at
            // rounding level, of either sign). It fell straight back.
            self.integ.y.theta_dot = 0.0;
            return self.fall_straight_back();
        }
        let before = self.integ.y;
        let after = self
            .kernel
            .impact_law(pivot.sign(), self.integ.y.theta_dot, self.integ.y.slip_vel, self.regime.building);
        self.integ.y.theta = 0.0;
        self.integ.y.theta_dot = after.theta_dot;
        self.integ.y.slip_vel = after.slip_vel;
        self.regime.tower = TowerRegime::Rocking(pivot.flipped());
        let old = self.regime.building;
        self.regime.building = after.building;
        self.emit(EventKind::Impact, before)?;
        if after.building != old {
            let kind = match (old, after.building) {
                (_, BuildingRegime::Stick) => EventKind::Stick,
                (BuildingRegime::Stick, BuildingRegime::Slip(_)) => EventKind::Slip,
                (BuildingRegime::Slip(_), BuildingRegime::Slip(_)) => EventKind::Reverse,
            };
            let at = self.integ.y;
            self.emit(kind, at)?;
        }
        if impact_ends_at_rest(self.integ.y.theta_dot) {
            let before = self.integ.y;
            self.integ.y.theta_dot = 0.0;
            self.regime.tower = TowerRegime::Rest;
            let g_e = self.g_e(self.integ.t);
            let acc_pivot = self.kernel.pivot_acceleration_at_rest(self.regime.building, self.a_g(self.integ.t), g_e);
            // If it would lift at once, `settle` switches to rocking: no rest in between.
            if acc_pivot.abs() <= self.kernel.uplift_threshold(g_e) {
                self.emit(EventKind::Rest, before)?;
            }
        }
        Ok(())
    }

    /// Emits an event at the current instant: to the summary, which derives
    /// its counts and first instants from events alone, and to the observer.
    /// Every event is followed by `settle`, which records the response
    /// there once no switch is due.
    pub(super) fn emit(&mut self, kind: EventKind, before: State) -> Result<(), Error> {
        let event = Event {
            time: self.integ.t,
            kind,
            before,
            after: self.integ.y,
            regime: self.regime,
            block: 0,
        };
        self.report.tracker.event(&event);
        if let ControlFlow::Break(halt) = self.report.observer.on_event(&event) {
            return Err(Error::halted(halt, self.integ.t));
        }
        // Recorded where `settle` leaves the regime that holds, which may
        // not be this event's.
        self.instant_due = true;
        Ok(())
    }
}

/// Whether a condition with its time derivative, at the current instant,
/// switches at once: it already holds, or it is zero and growing.
fn holds_now(j: Jet) -> bool {
    j.v > 0.0 || (j.v == 0.0 && j.d > 0.0)
}
