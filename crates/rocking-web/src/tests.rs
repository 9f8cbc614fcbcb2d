//! The page's functions against a second path to the same answer: the TOML
//! file parsed by the scenario crate directly (as `rocking run` does).

use super::*;
use rocking_scenario::{summary_json, RunOptions};

const TOWER: &str = include_str!("../../../examples/tower-on-church.toml");

fn parsed(text: &str) -> Value {
    serde_json::from_str(text).unwrap_or_else(|e| panic!("{e}: {text}"))
}

#[test]
fn a_toml_file_through_json_runs_as_the_file_itself() {
    let json = toml_to_json(TOWER).unwrap_or_else(|e| panic!("{e}"));
    let out = parsed(&run_json(&json).unwrap_or_else(|e| panic!("{e}")));
    let direct = Scenario::from_toml_str(TOWER, origin())
        .and_then(|s| s.build())
        .and_then(|c| c.run(RunOptions::ALL));
    let direct = direct.unwrap_or_else(|e| panic!("{e}"));
    // The same table reaches the same code: every field equal to the last bit.
    assert_eq!(out["summary"], summary_json(&direct, 0.0));
    let rows = direct.history.as_ref().map_or(0, |h| h.samples.len());
    let history = out["history"].as_object().cloned().unwrap_or_default();
    // history.csv's header, as the command writes it from the same descriptors.
    let header = rocking_scenario::columns::history_header(rocking_scenario::columns::HISTORY, rocking_scenario::columns::HISTORY_POINTS, &direct.layout);
    assert_eq!(history.keys().cloned().collect::<Vec<_>>(), header);
    // The example's 2 extra points: 2 columns each beyond the 9 of every run.
    assert_eq!(history.len(), 9 + 2 * 2);
    for (name, column) in &history {
        assert_eq!(column.as_array().map(Vec::len), Some(rows), "{name}");
    }
    assert_eq!(out["events"].as_array().map(Vec::len), Some(direct.events.len()));
    // The round trip to TOML gives the same table back (the page's download).
    let toml = json_to_toml(&json).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(toml_to_json(&toml), Ok(json));
}

#[test]
fn errors_are_the_commands_one_line() {
    let bad = toml_to_json(&TOWER.replace("width = 4.0 ", "width = -4.0 ")).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(
        run_json(&bad),
        Err("scenario.toml: tower.width: must be a finite number > 0, got -4".to_string())
    );
    let e = toml_to_json("[tower\nwidth = 1").err().unwrap_or_default();
    assert!(e.starts_with("scenario.toml: line 1") && !e.contains('\n'), "{e}");
    assert!(run_json("[1, 2]").is_err_and(|e| e.starts_with("scenario.toml: ") && !e.contains('\n')));
}

