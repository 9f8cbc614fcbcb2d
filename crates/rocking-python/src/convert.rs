//! Values between Python and the scenario's TOML table: a dict in (the same
//! nesting as the TOML file), a dict out (`Scenario.to_dict`), and the
//! summary out (from its field descriptors).
//!
//! `None` stands for an absent key, as JSON's `null` does in
//! [`rocking_scenario::Scenario::from_json`]; a `None` inside a list is an error.

use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use rocking_scenario::{summary_fields, Cell, Outcome, WALL_TIME_KEY};
use toml::{Table, Value};

/// A value that has no TOML counterpart, at a dotted key.
#[derive(Debug)]
pub struct Unsupported {
    /// The dotted key (`tower.points[0]`), empty for the whole object.
    pub key: String,
    /// What is wrong.
    pub reason: String,
}

impl Unsupported {
    /// Its `InputError`, `origin: key: reason` (the form of the scenario's errors).
    pub fn error(&self, origin: &str) -> pyo3::PyErr {
        crate::error::input_error(Some(origin), (!self.key.is_empty()).then_some(self.key.as_str()), self.reason.clone())
    }
}

/// The table of a Python mapping (a `dict` or any `collections.abc.Mapping`).
pub fn table_of(obj: &Bound<'_, PyAny>, prefix: &str) -> Result<Table, Unsupported> {
    let items = mapping_items(obj).ok_or_else(|| Unsupported {
        key: prefix.to_string(),
        reason: format!("expected a dict, got {}", type_name(obj)),
    })?;
    table_of_items(items, prefix, 0)
}

/// The deepest nesting of dicts and lists a scenario or sweep can hold is 4
/// (`sweep` → axis → `{from, to, steps}`, `tower.points` → point → number);
/// anything deeper is refused before the recursion could exhaust the stack: a
/// list or dict that contains itself, or a structure nested thousands deep.
const MAX_DEPTH: usize = 16;

/// The key to name for a value nested too deep: the outermost two dotted
/// components, without list indices (`tower.points`).
fn outer_key(key: &str) -> String {
    let plain = key.split('[').next().unwrap_or(key);
    plain.split('.').take(2).collect::<Vec<_>>().join(".")
}

/// The table of a mapping's items at `depth` (checked by [`value_of`], the
/// only way in below the top).
fn table_of_items(items: Vec<(Bound<'_, PyAny>, Bound<'_, PyAny>)>, prefix: &str, depth: usize) -> Result<Table, Unsupported> {
    let mut table = Table::new();
    for (key, value) in items {
        let Ok(key) = key.cast::<PyString>().map(|s| s.to_string()) else {
            return Err(Unsupported {
                key: prefix.to_string(),
                reason: format!("keys must be strings, got {}", type_name(&key)),
            });
        };
        let dotted = if prefix.is_empty() { key.clone() } else { format!("{prefix}.{key}") };
        if let Some(v) = value_of(&value, &dotted, depth + 1)? {
            table.insert(key, v);
        }
    }
    Ok(table)
}

/// The `(key, value)` pairs of a mapping, `None` if `obj` is not one.
fn mapping_items<'py>(obj: &Bound<'py, PyAny>) -> Option<Vec<(Bound<'py, PyAny>, Bound<'py, PyAny>)>> {
    if let Ok(dict) = obj.cast::<PyDict>() {
        return Some(dict.iter().collect());
    }
    // Any other mapping (e.g. types.MappingProxyType): keys() and __getitem__.
    if obj.is_instance_of::<PyString>() || obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() {
        return None;
    }
    let keys = obj.call_method0("keys").ok()?;
    let mut out = Vec::new();
    for key in keys.try_iter().ok()? {
        let key = key.ok()?;
        let value = obj.get_item(&key).ok()?;
        out.push((key, value));
    }
    Some(out)
}

