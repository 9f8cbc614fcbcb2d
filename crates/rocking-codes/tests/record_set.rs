//! Record sets fitted to a target spectrum: the closed-form log least-squares
//! scale against known factors and a direct minimisation, the NTC compatibility
//! band, and the refusals.

use approx::assert_relative_eq;
use rocking::{CsvOptions, Record};
use rocking_codes::{
    compatibility, default_period_range, fit_record_set, fitted_scale, response_spectrum, set_rule, CodeSpectrum, Error, NtcSite, NtcSpectrum, SetRule, Soil,
    Topography, DEFAULT_PERIODS,
};

const G: f64 = 9.81;

fn el_centro_spectrum(periods: &[f64]) -> Vec<f64> {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/../../data/records/elcentro_1940_ns.AT2");
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("cannot read {path}: {e}"));
    let record = Record::parse(&text, None, &CsvOptions::default(), G).unwrap_or_else(|e| panic!("{path}: {e}"));
    let psa = response_spectrum(&record, periods, 5.0).unwrap_or_else(|e| panic!("{e}"));
    psa.iter().map(|a| a / G).collect()
}

#[test]
fn a_record_fitted_to_itself_scaled_gets_the_factor() {
    let periods = DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    let psa = el_centro_spectrum(&periods);
    // Seven copies scaled by known factors, fitted to El Centro × 1.7: each gets 1.7 / its factor.
    let factors = [0.5, 0.8, 1.0, 1.3, 2.0, 2.9, 4.0];
    let spectra: Vec<Vec<f64>> = factors.iter().map(|f| psa.iter().map(|a| f * a).collect()).collect();
    let target: Vec<f64> = psa.iter().map(|a| 1.7 * a).collect();
    let set = fit_record_set(&periods, &spectra, &target, (0.15, 2.0)).unwrap_or_else(|e| panic!("{e}"));
    for (scale, factor) in set.scales.iter().zip(factors) {
        // The mean of ~60 logarithms of exact ratios: round-off of 1e-15 each.
        assert_relative_eq!(*scale, 1.7 / factor, max_relative = 1e-13);
    }
    assert_eq!(set.rule, SetRule::Mean);
    assert_relative_eq!(set.compatibility.least_ratio, 1.0, max_relative = 1e-13);
    assert_relative_eq!(set.compatibility.greatest_ratio, 1.0, max_relative = 1e-13);
    assert!(set.compatibility.holds);
    // The range 0.15–2 s holds the log-spaced periods between its ends.
    assert!(periods[set.in_range.start] >= 0.15 && periods[set.in_range.start - 1] < 0.15);
    assert!(periods[set.in_range.end - 1] <= 2.0 && periods[set.in_range.end] > 2.0);
}

#[test]
fn the_closed_form_scale_minimises_the_log_misfit() {
    // A second method: golden-section search on ln f of Σ (ln(f psa) − ln Se)².
    let periods = DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    let psa = el_centro_spectrum(&periods);
    let site = NtcSite::new(0.155, 2.47, 0.36).unwrap_or_else(|e| panic!("{e}"));
    let code = CodeSpectrum::Ntc(NtcSpectrum::new(site, Soil::C, Topography::T1, 5.0).unwrap_or_else(|e| panic!("{e}")));
    let (p, s): (Vec<f64>, Vec<f64>) = periods
        .iter()
        .zip(&psa)
        .filter(|(t, _)| (0.15..=2.0).contains(*t))
        .map(|(&t, &a)| (a, code.se(t)))
        .unzip();
    let misfit = |ln_f: f64| p.iter().zip(&s).map(|(a, b)| (ln_f + a.ln() - b.ln()).powi(2)).sum::<f64>();
    let (mut lo, mut hi) = (-5.0f64, 5.0f64);
    let phi = (5f64.sqrt() - 1.0) / 2.0;
    while hi - lo > 1e-12 {
        let (m1, m2) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
        if misfit(m1) < misfit(m2) {
            hi = m2;
        } else {
            lo = m1;
        }
    }
    // The search brackets the minimum of a parabola to 1e-12 in ln f; the flat bottom
    // of a sum of squares leaves round-off of about sqrt(1e-16) in ln f: 1e-7.
    assert_relative_eq!(fitted_scale(&p, &s), (0.5 * (lo + hi)).exp(), max_relative = 1e-7);
}

#[test]
fn compatibility_band_of_ntc() {
    let target = [1.0, 2.0, 4.0];
    let c = compatibility(&[0.95, 2.4, 4.0], &target);
    assert_relative_eq!(c.least_ratio, 0.95, max_relative = 1e-15);
    assert_relative_eq!(c.greatest_ratio, 1.2, max_relative = 1e-15);
    assert!(c.holds);
    assert!(!compatibility(&[0.89, 2.0, 4.0], &target).holds);
    assert!(!compatibility(&[1.0, 2.0, 5.3], &target).holds);
    // The band's ends are in it.
    assert!(compatibility(&[0.9, 2.6, 4.0], &target).holds);
}

#[test]
fn set_sizes_and_default_range() {
    assert_eq!(set_rule(7).ok(), Some(SetRule::Mean));
    assert_eq!(set_rule(3).ok(), Some(SetRule::Largest));
    assert_eq!(set_rule(6).ok(), Some(SetRule::Largest));
    assert!(matches!(set_rule(2), Err(Error::Fit(_))));
    assert_eq!(default_period_range(None), (0.15, 2.0));
    assert_eq!(default_period_range(Some(1.2)), (0.15, 2.0));
    assert_eq!(default_period_range(Some(3.1)), (0.15, 3.1));
}

#[test]
fn bad_sets_and_ranges_are_refused() {
    let periods = DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    let psa = el_centro_spectrum(&periods);
    let three = vec![psa.clone(), psa.clone(), psa.clone()];
    let fit = |spectra: &[Vec<f64>], range| fit_record_set(&periods, spectra, &psa, range);
    assert!(matches!(fit(&three[..2], (0.15, 2.0)), Err(Error::Fit(m)) if m.contains("at least 3")));
    assert!(matches!(fit(&three, (0.15, 5.0)), Err(Error::Fit(m)) if m.contains("outside the periods")));
    assert!(matches!(fit(&three, (2.0, 0.15)), Err(Error::Fit(_))));
    assert!(matches!(fit(&three, (1.0, 1.01)), Err(Error::Fit(m)) if m.contains("fewer than 2")));
    let mut zero = three.clone();
    zero[1] = vec![0.0; periods.len()];
    assert!(matches!(fit(&zero, (0.15, 2.0)), Err(Error::Fit(m)) if m.starts_with("record 2")));
    assert!(fit(&three, (0.15, 2.0)).is_ok());
}
