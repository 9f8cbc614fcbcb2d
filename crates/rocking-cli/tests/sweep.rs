//! `rocking sweep`: every row equals `rocking run` of its case, the file does
//! not depend on `--threads`, a failing case does not stop the others,
//! dimensionless axes, range expansion, bad sweep files, Ctrl-C, `--plot`.

use crate::util::{arg, csv_table, example, read, rocking, rocking_in, scenario_with, tempdir, write, SCENARIO};
use serde_json::Value;
use std::path::Path;

/// `SCENARIO` (the tower on its church, 1 s at 0.6 g, 5 Hz) with a `[sweep]` table.
fn sweep_file(dir: &Path, name: &str, axes: &str) -> std::path::PathBuf {
    write(dir, name, &format!("{SCENARIO}\n[sweep]\n{axes}\n"))
}

/// Runs `rocking sweep file --out dir/name extra…`, which must succeed; returns the CSV path.
fn sweep_ok(file: &Path, out: &Path, extra: &[&str]) -> std::path::PathBuf {
    let mut args = vec!["sweep", arg(file), "--out", arg(out)];
    args.extend_from_slice(extra);
    let r = rocking(&args);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stderr.is_empty(), "no progress bar when stderr is not a terminal: {r:?}");
    out.join("sweep.csv")
}

fn col(header: &[String], name: &str) -> usize {
    header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
}

fn number(text: &str) -> f64 {
    text.parse().unwrap_or_else(|e| panic!("{text:?}: {e}"))
}

#[test]
fn every_row_equals_rocking_run_of_its_case() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "\"ground.amplitude\" = [0.4, 1.5]\n\"ground.frequency\" = [2.0, 5.0]");
    let (header, rows) = csv_table(&sweep_ok(&file, &dir.path().join("o"), &[]));
    assert_eq!(&header[..2], ["ground.amplitude", "ground.frequency"]);
    assert_eq!(header.last().map(String::as_str), Some("error"));
    assert!(!header.iter().any(|h| h == "wall_time_s"));
    assert_eq!(rows.len(), 4);
    for (i, row) in rows.iter().enumerate() {
        // The CSV holds every digit: the case is the same when written back into a scenario.
        let text = scenario_with("amplitude = 0.6", &format!("amplitude = {}", row[0])).replacen("frequency = 5.0", &format!("frequency = {}", row[1]), 1);
        let case = write(dir.path(), &format!("case{i}.toml"), &text);
        let out = dir.path().join(format!("run{i}"));
        let r = rocking(&["run", arg(&case), "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{r:?}");
        let summary: Value = serde_json::from_str(&read(&out.join("summary.json"))).unwrap_or_else(|e| panic!("{e}"));
        let mut compared = 0;
        for (name, field) in header.iter().zip(row).skip(2) {
            if name == "error" {
                assert_eq!(field, "");
                continue;
            }
            let mut json = &summary;
            for part in name.split('.') {
                json = &json[part];
            }
            match json {
                Value::Null => assert_eq!(field, "", "{name}"),
                Value::Bool(b) => assert_eq!(field, &b.to_string(), "{name}"),
                Value::String(s) => assert_eq!(field, s, "{name}"),
                // The same number exactly: the integration is deterministic.
                Value::Number(n) => assert_eq!(
                    number(field).to_bits(),
                    n.as_f64().unwrap_or(f64::NAN).to_bits(),
                    "case {i}, {name}: {field} vs {n}"
                ),
                other => panic!("{name}: {other:?} is not a scalar"),
            }
            compared += 1;
        }
        assert_eq!(compared, header.len() - 3, "every summary column is compared");
    }
}

#[test]
fn the_file_does_not_depend_on_the_number_of_threads() {
    let dir = tempdir();
    // Cases of very different costs (no uplift, rocking, sliding, overturning): they finish out of order.
    let file = sweep_file(
        dir.path(),
        "s.toml",
        "\"ground.amplitude\" = [0.2, 0.6, 1.5, 3.0]\n\"ground.frequency\" = { from = 1.0, to = 5.0, steps = 5 }",
    );
    let one = read(&sweep_ok(&file, &dir.path().join("t1"), &["--threads", "1"]));
    assert_eq!(one.lines().count(), 21);
    for threads in ["2", "4"] {
        let other = read(&sweep_ok(&file, &dir.path().join(format!("t{threads}")), &["--threads", threads]));
        assert!(one == other, "--threads {threads} changed sweep.csv");
    }
    let default = read(&sweep_ok(&file, &dir.path().join("all"), &[]));
    assert!(one == default, "all cores changed sweep.csv");
}

