//! Gaussian elimination for the small dense systems of the stack (at most
//! [`MAX_COORDINATES`] unknowns). Written here: the systems are tiny and on the
//! stack, and a linear-algebra crate would bring generic matrices of any size
//! for one 7×7 solve.

use super::geometry::MAX_COORDINATES;
use crate::jet::Real;

/// A square matrix of order `C`, row-major (padded where it holds a system of
/// a lower order).
pub(crate) type Matrix<T = f64, const C: usize = MAX_COORDINATES> = [[T; C]; C];

/// Solves `a x = b` for the leading `n × n` block (`n ≤ C`) by elimination with partial
/// pivoting, in place: `b` becomes `x`, `a` is overwritten. Returns the
/// determinant of `a` (0 where a pivot vanishes, and then `x` is NaN). On
/// [`Jet`](crate::jet::Jet)s the pivots are chosen on the values, and `x`
/// carries the derivative of the solution; the determinant is the values'.
#[inline]
pub(crate) fn solve<T: Real, const C: usize>(a: &mut Matrix<T, C>, b: &mut [T; C], n: usize) -> f64 {
    let mut det = 1.0;
    for col in 0..n {
        let mut best = col;
        for row in col + 1..n {
            if a[row][col].value().abs() > a[best][col].value().abs() {
                best = row;
            }
        }
        if a[best][col].value() == 0.0 || !a[best][col].value().is_finite() {
            *b = [T::from(f64::NAN); C];
            return 0.0;
        }
        if best != col {
            a.swap(best, col);
            b.swap(best, col);
            det = -det;
        }
        let pivot = a[col][col];
        det *= pivot.value();
        for row in col + 1..n {
            let factor = a[row][col] / pivot;
            if !factor.is_zero() {
                for j in col..n {
                    a[row][j] = a[row][j] - factor * a[col][j];
                }
                b[row] = b[row] - factor * b[col];
            }
        }
    }
    for row in (0..n).rev() {
        let mut sum = b[row];
        for j in row + 1..n {
            sum = sum - a[row][j] * b[j];
        }
        b[row] = sum / a[row][row];
    }
    det
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3×3 system with a zero first pivot (needs the row swap), solution and
    /// determinant worked out by hand: `[[0,2,1],[1,1,0],[2,0,3]] x = [7,3,11]`
    /// has `x = (1, 2, 3)` (by substitution: 0+4+3 = 7, 1+2 = 3, 2+9 = 11);
    /// det = 0·3 − 2·(3 − 0) + 1·(0 − 2) = −8.
    #[test]
    fn three_by_three_by_hand() {
        let mut a = [[0.0; MAX_COORDINATES]; MAX_COORDINATES];
        a[0][..3].copy_from_slice(&[0.0, 2.0, 1.0]);
        a[1][..3].copy_from_slice(&[1.0, 1.0, 0.0]);
        a[2][..3].copy_from_slice(&[2.0, 0.0, 3.0]);
        let mut b = [0.0; MAX_COORDINATES];
        b[..3].copy_from_slice(&[7.0, 3.0, 11.0]);
        let det = solve(&mut a, &mut b, 3);
        // Small integers through a few eliminations: exact to a few ulps.
        for (got, want) in b.iter().zip([1.0, 2.0, 3.0]) {
            assert!((got - want).abs() < 1e-14, "{b:?}");
        }
        assert!((det + 8.0).abs() < 1e-13, "{det}");
    }
}
