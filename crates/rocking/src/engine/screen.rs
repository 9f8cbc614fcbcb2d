//! The proofs that a step hides nothing: from the step's two ends (the
//! state, its exact rate and the watched quantities, [`Ends`]) and bounds
//! of the equations over the step (`equations.rs`), which of the searches
//! inside the step are needed ([`Screen`]). A search that is not needed is
//! not made, and the dense output is built only if one is.
//!
//! The velocities `θ̇` and `u̇` are proved free of roots by [`free_of_roots`]
//! with the bounds of `θ̈`, `θ⃛` from (T) ([`Kernel::tower_acceleration_bound`],
//! [`Kernel::tower_jerk_bound`]) and of `ü`, `u⃛` of a resting slide
//! ([`Kernel::resting_slide_bounds`]); the peaks the summary keeps are
//! looked for only where the cubic Hermite interpolant of the ends comes
//! near the running maximum ([`PEAK_MARGIN`]) and an extremum could matter.

use super::watch::Watched;
use crate::condition::{pivot_sign, Condition};
use crate::equations::Kernel;
use crate::extrema::{above, hermite_range_reaches, matters_on_step, may_have_extremum, near_peak, taylor_enclosure, PEAK_MARGIN};
use crate::ground::Piece;
use crate::jet::Jet;
use crate::regime::{BuildingRegime, Regime, State, TowerRegime};
use crate::response::Kept;

/// One accepted step, seen from its ends: what the screens, the search for
/// the first transition and the peaks read.
pub(super) struct Ends<'a> {
    pub(super) kernel: &'a Kernel,
    pub(super) regime: Regime,
    /// The inputs' pieces over the step (horizontal, vertical).
    pub(super) pieces: (&'a Piece, &'a Piece),
    /// The regime's conditions.
    pub(super) list: &'a [Condition],
    pub(super) t0: f64,
    pub(super) t1: f64,
    pub(super) h: f64,
    /// The state at both ends.
    pub(super) y0: State,
    pub(super) y1: State,
    /// Its rate `(θ̇, θ̈, u̇, ü)` at both ends: the velocities' exact slopes.
    pub(super) f0: State,
    pub(super) f1: State,
    /// The watched quantities at both ends.
    pub(super) w0: &'a Watched,
    pub(super) w1: &'a Watched,
}

impl Ends<'_> {
    /// The pivot sign `s` (0 for a standing tower).
    pub(super) fn s(&self) -> f64 {
        pivot_sign(self.regime)
    }

    pub(super) fn rocking(&self) -> bool {
        matches!(self.regime.tower, TowerRegime::Rocking(_))
    }

    /// The pivot's friction demand `f_x / f_y` at an instant.
    pub(super) fn ratio(w: &Watched) -> Jet {
        w.fx / w.fy
    }
}

/// What the inside of a step needs: each flag is a search the ends could not
/// rule out. The peaks kept before the step ride along: the peaks' searches
/// ask whether an extremum could raise them.
pub(super) struct Screen {
    /// `θ̇` may vanish inside where a turning point can matter.
    pub(super) theta_roots: bool,
    /// `u̇` may vanish inside (a sliding building).
    pub(super) slip_roots: bool,
    /// The building is stuck under a rocking tower: its friction demand is
    /// searched for extrema.
    pub(super) stick_examined: bool,
    /// A condition is met at the step's end.
    pub(super) crossing_at_end: bool,
    /// A peak of the top acceleration may raise the maximum.
    pub(super) top: bool,
    /// A peak of the pivot's friction demand may raise the maximum.
    pub(super) ratio: bool,
    /// `f_y` may reach zero.
    pub(super) fy: bool,
    /// An extremum of a stuck building's friction demand may hold.
    pub(super) stick: bool,
    /// An observer wants the step's motion.
    pub(super) observed: bool,
    /// `f_y` falls below `g / 2` at an end: every extremum of the demand matters.
    low_fy: bool,
    /// The peaks kept before the step.
    kept: Kept,
}

