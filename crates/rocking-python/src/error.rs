//! Errors as Python exceptions, with the message the `rocking` command prints
//! (`file: key: what is wrong`, on one line), one exception class per kind as
//! polars does, each carrying the parts of its message as attributes (`.file`,
//! `.key`, `.reason`; `None` where the error has none), so that a program
//! reads them without parsing the text: `OSError` (its subclass by the error
//! number: `FileNotFoundError`, `PermissionError`, …) for a file that cannot
//! be read, `rocking.InputError` (a `ValueError`) for bad input,
//! `rocking.SimulationError` (a `RuntimeError`) for a numerical failure of a
//! run, `KeyboardInterrupt` for a run stopped by Ctrl-C. The message is made
//! from the parts in one place, `rocking_scenario::Error`'s `Display`.

use pyo3::create_exception;
use pyo3::exceptions::{PyKeyboardInterrupt, PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::PyErr;
use rocking_scenario::{ErrorKind, Fault};
use std::path::Path;

create_exception!(
    rocking,
    InputError,
    PyValueError,
    "Bad input: a file, a key or a value the tool refuses. `.file` names the file (or the origin given for a dict), `.key` the dotted key at fault (`tower.width`; None for the whole file), `.reason` what is wrong; str() is `file: key: reason`, the command's line."
);
create_exception!(
    rocking,
    SimulationError,
    PyRuntimeError,
    "A run that failed numerically (its equations lost their solution, a step too small). `.file`, `.key` and `.reason` as for InputError."
);

/// The exception of a scenario error, with its parts as attributes.
pub fn scenario_error(e: &rocking_scenario::Error) -> PyErr {
    let message = e.to_string();
    let err = match e.kind() {
        ErrorKind::Simulation(rocking::Error::Stopped { .. }) => PyKeyboardInterrupt::new_err(message),
        ErrorKind::Simulation(_) => SimulationError::new_err(message),
        ErrorKind::Read { os_error, .. } => file_error(message, *os_error),
        _ => InputError::new_err(message),
    };
    with_parts(err, Some(&e.file.display().to_string()), e.key(), &e.kind().to_string())
}

/// An `InputError` of `key` in `file` (`None`: an argument of a call, no
/// file): its message made as a scenario error's is.
pub fn input_error(file: Option<&str>, key: Option<&str>, reason: impl Into<String>) -> PyErr {
    let fault = Fault {
        key: key.map(str::to_string),
        kind: ErrorKind::Invalid(reason.into()),
    };
    match file {
        Some(file) => scenario_error(&fault.in_file(Path::new(file))),
        None => with_parts(InputError::new_err(fault.to_string()), None, key, &fault.kind.to_string()),
    }
}

/// The `InputError` of a code's function given a value out of its range
/// (the parameter its key), in `file` if one.
pub fn code_error(file: Option<&str>, e: &rocking_codes::Error) -> PyErr {
    match e {
        rocking_codes::Error::InvalidParameter { name, reason } => input_error(file, Some(name), reason.clone()),
        other => input_error(file, None, other.to_string()),
    }
}

/// `err` with the attributes `file`, `key` and `reason`.
pub fn with_parts(err: PyErr, file: Option<&str>, key: Option<&str>, reason: &str) -> PyErr {
    Python::attach(|py| {
        let value = err.value(py);
        // Setting an attribute of an exception instance fails only for a class with __slots__; none here.
        let _ = value.setattr("file", file);
        let _ = value.setattr("key", key);
        let _ = value.setattr("reason", reason);
    });
    err
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
    let err = file_error(format!("cannot read {}: {e}", path.display()), e.raw_os_error());
    with_parts(err, Some(&path.display().to_string()), None, &format!("cannot read it: {e}"))
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
