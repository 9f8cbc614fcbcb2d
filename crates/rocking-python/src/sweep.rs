//! `rocking.sweep`: a parametric study on all cores with the GIL released,
//! its rows gathered into NumPy columns in case order.
//!
//! `first` and `count` run one contiguous block of the cases (the mechanism
//! of `rocking sweep --shard K/N`): the package cuts a sweep into blocks for
//! the workers of a Dask cluster and puts their columns end to end.

use crate::convert::table_of;
use crate::error::scenario_error;
use crate::scenario::PyScenario;
use numpy::PyArray1;
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use rocking_scenario::columns::{Kind, SUMMARY, SUMMARY_BLOCKS};
use rocking_scenario::{Cell, Finished, Row, RunError, Sweep, ERROR_COLUMN};
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;
use toml::Value;

/// The most worker threads, as `rocking sweep --threads` takes.
const MAX_THREADS: usize = 4096;

/// How often the sweep looks for Ctrl-C (KeyboardInterrupt) while it runs.
pub(crate) const SIGNAL_CHECK: Duration = Duration::from_millis(100);

/// Runs the cases of `scenario` with `axes` (the `[sweep]` table of a sweep
/// file, as a dict) on `threads` worker threads (`None`: one per core) and
/// returns the columns of `sweep.csv` as NumPy arrays, in header order: the
/// rows of cases `first .. first + count` (default: every case).
#[pyfunction]
#[pyo3(signature = (scenario, axes, threads=None, first=0, count=None))]
pub fn sweep_raw<'py>(
    py: Python<'py>,
    scenario: &Bound<'py, PyScenario>,
    axes: &Bound<'py, PyAny>,
    threads: Option<i64>,
    first: usize,
    count: Option<usize>,
) -> PyResult<Bound<'py, PyDict>> {
    let threads = thread_count(threads)?;
    let sweep = build(py, scenario, axes)?;
    run_sweep(py, &sweep, threads, block(first, count))
}

/// The number of cases of `scenario` swept over `axes` (checks them as `sweep_raw` does).
#[pyfunction]
pub fn sweep_len_raw(py: Python<'_>, scenario: &Bound<'_, PyScenario>, axes: &Bound<'_, PyAny>) -> PyResult<usize> {
    Ok(build(py, scenario, axes)?.len())
}

fn build(py: Python<'_>, scenario: &Bound<'_, PyScenario>, axes: &Bound<'_, PyAny>) -> PyResult<Sweep> {
    let scenario = scenario.get();
    let origin = scenario.origin();
    let axes = table_of(axes, "sweep").map_err(|u| u.error(&origin.display().to_string()))?;
    let mut table = scenario.table().clone();
    table.insert("sweep".to_string(), Value::Table(axes));
    // Building the sweep parses its first cases and may read a record: without the GIL.
    py.detach(|| Sweep::from_table(table, origin)).map_err(|e| scenario_error(&e))
}

/// Runs a sweep file (a scenario plus its `[sweep]` table), as `rocking sweep`
/// does: cases `first .. first + count` (default: every case). `text`, when
/// given, is the file's content (a worker that cannot read the file); `path`
/// then only names it and locates relative record paths.
#[pyfunction]
#[pyo3(signature = (path, threads=None, first=0, count=None, text=None))]
pub fn sweep_file_raw(
    py: Python<'_>,
    path: PathBuf,
    threads: Option<i64>,
    first: usize,
    count: Option<usize>,
    text: Option<String>,
) -> PyResult<Bound<'_, PyDict>> {
    let threads = thread_count(threads)?;
    let sweep = build_file(py, &path, text)?;
    run_sweep(py, &sweep, threads, block(first, count))
}

/// The number of cases of a sweep file.
#[pyfunction]
#[pyo3(signature = (path, text=None))]
pub fn sweep_file_len_raw(py: Python<'_>, path: PathBuf, text: Option<String>) -> PyResult<usize> {
    Ok(build_file(py, &path, text)?.len())
}

fn build_file(py: Python<'_>, path: &std::path::Path, text: Option<String>) -> PyResult<Sweep> {
    let text = match text {
        Some(text) => text,
        None => rocking_scenario::file::read_text(path, rocking_scenario::file::MAX_INPUT_BYTES).map_err(|e| crate::error::io_error(&e, path))?,
    };
    py.detach(|| Sweep::from_toml_str(&text, path)).map_err(|e| scenario_error(&e))
}

