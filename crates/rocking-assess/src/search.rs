//! The least ground acceleration at which a check stops holding.
//!
//! The demand of a check moves with `ag` through every site parameter that
//! depends on it (NTC's `SS` and `TD`), so it need not grow with `ag`: on
//! subsoil D, `ag SS(ag)` rises, falls and rises again. The search scans `ag`
//! from zero upwards on a fine grid and bisects the first step on which the
//! check fails; it never assumes one root.

use crate::error::Error;

/// The scan's step in `ag` (g). A stretch of `ag` over which a check fails
/// that is narrower than this step, between two values at which it holds,
/// could be missed; the demands' pieces are polynomials of degree at most 3 in
/// `ag` between the kinks of `SS`, whose turning points are tenths of a g apart.
pub const AG_SCAN_STEP: f64 = 1e-4;

/// The top of the search (g): the largest `ag` a code spectrum accepts.
pub const AG_SEARCH_TOP: f64 = 2.0;

/// The bisection stops when the bracket is this narrow (g).
const AG_TOLERANCE: f64 = 1e-12;

/// The least `ag` at which a check stops holding.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AgCapacity {
    /// The check fails at this `ag` (g) and holds at every smaller one.
    At(f64),
    /// The check holds at every `ag` up to this one (g), the top of the search:
    /// the capacity is at least it.
    AtLeast(f64),
}

impl AgCapacity {
    /// The value (g): the capacity, or its lower bound.
    pub fn value(self) -> f64 {
        match self {
            AgCapacity::At(ag) | AgCapacity::AtLeast(ag) => ag,
        }
    }
    /// Whether the value is only a lower bound.
    pub fn is_lower_bound(self) -> bool {
        matches!(self, AgCapacity::AtLeast(_))
    }
}

/// The least `ag` (g) in `(0, top]` at which `excess(ag) ≥ 0` (the demand minus
/// the capacity: the check fails there): `ag` scanned by [`AG_SCAN_STEP`] from
/// zero, the first step on which it fails bisected to 1e-12 g. The check is
/// taken to hold as `ag` tends to zero (no demand).
pub fn least_failing_ag(top: f64, excess: impl Fn(f64) -> Result<f64, Error>) -> Result<AgCapacity, Error> {
    let steps = (top / AG_SCAN_STEP).ceil() as usize;
    let mut holds_at = 0.0;
    for k in 1..=steps {
        let ag = (k as f64 * AG_SCAN_STEP).min(top);
        if excess(ag)? >= 0.0 {
            let (mut lo, mut hi) = (holds_at, ag);
            while hi - lo > AG_TOLERANCE {
                let mid = 0.5 * (lo + hi);
                if excess(mid)? >= 0.0 {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return Ok(AgCapacity::At(hi));
        }
        holds_at = ag;
    }
    Ok(AgCapacity::AtLeast(top))
}