impl Screen {
    /// Whether the step's dense output is needed.
    pub(super) fn needs_dense(&self) -> bool {
        self.theta_roots || self.slip_roots || self.crossing_at_end || self.top || self.ratio || self.fy || self.stick || self.observed
    }

    /// Whether a value range of the top acceleration can raise its maximum.
    pub(super) fn top_matters(&self) -> impl Fn((f64, f64)) -> bool {
        above(self.kept.max_top_abs_acceleration)
    }

    /// Whether a value range of the demand matters: it can raise its maximum,
    /// or `f_y` is low (near `f_y = 0` the ratio has a pole close by and need
    /// not be concave between samples).
    pub(super) fn demand_matters(&self) -> impl Fn((f64, f64)) -> bool {
        let (low_fy, above) = (self.low_fy, above(self.kept.max_pivot_friction_demand));
        move |range| low_fy || above(range)
    }

    /// Whether a value range of `f_y` reaches zero.
    pub(super) fn fy_matters(&self) -> impl Fn((f64, f64)) -> bool {
        |(lo, _): (f64, f64)| lo <= 0.0
    }
}

/// Screens a step from its ends: which searches inside it are needed.
/// `kept`: the peaks so far; `observed`: an observer wants the step.
#[inline(always)]
pub(super) fn screen(e: &Ends, kept: Kept, observed: bool) -> Screen {
    let theta_roots = e.rocking()
        && match e.regime.building {
            BuildingRegime::Stick => theta_turns(e, kept.theta_range),
            BuildingRegime::Slip(_) => true,
        };
    let slip_roots = slip_turns(e);
    let stick_examined = e.rocking() && e.regime.building == BuildingRegime::Stick && e.kernel.has_building;
    let crossing_at_end = e.w1.conditions[..e.list.len()].iter().any(|c| c.v >= 0.0);
    let (w0, w1, h, g) = (e.w0, e.w1, e.h, e.kernel.g);
    let low_fy = w0.fy.v.min(w1.fy.v) < 0.5 * g;
    let mut screen = Screen {
        theta_roots,
        slip_roots,
        stick_examined,
        crossing_at_end,
        top: false,
        ratio: false,
        fy: false,
        stick: false,
        observed,
        low_fy,
        kept,
    };
    // Asked here as well as inside `interior_extrema` (which keeps its own
    // contract for every caller): a step ruled out by its ends needs no dense
    // output (1.5 M of the sweep's 178 M instructions).
    let near = |q0: Jet, q1: Jet, peak: f64| near_peak(q0, q1, h, peak);
    screen.top = e.rocking() && near(w0.top, w1.top, kept.max_top_abs_acceleration) && matters_on_step(e.t0, w0.top, e.t1, w1.top, screen.top_matters());
    // Once f_y has reached zero the demand is unbounded and the uplift
    // known: neither can change any more.
    let reaction_open = e.rocking() && !kept.tower_uplift_detected;
    let (r0, r1) = (Ends::ratio(w0), Ends::ratio(w1));
    // The demand |f_x| / f_y grows without bound as f_y falls towards zero (a
    // tower about to fly or overturn): no pruning where f_y is below g / 2.
    screen.ratio = reaction_open
        && w0.fy.v > 0.0
        && w1.fy.v > 0.0
        && (if low_fy {
            may_have_extremum(r0, r1, h)
        } else {
            near(r0, r1, kept.max_pivot_friction_demand)
        })
        && matters_on_step(e.t0, r0, e.t1, r1, screen.demand_matters());
    screen.fy = reaction_open
        && hermite_range_reaches(w0.fy, w1.fy, h, |(lo, _)| lo <= PEAK_MARGIN * g)
        && matters_on_step(e.t0, w0.fy, e.t1, w1.fy, screen.fy_matters());
    screen.stick = stick_examined && (0..e.list.len()).any(|i| !e.list[i].of_theta() && may_have_extremum(w0.conditions[i], w1.conditions[i], h));
    screen
}

