//! Local extrema, inside one step, of a smooth quantity that is not a
//! component of the state (the friction demand of a stuck building, the top
//! acceleration, the pivot reactions).
//!
//! The value and the exact time derivative of the quantity are known at both
//! ends of the step (forward-mode jets through the equations). An extremum
//! inside shows as a sign change of the derivative between the ends; a pair
//! of extrema (a maximum and a minimum) leaves the ends' derivatives of one
//! sign, but then the cubic Hermite interpolant of the four end values, which
//! matches the quantity to `O(h⁴)`, has its own two critical points there.
//! So the derivative is sampled at the ends, at the Hermite interpolant's
//! critical points and between them; every sign change among the samples
//! brackets an extremum, located by root finding on the exact derivative.
//! A step whose ends show no extremum and whose interpolant has no critical
//! point inside costs nothing beyond the end values.
//!
//! [`taylor_enclosure`] bounds a quantity over a whole step from its first
//! two derivatives at the ends and a bound on the third: a step that cannot
//! hold a value that matters is not examined inside.

use crate::jet::Jet;

/// The cubic Hermite interpolant of `q0`, `q1` with slopes `h d0`, `h d1` on
/// `x ∈ [0, 1]`: `p(x) = v0 + s0 x + c2 x² + c3 x³`.
struct Cubic {
    v0: f64,
    s0: f64,
    c2: f64,
    c3: f64,
}

impl Cubic {
    fn hermite(q0: Jet, q1: Jet, h: f64) -> Self {
        let delta = q1.v - q0.v;
        let (s0, s1) = (h * q0.d, h * q1.d);
        Self {
            v0: q0.v,
            s0,
            c2: 3.0 * delta - 2.0 * s0 - s1,
            c3: -2.0 * delta + s0 + s1,
        }
    }

    fn at(&self, x: f64) -> f64 {
        self.v0 + x * (self.s0 + x * (self.c2 + x * self.c3))
    }
}

/// Whether the cubic Hermite interpolant of `q0`, `q1` is strictly monotone on
/// the step, told from its derivative's Bernstein coefficients (proportional
/// to `s0`, `3 (v1 − v0) − s0 − s1`, `s1`): all of one strict sign keep the
/// derivative, their convex combination, off zero. A few operations that
/// spare most steps the quadratic's roots.
#[inline]
fn hermite_monotone(q0: Jet, q1: Jet, h: f64) -> bool {
    let (s0, s1) = (h * q0.d, h * q1.d);
    let middle = 3.0 * (q1.v - q0.v) - s0 - s1;
    (s0 > 0.0 && middle > 0.0 && s1 > 0.0) || (s0 < 0.0 && middle < 0.0 && s1 < 0.0)
}

/// The least and greatest Bernstein coefficients of the cubic Hermite
/// interpolant of `q0`, `q1` (`v0`, `v0 + s0/3`, `v1 − s1/3`, `v1`): by the
/// convex hull property, bounds of the interpolant on the step that cost no
/// root.
#[inline]
fn hermite_hull(q0: Jet, q1: Jet, h: f64) -> (f64, f64) {
    let (b1, b2) = (q0.v + h * q0.d / 3.0, q1.v - h * q1.d / 3.0);
    (q0.v.min(q1.v).min(b1).min(b2), q0.v.max(q1.v).max(b1).max(b2))
}

/// Critical points in `(0, 1)` of the cubic Hermite interpolant of `q0`,
/// `q1` with slopes `h d0`, `h d1` (at most two, in increasing order).
fn hermite_critical_points(q0: Jet, q1: Jet, h: f64) -> ([f64; 2], usize) {
    let p = Cubic::hermite(q0, q1, h);
    // p'(x) = s0 + 2 c2 x + 3 c3 x².
    let (a, b, c) = (3.0 * p.c3, 2.0 * p.c2, p.s0);
    let mut out = [0.0; 2];
    let mut n = 0;
    let mut push = |x: f64| {
        if x > 0.0 && x < 1.0 && x.is_finite() {
            out[n] = x;
            n += 1;
        }
    };
    let scale = a.abs().max(b.abs()).max(c.abs());
    if scale == 0.0 {
        return (out, 0);
    }
    if a.abs() <= 1e-12 * scale {
        if b != 0.0 {
            push(-c / b);
        }
    } else {
        let disc = b * b - 4.0 * a * c;
        if disc >= 0.0 {
            // Citardauq/quadratic pair without cancellation.
            let q = -0.5 * (b + b.signum() * disc.sqrt());
            let (x1, x2) = (q / a, if q != 0.0 { c / q } else { f64::NAN });
            let (lo, hi) = if x1 <= x2 || x2.is_nan() { (x1, x2) } else { (x2, x1) };
            push(lo);
            push(hi);
        }
    }
    (out, n)
}

