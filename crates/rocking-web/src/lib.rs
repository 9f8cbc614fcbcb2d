//! # rocking-web
//!
//! The engine for the page in `web/`: the scenario crate behind a few
//! functions that take and give JSON text, so that the page accepts exactly
//! the keys of a scenario file and gives exactly the numbers and the error
//! lines of the `rocking` command. `web/rocking.js` wraps them into
//! `window.rocking` (README, "The page in the browser").
//!
//! JSON text rather than JavaScript objects built field by field: one
//! `JSON.parse` on the page is faster than thousands of calls across the
//! boundary, and serde_json prints every `f64` in its shortest form that
//! reads back to the same bits, so nothing is rounded on the way.
//!
//! Scenarios are named `scenario.toml` in error lines (the page has no file):
//! `scenario.toml: tower.width: must be a finite number > 0, got -4`.
//!
//! ```
//! let out = rocking_web::run_json(r#"{"tower": {"width": 1, "height": 4, "density": 2400},
//!     "ground": {"type": "sine-pulse", "amplitude_ratio": 2.5, "frequency_ratio": 5}}"#)?;
//! let out: serde_json::Value = serde_json::from_str(&out).map_err(|e| e.to_string())?;
//! assert_eq!(out["summary"]["overturned"], false);
//! # Ok::<(), String>(())
//! ```

mod assess;
mod output;
mod spectrum;
mod town;

pub use assess::{assess_dynamic_json, assess_json, capacity_quantities_json, check_texts_json, grid_site_json, ASSESS_ORIGIN};
pub use spectrum::record_spectrum_json;
pub use town::WebTown;

use rocking_scenario::{Scenario, Sweep};
use serde_json::{json, Value};
use std::path::Path;
use wasm_bindgen::prelude::*;

/// The name of the page's scenario in error lines.
pub const ORIGIN: &str = "scenario.toml";

fn origin() -> &'static Path {
    Path::new(ORIGIN)
}

/// The scenario of a JSON object's text; a text that is not JSON is named.
fn scenario(text: &str) -> Result<Scenario, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("{ORIGIN}: not a JSON object: {e}"))?;
    Scenario::from_json(value, origin()).map_err(|e| e.to_string())
}

/// Runs a scenario (a JSON object with the TOML file's keys): the JSON text of
/// `{ summary, history, events }`, the summary as `summary.json` (with
/// `wall_time_s` 0: the page times the call), the history as columns named as
/// in `history.csv`, the events as rows named as in `events.csv`. An error is
/// the command's one line.
pub fn run_json(text: &str) -> Result<String, String> {
    let case = scenario(text)?.build().map_err(|e| e.to_string())?;
    let outcome = case.run(rocking_scenario::RunOptions::ALL).map_err(|e| e.to_string())?;
    Ok(output::outcome_json(&outcome).to_string())
}

/// The derived quantities of a scenario without running it (what `rocking
/// check` prints), as the JSON text of one object; a record is read.
pub fn check_json(text: &str) -> Result<String, String> {
    let case = scenario(text)?.build().map_err(|e| e.to_string())?;
    Ok(output::check(&case).to_string())
}

/// A TOML file's text as the JSON text of the same table (the page's examples
/// and the files a user opens); a syntax error is the command's one line.
pub fn toml_to_json(text: &str) -> Result<String, String> {
    let table = rocking_scenario::parse_toml(text, origin()).map_err(|e| e.to_string())?;
    serde_json::to_string(&table).map_err(|e| e.to_string())
}

/// A scenario's JSON text as a TOML file (the page's download), keys in the
/// order given; `null` members are left out.
pub fn json_to_toml(text: &str) -> Result<String, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("{ORIGIN}: not a JSON object: {e}"))?;
    let table: toml::Table = serde_json::from_value(strip_nulls(value)).map_err(|e| format!("{ORIGIN}: {e}"))?;
    toml::to_string(&table).map_err(|e| format!("{ORIGIN}: {e}"))
}

