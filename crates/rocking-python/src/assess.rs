//! `rocking.assess`: the assessment of a tower to the code, as `rocking
//! assess` computes it (the dynamic checks on all cores with the GIL
//! released): `assessment.json` as text, and the tables as CSV text, which the
//! Python package turns into a dict and NumPy columns.

use crate::convert::table_of;
use crate::error::scenario_error;
use crate::sweep::thread_count;
use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rocking_assess::{Assessment, AssessmentInput};
use std::path::{Path, PathBuf};

/// Assesses the tower of an assessment file given as a path or a dict.
/// Returns `{"assessment": JSON text, "capacity": CSV text, "records": CSV
/// text or None, "spectra": CSV text or None}`.
#[pyfunction]
#[pyo3(signature = (file, threads=None))]
pub fn assess_raw<'py>(py: Python<'py>, file: &Bound<'py, PyAny>, threads: Option<i64>) -> PyResult<Bound<'py, PyDict>> {
    let threads = thread_count(threads)?;
    let input = if let Ok(path) = file.extract::<PathBuf>() {
        let text = std::fs::read_to_string(&path).map_err(|e| crate::error::io_error(&e, &path))?;
        py.detach(|| AssessmentInput::from_toml_str(&text, &path)).map_err(|e| scenario_error(&e))?
    } else {
        let table = table_of(file, "").map_err(|u| PyValueError::new_err(u.message("<dict>")))?;
        py.detach(|| AssessmentInput::from_table(table, Path::new("<dict>")))
            .map_err(|e| scenario_error(&e))?
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| PyRuntimeError::new_err(format!("starting the worker threads: {e}")))?;
    let done = py.detach(|| pool.install(|| Assessment::run(&input))).map_err(|e| scenario_error(&e))?;
    let out = PyDict::new(py);
    out.set_item("assessment", done.json(&input).to_string())?;
    out.set_item("capacity", done.capacity_csv())?;
    let (records, spectra) = done.set_csvs().unzip();
    out.set_item("records", records)?;
    out.set_item("spectra", spectra)?;
    Ok(out)
}
