//! Errors as Python exceptions, with the message the `rocking` command prints
//! (`file: key: what is wrong`, on one line), one exception per kind as polars
//! does: `OSError` (its subclass by the error number: `FileNotFoundError`,
//! `PermissionError`, …) for a file that cannot be read, `ValueError` for bad
//! input, `RuntimeError` for a numerical failure of a run, `KeyboardInterrupt`
//! for a run stopped by Ctrl-C.

use pyo3::exceptions::{PyKeyboardInterrupt, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::PyErr;
use rocking_scenario::ErrorKind;
use std::path::Path;

/// The exception of a scenario error.
pub fn scenario_error(e: &rocking_scenario::Error) -> PyErr {
    match e.kind() {
        ErrorKind::Simulation(rocking::Error::Stopped { .. }) => PyKeyboardInterrupt::new_err(e.to_string()),
        ErrorKind::Simulation(_) => PyRuntimeError::new_err(e.to_string()),
        ErrorKind::Read { os_error, .. } => file_error(e.to_string(), *os_error),
        _ => PyValueError::new_err(e.to_string()),
    }
}

/// The exception of a file that cannot be read: the `OSError` subclass of its
/// error number (`FileNotFoundError` for `ENOENT`, as `open()` raises), its
/// `errno` set and its text the command's one-line message (which names the
/// file). `strerror` and `filename` stay `None`: were they set, Python would
/// print `[Errno 2] …: 'file'` in place of the command's message.
pub fn file_error(message: String, errno: Option<i32>) -> PyErr {
    Python::attach(|py| {
        // OSError(errno, strerror) picks the subclass; an exception of that class
        // made from the message alone, with only `errno` set, prints the message.
        let made = py.get_type::<PyOSError>().call1((errno.unwrap_or(0), "")).and_then(|probe| {
            let exc = probe.get_type().call1((message,))?;
            if let Some(n) = errno {
                exc.setattr("errno", n)?;
            }
            Ok(PyErr::from_value(exc))
        });
        made.unwrap_or_else(|e| e)
    })
}

/// The exception of an I/O error on `path`, with the command's message
/// (`cannot read PATH: reason (os error N)`).
pub fn io_error(e: &std::io::Error, path: &Path) -> PyErr {
    file_error(format!("cannot read {}: {e}", path.display()), e.raw_os_error())
}

/// `err` with `note` added to its notes (`BaseException.add_note`, shown
/// under its traceback; on Python < 3.11, which has no `add_note`, the list
/// `__notes__` is set, as `add_note` sets it).
pub fn with_note(py: Python<'_>, err: PyErr, note: &str) -> PyErr {
    let value = err.value(py);
    if value.call_method1("add_note", (note,)).is_err() {
        let _ = value.setattr("__notes__", vec![note]);
    }
    err
}