/// The critical points in `(0, 1)` of the cubic Hermite interpolant of the
/// end values (as [`hermite_critical_points`]) if the end values leave room
/// for an extremum inside the step: the interpolant is not strictly
/// monotone, and it has a critical point inside or the end slopes differ in
/// sign. `None` otherwise.
#[inline]
fn interior_critical_points(q0: Jet, q1: Jet, h: f64) -> Option<([f64; 2], usize)> {
    if h <= 0.0 || hermite_monotone(q0, q1, h) {
        return None;
    }
    let (critical, n) = hermite_critical_points(q0, q1, h);
    (n > 0 || q0.d * q1.d < 0.0).then_some((critical, n))
}

/// If the end values leave room for an extremum inside the step (as
/// [`may_have_extremum`]), the least and greatest values of the cubic Hermite
/// interpolant of the end values on the step (at its ends and critical
/// points): an estimate of the quantity's range over the step, accurate to
/// `O(h⁴)`.
fn hermite_range(q0: Jet, q1: Jet, h: f64) -> Option<(f64, f64)> {
    let (critical, n) = interior_critical_points(q0, q1, h)?;
    let p = Cubic::hermite(q0, q1, h);
    let (mut lo, mut hi) = (q0.v.min(q1.v), q0.v.max(q1.v));
    for &x in &critical[..n] {
        let v = p.at(x);
        lo = lo.min(v);
        hi = hi.max(v);
    }
    Some((lo, hi))
}

/// Whether the quantity's range over the step, as estimated by
/// [`hermite_range`], passes `reaches`, a test that a wider interval passes
/// whenever a narrower one does (a peak's threshold). The interpolant's
/// Bernstein hull, which holds that range, is tried first: a step it keeps
/// short of the test needs no root of the quadratic.
pub(crate) fn hermite_range_reaches(q0: Jet, q1: Jet, h: f64, reaches: impl Fn((f64, f64)) -> bool) -> bool {
    reaches(hermite_hull(q0, q1, h)) && hermite_range(q0, q1, h).is_some_and(reaches)
}

/// A step is searched for a peak of the top acceleration or of the pivot
/// friction demand only if the cubic Hermite interpolant of the exact end
/// values and slopes comes within this fraction of the running maximum (or
/// `f_y` within this fraction of `g_e` of zero). The interpolant's error is
/// `h⁴/384 max|q⁗|`, below 1e-3 of the quantity for the steps DOP853 takes
/// on these smooth quantities (ten or more per period of the input or of the
/// rocking), so a step it keeps 5% below cannot hold the peak. Transition
/// conditions are never pruned this way.
pub(crate) const PEAK_MARGIN: f64 = 0.05;

/// Whether the cubic Hermite interpolant of a quantity's exact end values
/// and slopes comes within [`PEAK_MARGIN`] of `peak`, the largest magnitude
/// kept so far: if not, the step is not searched for a peak of it.
pub(crate) fn near_peak(q0: Jet, q1: Jet, h: f64, peak: f64) -> bool {
    hermite_range_reaches(q0, q1, h, |(lo, hi)| lo.abs().max(hi.abs()) >= (1.0 - PEAK_MARGIN) * peak)
}

/// An extremum matters if it can raise the maximum kept before the step (one
/// kept during it is at least as high).
pub(crate) fn above(peak: f64) -> impl Fn((f64, f64)) -> bool {
    move |(lo, hi): (f64, f64)| lo.abs().max(hi.abs()) > peak
}

/// Relative accuracy of a located extremum's value.
const VALUE_RTOL: f64 = 1e-12;

