//! The JSON the page receives: a run's summary, history and events, the
//! derived quantities of `rocking check`, and the cells of a sweep row.
//!
//! Column and field names are those of the command's `history.csv`,
//! `events.csv` (rocking-cli's `output/history.rs` and `output/events.rs`)
//! and `summary.json` ([`rocking_scenario::summary_json`], used as is).

use rocking::{History, NormalForce};
use rocking_scenario::{record_format_name, summary_json, Case, Cell, Outcome};
use serde_json::{json, Map, Value};

/// The float columns of `history.csv` before `regime`.
pub const HISTORY_COLUMNS: [&str; 8] = ["t", "ground_acc", "theta", "theta_dot", "slip", "slip_vel", "top_dx", "top_abs_acc"];

/// `{ summary, history, events }` of a run (`wall_time_s` 0: the page times the call).
pub fn outcome_json(outcome: &Outcome) -> Value {
    let mut history = Map::new();
    if let Some(h) = &outcome.history {
        let columns = Columns::of(h);
        for (name, values) in columns.names.iter().zip(&columns.values) {
            history.insert(name.clone(), values.iter().map(|x| json!(x)).collect());
        }
        history.insert("regime".into(), json!(columns.regime));
        // `regime` comes after the 8 float columns of history.csv, before the points.
        let mut ordered = Map::new();
        for name in HISTORY_COLUMNS
            .iter()
            .copied()
            .chain(["regime"])
            .map(String::from)
            .chain(columns.names.iter().skip(8).cloned())
        {
            if let Some(v) = history.remove(&name) {
                ordered.insert(name, v);
            }
        }
        history = ordered;
    }
    json!({ "summary": summary_json(outcome, 0.0), "history": history, "events": events(outcome) })
}

/// The summary, the events and the names of the history's columns as JSON
/// (`columns`: the float columns in `history.csv` order, `regime` apart), and
/// the float columns themselves, handed to JavaScript as `Float64Array`s
/// (copying 10^5 numbers is far faster than printing and parsing them).
pub fn outcome_parts(outcome: &Outcome) -> (Value, Vec<Vec<f64>>) {
    let columns = outcome.history.as_ref().map(Columns::of).unwrap_or_default();
    let meta = json!({
        "summary": summary_json(outcome, 0.0),
        "events": events(outcome),
        "columns": columns.names,
        "regime": columns.regime,
    });
    (meta, columns.values)
}

/// The history as columns: the float columns of `history.csv` in its order
/// (the 8 before `regime`, then `pK_dx`, `pK_abs_acc` per extra point), and `regime`.
#[derive(Debug, Default)]
struct Columns {
    names: Vec<String>,
    values: Vec<Vec<f64>>,
    regime: Vec<&'static str>,
}

impl Columns {
    fn of(history: &History) -> Self {
        let samples = &history.samples;
        let getters: [fn(&rocking::Sample) -> f64; 8] = [
            |s| s.t,
            |s| s.ground_acc,
            |s| s.state.theta,
            |s| s.state.theta_dot,
            |s| s.state.slip,
            |s| s.state.slip_vel,
            |s| s.top_dx,
            |s| s.top_abs_acc,
        ];
        let mut names: Vec<String> = HISTORY_COLUMNS.iter().map(|c| c.to_string()).collect();
        let mut values: Vec<Vec<f64>> = getters.iter().map(|get| samples.iter().map(get).collect()).collect();
        let points = history.point_values.first().map_or(0, Vec::len);
        for k in 0..points {
            let column = |pick: fn(&(f64, f64)) -> f64| -> Vec<f64> { history.point_values.iter().map(|row| row.get(k).map_or(f64::NAN, pick)).collect() };
            names.push(format!("p{}_dx", k + 1));
            values.push(column(|v| v.0));
            names.push(format!("p{}_abs_acc", k + 1));
            values.push(column(|v| v.1));
        }
        let regime = samples.iter().map(|s| s.motion.as_str()).collect();
        Self { names, values, regime }
    }
}

/// The events as rows with the `events.csv` columns (`theta`, `slip_vel`,
/// `slip` after the event; `regime` the combined motion after it).
fn events(outcome: &Outcome) -> Value {
    outcome
        .events
        .iter()
        .map(|e| {
            json!({
                "t": e.time,
                "kind": e.kind.as_str(),
                "theta": e.after.theta,
                "theta_dot_before": e.before.theta_dot,
                "theta_dot_after": e.after.theta_dot,
                "slip_vel": e.after.slip_vel,
                "slip": e.after.slip,
                "regime": e.regime.motion().as_str(),
            })
        })
        .collect()
}

/// The quantities `rocking check` prints, named as in `summary.json` where
/// they appear there (`null` for an absent body): the tower's, the
/// building's, the ground motion's and the record's.
pub fn check(case: &Case) -> Value {
    let model = &case.model;
    let g = model.gravity();
    let d = model.derived();
    let building = model.building().map(|b| {
        json!({
            "mass_kg": b.mass(),
            "mu_static": b.mu_static(),
            "mu_kinetic": b.mu_kinetic(),
            "normal_force": match b.normal_force() {
                NormalForce::Constant => "constant",
                NormalForce::Dynamic => "dynamic",
            },
        })
    });
    let info = &case.ground_info;
    let record = info.record.as_ref().map(|r| {
        json!({
            "format": record_format_name(r.format),
            "samples": r.samples,
            "time_step_s": r.time_step_s,
            "duration_s": r.duration_s,
            "scale": r.scale,
        })
    });
    let (peak, peak_time) = case.ground.peak();
    json!({
        "name": case.name,
        "g_m_s2": g,
        "alpha_rad": d.alpha,
        "alpha_deg": d.alpha.map(f64::to_degrees),
        "R_m": d.radius,
        "p_rad_s": d.p,
        "restitution": d.restitution,
        "inertia_pivot_kg_m2": d.inertia_pivot,
        "tower_mass_kg": d.tower_mass,
        "sliding_mass_kg": d.sliding_mass,
        "uplift_acceleration_g": d.uplift_acceleration_g,
        "slip_acceleration_g": d.slip_acceleration_g,
        "points": case.points,
        "building": building,
        "ground": {
            "type": info.kind.as_str(),
            "amplitude_g": info.amplitude_g,
            "frequency_hz": info.frequency_hz,
            "phase_rad": info.phase_rad,
            "t0_s": info.t0_s,
            "end_time_s": info.end_time_s,
            "peak_acceleration_g": peak / g,
            "peak_time_s": peak_time,
            "record": record,
        },
    })
}

/// A sweep cell as JSON (`null` for an empty one).
pub fn cell(cell: &Cell) -> Value {
    match cell {
        Cell::Empty => Value::Null,
        Cell::Bool(b) => json!(b),
        Cell::Int(i) => json!(i),
        Cell::Float(x) => json!(x),
        Cell::Text(s) => json!(s),
    }
}
