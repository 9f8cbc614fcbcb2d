//! Sine and cosine for the inner loop.
//!
//! Every right-hand side evaluation needs `sin(ω t + φ)` of a harmonic input
//! and `sin, cos(α − s θ)` of the tower, and the platform `sin`/`sin_cos`
//! (about 20 ns each here, built for any argument up to 1e308) take most of the
//! run time. Arguments here are moderate (`|x| < 1e5` in any sensible run), so
//! a Cody–Waite reduction by π/2 in three parts followed by fdlibm's minimax
//! kernels on `[−π/4, π/4]` (errors below one ulp there) gives the same
//! accuracy at a third of the cost. Larger arguments fall back to the `libm`
//! crate (musl's code, the same on every target: see the workspace manifest).
//! No maintained crate offers a faster accurate scalar `sin_cos`: `libm` is a
//! port of the musl code that reduces any argument, with its cost.

// The constants are fdlibm's, written with the digits it publishes.
#![allow(clippy::excessive_precision)]

/// π/2 split for Cody–Waite reduction (fdlibm `pio2_1`, `pio2_2`, `pio2_3`):
/// the first two have 33 significant bits, so `k · PIO2_1` and `k · PIO2_2` are
/// exact for `|k| < 2²⁰`.
const PIO2_1: f64 = 1.570_796_326_734_125_614_17;
const PIO2_2: f64 = 6.077_100_506_303_965_976_6e-11;
const PIO2_3: f64 = 2.022_266_248_711_166_455_8e-21;
const TWO_OVER_PI: f64 = std::f64::consts::FRAC_2_PI;
/// `1.5 · 2⁵²`: adding and subtracting it rounds to the nearest integer without
/// a libm call (`round` is not an instruction on baseline x86-64).
const ROUNDER: f64 = 6_755_399_441_055_744.0;
/// Beyond this the three-part reduction loses accuracy.
const REDUCTION_LIMIT: f64 = 1.0e5;

/// fdlibm `__kernel_sin` on `|x| <= π/4`.
#[inline(always)]
fn kernel_sin(x: f64) -> f64 {
    const S1: f64 = -1.666_666_666_666_663_243_48e-1;
    const S2: f64 = 8.333_333_333_322_489_461_24e-3;
    const S3: f64 = -1.984_126_982_985_794_931_34e-4;
    const S4: f64 = 2.755_731_370_707_006_767_89e-6;
    const S5: f64 = -2.505_076_025_340_686_341_95e-8;
    const S6: f64 = 1.589_690_995_211_550_102_21e-10;
    // Estrin's scheme: the same polynomial with half the dependency depth of
    // Horner's (the inner loop is bound by latency, not by throughput).
    let z = x * x;
    let z2 = z * z;
    let r = (S2 + z * S3) + z2 * ((S4 + z * S5) + z2 * S6);
    x + x * z * (S1 + z * r)
}

/// fdlibm `__kernel_cos` on `|x| <= π/4`.
#[inline(always)]
fn kernel_cos(x: f64) -> f64 {
    const C1: f64 = 4.166_666_666_666_660_190_37e-2;
    const C2: f64 = -1.388_888_888_887_410_957_49e-3;
    const C3: f64 = 2.480_158_728_947_672_941_78e-5;
    const C4: f64 = -2.755_731_435_139_066_330_35e-7;
    const C5: f64 = 2.087_572_321_298_174_827_90e-9;
    const C6: f64 = -1.135_964_755_778_819_482_65e-11;
    let z = x * x;
    let z2 = z * z;
    let z4 = z2 * z2;
    let r = z * (((C1 + z * C2) + z2 * (C3 + z * C4)) + z4 * (C5 + z * C6));
    let hz = 0.5 * z;
    let w = 1.0 - hz;
    w + (((1.0 - w) - hz) + z * r)
}