/// The extremum between `ta` and `tb`, where the derivative has the signs of
/// `da` and `db` (opposite): the secant of the derivative through its two
/// latest samples, kept inside the bracket (bisection where it would leave
/// it), stopped once the value is known to [`VALUE_RTOL`].
///
/// Near a simple extremum `t*` the value differs from the extremum's by
/// `q̇(t)² / (2 |q̈|)` to leading order, and the secant slope of the last two
/// samples estimates `q̈` there: the iteration stops when `q̇² <= VALUE_RTOL
/// |q| |q̈|`, twice the leading-order error. The secant converges with order
/// 1.6 from the interpolant's own critical point (one of the ends, mostly),
/// so this takes one or two evaluations where a bracket-width test (the
/// bracket's far end stays at the step's end) took four or five; the width
/// test `|q̇| (tb − ta) <= VALUE_RTOL |q|` (the value cannot move by more
/// than the smaller end derivative times the bracket while `q̇` is monotone
/// on it) still ends the search where the curvature estimate is lost.
fn locate(eval: &mut impl FnMut(f64) -> Jet, mut ta: f64, mut da: f64, mut tb: f64, mut db: f64) -> (f64, f64) {
    // Signed so that the derivative goes from negative to positive.
    let sign = if da > 0.0 { -1.0 } else { 1.0 };
    da *= sign;
    db *= sign;
    // The secant's two points: the end with the smaller derivative last.
    let ((mut t_prev, mut d_prev), (mut t_last, mut d_last)) = if da.abs() < db.abs() { ((tb, db), (ta, da)) } else { ((ta, da), (tb, db)) };
    let mut best = (f64::NAN, f64::INFINITY, f64::NAN);
    for _ in 0..64 {
        let mut t = t_last - d_last * (t_last - t_prev) / (d_last - d_prev);
        if !(t > ta && t < tb) {
            t = 0.5 * (ta + tb);
        }
        if t <= ta || t >= tb {
            break;
        }
        let q = eval(t);
        let d = sign * q.d;
        if d.abs() < best.1 {
            best = (t, d.abs(), q.v);
        }
        if d == 0.0 {
            break;
        }
        if d < 0.0 {
            (ta, da) = (t, d);
        } else {
            (tb, db) = (t, d);
        }
        let curvature = ((d - d_last) / (t - t_last)).abs();
        (t_prev, d_prev, t_last, d_last) = (t_last, d_last, t, d);
        let tolerance = VALUE_RTOL * q.v.abs();
        if d * d <= tolerance * curvature || (tb - ta) * da.abs().min(db.abs()) <= tolerance {
            break;
        }
    }
    if best.2.is_nan() {
        // No point strictly inside the bracket was left: its ends are the extremum to rounding.
        best.0 = if da.abs() < db.abs() { ta } else { tb };
        best.2 = eval(best.0).v;
    }
    (best.0, best.2)
}

/// Whether the end values leave room for an extremum inside the step (if
/// not, [`interior_extrema`] finds none without evaluating anything).
pub(crate) fn may_have_extremum(q0: Jet, q1: Jet, h: f64) -> bool {
    interior_critical_points(q0, q1, h).is_some()
}

/// Bounds `(lo, hi)` of the extremum's value between `a` and `b`, where the
/// derivative has opposite signs and is monotone (the premise of every
/// bracket here): the quantity is concave there (a maximum) or convex (a
/// minimum), so it lies on one side of its tangents at both ends. The
/// extremum is then at least the larger end value (a maximum) and at most
/// where the two tangents meet, `T = q_a + q̇_a x` with `x = (q_b − q_a −
/// q̇_b H) / (q̇_a − q̇_b)`, `H = t_b − t_a`; mirrored for a minimum. `x` is
/// kept in `[0, H]`, where exact arithmetic puts it.
fn extremum_bounds((ta, a): (f64, Jet), (tb, b): (f64, Jet)) -> (f64, f64) {
    let span = tb - ta;
    let x = ((b.v - a.v - b.d * span) / (a.d - b.d)).clamp(0.0, span);
    let tangents = a.v + a.d * x;
    let end = if a.d > 0.0 { a.v.max(b.v) } else { a.v.min(b.v) };
    (tangents.min(end), tangents.max(end))
}

