//! The JSON the page receives: a run's summary, history and events, the
//! derived quantities of `rocking check`, and the cells of a sweep row.
//!
//! The history's columns and the events' keys are read from the column
//! descriptors the command's writers use (`rocking_scenario::columns`), in
//! the order of `history.csv` and `events.csv`, optional ones (extra points,
//! the vertical motion) included as the run's layout says; the summary is
//! [`rocking_scenario::summary_json`] as is.

use rocking::NormalForce;
use rocking_scenario::columns::{event_kind, history_header, Read, Value as CellValue, DERIVED, EVENTS, HISTORY, HISTORY_BLOCKS, HISTORY_POINTS, KIND};
use rocking_scenario::{record_format_name, summary_json, Case, Cell, Outcome};
use serde_json::{json, Map, Value};

/// `{ summary, history, events }` of a run (`wall_time_s` 0: the page times the call).
pub fn outcome_json(outcome: &Outcome) -> Value {
    let columns = Columns::of(outcome);
    let mut history = Map::new();
    // The numeric columns come in `order` with the text ones left out.
    let mut numbers = columns.values.iter();
    for name in &columns.order {
        let value = match columns.text.iter().find(|(n, _)| n == name) {
            Some((_, text)) => text.clone(),
            None => numbers.next().map_or(Value::Null, |values| json!(values)),
        };
        history.insert(name.clone(), value);
    }
    json!({ "summary": summary_json(outcome, 0.0), "history": history, "events": events(outcome) })
}

/// The summary, the events and the history's layout as JSON (`order`: every
/// column in `history.csv` order; `columns`: the numeric ones, in that order;
/// `text`: the text columns by name; `blocks`: the names of the blocks on the
/// tower), and the numeric columns themselves,
/// handed to JavaScript as `Float64Array`s (copying 10^5 numbers is far faster
/// than printing and parsing them).
pub fn outcome_parts(outcome: &Outcome) -> (Value, Vec<Vec<f64>>) {
    let columns = Columns::of(outcome);
    let meta = json!({
        "summary": summary_json(outcome, 0.0),
        "events": events(outcome),
        "event_columns": EVENTS.iter().filter(|c| (c.present)(&outcome.layout)).map(|c| c.name).collect::<Vec<_>>(),
        "order": columns.order,
        "columns": columns.names,
        "text": columns.text.into_iter().collect::<Map<String, Value>>(),
        "blocks": outcome.layout.blocks.iter().collect::<Vec<_>>(),
    });
    (meta, columns.values)
}

/// The history as columns, from the descriptors.
#[derive(Debug, Default)]
struct Columns {
    /// Every column, in `history.csv` order.
    order: Vec<String>,
    /// The numeric columns, in that order, and their values.
    names: Vec<String>,
    values: Vec<Vec<f64>>,
    /// The text columns (`regime`) by name.
    text: Vec<(String, Value)>,
}

impl Columns {
    fn of(outcome: &Outcome) -> Self {
        let Some(history) = &outcome.history else { return Self::default() };
        let layout = &outcome.layout;
        let samples = &history.samples;
        let mut columns = Self {
            order: history_header(HISTORY, HISTORY_POINTS, layout),
            ..Self::default()
        };
        for c in HISTORY.iter().filter(|c| (c.present)(layout)) {
            match c.read {
                Read::Number(f) => {
                    columns.names.push(c.name.to_string());
                    columns.values.push(samples.iter().map(f).collect());
                }
                Read::Text(f) => columns.text.push((c.name.to_string(), json!(samples.iter().map(f).collect::<Vec<_>>()))),
            }
        }
        for k in 0..layout.points {
            for p in HISTORY_POINTS {
                columns.names.push(format!("p{}_{}", k + 1, p.suffix));
                columns
                    .values
                    .push(history.point_values.iter().map(|row| row.get(k).map_or(f64::NAN, p.read)).collect());
            }
        }
        for (i, name) in layout.blocks.iter().enumerate() {
            for c in HISTORY_BLOCKS {
                columns.names.push(format!("{name}_{}", c.suffix));
                columns.values.push(samples.iter().map(|s| (c.read)(s, i + 1)).collect());
            }
        }
        columns
    }
}

/// The events as rows with the `events.csv` columns (a block's `kind` named by it: `belfry_uplift`).
fn events(outcome: &Outcome) -> Value {
    let columns: Vec<_> = EVENTS.iter().filter(|c| (c.present)(&outcome.layout)).collect();
    outcome
        .events
        .iter()
        .map(|e| {
            let row: Map<String, Value> = columns
                .iter()
                .map(|c| {
                    let value = match c.read.value(e) {
                        _ if c.name == KIND => json!(event_kind(&outcome.layout, e)),
                        CellValue::Number(x) => json!(x),
                        CellValue::Text(t) => json!(t),
                    };
                    (c.name.to_string(), value)
                })
                .collect();
            Value::Object(row)
        })
        .collect()
}

/// The quantities `rocking check` prints, named as in `summary.json` where
/// they appear there (`null` for an absent body): the name, the derived
/// quantities ([`DERIVED`]), the points, the building's, the ground motion's
/// and the record's.
pub fn check(case: &Case) -> Value {
    let model = &case.model;
    let g = model.gravity();
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
    let mut out = Map::new();
    out.insert("name".into(), json!(case.name));
    for q in DERIVED {
        out.insert(q.name.into(), json!((q.value)(model)));
    }
    out.insert("points".into(), json!(case.points));
    out.insert("blocks".into(), blocks(case));
    out.insert("building".into(), json!(building));
    out.insert(
        "ground".into(),
        json!({
            "type": info.kind.as_str(),
            "amplitude_g": info.amplitude_g,
            "frequency_hz": info.frequency_hz,
            "phase_rad": info.phase_rad,
            "t0_s": info.t0_s,
            "end_time_s": info.end_time_s,
            "peak_acceleration_g": peak / g,
            "peak_time_s": peak_time,
            "record": record,
        }),
    );
    Value::Object(out)
}

/// The blocks on the tower, the lowest first, as the engine holds them:
/// `[{ name, width_m, height_m, mass_kg, inertia_centre_kg_m2, alpha_rad,
/// uplift_acceleration_g }, …]`, the last the ground acceleration that lifts
/// the block off the one below from rest (what `rocking check` prints); empty
/// without blocks.
fn blocks(case: &Case) -> Value {
    let Some(stack) = case.model.stack() else { return json!([]) };
    let g = case.model.gravity();
    let thresholds = stack.uplift_thresholds();
    let above = stack.blocks().iter().zip(thresholds.iter()).enumerate().skip(1);
    above
        .map(|(k, (b, threshold))| {
            json!({
                "name": case.blocks.name(k),
                "width_m": b.width(),
                "height_m": b.height(),
                "mass_kg": b.mass(),
                "inertia_centre_kg_m2": b.inertia_centre(),
                "alpha_rad": b.alpha(),
                "uplift_acceleration_g": threshold / g,
            })
        })
        .collect()
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
