//! `rocking.Scenario`: a validated scenario, from a TOML file or a dict with
//! the same keys, and the table it came from (for `to_dict` and sweeps).

use crate::convert::{table_of, table_to_py};
use crate::error::scenario_error;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rocking_scenario::{get_dotted, parse_toml, set_dotted, Scenario};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// What a scenario given as a dict is called in error messages (in place of a file name).
pub const DICT_ORIGIN: &str = "<dict>";

/// The keys that name a record file: the horizontal and the vertical motion's.
const RECORD_KEYS: [&str; 2] = ["ground.file", "ground.vertical.file"];

/// A validated scenario: a tower, a building or both, a ground motion, the
/// initial state and the simulation settings, with the keys and sections of
/// a scenario file of the `rocking` command (`[tower]`, `[building]`,
/// `[ground]`, `[initial]`, `[simulation]`).
///
/// Make one with `Scenario.from_toml(path)` or `Scenario.from_dict(d)`; every
/// value is checked then, so a `Scenario` is always valid. A ground-motion
/// record is read when the scenario is run.
#[pyclass(name = "Scenario", module = "rocking", frozen)]
pub struct PyScenario {
    /// The table as given (the sweep's base).
    table: Table,
    /// The file, or `<dict>`.
    origin: PathBuf,
    scenario: Scenario,
}

impl PyScenario {
    /// The validated scenario.
    pub fn scenario(&self) -> &Scenario {
        &self.scenario
    }
    /// The table as given.
    pub fn table(&self) -> &Table {
        &self.table
    }
    /// The file, or `<dict>`.
    pub fn origin(&self) -> &Path {
        &self.origin
    }
}

#[pymethods]
impl PyScenario {
    /// Reads and validates a scenario file (TOML). A relative record path in
    /// it is resolved against the file's folder.
    ///
    /// Raises `ValueError` with the one-line message of `rocking check`
    /// (`file: key: what is wrong`), or `OSError` (`FileNotFoundError`, …) if
    /// the file cannot be read, as `open()` does.
    #[staticmethod]
    fn from_toml(path: PathBuf) -> PyResult<Self> {
        let text = rocking_scenario::file::read_text(&path, rocking_scenario::file::MAX_INPUT_BYTES).map_err(|e| crate::error::io_error(&e, &path))?;
        let table = parse_toml(&text, &path).map_err(|e| scenario_error(&e))?;
        let scenario = Scenario::from_table(table.clone(), &path).map_err(|e| scenario_error(&e))?;
        Ok(Self { table, origin: path, scenario })
    }

    /// Validates a scenario given as a dict with the keys of the TOML file,
    /// sections as nested dicts: `{"tower": {"width": 4.0, ...}, "ground": {...}}`.
    /// `None` stands for an absent key. A relative record path
    /// (`ground.file`, `ground.vertical.file`) is resolved against the current directory, now.
    ///
    /// Raises `ValueError` naming the key (`<dict>: tower.hieght: unknown key ...`).
    #[staticmethod]
    fn from_dict(d: &Bound<'_, PyAny>) -> PyResult<Self> {
        let mut table = table_of(d, "").map_err(|u| u.error(DICT_ORIGIN))?;
        for key in RECORD_KEYS {
            if let Some(Value::String(file)) = get_dotted(&table, key) {
                if Path::new(file).is_relative() {
                    if let Ok(absolute) = std::path::absolute(file) {
                        let absolute = Value::String(absolute.to_string_lossy().into_owned());
                        // The table is there: get_dotted found a value under it.
                        let _ = set_dotted(&mut table, key, absolute);
                    }
                }
            }
        }
        let origin = PathBuf::from(DICT_ORIGIN);
        let scenario = Scenario::from_table(table.clone(), &origin).map_err(|e| scenario_error(&e))?;
        Ok(Self { table, origin, scenario })
    }

    /// The scenario as a dict with the keys of the TOML file, as given (defaults
    /// are not filled in), except `ground.file` (and `ground.vertical.file`), each the absolute path of
    /// the record the scenario reads. `Scenario.from_dict(s.to_dict())` gives
    /// the same scenario from any directory.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let mut table = self.table.clone();
        for (key, file) in RECORD_KEYS.into_iter().zip([self.scenario.record_file(), self.scenario.vertical_record_file()]) {
            if let Some(file) = file {
                let file = std::path::absolute(file).unwrap_or_else(|_| file.to_path_buf());
                let _ = set_dotted(&mut table, key, Value::String(file.to_string_lossy().into_owned()));
            }
        }
        table_to_py(py, &table)
    }

    /// The scenario's name (`name`; default: the file stem, or `<dict>`).
    #[getter]
    fn name(&self) -> &str {
        self.scenario.name()
    }

    /// The file the scenario was read from, or `<dict>`.
    #[getter(origin)]
    fn origin_str(&self) -> String {
        self.origin.display().to_string()
    }

    /// Pickling (a Dask worker receives the scenario this way): the table as
    /// TOML text and the origin, made absolute so that a relative record path
    /// resolves to the same file from another working directory.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<(Bound<'py, PyAny>, (String, PathBuf))> {
        let this = slf.get();
        let text = toml::to_string(&this.table)
            .map_err(|e| crate::error::input_error(Some(&this.origin.display().to_string()), None, format!("cannot pickle the scenario: {e}")))?;
        let origin = if this.origin == Path::new(DICT_ORIGIN) {
            this.origin.clone()
        } else {
            std::path::absolute(&this.origin).unwrap_or_else(|_| this.origin.clone())
        };
        Ok((slf.get_type().getattr("_from_toml_text")?, (text, origin)))
    }

    /// The scenario of a TOML text read from `origin` (for unpickling).
    #[staticmethod]
    fn _from_toml_text(text: &str, origin: PathBuf) -> PyResult<Self> {
        let table = parse_toml(text, &origin).map_err(|e| scenario_error(&e))?;
        let scenario = Scenario::from_table(table.clone(), &origin).map_err(|e| scenario_error(&e))?;
        Ok(Self { table, origin, scenario })
    }

    fn __repr__(&self) -> String {
        format!("Scenario(name={:?}, origin={:?})", self.scenario.name(), self.origin.display().to_string())
    }
}
