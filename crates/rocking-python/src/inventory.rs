//! `rocking.inventory`: every bell tower of a town assessed as `rocking
//! inventory` assesses them ([`rocking_assess::Inventory`]), on all cores with
//! the GIL released, the rows gathered into NumPy columns in input order.
//!
//! `first` and `count` run one contiguous block of the towers (the mechanism
//! of `rocking inventory --shard K/N`): the package cuts a town into blocks
//! for the workers of a Dask cluster and puts their columns end to end.

use crate::convert::table_of;
use crate::error::scenario_error;
use crate::sweep::{column, gather, thread_count, Told};
use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rocking_assess::{calling_pool, Inventory, InventoryError};
use rocking_scenario::{run_cases, Cases, Cell, GridCache};
use std::path::{Path, PathBuf};

/// The name of an assessment given as a dict, in errors.
const DICT: &str = "<dict>";

/// The exception of an inventory that cannot start.
fn inventory_error(e: &InventoryError) -> PyErr {
    match e {
        InventoryError::Assessment(e) => scenario_error(e),
        other => crate::error::input_error(None, None, other.to_string()),
    }
}

/// The text of `path`, or `text` when given (a worker that cannot read the file).
fn text_of(path: &Path, text: Option<String>) -> PyResult<String> {
    match text {
        Some(text) => Ok(text),
        None => std::fs::read_to_string(path).map_err(|e| crate::error::io_error(&e, path)),
    }
}

/// The inventory of the towers' file `towers` (`towers_text`: its content,
/// if given) on the assessment file `assess`, a path (`assess_text`: its
/// content, if given) or a dict.
fn build(py: Python<'_>, towers: &Path, assess: &Bound<'_, PyAny>, towers_text: Option<String>, assess_text: Option<String>) -> PyResult<Inventory> {
    let csv = text_of(towers, towers_text)?;
    if let Ok(path) = assess.extract::<PathBuf>() {
        let text = text_of(&path, assess_text)?;
        py.detach(|| Inventory::new(&text, &path, csv.as_bytes(), towers))
    } else {
        let table = table_of(assess, "").map_err(|u| u.error(DICT))?;
        py.detach(|| Inventory::from_table(table, Path::new(DICT), csv.as_bytes(), towers, GridCache::default()))
    }
    .map_err(|e| inventory_error(&e))
}

/// Assesses towers `first .. first + count` (default: every tower) of the
/// towers' file on the assessment file on `threads` worker threads (`None`:
/// one per core) and returns the columns of `inventory.csv` as NumPy arrays,
/// in header order (`lon` and `lat` as numbers, `NaN` where not one).
#[pyfunction]
#[pyo3(signature = (towers, assess, threads=None, first=0, count=None, towers_text=None, assess_text=None))]
#[allow(clippy::too_many_arguments)]
pub fn inventory_raw<'py>(
    py: Python<'py>,
    towers: PathBuf,
    assess: &Bound<'py, PyAny>,
    threads: Option<i64>,
    first: usize,
    count: Option<usize>,
    towers_text: Option<String>,
    assess_text: Option<String>,
) -> PyResult<Bound<'py, PyDict>> {
    let threads = thread_count(threads)?;
    let inventory = build(py, &towers, assess, towers_text, assess_text)?;
    let end = count.map_or(inventory.len(), |c| first.saturating_add(c).min(inventory.len()));
    let cases = first.min(end)..end;
    let pool = calling_pool(cases.len(), threads).map_err(|e| PyRuntimeError::new_err(format!("starting the worker threads: {e}")))?;
    let header = inventory.header();
    let told = Told {
        call: "rocking.inventory",
        total: cases.len(),
        counted: "towers",
    };
    let columns = gather(
        py,
        header.len(),
        &towers,
        &told,
        |_| {},
        |cancel, sink| pool.install(|| run_cases(&inventory, cases, threads, cancel, sink)),
    )?;
    let out = PyDict::new(py);
    for (name, cells) in header.iter().zip(columns) {
        let cells = if matches!(name.as_str(), "lon" | "lat") {
            // The place as a number: the text of inventory.csv read as a float.
            cells
                .into_iter()
                .map(|c| c.as_str().and_then(|t| t.parse::<f64>().ok()).map_or(Cell::Empty, Cell::Float))
                .collect()
        } else {
            cells
        };
        out.set_item(name, column(py, name, cells)?)?;
    }
    Ok(out)
}

/// The number of towers of the towers' file (checks both files as `inventory_raw` does).
#[pyfunction]
#[pyo3(signature = (towers, assess, towers_text=None, assess_text=None))]
pub fn inventory_len_raw(
    py: Python<'_>,
    towers: PathBuf,
    assess: &Bound<'_, PyAny>,
    towers_text: Option<String>,
    assess_text: Option<String>,
) -> PyResult<usize> {
    Ok(build(py, &towers, assess, towers_text, assess_text)?.len())
}
