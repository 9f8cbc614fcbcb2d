//! The first transition inside a step: every condition of the regime is
//! followed between the step's ends through the points where it may turn
//! (the extremes of θ for a condition of θ, the roots of `u̇` for the end of
//! a slip, the extrema of a stuck building's friction demand), and the first
//! bracket where it reaches zero is narrowed by root finding on the dense
//! output.

use super::screen::{Ends, Screen};
use super::watch::condition_on;
use crate::condition::Condition;
use crate::extrema::interior_extrema;
use crate::integrator::bernstein;
use crate::integrator::{find_crossing, find_crossing_newton, DenseOutput};
use crate::jet::Jet;
use crate::regime::State;
use arrayvec::ArrayVec;

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
pub(crate) struct Points(ArrayVec<(f64, f64), MAX_POINTS>);

impl Points {
    #[inline]
    pub(crate) fn push(&mut self, p: (f64, f64)) {
        let _ = self.0.try_push(p);
    }

    #[inline]
    pub(crate) fn as_slice(&self) -> &[(f64, f64)] {
        &self.0
    }
}

/// The extremes of θ inside a step: the roots of `θ̇` on the dense output,
/// isolated in the Bernstein form and narrowed by Newton, each with θ there.
#[inline(always)]
pub(super) fn theta_extremes<const N: usize>(d: &DenseOutput<N>, t0: f64, t1: f64) -> Points {
    // θ and θ̇ are the state's components 0 and 1 (`State::from_components`).
    extremes(d, t0, t1, 0, 1)
}

/// The extremes of the component `value` of the dense output inside a step
/// whose rate is the component `rate` (θ_k and θ̇_k of the stack): the roots
/// of `rate`, isolated in the Bernstein form and narrowed by Newton, each
/// with `value` there.
#[inline(always)]
pub(crate) fn extremes<const N: usize>(d: &DenseOutput<N>, t0: f64, t1: f64, value: usize, rate: usize) -> Points {
    let h = t1 - t0;
    let mut points = Points::default();
    bernstein::isolate(&bernstein::coefficients(d, rate, 0.0), &mut |xa, xb| {
        let (ta, tb) = (t0 + xa * h, (t0 + xb * h).min(t1));
        let sign = if d.state(ta)[rate] < 0.0 { 1.0 } else { -1.0 };
        let rising = |t: f64| {
            let (y, dy) = d.state_and_rate(t);
            (sign * y[rate], sign * dy[rate])
        };
        let (va, vb) = (rising(ta).0, rising(tb).0);
        let root = if va < 0.0 && vb >= 0.0 {
            find_crossing_newton(rising, ta, va, tb, vb).tb
        } else {
            0.5 * (ta + tb)
        };
        points.push((root, d.state(root)[value]));
    });
    points
}

/// A bracket `(ta, tb)` around the first root inside the step `[t0, t1]` of
/// the component `j` of the dense output (`u̇` for the end of a slip),
/// isolated in the Bernstein form; `None` if it has none.
#[inline(always)]
pub(crate) fn first_root<const N: usize>(d: &DenseOutput<N>, j: usize, t0: f64, t1: f64) -> Option<(f64, f64)> {
    let h = t1 - t0;
    let mut bracket = None;
    bernstein::isolate(&bernstein::coefficients(d, j, 0.0), &mut |xa, xb| {
        bracket.get_or_insert((t0 + xa * h, (t0 + xb * h).min(t1)));
    });
    bracket
}

/// The first transition in the step: its instant and condition. A step
/// without its dense output has none to search: every condition ends it
/// negative and none can have come back inside (or the screen would have
/// asked for the dense output). `fell_back`: the tower fell straight back
/// at the step's start.
#[inline(always)]
pub(super) fn first_transition<const N: usize>(
    e: &Ends,
    screen: &Screen,
    dense: Option<&DenseOutput<N>>,
    theta_points: &Points,
    fell_back: bool,
) -> Option<(f64, Condition)> {
    let d = dense?;
    let mut first: Option<(f64, Condition)> = None;
    for (i, &c) in e.list.iter().enumerate() {
        let hit = if c.of_theta() {
            theta_crossing(e, i, d, theta_points)
        } else {
            state_crossing(e, screen, i, d, OnZero::of(c, fell_back))
        };
        if let Some(tb) = hit {
            if first.is_none_or(|(tf, _)| tb < tf) {
                first = Some((tb, c));
            }
        }
    }
    first
}

/// Where the `i`-th condition, one of θ (impact, overturn), first reaches
/// zero in the step: it is monotone from one extreme of θ to the next.
#[inline(always)]
fn theta_crossing<const N: usize>(e: &Ends, i: usize, d: &DenseOutput<N>, theta_points: &Points) -> Option<f64> {
    let (c, s) = (e.list[i], e.s());
    let mut points = Points::default();
    points.push((e.t0, e.w0.conditions[i].v));
    for &(t, theta) in theta_points.as_slice() {
        points.push((t, c.theta_margin(s, theta)));
    }
    points.push((e.t1, e.w1.conditions[i].v));
    first_crossing(
        points.as_slice(),
        OnZero::of(c, false),
        |ta, va, tb, vb| {
            // With its derivative (θ̇ from the same dense output) for Newton.
            let f = |t: f64| {
                let y = State::from_components(&d.state(t));
                let m = c.theta_margin(s, Jet::new(y.theta, y.theta_dot));
                (m.v, m.d)
            };
            find_crossing_newton(f, ta, va, tb, vb).tb
        },
        |ta, tb| leaving_point(&|t| c.theta_margin(s, State::from_components(&d.state(t)).theta), ta, tb),
    )
}

