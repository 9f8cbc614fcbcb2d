//! The assessment to the code for the page's assess tab: the capacity of the
//! tower and the kinematic checks of `rocking assess` (rocking-assess), and
//! the site parameters of a hazard grid at a site (rocking-codes), so that a
//! grid's site fills the page's fields with the numbers the command uses.

use rocking_assess::{Assessment, AssessmentInput, Method, CAPACITY_POINTS};
use rocking_codes::{HazardGrid, LimitState};
use rocking_scenario::RecordCache;
use serde_json::{json, Value};
use std::cell::RefCell;
use std::path::Path;
use wasm_bindgen::prelude::*;

/// The name of the page's assessment in error lines.
pub const ASSESS_ORIGIN: &str = "assess.toml";

/// The kinematic part of `rocking assess` for an assessment file given as the
/// JSON text of its table (the scenario's sections without `[ground]`, plus
/// `[site]` with each limit state's table and `[assessment]` without
/// `records`): the JSON text of `assessment.json` as the command writes it
/// without a record set (`capacity`, `sites`, `checks`, `governing` and, with
/// blocks on the tower, `mechanisms`: each block's own, the governing check
/// taken over all and naming its `mechanism`), plus `curve`, the tower's
/// capacity curve `[[d*, a*], …]` of `capacity.csv`, `curves`, each
/// mechanism's (the tower's first), and `adrs`, each mechanism's points of the
/// ADRS chart on its curve. An error is the command's one line, the file
/// named `assess.toml`.
pub fn assess_json(text: &str) -> Result<String, String> {
    let input = input(text)?;
    if !input.file.records.is_empty() {
        return Err(format!(
            "{ASSESS_ORIGIN}: assessment.records: the kinematic checks take no record set: the dynamic checks are assess_dynamic_json's"
        ));
    }
    // Without a record set the assessment is the kinematic part alone.
    let done = Assessment::run(&input).map_err(|e| e.to_string())?;
    let mut out = done.json(&input);
    insert_curves(&mut out, &done);
    Ok(out.to_string())
}

/// `curve` (the tower's capacity curve, `[[d*, a*], …]`), `curves` (each
/// mechanism's, the tower's first) and `adrs` (each mechanism's points of the
/// ADRS chart on its curve, `[[d*, a*(d*)], …]`, as report.html places them:
/// d_SLV, d_SLC and each non-linear check's demand, at most d0), put into the
/// page's `assessment.json`: the chart's markers sit on the curve's own
/// a*(d), not on a line between two of its points.
fn insert_curves(out: &mut Value, done: &Assessment) {
    if let Value::Object(map) = out {
        map.insert("curve".into(), json!(done.capacity.curve_points(CAPACITY_POINTS)));
        let mechanisms = done.mechanisms();
        let curves: Vec<Value> = mechanisms.iter().map(|m| json!(m.capacity.curve_points(CAPACITY_POINTS))).collect();
        map.insert("curves".into(), Value::Array(curves));
        let adrs: Vec<Value> = mechanisms
            .iter()
            .map(|m| {
                let c = m.capacity;
                let demands = m
                    .completed()
                    .into_iter()
                    .filter(|k| matches!(k.method, Method::NonlinearKinematic | Method::NonlinearDynamic))
                    .map(|k| k.demand.min(c.d0));
                let points: Vec<(f64, f64)> = [c.d_slv, c.d_slc].into_iter().chain(demands).map(|d| (d, c.acceleration_at(d))).collect();
                json!(points)
            })
            .collect();
        map.insert("adrs".into(), Value::Array(adrs));
    }
}

