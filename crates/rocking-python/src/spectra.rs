//! `rocking.spectrum` and `rocking.code_spectrum`: the columns of `rocking
//! spectrum`'s `spectra.csv` as NumPy arrays, computed by the same functions.

use crate::convert::table_of;
use crate::error::{code_error, file_error, input_error, scenario_error, with_note};
use crate::sweep::interruptible;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rocking_codes::PeriodGrid;
use rocking_scenario::{code_spectra_columns, read_record, record_names, record_spectra_in_g, same_record_twice, AssessmentFile, ErrorKind, DEFAULT_G};
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The periods `(from, to, count)`, checked, or a `ValueError` naming `periods`.
fn periods_of(periods: (f64, f64, usize)) -> PyResult<Vec<f64>> {
    let (from, to, count) = periods;
    PeriodGrid { from, to, count }.periods().map_err(|e| code_error(None, &e))
}

/// `{"period_s": array, name: array, …}` in order.
fn columns<'py>(py: Python<'py>, periods: Vec<f64>, columns: Vec<(String, Vec<f64>)>) -> PyResult<Bound<'py, PyDict>> {
    let out = PyDict::new(py);
    out.set_item("period_s", PyArray1::from_vec(py, periods))?;
    for (name, values) in columns {
        out.set_item(name, PyArray1::from_vec(py, values))?;
    }
    Ok(out)
}

/// Periods whose ordinates are computed between two looks for Ctrl-C.
const PERIODS_BETWEEN_CHECKS: usize = 16;

/// The pseudo-acceleration spectra (g) of record files (format guessed, as
/// `[ground]` reads them) at `damping` (%) and the log-spaced `periods`
/// `(from, to, count)`: `{"period_s": array, <file name>: array, …}`.
#[pyfunction]
#[pyo3(signature = (records, damping, periods))]
pub fn spectrum_raw<'py>(py: Python<'py>, records: Vec<PathBuf>, damping: f64, periods: (f64, f64, usize)) -> PyResult<Bound<'py, PyDict>> {
    let periods = periods_of(periods)?;
    rocking_codes::check_damping(damping).map_err(|e| code_error(None, &e))?;
    if records.is_empty() {
        return Err(input_error(None, Some("records"), "give at least one record file"));
    }
    if let Some((i, j)) = same_record_twice(&records) {
        return Err(input_error(
            None,
            Some("records"),
            format!(
                "{} is given twice (as {} and {}): a spectrum has one column per file",
                records[j].display(),
                records[i].display(),
                records[j].display()
            ),
        ));
    }
    let read = py.detach(|| records.iter().map(|p| read_record(p, DEFAULT_G)).collect::<Result<Vec<_>, ErrorKind>>());
    let read = read.map_err(|kind| match kind {
        ErrorKind::Read { os_error, .. } => file_error(kind.to_string(), os_error),
        other => input_error(None, None, other.to_string()),
    })?;
    // Ctrl-C looked for between parts of the periods (each period's ordinate is its own
    // oscillator's, so the parts join exactly): a long record over many periods stops soon.
    let ordinates = AtomicUsize::new(0);
    let spectra = interruptible(py, |halted| {
        read.iter()
            .map(|record| {
                let mut column = Vec::with_capacity(periods.len());
                for part in periods.chunks(PERIODS_BETWEEN_CHECKS) {
                    if halted.load(Ordering::Relaxed) {
                        break;
                    }
                    column.extend(record_spectra_in_g(std::slice::from_ref(record), part, damping, DEFAULT_G)?.concat());
                    ordinates.fetch_add(part.len(), Ordering::Relaxed);
                }
                Ok(column)
            })
            .collect::<Result<Vec<Vec<f64>>, rocking_codes::Error>>()
    })
    .map_err(|interrupt| {
        let (done, total) = (ordinates.load(Ordering::Relaxed), read.len() * periods.len());
        with_note(py, interrupt, &format!("rocking.spectrum: stopped after {done} of {total} ordinates"))
    })?
    .map_err(|e| code_error(None, &e))?;
    let names = record_names(&records.iter().map(|p| p.display().to_string()).collect::<Vec<_>>());
    columns(py, periods, names.into_iter().zip(spectra).collect())
}

/// The code spectra of the limit states of an assessment file's `[site]`
/// (a path, or a dict with its keys) at the log-spaced `periods`:
/// `{"period_s": array, "Se_SLV_g": array, "SDe_SLV_m": array, …}`.
#[pyfunction]
#[pyo3(signature = (site, periods))]
pub fn code_spectrum_raw<'py>(py: Python<'py>, site: &Bound<'py, PyAny>, periods: (f64, f64, usize)) -> PyResult<Bound<'py, PyDict>> {
    let periods = periods_of(periods)?;
    let file = if let Ok(path) = site.extract::<PathBuf>() {
        let text = std::fs::read_to_string(&path).map_err(|e| crate::error::io_error(&e, &path))?;
        py.detach(|| AssessmentFile::from_toml_str(&text, &path)).map_err(|e| scenario_error(&e))?
    } else {
        let table = table_of(site, "").map_err(|u| u.error("<dict>"))?;
        py.detach(|| AssessmentFile::from_table(table, Path::new("<dict>")))
            .map_err(|e| scenario_error(&e))?
    };
    let spectra =
        code_spectra_columns(&file.site, &periods, file.g).map_err(|e| input_error(Some(&file.origin().display().to_string()), Some("site"), e.to_string()))?;
    columns(py, periods, spectra.into_iter().map(|c| (c.name, c.values)).collect())
}