#[test]
fn a_sweep_block_by_block_gives_one_row_per_case() {
    let scenario = toml_to_json(TOWER).unwrap_or_else(|e| panic!("{e}"));
    let sweep = WebSweep::create(&scenario, r#"{"ground.frequency": [4.0, 5.0, 6.0], "ground.amplitude": [0.5, 1.5]}"#).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(sweep.length(), 6);
    let header = parsed(&sweep.header());
    let width = header.as_array().map_or(0, Vec::len);
    // Blocks of 4 then the rest (past the end is clamped): 6 rows in case order.
    let blocks = [parsed(&sweep.run_cases(0, 4)), parsed(&sweep.run_cases(4, 100))];
    let rows: Vec<Value> = blocks.iter().flat_map(|b| b["rows"].as_array().cloned().unwrap_or_default()).collect();
    assert_eq!(rows.len(), 6);
    for (i, row) in rows.iter().enumerate() {
        assert_eq!(row.as_array().map(Vec::len), Some(width));
        // The first axis varies slowest.
        assert_eq!(row[0], json!([4.0, 5.0, 6.0][i / 2]));
        assert_eq!(row[1], json!([0.5, 1.5][i % 2]));
        assert_eq!(row[width - 1], Value::Null, "case {i} failed");
    }
    // The fifth case (6 Hz, 0.5 g) as a scenario of its own: the same max θ/α.
    let one = scenario
        .replace("\"frequency\":5.0", "\"frequency\":6.0")
        .replace("\"amplitude\":1.5", "\"amplitude\":0.5");
    let single = parsed(&run_json(&one).unwrap_or_else(|e| panic!("{e}")));
    let column = header.as_array().and_then(|h| h.iter().position(|c| c == "max_theta_over_alpha")).unwrap_or(0);
    assert_eq!(rows[4][column], single["summary"]["max_theta_over_alpha"]);
    let csv = format!("{}{}", blocks[0]["csv"].as_str().unwrap_or(""), blocks[1]["csv"].as_str().unwrap_or(""));
    assert_eq!(csv.lines().count(), 6);
}

#[test]
fn the_typed_columns_hold_the_json_history() {
    let json = toml_to_json(TOWER).unwrap_or_else(|e| panic!("{e}"));
    let full = parsed(&run_json(&json).unwrap_or_else(|e| panic!("{e}")));
    let case = scenario(&json)
        .and_then(|s| s.build().map_err(|e| e.to_string()))
        .unwrap_or_else(|e| panic!("{e}"));
    let outcome = case.run(rocking_scenario::RunOptions::ALL).unwrap_or_else(|e| panic!("{e}"));
    let (meta, columns) = output::outcome_parts(&outcome);
    assert_eq!(meta["summary"], full["summary"]);
    assert_eq!(meta["events"], full["events"]);
    assert_eq!(meta["text"]["regime"], full["history"]["regime"]);
    let names: Vec<&str> = meta["columns"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    // The JSON history's keys are `order`, and the numeric names are `order` without `regime`.
    let order: Vec<&str> = meta["order"]
        .as_array()
        .map(|a| a.iter().filter_map(Value::as_str).collect())
        .unwrap_or_default();
    let keys: Vec<&str> = full["history"].as_object().map(|m| m.keys().map(String::as_str).collect()).unwrap_or_default();
    assert_eq!(keys, order);
    assert_eq!(names, order.iter().copied().filter(|n| *n != "regime").collect::<Vec<_>>());
    for (name, column) in names.iter().zip(&columns) {
        assert_eq!(&json!(column), &full["history"][*name], "{name}");
    }
}

#[test]
fn the_summary_fields_are_the_keys_of_a_summary_in_order() {
    // An independent walk of a run's summary object: its keys, nested ones dotted.
    let json = toml_to_json(TOWER).unwrap_or_else(|e| panic!("{e}"));
    let summary = &parsed(&run_json(&json).unwrap_or_else(|e| panic!("{e}")))["summary"];
    let mut keys = Vec::new();
    for (k, v) in summary.as_object().into_iter().flatten() {
        match v.as_object() {
            Some(inner) => keys.extend(inner.keys().map(|i| format!("{k}.{i}"))),
            None => keys.push(k.clone()),
        }
    }
    let fields = parsed(&summary_fields_json());
    let names: Vec<String> = fields
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|f| f["name"].as_str().map(String::from))
        .collect();
    // Every field, in order; the summary of this scenario (no vertical motion, no block on the tower) lacks only the vertical's and the stack's
    // (each block's described once, as `<name>_…`).
    let present: Vec<String> = names.iter().filter(|n| keys.contains(n)).cloned().collect();
    assert_eq!(present, keys);
    let absent: Vec<&String> = names.iter().filter(|n| !keys.contains(n)).collect();
    let blocks: Vec<String> = [
        "max_abs_theta_rad",
        "max_theta_over_alpha",
        "impacts",
        "first_uplift_time_s",
        "overturned",
        "max_friction_demand",
    ]
    .iter()
    .map(|s| format!("<name>_{s}"))
    .collect();
    let mut expected: Vec<&str> = vec!["min_effective_gravity_m_s2", "max_seat_impulse_ratio", "overturned_block"];
    expected.extend(blocks.iter().map(String::as_str));
    assert_eq!(absent, expected);
    // Each has a meaning to show; the end state is described as the reference does.
    let end = fields
        .as_array()
        .into_iter()
        .flatten()
        .find(|f| f["name"] == "end_state")
        .cloned()
        .unwrap_or_default();
    assert!(end["meaning"].as_str().is_some_and(|m| m.contains("beyond_stability_limit")), "{end}");
}

/// El Centro's text as a scenario's record, and the same file as `rocking spectrum` reads it.
const ELCENTRO: &str = include_str!("../../../data/records/elcentro_1940_ns.AT2");

#[test]
fn a_records_spectrum_is_the_one_rocking_spectrum_computes() {
    let scenario = json!({"tower": {"width": 3, "height": 18, "density": 1800}, "ground": {"type": "record", "text": ELCENTRO}});
    let out = parsed(&record_spectrum_json(&scenario.to_string(), 5.0).unwrap_or_else(|e| panic!("{e}")));
    // The command's path: the file read by read_record (format guessed, in g), its spectrum in g.
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/records/elcentro_1940_ns.AT2");
    let record = rocking_scenario::read_record(&path, 9.81).unwrap_or_else(|e| panic!("{e}"));
    let periods = rocking_codes::DEFAULT_PERIODS.periods().unwrap_or_else(|e| panic!("{e}"));
    let psa = rocking_scenario::record_spectra_in_g(&[record], &periods, 5.0, 9.81).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(out["periods_s"], json!(periods));
    assert_eq!(out["psa_g"], json!(psa[0]));
    // The AT2's header: NPTS = 1559, DT = .0200; its largest |a| is 0.31882 g, as the
    // file prints it (× g then / g: within an ulp or two).
    assert_eq!(out["t_s"].as_array().map(Vec::len), Some(1559));
    let pga = out["pga_g"].as_f64().unwrap_or_default();
    assert!((pga - 0.31882).abs() < 1e-15, "{pga}");
}

#[test]
fn a_spectrum_needs_a_record_and_a_damping_in_range() {
    let harmonic = r#"{"tower": {"width": 1, "height": 4, "density": 2400}, "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 2}}"#;
    let e = record_spectrum_json(harmonic, 5.0).err().unwrap_or_default();
    assert!(e.starts_with("scenario.toml: ground.type: a response spectrum is a record's"), "{e}");
    let record = json!({"tower": {"width": 1, "height": 4, "density": 2400}, "ground": {"type": "record", "text": ELCENTRO}}).to_string();
    let e = record_spectrum_json(&record, 100.0).err().unwrap_or_default();
    assert_eq!(e, "damping: must be a percentage of critical in [0, 100), got 100");
}

/// The tower of the assessment crate's example: 4 m × 12 m, 150 t, on subsoil B.
fn assessment(q: &str) -> String {
    format!(
        r#"{{"tower": {{"width": 4, "height": 12, "mass": 1.5e5}},
        "site": {{"soil": "B", "SLD": {{"ag": 0.062, "F0": 2.52, "Tc_star": 0.30}}, "SLV": {{"ag": 0.155, "F0": 2.47, "Tc_star": 0.36}},
                 "SLC": {{"ag": 0.196, "F0": 2.50, "Tc_star": 0.37}}}},
        "assessment": {{"confidence_factor": 1.35, "q": {q}}}}}"#
    )
}

