//! Risk at a site (README, "Risk at a site"): a study with `measure = "pga"`
//! may name its site with an assessment's `[site]` keys on a hazard grid;
//! its hazard curve of surface PGA ([`rocking_codes::HazardCurve`]) and, for
//! each fitted limit state, the mean annual frequency of exceeding it, its
//! return period and the probability in 50 years and in `VN · CU`.

use super::{Fit, LimitState, Measure};
use crate::assessment::{parse_site, Code, GridCache};
use crate::error::{ErrorKind, Fault};
use crate::{Cell, Row};
use rocking_codes::{probability_in_period, CodeSpectrum, HazardCurve, LimitStateFrequency};
use std::path::Path;
use toml::Value;

/// The columns of `hazard.csv`.
pub const HAZARD_HEADER: [&str; 5] = ["return_period_years", "ag_g", "S", "pga_g", "annual_frequency"];
/// The columns of `risk.csv`.
pub const RISK_HEADER: [&str; 11] = [
    "limit_state",
    "median",
    "beta",
    "annual_frequency",
    "return_period_years",
    "probability_50y",
    "reference_period_years",
    "probability_VR",
    "share_below_30y",
    "share_above_2475y",
    "method",
];
/// The reference period of `probability_50y` (years).
pub const FIFTY_YEARS: f64 = 50.0;

/// The site of a study: its hazard curve and the reference period `VN · CU` when given.
#[derive(Debug, Clone)]
pub struct StudySite {
    /// The hazard curve of surface PGA.
    pub curve: HazardCurve,
    /// `VN · CU` (years), when the site gives `VN` or `CU`.
    pub reference_period: Option<f64>,
}

/// The risk of one limit state with a fit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Risk {
    /// `λ_LS` and the shares of the curve's extensions.
    pub frequency: LimitStateFrequency,
    /// `1 / λ_LS` (years).
    pub return_period: f64,
    /// `1 − exp(−50 λ_LS)`.
    pub probability_50y: f64,
    /// `1 − exp(−VN CU λ_LS)`, when `VN · CU` is given.
    pub probability_reference: Option<f64>,
}

/// Parses the study's `[site]`: the assessment's keys, on a hazard grid, for `measure = "pga"`.
pub(crate) fn parse(value: &Value, folder: &Path, measure: Measure) -> Result<StudySite, Fault> {
    if measure != Measure::Pga {
        return Err(Fault::new(
            "site",
            ErrorKind::NotApplicable(format!(
                "the site's hazard curve is of PGA: it needs study.measure = \"pga\", not \"{}\"",
                measure.as_str()
            )),
        ));
    }
    let site = parse_site(value, folder, &GridCache::default())?;
    if site.code != Code::Ntc2018 {
        return Err(Fault::invalid("site.code", "a hazard curve needs the NTC 2018 hazard grid: code = \"ntc2018\""));
    }
    let hazard = site.hazard.ok_or_else(|| {
        Fault::new(
            "site.grid",
            ErrorKind::Missing("a study's site needs a hazard grid and the site on it (grid, lon, lat): the limit states' tables give no hazard curve".into()),
        )
    })?;
    let topography = match site.spectra.first() {
        Some((_, CodeSpectrum::Ntc(s))) => s.topography(),
        _ => rocking_codes::Topography::T1,
    };
    let curve = HazardCurve::of_site(&hazard, site.soil, topography).map_err(|e| Fault::invalid("site.soil", e.to_string()))?;
    let given = |key: &str| value.get(key).is_some();
    let reference_period = match site.source.reference_life() {
        Some((nominal_life, use_coefficient)) if given("VN") || given("CU") => Some(nominal_life * use_coefficient),
        _ => None,
    };
    Ok(StudySite { curve, reference_period })
}

impl StudySite {
    /// The risk of a limit state with median `θ` (g) and dispersion `β`.
    pub fn risk(&self, median: f64, beta: f64) -> Risk {
        let frequency = self.curve.limit_state_frequency(median, beta);
        let lambda = frequency.annual_frequency;
        Risk {
            frequency,
            return_period: 1.0 / lambda,
            probability_50y: probability_in_period(lambda, FIFTY_YEARS),
            probability_reference: self.reference_period.map(|vr| probability_in_period(lambda, vr)),
        }
    }

    /// `hazard.csv`: one row per point of the curve.
    pub fn hazard_csv(&self) -> String {
        let rows = self
            .curve
            .points()
            .iter()
            .map(|p| [p.return_period, p.ag, p.s, p.pga, p.annual_frequency].map(Cell::Float).to_vec());
        csv_text(&HAZARD_HEADER, rows)
    }

    /// `risk.csv`: one row per limit state, its risk where it has a fit (else empty cells and the fit's `method`).
    pub fn risk_csv(&self, states: &[LimitState], fits: &[Fit]) -> String {
        let rows = states.iter().zip(fits).map(|(state, fit)| {
            let mut cells = vec![Cell::Text(state.name.clone())];
            let numbers: [Option<f64>; 9] = match fit.median.zip(fit.beta) {
                Some((m, b)) => {
                    let r = self.risk(m, b);
                    [
                        Some(m),
                        Some(b),
                        Some(r.frequency.annual_frequency),
                        Some(r.return_period),
                        Some(r.probability_50y),
                        self.reference_period,
                        r.probability_reference,
                        Some(r.frequency.share_below),
                        Some(r.frequency.share_above),
                    ]
                }
                None => [None; 9],
            };
            cells.extend(numbers.map(|x| x.map_or(Cell::Empty, Cell::Float)));
            cells.push(Cell::Text(fit.method.clone()));
            cells
        });
        csv_text(&RISK_HEADER, rows)
    }
}

/// A CSV file: the header, then each row, one per line.
fn csv_text(header: &[&str], rows: impl Iterator<Item = Vec<Cell>>) -> String {
    let mut out = crate::csv_line(header.iter().copied()) + "\n";
    for cells in rows {
        out.push_str(&Row { index: 0, cells }.to_csv_line());
        out.push('\n');
    }
    out
}