#[test]
fn a_failing_case_does_not_stop_the_others() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "friction.toml", "\"building.mu_kinetic\" = [0.5, 1.5, 1.0]");
    // Run from the temp folder with a relative path: the default output is out/<stem>.
    let r = rocking_in(dir.path(), &["sweep", "friction.toml"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stdout.contains("3 cases") && r.stdout.contains("1 failed"), "{}", r.stdout);
    let (header, rows) = csv_table(&dir.path().join("out/friction/sweep.csv"));
    let (error, peak) = (col(&header, "error"), col(&header, "max_theta_over_alpha"));
    assert_eq!(rows[1][0], "1.5");
    assert_eq!(
        rows[1][error],
        "building.mu_kinetic: 1.5 exceeds mu_static = 1.25; kinetic friction cannot exceed static friction"
    );
    assert!(rows[1][1..error].iter().all(String::is_empty), "{:?}", rows[1]);
    for i in [0, 2] {
        assert_eq!(rows[i][error], "");
        assert!(number(&rows[i][peak]) > 0.0, "{:?}", rows[i]);
    }
    drop(file);
}

#[test]
fn dimensionless_axes_replace_the_dimensional_keys_of_the_base() {
    let dir = tempdir();
    // SCENARIO gives amplitude and frequency: sweeping their ratios is not "both given".
    let ratios = sweep_file(
        dir.path(),
        "r.toml",
        "\"ground.amplitude_ratio\" = [1.5, 3.0]\n\"ground.frequency_ratio\" = [2.0, 6.0]",
    );
    let (h, r) = csv_table(&sweep_ok(&ratios, &dir.path().join("r"), &[]));
    let (alpha, p) = (number(&r[0][col(&h, "alpha_rad")]), number(&r[0][col(&h, "p_rad_s")]));
    let amplitudes = [1.5, 3.0].map(|x| (x * alpha.tan()).to_string()).join(", ");
    let frequencies = [2.0, 6.0].map(|x| (x * p / (2.0 * std::f64::consts::PI)).to_string()).join(", ");
    let values = sweep_file(
        dir.path(),
        "v.toml",
        &format!("\"ground.amplitude\" = [{amplitudes}]\n\"ground.frequency\" = [{frequencies}]"),
    );
    let (hv, v) = csv_table(&sweep_ok(&values, &dir.path().join("v"), &[]));
    let (kr, kv) = (col(&h, "max_theta_over_alpha"), col(&hv, "max_theta_over_alpha"));
    assert_eq!(r.len(), 4);
    for (a, b) in r.iter().zip(&v) {
        let (x, y) = (number(&a[kr]), number(&b[kv]));
        assert!(x > 0.0, "{a:?}");
        // The ratio → value conversion rounds (here through the decimal text of
        // the value); the response carries an ulp-sized change of its input
        // far below 1e-9, itself far below the integration tolerance (1e-8).
        assert!((x - y).abs() <= 1e-9 * x.abs(), "{x} vs {y}");
    }
}

#[test]
fn ranges_expand_to_the_expected_values() {
    let dir = tempdir();
    let file = sweep_file(
        dir.path(),
        "s.toml",
        "\"ground.frequency\" = { from = 3.0, to = 4.0, steps = 5 }\n\"ground.amplitude\" = { from = 0.9, to = 0.3, step = 0.3 }",
    );
    let (_, rows) = csv_table(&sweep_ok(&file, &dir.path().join("o"), &[]));
    let pairs: Vec<(&str, &str)> = rows.iter().map(|r| (r[0].as_str(), r[1].as_str())).collect();
    let mut expected = Vec::new();
    for f in ["3.0", "3.25", "3.5", "3.75", "4.0"] {
        for a in ["0.9", "0.6", "0.3"] {
            expected.push((f, a));
        }
    }
    assert_eq!(pairs, expected);
}

/// `rocking sweep` on `axes` must exit 1 with one line naming the file and every one of `needles`.
fn bad(axes: &str, needles: &[&str]) {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "bad-sweep.toml", axes);
    let r = rocking_in(dir.path(), &["sweep", arg(&file)]);
    assert_eq!(r.code, Some(1), "{axes}: {r:?}");
    let lines: Vec<&str> = r.stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{r:?}");
    assert!(lines[0].starts_with("error: ") && lines[0].contains("bad-sweep.toml"), "{}", lines[0]);
    for needle in needles {
        assert!(lines[0].contains(needle), "{needle:?} not in: {}", lines[0]);
    }
    assert!(!r.stderr.contains("panicked"), "{r:?}");
    assert!(!dir.path().join("out").exists(), "a refused sweep created its output folder");
}

