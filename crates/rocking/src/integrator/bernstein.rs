//! Every root of one component of a step's dense output.
//!
//! The dense output is a polynomial of degree 7 in `x = (t − t_old)/h`.
//! Written in the Bernstein basis on `[0, 1]`, a polynomial lies in the convex
//! hull of its coefficients and has no more roots in `[0, 1]` than they have
//! sign changes (Descartes' rule in Bernstein form, the variation diminishing
//! property). So: no sign change proves that there is no root, one sign change
//! with opposite signs at the ends proves exactly one, and anything else is
//! split in halves by de Casteljau's algorithm until it is one of the two.
//! This is what lets a step that ends on the same side of zero as it started
//! prove that it did not cross zero twice in between, whatever the step's
//! length (the sign of the ends alone proves nothing).

use super::DenseOutput;

const DEGREE: usize = 7;
type Coefficients = [f64; DEGREE + 1];

/// Deepest subdivision: `2^-40` of a step is far below any resolvable time.
const MAX_DEPTH: u32 = 40;

/// Bernstein coefficients of component `j` of `d` minus `level`, on the step.
pub(crate) fn coefficients<const N: usize>(d: &DenseOutput<N>, j: usize, level: f64) -> Coefficients {
    // Hairer's nesting y_old + x(F0 + (1−x)(F1 + x(F2 + … x F6))), built from
    // the inside out: adding a constant adds it to every coefficient; a factor
    // x or (1 − x) raises the degree by one (degree elevation).
    let mut b = [0.0; DEGREE + 1];
    let mut m = 0usize; // current degree
    for (i, row) in d.f.iter().rev().enumerate() {
        for c in &mut b[..=m] {
            *c += row[j];
        }
        let next = m + 1;
        let scale = 1.0 / next as f64;
        if i % 2 == 0 {
            // times x: c_i = i/(m+1) b_{i−1}
            for k in (1..=next).rev() {
                b[k] = k as f64 * scale * b[k - 1];
            }
            b[0] = 0.0;
        } else {
            // times (1 − x): c_i = (m+1−i)/(m+1) b_i
            for (k, c) in b[..next].iter_mut().enumerate() {
                *c *= (next - k) as f64 * scale;
            }
            b[next] = 0.0;
        }
        m = next;
    }
    let base = d.y_old[j] - level;
    for c in &mut b {
        *c += base;
    }
    b
}

/// Sign changes of the coefficients, zeros skipped.
fn sign_changes(b: &Coefficients) -> u32 {
    let mut last = 0.0f64;
    let mut n = 0;
    for &c in b {
        if c != 0.0 {
            if last != 0.0 && (c > 0.0) != (last > 0.0) {
                n += 1;
            }
            last = c;
        }
    }
    n
}

/// The two halves of `b` (de Casteljau at `x = 1/2`).
fn split(b: &Coefficients) -> (Coefficients, Coefficients) {
    let mut left = [0.0; DEGREE + 1];
    let mut right = [0.0; DEGREE + 1];
    let mut work = *b;
    for k in 0..=DEGREE {
        left[k] = work[0];
        right[DEGREE - k] = work[DEGREE - k];
        for i in 0..DEGREE - k {
            work[i] = 0.5 * (work[i] + work[i + 1]);
        }
    }
    (left, right)
}

/// Calls `found(xa, xb)` for each interval of `[0, 1]`, in increasing order,
/// on whose ends the polynomial has strictly opposite signs and inside which
/// it has exactly one root. Roots exactly at `x = 0` (a step that starts on
/// zero) are not reported; double roots (touching zero without crossing) are
/// not either.
pub(crate) fn isolate(b: &Coefficients, found: &mut impl FnMut(f64, f64)) {
    isolate_in(b, 0.0, 1.0, 0, found);
}