/// Where the `i`-th condition, one of the state and the inputs (a slip, the
/// end of a slip, an uplift), first reaches zero in the step: through the
/// first root of `u̇` for the end of a slip, the extrema of the friction
/// demand for a stuck building under a rocking tower.
#[inline(always)]
fn state_crossing<const N: usize>(e: &Ends, screen: &Screen, i: usize, d: &DenseOutput<N>, on_zero: OnZero) -> Option<f64> {
    let (c, kernel, regime, (piece, vpiece)) = (e.list[i], e.kernel, e.regime, e.pieces);
    let (t0, t1) = (e.t0, e.t1);
    let value = |t: f64| {
        let y = State::from_components(&d.state(t));
        let (a_g, g_e) = if c.uses_ground() {
            (piece.eval(t), kernel.g + vpiece.eval(t))
        } else {
            (0.0, kernel.g)
        };
        c.value(kernel, regime, a_g, g_e, &y)
    };
    let mut points = Points::default();
    points.push((t0, e.w0.conditions[i].v));
    if c == Condition::SlipStop && screen.slip_roots {
        // u̇ is the state's component 3 (`State::from_components`).
        if let Some((ta, tb)) = first_root(d, 3, t0, t1) {
            points.push((ta, value(ta)));
            points.push((tb, value(tb)));
        }
    } else if screen.stick_examined {
        let mut eval = |t: f64| condition_on(kernel, regime, (piece, vpiece), c, d, t);
        interior_extrema(t0, e.w0.conditions[i], t1, e.w1.conditions[i], &mut eval, |_| true, &mut |t, v| {
            points.push((t, v))
        });
    }
    points.push((t1, e.w1.conditions[i].v));
    first_crossing(
        points.as_slice(),
        on_zero,
        |ta, va, tb, vb| find_crossing(value, ta, va, tb, vb, 0.0).tb,
        |ta, tb| leaving_point(&value, ta, tb),
    )
}

/// How a condition read on zero at a step's start, and not seen to leave
/// it, is taken.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum OnZero {
    /// It grows from zero: a transition at once.
    Grows,
    /// It departs from zero ([`Condition::departs_from_zero`]): armed where
    /// it is first negative; a transition at once if it never is in the step.
    Departs,
    /// An uplift condition at the instant the tower fell straight back
    /// (`Run::fall_straight_back`): armed where it is first negative; none
    /// in the step if it never is.
    Waits,
}

impl OnZero {
    /// How `c` is taken on zero at a step's start; `fell_back`: the tower
    /// fell straight back at that instant.
    pub(crate) fn of(c: Condition, fell_back: bool) -> Self {
        if c.departs_from_zero() {
            OnZero::Departs
        } else if fell_back && c.lifts() {
            OnZero::Waits
        } else {
            OnZero::Grows
        }
    }
}

/// The first instant in `points` (ordered, the condition monotone between
/// consecutive ones) where a condition reaches zero: `locate(ta, va, tb, vb)`
/// narrows a bracket `va < 0 <= vb`; `leaving(ta, tb)` finds where a
/// condition that starts on zero has become negative; `on_zero`: how a
/// start on zero that the motion does not leave is taken.
pub(crate) fn first_crossing(
    points: &[(f64, f64)],
    on_zero: OnZero,
    mut locate: impl FnMut(f64, f64, f64, f64) -> f64,
    leaving: impl Fn(f64, f64) -> Option<(f64, f64)>,
) -> Option<f64> {
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
        // would have ended the search): find where the motion left it.
        if let Some((tl, vl)) = leaving(ta, tb) {
            return Some(locate(tl, vl, tb, vb));
        }
        // It never did: the condition grew from zero, a transition at once,
        // unless it departs from zero. Which way such a condition leaves zero
        // was decided at the switch that set it there, by the next
        // derivative (`falls_back`, `slides_on`), and the regime was kept: a
        // start on the wrong side is the rounding of that derivative (after a
        // grazing uplift θ̈ is zero, computed as ±1e-16). It is armed where
        // it is first negative. If it never is in the step, the motion
        // itself says it does not leave zero: a transition at once (the
        // impact of a tower that falls straight back), or, for the uplift of
        // that tower, none.
        if on_zero == OnZero::Grows {
            return Some(ta);
        }
        return match points.iter().position(|&(_, v)| v < 0.0) {
            Some(j) => first_crossing(&points[j..], OnZero::Grows, locate, leaving),
            None => (on_zero == OnZero::Departs).then_some(ta),
        };
    }
    None
}

/// For a condition that is zero at `t0`: a point in `(t0, t1)` where it is
/// negative, found by halving towards `t0` (the dense output's first two
/// Taylor terms are exact there, so the motion's departure shows).
pub(crate) fn leaving_point(value: &impl Fn(f64) -> f64, t0: f64, t1: f64) -> Option<(f64, f64)> {
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
