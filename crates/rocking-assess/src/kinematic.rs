//! The kinematic checks of a local mechanism (Circolare 21 gennaio 2019 n. 7,
//! §C8.7.1.2.1.6–C8.7.1.2.1.8, the mechanism at ground level; NTC 2018 §3.2.3
//! for the spectra):
//!
//! ```text
//! activation (damage state):        ag S ≥ a0*                    fails
//! linear kinematic (life safety):   a_g,capacity = q · a_g,capacity(activation)
//! non-linear kinematic (LS, C):     max_{T ≤ T_LS} SDe(T; ξ) > d_LS  fails, ξ = 8% (SLV), 10% (SLC)
//! ```
//!
//! Each gives the least `ag` at which it stops holding, every other site
//! parameter of the limit state kept and `S`, `TD` moved with `ag`
//! ([`least_failing_ag`]).

use crate::capacity::Capacity;
use crate::check::{Check, Method, Unit};
use crate::error::{invalid, Error};
use crate::search::{least_failing_ag, AgCapacity, AG_SEARCH_TOP};
use crate::site::{Role, Site};
use rocking_codes::{displacement_corner_te, CodeSpectrum};

/// The behaviour factor q of the linear kinematic check when none is given,
/// 2 (Circolare 2019 §C8.7.1.2.1.7): the assessment file's default.
pub use rocking_scenario::DEFAULT_Q;

/// The damping (% of critical) of the collapse displacement spectrum (10%).
pub use rocking_scenario::KINEMATIC_DAMPING_COLLAPSE_PCT as NONLINEAR_DAMPING_COLLAPSE_PCT;
/// The damping (% of critical) of the life-safety displacement spectrum in the
/// non-linear kinematic check, 8%: rocking-scenario's, which its
/// `kinematic_damping_pct` gives the spectra of `rocking spectrum` too.
pub use rocking_scenario::KINEMATIC_DAMPING_LIFE_SAFETY_PCT as NONLINEAR_DAMPING_LIFE_SAFETY_PCT;

/// The soil factor `S` of a spectrum: NTC's `SS ST`, EN 1998-1's `S`.
pub fn soil_factor(spectrum: &CodeSpectrum) -> f64 {
    match spectrum {
        CodeSpectrum::Ntc(s) => s.s(),
        CodeSpectrum::Ec8(s) => s.parameters().s,
    }
}

/// The corner periods `TB`, `TC`, `TD`, `TE` (s) of a spectrum.
pub fn corner_periods(spectrum: &CodeSpectrum) -> [f64; 4] {
    match spectrum {
        CodeSpectrum::Ntc(s) => [s.tb(), s.tc(), s.td(), displacement_corner_te(s.soil())],
        CodeSpectrum::Ec8(s) => {
            let p = s.parameters();
            [p.tb, p.tc, p.td, displacement_corner_te(s.soil())]
        }
    }
}

/// The demand of the activation check, the ground acceleration `ag S` (m/s²)
/// of the spectrum (Circolare 2019 eq. C8.7.1.8, the mechanism at ground
/// level), `g` in m/s².
pub fn activation_demand(spectrum: &CodeSpectrum, g: f64) -> f64 {
    spectrum.ag() * soil_factor(spectrum) * g
}

/// The spectral demand `ag S / q` (m/s²) of the linear kinematic check
/// (§C8.7.1.2.1.7, the mechanism at ground level) as the 2009 Circolare wrote
/// it, to be set against a0* (the 2019 text's eq. C8.7.1.9 is the check of
/// elements free to vibrate, which this tool does not use).
/// The linear kinematic check's capacity is [`linear_kinematic_capacity`];
/// this demand, with the life-safety spectrum's own `S`, is reported beside it.
pub fn linear_kinematic_demand(spectrum: &CodeSpectrum, q: f64, g: f64) -> f64 {
    activation_demand(spectrum, g) / q
}

/// The capacity of the linear kinematic check (Circolare 2019 §C8.7.1.2.1.7):
/// `a_g,capacity = q · a_g,capacity(activation)` (g), the behaviour factor
/// times the least `ag` of the damage state at which the mechanism activates;
/// a lower bound when the activation's is.
pub fn linear_kinematic_capacity(activation: AgCapacity, q: f64) -> AgCapacity {
    match activation {
        AgCapacity::At(ag) => AgCapacity::At(q * ag),
        AgCapacity::AtLeast(ag) => AgCapacity::AtLeast(q * ag),
    }
}