fn isolate_in(b: &Coefficients, a: f64, w: f64, depth: u32, found: &mut impl FnMut(f64, f64)) {
    let changes = sign_changes(b);
    if changes == 0 {
        return;
    }
    let (first, last) = (b[0], b[DEGREE]);
    if changes == 1 && first * last < 0.0 {
        found(a, a + w);
        return;
    }
    if depth >= MAX_DEPTH {
        if first * last < 0.0 {
            found(a, a + w);
        }
        return;
    }
    let (left, right) = split(b);
    isolate_in(&left, a, 0.5 * w, depth + 1, found);
    isolate_in(&right, a + 0.5 * w, 0.5 * w, depth + 1, found);
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A dense output whose component 0 is `(x − r1)(x − r2)(x − r3)`,
    /// written in Hairer's nested form (rows F0–F2, the others zero).
    fn cubic_through_rows(r: [f64; 3]) -> DenseOutput<1> {
        // p = −e3 + e2 x − e1 x² + x³, e1 = Σ r_i, e2 = Σ r_i r_j, e3 = r1 r2 r3.
        let e1 = r[0] + r[1] + r[2];
        let e2 = r[0] * r[1] + r[0] * r[2] + r[1] * r[2];
        let e3 = r[0] * r[1] * r[2];
        // x(F0 + (1−x)(F1 + x F2)) = F0 x + F1 x + (F2 − F1) x² − F2 x³.
        let f2 = -1.0;
        let f1 = f2 + e1; // F2 − F1 = −e1
        let f0 = e2 - f1;
        let mut f = [[0.0; 1]; 7];
        f[0][0] = f0;
        f[1][0] = f1;
        f[2][0] = f2;
        DenseOutput {
            t_old: 0.0,
            h: 1.0,
            y_old: [-e3],
            f,
        }
    }

    /// The Bernstein form evaluates to the same polynomial as the nesting:
    /// de Casteljau's end values are the polynomial at 0 and 1, and the
    /// coefficients of a constant are all that constant.
    #[test]
    fn coefficients_reproduce_the_polynomial_at_the_ends() {
        let d = cubic_through_rows([0.2, 0.5, 0.9]);
        let b = coefficients(&d, 0, 0.0);
        assert!((b[0] - d.state(0.0)[0]).abs() < 1e-15);
        assert!((b[DEGREE] - d.state(1.0)[0]).abs() < 1e-15);
        let (left, _) = split(&b);
        assert!((left[DEGREE] - d.state(0.5)[0]).abs() < 1e-15);
    }

    /// Three roots, two of them 1e-6 apart: the signs at the ends show one
    /// crossing and hide the other two. All three are isolated, each in an
    /// interval that contains it.
    #[test]
    fn isolates_close_roots_hidden_from_the_ends() {
        let roots = [0.3, 0.7, 0.700001];
        let d = cubic_through_rows(roots);
        let mut found = Vec::new();
        isolate(&coefficients(&d, 0, 0.0), &mut |a, b| found.push((a, b)));
        assert_eq!(found.len(), 3, "{found:?}");
        for (root, (a, b)) in roots.iter().zip(&found) {
            assert!(*a <= *root && *root <= *b, "{root} not in [{a}, {b}]");
        }
    }

    /// A polynomial that stays positive reports nothing, and a root at the
    /// very start (a step that begins on zero) is not reported.
    #[test]
    fn no_roots_and_a_root_at_the_start() {
        let d = cubic_through_rows([-0.5, 1.5, 2.0]);
        let mut n = 0;
        isolate(&coefficients(&d, 0, 0.0), &mut |_, _| n += 1);
        assert_eq!(n, 0);
        let d = cubic_through_rows([0.0, 0.6, 3.0]);
        let mut found = Vec::new();
        isolate(&coefficients(&d, 0, 0.0), &mut |a, b| found.push((a, b)));
        assert_eq!(found.len(), 1, "{found:?}");
        assert!(found[0].0 <= 0.6 && 0.6 <= found[0].1);
    }
}
