//! `rocking run`: the three files, their headers and rows, and a summary that
//! does not depend on the output spacing.

use crate::util::{arg, read, rocking, rocking_in, root, scenario_with, tempdir, write, SCENARIO};
use serde_json::Value;

const HISTORY_HEADER: &str = "t,ground_acc,theta,theta_dot,slip,slip_vel,top_dx,top_abs_acc,regime";
const EVENTS_HEADER: &str = "t,kind,theta,theta_dot_before,theta_dot_after,slip_vel";

fn summary(dir: &std::path::Path) -> serde_json::Map<String, Value> {
    match serde_json::from_str(&read(&dir.join("summary.json"))) {
        Ok(Value::Object(map)) => map,
        other => panic!("summary.json is not an object: {other:?}"),
    }
}

#[test]
fn the_church_example_writes_the_three_files() {
    let out = tempdir();
    let r = rocking(&["run", "examples/tower-on-church.toml", "--out", arg(out.path())]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stderr.is_empty(), "{r:?}");
    assert!(r.stdout.contains("max θ/α"), "{}", r.stdout);
    assert!(r.stdout.contains(arg(out.path())), "the report says where the files went: {}", r.stdout);

    let history = read(&out.path().join("history.csv"));
    let mut lines = history.lines();
    // Two extra points in the example: p1 and p2.
    assert_eq!(lines.next(), Some(format!("{HISTORY_HEADER},p1_dx,p1_abs_acc,p2_dx,p2_abs_acc").as_str()));
    // 15 s every 5 ms.
    assert_eq!(lines.count(), 3001);
    let events = read(&out.path().join("events.csv"));
    let header = events.lines().next().unwrap_or_default();
    assert!(header.starts_with(EVENTS_HEADER), "{header}");
    let kinds: Vec<&str> = events.lines().skip(1).filter_map(|l| l.split(',').nth(1)).collect();
    assert_eq!(kinds.first(), Some(&"uplift"), "1.5 g > tan α g: the tower lifts first");
    assert!(kinds.contains(&"impact") && kinds.contains(&"slip") && kinds.contains(&"stick"), "{kinds:?}");

    let s = summary(out.path());
    assert!(s["impacts"].as_u64().is_some_and(|n| n > 0), "{s:?}");
    assert!(s["max_abs_slip_m"].as_f64().is_some_and(|u| u > 0.0), "1.5 g > μs g: the church slides");
    assert_eq!(s["overturned"], Value::Bool(false));
    assert!(s["alpha_rad"].as_f64().is_some_and(|a| (a - (1.0f64 / 3.0).atan()).abs() < 1e-15));
}

#[test]
fn history_has_one_row_per_output_step_with_every_digit() {
    let dir = tempdir();
    let file = write(dir.path(), "small.toml", SCENARIO);
    let out = dir.path().join("o");
    let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let history = read(&out.join("history.csv"));
    let mut lines = history.lines();
    assert_eq!(lines.next(), Some(HISTORY_HEADER), "no extra points, no extra columns");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // floor(1.0 / 0.003) + 1 = 334.
    assert_eq!(rows.len(), (1.0f64 / 0.003).floor() as usize + 1);
    for row in &rows {
        assert_eq!(row.len(), 9, "{row:?}");
        assert!(["rest", "rocking", "sliding", "rocking_sliding"].contains(&row[8]), "{row:?}");
        for x in &row[..8] {
            assert!(x.parse::<f64>().is_ok_and(f64::is_finite), "{x} in {row:?}");
        }
    }
    // Row k is at k·dt, and ground_acc is in m/s²: 0.6 g sin(2π 5 t).
    for row in [&rows[1], &rows[100]] {
        let t: f64 = row[0].parse().unwrap_or(f64::NAN);
        let a: f64 = row[1].parse().unwrap_or(f64::NAN);
        let expected = 0.6 * 9.81 * (2.0 * std::f64::consts::PI * 5.0 * t).sin();
        assert!((a - expected).abs() < 1e-9 * 9.81, "t = {t}: {a} vs {expected}");
    }
    // Not rounded: some value carries more than 10 significant digits.
    assert!(rows.iter().any(|r| r[2].trim_start_matches(['-', '0', '.']).len() > 10), "θ looks rounded");
    assert!(rows.iter().any(|r| r[8] == "rocking"), "0.6 g > tan α g: the tower rocks");
}