#[test]
fn bad_sweep_files_are_refused_with_one_line() {
    bad(
        "\"ground.frequncy\" = [3.0]",
        &["sweep.\"ground.frequncy\": unknown key", "did you mean `ground.frequency`"],
    );
    bad(
        "\"ground.frequency\" = { from = 3.0, to = 7.0, steps = 0 }",
        &["sweep.\"ground.frequency\".steps", "must be an integer >= 1"],
    );
    bad("\"ground.frequency\" = []", &["sweep.\"ground.frequency\"", "empty"]);
    bad(
        "\"ground.frequency\" = { from = \"3\", to = 7.0, steps = 5 }",
        &["sweep.\"ground.frequency\".from", "expected a number, got a string"],
    );
    bad(
        "\"ground.frequency\" = { from = 3.0, to = 7.0, step = 3.0 }",
        &["sweep.\"ground.frequency\".step", "does not divide"],
    );
    bad("\"tower.points\" = [1.0]", &["sweep.\"tower.points\"", "not a scalar"]);
    bad("", &["sweep", "no swept key"]);
    let dir = tempdir();
    let plain = write(dir.path(), "plain.toml", SCENARIO);
    let r = rocking_in(dir.path(), &["sweep", arg(&plain)]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert!(r.stderr.contains("plain.toml: sweep: missing section [sweep]"), "{r:?}");
    let r = rocking_in(dir.path(), &["sweep", arg(&plain), "--threads", "0"]);
    assert_eq!(r.code, Some(2), "bad usage: {r:?}");
}

#[test]
fn the_figure_6_example_runs_and_rotation_falls_with_frequency() {
    let dir = tempdir();
    let r = rocking(&["sweep", "examples/figure6-sweep.toml", "--out", arg(dir.path())]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let (header, rows) = csv_table(&dir.path().join("sweep.csv"));
    assert_eq!(rows.len(), 4 * 41);
    let (error, peak) = (col(&header, "error"), col(&header, "max_theta_over_alpha"));
    assert!(rows.iter().all(|r| r[error].is_empty()));
    assert_eq!(&header[..2], ["ground.frequency", "ground.amplitude"], "the figure's x axis first");
    // Rows 0..4 are at 3 Hz, the last four at 7 Hz, one per amplitude.
    let (low, high) = (&rows[..4], &rows[rows.len() - 4..]);
    for (at3, at7) in low.iter().zip(high) {
        assert_eq!((at3[0].as_str(), at7[0].as_str(), &at3[1]), ("3.0", "7.0", &at7[1]));
        let (low, high) = (number(&at3[peak]), number(&at7[peak]));
        assert!(low > high && high > 0.0, "{} g: θ/α {low} at 3 Hz, {high} at 7 Hz", at3[1]);
    }
    assert!(example("figure6-sweep.toml").exists());
}

#[test]
fn plot_comes_after_the_csv() {
    let dir = tempdir();
    let file = sweep_file(dir.path(), "s.toml", "\"ground.amplitude\" = [0.5, 1.0]\n\"ground.frequency\" = [3.0, 5.0]");
    let out = dir.path().join("o");
    let r = rocking(&["sweep", arg(&file), "--out", arg(&out), "--plot"]);
    // Whether or not the figures can be drawn, sweep.csv is complete.
    let (_, rows) = csv_table(&out.join("sweep.csv"));
    assert_eq!(rows.len(), 4);
    match r.code {
        Some(0) => assert!(r.stdout.contains("sweep.csv"), "{r:?}"),
        _ => {
            assert_eq!(r.code, Some(1), "{r:?}");
            assert!(r.stderr.starts_with("error: drawing the figures"), "{r:?}");
        }
    }
}

#[cfg(unix)]
#[test]
fn ctrl_c_leaves_the_rows_finished_in_order_and_exits_130() {
    use std::time::Duration;
    let dir = tempdir();
    // 20,000 cases of 5 s: far longer than the test waits.
    let text = format!(
        "{}\n[sweep]\n\"ground.frequency\" = {{ from = 1.0, to = 9.0, steps = 20000 }}\n",
        SCENARIO.replace("duration = 1.0", "duration = 5.0")
    );
    let file = write(dir.path(), "long.toml", &text);
    let out = dir.path().join("o");
    let csv = out.join("sweep.csv");
    // The rows go to a staging folder until the sweep ends (or is interrupted):
    // interrupted once some rows have reached it (the writer is buffered).
    let some_rows = |staging: &Path| std::fs::read_to_string(staging.join("sweep.csv")).map_or(0, |t| t.lines().count()) >= 3;
    let args = ["sweep", arg(&file), "--out", arg(&out), "--threads", "2"];
    let r = crate::util::interrupted(&args, &out, "-INT", Duration::from_secs(60), some_rows);
    let (stderr, partial) = (r.stderr, r.staging.join("sweep.csv"));
    assert_eq!(r.code, Some(130), "{stderr}");
    let lines: Vec<&str> = stderr.lines().collect();
    assert_eq!(lines.len(), 1, "{stderr}");
    let (header, rows) = csv_table(&csv);
    assert!(rows.len() >= 2 && rows.len() < 20000, "{} rows", rows.len());
    assert!(
        lines[0].starts_with(&format!("interrupted: wrote {} of 20000 cases to ", rows.len())),
        "{stderr}"
    );
    // Complete rows, cases 0..n in order.
    let error = col(&header, "error");
    let mut previous = 0.0;
    for row in &rows {
        assert_eq!(row.len(), header.len());
        assert_eq!(row[error], "");
        let f = number(&row[0]);
        assert!(f > previous, "rows out of order: {f} after {previous}");
        previous = f;
    }
    assert!(read(&csv).ends_with('\n'), "the last row is complete");
    assert!(!partial.exists(), "the staging folder is left behind");
}
