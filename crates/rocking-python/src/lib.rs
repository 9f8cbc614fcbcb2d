//! # rocking-python
//!
//! The extension module `rocking._rocking` of the Python package `rocking`
//! (`python/` at the repository root, built by maturin). It wraps
//! `rocking-scenario`: a scenario from a TOML file or a dict, a run with its
//! history as NumPy arrays, a parametric sweep on all cores, and the derived
//! quantities, fragility studies, the towers of a town, and response and code spectra. The Python package adds the `Result` class and the docs; the
//! stubs are in `python/rocking/_rocking.pyi`.
//!
//! The GIL is released while a case or a sweep runs. Errors are `ValueError`
//! (bad input) or `RuntimeError` (a numerical failure) with the one-line
//! message of the `rocking` command (`file: key: what is wrong`).

mod assess;
mod convert;
mod error;
mod fragility;
mod inventory;
mod run;
mod scenario;
mod spectra;
mod sweep;

use pyo3::prelude::*;

/// The native part of the `rocking` package; use `rocking` itself.
#[pymodule]
fn _rocking(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    let (history, events) = run::column_names();
    m.add("HISTORY_COLUMNS", pyo3::types::PyTuple::new(m.py(), history)?)?;
    m.add("EVENT_COLUMNS", pyo3::types::PyTuple::new(m.py(), events)?)?;
    // The descriptions of the keys and of the derived quantities, as JSON text the package reads.
    m.add("KEYS_JSON", rocking_scenario::keys_json().to_string())?;
    m.add("DERIVED_JSON", rocking_scenario::columns::derived_json().to_string())?;
    m.add("InputError", m.py().get_type::<error::InputError>())?;
    m.add("SimulationError", m.py().get_type::<error::SimulationError>())?;
    m.add_class::<scenario::PyScenario>()?;
    m.add_function(wrap_pyfunction!(run::run_raw, m)?)?;
    m.add_function(wrap_pyfunction!(run::derived, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_raw, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_file_raw, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_len_raw, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep_file_len_raw, m)?)?;
    m.add_function(wrap_pyfunction!(fragility::fragility_raw, m)?)?;
    m.add_function(wrap_pyfunction!(assess::assess_raw, m)?)?;
    m.add_function(wrap_pyfunction!(inventory::inventory_raw, m)?)?;
    m.add_function(wrap_pyfunction!(inventory::inventory_len_raw, m)?)?;
    m.add_function(wrap_pyfunction!(spectra::spectrum_raw, m)?)?;
    m.add_function(wrap_pyfunction!(spectra::code_spectrum_raw, m)?)?;
    Ok(())
}
