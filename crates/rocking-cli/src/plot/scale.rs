//! Axis ranges and units: never empty, never NaN, in a unit that suits the size.

/// `[lo, hi]` widened by `pad` of its width on both sides; a point or an
/// empty/non-finite range becomes a unit-wide range around it (or around 0).
pub fn padded(lo: f64, hi: f64, pad: f64) -> (f64, f64) {
    if !(lo.is_finite() && hi.is_finite()) || hi < lo {
        return (-1.0, 1.0);
    }
    let width = hi - lo;
    if width <= f64::EPSILON * lo.abs().max(hi.abs()).max(1.0) {
        let half = if lo.abs() > 0.0 { 0.1 * lo.abs() } else { 1.0 };
        return (lo - half, hi + half);
    }
    (lo - pad * width, hi + pad * width)
}

/// `±1.12 max_abs` (±1 when `max_abs` is zero or not finite).
pub fn symmetric(max_abs: f64) -> (f64, f64) {
    if max_abs.is_finite() && max_abs > 0.0 {
        (-1.12 * max_abs, 1.12 * max_abs)
    } else {
        (-1.0, 1.0)
    }
}

/// The largest finite `|x|` (0 if none).
pub fn max_abs(values: impl IntoIterator<Item = f64>) -> f64 {
    values.into_iter().filter(|x| x.is_finite()).fold(0.0, |m, x| m.max(x.abs()))
}

/// The time axis of a run: `0 … end` (a short or empty run gets at least 1 ms).
pub fn time_range(end: f64) -> (f64, f64) {
    if end.is_finite() && end > 1e-3 {
        (0.0, end)
    } else {
        (0.0, 1e-3)
    }
}

/// A tick label: `v` with 4 significant digits, 0 for rounding noise
/// (below 1e-9 of the axis' `span`), never `-0`.
pub fn tick(v: f64, span: f64) -> String {
    if v.abs() <= 1e-9 * span.abs() {
        return "0".into();
    }
    crate::format::sig(v, 4)
}

/// A length unit for an axis.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LengthUnit {
    /// `mm` or `m`.
    pub name: &'static str,
    /// Values in metres are multiplied by this.
    pub per_metre: f64,
}

/// Millimetres below 0.1 m (and for zero), metres above.
pub fn length_unit(max_abs_m: f64) -> LengthUnit {
    if max_abs_m.is_finite() && max_abs_m >= 0.1 {
        LengthUnit { name: "m", per_metre: 1.0 }
    } else {
        LengthUnit { name: "mm", per_metre: 1000.0 }
    }
}

/// The runs of finite points of a curve: a non-finite value leaves a gap.
pub fn segments(points: impl IntoIterator<Item = (f64, f64)>) -> Vec<Vec<(f64, f64)>> {
    let mut out: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current = Vec::new();
    for (x, y) in points {
        if x.is_finite() && y.is_finite() {
            current.push((x, y));
        } else if !current.is_empty() {
            out.push(std::mem::take(&mut current));
        }
    }
    if !current.is_empty() {
        out.push(current);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_are_never_empty() {
        assert_eq!(padded(2.0, 2.0, 0.05), (1.8, 2.2));
        assert_eq!(padded(0.0, 0.0, 0.05), (-1.0, 1.0));
        assert_eq!(padded(f64::NAN, 1.0, 0.05), (-1.0, 1.0));
        assert_eq!(symmetric(0.0), (-1.0, 1.0));
        assert_eq!(time_range(0.0), (0.0, 1e-3));
        let (lo, hi) = padded(0.0, 10.0, 0.1);
        assert!((lo + 1.0).abs() < 1e-12 && (hi - 11.0).abs() < 1e-12);
    }

    #[test]
    fn tick_labels() {
        assert_eq!(tick(-5.551e-17, 0.4), "0");
        assert_eq!(tick(0.30000000000000004, 1.0), "0.3");
        assert_eq!(tick(-2.0, 8.0), "-2");
    }

    #[test]
    fn units_by_size() {
        assert_eq!(length_unit(0.0).name, "mm");
        assert_eq!(length_unit(0.05).name, "mm");
        assert_eq!(length_unit(0.3).name, "m");
        assert_eq!(length_unit(f64::NAN).name, "mm");
    }

    #[test]
    fn gaps_split_curves() {
        let s = segments([(0.0, 1.0), (1.0, f64::NAN), (2.0, 3.0), (3.0, 4.0)]);
        assert_eq!(s, vec![vec![(0.0, 1.0)], vec![(2.0, 3.0), (3.0, 4.0)]]);
        assert!(segments([(0.0, f64::INFINITY)]).is_empty());
    }
}
