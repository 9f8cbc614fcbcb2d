//! `rocking.fragility`: a fragility study on all cores with the GIL released:
//! the stripes as NumPy columns in case order, the fitted fragility per limit
//! state and the observed fractions.

use crate::convert::table_of;
use crate::error::scenario_error;
use crate::sweep::{column, gather, interruptible, thread_count, Told};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};
use rocking_scenario::Study;
use std::path::{Path, PathBuf};

/// Runs a study given as the path of a study file or as a dict with its keys
/// (relative record patterns then resolve against the current directory).
/// Returns `{"stripes": {column: array}, "fragility": {column: array},
/// "fractions": {column: array}}`, and with a `[site]` also `"hazard"` and
/// `"risk"` (the columns of hazard.csv and risk.csv).
#[pyfunction]
#[pyo3(signature = (study, threads=None))]
pub fn fragility_raw<'py>(py: Python<'py>, study: &Bound<'py, PyAny>, threads: Option<i64>) -> PyResult<Bound<'py, PyDict>> {
    let threads = thread_count(threads)?;
    let study = if let Ok(path) = study.extract::<PathBuf>() {
        let text = rocking_scenario::file::read_text(&path, rocking_scenario::file::MAX_INPUT_BYTES).map_err(|e| crate::error::io_error(&e, &path))?;
        py.detach(|| Study::from_toml_str(&text, &path)).map_err(|e| scenario_error(&e))?
    } else {
        let table = table_of(study, "").map_err(|u| u.error("<dict>"))?;
        py.detach(|| Study::from_table(table, Path::new("<dict>"))).map_err(|e| scenario_error(&e))?
    };

    let header = study.header();
    let mut tally = study.tally();
    let told = Told {
        call: "rocking.fragility",
        total: study.len(),
        counted: "cases",
    };
    let columns = gather(
        py,
        header.len(),
        study.origin(),
        &told,
        |row| tally.add(row),
        |cancel, sink| study.run(threads, cancel, sink),
    )?;
    let stripes = PyDict::new(py);
    for (name, cells) in header.iter().zip(columns) {
        stripes.set_item(name, column(py, name, cells)?)?;
    }

    let states = study.limit_states();
    // Ctrl-C during the fits raises KeyboardInterrupt as it does during the cases.
    let fits = interruptible(py, |cancel| tally.fits_until(cancel))?;
    let text = |py: Python<'py>, items: Vec<String>| -> Bound<'py, PyAny> {
        let objects: Vec<Py<PyAny>> = items.iter().map(|s| PyString::new(py, s).into_any().unbind()).collect();
        PyArray1::from_vec(py, objects).into_any()
    };
    let floats = |py: Python<'py>, items: Vec<f64>| PyArray1::<f64>::from_vec(py, items).into_any();
    let fragility = PyDict::new(py);
    fragility.set_item("limit_state", text(py, states.iter().map(|s| s.name.clone()).collect()))?;
    fragility.set_item("median", floats(py, fits.iter().map(|f| f.median.unwrap_or(f64::NAN)).collect()))?;
    fragility.set_item("beta", floats(py, fits.iter().map(|f| f.beta.unwrap_or(f64::NAN)).collect()))?;
    fragility.set_item("cases", PyArray1::<i64>::from_vec(py, fits.iter().map(|f| f.cases as i64).collect()))?;
    fragility.set_item("exceeded", PyArray1::<i64>::from_vec(py, fits.iter().map(|f| f.exceeded as i64).collect()))?;
    fragility.set_item("method", text(py, fits.iter().map(|f| f.method.clone()).collect()))?;

    let (mut names, mut levels, mut cases, mut exceeded) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (i, state) in states.iter().enumerate() {
        for s in tally.stripes(i) {
            names.push(state.name.clone());
            levels.push(s.level);
            cases.push(s.cases as i64);
            exceeded.push(s.exceeded as i64);
        }
    }
    let fractions = PyDict::new(py);
    fractions.set_item("limit_state", text(py, names))?;
    fractions.set_item("level", floats(py, levels))?;
    fractions.set_item("cases", PyArray1::<i64>::from_vec(py, cases))?;
    fractions.set_item("exceeded", PyArray1::<i64>::from_vec(py, exceeded))?;

    let out = PyDict::new(py);
    out.set_item("stripes", stripes)?;
    out.set_item("fragility", fragility)?;
    out.set_item("fractions", fractions)?;
    // With a [site]: the hazard curve and each limit state's risk (NaN where no fit), as hazard.csv and risk.csv.
    if let Some(site) = study.site() {
        let points = site.curve.points();
        let hazard = PyDict::new(py);
        hazard.set_item("return_period_years", floats(py, points.iter().map(|p| p.return_period).collect()))?;
        hazard.set_item("ag_g", floats(py, points.iter().map(|p| p.ag).collect()))?;
        hazard.set_item("S", floats(py, points.iter().map(|p| p.s).collect()))?;
        hazard.set_item("pga_g", floats(py, points.iter().map(|p| p.pga).collect()))?;
        hazard.set_item("annual_frequency", floats(py, points.iter().map(|p| p.annual_frequency).collect()))?;
        let risks: Vec<Option<rocking_scenario::Risk>> = fits.iter().map(|f| f.median.zip(f.beta).map(|(m, b)| site.risk(m, b))).collect();
        let of = |value: &dyn Fn(&rocking_scenario::Risk) -> Option<f64>| -> Vec<f64> {
            risks.iter().map(|r| r.as_ref().and_then(value).unwrap_or(f64::NAN)).collect()
        };
        let risk = PyDict::new(py);
        risk.set_item("limit_state", text(py, states.iter().map(|s| s.name.clone()).collect()))?;
        risk.set_item("median", floats(py, fits.iter().map(|f| f.median.unwrap_or(f64::NAN)).collect()))?;
        risk.set_item("beta", floats(py, fits.iter().map(|f| f.beta.unwrap_or(f64::NAN)).collect()))?;
        risk.set_item("annual_frequency", floats(py, of(&|r| Some(r.frequency.annual_frequency))))?;
        risk.set_item("return_period_years", floats(py, of(&|r| Some(r.return_period))))?;
        risk.set_item("probability_50y", floats(py, of(&|r| Some(r.probability_50y))))?;
        risk.set_item("reference_period_years", floats(py, of(&|_| site.reference_period)))?;
        risk.set_item("probability_VR", floats(py, of(&|r| r.probability_reference)))?;
        risk.set_item("share_below_30y", floats(py, of(&|r| Some(r.frequency.share_below))))?;
        risk.set_item("share_above_2475y", floats(py, of(&|r| Some(r.frequency.share_above))))?;
        out.set_item("hazard", hazard)?;
        out.set_item("risk", risk)?;
    }
    Ok(out)
}
