//! The end of an impact cascade jumped in closed form (`cascade.rs`): when a
//! free flight applies, and the flights one after another, with the
//! summary's instants of the long middle of the cascade left out.

use super::Run;
use crate::cascade::Flight;
use crate::condition::{conditions, Condition};
use crate::equations::Kernel;
use crate::error::Error;
use crate::ground::{Piece, Segment};
use crate::observer::{Interpolant, Observer};
use crate::regime::{BuildingRegime, Regime, State, TowerRegime};
use crate::response::Tracker;

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
pub(super) struct Deferred {
    items: [Option<Instant>; 8],
    next: usize,
}

impl Deferred {
    pub(super) fn push(&mut self, item: Instant) {
        self.items[self.next] = Some(item);
        self.next = (self.next + 1) % self.items.len();
    }

    /// The instants kept, emptied.
    pub(super) fn drain(&mut self) -> impl Iterator<Item = Instant> + '_ {
        self.next = 0;
        self.items.iter_mut().filter_map(Option::take)
    }
}

impl<O: Observer, const N: usize> Run<'_, O, N> {
    /// The free flight that starts now, if the cascade's closed form applies
    /// (`cascade.rs`, "When it does not apply"): the tower has just left
    /// `θ = 0`, no ground motion is left to come, the building is absent or
    /// stuck with a margin at both ends of the flight, the flight is small
    /// (`ψm <= 0.1 √rtol`) and ends within the run. Inlined: its first test,
    /// that the integrator restarts (a flight starts only at an event), ends
    /// it at every other step of the run.
    #[inline(always)]
    pub(super) fn free_flight(&self) -> Option<Flight> {
        if !self.integ.restart {
            return None;
        }
        let TowerRegime::Rocking(pivot) = self.regime.tower else { return None };
        let s = pivot.sign();
        let omega = s * self.integ.y.theta_dot;
        let input_over = |segment: &Segment| segment.kink == f64::INFINITY && matches!(segment.piece, Piece::Constant(a) if a == 0.0);
        if self.integ.y.theta != 0.0 || omega <= 0.0 || !input_over(&self.input.segment) || !input_over(&self.input.vsegment) {
            return None;
        }
        let flight = self
            .kernel
            .free_flight(s, self.integ.t, omega, self.integ.y.slip, 0.1 * self.integ.rtol.sqrt())?;
        if self.integ.t + flight.duration >= self.input.end {
            return None;
        }
        if self.kernel.has_building {
            if self.regime.building != BuildingRegime::Stick {
                return None;
            }
            // The stick demand at the impact (the same on arrival, `θ̇²` being
            // equal) and at the apex, with a margin of 1e-6 μs M g (the
            // static friction law's hold on the weight, `−margin(0, M g)`):
            // the demand inside departs from these by a relative `ψm² / 8`.
            let hold = -self.kernel.friction.static_friction_margin(0.0, self.kernel.total * self.kernel.g);
            let margin = 1e-6 * hold;
            let list = conditions(self.kernel, self.regime);
            let apex = State {
                theta: s * flight.apex,
                theta_dot: 0.0,
                slip: self.integ.y.slip,
                slip_vel: 0.0,
            };
            let ends = [self.integ.y, apex];
            let holds = ends.iter().all(|y| {
                list.iter()
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
    pub(super) fn advance_free_flight(&mut self, first: Flight) -> Result<(), Error> {
        let mut flight = first;
        let mut jumped = 0u32;
        let result = loop {
            // From the third flight on, instants wait in `deferred`; the
            // last few are fed to the tracker when the cascade ends.
            self.report.deferring = jumped >= 2;
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
            self.integ.t = t1;
            self.integ.y = State {
                theta: 0.0,
                theta_dot: -flight.s * flight.omega,
                slip: flight.slip,
                slip_vel: 0.0,
            };
            self.integ.restart = true;
            self.note_instant(self.a_g(self.integ.t), self.g_e(self.integ.t), self.integ.y);
            if let Err(e) = self.switch(Condition::Impact).and_then(|()| self.next_instant()) {
                break Err(e);
            }
            jumped += 1;
            match self.free_flight() {
                Some(next) if !self.finished => flight = next,
                _ => break Ok(()),
            }
        };
        self.report.deferring = false;
        for instant in self.report.deferred.drain() {
            track(&mut self.report.tracker, self.kernel, instant);
        }
        result
    }

    /// Feeds the tracker the response at `y` in the current regime, or keeps
    /// it among the last instants of a cascade (see [`Self::advance_free_flight`]).
    pub(super) fn note_instant(&mut self, a_g: f64, g_e: f64, y: State) {
        let instant = (self.regime, a_g, g_e, y);
        if self.report.deferring {
            self.report.deferred.push(instant);
        } else {
            track(&mut self.report.tracker, self.kernel, instant);
        }
    }
}
