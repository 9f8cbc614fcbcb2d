//! The capacity and the kinematic checks of two towers on two sites, against
//! numbers worked out by hand from the formulas of the Circolare 2019
//! (§C8.7.1.2.1) and NTC 2018 (§3.2.3): each expected value is the closed-form
//! root of the check's equation on the branch of the spectrum it falls on (the
//! branch named and verified in the test).
//!
//! Tower 1: 4 m × 12 m, b = 2, h = 6, 150 t, FC = 1.35, on subsoil B (the
//! assessment file's example site). Tower 2: b = 1.85, h = 5, 80 t, FC = 1,
//! on subsoil D with a high hazard, where `ag SS(ag)` rises, falls and rises
//! again: with α0 = 0.37 the activation equation has three roots and the
//! site's SLD demand lies below a0* although a smaller `ag` activates the tower.

#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use rocking_assess::{activation_demand, displacement_demand, kinematic_checks, least_failing_ag, AgCapacity, Capacity, Check, CurveKind, Method, Site};
use rocking_codes::{CodeSpectrum, NtcSite, NtcSpectrum, Soil, Topography};
use std::f64::consts::PI;

const G: f64 = 9.81;
/// The roots are bisected to 1e-12 g and the closed forms are evaluated in
/// f64: agreement to 1e-9 relative leaves room for the spectra's powf and
/// sqrt roundings (1e-15 each) amplified by the slopes of the equations.
const TOL: f64 = 1e-9;

fn ntc(soil: Soil, ag: f64, f0: f64, tc_star: f64) -> CodeSpectrum {
    CodeSpectrum::Ntc(NtcSpectrum::new(NtcSite::new(ag, f0, tc_star).unwrap(), soil, Topography::T1, 5.0).unwrap())
}

fn site(soil: Soil, states: [(f64, f64, f64); 3]) -> Site {
    let [d, v, c] = states.map(|(ag, f0, tc)| ntc(soil, ag, f0, tc));
    Site::new(d, v, c).unwrap()
}

const SITE_B: [(f64, f64, f64); 3] = [(0.062, 2.52, 0.30), (0.155, 2.47, 0.36), (0.196, 2.50, 0.37)];
const SITE_D: [(f64, f64, f64); 3] = [(0.40, 2.5, 0.35), (0.45, 2.4, 0.40), (0.55, 2.4, 0.42)];

fn tower(b: f64, h: f64, mass: f64, fc: f64) -> Capacity {
    Capacity::new(mass, b.hypot(h), (b / h).atan(), G, fc, CurveKind::Linear).unwrap()
}

fn at(check: &Check) -> f64 {
    match check.ag_capacity {
        AgCapacity::At(ag) => ag,
        AgCapacity::AtLeast(ag) => panic!("{} {}: holds up to {ag} g", check.limit_state, check.method),
    }
}

/// η at 8% and 10%: sqrt(10 / (5 + ξ)).
fn eta(xi: f64) -> f64 {
    (10.0 / (5.0 + xi)).sqrt()
}

