//! The kinematic checks of a mechanism above ground: the tower standing on an
//! elastic support (the church), a belfry on its shaft. The Circolare 2019
//! (§C8.7.1.2.1.4–8) checks them against the floor spectrum of the level they
//! stand on, eqs. [C7.2.5]–[C7.2.8] of §C7.2.3 (rocking-codes' `floor`); with
//! `code = "ec8"`, EN 1998-1 §4.3.5.2 eq. (4.25) at the support's top
//! (`z/H = 1`). Every mechanism of a stack stands on the support's top or
//! above it, through the tower, which is rigid and seated until it activates.
//!
//! ```text
//! activation (damage state):   a_Z(a_g) ≥ a0*  activates          [C8.7.1.8] with [C7.2.8]   (EC8: S_a(0) = 2.5 α S)
//! linear kinematic (SLV):      a_g,capacity = q · a_g,capacity(activation)                 §C8.7.1.2.1.7
//! non-linear kinematic:        d = S_eZ(T_LS, ξ) T_LS²/(4π²), not less than
//!                              S_eZ(T_1, ξ) b² T_1²/(4π²) when T_LS > b T_1 ;  d > d_LS fails   [C8.7.1.12]
//!                              (EC8: S_a(T_LS) g T_LS²/(4π²))
//! ```
//!
//! The support's periods and dampings are those of each limit state
//! (`[assessment.support.SLV]`: its `period_factor` and `damping`); the
//! damage state's are the support's own.

use crate::capacity::Capacity;
use crate::check::{Check, Level, Method, Unit};
use crate::error::{invalid, Error};
use crate::kinematic::{check_q, linear_kinematic_capacity, soil_factor, NONLINEAR_DAMPING_COLLAPSE_PCT, NONLINEAR_DAMPING_LIFE_SAFETY_PCT};
use crate::search::{least_failing_ag, AgCapacity, AG_SEARCH_TOP};
use crate::site::{Role, Site};
use rocking_codes::{ec8_floor_spectrum, floor_acceleration, floor_spectrum, modal_floor_acceleration, modal_floor_spectrum, CodeSpectrum, FLOOR_PLATEAU_END};
use rocking_scenario::SupportMode;
use std::f64::consts::PI;

/// The relative height `z/H` at which a mechanism stands in EN 1998-1's eq.
/// (4.25): the support's top.
pub const EC8_HEIGHT_RATIO: f64 = 1.0;

/// The support's modes at each limit state: the damage, life-safety and
/// collapse states' (each mode's period and damping of that state).
#[derive(Debug, Clone, PartialEq)]
pub struct SupportModes {
    modes: [Vec<SupportMode>; 3],
}

impl SupportModes {
    /// From the modes of the damage, life-safety and collapse states, each
    /// with at least one mode of positive period and damping.
    pub fn new(damage: Vec<SupportMode>, life_safety: Vec<SupportMode>, collapse: Vec<SupportMode>) -> Result<Self, Error> {
        let modes = [damage, life_safety, collapse];
        for m in modes.iter().flatten() {
            if !(m.period > 0.0 && m.period.is_finite() && m.damping > 0.0 && m.damping < 1.0 && m.participation.is_finite()) {
                return Err(invalid(
                    "support",
                    format!("a mode of period {} s and damping {} cannot give a floor spectrum", m.period, m.damping),
                ));
            }
        }
        if modes.iter().any(Vec::is_empty) {
            return Err(invalid("support", "a support has at least one mode at every limit state"));
        }
        Ok(Self { modes })
    }

    /// The modes of a role's limit state.
    pub fn of(&self, role: Role) -> &[SupportMode] {
        &self.modes[role as usize]
    }
}

/// The first period `T_1` (s) of a support's modes: the longest.
pub fn first_period(modes: &[SupportMode]) -> f64 {
    modes.iter().map(|m| m.period).fold(0.0, f64::max)
}

/// The peak floor acceleration `a_Z` (g) of the support's top for the ground's
/// spectrum `spectrum` (its `a_g`, soil and topography): NTC, [C7.2.7] for
/// each mode (the ground's spectrum at the mode's period and damping) and
/// [C7.2.8] of the Circolare 2019; EN 1998-1, eq. (4.25) at `T_a = 0`,
/// `2.5 α S` at the top.
pub fn peak_floor_acceleration(spectrum: &CodeSpectrum, modes: &[SupportMode]) -> Result<f64, Error> {
    match spectrum {
        CodeSpectrum::Ntc(_) => Ok(floor_acceleration(&modal_accelerations(spectrum, modes)?)),
        CodeSpectrum::Ec8(_) => Ok(ec8_floor_spectrum(
            0.0,
            first_period(modes),
            spectrum.ag() * soil_factor(spectrum),
            EC8_HEIGHT_RATIO,
        )),
    }
}

