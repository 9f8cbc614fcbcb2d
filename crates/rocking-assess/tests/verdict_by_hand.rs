//! The method that carries the verdict (the Circolare 2019 offers the linear
//! and the non-linear analyses of a local mechanism as alternatives for the
//! ultimate limit states, §C8.7.1.2.1.7–C8.7.1.2.1.9): per limit state, the
//! check of the method the file names, else of the most refined computed;
//! the verdict the worse of SLV and SLC; SLD's activation beside it.
//!
//! Tower 1 of `kinematic_by_hand.rs` (4 m × 12 m, 150 t, FC = 1.35, subsoil
//! B), whose four ζ_E are worked out there by hand: activation 3.3437, SLV
//! linear 2.6750, SLV non-linear 5.0404, SLC non-linear 4.6767. The least of
//! them, the linear check's, was the "governing" before; the verdict by the
//! most refined method is SLC's non-linear one.

#![allow(clippy::unwrap_used)]

use approx::assert_relative_eq;
use rocking_assess::{kinematic_checks, verdict, verdicts, Assessment, AssessmentInput, Capacity, Check, CurveKind, Method, Site};
use rocking_codes::{CodeSpectrum, LimitState, NtcSite, NtcSpectrum, Soil, Topography};
use std::f64::consts::PI;
use std::path::Path;

const G: f64 = 9.81;
/// The roots are bisected to 1e-12 g; the closed forms below are those of
/// `kinematic_by_hand.rs`, agreement to 1e-9 relative as there.
const TOL: f64 = 1e-9;

fn ntc(ag: f64, f0: f64, tc_star: f64) -> CodeSpectrum {
    CodeSpectrum::Ntc(NtcSpectrum::new(NtcSite::new(ag, f0, tc_star).unwrap(), Soil::B, Topography::T1, 5.0).unwrap())
}

/// The four ζ_E of tower 1 by hand: activation, SLV linear, SLV non-linear, SLC non-linear.
fn by_hand() -> [f64; 4] {
    let a0 = G / 3.0 / 1.35;
    let a = a0 / G;
    let act = (1.4 - (1.96 - 4.0 * 1.008 * a).sqrt()) / (2.0 * 1.008);
    let eta = |xi: f64| (10.0 / (5.0 + xi)).sqrt();
    let t_slv = 1.68 * PI * (0.8 / (0.6 * a0)).sqrt();
    let tc = 1.1 * 0.36f64.powf(-0.2) * 0.36;
    let slv = 0.8 * 4.0 * PI * PI / (eta(8.0) * 2.47 * tc * G * t_slv);
    let tc = 1.1 * 0.37f64.powf(-0.2) * 0.37;
    let k = 0.025 * G * tc * 2.50 * eta(10.0);
    let slc = (-1.6 * k + ((1.6 * k).powi(2) + 4.0 * 4.0 * k * 1.2).sqrt()) / (2.0 * 4.0 * k);
    [act / 0.062, 2.0 * act / 0.155, slv / 0.155, slc / 0.196]
}

fn checks() -> Vec<Check> {
    let capacity = Capacity::new(1.5e5, 40f64.sqrt(), (1.0f64 / 3.0).atan(), G, 1.35, CurveKind::Linear).unwrap();
    let site = Site::new(ntc(0.062, 2.52, 0.30), ntc(0.155, 2.47, 0.36), ntc(0.196, 2.50, 0.37)).unwrap();
    kinematic_checks(&capacity, &site, 2.0).unwrap()
}

#[test]
fn the_most_refined_method_computed_carries_the_verdict() {
    let [activation, linear, slv, slc] = by_hand();
    // The numbers as written by hand: the linear check is the least of the four.
    assert_relative_eq!(linear, 2.6750, max_relative = 1e-4);
    assert_relative_eq!(slc, 4.6767, max_relative = 1e-4);
    assert!(linear < activation && linear < slc && slc < slv);
    let checks = checks();
    // Without a record set the non-linear kinematic check is the most refined,
    // for SLV and for SLC; the linear one is information.
    let each = verdicts(&checks, None);
    assert_eq!(each.len(), 2);
    assert_eq!((each[0].check.limit_state, each[0].check.method), (LimitState::Slv, Method::NonlinearKinematic));
    assert_eq!((each[1].check.limit_state, each[1].check.method), (LimitState::Slc, Method::NonlinearKinematic));
    assert!(each.iter().all(|v| !v.named));
    assert_relative_eq!(each[0].check.zeta_e, slv, max_relative = TOL);
    // The verdict: the worse of the two, SLC's 4.6767, not the linear 2.6750.
    let v = verdict(&checks, None).unwrap();
    assert_eq!((v.check.limit_state, v.check.method), (LimitState::Slc, Method::NonlinearKinematic));
    assert_relative_eq!(v.check.zeta_e, slc, max_relative = TOL);
}