#[test]
fn tower_one_on_subsoil_b() {
    let cap = tower(2.0, 6.0, 1.5e5, 1.35);
    // α0 = b/h = 1/3; a0* = α0 g / FC; d0 = b; d_SLV = 0.8 m, d_SLC = 1.2 m;
    // on the linear curve a*(d_SLV) = 0.6 a0*, a*(d_SLC) = 0.4 a0*.
    let a0 = G / 3.0 / 1.35;
    assert_relative_eq!(cap.alpha0, 1.0 / 3.0, max_relative = 1e-15);
    assert_relative_eq!(cap.a0_star, a0, max_relative = 1e-15);
    assert_relative_eq!(cap.m_star, 1.5e5, max_relative = 1e-15);
    assert_relative_eq!(cap.d0, 2.0, max_relative = 1e-15);
    assert_relative_eq!(cap.d_slv, 0.8, max_relative = 1e-15);
    assert_relative_eq!(cap.d_slc, 1.2, max_relative = 1e-15);
    let t_slv = 1.68 * PI * (0.8 / (0.6 * a0)).sqrt();
    let t_slc = 1.56 * PI * (1.2 / (0.4 * a0)).sqrt();
    assert_relative_eq!(cap.t_slv, t_slv, max_relative = 1e-14);
    assert_relative_eq!(cap.t_slc, t_slc, max_relative = 1e-14);
    assert_relative_eq!(t_slv, 3.9158, max_relative = 1e-4); // as written by hand
    assert_relative_eq!(t_slc, 5.4542, max_relative = 1e-4);

    let checks = kinematic_checks(&cap, &site(Soil::B, SITE_B), 2.0).unwrap();
    assert_eq!(
        checks.iter().map(|c| c.method).collect::<Vec<_>>(),
        [
            Method::Activation,
            Method::LinearKinematic,
            Method::NonlinearKinematic,
            Method::NonlinearKinematic
        ]
    );
    let a = a0 / G; // a0* in g: 0.246914

    // SLD activation: ag SS(ag) = a; SS = 1.4 − 0.4·2.52 ag is between its
    // bounds at the root (1.191): 1.008 ag² − 1.4 ag + a = 0, the lesser root.
    let act = (1.4 - (1.96 - 4.0 * 1.008 * a).sqrt()) / (2.0 * 1.008);
    assert!((1.0..=1.2).contains(&(1.4 - 1.008 * act)));
    assert_relative_eq!(at(&checks[0]), act, max_relative = TOL);
    assert_relative_eq!(checks[0].zeta_e, act / 0.062, max_relative = TOL);
    assert_relative_eq!(checks[0].demand, 0.062 * 1.2 * G, max_relative = 1e-14); // SS clamped at 1.2
    assert!(checks[0].holds);

    // SLV linear: q times the activation's, 2·0.20731 = 0.41462 g (the
    // equation ag S(ag) / q = a0* on the SLV site would give 2a = 0.4938 g, S = 1
    // there: not the check). Demand and capacity are those two ag in g.
    assert_relative_eq!(at(&checks[1]), 2.0 * act, max_relative = TOL);
    assert_relative_eq!(2.0 * act, 0.41462, max_relative = 1e-4); // as written by hand
    assert_relative_eq!(checks[1].zeta_e, 2.0 * act / 0.155, max_relative = TOL);
    assert_relative_eq!(checks[1].demand, 0.155, max_relative = 1e-15);
    assert_relative_eq!(checks[1].capacity, 2.0 * act, max_relative = TOL);
    assert_eq!(checks[1].unit.as_str(), "g");

    // SLV non-linear: T_SLV < TD = 4 ag + 1.6 at the root, SS = 1: on the
    // branch TC ≤ T < TD, SDe = ag η F0 TC g T / 4π², linear in ag.
    let tc = 1.1 * 0.36f64.powf(-0.2) * 0.36;
    let slv = 0.8 * 4.0 * PI * PI / (eta(8.0) * 2.47 * tc * G * t_slv);
    assert!(4.0 * slv + 1.6 > t_slv && 1.4 - 0.988 * slv <= 1.0);
    assert_relative_eq!(at(&checks[2]), slv, max_relative = TOL);
    assert_relative_eq!(checks[2].zeta_e, slv / 0.155, max_relative = TOL);
    assert_relative_eq!(checks[2].capacity, 0.8, max_relative = 1e-15);
    // Its demand at the site's 0.155 g: TD = 4·0.155 + 1.6 = 2.22 s < T_SLV < TE = 5 s,
    // so the running maximum is the plateau of SDe from TD to TE,
    // ag S η F0 TC TD g / 4π² (SS = 1.2, clamped), 0.10798 m.
    let plateau = |ag: f64, xi: f64, f0: f64, tc: f64| ag * 1.2 * eta(xi) * f0 * tc * (4.0 * ag + 1.6) * G / (4.0 * PI * PI);
    assert_relative_eq!(checks[2].demand, plateau(0.155, 8.0, 2.47, tc), max_relative = 1e-13);
    assert_relative_eq!(checks[2].demand, 0.10798, max_relative = 1e-4); // as written by hand

    // SLC non-linear: T_SLC = 5.45 s > TE = 5 s, and at the root TD > TE/(0.025·4π²):
    // the largest SDe up to T_SLC is just past TE, 0.025 ag S g TC TD F0 η, with
    // S = 1: 0.025 g TC F0 η · ag (4 ag + 1.6) = 1.2, a quadratic.
    let tc = 1.1 * 0.37f64.powf(-0.2) * 0.37;
    let k = 0.025 * G * tc * 2.50 * eta(10.0);
    let slc = (-1.6 * k + ((1.6 * k).powi(2) + 4.0 * 4.0 * k * 1.2).sqrt()) / (2.0 * 4.0 * k);
    assert!(4.0 * slc + 1.6 > 5.0 / (0.025 * 4.0 * PI * PI) && t_slc > 5.0);
    assert_relative_eq!(at(&checks[3]), slc, max_relative = TOL);
    assert_relative_eq!(checks[3].zeta_e, slc / 0.196, max_relative = TOL);
    // Its demand at the site's 0.196 g: TD = 2.384 s is below TE/(0.025·4π²) = 5.07 s,
    // so SDe drops at TE and the running maximum is the plateau before it (SS = 1.2).
    assert_relative_eq!(checks[3].demand, plateau(0.196, 10.0, 2.50, tc), max_relative = 1e-13);
    assert_relative_eq!(checks[3].capacity, 1.2, max_relative = 1e-15);
    assert!(checks.iter().all(|c| c.holds));
}