/// The cases `first .. first + count` (every case from `first` when `count` is `None`).
fn block(first: usize, count: Option<usize>) -> Range<usize> {
    first..count.map_or(usize::MAX, |c| first.saturating_add(c))
}

pub(crate) fn thread_count(threads: Option<i64>) -> PyResult<Option<usize>> {
    match threads {
        None => Ok(None),
        Some(n) => match usize::try_from(n) {
            // The command's limit (`--threads` takes 1..=4096).
            Ok(n) if (1..=MAX_THREADS).contains(&n) => Ok(Some(n)),
            _ => Err(crate::error::input_error(None, Some("threads"), format!("{n} is not in 1..={MAX_THREADS}"))),
        },
    }
}

fn run_sweep<'py>(py: Python<'py>, sweep: &Sweep, threads: Option<usize>, cases: Range<usize>) -> PyResult<Bound<'py, PyDict>> {
    let header = sweep.header();
    let told = Told {
        call: "rocking.sweep",
        total: cases.end.min(sweep.len()).saturating_sub(cases.start),
        counted: "cases",
    };
    let columns = gather(
        py,
        header.len(),
        sweep.origin(),
        &told,
        |_| {},
        |cancel, sink| sweep.run_range(cases, threads, cancel, sink),
    )?;
    let out = PyDict::new(py);
    for (name, cells) in header.iter().zip(columns) {
        out.set_item(name, column(py, name, cells)?)?;
    }
    Ok(out)
}

/// What a call's Ctrl-C note says: `rocking.sweep: stopped after 3 of 40 cases`.
pub(crate) struct Told {
    /// The Python call.
    pub call: &'static str,
    /// The cases it runs.
    pub total: usize,
    /// What a case is (`cases`, `towers`).
    pub counted: &'static str,
}

/// Runs the cases of a sweep or a study by `run` with the GIL released and
/// gathers their rows into `width` columns of cells, each row shown to `each`
/// first (a study's tally). The columns grow as the rows arrive (a sweep of
/// 10⁷ cases reserves nothing up front; a row that cannot be stored raises
/// `MemoryError`). The cases run on a thread of their own while the calling
/// thread looks for Ctrl-C every `SIGNAL_CHECK`: its `KeyboardInterrupt`
/// stops the cases under way at their next event and is raised, with a note
/// of how many rows were done of `told.total` (`told`). Another failure is a
/// `RuntimeError` naming `origin`.
pub(crate) fn gather(
    py: Python<'_>,
    width: usize,
    origin: &Path,
    told: &Told,
    mut each: impl FnMut(&Row) + Send,
    run: impl FnOnce(&AtomicBool, &mut (dyn FnMut(Row) -> PyResult<()> + Send)) -> Result<Finished, RunError<PyErr>> + Send,
) -> PyResult<Vec<Vec<Cell>>> {
    let mut columns: Vec<Vec<Cell>> = (0..width).map(|_| Vec::new()).collect();
    let finished = interruptible(py, |cancel| {
        run(cancel, &mut |row: Row| {
            each(&row);
            for (column, cell) in columns.iter_mut().zip(row.cells) {
                column
                    .try_reserve(1)
                    .map_err(|e| PyMemoryError::new_err(format!("{}: {e}", origin.display())))?;
                column.push(cell);
            }
            Ok(())
        })
    });
    let finished = match finished {
        Ok(finished) => finished,
        Err(interrupt) => {
            let done = columns.first().map_or(0, Vec::len);
            let note = format!("{}: stopped after {done} of {} {}", told.call, told.total, told.counted);
            return Err(crate::error::with_note(py, interrupt, &note));
        }
    };
    match finished {
        Ok(_) => Ok(columns),
        Err(RunError::Stopped(e)) => Err(e),
        Err(e) => Err(crate::error::with_parts(
            crate::error::SimulationError::new_err(format!("{}: {e}", origin.display())),
            Some(&origin.display().to_string()),
            None,
            &e.to_string(),
        )),
    }
}