#[test]
fn a_named_method_carries_the_verdict_where_it_was_computed() {
    let [_, linear, _, slc] = by_hand();
    let checks = checks();
    // The linear check is of SLV alone: SLC keeps its most refined one.
    let each = verdicts(&checks, Some(Method::LinearKinematic));
    assert_eq!((each[0].check.method, each[0].named), (Method::LinearKinematic, true));
    assert_eq!((each[1].check.method, each[1].named), (Method::NonlinearKinematic, false));
    let v = verdict(&checks, Some(Method::LinearKinematic)).unwrap();
    assert_eq!((v.check.limit_state, v.check.method), (LimitState::Slv, Method::LinearKinematic));
    assert_relative_eq!(v.check.zeta_e, linear, max_relative = TOL);
    // A dynamic check, where one was completed, is more refined than both:
    // one made up with ζ_E = 1.5 for SLC carries SLC's verdict, and the verdict.
    let mut with_dynamic = checks.clone();
    let mut dynamic = checks[3];
    dynamic.method = Method::NonlinearDynamic;
    dynamic.zeta_e = 1.5;
    with_dynamic.push(dynamic);
    let v = verdict(&with_dynamic, None).unwrap();
    assert_eq!((v.check.method, v.check.zeta_e), (Method::NonlinearDynamic, 1.5));
    // Named non-linear kinematic, the dynamic one is information: SLC's 4.6767 again.
    let v = verdict(&with_dynamic, Some(Method::NonlinearKinematic)).unwrap();
    assert_eq!((v.check.method, v.named), (Method::NonlinearKinematic, true));
    assert_relative_eq!(v.check.zeta_e, slc, max_relative = TOL);
}

const FILE: &str = "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n[site]\nsoil = \"B\"\n\
[site.SLD]\nag = 0.062\nF0 = 2.52\nTc_star = 0.30\n[site.SLV]\nag = 0.155\nF0 = 2.47\nTc_star = 0.36\n\
[site.SLC]\nag = 0.196\nF0 = 2.50\nTc_star = 0.37\n[assessment]\n";

#[test]
fn the_file_names_the_method_and_the_json_says_which_carries_the_verdict() {
    let [activation, linear, _, slc] = by_hand();
    let run = |extra: &str| {
        let input = AssessmentInput::from_toml_str(&format!("{FILE}{extra}"), Path::new("a.toml")).unwrap();
        let done = Assessment::run(&input).unwrap();
        done.json(&input)
    };
    let json = run("");
    assert_eq!(json["governing"]["method"], "nonlinear_kinematic");
    assert_eq!(json["governing"]["limit_state"], "SLC");
    assert_eq!(json["governing"]["verdict_basis"], "most_refined");
    assert_relative_eq!(json["governing"]["zeta_E"].as_f64().unwrap(), slc, max_relative = TOL);
    assert_eq!(json["verdicts"].as_array().unwrap().len(), 2);
    // SLD beside it.
    assert_eq!(json["damage"]["method"], "activation");
    assert_relative_eq!(json["damage"]["zeta_E"].as_f64().unwrap(), activation, max_relative = TOL);

    let json = run("verdict_method = \"linear_kinematic\"\n");
    assert_eq!(json["governing"]["method"], "linear_kinematic");
    assert_eq!(json["governing"]["verdict_basis"], "named");
    assert_relative_eq!(json["governing"]["zeta_E"].as_f64().unwrap(), linear, max_relative = TOL);

    // The dynamic method named without a record set is refused, naming the key.
    let e = AssessmentInput::from_toml_str(&format!("{FILE}verdict_method = \"nonlinear_dynamic\"\n"), Path::new("a.toml"))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(e.contains("assessment.verdict_method") && e.contains("record set"), "{e}");
    let e = AssessmentInput::from_toml_str(&format!("{FILE}verdict_method = \"least\"\n"), Path::new("a.toml"))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert!(e.contains("assessment.verdict_method") && e.contains("nonlinear_kinematic"), "{e}");
}