fn strip_nulls(value: Value) -> Value {
    match value {
        Value::Object(map) => Value::Object(map.into_iter().filter(|(_, v)| !v.is_null()).map(|(k, v)| (k, strip_nulls(v))).collect()),
        Value::Array(items) => Value::Array(items.into_iter().map(strip_nulls).collect()),
        other => other,
    }
}

/// Runs `scenario` (JSON text) and returns the JSON text of `{ summary, history, events }`.
#[wasm_bindgen]
pub fn run(scenario: &str) -> Result<String, JsError> {
    run_json(scenario).map_err(|e| JsError::new(&e))
}

/// A run for the page: the JSON text of `{ summary, events, columns, regime }`
/// and the history's float columns as `Float64Array`s.
#[wasm_bindgen]
pub struct RunOutput {
    meta: String,
    columns: Vec<Vec<f64>>,
}

#[wasm_bindgen]
impl RunOutput {
    /// The JSON text of `{ summary, events, columns, regime }` (`columns`: the names of the float columns).
    pub fn meta(&self) -> String {
        self.meta.clone()
    }
    /// Float column `index` of the history (in the order of `columns`); empty past the end.
    pub fn column(&self, index: usize) -> Vec<f64> {
        self.columns.get(index).cloned().unwrap_or_default()
    }
}

/// Runs `scenario` (JSON text): the page's fast path (the history as typed arrays).
#[wasm_bindgen(js_name = runColumns)]
pub fn run_columns(scenario: &str) -> Result<RunOutput, JsError> {
    let run = || -> Result<RunOutput, String> {
        let case = self::scenario(scenario)?.build().map_err(|e| e.to_string())?;
        let outcome = case.run(rocking_scenario::RunOptions::ALL).map_err(|e| e.to_string())?;
        let (meta, columns) = output::outcome_parts(&outcome);
        Ok(RunOutput {
            meta: meta.to_string(),
            columns,
        })
    };
    run().map_err(|e| JsError::new(&e))
}

/// The derived quantities of `scenario` (JSON text), as JSON text.
#[wasm_bindgen]
pub fn check(scenario: &str) -> Result<String, JsError> {
    check_json(scenario).map_err(|e| JsError::new(&e))
}

/// A TOML text as JSON text.
#[wasm_bindgen(js_name = tomlToJson)]
pub fn toml_to_json_js(text: &str) -> Result<String, JsError> {
    toml_to_json(text).map_err(|e| JsError::new(&e))
}

/// A scenario's JSON text as TOML text.
#[wasm_bindgen(js_name = jsonToToml)]
pub fn json_to_toml_js(text: &str) -> Result<String, JsError> {
    json_to_toml(text).map_err(|e| JsError::new(&e))
}

/// The keys a sweep can vary (dotted).
#[wasm_bindgen(js_name = sweepableKeys)]
pub fn sweepable_keys() -> String {
    json!(*rocking_scenario::SWEEPABLE_KEYS).to_string()
}

/// Every key's description, as `rocking keys --json` prints it: the JSON text
/// of `{ scenario: [{ key, section, name, kind, unit, symbol, label, default,
/// placeholder, range, meaning, example, choices, sweepable, on_form, types? }, …],
/// assessment: […] }`. The page builds its form from it.
#[wasm_bindgen]
pub fn keys() -> String {
    rocking_scenario::keys_json().to_string()
}

