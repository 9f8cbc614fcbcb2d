//! Bracketing root finder for event location on a dense output.
//!
//! Hand-written because event location needs the *bracket* back, not only a
//! point: the switch happens at the right end `tb`, where the new condition
//! already holds (`f(tb) >= 0`), so the next regime starts consistent with it
//! (DifferentialEquations.jl's `RightRootFind`). Root-finding crates return a
//! single estimate and may leave the bracket. This is the Anderson–Björck
//! variant of regula falsi, which keeps a bracket at every iteration and
//! converges superlinearly; a bisection every third stalled iteration bounds the
//! worst case.

/// A bracket `[ta, tb]` with `f(ta) < 0 <= f(tb)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Bracket {
    /// Last point where the condition does not hold.
    pub(crate) ta: f64,
    /// First point found where it holds: the event instant.
    pub(crate) tb: f64,
}

/// Narrows `[ta, tb]`, given `fa = f(ta) < 0 <= fb = f(tb)`, until `tb - ta` is
/// below `xtol` (s) or a few units in the last place of `tb`, or `f(tb)` is
/// exactly zero.
pub(crate) fn find_crossing(mut f: impl FnMut(f64) -> f64, mut ta: f64, mut fa: f64, mut tb: f64, mut fb: f64, xtol: f64) -> Bracket {
    debug_assert!(fa < 0.0 && fb >= 0.0);
    // Which end moved last (-1: a, +1: b), to detect a stalled side.
    let mut side = 0i32;
    let mut stalled = 0u32;
    for _ in 0..200 {
        let tol = (4.0 * f64::EPSILON * ta.abs().max(tb.abs()).max(1e-300)).max(xtol);
        if tb - ta <= tol || fb == 0.0 {
            break;
        }
        let mut t = if stalled >= 2 {
            stalled = 0;
            0.5 * (ta + tb)
        } else {
            (ta * fb - tb * fa) / (fb - fa)
        };
        if !(t > ta && t < tb) {
            t = 0.5 * (ta + tb);
        }
        if t <= ta || t >= tb {
            break;
        }
        let ft = f(t);
        if ft >= 0.0 {
            if side == 1 {
                // Anderson–Björck: scale the stale end down.
                let m = 1.0 - ft / fb;
                fa *= if m > 0.0 { m } else { 0.5 };
                stalled += 1;
            } else {
                stalled = 0;
            }
            tb = t;
            fb = ft;
            side = 1;
        } else {
            if side == -1 {
                let m = 1.0 - ft / fa;
                fb *= if m > 0.0 { m } else { 0.5 };
                stalled += 1;
            } else {
                stalled = 0;
            }
            ta = t;
            fa = ft;
            side = -1;
        }
    }
    Bracket { ta, tb }
}

/// As [`find_crossing`], for a function evaluated with its derivative (the
/// dense output gives `θ` and `θ̇` together): safeguarded Newton, which
/// converges quadratically and so needs about half the evaluations; a Newton
/// step that leaves the bracket is replaced by bisection, and once the steps
/// fall below a few ulp the bracket is closed by probing one step beyond.
pub(crate) fn find_crossing_newton(mut f: impl FnMut(f64) -> (f64, f64), mut ta: f64, fa: f64, mut tb: f64, fb: f64) -> Bracket {
    debug_assert!(fa < 0.0 && fb >= 0.0);
    let mut t = (ta * fb - tb * fa) / (fb - fa);
    if !(t > ta && t < tb) {
        t = 0.5 * (ta + tb);
    }
    for _ in 0..100 {
        let (ft, slope) = f(t);
        if ft >= 0.0 {
            tb = t;
        } else {
            ta = t;
        }
        let tol = 4.0 * f64::EPSILON * ta.abs().max(tb.abs()).max(1e-300);
        if tb - ta <= tol || ft == 0.0 {
            break;
        }
        let newton = t - ft / slope;
        let next = if (newton - t).abs() <= tol {
            // Converged from one side: probe just across the root.
            if ft >= 0.0 {
                t - tol
            } else {
                t + tol
            }
        } else {
            newton
        };
        t = if next > ta && next < tb { next } else { 0.5 * (ta + tb) };
    }
    Bracket { ta, tb }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// cos t − 0.5 crosses zero upward at 5π/3 on [4, 6]; the bracket must hold it
    /// and be a few ulp wide.
    #[test]
    fn brackets_a_transcendental_root() {
        let f = |t: f64| t.cos() - 0.5;
        let b = find_crossing(f, 4.0, f(4.0), 6.0, f(6.0), 0.0);
        let root = 5.0 * std::f64::consts::PI / 3.0;
        assert!(f(b.ta) < 0.0 && f(b.tb) >= 0.0);
        assert!(b.ta <= root + 1e-15 && b.tb >= root - 1e-15);
        assert!(b.tb - b.ta < 1e-14, "width {}", b.tb - b.ta);
    }

    /// Newton's variant brackets the same root as tightly, from either side.
    #[test]
    fn newton_variant_brackets_the_root() {
        let f = |t: f64| (t.cos() - 0.5, -t.sin());
        let b = find_crossing_newton(f, 4.0, f(4.0).0, 6.0, f(6.0).0);
        let root = 5.0 * std::f64::consts::PI / 3.0;
        assert!(f(b.ta).0 < 0.0 && f(b.tb).0 >= 0.0);
        assert!(b.ta <= root + 1e-15 && b.tb >= root - 1e-15 && b.tb - b.ta < 1e-14, "{b:?}");
        // A root near the start of a long bracket, as after a tiny rocking arc.
        let g = |t: f64| (t - 1e-9, 1.0);
        let b = find_crossing_newton(g, 1e-12, g(1e-12).0, 1.0, g(1.0).0);
        assert!((b.tb - 1e-9).abs() < 1e-22, "{b:?}");
    }

    /// A root very close to one end (a tiny rocking arc) is still found.
    #[test]
    fn root_near_the_left_end() {
        let root = 1e-9;
        let f = |t: f64| (t - root) * (1.0 + 1e3 * t);
        let b = find_crossing(f, 1e-12, f(1e-12), 1.0, f(1.0), 0.0);
        assert!((b.tb - root).abs() < 1e-22, "tb {}", b.tb);
    }
}