/// The NTC site parameters of SLD, SLV and SLC at a site of a hazard grid
/// (the text of its file, in the layout of NTC Allegato B): the JSON text of
/// `{ "SLD": { "ag", "F0", "Tc_star" }, … }` for the nominal life `VN` and
/// the coefficient of use `CU`, each the value `rocking assess` computes for
/// `[site]` with `grid`, `lon`, `lat`, `VN`, `CU`; `grid` = `"ntc2018"` is the
/// official grid, held by the library. An error names the key.
pub fn grid_site_json(grid: &str, lon: f64, lat: f64, nominal_life: f64, use_coefficient: f64) -> Result<String, String> {
    let parsed;
    let grid = if grid.trim() == rocking_scenario::OFFICIAL_GRID {
        HazardGrid::ntc2018()
    } else {
        parsed = HazardGrid::parse(grid).map_err(|e| format!("site.grid: {e}"))?;
        &parsed
    };
    let hazard = grid.site(lon, lat).map_err(|e| match e {
        rocking_codes::Error::OutsideGrid { .. } => format!("site.lon: {e}"),
        other => format!("site: {other}"),
    })?;
    let mut out = serde_json::Map::new();
    for state in [LimitState::Sld, LimitState::Slv, LimitState::Slc] {
        let site = hazard.for_limit_state(state, nominal_life, use_coefficient).map_err(|e| match e {
            rocking_codes::Error::InvalidParameter { name, reason } => format!("site.{name}: {reason}"),
            other => format!("site: {other}"),
        })?;
        out.insert(state.as_str().into(), json!({ "ag": site.ag, "F0": site.f0, "Tc_star": site.tc_star }));
    }
    Ok(Value::Object(out).to_string())
}

/// The whole of `rocking assess` for an assessment file given as the JSON text
/// of its table, the record set given as text: `assessment.records` is
/// `[{ "name": "elcentro.AT2", "text": "…the file's content…" }, …]`, each
/// record read by the reader of the command's files. The JSON text of
/// `assessment.json` as the command writes it (with the dynamic checks and,
/// with blocks on the tower, each block's `mechanisms`), plus `curve`,
/// `curves` and `adrs` (as [`assess_json`]'s), `records_csv` and
/// `spectra_csv` (the texts of `records.csv` and `spectra.csv`) and
/// `responses` (the rows of `records.csv` as objects).
/// `progress(done, most)` is told after each record's run. An error is the
/// command's one line, the file named `assess.toml`; a record that fails to
/// run leaves its check not completed, as in the command's `assessment.json`.
pub fn assess_dynamic_json(text: &str, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<String, String> {
    let input = input(text)?;
    if input.file.records.is_empty() {
        return Err(format!(
            "{ASSESS_ORIGIN}: assessment.records: give the record set (3 records or more) for the dynamic checks"
        ));
    }
    let done = Assessment::run_observed(&input, &RecordCache::with_capacity(input.file.records.len()), progress).map_err(|e| e.to_string())?;
    let mut out = done.json(&input);
    insert_curves(&mut out, &done);
    if let Value::Object(map) = &mut out {
        if let Some((records, spectra)) = done.set_csvs() {
            map.insert("records_csv".into(), json!(records));
            map.insert("spectra_csv".into(), json!(spectra));
        }
        map.insert("responses".into(), responses(&done));
    }
    Ok(out.to_string())
}

/// The rows of `records.csv` as objects (the page's table of them): per
/// dynamic check and record, its scale at λ = 1 and the tower's response
/// there, and `blocks`: each block's `name`, `max_control_displacement_m`
/// (its own θ's d*) and `overturned` (it fell, or a block under it did), as
/// records.csv's `<name>_…` columns.
fn responses(done: &Assessment) -> Value {
    let Some((set, checks)) = done.dynamic_part() else { return json!([]) };
    let mut rows = Vec::new();
    for (c, check) in checks.iter().enumerate() {
        for (i, ((record, scale), response)) in set.records.iter().zip(&check.fitted.scales).zip(&check.at_one.responses).enumerate() {
            let (d, overturned, slip, error) = match response {
                Ok(r) => (r.max_displacement, Some(r.overturned), r.max_slip, None),
                Err(e) => (None, None, None, Some(e.as_str())),
            };
            let blocks: Vec<Value> = done
                .blocks
                .iter()
                .map(|b| {
                    let (d, overturned) = match &b.dynamic[c].at_one.responses[i] {
                        Ok(r) => (r.max_displacement, Some(r.overturned)),
                        Err(_) => (None, None),
                    };
                    json!({ "name": b.name, "max_control_displacement_m": d, "overturned": overturned })
                })
                .collect();
            rows.push(json!({
                "limit_state": check.limit_state.as_str(), "record": record.path, "scale": scale,
                "max_control_displacement_m": d, "overturned": overturned, "max_building_slip_m": slip, "error": error,
                "blocks": blocks,
            }));
        }
    }
    Value::Array(rows)
}

/// Each check's name and formula (HTML) as the command's report.html writes
/// them, for the behaviour factor `q` (absent: the default): the JSON text of `{ "activation": {
/// "name", "formula_html" }, … }`, keyed by the method's name in the outputs.
pub fn check_texts_json(q: Option<f64>) -> String {
    let q = q.unwrap_or(rocking_assess::DEFAULT_Q);
    let map: serde_json::Map<String, Value> = Method::ALL
        .iter()
        .map(|m| {
            let t = m.text(q);
            (m.as_str().to_string(), json!({ "name": t.name, "formula_html": t.formula_html }))
        })
        .collect();
    Value::Object(map).to_string()
}

/// The capacity's quantities as report.html describes them: the JSON text of
/// `[{ "key", "symbol_html", "unit", "meaning" }, …]`, `key` the field of
/// `assessment.json`'s `capacity` (rocking_assess::CAPACITY_QUANTITIES).
pub fn capacity_quantities_json() -> String {
    let rows: Vec<Value> = rocking_assess::CAPACITY_QUANTITIES
        .iter()
        .map(|q| json!({ "key": q.key, "symbol_html": q.symbol_html, "unit": q.unit, "meaning": q.meaning }))
        .collect();
    Value::Array(rows).to_string()
}

/// See [`capacity_quantities_json`].
#[wasm_bindgen(js_name = capacityQuantities)]
pub fn capacity_quantities() -> String {
    capacity_quantities_json()
}

/// The assessment file's table from its JSON text, validated.
fn input(text: &str) -> Result<AssessmentInput, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("{ASSESS_ORIGIN}: not a JSON object: {e}"))?;
    let table: toml::Table = serde_json::from_value(crate::strip_nulls(value)).map_err(|e| format!("{ASSESS_ORIGIN}: {e}"))?;
    AssessmentInput::from_table(table, Path::new(ASSESS_ORIGIN)).map_err(|e| e.to_string())
}

