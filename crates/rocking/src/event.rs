//! Regime changes, each located in time by root finding (docs/src/model.md, "Regimes and transitions").

use crate::regime::{Regime, State};

/// The kind of a regime change, as written in `events.csv`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum EventKind {
    /// The tower lifts off a base corner and starts rocking.
    Uplift,
    /// The tower's rotation returns to zero: `θ̇⁺ = r θ̇⁻` and the pivot flips.
    Impact,
    /// After an impact too small to lift the tower again, it stands.
    Rest,
    /// The building starts sliding.
    Slip,
    /// The sliding building sticks to its foundation.
    Stick,
    /// The sliding building reverses its direction without sticking.
    Reverse,
    /// `|θ|` reaches `π/2`; the run ends.
    Overturn,
}

impl EventKind {
    /// The name used in `events.csv`.
    pub fn as_str(self) -> &'static str {
        match self {
            EventKind::Uplift => "uplift",
            EventKind::Impact => "impact",
            EventKind::Rest => "rest",
            EventKind::Slip => "slip",
            EventKind::Stick => "stick",
            EventKind::Reverse => "reverse",
            EventKind::Overturn => "overturn",
        }
    }
}

/// A regime change at an instant, with the states before and after it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Event {
    /// Time (s).
    pub time: f64,
    /// What happened.
    pub kind: EventKind,
    /// State just before.
    pub before: State,
    /// State just after (differs from `before` in `θ̇` at an impact).
    pub after: State,
    /// Regime after the event (of the tower and the building in a stacked run).
    pub regime: Regime,
    /// Whose event: 0 the tower's or the building's, `k` the `k`-th block
    /// above the tower (stacked runs); `before` and `after` then hold that
    /// block's `θ` and `θ̇` relative to the block below.
    pub block: usize,
}
