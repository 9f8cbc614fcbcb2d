//! Errors as Python exceptions, with the message the `rocking` command prints
//! (`file: key: what is wrong`, on one line): `ValueError` for bad input,
//! `RuntimeError` for a numerical failure of a run.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::PyErr;
use rocking_scenario::ErrorKind;

/// The exception of a scenario error.
pub fn scenario_error(e: &rocking_scenario::Error) -> PyErr {
    match e.kind() {
        ErrorKind::Simulation(_) => PyRuntimeError::new_err(e.to_string()),
        _ => PyValueError::new_err(e.to_string()),
    }
}