#[test]
fn tower_two_on_subsoil_d_where_ag_s_is_not_monotone() {
    let cap = tower(1.85, 5.0, 8.0e4, 1.0);
    let a = 0.37; // a0*/g = α0 / FC
    assert_relative_eq!(cap.a0_star, a * G, max_relative = 1e-15);
    let checks = kinematic_checks(&cap, &site(Soil::D, SITE_D), 2.0).unwrap();

    // SLD: SS = clamp(2.4 − 3.75 ag, 0.9, 1.8); ag SS(ag) = 0.37 has three roots:
    // 3.75 ag² − 2.4 ag + 0.37 = 0 gives 0.2589 and 0.3811, and 0.9 ag = 0.37 gives 0.4111.
    let roots = [(2.4 - 0.21f64.sqrt()) / 7.5, (2.4 + 0.21f64.sqrt()) / 7.5, 0.37 / 0.9];
    assert!(roots[0] > 0.16 && roots[1] < 0.4 && roots[2] > 0.4, "each root on its branch of SS");
    assert_relative_eq!(at(&checks[0]), roots[0], max_relative = TOL);
    // At the site's own ag = 0.40 g the demand ag S = 0.36 g lies below a0*,
    // yet the tower activates from 0.2589 g: ζ_E < 1, the check fails.
    assert_relative_eq!(checks[0].demand, 0.40 * 0.9 * G, max_relative = 1e-14);
    assert!(checks[0].demand < checks[0].capacity);
    assert_relative_eq!(checks[0].zeta_e, roots[0] / 0.40, max_relative = TOL);
    assert!(!checks[0].holds);

    // SLV linear: q times the activation's least root, 2·0.25890 = 0.51780 g, not
    // the root 0.74/0.9 = 0.822 g of ag SS(ag) / q = a0* on the SLV site: the
    // capacity keeps the activation's soil factor (1.43 at 0.2589 g).
    assert_relative_eq!(at(&checks[1]), 2.0 * roots[0], max_relative = TOL);
    assert_relative_eq!(2.0 * roots[0], 0.51780, max_relative = 1e-4); // by hand
    assert_relative_eq!(checks[1].zeta_e, 2.0 * roots[0] / 0.45, max_relative = TOL);
    assert!(checks[1].holds);

    // SLV and SLC non-linear: at the roots SS = 0.9 and T_LS < TD: the branch
    // TC ≤ T < TD, ag = d_LS 4π² / (0.9 η F0 TC g T_LS).
    let (d_slv, d_slc) = (0.4 * 1.85, 0.6 * 1.85);
    let t_slv = 1.68 * PI * (d_slv / (0.6 * a * G)).sqrt();
    let t_slc = 1.56 * PI * (d_slc / (0.4 * a * G)).sqrt();
    assert_relative_eq!(cap.t_slv, t_slv, max_relative = 1e-14);
    assert_relative_eq!(cap.t_slc, t_slc, max_relative = 1e-14);
    for (check, d, t, xi, f0, tc_star, ag_site) in [
        (&checks[2], d_slv, t_slv, 8.0, 2.4, 0.40f64, 0.45),
        (&checks[3], d_slc, t_slc, 10.0, 2.4, 0.42, 0.55),
    ] {
        let tc = 1.25 * tc_star * tc_star.powf(-0.5);
        let root = d * 4.0 * PI * PI / (0.9 * eta(xi) * f0 * tc * G * t);
        assert!(2.4 - 1.5 * f0 * root <= 0.9 && 4.0 * root + 1.6 > t);
        assert_relative_eq!(at(check), root, max_relative = TOL);
        assert_relative_eq!(check.zeta_e, root / ag_site, max_relative = TOL);
        assert!(check.holds);
    }
}

