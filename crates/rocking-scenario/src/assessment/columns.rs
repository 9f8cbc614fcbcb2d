//! The columns of `rocking spectrum`'s `spectra.csv`, named once for the
//! command and the Python package: the records' spectra in g, and the code
//! spectra of a site's limit states.

use super::{kinematic_damping_pct, Site};
use rocking::Record;
use rocking_codes::{response_spectrum, LimitState, DEFAULT_DAMPING_PCT};
use std::path::Path;

/// What a code-spectrum column holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SpectrumKind {
    /// The elastic acceleration spectrum `Se` (g).
    Acceleration,
    /// The elastic displacement spectrum `SDe` (m).
    Displacement,
}

/// One column of code spectra.
#[derive(Debug, Clone, PartialEq)]
pub struct SpectrumColumn {
    /// Its name: `Se_SLV_g`, `SDe_SLV_m` (5%), `Se_SLV_8pct_g` (another damping).
    pub name: String,
    /// The limit state.
    pub limit_state: LimitState,
    /// The damping (% of critical).
    pub damping_pct: f64,
    /// Acceleration or displacement.
    pub kind: SpectrumKind,
    /// The values at the periods.
    pub values: Vec<f64>,
}

/// The code spectra of each limit state of `site` at `periods` (s), gravity `g`
/// (m/s²): `Se_<LS>_g` and `SDe_<LS>_m` at 5%, then, for the limit states of the
/// non-linear kinematic checks, the same at their damping (`Se_SLV_8pct_g`, …).
pub fn code_spectra_columns(site: &Site, periods: &[f64], g: f64) -> Result<Vec<SpectrumColumn>, rocking_codes::Error> {
    let mut columns = Vec::new();
    for (state, spectrum) in &site.spectra {
        let mut dampings = vec![DEFAULT_DAMPING_PCT];
        dampings.extend(kinematic_damping_pct(*state));
        for damping in dampings {
            let s = spectrum.with_damping(damping)?;
            let tag = if (damping - DEFAULT_DAMPING_PCT).abs() < 1e-12 {
                String::new()
            } else {
                format!("_{damping}pct")
            };
            columns.push(SpectrumColumn {
                name: format!("Se_{state}{tag}_g"),
                limit_state: *state,
                damping_pct: damping,
                kind: SpectrumKind::Acceleration,
                values: periods.iter().map(|&t| s.se(t)).collect(),
            });
            columns.push(SpectrumColumn {
                name: format!("SDe_{state}{tag}_m"),
                limit_state: *state,
                damping_pct: damping,
                kind: SpectrumKind::Displacement,
                values: periods.iter().map(|&t| s.sde(t, g)).collect(),
            });
        }
    }
    Ok(columns)
}

/// The column names of records: each file's name, or the paths as given when two share a name.
pub fn record_names(paths: &[String]) -> Vec<String> {
    let names: Vec<String> = paths
        .iter()
        .map(|p| Path::new(p).file_name().map_or_else(|| p.clone(), |n| n.to_string_lossy().into_owned()))
        .collect();
    let unique = names.iter().enumerate().all(|(i, n)| !names[..i].contains(n));
    if unique {
        names
    } else {
        paths.to_vec()
    }
}

/// The first two of `paths` that are one file (the same path, or the same
/// file by its canonical path): `(i, j)`, `i < j`. A spectrum has one column
/// per file given, so a file given twice is refused.
pub fn same_record_twice(paths: &[std::path::PathBuf]) -> Option<(usize, usize)> {
    let canonical: Vec<_> = paths.iter().map(|p| std::fs::canonicalize(p).unwrap_or_else(|_| p.clone())).collect();
    (1..paths.len()).find_map(|j| (0..j).find(|&i| canonical[i] == canonical[j]).map(|i| (i, j)))
}

/// Each record's pseudo-acceleration spectrum in g (its values in m/s² divided by
/// `g`) at `periods` (s) and `damping_pct`; an error names the record by its place.
pub fn record_spectra_in_g(records: &[Record], periods: &[f64], damping_pct: f64, g: f64) -> Result<Vec<Vec<f64>>, rocking_codes::Error> {
    records
        .iter()
        .map(|r| Ok(response_spectrum(r, periods, damping_pct)?.iter().map(|a| a / g).collect()))
        .collect()
}