/// Whether an extremum inside the step may matter, told from the ends
/// alone where the interpolant shows a single one with a monotone
/// derivative (its derivative, a quadratic, changes sign between the ends
/// and has its vertex outside the step): [`extremum_bounds`] over the whole
/// step. Anywhere else, `true` (the samples inside will tell).
pub(crate) fn matters_on_step(t0: f64, q0: Jet, t1: f64, q1: Jet, matters: impl Fn((f64, f64)) -> bool) -> bool {
    if q0.d * q1.d >= 0.0 {
        return true;
    }
    let p = Cubic::hermite(q0, q1, t1 - t0);
    // p'(x) = s0 + 2 c2 x + 3 c3 x², vertex at −c2 / (3 c3).
    let vertex = -p.c2 / (3.0 * p.c3);
    if vertex > 0.0 && vertex < 1.0 {
        return true;
    }
    matters(extremum_bounds((t0, q0), (t1, q1)))
}

/// An enclosure `(lo, hi)` of a quantity `q` over a whole step of length
/// `h`, from its value and first two derivatives at both ends, `q0 = (q,
/// q̇, q̈)` at the start and `q1` at the end, and a bound `|q⃛| <=
/// third_bound` on the step. Each half of the step is nearer one end, where
/// Taylor's theorem gives `q = q_e + q̇_e τ + q̈_e τ²/2 + ρ` with `|ρ| <=
/// third_bound τ³/6`, `τ <= h/2` the distance to that end: the quadratic's
/// range on `[0, h/2]` (its ends and vertex), widened by the remainder's
/// bound, holds `q` there. A proof, not an estimate: the factor `1 + 1e-9`
/// and the `4 ε` terms cover the rounding of the bounds.
pub(crate) fn taylor_enclosure(q0: [f64; 3], q1: [f64; 3], h: f64, third_bound: f64) -> (f64, f64) {
    let half = 0.5 * h;
    let remainder = third_bound * half * half * half / 6.0 * (1.0 + 1e-9);
    // The quadratic from one end, `direction` +1 forwards from t0, −1 backwards from t1.
    let half_range = |[v, d, dd]: [f64; 3], direction: f64| {
        let d = direction * d;
        let p = |tau: f64| v + tau * (d + 0.5 * dd * tau);
        let (mut lo, mut hi) = (v.min(p(half)), v.max(p(half)));
        let vertex = -d / dd;
        if vertex > 0.0 && vertex < half {
            (lo, hi) = (lo.min(p(vertex)), hi.max(p(vertex)));
        }
        let rounding = 4.0 * f64::EPSILON * (v.abs() + d.abs() * half + dd.abs() * half * half);
        (lo - remainder - rounding, hi + remainder + rounding)
    };
    let (a, b) = (half_range(q0, 1.0), half_range(q1, -1.0));
    (a.0.min(b.0), a.1.max(b.1))
}

