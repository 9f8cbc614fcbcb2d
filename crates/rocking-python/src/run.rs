//! `rocking.run` and `rocking.derived`: one analysis with its history and
//! events, and the quantities derived from a scenario without running it.

use crate::convert::summary_dict;
use crate::error::scenario_error;
use crate::scenario::PyScenario;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use rocking::{Event, Flow, Halt, History, Observer, Step};
use rocking_scenario::columns::{event_kind, Layout, Read, Value, DERIVED, EVENTS, HISTORY, HISTORY_BLOCKS, HISTORY_POINTS, KIND};
use rocking_scenario::{Outcome, RunOptions};
use std::time::{Duration, Instant};

/// How often a run looks for Ctrl-C (KeyboardInterrupt).
const SIGNAL_CHECK: Duration = Duration::from_millis(100);

/// Stops the run when Python has a pending signal (Ctrl-C), keeping its exception.
struct Signals {
    last_check: Instant,
    raised: Option<PyErr>,
}

impl Signals {
    fn check(&mut self) -> Flow {
        if self.last_check.elapsed() < SIGNAL_CHECK {
            return Flow::Continue(());
        }
        self.last_check = Instant::now();
        match Python::attach(|py| py.check_signals()) {
            Ok(()) => Flow::Continue(()),
            Err(e) => {
                self.raised = Some(e);
                Flow::Break(Halt::Stop)
            }
        }
    }
}

impl Observer for Signals {
    fn on_step(&mut self, _: &Step<'_>) -> Flow {
        self.check()
    }
    fn on_event(&mut self, _: &Event) -> Flow {
        self.check()
    }
}

/// Runs a scenario with the GIL released and returns `(summary, history, events)`:
/// the `summary.json` object as a dict, the `history.csv` columns as NumPy
/// arrays, the `events.csv` rows as dicts. The Python `rocking.run` wraps them.
/// Ctrl-C stops the run and raises `KeyboardInterrupt`.
#[pyfunction]
pub fn run_raw<'py>(py: Python<'py>, scenario: &Bound<'py, PyScenario>) -> PyResult<Bound<'py, PyTuple>> {
    let scenario = scenario.get();
    let mut signals = Signals {
        last_check: Instant::now(),
        raised: None,
    };
    let result = py.detach(|| {
        let case = scenario.scenario().build()?;
        let start = Instant::now();
        let outcome = case.run_observed(RunOptions::ALL, &mut signals)?;
        Ok::<_, rocking_scenario::Error>((outcome, start.elapsed().as_secs_f64()))
    });
    let (outcome, wall) = match result {
        Ok(done) => done,
        // Ctrl-C: the handler's exception, with a note of where the run stopped (`stopped at t = 1.2 s`).
        Err(e) => {
            return Err(match signals.raised.take() {
                Some(raised) => crate::error::with_note(py, raised, &format!("rocking.run: {}", e.kind())),
                None => scenario_error(&e),
            })
        }
    };
    let summary = summary_dict(py, &outcome, wall)?.into_any();
    let history = match &outcome.history {
        Some(h) => history_columns(py, h, &outcome.layout)?,
        None => PyDict::new(py),
    };
    let events = events_list(py, &outcome)?;
    PyTuple::new(py, [summary, history.into_any(), events.into_any()])
}

/// The history as a dict of 1-D arrays named and ordered like the `history.csv`
/// columns (rocking_scenario::columns): float64 for the numbers, an object
/// array of `str` for the names (`regime`); each block's (`belfry_theta`,
/// `belfry_theta_dot`) after the points.
fn history_columns<'py>(py: Python<'py>, history: &History, layout: &Layout) -> PyResult<Bound<'py, PyDict>> {
    let samples = &history.samples;
    let columns = PyDict::new(py);
    for c in HISTORY.iter().filter(|c| (c.present)(layout)) {
        match c.read {
            Read::Number(f) => columns.set_item(c.name, PyArray1::from_vec(py, samples.iter().map(f).collect()))?,
            Read::Text(f) => {
                // One str object per distinct name, shared by the rows.
                let mut interned: Vec<(&'static str, Py<PyAny>)> = Vec::new();
                let mut objects: Vec<Py<PyAny>> = Vec::with_capacity(samples.len());
                for s in samples {
                    let name = f(s);
                    let object = match interned.iter().find(|(n, _)| *n == name) {
                        Some((_, o)) => o.clone_ref(py),
                        None => {
                            let o = PyString::intern(py, name).into_any().unbind();
                            interned.push((name, o.clone_ref(py)));
                            o
                        }
                    };
                    objects.push(object);
                }
                columns.set_item(c.name, PyArray1::from_vec(py, objects))?;
            }
        }
    }
    for k in 0..layout.points {
        for c in HISTORY_POINTS {
            let values = history.point_values.iter().map(|row| row.get(k).map_or(f64::NAN, c.read)).collect();
            columns.set_item(format!("p{}_{}", k + 1, c.suffix), PyArray1::from_vec(py, values))?;
        }
    }
    for (i, name) in layout.blocks.iter().enumerate() {
        for c in HISTORY_BLOCKS {
            let values = samples.iter().map(|s| (c.read)(s, i + 1)).collect();
            columns.set_item(format!("{name}_{}", c.suffix), PyArray1::from_vec(py, values))?;
        }
    }
    Ok(columns)
}

/// The events as dicts with the `events.csv` columns (rocking_scenario::columns),
/// a block's `kind` prefixed by its name (`belfry_uplift`).
fn events_list<'py>(py: Python<'py>, outcome: &Outcome) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    let columns: Vec<_> = EVENTS.iter().filter(|c| (c.present)(&outcome.layout)).collect();
    for e in &outcome.events {
        let row = PyDict::new(py);
        for c in &columns {
            if c.name == KIND {
                row.set_item(c.name, event_kind(&outcome.layout, e).as_ref())?;
                continue;
            }
            match c.read.value(e) {
                Value::Number(x) => row.set_item(c.name, x)?,
                Value::Text(t) => row.set_item(c.name, t)?,
            }
        }
        list.append(row)?;
    }
    Ok(list)
}

/// The names of the history's columns before the extra points, and of the
/// events' keys, for the Python module's `HISTORY_COLUMNS` and `EVENT_COLUMNS`.
pub fn column_names() -> (Vec<&'static str>, Vec<&'static str>) {
    let all = Layout::default();
    (
        HISTORY
            .iter()
            .filter(|c| (c.present)(&all) && matches!(c.read, Read::Number(_)))
            .map(|c| c.name)
            .collect(),
        EVENTS.iter().map(|c| c.name).collect(),
    )
}

/// The quantities derived from a scenario without running it (what `rocking
/// check` prints), named and ordered as `rocking_scenario::columns::DERIVED`
/// describes them (`alpha_rad`, `R_m`, … as in `summary.json`). A quantity of
/// an absent body is `None`.
#[pyfunction]
pub fn derived<'py>(py: Python<'py>, scenario: &Bound<'py, PyScenario>) -> PyResult<Bound<'py, PyDict>> {
    let model = scenario.get().scenario().model();
    let out = PyDict::new(py);
    for q in DERIVED {
        out.set_item(q.name, (q.value)(model))?;
    }
    Ok(out)
}
