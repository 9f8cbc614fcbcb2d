//! `summary.json`: the keys of the interface (interface.md, "Outputs of
//! `run`"), `null` where a quantity does not exist (the tower's without a
//! tower, the slip's without a building), plus a few additions.

use crate::run::Outcome;
use rocking::{EndReason, Motion};
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
pub fn summary_json(outcome: &Outcome, wall_time_s: f64) -> Value {
    let s = &outcome.summary;
    let d = &outcome.derived;
    let tower = d.alpha.is_some();
    let building = d.slip_acceleration_g.is_some();
    let if_tower = |v: f64| if tower { json!(v) } else { Value::Null };
    let if_building = |v: f64| if building { json!(v) } else { Value::Null };
    let mut regimes = Map::new();
    for m in Motion::ALL {
        regimes.insert(m.as_str().to_string(), json!(s.time_in(m)));
    }
    json!({
        "name": outcome.name,
        "alpha_rad": d.alpha,
        "R_m": d.radius,
        "p_rad_s": d.p,
        "restitution": d.restitution,
        "uplift_acceleration_g": d.uplift_acceleration_g,
        "slip_acceleration_g": d.slip_acceleration_g,
        "max_abs_theta_rad": if_tower(s.max_abs_theta()),
        "max_theta_over_alpha": d.alpha.map(|a| s.max_abs_theta() / a),
        "max_abs_slip_m": if_building(s.max_abs_slip),
        "final_slip_m": if_building(s.final_slip),
        "impacts": if tower { json!(s.impacts) } else { Value::Null },
        "overturned": s.overturned(),
        "overturn_time_s": s.overturn_time,
        "first_uplift_time_s": s.first_uplift_time,
        "first_slip_time_s": s.first_slip_time,
        "max_top_displacement_m": if_tower(s.max_top_displacement),
        "max_top_abs_acceleration_m_s2": if_tower(s.max_top_abs_acceleration),
        "max_pivot_friction_demand": if_tower(s.max_pivot_friction_demand),
        "tower_uplift_detected": s.tower_uplift_detected,
        "time_in_regime_s": regimes,
        "end_time_s": s.end_time,
        "end_reason": match s.end_reason {
            EndReason::EndOfDuration => "end_of_duration",
            EndReason::Overturned => "overturned",
        },
        "min_theta_rad": if_tower(s.theta_range.0),
        "max_theta_rad": if_tower(s.theta_range.1),
        "events": s.events,
        "rhs_evaluations": s.evaluations,
        "wall_time_s": wall_time_s,
    })
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