/// The summary's fields as the outputs reference describes them: the JSON
/// text of `[{ name, unit, meaning }, …]`, in the order of `summary.json`
/// (dotted names for nested ones), each block's as `<name>_max_abs_theta_rad`
/// …, `wall_time_s` last. The page labels its summary with them.
pub fn summary_fields_json() -> String {
    use rocking_scenario::columns::{SUMMARY, SUMMARY_BLOCKS, WALL_TIME};
    let field = |name: String, unit: &str, meaning: &str| json!({ "name": name, "unit": unit, "meaning": meaning });
    let fields: Vec<Value> = SUMMARY
        .iter()
        .map(|f| field(f.name.to_string(), f.unit, f.meaning))
        .chain(SUMMARY_BLOCKS.iter().map(|f| field(format!("<name>_{}", f.suffix), f.unit, f.meaning)))
        .chain([field(WALL_TIME.name.to_string(), WALL_TIME.unit, WALL_TIME.meaning)])
        .collect();
    Value::Array(fields).to_string()
}

/// The quantities of [`check`] that the summary may lack, described: the
/// JSON text of `[{ name, unit, meaning }, …]` (`rocking_scenario::columns::DERIVED`).
/// The page labels its table of derived quantities with them.
#[wasm_bindgen(js_name = derivedFields)]
pub fn derived_fields() -> String {
    rocking_scenario::columns::derived_json().to_string()
}

/// See [`summary_fields_json`].
#[wasm_bindgen(js_name = summaryFields)]
pub fn summary_fields_js() -> String {
    summary_fields_json()
}

/// A sweep, run a block of cases at a time by the page's Web Worker (which
/// reports progress between blocks and is ended to cancel).
#[wasm_bindgen]
pub struct WebSweep {
    sweep: Sweep,
}

impl WebSweep {
    /// A sweep of `scenario` over `axes`, both JSON texts: `axes` is the
    /// `[sweep]` table as an object (`{"ground.frequency": {"from": 3, "to": 7,
    /// "steps": 41}, "ground.amplitude": [0.5, 1]}`), the first key slowest.
    pub fn create(scenario: &str, axes: &str) -> Result<Self, String> {
        let parse = |text: &str| serde_json::from_str::<Value>(text).map_err(|e| format!("{ORIGIN}: not a JSON object: {e}"));
        let mut value = parse(scenario)?;
        let Value::Object(map) = &mut value else {
            return Err(format!("{ORIGIN}: expected a JSON object"));
        };
        map.insert("sweep".into(), parse(axes)?);
        let sweep = Sweep::from_json(value, origin()).map_err(|e| e.to_string())?;
        Ok(Self { sweep })
    }
}

#[wasm_bindgen]
impl WebSweep {
    /// See [`WebSweep::create`].
    #[wasm_bindgen(constructor)]
    pub fn new(scenario: &str, axes: &str) -> Result<WebSweep, JsError> {
        Self::create(scenario, axes).map_err(|e| JsError::new(&e))
    }

    /// The number of cases.
    #[wasm_bindgen(getter)]
    pub fn length(&self) -> usize {
        self.sweep.len()
    }

    /// The columns of `sweep.csv`, as a JSON array.
    pub fn header(&self) -> String {
        json!(self.sweep.header()).to_string()
    }

    /// The header line of `sweep.csv` (without its line break).
    #[wasm_bindgen(js_name = csvHeader)]
    pub fn csv_header(&self) -> String {
        self.sweep.csv_header()
    }

    /// Runs cases `start .. end` (clamped to the sweep) in order: the JSON
    /// text of `{ rows: [[cell, …], …], csv: "line\n…" }`, the rows' cells in
    /// header order (null for an empty cell) and the same rows as `sweep.csv`
    /// lines, each with its line break.
    #[wasm_bindgen(js_name = runCases)]
    pub fn run_cases(&self, start: usize, end: usize) -> String {
        let end = end.min(self.sweep.len());
        let mut rows = Vec::with_capacity(end.saturating_sub(start));
        let mut csv = String::new();
        for index in start..end {
            let row = self.sweep.run_case(index);
            csv.push_str(&row.to_csv_line());
            csv.push('\n');
            rows.push(Value::Array(row.cells.iter().map(output::cell).collect()));
        }
        json!({ "rows": rows, "csv": csv }).to_string()
    }
}

#[cfg(test)]
mod tests;
