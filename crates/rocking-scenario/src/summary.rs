//! `summary.json`: the keys of the outputs reference
//! (docs/src/reference/outputs.md), `null` where a quantity does not exist (the tower's without a
//! tower, the slip's without a building), plus a few additions.

use crate::columns::{block_fields_of, fields_of, SUMMARY};
use crate::run::Outcome;
use crate::sweep::{Cell, WALL_TIME_KEY};
use serde_json::{json, Map, Value};

/// The summary of a run as a JSON object, `wall_time_s` the run's wall-clock time (s).
///
/// Required keys: `alpha_rad`, `R_m`, `p_rad_s`, `restitution`,
/// `uplift_acceleration_g`, `slip_acceleration_g`, `max_abs_theta_rad`,
/// `max_theta_over_alpha`, `max_abs_slip_m`, `final_slip_m`, `impacts`,
/// `overturned`, `overturn_time_s`, `first_uplift_time_s`, `first_slip_time_s`,
/// `max_top_displacement_m`, `max_top_abs_acceleration_m_s2`,
/// `max_pivot_friction_demand`, `tower_uplift_detected`, `time_in_regime_s`
/// (`rest`, `rocking`, `sliding`, `rocking_sliding`), `wall_time_s`.
/// Additions: `name`, `end_time_s`, `end_reason` (`"end_of_duration"` |
/// `"overturned"`), `min_theta_rad`, `max_theta_rad`, `events` (count),
/// `rhs_evaluations`.
///
/// Without a tower the tower's quantities (and `impacts`) are `null`, its
/// booleans `false`; without a building the slip quantities are `null`.
///
/// The fields are those of [`summary_fields`], in its order (a dotted name
/// `time_in_regime_s.rest` becomes a nested object), then `wall_time_s`.
pub fn summary_json(outcome: &Outcome, wall_time_s: f64) -> Value {
    let mut map = Map::new();
    for (key, cell) in summary_fields(outcome) {
        let value = cell_json(cell);
        match key.split_once('.') {
            Some((outer, inner)) => {
                if let Value::Object(nested) = map.entry(outer).or_insert_with(|| Value::Object(Map::new())) {
                    nested.insert(inner.to_string(), value);
                }
            }
            None => {
                map.insert(key, value);
            }
        }
    }
    map.insert(WALL_TIME_KEY.to_string(), json!(wall_time_s));
    Value::Object(map)
}

/// Every field of the summary but the wall time ([`crate::columns::SUMMARY`]
/// present in the outcome's layout), in the order of `summary.json`, nested ones with dotted names (`time_in_regime_s.rest`):
/// the columns of `sweep.csv`, taken without building any JSON. An absent
/// quantity (`null` in the JSON) is [`Cell::Empty`].
pub fn summary_fields(outcome: &Outcome) -> Vec<(String, Cell)> {
    let mut fields = fields_of(SUMMARY, &outcome.layout, outcome);
    fields.extend(block_fields_of(outcome));
    fields
}

/// The JSON value of a summary cell (`null` for an empty one).
fn cell_json(cell: Cell) -> Value {
    match cell {
        Cell::Empty => Value::Null,
        Cell::Bool(b) => json!(b),
        Cell::Int(i) => json!(i),
        Cell::Float(x) => json!(x),
        Cell::Text(t) => Value::String(t),
    }
}

/// The scalar fields of a summary, in order, nested objects flattened with
/// dotted names (`time_in_regime_s.rest`); arrays are left out. The columns of
/// a sweep's `sweep.csv`.
pub fn summary_scalars(summary: &Value) -> Vec<(String, Value)> {
    let mut out = Vec::new();
    flatten(summary, "", &mut out);
    out
}

fn flatten(value: &Value, prefix: &str, out: &mut Vec<(String, Value)>) {
    match value {
        Value::Object(map) => {
            for (k, v) in map {
                if prefix.is_empty() {
                    flatten(v, k, out);
                } else {
                    flatten(v, &format!("{prefix}.{k}"), out);
                }
            }
        }
        Value::Array(_) => {}
        scalar => out.push((prefix.to_string(), scalar.clone())),
    }
}