/// Each mode's peak floor acceleration `a_Z,k` (g), [C7.2.7].
fn modal_accelerations(spectrum: &CodeSpectrum, modes: &[SupportMode]) -> Result<Vec<f64>, Error> {
    modes
        .iter()
        .map(|m| {
            let pct = m.damping * 100.0;
            let se = spectrum.with_damping(pct)?.se(m.period);
            Ok(modal_floor_acceleration(se, m.participation, pct))
        })
        .collect()
}

/// The floor spectrum (g) of the support's top at the period `period` (s)
/// and the mechanism's damping `damping_pct` (%): NTC, [C7.2.6] of each mode
/// combined by [C7.2.5] (not less than the ground's `S_e(T, ξ)` beyond the
/// support's first period); EN 1998-1, eq. (4.25) at the top (no damping in it).
pub fn floor_spectrum_at(spectrum: &CodeSpectrum, modes: &[SupportMode], period: f64, damping_pct: f64) -> Result<f64, Error> {
    let t1 = first_period(modes);
    match spectrum {
        CodeSpectrum::Ntc(_) => {
            let modal: Vec<f64> = modal_accelerations(spectrum, modes)?
                .into_iter()
                .zip(modes)
                .map(|(a, m)| modal_floor_spectrum(period, m.period, m.damping, a, damping_pct))
                .collect();
            let ground = spectrum.with_damping(damping_pct)?.se(period);
            Ok(floor_spectrum(&modal, ground, period, t1))
        }
        CodeSpectrum::Ec8(_) => Ok(ec8_floor_spectrum(period, t1, spectrum.ag() * soil_factor(spectrum), EC8_HEIGHT_RATIO)),
    }
}

/// The demand (m) of the non-linear kinematic check at height, [C8.7.1.12]
/// of the Circolare 2019: `S_eZ(T_LS, ξ) T_LS² / (4π²)`, and not less than
/// `S_eZ(T_1, ξ) b² T_1² / (4π²)` when `T_LS > b T_1` (beyond the plateau of
/// the first mode the floor spectrum falls faster than `T²` rises); EN
/// 1998-1: `S_a(T_LS) g T_LS² / (4π²)`. `g` in m/s², ξ in %.
pub fn floor_displacement_demand(spectrum: &CodeSpectrum, modes: &[SupportMode], t_ls: f64, damping_pct: f64, g: f64) -> Result<f64, Error> {
    let to_displacement = |sa: f64, t: f64| sa * g * t * t / (4.0 * PI * PI);
    let at_secant = to_displacement(floor_spectrum_at(spectrum, modes, t_ls, damping_pct)?, t_ls);
    match spectrum {
        CodeSpectrum::Ntc(_) => {
            let t1 = first_period(modes);
            let end = FLOOR_PLATEAU_END * t1;
            if t_ls > end {
                let plateau = floor_spectrum_at(spectrum, modes, t1, damping_pct)?;
                Ok(at_secant.max(to_displacement(plateau, end)))
            } else {
                Ok(at_secant)
            }
        }
        CodeSpectrum::Ec8(_) => Ok(at_secant),
    }
}

/// The activation check at height: `a_g,capacity` the least `a_g` with
/// `a_Z(a_g) g ≥ a0*` ([C8.7.1.8] with [C7.2.8]), the damage state's F0,
/// Tc*, soil and topography kept; demand `a_Z g` (m/s²) at its `a_g`.
pub fn activation_check_at_height(capacity: &Capacity, site: &Site, support: &SupportModes) -> Result<Check, Error> {
    let spectrum = site.spectrum(Role::Damage);
    let modes = support.of(Role::Damage);
    let g = capacity.g;
    let ag_capacity = least_failing_ag(AG_SEARCH_TOP, |ag| {
        Ok(peak_floor_acceleration(&spectrum.with_ag(ag)?, modes)? * g - capacity.a0_star)
    })?;
    let a_z = peak_floor_acceleration(&spectrum, modes)?;
    Ok(Check::new(
        site.limit_state(Role::Damage),
        Method::Activation,
        Unit::Acceleration,
        a_z * g,
        capacity.a0_star,
        spectrum.ag(),
        ag_capacity,
    )
    .at(Level::Support, Some(a_z)))
}

/// The linear kinematic check at height: `q` times the activation's
/// `a_g,capacity` at height (§C8.7.1.2.1.7, as at ground level), against the
/// life-safety state's `a_g`; its `a_Z` that of the life-safety state.
pub fn linear_kinematic_check_at_height(site: &Site, support: &SupportModes, q: f64, activation: AgCapacity) -> Result<Check, Error> {
    let q = check_q(q)?;
    let spectrum = site.spectrum(Role::LifeSafety);
    let ag = spectrum.ag();
    let ag_capacity = linear_kinematic_capacity(activation, q);
    let a_z = peak_floor_acceleration(&spectrum, support.of(Role::LifeSafety))?;
    Ok(Check::new(
        site.limit_state(Role::LifeSafety),
        Method::LinearKinematic,
        Unit::GroundAcceleration,
        ag,
        ag_capacity.value(),
        ag,
        ag_capacity,
    )
    .at(Level::Support, Some(a_z)))
}