/// Upper bounds over the step of `|a_g|`, `|ȧ_g|`, `g_e` and `|ġ_e|`.
#[inline(always)]
fn input_bounds(e: &Ends) -> (f64, f64, f64, f64) {
    let (piece, vpiece) = e.pieces;
    (
        piece.max_abs(e.t0, e.t1),
        piece.max_abs_rate(),
        e.kernel.g + vpiece.max_abs(e.t0, e.t1),
        vpiece.max_abs_rate(),
    )
}

/// Whether `θ̇` of a tower rocking on a stuck building may vanish inside the
/// step where the turning point can matter.
///
/// With the bounds of `|θ̈|` and `|θ⃛|` from (T), where
/// `max|θ̇| <= (|θ̇0| + |θ̇1| + max|θ̈| h) / 2`, [`free_of_roots`] may prove
/// that it keeps its sign. Otherwise a root of `θ̇` is located for θ's value
/// there: a peak of θ, or a point of the conditions of θ between the ends.
/// With the same bound on `|θ⃛|`, θ over the whole step lies in
/// `taylor_enclosure`; if that range is inside the peaks kept so far and
/// keeps every condition of θ negative (each is monotone in θ, so its ends
/// tell), the root changes nothing and is not located (half the steps that
/// hold one in the 100-case sweep, each a dense output, a Bernstein
/// isolation and a Newton solve). The two ends are the step's solution,
/// which the dense output also interpolates: the enclosure is that of the
/// computed motion, to the step's local error.
#[inline(always)]
fn theta_turns(e: &Ends, theta_range: (f64, f64)) -> bool {
    let (a_max, a_rate, g_e, g_rate) = input_bounds(e);
    let (y0, y1, f0, f1, h) = (e.y0, e.y1, e.f0, e.f1, e.h);
    let (rate_bound, reach) = e.kernel.tower_acceleration_bound(g_e, a_max);
    let w_max = 0.5 * (y0.theta_dot.abs() + y1.theta_dot.abs() + rate_bound * h);
    let third_bound = e.kernel.tower_jerk_bound(reach, g_rate, a_rate, w_max);
    !free_of_roots(
        Jet::new(y0.theta_dot, f0.theta_dot),
        Jet::new(y1.theta_dot, f1.theta_dot),
        h,
        rate_bound,
        third_bound,
    ) && !theta_proved_inside(
        taylor_enclosure([y0.theta, y0.theta_dot, f0.theta_dot], [y1.theta, y1.theta_dot, f1.theta_dot], h, third_bound),
        theta_range,
        e.list,
        e.s(),
    )
}

/// Whether `u̇` of a sliding building may vanish inside the step. Under a
/// standing tower the complex slides as one body, and the bounds of `|ü|`
/// and `|u⃛|` of the resting slide may prove it keeps its sign; under a
/// rocking tower it is always searched.
#[inline(always)]
fn slip_turns(e: &Ends) -> bool {
    match (e.regime.tower, e.regime.building) {
        (_, BuildingRegime::Stick) => false,
        (TowerRegime::Rocking(_), BuildingRegime::Slip(_)) => true,
        (TowerRegime::Rest, BuildingRegime::Slip(_)) => {
            let (a_max, a_rate, g_e, g_rate) = input_bounds(e);
            let (rate_bound, curvature_bound) = e.kernel.resting_slide_bounds(g_e, g_rate, a_max, a_rate);
            !free_of_roots(
                Jet::new(e.y0.slip_vel, e.f0.slip_vel),
                Jet::new(e.y1.slip_vel, e.f1.slip_vel),
                e.h,
                rate_bound,
                curvature_bound,
            )
        }
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
pub(crate) fn free_of_roots(v0: Jet, v1: Jet, h: f64, rate_bound: f64, curvature_bound: f64) -> bool {
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
