//! The floor spectrum of a mechanism above ground: the acceleration spectrum
//! of the level a tower (or a belfry) stands on, from the modes of the
//! structure under it (the church, the shaft).
//!
//! Circolare 21 gennaio 2019 n. 7, §C7.2.3, eqs. [C7.2.5]–[C7.2.8] (to which
//! §C8.7.1.2.1.4–8 refer; they supersede the 2009 Circolare's
//! `S_e(T1) ψ(Z) γ`), the mode shapes normalised to 1 where the tower stands,
//! so that `γ_k ψ_k(z) = Γ_k`:
//!
//! ```text
//! [C7.2.7]  a_Z,k = S_e(T_k, ξ_k) |Γ_k| sqrt(1 + 0.0004 ξ_k²)          ξ_k in percent
//! [C7.2.8]  a_Z = sqrt(Σ_k a_Z,k²)
//! [C7.2.6]  S_eZ,k(T) = A_k a_Z,k / (1 + (A_k − 1)(1 − T/(a T_k))^1.6)  T < a T_k
//!                     = A_k a_Z,k                                     a T_k ≤ T < b T_k
//!                     = A_k a_Z,k / (1 + (A_k − 1)(T/(b T_k) − 1)^1.2)  T ≥ b T_k
//!           A_k = 1.1 ξ_k^(−1/2) η(ξ), a = 0.8, b = 1.1
//! [C7.2.5]  S_eZ(T) = sqrt(Σ_k S_eZ,k(T)²), not less than S_e(T) for T > T_1
//! ```
//!
//! In [C7.2.6] `ξ_k` is read as a fraction of critical (0.05): read in
//! percent, `A_k` would be 0.49 at 5% and the plateau would fall below the
//! floor's own peak acceleration, against the text's purpose, its Table
//! C7.2.II (`a_p = 5` at 5%) and the formulation's source (Degli Abbati,
//! Cattari, Lagomarsino, Earthquake Spectra 2018). `η(ξ)` is the damping
//! correction of the mechanism's damping ξ (percent), as in the ground's spectra.
//!
//! EN 1998-1 §4.3.5.2, eq. (4.25), for an element of period `T_a` at height
//! `z` of a structure of height `H` and first period `T_1`:
//! `S_a = α S [3 (1 + z/H) / (1 + (1 − T_a/T_1)²) − 0.5]`, not less than `α S`.
//!
//! Units: periods in s, accelerations in g (or any one unit, the same in and out).

use crate::elastic::damping_correction;

/// The ratio `a` of [C7.2.6]: the plateau of mode `k` starts at `a T_k`.
pub const FLOOR_PLATEAU_START: f64 = 0.8;
/// The ratio `b` of [C7.2.6]: the plateau of mode `k` ends at `b T_k`.
pub const FLOOR_PLATEAU_END: f64 = 1.1;

/// [C7.2.7] of the Circolare 2019: mode `k`'s peak floor acceleration
/// `a_Z,k = S_e(T_k, ξ_k) |Γ_k| sqrt(1 + 0.0004 ξ_k²)`, from the ground's
/// spectrum at the mode's period and damping `se_at_mode` (g), its
/// participation `Γ_k` (the shape 1 where the tower stands) and its damping
/// `ξ_k` in percent of critical.
pub fn modal_floor_acceleration(se_at_mode: f64, participation: f64, damping_pct: f64) -> f64 {
    se_at_mode * participation.abs() * (1.0 + 0.0004 * damping_pct * damping_pct).sqrt()
}

/// [C7.2.8] of the Circolare 2019: the peak floor acceleration
/// `a_Z = sqrt(Σ_k a_Z,k²)` of the modes' [`modal_floor_acceleration`]s.
pub fn floor_acceleration(modal: &[f64]) -> f64 {
    modal.iter().map(|a| a * a).sum::<f64>().sqrt()
}

/// The amplification `A_k = 1.1 ξ_k^(−1/2) η(ξ)` of [C7.2.6]: `ξ_k` the mode's
/// damping as a fraction of critical (> 0; see the module's note), `ξ` the
/// mechanism's damping in percent (η as in the ground's spectra).
pub fn floor_amplification(mode_damping: f64, damping_pct: f64) -> f64 {
    1.1 / mode_damping.sqrt() * damping_correction(damping_pct)
}

/// [C7.2.6] of the Circolare 2019: mode `k`'s floor spectrum `S_eZ,k(T, ξ)`
/// (the unit of `modal_acceleration`, its [`modal_floor_acceleration`]) at the
/// period `T` (s), for the mode's period `T_k` (s) and damping `ξ_k` (a
/// fraction, > 0) and the mechanism's damping ξ (percent).
pub fn modal_floor_spectrum(period: f64, mode_period: f64, mode_damping: f64, modal_acceleration: f64, damping_pct: f64) -> f64 {
    let a = floor_amplification(mode_damping, damping_pct);
    let plateau = a * modal_acceleration;
    let start = FLOOR_PLATEAU_START * mode_period;
    let end = FLOOR_PLATEAU_END * mode_period;
    if period < start {
        plateau / (1.0 + (a - 1.0) * libm::pow(1.0 - period / start, 1.6))
    } else if period < end {
        plateau
    } else {
        plateau / (1.0 + (a - 1.0) * libm::pow(period / end - 1.0, 1.2))
    }
}

/// [C7.2.5] of the Circolare 2019: the floor spectrum `S_eZ(T, ξ) =
/// sqrt(Σ_k S_eZ,k(T, ξ)²)` of the modes' [`modal_floor_spectrum`]s at `T`,
/// and not less than the ground's `ground` = `S_e(T, ξ)` when `T` is beyond
/// the support's first period `first_period` (s).
pub fn floor_spectrum(modal: &[f64], ground: f64, period: f64, first_period: f64) -> f64 {
    let combined = floor_acceleration(modal);
    if period > first_period {
        combined.max(ground)
    } else {
        combined
    }
}

/// EN 1998-1 §4.3.5.2, eq. (4.25): the spectral acceleration (in the unit of
/// `alpha_s`) of an element of period `T_a` (s) at the relative height
/// `z/H` = `height_ratio` of a structure of first period `T_1` (s),
/// `α S [3 (1 + z/H) / (1 + (1 − T_a/T_1)²) − 0.5]`, not less than `α S`;
/// `alpha_s` is `α S`, `α = a_g/g` the design ground acceleration's ratio and
/// `S` the soil factor.
pub fn ec8_floor_spectrum(period: f64, first_period: f64, alpha_s: f64, height_ratio: f64) -> f64 {
    let r = 1.0 - period / first_period;
    (alpha_s * (3.0 * (1.0 + height_ratio) / (1.0 + r * r) - 0.5)).max(alpha_s)
}
