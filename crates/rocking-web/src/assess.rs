//! The assessment to the code for the page's assess tab: the capacity of the
//! tower and the kinematic checks of `rocking assess` (rocking-assess), and
//! the site parameters of a hazard grid at a site (rocking-codes), so that a
//! grid's site fills the page's fields with the numbers the command uses.

use rocking_assess::{assessment_json, AssessmentInput, CAPACITY_POINTS};
use rocking_codes::{HazardGrid, LimitState};
use serde_json::{json, Value};
use std::path::Path;
use wasm_bindgen::prelude::*;

/// The name of the page's assessment in error lines.
pub const ASSESS_ORIGIN: &str = "assess.toml";

/// The kinematic part of `rocking assess` for an assessment file given as the
/// JSON text of its table (the scenario's sections without `[ground]`, plus
/// `[site]` with each limit state's table and `[assessment]` without
/// `records`): the JSON text of `assessment.json` as the command writes it
/// without a record set (`capacity`, `sites`, `checks`, `governing`), plus
/// `curve`, the capacity curve `[[d*, a*], …]` of `capacity.csv`. An error is
/// the command's one line, the file named `assess.toml`.
pub fn assess_json(text: &str) -> Result<String, String> {
    let value: Value = serde_json::from_str(text).map_err(|e| format!("{ASSESS_ORIGIN}: not a JSON object: {e}"))?;
    let table: toml::Table = serde_json::from_value(crate::strip_nulls(value)).map_err(|e| format!("{ASSESS_ORIGIN}: {e}"))?;
    let input = AssessmentInput::from_table(table, Path::new(ASSESS_ORIGIN)).map_err(|e| e.to_string())?;
    if !input.file.records.is_empty() {
        return Err(format!(
            "{ASSESS_ORIGIN}: assessment.records: the page runs the kinematic checks only: run the dynamic ones with rocking assess"
        ));
    }
    let capacity = input.capacity().map_err(|e| e.to_string())?;
    let checks = input.kinematic_checks(&capacity).map_err(|e| e.to_string())?;
    let mut out = assessment_json(input.name(), &capacity, &input.site, &checks, None);
    if let Value::Object(map) = &mut out {
        map.insert("curve".into(), json!(capacity.curve_points(CAPACITY_POINTS)));
    }
    Ok(out.to_string())
}

/// The NTC site parameters of SLD, SLV and SLC at a site of a hazard grid
/// (the text of its file, in the layout of NTC Allegato B): the JSON text of
/// `{ "SLD": { "ag", "F0", "Tc_star" }, … }` for the nominal life `VN` and
/// the coefficient of use `CU`, each the value `rocking assess` computes for
/// `[site]` with `grid`, `lon`, `lat`, `VN`, `CU`. An error names the key.
pub fn grid_site_json(grid: &str, lon: f64, lat: f64, nominal_life: f64, use_coefficient: f64) -> Result<String, String> {
    let grid = HazardGrid::parse(grid).map_err(|e| format!("site.grid: {e}"))?;
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