/// The non-linear kinematic check at height of the life-safety or collapse
/// state: `a_g,capacity` the least `a_g` at which [`floor_displacement_demand`]
/// at `T_LS` and ξ = 8% (life safety) or 10% (collapse) exceeds `d_LS`, and not
/// less than the activation's.
pub fn nonlinear_kinematic_check_at_height(
    capacity: &Capacity,
    site: &Site,
    support: &SupportModes,
    role: Role,
    activation: AgCapacity,
) -> Result<Check, Error> {
    let (damping, d_ls, t_ls) = match role {
        Role::LifeSafety => (NONLINEAR_DAMPING_LIFE_SAFETY_PCT, capacity.d_slv, capacity.t_slv),
        Role::Collapse => (NONLINEAR_DAMPING_COLLAPSE_PCT, capacity.d_slc, capacity.t_slc),
        Role::Damage => {
            return Err(invalid(
                "limit_state",
                "the non-linear kinematic check is of the life-safety and collapse states",
            ))
        }
    };
    let spectrum = site.spectrum(role);
    let modes = support.of(role);
    let g = capacity.g;
    let found = least_failing_ag(AG_SEARCH_TOP, |ag| {
        Ok(floor_displacement_demand(&spectrum.with_ag(ag)?, modes, t_ls, damping, g)? - d_ls)
    })?;
    let ag_capacity = match (found, activation) {
        (AgCapacity::At(a), AgCapacity::At(b)) => AgCapacity::At(a.max(b)),
        (AgCapacity::At(a), AgCapacity::AtLeast(b)) if a < b => AgCapacity::AtLeast(b),
        (AgCapacity::At(a), AgCapacity::AtLeast(_)) => AgCapacity::At(a),
        (AgCapacity::AtLeast(a), _) => AgCapacity::AtLeast(a.max(activation.value())),
    };
    Ok(Check::new(
        site.limit_state(role),
        Method::NonlinearKinematic,
        Unit::Displacement,
        floor_displacement_demand(&spectrum, modes, t_ls, damping, g)?,
        d_ls,
        spectrum.ag(),
        ag_capacity,
    )
    .at(Level::Support, Some(peak_floor_acceleration(&spectrum, modes)?)))
}

/// The four kinematic checks at height, in order: activation (damage state),
/// linear kinematic (life safety), non-linear kinematic (life safety, collapse).
pub fn kinematic_checks_at_height(capacity: &Capacity, site: &Site, support: &SupportModes, q: f64) -> Result<Vec<Check>, Error> {
    let activation = activation_check_at_height(capacity, site, support)?;
    Ok(vec![
        activation,
        linear_kinematic_check_at_height(site, support, q, activation.ag_capacity)?,
        nonlinear_kinematic_check_at_height(capacity, site, support, Role::LifeSafety, activation.ag_capacity)?,
        nonlinear_kinematic_check_at_height(capacity, site, support, Role::Collapse, activation.ag_capacity)?,
    ])
}

/// The absolute horizontal acceleration of the support's top (in the
/// record's units) under the ground acceleration `record`, the support alone
/// and linear (without the tower): each mode a linear oscillator of its
/// period and damping from rest, `ÿ_k + 2 ζ_k ω_k ẏ_k + ω_k² y_k = −a_g`
/// (Nigam & Jennings' exact steps for the piecewise-linear record), and the
/// top's `a_g + Σ_k Γ_k ÿ_k` (every shape 1 there) at each sample, then over a
/// free tail of two first periods (the ground still) at the record's spacing.
/// The result is a record through those samples (linear between them: a
/// step's error in the top's acceleration is of order `(ω_k dt)²`).
pub fn support_top_motion(record: &rocking::Record, modes: &[SupportMode]) -> Result<rocking::Record, Error> {
    let (times, values) = (record.times(), record.values());
    let n = times.len();
    let spacing = if n > 1 { (times[n - 1] - times[0]) / (n - 1) as f64 } else { 0.01 };
    let tail = (2.0 * first_period(modes) / spacing).ceil() as usize;
    let mut all_times = times.to_vec();
    all_times.extend((1..=tail).map(|k| times[n - 1] + k as f64 * spacing));
    let ground = |k: usize| if k < n { values[k] } else { 0.0 };
    let mut top: Vec<f64> = (0..all_times.len()).map(ground).collect();
    for m in modes {
        let omega = 2.0 * PI / m.period;
        let (mut x, mut v) = (0.0, 0.0);
        let relative = |a_g: f64, x: f64, v: f64| -a_g - 2.0 * m.damping * omega * v - omega * omega * x;
        top[0] += m.participation * relative(ground(0), x, v);
        for k in 1..all_times.len() {
            let map = rocking_codes::NigamJennings::new(omega, m.damping, all_times[k] - all_times[k - 1]);
            (x, v) = map.step(x, v, ground(k - 1), ground(k));
            top[k] += m.participation * relative(ground(k), x, v);
        }
    }
    rocking::Record::from_samples(all_times, top).map_err(|e| invalid("support", e.to_string()))
}