#[test]
fn extra_points_add_two_columns_each() {
    let dir = tempdir();
    let file = write(
        dir.path(),
        "p.toml",
        &scenario_with("mass = 1.5e5\n", "mass = 1.5e5\npoints = [[0.0, 12.0], [2.0, 0.0]]\n"),
    );
    let out = dir.path().join("o");
    assert_eq!(rocking(&["run", arg(&file), "--out", arg(&out)]).code, Some(0));
    let history = read(&out.join("history.csv"));
    let mut lines = history.lines();
    assert_eq!(lines.next(), Some(format!("{HISTORY_HEADER},p1_dx,p1_abs_acc,p2_dx,p2_abs_acc").as_str()));
    for line in lines {
        let f: Vec<&str> = line.split(',').collect();
        // p1 is the top centre: the same displacement as top_dx.
        assert_eq!(f[9], f[6], "{line}");
    }
}

#[test]
fn the_summary_does_not_depend_on_the_output_spacing() {
    let dir = tempdir();
    let mut summaries = Vec::new();
    for dt in ["0.001", "0.05"] {
        let file = write(
            dir.path(),
            &format!("dt{dt}.toml"),
            &scenario_with("output_dt = 0.003", &format!("output_dt = {dt}")),
        );
        let out = dir.path().join(format!("out{dt}"));
        let r = rocking(&["run", arg(&file), "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{r:?}");
        let mut s = summary(&out);
        assert!(s.remove("wall_time_s").is_some_and(|w| w.is_f64()));
        summaries.push(s);
    }
    // Exactly equal numbers: the integration never depends on the output spacing.
    assert_eq!(summaries[0], summaries[1]);
}

/// The file the command writes is the library's summary of the same run (the
/// keys the outputs reference lists are checked on that summary, in
/// rocking-scenario's tests), with the wall time filled in.
#[test]
fn summary_json_is_the_summary_of_the_same_run() {
    let out = tempdir();
    let r = rocking(&["run", "examples/housner-block.toml", "--out", arg(out.path())]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let s = summary(out.path());
    let file = root().join("examples/housner-block.toml");
    let scenario = rocking_scenario::Scenario::from_toml_str(&read(&file), &file);
    let outcome = scenario.and_then(|s| s.build()).and_then(|c| c.run(rocking_scenario::RunOptions::SUMMARY));
    let outcome = outcome.unwrap_or_else(|e| panic!("{e}"));
    let wall = s.get("wall_time_s").and_then(Value::as_f64);
    assert!(wall.is_some_and(|w| w >= 0.0), "wall_time_s: {wall:?}");
    let expected = rocking_scenario::summary_json(&outcome, wall.unwrap_or(0.0));
    assert_eq!(Value::Object(s.clone()), expected);
    // A fixed base: no slip threshold, no slip.
    assert_eq!(s["slip_acceleration_g"], Value::Null);
    assert_eq!(s["max_abs_slip_m"], Value::Null);
    let regimes = s["time_in_regime_s"].as_object().cloned().unwrap_or_default();
    for r in ["rest", "rocking", "sliding", "rocking_sliding"] {
        assert!(regimes.get(r).is_some_and(Value::is_f64), "time_in_regime_s.{r}");
    }
    // The example's block rocks to about 0.7 α and survives (see its comments).
    let ratio = s["max_theta_over_alpha"].as_f64().unwrap_or(0.0);
    assert!(ratio > 0.5 && ratio < 1.0, "{ratio}");
    assert_eq!(s["overturned"], Value::Bool(false));
}

#[test]
fn out_defaults_to_out_slash_the_stem_in_the_current_folder() {
    let dir = tempdir();
    let scenarios = tempdir();
    let file = write(scenarios.path(), "my-case.toml", SCENARIO);
    let r = rocking_in(dir.path(), &["run", arg(&file)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    for f in ["summary.json", "history.csv", "events.csv"] {
        assert!(dir.path().join("out/my-case").join(f).is_file(), "{f} not in out/my-case");
    }
}

#[test]
fn plot_draws_the_two_figures_as_svg_and_png() {
    let out = tempdir();
    let file = write(out.path(), "s.toml", SCENARIO);
    let dir = out.path().join("o");
    let r = rocking(&["run", arg(&file), "--out", arg(&dir), "--plot"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stderr.is_empty(), "{r:?}");
    assert!(r.stdout.contains("theta.svg, theta.png, slip.svg, slip.png"), "{}", r.stdout);
    assert!(dir.join("summary.json").is_file());
    for name in ["theta.svg", "theta.png", "slip.svg", "slip.png"] {
        let bytes = std::fs::read(dir.join(name)).unwrap_or_else(|e| panic!("{name}: {e}"));
        assert!(bytes.len() > 1000, "{name} has only {} bytes", bytes.len());
        if name.ends_with(".png") {
            assert!(bytes.starts_with(b"\x89PNG\r\n\x1a\n"), "{name} does not start with the PNG signature");
        }
    }
    // The title (the scenario's name), the axis labels with their units, the legend.
    let theta = read(&dir.join("theta.svg"));
    for text in [
        "small",
        "rotation θ/α (–)",
        "a_g (g)",
        "time t (s)",
        "θ/α",
        "impact",
        "±tan α = ±0.333 g: uplift",
    ] {
        assert!(theta.contains(text), "theta.svg lacks {text:?}");
    }
    let slip = read(&dir.join("slip.svg"));
    // 0.6 g < μs: the church does not slide; the top moves by some mm.
    for text in ["small", "slip u (mm)", "top Δx (mm)", "time t (s)", "the building did not slide"] {
        assert!(slip.contains(text), "slip.svg lacks {text:?}");
    }
}

#[test]
fn plot_never_overwrites_an_input_named_like_a_figure() {
    let dir = tempdir();
    let file = write(dir.path(), "theta.svg", SCENARIO);
    let r = rocking(&["run", arg(&file), "--out", arg(dir.path()), "--plot"]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("refusing to write"), "{}", r.stderr);
    assert_eq!(read(&file), SCENARIO);
}

#[test]
fn a_second_run_overwrites_the_tool_own_files() {
    let dir = tempdir();
    let out = dir.path().join("o");
    let first = write(dir.path(), "a.toml", SCENARIO);
    assert_eq!(rocking(&["run", arg(&first), "--out", arg(&out)]).code, Some(0));
    let second = write(dir.path(), "b.toml", &scenario_with("duration = 1.0", "duration = 0.5"));
    assert_eq!(rocking(&["run", arg(&second), "--out", arg(&out)]).code, Some(0));
    // 0.5 s every 3 ms: 167 rows, not the first run's 334.
    assert_eq!(read(&out.join("history.csv")).lines().count(), 1 + 167);
    assert_eq!(summary(&out)["end_time_s"].as_f64(), Some(0.5));
}

#[test]
fn a_record_scenario_runs() {
    let dir = tempdir();
    let mut csv = String::from("time,acceleration\n");
    for k in 0..=100 {
        let t = k as f64 * 0.01;
        csv.push_str(&format!("{t},{}\n", 0.8 * (2.0 * std::f64::consts::PI * 2.0 * t).sin()));
    }
    write(dir.path(), "quake.csv", &csv);
    let ground = "[ground]\ntype = \"record\"\nfile = \"quake.csv\"\nunits = \"g\"\n";
    let text = SCENARIO.split("[ground]").next().unwrap_or_default().to_string() + ground + "[simulation]\nduration = 2.0\n";
    let file = write(dir.path(), "rec.toml", &text);
    // Run from elsewhere: the record is found next to the scenario.
    let r = rocking(&["run", arg(&file), "--out", arg(&dir.path().join("o"))]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let s = summary(&dir.path().join("o"));
    assert!(s["first_uplift_time_s"].as_f64().is_some(), "0.8 g > tan α g: {s:?}");
}