thread_local! {
    /// The page's progress function during [`assess_dynamic`] (the page's
    /// engine runs on one thread: rayon runs its work where it is called).
    static PROGRESS: RefCell<Option<js_sys::Function>> = const { RefCell::new(None) };
}

/// Tells the page's progress function, if any, the runs done and the most.
fn tell_progress(done: usize, most: usize) {
    PROGRESS.with(|p| {
        if let Some(f) = &*p.borrow() {
            // A progress function that throws does not stop the assessment.
            let _ = f.call2(&JsValue::NULL, &JsValue::from(done as f64), &JsValue::from(most as f64));
        }
    });
}

/// See [`assess_dynamic_json`]; `progress` a JavaScript function `(done, most) => …`.
#[wasm_bindgen(js_name = assessDynamic)]
pub fn assess_dynamic(text: &str, progress: js_sys::Function) -> Result<String, JsError> {
    PROGRESS.with(|p| *p.borrow_mut() = Some(progress));
    let out = assess_dynamic_json(text, &tell_progress);
    PROGRESS.with(|p| *p.borrow_mut() = None);
    out.map_err(|e| JsError::new(&e))
}

/// See [`check_texts_json`]; `q` absent is the default.
#[wasm_bindgen(js_name = checkTexts)]
pub fn check_texts(q: Option<f64>) -> String {
    check_texts_json(q)
}

/// See [`assess_json`].
#[wasm_bindgen]
pub fn assess(text: &str) -> Result<String, JsError> {
    assess_json(text).map_err(|e| JsError::new(&e))
}

/// See [`grid_site_json`].
#[wasm_bindgen(js_name = gridSite)]
pub fn grid_site(grid: &str, lon: f64, lat: f64, nominal_life: f64, use_coefficient: f64) -> Result<String, JsError> {
    grid_site_json(grid, lon, lat, nominal_life, use_coefficient).map_err(|e| JsError::new(&e))
}
