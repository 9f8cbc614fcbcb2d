//! Sweeps: expansion of lists and ranges, the order of cases, the columns,
//! rows that do not depend on the number of threads, failed cases that do not
//! stop the others, dimensionless axes, cancellation, and every class of error
//! in a sweep file.

use super::*;
use crate::summary_fields;
use crate::{summary_json, summary_scalars};
use std::convert::Infallible;
use std::sync::atomic::{AtomicBool, Ordering};

const ORIGIN: &str = "dir/sweep.toml";

/// The bell tower on its church, shaken for one second.
const BASE: &str = concat!(
    "name = \"t\"\n",
    include_str!("../../tests/data/church.toml"),
    r#"
[ground]
type = "harmonic"
amplitude = 0.5
frequency = 5.0

[simulation]
duration = 1.0
"#
);

fn sweep(axes: &str) -> Result<Sweep, crate::Error> {
    Sweep::from_toml_str(&format!("{BASE}\n[sweep]\n{axes}\n"), Path::new(ORIGIN))
}

fn ok(axes: &str) -> Sweep {
    sweep(axes).unwrap_or_else(|e| panic!("{axes}: {e}"))
}

/// The one-line error of a sweep file that must fail, checked to start with the file and `key`.
fn fails(axes: &str, key: &str) -> String {
    let e = match sweep(axes) {
        Ok(_) => panic!("{axes} should fail on {key}"),
        Err(e) => e.to_string(),
    };
    assert!(!e.contains('\n'), "one line: {e}");
    let prefix = format!("{ORIGIN}: {key}: ");
    assert!(e.starts_with(&prefix), "{e:?} should start with {prefix:?}");
    e[prefix.len()..].to_string()
}

/// The values of the one axis of `axes`, as numbers.
fn values(axes: &str) -> Vec<f64> {
    let s = ok(axes);
    s.axes()[0].values().iter().filter_map(crate::read::as_number).collect()
}

/// Every row of `sweep`, in the order they were passed on.
fn rows(sweep: &Sweep, threads: Option<usize>) -> Vec<Row> {
    let mut out = Vec::new();
    let done = sweep.run(threads, &AtomicBool::new(false), |row| {
        out.push(row);
        Ok::<(), Infallible>(())
    });
    let done = done.unwrap_or_else(|e| panic!("{e}"));
    assert_eq!((done.written, done.cancelled), (sweep.len(), false));
    out
}

fn column(sweep: &Sweep, name: &str) -> usize {
    sweep.header().iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"))
}

/// Decimal literals, as a file would give them.
fn literals(texts: &[&str]) -> Vec<f64> {
    texts.iter().map(|t| t.parse::<f64>().unwrap_or_else(|e| panic!("{t}: {e}"))).collect()
}