/// The TOML value of a Python value; `Ok(None)` for `None` (an absent key).
fn value_of(obj: &Bound<'_, PyAny>, key: &str, depth: usize) -> Result<Option<Value>, Unsupported> {
    let unsupported = |reason: String| Unsupported { key: key.to_string(), reason };
    if depth > MAX_DEPTH {
        return Err(Unsupported {
            key: outer_key(key),
            reason: format!("nested more than {MAX_DEPTH} levels deep (a dict or list that contains itself?)"),
        });
    }
    if obj.is_none() {
        return Ok(None);
    }
    // bool before int: Python's bool is an int.
    if let Ok(b) = obj.cast::<PyBool>() {
        return Ok(Some(Value::Boolean(b.is_true())));
    }
    if obj.is_instance_of::<PyInt>() {
        return obj
            .extract::<i64>()
            .map(|i| Some(Value::Integer(i)))
            .map_err(|_| unsupported("integer out of the 64-bit range".into()));
    }
    if let Ok(f) = obj.cast::<PyFloat>() {
        return Ok(Some(Value::Float(f.value())));
    }
    if let Ok(s) = obj.cast::<PyString>() {
        return Ok(Some(Value::String(s.to_string())));
    }
    if obj.is_instance_of::<PyList>() || obj.is_instance_of::<PyTuple>() || is_ndarray(obj) {
        let mut items = Vec::new();
        for (i, item) in obj.try_iter().map_err(|e| unsupported(e.to_string()))?.enumerate() {
            let item_key = format!("{key}[{i}]");
            let item = item.map_err(|e| Unsupported {
                key: item_key.clone(),
                reason: e.to_string(),
            })?;
            match value_of(&item, &item_key, depth + 1)? {
                Some(v) => items.push(v),
                None => {
                    return Err(Unsupported {
                        key: item_key,
                        reason: "None is not allowed in a list".into(),
                    })
                }
            }
        }
        return Ok(Some(Value::Array(items)));
    }
    if let Some(items) = mapping_items(obj) {
        return table_of_items(items, key, depth).map(|t| Some(Value::Table(t)));
    }
    // A path (pathlib.Path) is its string; a NumPy integer or float scalar its number.
    if obj.hasattr("__fspath__").unwrap_or(false) {
        if let Ok(path) = obj.extract::<std::path::PathBuf>() {
            return Ok(Some(Value::String(path.to_string_lossy().into_owned())));
        }
    }
    if obj.hasattr("__index__").unwrap_or(false) {
        if let Ok(i) = obj.extract::<i64>() {
            return Ok(Some(Value::Integer(i)));
        }
    }
    if obj.hasattr("__float__").unwrap_or(false) {
        if let Ok(f) = obj.extract::<f64>() {
            return Ok(Some(Value::Float(f)));
        }
    }
    Err(unsupported(format!(
        "expected a number, a string, a boolean, a list or a dict, got {}",
        type_name(obj)
    )))
}

fn is_ndarray(obj: &Bound<'_, PyAny>) -> bool {
    obj.get_type().name().is_ok_and(|n| n == "ndarray") && obj.hasattr("tolist").unwrap_or(false)
}

fn type_name(obj: &Bound<'_, PyAny>) -> String {
    obj.get_type()
        .name()
        .map_or_else(|_| "an object".to_string(), |n| format!("an object of type `{n}`"))
}

/// A TOML table as a Python dict (dates and times become strings).
pub fn table_to_py<'py>(py: Python<'py>, table: &Table) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (key, value) in table {
        dict.set_item(key, toml_to_py(py, value)?)?;
    }
    Ok(dict)
}

fn toml_to_py<'py>(py: Python<'py>, value: &Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match value {
        Value::String(s) => PyString::new(py, s).into_any(),
        Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        Value::Float(f) => PyFloat::new(py, *f).into_any(),
        Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        Value::Datetime(d) => PyString::new(py, &d.to_string()).into_any(),
        Value::Array(items) => PyList::new(py, items.iter().map(|v| toml_to_py(py, v)).collect::<PyResult<Vec<_>>>()?)?.into_any(),
        Value::Table(t) => table_to_py(py, t)?.into_any(),
    })
}

/// The summary as the dict of `summary.json`, read from the summary's field
/// descriptors (`rocking_scenario::columns::SUMMARY`) with no JSON in
/// between: a dotted name (`time_in_regime_s.rest`) becomes a nested dict, an
/// absent quantity `None`; `wall_time_s` last.
pub fn summary_dict<'py>(py: Python<'py>, outcome: &Outcome, wall_time_s: f64) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    for (key, cell) in summary_fields(outcome) {
        let value = cell_to_py(py, cell)?;
        match key.split_once('.') {
            Some((outer, inner)) => {
                let nested = match dict.get_item(outer)? {
                    Some(existing) => existing.cast_into::<PyDict>()?,
                    None => {
                        let nested = PyDict::new(py);
                        dict.set_item(outer, &nested)?;
                        nested
                    }
                };
                nested.set_item(inner, value)?;
            }
            None => dict.set_item(key, value)?,
        }
    }
    dict.set_item(WALL_TIME_KEY, wall_time_s)?;
    Ok(dict)
}

/// One summary value in Python: `None`, `bool`, `int`, `float` or `str`.
fn cell_to_py(py: Python<'_>, cell: Cell) -> PyResult<Bound<'_, PyAny>> {
    Ok(match cell {
        Cell::Empty => py.None().into_bound(py),
        Cell::Bool(b) => PyBool::new(py, b).to_owned().into_any(),
        Cell::Int(i) => i.into_pyobject(py)?.into_any(),
        Cell::Float(x) => PyFloat::new(py, x).into_any(),
        Cell::Text(t) => PyString::new(py, &t).into_any(),
    })
}