#[test]
fn the_assessment_is_the_capacity_and_the_kinematic_checks() {
    let out = parsed(&assess_json(&assessment("2")).unwrap_or_else(|e| panic!("{e}")));
    // α0 = b/h = 1/3; one rigid block: e* = 1, a0* = α0 g / (e* FC); d0 = R sin α = b = 2 m
    // (the centre of mass carried over the corner).
    let c = &out["capacity"];
    let close = |v: &Value, x: f64| (v.as_f64().unwrap_or(f64::NAN) - x).abs() <= 1e-12 * x.abs();
    assert!(close(&c["alpha0"], 1.0 / 3.0), "{c}");
    assert!(close(&c["a0_star_m_s2"], 9.81 / 3.0 / 1.35), "{c}");
    assert!(close(&c["d0_m"], 2.0), "{c}");
    let methods: Vec<&str> = out["checks"].as_array().into_iter().flatten().filter_map(|c| c["method"].as_str()).collect();
    assert_eq!(methods, ["activation", "linear_kinematic", "nonlinear_kinematic", "nonlinear_kinematic"]);
    // The SLD activation demand a_g S(a_g) (eq. C8.7.1.8) in m/s²: S = SS ST with SS = 1.2
    // (clamped: 1.40 − 0.40·2.52·0.062 > 1.2) and ST = 1 (T1); 1e-12 covers the rounding of three products.
    let demand = out["checks"][0]["demand"].as_f64().unwrap_or_default();
    assert!((demand - 0.062 * 1.2 * 9.81).abs() < 1e-12, "{demand}");
    // The governing check is the worse of SLV's and SLC's non-linear kinematic
    // checks (the most refined computed without records).
    let least = out["checks"]
        .as_array()
        .into_iter()
        .flatten()
        .filter(|c| c["method"] == "nonlinear_kinematic")
        .filter_map(|c| c["zeta_E"].as_f64())
        .fold(f64::INFINITY, f64::min);
    assert_eq!(out["governing"]["zeta_E"].as_f64(), Some(least));
    assert_eq!(out["curve"].as_array().map(Vec::len), Some(rocking_assess::CAPACITY_POINTS));
}

