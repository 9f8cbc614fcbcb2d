//! The floor spectra ([C7.2.5]–[C7.2.8] of the Circolare 2019, EN 1998-1
//! eq. (4.25)) against values worked out by hand from the equations.
//!
//! The site: NTC 2018, `a_g = 0.25 g`, `F0 = 2.4`, `Tc* = 0.30 s`, soil B,
//! flat ground; a support of one mode, `T_1 = 0.6409 s`, `ξ_1 = 5%`, `Γ = 1.2`.
//!
//! ```text
//! SS = 1.40 − 0.40·2.4·0.25 = 1.16;  CC = 1.10·0.30^−0.2 = 1.39949;  TC = 0.41985 s
//! S_e(T_1) = 0.25·1.16·2.4·0.41985 / 0.6409 = 0.45594 g           (TC ≤ T_1 < TD = 2.6 s)
//! a_Z = 0.45594 · 1.2 · sqrt(1 + 0.0004·25) = 0.54986 g             [C7.2.7], [C7.2.8]
//! A = 1.1 / sqrt(0.05) · η(5%) = 4.91935;  plateau A a_Z = 2.7049 g [C7.2.6]
//! ```
//!
//! The values are given to four decimals: the tolerance, 2e-4 g, is that
//! rounding carried through the plateau (4.919 × 0.5498 = 2.7046).

use approx::assert_abs_diff_eq;
use rocking_codes::{
    ec8_floor_spectrum, floor_acceleration, floor_amplification, floor_spectrum, modal_floor_acceleration, modal_floor_spectrum, NtcSite, NtcSpectrum, Soil,
    Topography,
};

const T1: f64 = 0.6409;
const DAMPING: f64 = 0.05;
const GAMMA: f64 = 1.2;
const ROUNDING: f64 = 2e-4;

fn ground() -> NtcSpectrum {
    let site = NtcSite::new(0.25, 2.4, 0.30).unwrap_or_else(|e| panic!("{e}"));
    NtcSpectrum::new(site, Soil::B, Topography::T1, 5.0).unwrap_or_else(|e| panic!("{e}"))
}

fn modal_acceleration() -> f64 {
    modal_floor_acceleration(ground().se(T1), GAMMA, DAMPING * 100.0)
}

#[test]
fn peak_floor_acceleration_c7_2_7_and_c7_2_8() {
    // a_Z = S_e(T_1) |Γ| sqrt(1 + 0.0004 ξ²) = 0.45594 · 1.2 · 1.004988 = 0.5498 g.
    assert_abs_diff_eq!(ground().se(T1), 0.4559, epsilon = ROUNDING);
    assert_abs_diff_eq!(modal_acceleration(), 0.5498, epsilon = ROUNDING);
    // One mode: [C7.2.8] is the mode's own; a negative Γ gives the same.
    assert_abs_diff_eq!(floor_acceleration(&[modal_acceleration()]), 0.5498, epsilon = ROUNDING);
    assert_abs_diff_eq!(modal_floor_acceleration(ground().se(T1), -GAMMA, 5.0), modal_acceleration(), epsilon = 1e-15);
    // Two modes of 0.3 g and 0.4 g combine as 3-4-5: 0.5 g (to the last bits).
    assert_abs_diff_eq!(floor_acceleration(&[0.3, 0.4]), 0.5, epsilon = 1e-15);
}

#[test]
fn floor_spectrum_c7_2_5_and_c7_2_6() {
    let a_z = modal_acceleration();
    // A = 1.1 / sqrt(0.05) · 1 = 4.91935 (ξ as a fraction; in percent it would be 0.49).
    assert_abs_diff_eq!(floor_amplification(DAMPING, 5.0), 4.91935, epsilon = 1e-5);
    let at = |t: f64| floor_spectrum(&[modal_floor_spectrum(t, T1, DAMPING, a_z, 5.0)], ground().se(t), t, T1);
    // T = 0: the first branch at T = 0 is A a_Z / (1 + (A − 1)) = a_Z.
    assert_abs_diff_eq!(at(0.0), 0.5498, epsilon = ROUNDING);
    // T = 0.6 s in [0.8 T_1, 1.1 T_1) = [0.5127, 0.7050): the plateau A a_Z.
    assert_abs_diff_eq!(at(0.6), 2.7048, epsilon = ROUNDING);
    // T = 1.282 s = 2 T_1: (2/1.1 − 1)^1.2 = 0.78626, 2.7049 / (1 + 3.91935·0.78626) = 0.6627 g
    // (above the ground's 0.2279 g, so the bound of [C7.2.5] does not act).
    assert_abs_diff_eq!(at(1.282), 0.6627, epsilon = ROUNDING);
    // T = 1.923 s = 3 T_1: (3/1.1 − 1)^1.2 = 1.92734, 2.7049 / (1 + 3.91935·1.92734) = 0.3162 g.
    assert_abs_diff_eq!(at(1.923), 0.3162, epsilon = ROUNDING);
    // The bound of [C7.2.5]: beyond T_1 a floor spectrum under the ground's is raised to it.
    assert_abs_diff_eq!(floor_spectrum(&[0.1], 0.3, 1.0, T1), 0.3, epsilon = 1e-15);
    assert_abs_diff_eq!(floor_spectrum(&[0.1], 0.3, 0.5, T1), 0.1, epsilon = 1e-15);
}

#[test]
fn ec8_floor_spectrum_4_25() {
    // α S = 0.29, z/H = 0.8: S_a = 0.29 [3·1.8 / (1 + (1 − T_a/T_1)²) − 0.5].
    // T_a = 0:        0.29 (5.4/2 − 0.5)                      = 0.6380 g
    // T_a = 0.2:      r = 0.68794, 0.29 (5.4/1.47326 − 0.5)     = 0.9179 g
    // T_a = 0.3205:   r = 0.49992, 0.29 (5.4/1.24992 − 0.5)     = 1.1079 g
    // T_a = T_1:      0.29 (5.4 − 0.5)                         = 1.4210 g
    for (ta, expected) in [(0.0, 0.6380), (0.2, 0.9179), (0.3205, 1.1079), (T1, 1.4210)] {
        assert_abs_diff_eq!(ec8_floor_spectrum(ta, T1, 0.29, 0.8), expected, epsilon = ROUNDING);
    }
    // At the top (z/H = 1), T_a = 0: 2.5 α S; far beyond T_1 the bound α S.
    assert_abs_diff_eq!(ec8_floor_spectrum(0.0, T1, 0.29, 1.0), 2.5 * 0.29, epsilon = 1e-15);
    assert_abs_diff_eq!(ec8_floor_spectrum(100.0, T1, 0.29, 1.0), 0.29, epsilon = 1e-15);
}