/// `(sin x, cos x)`.
#[inline(always)]
pub(crate) fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() <= std::f64::consts::FRAC_PI_4 {
        return (kernel_sin(x), kernel_cos(x));
    }
    if x.abs() >= REDUCTION_LIMIT || x.is_nan() {
        return (libm::sin(x), libm::cos(x));
    }
    let k = (x * TWO_OVER_PI + ROUNDER) - ROUNDER;
    let r = ((x - k * PIO2_1) - k * PIO2_2) - k * PIO2_3;
    let (s, c) = (kernel_sin(r), kernel_cos(r));
    // Quadrant k mod 4.
    match (k as i64) & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// `sin x`.
#[inline(always)]
pub(crate) fn sin(x: f64) -> f64 {
    if x.abs() <= std::f64::consts::FRAC_PI_4 {
        return kernel_sin(x);
    }
    if x.abs() >= REDUCTION_LIMIT || x.is_nan() {
        return libm::sin(x);
    }
    let k = (x * TWO_OVER_PI + ROUNDER) - ROUNDER;
    let r = ((x - k * PIO2_1) - k * PIO2_2) - k * PIO2_3;
    match (k as i64) & 3 {
        0 => kernel_sin(r),
        1 => kernel_cos(r),
        2 => -kernel_sin(r),
        _ => -kernel_cos(r),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Against the platform's correctly rounded-in-practice `sin_cos`, on a
    /// dense sweep of the range the engine uses: within 2e-16 absolute (about
    /// one ulp of a value of order 1), which is 8 orders of magnitude below any
    /// integration tolerance.
    #[test]
    fn matches_the_platform_to_an_ulp() {
        let mut worst: f64 = 0.0;
        let mut x = -3000.0;
        while x < 3000.0 {
            let (s, c) = sin_cos(x);
            let (se, ce) = x.sin_cos();
            worst = worst.max((s - se).abs()).max((c - ce).abs()).max((sin(x) - se).abs());
            x += 0.000_731;
        }
        assert!(worst <= 2.3e-16, "worst error {worst:e}");
    }

    #[test]
    fn exact_at_special_points_and_falls_back_outside_the_range() {
        assert_eq!(sin_cos(0.0), (0.0, 1.0));
        let big = 1.0e9 + 0.3;
        // The fallback reduces 1e9 exactly: the platform's value to an ulp.
        let ((s, c), (se, ce)) = (sin_cos(big), big.sin_cos());
        assert!((s - se).abs() <= f64::EPSILON && (c - ce).abs() <= f64::EPSILON, "{s} {c} against {se} {ce}");
        assert!(sin(f64::NAN).is_nan());
    }

    /// Near a harmonic input's crest `sin` is exactly ±1, as the true sine
    /// rounds there: within 1e-8 of `(k + ½) π` it differs from ±1 by less
    /// than `(1e-8)²/2 = 5e-17`, under half an ulp of 1. An amplitude given
    /// at a threshold (`amplitude = g tan α`) then meets it the same way on
    /// every run. (A reduction by π with one wider sine kernel, tried once,
    /// returned 1 − 2⁻⁵³ for a third of the arguments within 2e-8 of the
    /// first crest, and a tower whose uplift threshold the crest reaches
    /// stood instead of lifting off.)
    #[test]
    fn the_crests_of_a_sine_are_exact() {
        for k in -1000i32..1000 {
            let crest = if k.rem_euclid(2) == 0 { 1.0 } else { -1.0 };
            for offset in [-1e-8, -3.3e-9, -1e-12, 0.0, 1e-12, 3.3e-9, 1e-8] {
                let x = (f64::from(k) + 0.5) * std::f64::consts::PI + offset;
                assert_eq!(sin(x).to_bits(), f64::to_bits(crest), "sin at k = {k}, offset {offset:e}");
                assert_eq!(sin_cos(x).0.to_bits(), f64::to_bits(crest), "sin_cos at k = {k}, offset {offset:e}");
            }
        }
        // ω t at a quarter period of 1 Hz, as the right-hand side forms it.
        assert_eq!(sin(2.0 * std::f64::consts::PI * 1.0 * 0.25).to_bits(), 1f64.to_bits());
    }
}