#[test]
fn assessment_errors_name_the_key() {
    let e = assess_json(&assessment("0")).err().unwrap_or_default();
    assert!(e.starts_with("assess.toml: assessment.q: "), "{e}");
    let e = assess_json(r#"{"tower": {"width": 4, "height": 12, "mass": 1.5e5}, "site": {"soil": "B", "SLV": {"ag": 0.155, "F0": 2.47, "Tc_star": 0.36}}}"#)
        .err()
        .unwrap_or_default();
    assert!(e.starts_with("assess.toml: site.SLD: missing [site.SLD]"), "{e}");
    let e = assess_json(&assessment("2").replace("0.155", "-0.155")).err().unwrap_or_default();
    assert!(e.starts_with("assess.toml: site.SLV.ag: "), "{e}");
}

const GRID: &str = include_str!("../../../data/hazard/synthetic_grid.txt");

#[test]
fn a_grid_site_on_a_node_is_the_nodes_values_interpolated_in_the_return_period() {
    let out = parsed(&grid_site_json(GRID, 14.30, 40.95, 50.0, 1.0).unwrap_or_else(|e| panic!("{e}")));
    // Node 40001; SLV: P_VR = 10%, TR = −50 / ln 0.9 = 474.56 years, between the
    // grid's 201 and 475: log-log between ag 1.115 and 1.600 (g/10) (NTC Allegato A).
    let tr = -50.0 / 0.9f64.ln();
    let ag = (0.1115f64.ln() + (0.1600f64 / 0.1115).ln() * (tr / 201.0).ln() / (475.0f64 / 201.0).ln()).exp();
    let got = out["SLV"]["ag"].as_f64().unwrap_or_default();
    assert!((got - ag).abs() < 1e-12, "{got} {ag}");
    let e = grid_site_json(GRID, 9.0, 45.0, 50.0, 1.0).err().unwrap_or_default();
    assert!(e.starts_with("site.lon: "), "{e}");
    let e = grid_site_json(GRID, 14.30, 40.95, -1.0, 1.0).err().unwrap_or_default();
    assert!(e.starts_with("site.VN: "), "{e}");
}

/// The page's description of the keys is every key of the scenario table,
/// in order, with a hand-checked sample of what its form shows (units,
/// choices, the types of [ground] that take a key).
#[test]
fn the_keys_are_every_scenario_key() {
    let described = parsed(&keys());
    let keys: Vec<&str> = described["scenario"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|k| k["key"].as_str())
        .collect();
    let table: Vec<&str> = rocking_scenario::SCENARIO_KEYS.iter().map(|k| k.key).collect();
    assert_eq!(keys, table);
    let of = |key: &str| {
        described["scenario"]
            .as_array()
            .into_iter()
            .flatten()
            .find(|k| k["key"] == key)
            .cloned()
            .unwrap_or_default()
    };
    assert_eq!(
        (of("tower.density")["unit"].clone(), of("tower.density")["on_form"].clone()),
        (json!("kg/m³"), json!(true))
    );
    assert_eq!(of("tower.alpha")["on_form"], json!(false));
    assert_eq!(of("building.normal_force")["choices"], json!(["constant", "dynamic"]));
    assert_eq!(of("ground.t0")["types"], json!(["ricker"]));
    assert_eq!(of("ground.t0")["placeholder"], json!("1.5 / f"));
    assert_eq!(of("ground.vertical")["kind"], json!("table"));
}
