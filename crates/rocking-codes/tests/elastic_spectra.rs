//! The NTC 2018 and EN 1998-1 elastic spectra against values worked out by hand
//! from the codes' formulas (each literal below was computed outside this crate,
//! in a few lines of Python that transcribe the tables of the codes).

use approx::assert_relative_eq;
use rocking_codes::{damping_correction, ntc_cc, ntc_ss, CodeSpectrum, Ec8Spectrum, Ec8Type, Error, NtcSite, NtcSpectrum, Soil, Topography};

// The hand values carry 16 digits; the code reaches them through a few products,
// quotients and one power, each good to an ulp: 1e-14 leaves room for ten of them.
const TIGHT: f64 = 1e-14;

fn ntc(ag: f64, f0: f64, tc_star: f64, soil: Soil, topo: Topography, damping: f64) -> NtcSpectrum {
    let site = NtcSite::new(ag, f0, tc_star).unwrap_or_else(|e| panic!("{e}"));
    NtcSpectrum::new(site, soil, topo, damping).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn damping_correction_at_5_8_10_and_the_floor() {
    assert_relative_eq!(damping_correction(5.0), 1.0, max_relative = TIGHT);
    assert_relative_eq!(damping_correction(8.0), 0.8770580193070292, max_relative = TIGHT);
    assert_relative_eq!(damping_correction(10.0), 0.816496580927726, max_relative = TIGHT);
    // sqrt(10/35) = 0.534 is under the floor 0.55.
    assert_relative_eq!(damping_correction(30.0), 0.55, max_relative = TIGHT);
    assert_relative_eq!(damping_correction(0.0), 2f64.sqrt(), max_relative = TIGHT);
}

#[test]
fn ntc_corner_values_soil_c_t2() {
    // ag 0.155 g, F0 2.47, Tc* 0.36 s on C, T2, 5%:
    // SS = 1.70 − 0.60·2.47·0.155 = 1.47029, CC = 1.05·0.36^−0.33, S = 1.2 SS.
    let s = ntc(0.155, 2.47, 0.36, Soil::C, Topography::T2, 5.0);
    assert_relative_eq!(s.ss(), 1.47029, max_relative = TIGHT);
    assert_relative_eq!(s.cc(), 1.4709891650005973, max_relative = TIGHT);
    assert_relative_eq!(s.st(), 1.2, max_relative = TIGHT);
    assert_relative_eq!(s.tc(), 0.529556099400215, max_relative = TIGHT);
    assert_relative_eq!(s.tb(), 0.17651869980007165, max_relative = TIGHT);
    assert_relative_eq!(s.td(), 2.22, max_relative = TIGHT);
    let plateau = 0.6754806318;
    assert_relative_eq!(s.plateau(), plateau, max_relative = TIGHT);
    // Each branch: T = 0 (ag S), inside the rise, on the plateau at both its ends, 1/T, 1/T².
    assert_relative_eq!(s.se(0.0), 0.27347393999999997, max_relative = TIGHT);
    assert_relative_eq!(s.se(0.1), 0.5012156422985781, max_relative = TIGHT);
    assert_relative_eq!(s.se(s.tb()), plateau, max_relative = TIGHT);
    assert_relative_eq!(s.se(0.5), plateau, max_relative = TIGHT);
    assert_relative_eq!(s.se(s.tc()), plateau, max_relative = TIGHT);
    assert_relative_eq!(s.se(1.0), 0.35770488859640076, max_relative = TIGHT);
    assert_relative_eq!(s.se(3.0), 0.08823387252044552, max_relative = TIGHT);
    // Continuity at TD: the two branches meet (plateau·TC/TD).
    assert_relative_eq!(s.se(s.td()), plateau * s.tc() / s.td(), max_relative = TIGHT);
}

#[test]
fn ntc_displacement_spectrum_branches() {
    let s = ntc(0.155, 2.47, 0.36, Soil::C, Topography::T2, 5.0);
    let g = 9.81;
    // T ≤ TE = 6 s (C): Se (T/2π)² in m.
    assert_relative_eq!(s.sde(3.0, g), 0.19732727595369212, max_relative = TIGHT);
    // TE < T ≤ TF: dg [F0η + (1 − F0η)(T − TE)/(TF − TE)], dg = 0.025 ag S TC TD (ag in m/s²).
    assert_relative_eq!(s.sde(7.0, g), 0.16577762643375873, max_relative = TIGHT);
    assert_relative_eq!(s.sde(10.0, g), 0.07884786037277466, max_relative = TIGHT);
    assert_relative_eq!(s.sde(12.0, g), 0.07884786037277466, max_relative = TIGHT);
}

#[test]
fn ss_at_both_clamps_of_each_category() {
    // F0 ag = 0.125: every linear value is above its upper clamp.
    let low = [(Soil::A, 1.0), (Soil::B, 1.20), (Soil::C, 1.50), (Soil::D, 1.80), (Soil::E, 1.60)];
    // F0 ag = 1.5: every linear value is below its lower clamp.
    let high = [(Soil::A, 1.0), (Soil::B, 1.00), (Soil::C, 1.00), (Soil::D, 0.90), (Soil::E, 1.00)];
    for ((soil, lo), (_, hi)) in low.into_iter().zip(high) {
        assert_relative_eq!(ntc_ss(soil, 0.05, 2.5), lo, max_relative = TIGHT);
        assert_relative_eq!(ntc_ss(soil, 0.6, 2.5), hi, max_relative = TIGHT);
    }
    // Between the clamps, the line: D at F0 ag = 0.5: 2.40 − 0.75.
    assert_relative_eq!(ntc_ss(Soil::D, 0.2, 2.5), 1.65, max_relative = TIGHT);
}

#[test]
fn cc_of_each_category() {
    // At Tc* = 0.3 s: A 1, B 1.10·0.3^−0.20, C 1.05·0.3^−0.33, D 1.25·0.3^−0.50, E 1.15·0.3^−0.40.
    let expected = [
        (Soil::A, 1.0),
        (Soil::B, 1.3994856001933313),
        (Soil::C, 1.5622095378895753),
        (Soil::D, 2.282177322938192),
        (Soil::E, 1.8614412701824479),
    ];
    for (soil, cc) in expected {
        assert_relative_eq!(ntc_cc(soil, 0.3), cc, max_relative = TIGHT);
    }
}

#[test]
fn ntc_damping_scales_the_plateau_not_the_zero_period() {
    let at5 = ntc(0.2, 2.5, 0.3, Soil::A, Topography::T1, 5.0);
    let at10 = ntc(0.2, 2.5, 0.3, Soil::A, Topography::T1, 10.0);
    assert_relative_eq!(at10.plateau() / at5.plateau(), 0.816496580927726, max_relative = TIGHT);
    assert_relative_eq!(at10.se(0.0), at5.se(0.0), max_relative = TIGHT);
    assert_relative_eq!(at10.se(0.0), 0.2, max_relative = TIGHT);
}

#[test]
fn ec8_type1_soil_c_at_10_percent() {
    // ag 0.25 g, S 1.15, TB 0.2, TC 0.6, TD 2.0, η = sqrt(10/15).
    let s = Ec8Spectrum::new(0.25, Soil::C, Ec8Type::Type1, 10.0).unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(s.se(0.0), 0.25 * 1.15, max_relative = TIGHT);
    assert_relative_eq!(s.se(0.1), 0.4371784587709015, max_relative = TIGHT);
    assert_relative_eq!(s.se(0.2), 0.5868569175418031, max_relative = TIGHT);
    assert_relative_eq!(s.se(0.6), 0.5868569175418031, max_relative = TIGHT);
    assert_relative_eq!(s.se(1.0), 0.3521141505250819, max_relative = TIGHT);
    assert_relative_eq!(s.se(3.0), 0.07824758900557376, max_relative = TIGHT);
    assert_relative_eq!(s.sde(2.5, 9.81), 0.17499383340378832, max_relative = TIGHT);
    assert_relative_eq!(s.sde(8.0, 9.81), 0.12866162041627632, max_relative = TIGHT);
}

#[test]
fn ec8_tables() {
    let t2 = Ec8Spectrum::new(0.1, Soil::D, Ec8Type::Type2, 5.0).unwrap_or_else(|e| panic!("{e}"));
    let p = t2.parameters();
    assert_relative_eq!(p.s, 1.80, max_relative = TIGHT);
    assert_relative_eq!(p.tb, 0.10, max_relative = TIGHT);
    assert_relative_eq!(p.tc, 0.30, max_relative = TIGHT);
    assert_relative_eq!(p.td, 1.2, max_relative = TIGHT);
    assert_relative_eq!(CodeSpectrum::Ec8(t2).se(0.2), 2.5 * 0.1 * 1.8, max_relative = TIGHT);
}

#[test]
fn bad_parameters_are_refused_by_name() {
    let site = NtcSite::new(0.1, 2.5, 0.3).unwrap_or_else(|e| panic!("{e}"));
    let named = |r: Result<NtcSpectrum, Error>| match r {
        Err(Error::InvalidParameter { name, .. }) => name,
        other => panic!("expected an invalid parameter, got {other:?}"),
    };
    assert_eq!(named(NtcSpectrum::new(site, Soil::B, Topography::T1, -1.0)), "damping");
    assert_eq!(named(NtcSpectrum::new(site, Soil::B, Topography::Factor(2.0), 5.0)), "ST");
    assert_eq!(
        named(NtcSite::new(-0.1, 2.5, 0.3).and_then(|s| NtcSpectrum::new(s, Soil::B, Topography::T1, 5.0))),
        "ag"
    );
    assert!(matches!("F".parse::<Soil>(), Err(Error::InvalidParameter { name: "soil", .. })));
    assert!(matches!("T5".parse::<Topography>(), Err(Error::InvalidParameter { name: "topography", .. })));
    assert_eq!("c".parse::<Soil>(), Ok(Soil::C));
}