/// Runs `work` with the GIL released on a thread of its own while the calling
/// thread looks for Ctrl-C every `SIGNAL_CHECK`. Ctrl-C sets the flag `work`
/// is given (which must then end soon: the cases stop at their next event, a
/// fit at its next evaluation) and its `KeyboardInterrupt` is returned once
/// `work` has ended.
pub(crate) fn interruptible<T: Send>(py: Python<'_>, work: impl FnOnce(&AtomicBool) -> T + Send) -> PyResult<T> {
    let cancel = AtomicBool::new(false);
    let (value, interrupt) = py.detach(|| {
        std::thread::scope(|scope| {
            // Dropped when the work ends: the wait below then ends at once.
            let (done, ended) = mpsc::channel::<()>();
            let worker = scope.spawn(|| {
                let _done = done;
                work(&cancel)
            });
            let mut interrupt = None;
            while let Err(mpsc::RecvTimeoutError::Timeout) = ended.recv_timeout(SIGNAL_CHECK) {
                // Signal handlers run on the main thread only: elsewhere (a Dask worker) this finds nothing.
                if let Err(e) = Python::attach(|py| py.check_signals()) {
                    interrupt.get_or_insert(e);
                    cancel.store(true, Ordering::Relaxed);
                }
            }
            let value = worker.join().unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            (value, interrupt)
        })
    });
    match interrupt {
        Some(e) => Err(e),
        None => Ok(value),
    }
}

/// Whether the column `name` holds text (the summary's names and the error
/// message) or flags, from the summary's field list (a block's field by the
/// part after its name, `belfry_overturned`): its type when every cell of the
/// column is empty (every case failed).
fn field_kind(name: &str) -> Option<Kind> {
    if name == ERROR_COLUMN {
        return Some(Kind::Text);
    }
    SUMMARY.iter().find(|f| f.name == name).map(|f| f.kind).or_else(|| {
        SUMMARY_BLOCKS
            .iter()
            .find(|f| name.strip_suffix(f.suffix).is_some_and(|rest| rest.ends_with('_')))
            .map(|f| f.kind)
    })
}

/// A column as a NumPy array: numbers as float64 (`NaN` where the CSV field
/// is empty), booleans as bool when no field is empty, text as an object
/// array of `str` (`""` where empty), and a mixture, or booleans with an
/// empty field (`will_overturn` undecided, any flag of a failed case), as an
/// object array of Python values (`None` where empty): a null stays a null,
/// never `False`.
pub(crate) fn column<'py>(py: Python<'py>, name: &str, cells: Vec<Cell>) -> PyResult<Bound<'py, PyAny>> {
    let all = |f: fn(&Cell) -> bool| cells.iter().all(|c| c.is_empty() || f(c));
    let all_empty = cells.iter().all(Cell::is_empty);
    let is_text = all(|c| matches!(c, Cell::Text(_))) && (!all_empty || field_kind(name) == Some(Kind::Text));
    let is_bool = all(|c| matches!(c, Cell::Bool(_))) && (!all_empty || field_kind(name) == Some(Kind::Flag));
    let has_empty = cells.iter().any(Cell::is_empty);
    if !is_text && !is_bool && all(|c| matches!(c, Cell::Float(_) | Cell::Int(_))) {
        let values = cells.iter().map(|c| c.as_f64().unwrap_or(f64::NAN)).collect();
        return Ok(PyArray1::<f64>::from_vec(py, values).into_any());
    }
    if is_bool && !has_empty {
        let values = cells.iter().map(|c| matches!(c, Cell::Bool(true))).collect();
        return Ok(PyArray1::<bool>::from_vec(py, values).into_any());
    }
    let empty = if is_text { PyString::intern(py, "").into_any().unbind() } else { py.None() };
    let mut objects: Vec<Py<PyAny>> = Vec::with_capacity(cells.len());
    for cell in cells {
        objects.push(match cell {
            Cell::Empty => empty.clone_ref(py),
            Cell::Bool(b) => b.into_pyobject(py)?.to_owned().into_any().unbind(),
            Cell::Int(i) => i.into_pyobject(py)?.into_any().unbind(),
            Cell::Float(x) => x.into_pyobject(py)?.into_any().unbind(),
            Cell::Text(s) => PyString::new(py, &s).into_any().unbind(),
        });
    }
    Ok(PyArray1::from_vec(py, objects).into_any())
}