/// The same two towers on each other's sites: tower 1 activates on D where SS
/// is clamped at 1.8, tower 2 on B where SS slopes.
#[test]
fn towers_swapped_between_the_sites() {
    let t1 = tower(2.0, 6.0, 1.5e5, 1.35);
    let a = 1.0 / 3.0 / 1.35;
    let checks = kinematic_checks(&t1, &site(Soil::D, SITE_D), 2.0).unwrap();
    // SS = 1.8 up to ag = 0.6/3.75 = 0.16 g; a / 1.8 = 0.1372 < 0.16.
    assert_relative_eq!(at(&checks[0]), a / 1.8, max_relative = TOL);
    // The linear check: q = 2 times it, 0.2743 g against the SLV's 0.45 g: fails.
    assert_relative_eq!(at(&checks[1]), 2.0 * a / 1.8, max_relative = TOL);
    assert!(!checks[1].holds);
    let t2 = tower(1.85, 5.0, 8.0e4, 1.0);
    let checks = kinematic_checks(&t2, &site(Soil::B, SITE_B), 2.0).unwrap();
    // 1.008 ag² − 1.4 ag + 0.37 = 0, SS = 1.4 − 1.008 ag in [1, 1.2] at the root.
    let act = (1.4 - (1.96f64 - 4.0 * 1.008 * 0.37).sqrt()) / (2.0 * 1.008);
    assert!((1.0..=1.2).contains(&(1.4 - 1.008 * act)));
    assert_relative_eq!(at(&checks[0]), act, max_relative = TOL);
    // The linear check: q = 2 times the activation's.
    assert_relative_eq!(at(&checks[1]), 2.0 * act, max_relative = TOL);
}

/// The non-linear check is never below the activation: a tower whose
/// displacement demand reaches d_LS before it activates takes the activation's ag.
#[test]
fn nonlinear_capacity_is_at_least_the_activation() {
    // A stocky block of small size: d_LS tiny, a0* large.
    let cap = tower(0.05, 0.1, 100.0, 1.0);
    let checks = kinematic_checks(&cap, &site(Soil::B, SITE_B), 2.0).unwrap();
    let activation = at(&checks[0]);
    for c in &checks[2..] {
        assert_relative_eq!(at(c), activation, max_relative = 1e-15);
    }
    // and the displacement demand alone would have failed first.
    let spectrum = ntc(Soil::B, 0.155, 2.47, 0.36).with_damping(8.0).unwrap();
    let alone = least_failing_ag(2.0, |ag| Ok(displacement_demand(&spectrum.with_ag(ag)?, cap.t_slv, G) - cap.d_slv)).unwrap();
    assert!(alone.value() < activation);
}

/// The non-decreasing displacement spectrum equals the largest of SDe on a
/// dense grid of periods up to T_LS (a second method), for both codes, four
/// soils, T_LS across every branch and across TE, and ag on either side of the
/// jump at TE; the grid misses the supremum by at most its spacing's change of SDe.
#[test]
fn displacement_demand_is_the_running_maximum() {
    for soil in [Soil::A, Soil::B, Soil::C, Soil::D] {
        for ag in [0.05, 0.3, 0.95] {
            let spectra = [
                ntc(soil, ag, 2.5, 0.4).with_damping(10.0).unwrap(),
                CodeSpectrum::Ec8(rocking_codes::Ec8Spectrum::new(ag, soil, rocking_codes::Ec8Type::Type1, 8.0).unwrap()),
            ];
            for spectrum in spectra {
                for t_ls in [0.05, 0.3, 1.0, 2.5, 4.9, 5.5, 6.5, 8.0] {
                    let n = 200_000;
                    let dense = (0..=n).map(|k| spectrum.sde(t_ls * k as f64 / n as f64, G)).fold(0.0, f64::max);
                    let demand = displacement_demand(&spectrum, t_ls, G);
                    // The closed form is the supremum: never below the samples, above by at most 1e-4 relative.
                    assert!(demand >= dense * (1.0 - 1e-12), "{soil} {ag} {t_ls}: {demand} < {dense}");
                    assert_relative_eq!(demand, dense, max_relative = 1e-4);
                }
            }
        }
    }
}