/// The demand of the non-linear kinematic check: the displacement spectrum
/// made non-decreasing, `max over T ≤ T_LS of SDe(T)` (m) (Circolare 2019
/// §C8.7.1.2.1.8, eq. C8.7.1.12), for the spectrum at the check's damping.
///
/// Each branch of `SDe` is monotone in T but for the first (`T < TB`), whose
/// `T² (1 + k T/TB)` turns at `T = −2 TB / (3k)` when `k = η F0 − 1 < 0`; the
/// maximum is at `T_LS`, a corner period below it or that turning point. The
/// spectrum jumps at `TE` (up when `TD > TE / (0.025·4π²)`, `ag` above 0.87 g),
/// so the value just past `TE` is a candidate too when `T_LS > TE`.
pub fn displacement_demand(spectrum: &CodeSpectrum, t_ls: f64, g: f64) -> f64 {
    let [tb, _, _, te] = corner_periods(spectrum);
    let amplification = match spectrum {
        CodeSpectrum::Ntc(s) => s.site().f0 * s.eta(),
        CodeSpectrum::Ec8(s) => rocking_codes::EC8_AMPLIFICATION * s.eta(),
    };
    let k = amplification - 1.0;
    let turning = if k < 0.0 { -2.0 * tb / (3.0 * k) } else { 0.0 };
    corner_periods(spectrum)
        .into_iter()
        .chain([turning, te.next_up(), t_ls])
        .filter(|&t| t <= t_ls)
        .map(|t| spectrum.sde(t, g))
        .fold(0.0, f64::max)
}

/// Checks a behaviour factor: finite and > 0.
pub fn check_q(q: f64) -> Result<f64, Error> {
    if q.is_finite() && q > 0.0 {
        Ok(q)
    } else {
        Err(invalid(
            "q",
            format!("must be a finite number > 0 (the behaviour factor, 2 by default), got {q}"),
        ))
    }
}

/// The activation check of the damage limit state: `a_g,capacity` the least
/// `ag` with `ag S(ag) ≥ a0*`, the state's F0, Tc*, soil and topography kept.
pub fn activation_check(capacity: &Capacity, site: &Site) -> Result<Check, Error> {
    let spectrum = site.spectrum(Role::Damage);
    let g = capacity.g;
    let ag_capacity = least_failing_ag(AG_SEARCH_TOP, |ag| Ok(activation_demand(&spectrum.with_ag(ag)?, g) - capacity.a0_star))?;
    Ok(Check::new(
        site.limit_state(Role::Damage),
        Method::Activation,
        Unit::Acceleration,
        activation_demand(&spectrum, g),
        capacity.a0_star,
        spectrum.ag(),
        ag_capacity,
    ))
}

/// The linear kinematic check of the life-safety state: its capacity
/// [`linear_kinematic_capacity`], `q` times the activation's `activation`,
/// against the life-safety state's `ag`, both in g (demand `ag`, capacity
/// `q · a_g,capacity(activation)`: the check holds when ζ_E ≥ 1).
pub fn linear_kinematic_check(site: &Site, q: f64, activation: AgCapacity) -> Result<Check, Error> {
    let q = check_q(q)?;
    let ag = site.spectrum(Role::LifeSafety).ag();
    let ag_capacity = linear_kinematic_capacity(activation, q);
    Ok(Check::new(
        site.limit_state(Role::LifeSafety),
        Method::LinearKinematic,
        Unit::GroundAcceleration,
        ag,
        ag_capacity.value(),
        ag,
        ag_capacity,
    ))
}

/// The non-linear kinematic check of the life-safety or collapse state
/// (`role`): `a_g,capacity` the least `ag` at which [`displacement_demand`]
/// at `T_LS` and ξ = 8% (life safety) or 10% (collapse) exceeds `d_LS`, and not
/// less than the activation's `activation` (a mechanism that has not
/// activated has no displacement).
pub fn nonlinear_kinematic_check(capacity: &Capacity, site: &Site, role: Role, activation: AgCapacity) -> Result<Check, Error> {
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
    let spectrum = site.spectrum(role).with_damping(damping)?;
    let g = capacity.g;
    let found = least_failing_ag(AG_SEARCH_TOP, |ag| Ok(displacement_demand(&spectrum.with_ag(ag)?, t_ls, g) - d_ls))?;
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
        displacement_demand(&spectrum, t_ls, g),
        d_ls,
        spectrum.ag(),
        ag_capacity,
    ))
}

/// The four kinematic checks in order: activation (damage state), linear
/// kinematic (life safety), non-linear kinematic (life safety, collapse).
pub fn kinematic_checks(capacity: &Capacity, site: &Site, q: f64) -> Result<Vec<Check>, Error> {
    let activation = activation_check(capacity, site)?;
    Ok(vec![
        activation,
        linear_kinematic_check(site, q, activation.ag_capacity)?,
        nonlinear_kinematic_check(capacity, site, Role::LifeSafety, activation.ag_capacity)?,
        nonlinear_kinematic_check(capacity, site, Role::Collapse, activation.ag_capacity)?,
    ])
}