/// Calls `found(t, q)` for each local extremum of `q` found inside
/// `(t0, t1)`, in increasing time; `eval(t)` gives `q` and `q̇` at `t`.
///
/// `matters((lo, hi))` tells whether an extremum whose value lies in
/// `[lo, hi]` could change what the caller keeps (a running maximum above
/// `hi` cannot): once a bracket is found, [`extremum_bounds`] gives such an
/// interval from the bracket's ends at no cost, and an extremum that cannot
/// matter is not located. A harmonic response repeats its peaks every
/// half-period a little below the running maximum, so most of them end
/// here, after the one evaluation that found their bracket.
pub(crate) fn interior_extrema(
    t0: f64,
    q0: Jet,
    t1: f64,
    q1: Jet,
    eval: &mut impl FnMut(f64) -> Jet,
    matters: impl Fn((f64, f64)) -> bool,
    found: &mut impl FnMut(f64, f64),
) {
    let h = t1 - t0;
    let Some((critical, n)) = interior_critical_points(q0, q1, h) else {
        return;
    };
    if !matters_on_step(t0, q0, t1, q1, &matters) {
        return;
    }
    // Samples: ends, critical points, and between two of them.
    let mut samples = [(0.0, Jet::from(0.0)); 5];
    let mut m = 0;
    samples[m] = (t0, q0);
    m += 1;
    for (i, &x) in critical[..n].iter().enumerate() {
        if i == 1 {
            let mid = t0 + 0.5 * (critical[0] + x) * h;
            samples[m] = (mid, eval(mid));
            m += 1;
        }
        let t = t0 + x * h;
        samples[m] = (t, eval(t));
        m += 1;
    }
    samples[m] = (t1, q1);
    m += 1;
    // Sign changes between consecutive nonzero samples; a sample exactly on
    // zero between them is the extremum itself.
    let mut last: Option<usize> = None;
    for k in 0..m {
        let (tb, b) = samples[k];
        if b.d == 0.0 {
            continue;
        }
        if let Some(j) = last {
            let (ta, a) = samples[j];
            if a.d * b.d < 0.0 {
                if let Some(z) = (j + 1..k).find(|&z| samples[z].1.d == 0.0) {
                    let (t, q) = samples[z];
                    found(t, q.v);
                } else if matters(extremum_bounds((ta, a), (tb, b))) {
                    let (t, v) = locate(eval, ta, a.d, tb, b.d);
                    found(t, v);
                }
            }
        }
        last = Some(k);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;

    fn jet_of(f: impl Fn(f64) -> (f64, f64), t: f64) -> Jet {
        let (v, d) = f(t);
        Jet::new(v, d)
    }

    /// sin(t) on [1, 2.2]: one maximum at π/2, value 1 exact to rounding.
    /// The search stops on the value (to 1e-12 relative), so the instant is
    /// known to `sqrt(2 · 1e-12 / |q̈|)` = 1.4e-6 at most (`q̈ = −1`); in fact
    /// the secant lands far closer.
    #[test]
    fn one_maximum_between_ends_of_opposite_slope() {
        let f = |t: f64| (t.sin(), t.cos());
        let mut got = Vec::new();
        interior_extrema(1.0, jet_of(f, 1.0), 2.2, jet_of(f, 2.2), &mut |t| jet_of(f, t), |_| true, &mut |t, v| {
            got.push((t, v))
        });
        assert_eq!(got.len(), 1);
        assert_relative_eq!(got[0].0, std::f64::consts::FRAC_PI_2, epsilon = 1.5e-6);
        assert_relative_eq!(got[0].1, 1.0, epsilon = 1e-15);
    }

    /// t³ − 3 a² t with a = 0.1 on [−0.3, 0.3]: slopes at both ends are
    /// positive (27a² − 3a² > 0), yet there is a maximum at −a and a minimum at
    /// +a, with values ±2a³. Both are found.
    #[test]
    fn a_pair_hidden_from_the_ends_slopes() {
        let a: f64 = 0.1;
        let f = move |t: f64| (t * t * t - 3.0 * a * a * t, 3.0 * t * t - 3.0 * a * a);
        let mut got = Vec::new();
        interior_extrema(-0.3, jet_of(f, -0.3), 0.3, jet_of(f, 0.3), &mut |t| jet_of(f, t), |_| true, &mut |t, v| {
            got.push((t, v))
        });
        assert_eq!(got.len(), 2, "{got:?}");
        assert_relative_eq!(got[0].0, -a, epsilon = 1e-12);
        assert_relative_eq!(got[0].1, 2.0 * a.powi(3), epsilon = 1e-15);
        assert_relative_eq!(got[1].0, a, epsilon = 1e-12);
        assert_relative_eq!(got[1].1, -2.0 * a.powi(3), epsilon = 1e-15);
    }

    /// A monotone quantity reports nothing and evaluates nothing inside.
    #[test]
    fn monotone_costs_nothing() {
        let f = |t: f64| (t.exp(), t.exp());
        let mut evaluations = 0;
        interior_extrema(
            0.0,
            jet_of(f, 0.0),
            1.0,
            jet_of(f, 1.0),
            &mut |t| {
                evaluations += 1;
                jet_of(f, t)
            },
            |_| true,
            &mut |_, _| panic!("no extremum"),
        );
        assert_eq!(evaluations, 0);
    }

    /// sin(t) on [1, 2.2] again: the maximum, 1, lies inside the bounds the
    /// bracket's ends give (the tangents at both ends of a concave stretch
    /// lie above it; the larger end value lies below it). The interpolant's
    /// critical point falls `a` = 1.8e-3 from π/2 and the far end `b` = 0.63
    /// beyond it, where the tangents of `1 − (t − π/2)²/2` would meet at
    /// `1 + ab/2` = 1 + 5.7e-4: an extremum that only matters above 1.001 is
    /// not located (one evaluation, the critical point that brackets it), and
    /// one that matters above 1 − 1e-9 is, to the same 1e-15.
    #[test]
    fn an_extremum_that_cannot_matter_is_not_located() {
        let f = |t: f64| (t.sin(), t.cos());
        let (q0, q1) = (jet_of(f, 1.0), jet_of(f, 2.2));
        let run = |threshold: f64| {
            let (mut evaluations, mut got) = (0, Vec::new());
            let mut eval = |t: f64| {
                evaluations += 1;
                jet_of(f, t)
            };
            interior_extrema(
                1.0,
                q0,
                2.2,
                q1,
                &mut eval,
                |(lo, hi): (f64, f64)| {
                    assert!(lo <= 1.0 && hi >= 1.0, "bounds ({lo}, {hi}) miss the maximum");
                    hi > threshold
                },
                &mut |_, v| got.push(v),
            );
            (evaluations, got)
        };
        assert_eq!(run(1.001), (1, vec![]));
        let (evaluations, got) = run(1.0 - 1e-9);
        assert!(evaluations > 1);
        assert_eq!(got.len(), 1);
        assert_relative_eq!(got[0], 1.0, epsilon = 1e-15);
    }

    /// The bounds of a minimum mirror those of a maximum: for q = t² − 1 on
    /// a bracket [−0.5, 1] (q̇ = −1 and 2), the tangents meet at
    /// x = (0 − (−0.75) − 2 · 1.5) / (−1 − 2) = 0.75, T = −0.75 − 0.75 = −1.5,
    /// and the smaller end value is −0.75: the minimum −1 lies between.
    #[test]
    fn bounds_of_a_minimum_by_hand() {
        let (lo, hi) = extremum_bounds((-0.5, Jet::new(-0.75, -1.0)), (1.0, Jet::new(0.0, 2.0)));
        assert_eq!((lo, hi), (-1.5, -0.75));
    }

    /// sin(t) on [1, 2.2] once more, from the ends alone: the interpolant's
    /// derivative has its vertex at x = 28 (outside the step), so the
    /// tangents at t = 1 and t = 2.2 bound the one maximum: they meet at
    /// x = (sin 2.2 − sin 1 − 1.2 cos 2.2) / (cos 1 − cos 2.2) = 0.5964,
    /// T = sin 1 + 0.5964 cos 1 = 1.1637, above the true 1. An extremum that
    /// only matters above 1.2 costs no evaluation at all; one that matters
    /// above 1.1 is searched (and found at 1, below that threshold and so not
    /// located, after the one evaluation that brackets it).
    #[test]
    fn the_ends_alone_can_rule_out_an_extremum() {
        let f = |t: f64| (t.sin(), t.cos());
        let (q0, q1) = (jet_of(f, 1.0), jet_of(f, 2.2));
        assert!(!matters_on_step(1.0, q0, 2.2, q1, |(_, hi)| hi > 1.2));
        assert!(matters_on_step(1.0, q0, 2.2, q1, |(lo, hi)| {
            // The tangents' meeting point evaluated in double precision by hand: 1.1637112998144874.
            assert_relative_eq!(hi, 1.163_711_299_814_487_4, epsilon = 4e-16);
            assert_relative_eq!(lo, 1.0f64.sin(), epsilon = 1e-15);
            hi > 1.1
        }));
        let mut evaluations = 0;
        let mut eval = |t: f64| {
            evaluations += 1;
            jet_of(f, t)
        };
        interior_extrema(1.0, q0, 2.2, q1, &mut eval, |(_, hi)| hi > 1.2, &mut |_, _| panic!("not located"));
        assert_eq!(evaluations, 0);
    }

    /// Where the interpolant's derivative turns inside the step, the ends'
    /// tangents bound nothing and the extremum is left to the samples
    /// inside: t³ − 3a²t (a = 0.1, its own interpolant) on [−0.3, 0.05] has
    /// slopes 0.24 and −0.0225 at the ends, a maximum at −0.1, and a
    /// derivative that turns at t = 0 (x = 0.86 of the step).
    #[test]
    fn the_ends_say_nothing_about_a_hidden_pair() {
        let a: f64 = 0.1;
        let f = move |t: f64| (t * t * t - 3.0 * a * a * t, 3.0 * t * t - 3.0 * a * a);
        assert!(matters_on_step(-0.3, jet_of(f, -0.3), 0.05, jet_of(f, 0.05), |_| false));
    }

    /// sin on [1, 2.2], `|q⃛| <= 1`, by hand: from t = 1 the quadratic
    /// `sin 1 + τ cos 1 − τ² sin 1 / 2` has its vertex at τ = cot 1 =
    /// 0.642 > h/2 = 0.6, so its largest value on [0, 0.6] is at 0.6,
    /// 1.0141875910633589; from t = 2.2 backwards the vertex is at
    /// −cot 2.2 = 0.728, the value at 0.6 is 1.0160677214852716. The
    /// remainder is 0.6³/6 = 0.036: hi = 1.0520677214852716. The least value
    /// is sin 2.2 at τ = 0 from the end, less the remainder:
    /// 0.7724964038195901. The true range, [sin 2.2, 1], lies inside.
    #[test]
    fn enclosure_of_a_sine_by_hand() {
        let q = |t: f64| [t.sin(), t.cos(), -t.sin()];
        let (lo, hi) = taylor_enclosure(q(1.0), q(2.2), 1.2, 1.0);
        // Hand values to 16 digits, without the bound's 1e-9 safety factor on
        // the remainder (3.6e-11 on 0.036) and its 4 ε rounding terms (2e-15).
        assert!((hi - 1.0520677214852716).abs() < 3.7e-11, "hi {hi}");
        assert!((lo - 0.7724964038195901).abs() < 3.7e-11, "lo {lo}");
        assert!(lo <= 2.2f64.sin() && hi >= 1.0);
    }

    proptest::proptest! {
        #![proptest_config(proptest::prelude::ProptestConfig { cases: 256, ..Default::default() })]
        /// `q = a sin(ω t + φ) + b t² + c t`, `|q⃛| <= a ω³`, on random steps:
        /// every one of 2001 samples lies inside the enclosure, and the
        /// enclosure exceeds the sampled range by at most twice the
        /// remainder's bound (the quadratic is off `q` by at most that bound
        /// where `q` is extreme, and is widened by it once more), plus what
        /// the samples can miss of an extremum between two of them, at most
        /// `max|q̈| (Δ/2)² / 2` for a spacing `Δ = h/2000`, plus rounding.
        #[test]
        fn the_enclosure_holds_every_sample(
            a in 0.1f64..2.0, omega in 0.5f64..20.0, phase in 0.0f64..6.3,
            b in -3.0f64..3.0, c in -3.0f64..3.0, t0 in -5.0f64..5.0, h in 1e-3f64..1.0,
        ) {
            let q = |t: f64| {
                let (s, co) = (omega * t + phase).sin_cos();
                [a * s + b * t * t + c * t, a * omega * co + 2.0 * b * t + c, -a * omega * omega * s + 2.0 * b]
            };
            let third = a * omega.powi(3);
            let (lo, hi) = taylor_enclosure(q(t0), q(t0 + h), h, third);
            let (mut min, mut max) = (f64::INFINITY, f64::NEG_INFINITY);
            for i in 0..=2000 {
                let v = q(t0 + h * i as f64 / 2000.0)[0];
                (min, max) = (min.min(v), max.max(v));
            }
            proptest::prop_assert!(lo <= min && max <= hi, "[{lo}, {hi}] against samples [{min}, {max}]");
            let missed = (a * omega * omega + 2.0 * b.abs()) * (h / 4000.0).powi(2) / 2.0;
            let slack = 2.0 * third * (0.5 * h).powi(3) / 6.0 * (1.0 + 1e-9) + missed + 1e-14 * (min.abs() + max.abs() + a);
            proptest::prop_assert!(hi - max <= slack && min - lo <= slack, "[{lo}, {hi}] against [{min}, {max}], slack {slack}");
        }
    }
}