#[test]
fn steps_are_the_number_of_values_both_ends_included() {
    let expected: Vec<String> = (0..41).map(|i| format!("{}.{}", 3 + i / 10, i % 10)).collect();
    let expected = literals(&expected.iter().map(String::as_str).collect::<Vec<_>>());
    // Bit for bit the decimal a file would hold: 3.1 is written 3.1.
    assert_eq!(values(r#""ground.frequency" = { from = 3.0, to = 7.0, steps = 41 }"#), expected);
    assert_eq!(values(r#""ground.frequency" = { from = 1, to = 2, steps = 2 }"#), [1.0, 2.0]);
    assert_eq!(
        values(r#""ground.frequency" = { from = 2, to = 1, steps = 5 }"#),
        literals(&["2", "1.75", "1.5", "1.25", "1"])
    );
    assert_eq!(values(r#""ground.frequency" = { from = 2.5, to = 2.5, steps = 1 }"#), [2.5]);
    assert_eq!(
        values(r#""ground.amplitude" = { from = 0.1, to = 0.9, steps = 9 }"#),
        literals(&["0.1", "0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8", "0.9"])
    );
    // A value with no short decimal keeps the computed one, (from·2 + to·1) / 3.
    let thirds = values(r#""ground.amplitude" = { from = 0, to = 1, steps = 4 }"#);
    assert_eq!(thirds.len(), 4);
    approx::assert_relative_eq!(thirds[1], 1.0 / 3.0, max_relative = 1e-15);
    approx::assert_relative_eq!(thirds[2], 2.0 / 3.0, max_relative = 1e-15);
    // Symmetric about zero: the middle value is 0, not a rounding residue.
    assert_eq!(values(r#""initial.theta_dot" = { from = -0.3, to = 0.3, steps = 3 }"#), [-0.3, 0.0, 0.3]);
}

#[test]
fn a_step_gives_from_to_to_and_must_divide_the_range() {
    assert_eq!(
        values(r#""ground.frequency" = { from = 1.0, to = 7.0, step = 1.0 }"#),
        literals(&["1", "2", "3", "4", "5", "6", "7"])
    );
    assert_eq!(
        values(r#""ground.amplitude" = { from = 0.3, to = 0.9, step = 0.2 }"#),
        literals(&["0.3", "0.5", "0.7", "0.9"])
    );
    assert_eq!(
        values(r#""ground.amplitude" = { from = 0.9, to = 0.3, step = 0.2 }"#),
        literals(&["0.9", "0.7", "0.5", "0.3"])
    );
    assert_eq!(values(r#""ground.frequency" = { from = 3, to = 3, step = 0.5 }"#), [3.0]);
    let e = fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, step = 0.3 }"#,
        r#"sweep."ground.frequency".step"#,
    );
    assert!(e.starts_with("0.3 does not divide to − from = 1 (3.333333 steps)"), "{e}");
    let e = fails(r#""ground.frequency" = { from = 1.0, to = 2.0, step = 0 }"#, r#"sweep."ground.frequency".step"#);
    assert_eq!(e, "must be a finite number > 0, got 0");
    let e = fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, step = 1e-9 }"#,
        r#"sweep."ground.frequency".step"#,
    );
    assert!(e.contains("more than 1000000"), "{e}");
    // Five axes of 10,000 values each: more cases than a 64-bit usize counts.
    let big = r#"{ from = 1.0, to = 2.0, steps = 10000 }"#;
    let keys = ["ground.frequency", "ground.amplitude", "ground.phase", "ground.duration", "simulation.duration"];
    let axes: Vec<String> = keys.iter().map(|k| format!("\"{k}\" = {big}")).collect();
    if usize::BITS == 64 {
        assert_eq!(
            fails(&axes.join("\n"), "sweep"),
            "10000 × 10000 × 10000 × 10000 × 10000 values: too many combinations to count"
        );
    }
}

#[test]
fn lists_keep_their_values_and_types() {
    let s = ok(r#""ground.frequency" = [5, 2.5]
"building.normal_force" = ["constant", "dynamic"]"#);
    assert_eq!(s.axes()[0].values(), [Value::Integer(5), Value::Float(2.5)]);
    assert_eq!(s.axes()[1].values(), [Value::String("constant".into()), Value::String("dynamic".into())]);
    let r = s.run_case(3);
    assert_eq!(r.cells[..2], [Cell::Float(2.5), Cell::Text("dynamic".into())]);
    assert!(r.to_csv_line().starts_with("2.5,dynamic,t,"), "{}", r.to_csv_line());
}

#[test]
fn the_first_axis_varies_slowest() {
    let s = ok(r#""ground.amplitude" = [0.5, 0.6]
"ground.frequency" = [3.0, 4.0, 5.0]"#);
    assert_eq!(s.len(), 6);
    let pairs: Vec<(f64, f64)> = (0..6)
        .filter_map(|i| s.case_values(i))
        .map(|v| (crate::read::as_number(v[0]).unwrap_or(0.0), crate::read::as_number(v[1]).unwrap_or(0.0)))
        .collect();
    assert_eq!(pairs, [(0.5, 3.0), (0.5, 4.0), (0.5, 5.0), (0.6, 3.0), (0.6, 4.0), (0.6, 5.0)]);
    assert!(s.case_values(6).is_none());
    assert!(s.case_table(6).is_err());
    let t = s.case_table(4).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(crate::get_dotted(&t, "ground.frequency"), Some(&Value::Float(4.0)));
    assert_eq!(crate::get_dotted(&t, "ground.amplitude"), Some(&Value::Float(0.6)));
}

#[test]
fn unquoted_dotted_keys_are_the_same_axes() {
    let quoted = ok(r#""ground.frequency" = [3.0, 4.0]"#);
    let nested = ok("ground.frequency = [3.0, 4.0]");
    assert_eq!(quoted.axes(), nested.axes());
    let e = fails("ground.frequency = [3.0]\n\"ground.frequency\" = [4.0]", r#"sweep."ground.frequency""#);
    assert_eq!(e, "is given twice");
    // Three levels: a key of the vertical motion.
    let quoted = ok(r#""ground.vertical.type" = ["harmonic"]
"ground.vertical.frequency" = [5.0]
"ground.vertical.amplitude" = [0.1, 0.2]"#);
    let nested = ok(r#"ground.vertical.type = ["harmonic"]
ground.vertical.frequency = [5.0]
ground.vertical.amplitude = [0.1, 0.2]"#);
    assert_eq!(quoted.axes(), nested.axes());
    assert_eq!(nested.axes()[2].key(), "ground.vertical.amplitude");
}

#[test]
fn the_header_is_axes_then_summary_scalars_then_error() {
    let s = ok(r#""ground.frequency" = [3.0]"#);
    let h = s.header();
    assert_eq!(h[0], "ground.frequency");
    let outcome = s.scenario(0).and_then(|sc| sc.build()).and_then(|c| c.run(RunOptions::SUMMARY));
    let outcome = outcome.unwrap_or_else(|e| panic!("{e}"));
    let keys: Vec<String> = summary_scalars(&summary_json(&outcome, 1.0))
        .into_iter()
        .map(|(k, _)| k)
        .filter(|k| k != WALL_TIME_KEY)
        .collect();
    assert_eq!(h[1..h.len() - 1], keys[..]);
    assert!(keys.iter().any(|k| k == "time_in_regime_s.rocking_sliding"));
    assert_eq!(h.last().map(String::as_str), Some(ERROR_COLUMN));
    assert!(!h.iter().any(|k| k == WALL_TIME_KEY), "the wall time differs from run to run");
    assert!(s.csv_header().starts_with("ground.frequency,name,alpha_rad,"), "{}", s.csv_header());
}

#[test]
fn each_row_is_the_summary_of_its_case_run_alone() {
    let s = ok(r#""ground.amplitude" = [0.4, 1.5]
"ground.frequency" = [2.0, 5.0]"#);
    for row in rows(&s, Some(2)) {
        let mut t = crate::parse_toml(BASE, Path::new(ORIGIN)).unwrap_or_else(|e| panic!("{e}"));
        for (axis, cell) in s.axes().iter().zip(&row.cells) {
            let v = cell.as_f64().unwrap_or_else(|| panic!("{cell:?}"));
            crate::set_dotted(&mut t, axis.key(), Value::Float(v)).unwrap_or_else(|e| panic!("{e}"));
        }
        let alone = Scenario::from_table(t, Path::new(ORIGIN))
            .and_then(|sc| sc.build())
            .and_then(|c| c.run(RunOptions::ALL));
        let alone = alone.unwrap_or_else(|e| panic!("{e}"));
        let expected: Vec<Cell> = summary_scalars(&summary_json(&alone, 0.0))
            .iter()
            .filter(|(k, _)| k != WALL_TIME_KEY)
            .map(|(_, v)| Cell::from_json(v))
            .collect();
        assert_eq!(row.cells[2..row.cells.len() - 1], expected[..], "case {}", row.index);
        assert_eq!(row.error(), None);
    }
}

#[test]
fn rows_do_not_depend_on_the_number_of_threads() {
    // Cases of very different costs (no uplift, rocking, sliding, overturning) so that they finish out of order.
    let s = ok(r#""ground.amplitude" = [0.2, 0.6, 1.5, 3.0]
"ground.frequency" = { from = 1.0, to = 5.0, steps = 5 }"#);
    let one = rows(&s, Some(1));
    assert_eq!(one.iter().map(|r| r.index).collect::<Vec<_>>(), (0..s.len()).collect::<Vec<_>>());
    for threads in [Some(2), Some(4), None] {
        assert_eq!(rows(&s, threads), one, "{threads:?} threads");
    }
}

#[test]
fn a_failing_case_fills_its_error_and_the_others_run() {
    let s = ok(r#""building.mu_kinetic" = [0.5, 1.5, 1.0]"#);
    let rows = rows(&s, Some(2));
    let err = column(&s, ERROR_COLUMN);
    let peak = column(&s, "max_theta_over_alpha");
    assert_eq!(
        rows[1].error(),
        Some("building.mu_kinetic: 1.5 exceeds mu_static = 1.25; kinetic friction cannot exceed static friction")
    );
    assert!(rows[1].cells[1..err].iter().all(Cell::is_empty), "{:?}", rows[1]);
    assert_eq!(rows[1].cells[0], Cell::Float(1.5), "the axis value is kept");
    for r in [&rows[0], &rows[2]] {
        assert_eq!(r.error(), None);
        assert!(r.cells[peak].as_f64().is_some_and(|p| p > 0.0), "{r:?}");
        assert_eq!(r.cells[err], Cell::Empty);
    }
    let line = rows[1].to_csv_line();
    assert!(line.starts_with("1.5,,,"), "{line}");
    assert!(
        line.ends_with(",building.mu_kinetic: 1.5 exceeds mu_static = 1.25; kinetic friction cannot exceed static friction"),
        "{line}"
    );
}

#[test]
fn dimensionless_axes_give_the_rows_of_their_dimensional_equivalents() {
    let ratios = ok(r#""ground.amplitude_ratio" = [1.5, 3.0, 4.5]
"ground.frequency_ratio" = [1.0, 2.5, 6.0]"#);
    assert_eq!(ratios.len(), 9);
    // From the geometry, independently of the library: tan α = b/h = 1/3, p = sqrt(3 g / 4 R).
    let (b, h, g) = (2.0f64, 6.0f64, 9.81f64);
    let p = (3.0 * g / (4.0 * b.hypot(h))).sqrt();
    let amplitudes: Vec<String> = [1.5, 3.0, 4.5].iter().map(|r| (r * b / h).to_string()).collect();
    let frequencies: Vec<String> = [1.0, 2.5, 6.0].iter().map(|r| (r * p / (2.0 * std::f64::consts::PI)).to_string()).collect();
    let dimensional = ok(&format!(
        "\"ground.amplitude\" = [{}]\n\"ground.frequency\" = [{}]",
        amplitudes.join(", "),
        frequencies.join(", ")
    ));
    let (a, d) = (rows(&ratios, None), rows(&dimensional, None));
    let (ka, kd) = (column(&ratios, "max_theta_over_alpha"), column(&dimensional, "max_theta_over_alpha"));
    for (ra, rd) in a.iter().zip(&d) {
        let (x, y) = (ra.cells[ka].as_f64().unwrap_or(f64::NAN), rd.cells[kd].as_f64().unwrap_or(f64::NAN));
        assert!(x > 0.0, "every case rocks: {ra:?}");
        // The two conversions (tan(atan(b/h)) in the library, b/h here; p from R
        // and the decimal text) differ by an ulp or so, and the integration
        // carries that to its result amplified by the sensitivity of the
        // response (impacts, rounding of step sizes); 1e-9 is far above that
        // and far below the integration's own tolerance, rtol = 1e-8, which a
        // different sequence of steps would show.
        approx::assert_relative_eq!(x, y, max_relative = 1e-9);
    }
}

#[test]
fn an_axis_replaces_the_alternative_given_in_the_base() {
    // BASE gives amplitude and frequency; the ratios are swept instead.
    let s = ok(r#""ground.amplitude_ratio" = [1.5]"#);
    let t = s.case_table(0).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(crate::get_dotted(&t, "ground.amplitude"), None);
    assert_eq!(crate::get_dotted(&t, "ground.frequency"), Some(&Value::Float(5.0)));
    assert_eq!(rows(&s, Some(1))[0].error(), None);
    let e = fails(
        r#""ground.amplitude" = [0.5]
"ground.amplitude_ratio" = [1.5]"#,
        r#"sweep."ground.amplitude_ratio""#,
    );
    assert_eq!(e, "sweep either ground.amplitude or ground.amplitude_ratio, not both");
}

#[test]
fn cancelling_stops_after_the_cases_under_way_and_keeps_a_prefix() {
    // More cases than the window lets the workers run ahead of the rows passed on.
    let s = ok(&format!(r#""ground.amplitude" = {{ from = 0.4, to = 1.0, steps = {} }}"#, 3 * WINDOW));
    let cancel = AtomicBool::new(false);
    let mut seen = Vec::new();
    let done = s.run(Some(2), &cancel, |row| {
        seen.push(row.index);
        if seen.len() == 3 {
            cancel.store(true, Ordering::Relaxed);
        }
        Ok::<(), Infallible>(())
    });
    let done = done.unwrap_or_else(|e| panic!("{e}"));
    assert!(done.cancelled);
    assert!(done.written >= 3 && done.written < s.len(), "{done:?}");
    assert_eq!(seen, (0..done.written).collect::<Vec<_>>(), "rows in order, no gap");
}

#[test]
fn an_error_from_on_row_stops_the_run() {
    let s = ok(r#""ground.amplitude" = { from = 0.4, to = 1.0, steps = 20 }"#);
    let mut calls = 0;
    let r = s.run(Some(2), &AtomicBool::new(false), |_| {
        calls += 1;
        if calls == 2 {
            Err("disk full")
        } else {
            Ok(())
        }
    });
    assert!(matches!(r, Err(RunError::Stopped("disk full"))), "{r:?}");
    assert_eq!(calls, 2, "no row is passed on after the error");
}

#[test]
fn bad_axes_are_named_before_anything_runs() {
    let e = fails(r#""ground.frequncy" = [3.0]"#, r#"sweep."ground.frequncy""#);
    assert!(
        e.starts_with("unknown key (did you mean `ground.frequency`?); valid keys: ground.type, ground.amplitude,"),
        "{e}"
    );
    let e = fails(r#""colour" = [3.0]"#, r#"sweep."colour""#);
    assert!(e.starts_with("unknown key; valid keys: name, tower.width,"), "{e}");
    assert!(fails(r#""tower.points" = [1.0]"#, r#"sweep."tower.points""#).contains("not a scalar"));
    assert!(fails(r#""tower" = [1.0]"#, r#"sweep."tower""#).contains("is a section"));
    assert_eq!(
        fails(r#""ground.frequency" = []"#, r#"sweep."ground.frequency""#),
        "the list of values is empty: give at least one"
    );
    assert_eq!(
        fails(r#""ground.frequency" = 3.0"#, r#"sweep."ground.frequency""#),
        "expected a list of values or a range { from, to, steps } / { from, to, step }, got a float"
    );
    assert_eq!(
        fails(r#""ground.frequency" = [3.0, "x"]"#, r#"sweep."ground.frequency"[1]"#),
        "expected a number, got a string"
    );
    assert_eq!(
        fails(r#""ground.frequency" = [3.0, nan]"#, r#"sweep."ground.frequency"[1]"#),
        "must be a finite number, got NaN"
    );
    assert_eq!(fails(r#""ground.type" = [3.0]"#, r#"sweep."ground.type"[0]"#), "expected a string, got a float");
    assert!(fails(r#""ground.type" = { from = 1, to = 2, steps = 2 }"#, r#"sweep."ground.type""#).starts_with("expected a list of strings"));
    assert_eq!(
        fails(
            r#""ground.frequency" = { from = 1.0, to = 2.0, steps = 0 }"#,
            r#"sweep."ground.frequency".steps"#
        ),
        "must be an integer >= 1 (the number of values), got 0"
    );
    assert!(fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, steps = 1 }"#,
        r#"sweep."ground.frequency".steps"#
    )
    .starts_with("steps = 1 gives the single value from = 1"));
    assert!(fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, steps = 2.0 }"#,
        r#"sweep."ground.frequency".steps"#
    )
    .starts_with("expected an integer"));
    assert_eq!(
        fails(
            r#""ground.frequency" = { from = "a", to = 2.0, steps = 2 }"#,
            r#"sweep."ground.frequency".from"#
        ),
        "expected a number, got a string"
    );
    assert_eq!(
        fails(r#""ground.frequency" = { from = 1.0, to = inf, steps = 2 }"#, r#"sweep."ground.frequency".to"#),
        "must be a finite number, got inf"
    );
    assert!(fails(r#""ground.frequency" = { from = 1.0, steps = 2 }"#, r#"sweep."ground.frequency".to"#).starts_with("required"));
    assert!(fails(r#""ground.frequency" = { from = 1.0, to = 2.0 }"#, r#"sweep."ground.frequency".steps"#).starts_with("required"));
    assert!(fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, steps = 2, step = 1.0 }"#,
        r#"sweep."ground.frequency".step"#
    )
    .starts_with("give either"));
    assert!(fails(
        r#""ground.frequency" = { from = 1.0, to = 2.0, stesp = 2 }"#,
        r#"sweep."ground.frequency".stesp"#
    )
    .starts_with("unknown key (did you mean `steps`?)"));
}

#[test]
fn a_sweep_needs_its_table_and_a_valid_base() {
    let e = Sweep::from_toml_str(BASE, Path::new(ORIGIN)).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.starts_with("dir/sweep.toml: sweep: missing section [sweep]"), "{e}");
    let e = Sweep::from_toml_str(&format!("sweep = 3\n{BASE}"), Path::new(ORIGIN))
        .err()
        .map(|e| e.to_string())
        .unwrap_or_default();
    assert_eq!(e, "dir/sweep.toml: sweep: expected a table (a [sweep] section), got an integer");
    assert!(fails("", "sweep").starts_with("no swept key"));
    // A base that no case can fix: the first case's error, before running.
    let bad = BASE.replace("width = 4.0", "width = -4.0");
    let e = Sweep::from_toml_str(&format!("{bad}\n[sweep]\n\"ground.frequency\" = [3.0, 4.0]"), Path::new(ORIGIN));
    assert_eq!(
        e.err().map(|e| e.to_string()).unwrap_or_default(),
        "dir/sweep.toml: tower.width: must be a finite number > 0, got -4"
    );
    // A key of another type in the base: every case fails, so the sweep does.
    let e = fails(r#""ground.t0" = [1.0]"#, "ground.t0");
    assert!(e.starts_with("does not apply to type = \"harmonic\""), "{e}");
    // …but a first case that fails while others run is a row, not an error.
    let s = ok(r#""building.mu_static" = [0.5, 1.25]"#);
    assert_eq!(
        s.run_case(0).error().map(|e| e.starts_with("building.mu_kinetic: 1 exceeds mu_static = 0.5")),
        Some(true)
    );
    assert_eq!(s.run_case(1).error(), None);
}

#[test]
fn a_missing_record_is_an_error_before_running() {
    let text = format!(
        "{}\n[sweep]\n\"ground.scale\" = [1.0, 2.0]\n",
        BASE.replace(
            "type = \"harmonic\"\namplitude = 0.5\nfrequency = 5.0",
            "type = \"record\"\nfile = \"nowhere.AT2\""
        )
    );
    let e = Sweep::from_toml_str(&text, Path::new(ORIGIN)).err().map(|e| e.to_string()).unwrap_or_default();
    assert!(e.starts_with("dir/sweep.toml: ground.file: cannot read dir/nowhere.AT2"), "{e}");
}

#[test]
fn json_gives_the_same_sweep_as_toml() {
    let toml = ok(r#""ground.frequency" = { from = 3.0, to = 4.0, steps = 3 }"#);
    let mut value = match serde_json::to_value(crate::parse_toml(BASE, Path::new(ORIGIN)).unwrap_or_default()) {
        Ok(v) => v,
        Err(e) => panic!("{e}"),
    };
    value["sweep"] = serde_json::json!({"ground.frequency": {"from": 3.0, "to": 4.0, "steps": 3}});
    let json = Sweep::from_json(value, Path::new(ORIGIN)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(json.axes(), toml.axes());
    assert_eq!(json.header(), toml.header());
    let from_parts = Sweep::from_parts(
        crate::parse_toml(BASE, Path::new(ORIGIN)).unwrap_or_default(),
        vec![("ground.frequency".into(), AxisSpec::Steps { from: 3.0, to: 4.0, steps: 3 })],
        Path::new(ORIGIN),
    );
    assert_eq!(from_parts.map(|s| s.axes().to_vec()).ok(), Some(toml.axes().to_vec()));
}

#[test]
fn csv_text_is_quoted_only_when_needed() {
    assert_eq!(csv_line(["a", "b,c", "say \"hi\"", ""]), "a,\"b,c\",\"say \"\"hi\"\"\",");
    let row = Row {
        index: 0,
        cells: vec![
            Cell::Float(3.1),
            Cell::Int(-2),
            Cell::Bool(true),
            Cell::Empty,
            Cell::Float(1e-10),
            Cell::Float(5.0),
        ],
    };
    assert_eq!(row.to_csv_line(), "3.1,-2,true,,1e-10,5.0");
}

/// A sweep over the scale of one record reads the file once: once the sweep
/// is built (its first case read the record), the file can go, and every row
/// is still the summary of its case run alone from the file, scaled.
#[test]
fn a_record_is_read_once_and_scaled_per_case() {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("../rocking/tests/data/records/synthetic.AT2");
    let record = dir.path().join("record.AT2");
    std::fs::copy(&source, &record).unwrap_or_else(|e| panic!("{e}"));
    let base = BASE.replace(
        "type = \"harmonic\"\namplitude = 0.5\nfrequency = 5.0",
        "type = \"record\"\nfile = \"record.AT2\"",
    );
    let origin = dir.path().join("sweep.toml");
    let scales = [0.5, 4.0, 8.0];
    let expected: Vec<Vec<Cell>> = scales
        .iter()
        .map(|scale| {
            let text = base.replace("file = \"record.AT2\"", &format!("file = \"record.AT2\"\nscale = {scale:?}"));
            let alone = Scenario::from_toml_str(&text, &origin)
                .and_then(|s| s.build())
                .and_then(|c| c.run(RunOptions::SUMMARY));
            let alone = alone.unwrap_or_else(|e| panic!("{e}"));
            summary_fields(&alone).into_iter().map(|(_, c)| c).collect()
        })
        .collect();
    let sweep = Sweep::from_toml_str(&format!("{base}\n[sweep]\n\"ground.scale\" = {scales:?}\n"), &origin).unwrap_or_else(|e| panic!("{e}"));
    std::fs::remove_file(&record).unwrap_or_else(|e| panic!("{e}"));
    let rows = rows(&sweep, Some(2));
    for (row, expected) in rows.iter().zip(&expected) {
        assert_eq!(row.error(), None);
        assert_eq!(row.cells[1..row.cells.len() - 1], expected[..], "case {}", row.index);
    }
    // The scale matters: the peaks differ from case to case.
    let peak = column(&sweep, "max_abs_theta_rad");
    assert!(
        rows.windows(2).all(|w| w[0].cells[peak] != w[1].cells[peak]),
        "{:?}",
        rows.iter().map(|r| &r.cells[peak]).collect::<Vec<_>>()
    );
}

#[test]
fn shards_are_contiguous_blocks_covering_every_case_once() {
    // The blocks of `--shard K/N`, floor((K−1)·n/N) .. floor(K·n/N), written out
    // by hand for n = 10, N = 3 and n = 2, N = 3 (an empty block).
    let blocks = |total: usize, n: usize| (1..=n).map(|k| Shard::new(k, n).map(|s| s.cases(total))).collect::<Result<Vec<_>, _>>();
    assert_eq!(blocks(10, 3), Ok(vec![0..3, 3..6, 6..10]));
    assert_eq!(blocks(2, 3), Ok(vec![0..0, 0..1, 1..2]));
    // In general: end to end from 0 to n, sizes within one of n / N.
    for total in [0, 1, 7, 100, 1_000_003] {
        for n in [1, 2, 3, 7, 16, 1000] {
            let b = blocks(total, n).unwrap_or_else(|e| panic!("{e}"));
            assert_eq!(b[0].start, 0);
            assert_eq!(b[n - 1].end, total);
            assert!(b.windows(2).all(|w| w[0].end == w[1].start), "{total} in {n}: {b:?}");
            assert!(b.iter().all(|r| r.len() == total / n || r.len() == total / n + 1), "{total} in {n}");
        }
    }
    // No overflow of (K − 1)·n for a sweep whose count barely fits.
    assert_eq!(Shard::new(2, 2).map(|s| s.cases(usize::MAX)), Ok(usize::MAX / 2..usize::MAX));
}

#[test]
fn shard_text_is_k_slash_n_with_one_based_k() {
    assert_eq!("3/16".parse::<Shard>().map(|s| (s.k(), s.n())), Ok((3, 16)));
    assert_eq!("1/1".parse::<Shard>().map(|s| s.to_string()), Ok("1/1".to_string()));
    for bad in ["0/3", "4/3", "1/0", "3", "a/b", "-1/3", "1/3/4", ""] {
        let e = bad.parse::<Shard>().err().unwrap_or_else(|| panic!("{bad:?} should be refused"));
        assert!(e.contains("K/N"), "{bad:?}: {e}");
    }
}

#[test]
fn blocks_of_cases_put_end_to_end_are_the_whole_sweep() {
    // 3 × 5 cases, one of them failing (mu_kinetic > mu_static), in blocks
    // of 7 (some empty) on 2 threads and 1: the same CSV lines as one run.
    let s = ok(r#""building.mu_kinetic" = [0.5, 1.0, 2.0]
"ground.amplitude" = { from = 0.4, to = 1.6, steps = 5 }"#);
    let whole: Vec<String> = rows(&s, Some(2)).iter().map(Row::to_csv_line).collect();
    assert!(whole.iter().any(|l| !l.ends_with(',')), "one case fails: {whole:?}");
    let mut joined = Vec::new();
    for k in 1..=7 {
        let cases = Shard::new(k, 7).map(|sh| sh.cases(s.len())).unwrap_or_else(|e| panic!("{e}"));
        let threads = Some(1 + k % 2);
        let done = s.run_range(cases.clone(), threads, &AtomicBool::new(false), |row| {
            assert!(cases.contains(&row.index), "row {} outside {cases:?}", row.index);
            joined.push(row.to_csv_line());
            Ok::<(), Infallible>(())
        });
        let done = done.unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((done.written, done.cancelled), (cases.len(), false));
    }
    assert_eq!(joined, whole);
    // A range past the end is clipped, not an error.
    let done = s.run_range(s.len() - 1..s.len() + 5, None, &AtomicBool::new(false), |_| Ok::<(), Infallible>(()));
    assert_eq!(done.map(|d| d.written).ok(), Some(1));
}
