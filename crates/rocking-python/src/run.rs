//! `rocking.run` and `rocking.derived`: one analysis with its history and
//! events, and the quantities derived from a scenario without running it.

use crate::convert::json_to_py;
use crate::error::scenario_error;
use crate::scenario::PyScenario;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use rocking::{History, Motion};
use rocking_scenario::{summary_json, Outcome, RunOptions};
use std::time::Instant;

/// The float columns of `history.csv` before the extra points (rocking-cli's `output/history.rs`).
const HISTORY_COLUMNS: [&str; 8] = ["t", "ground_acc", "theta", "theta_dot", "slip", "slip_vel", "top_dx", "top_abs_acc"];

/// Runs a scenario with the GIL released and returns `(summary, history, events)`:
/// the `summary.json` object as a dict, the `history.csv` columns as NumPy
/// arrays, the `events.csv` rows as dicts. The Python `rocking.run` wraps them.
#[pyfunction]
pub fn run_raw<'py>(py: Python<'py>, scenario: &Bound<'py, PyScenario>) -> PyResult<Bound<'py, PyTuple>> {
    let scenario = scenario.get();
    let (outcome, wall) = py
        .detach(|| {
            let case = scenario.scenario().build()?;
            let start = Instant::now();
            let outcome = case.run(RunOptions::ALL)?;
            Ok::<_, rocking_scenario::Error>((outcome, start.elapsed().as_secs_f64()))
        })
        .map_err(|e| scenario_error(&e))?;
    let summary = json_to_py(py, &summary_json(&outcome, wall))?;
    let history = match &outcome.history {
        Some(h) => history_columns(py, h)?,
        None => PyDict::new(py),
    };
    let events = events_list(py, &outcome)?;
    PyTuple::new(py, [summary, history.into_any(), events.into_any()])
}

/// The history as a dict of 1-D arrays named and ordered like the `history.csv`
/// columns: float64 for the numbers, an object array of `str` for `regime`.
fn history_columns<'py>(py: Python<'py>, history: &History) -> PyResult<Bound<'py, PyDict>> {
    let samples = &history.samples;
    let columns = PyDict::new(py);
    let float_column = |f: &dyn Fn(&rocking::Sample) -> f64| PyArray1::from_vec(py, samples.iter().map(f).collect());
    let getters: [&dyn Fn(&rocking::Sample) -> f64; 8] = [
        &|s| s.t,
        &|s| s.ground_acc,
        &|s| s.state.theta,
        &|s| s.state.theta_dot,
        &|s| s.state.slip,
        &|s| s.state.slip_vel,
        &|s| s.top_dx,
        &|s| s.top_abs_acc,
    ];
    for (name, get) in HISTORY_COLUMNS.iter().zip(getters) {
        columns.set_item(name, float_column(get))?;
    }
    // One str object per regime, shared by every row.
    let names = Motion::ALL.map(|m| PyString::intern(py, m.as_str()).into_any().unbind());
    let regime: Vec<Py<PyAny>> = samples.iter().map(|s| names[s.motion.index()].clone_ref(py)).collect();
    columns.set_item("regime", PyArray1::from_vec(py, regime))?;
    let points = history.point_values.first().map_or(0, Vec::len);
    for k in 0..points {
        let column = |pick: fn(&(f64, f64)) -> f64| {
            let values = history.point_values.iter().map(|row| row.get(k).map_or(f64::NAN, pick)).collect();
            PyArray1::from_vec(py, values)
        };
        columns.set_item(format!("p{}_dx", k + 1), column(|v| v.0))?;
        columns.set_item(format!("p{}_abs_acc", k + 1), column(|v| v.1))?;
    }
    Ok(columns)
}

/// The events as dicts with the `events.csv` columns (`theta`, `slip_vel`
/// and `slip` after the event, `regime` the combined motion after it).
fn events_list<'py>(py: Python<'py>, outcome: &Outcome) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for e in &outcome.events {
        let row = PyDict::new(py);
        row.set_item("t", e.time)?;
        row.set_item("kind", e.kind.as_str())?;
        row.set_item("theta", e.after.theta)?;
        row.set_item("theta_dot_before", e.before.theta_dot)?;
        row.set_item("theta_dot_after", e.after.theta_dot)?;
        row.set_item("slip_vel", e.after.slip_vel)?;
        row.set_item("slip", e.after.slip)?;
        row.set_item("regime", e.regime.motion().as_str())?;
        list.append(row)?;
    }
    Ok(list)
}

/// The quantities derived from a scenario without running it (what `rocking
/// check` prints): `alpha_rad`, `R_m`, `p_rad_s`, `restitution`,
/// `uplift_acceleration_g`, `slip_acceleration_g` (named as in `summary.json`),
/// `inertia_pivot_kg_m2`, `tower_mass_kg`, `sliding_mass_kg`, `g_m_s2`.
/// A quantity of an absent body is `None`.
#[pyfunction]
pub fn derived<'py>(py: Python<'py>, scenario: &Bound<'py, PyScenario>) -> PyResult<Bound<'py, PyDict>> {
    let model = scenario.get().scenario().model();
    let d = model.derived();
    let out = PyDict::new(py);
    let items: [(&str, Option<f64>); 10] = [
        ("alpha_rad", d.alpha),
        ("R_m", d.radius),
        ("p_rad_s", d.p),
        ("restitution", d.restitution),
        ("uplift_acceleration_g", d.uplift_acceleration_g),
        ("slip_acceleration_g", d.slip_acceleration_g),
        ("inertia_pivot_kg_m2", d.inertia_pivot),
        ("tower_mass_kg", d.tower_mass),
        ("sliding_mass_kg", d.sliding_mass),
        ("g_m_s2", Some(model.gravity())),
    ];
    for (key, value) in items {
        out.set_item(key, value)?;
    }
    Ok(out)
}
