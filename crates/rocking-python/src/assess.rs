//! `rocking.assess`: the assessment of a tower to the code, as `rocking
//! assess` computes it (the dynamic checks on all cores with the GIL
//! released, stopped by Ctrl-C): `assessment.json` as text, and the tables as CSV text, which the
//! Python package turns into a dict and NumPy columns.

use crate::convert::table_of;
use crate::error::{scenario_error, with_note};
use crate::sweep::{interruptible, thread_count};
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rocking_assess::{Assessment, AssessmentInput};
use rocking_scenario::RecordCache;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

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
        let table = table_of(file, "").map_err(|u| u.error("<dict>"))?;
        py.detach(|| AssessmentInput::from_table(table, Path::new("<dict>")))
            .map_err(|e| scenario_error(&e))?
    };
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads.unwrap_or(0))
        .build()
        .map_err(|e| PyRuntimeError::new_err(format!("starting the worker threads: {e}")))?;
    // Ctrl-C: no record's run begins after it, and KeyboardInterrupt is raised once those under
    // way end, with a note of the runs done (`rocking.assess: stopped after 12 of at most 4,914 record runs`).
    let cache = RecordCache::with_capacity(input.file.records.len());
    let runs = (AtomicUsize::new(0), AtomicUsize::new(0));
    let count = |done: usize, most: usize| {
        runs.0.fetch_max(done, Ordering::Relaxed);
        runs.1.store(most, Ordering::Relaxed);
    };
    let done = interruptible(py, |halted| pool.install(|| Assessment::run_until(&input, &cache, &count, halted)))
        .map_err(|interrupt| {
            let (done, most) = (runs.0.load(Ordering::Relaxed), runs.1.load(Ordering::Relaxed));
            with_note(py, interrupt, &format!("rocking.assess: stopped after {done} of at most {most} record runs"))
        })?
        .map_err(|e| scenario_error(&e))?
        .ok_or_else(|| PyKeyboardInterrupt::new_err("rocking.assess: stopped"))?;
    let out = PyDict::new(py);
    out.set_item("assessment", done.json(&input).to_string())?;
    out.set_item("capacity", done.capacity_csv())?;
    let (records, spectra) = done.set_csvs().unzip();
    out.set_item("records", records)?;
    out.set_item("spectra", spectra)?;
    Ok(out)
}