/// The search finds the least of several roots, however a bisection over the
/// whole range would land: f(ag) = −(ag − 0.3)(ag − 0.5)(ag − 0.9) − 0.0 fails
/// (≥ 0) on [0.3, 0.5] and beyond 0.9.
#[test]
fn least_root_of_a_non_monotone_excess() {
    let f = |ag: f64| Ok((ag - 0.3) * (ag - 0.5) * (ag - 0.9));
    // f < 0 below 0.3, > 0 on (0.3, 0.5), < 0 on (0.5, 0.9), > 0 beyond.
    let found = least_failing_ag(2.0, f).unwrap();
    assert_relative_eq!(found.value(), 0.3, max_relative = 1e-11);
    assert!(!found.is_lower_bound());
    let never = least_failing_ag(2.0, |ag| Ok(ag - 5.0)).unwrap();
    assert_eq!(never, AgCapacity::AtLeast(2.0));
    // The activation demand is ag S g.
    assert_relative_eq!(activation_demand(&ntc(Soil::A, 0.2, 2.5, 0.3), G), 0.2 * G, max_relative = 1e-15);
}

/// The exact curve: a*(0) = a0* on both curves, a* = 0 at d0, and the
/// displacement-to-acceleration inversion agrees with the curve by θ.
#[test]
fn exact_curve_inverts() {
    let b = 2.0f64;
    let h = 6.0f64;
    let cap = Capacity::new(1.0e5, b.hypot(h), (b / h).atan(), G, 1.35, CurveKind::Exact).unwrap();
    let points = cap.curve_points(101);
    assert_relative_eq!(points[0].1, cap.a0_star, max_relative = 1e-14);
    assert_relative_eq!(points[100].0, cap.d0, max_relative = 1e-14);
    assert!(points[100].1.abs() < 1e-15);
    for &(d, a) in &points[1..100] {
        assert_relative_eq!(cap.acceleration_at(d), a, max_relative = 1e-10);
    }
    // The rigid body's curve lies below the straight line that joins its ends:
    // a*(d) ≤ a0*(1 − d/d0) for 0 < d < d0.
    for &(d, a) in &points[1..100] {
        assert!(a <= cap.a0_star * (1.0 - d / cap.d0) + 1e-12);
    }
}

#[test]
fn bad_input_is_refused() {
    let r = 40f64.sqrt();
    let alpha = (1.0f64 / 3.0).atan();
    let e = Capacity::new(1e5, r, alpha, G, 0.9, CurveKind::Linear).unwrap_err().to_string();
    assert!(e.starts_with("confidence_factor: must be a finite number >= 1"), "{e}");
    let cap = Capacity::new(1e5, r, alpha, G, 1.0, CurveKind::Linear).unwrap();
    for q in [0.0, -2.0, f64::NAN] {
        let e = kinematic_checks(&cap, &site(Soil::B, SITE_B), q).unwrap_err().to_string();
        assert!(e.starts_with("q: must be a finite number > 0"), "{e}");
    }
}

/// Tower 1 on an EN 1998-1 site (type 1, ground B: S = 1.2, TC = 0.5 s,
/// TD = 2 s, none moving with ag): every capacity is a closed form.
#[test]
fn tower_one_on_an_ec8_site() {
    use rocking_codes::{Ec8Spectrum, Ec8Type};
    let cap = tower(2.0, 6.0, 1.5e5, 1.35);
    let ec8 = |ag| CodeSpectrum::Ec8(Ec8Spectrum::new(ag, Soil::B, Ec8Type::Type1, 5.0).unwrap());
    let site = Site::new(ec8(0.06), ec8(0.15), ec8(0.20)).unwrap();
    let checks = kinematic_checks(&cap, &site, 2.0).unwrap();
    let a = 1.0 / 3.0 / 1.35;
    assert_eq!(checks[0].limit_state.as_str(), "DL");
    assert_relative_eq!(at(&checks[0]), a / 1.2, max_relative = TOL);
    assert_relative_eq!(at(&checks[1]), 2.0 * a / 1.2, max_relative = TOL);
    // T_SLV = 3.92 s and T_SLC = 5.45 s are beyond TD = 2 s: SDe is flat from TD
    // to TE = 5 s at 2.5 ag S η TC TD g / 4π², above its value just past TE
    // (0.025 in place of 1/4π²), so both demands are that plateau.
    for (check, d, xi, ag) in [(&checks[2], 0.8, 8.0, 0.15), (&checks[3], 1.2, 10.0, 0.20)] {
        let root = d * 4.0 * PI * PI / (2.5 * 1.2 * eta(xi) * 0.5 * 2.0 * G);
        assert_relative_eq!(at(check), root, max_relative = TOL);
        assert_relative_eq!(check.zeta_e, root / ag, max_relative = TOL);
    }
}
