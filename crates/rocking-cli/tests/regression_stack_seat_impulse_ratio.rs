//! Regression (issue 48, item 10): the assessment of a stack dropped
//! `max_seat_impulse_ratio` (model.md: above 1 the model's assumption that a
//! seated block stays seated is violated), so a dynamic verdict could rest on
//! runs that break the model without a word. `records.csv` now has it for
//! each record's run (checked here against `rocking run` of the same record
//! at the same scale), and the report warns when a run's exceeds 1. Also:
//! one file given twice to `rocking spectrum` gave two columns of one name;
//! it is refused.

use crate::util::{arg, csv_table, read, rocking, tempdir, write};

#[test]
fn each_record_of_a_stack_has_its_seat_impulse_ratio() {
    let dir = tempdir();
    crate::assess::synthetic_records(dir.path(), "records");
    let belfry = "[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n";
    let text = crate::assess::tower_on_b().replace("[site]\n", &format!("{belfry}\n[site]\n"))
        + "records = [\"records/*.AT2\"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 1.0, step = 0.5 }\n";
    let file = write(dir.path(), "assess.toml", &text);
    let out = dir.path().join("out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let (header, rows) = csv_table(&out.join("records.csv"));
    let column = |name: &str| {
        header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name} in {header:?}"))
    };
    let (ratio, record, scale) = (column("max_seat_impulse_ratio"), column("record"), column("scale"));
    assert_eq!(rows.len(), 6, "2 limit states × 3 records");
    // The first row's run again, from a scenario file written by hand: the same ratio to the last digit.
    let row = &rows[0];
    let record_file = dir.path().join(&row[record]);
    let duration = read(&record_file).lines().nth(3).map(|l| {
        // NPTS and DT of the AT2 header: the record lasts (NPTS − 1) DT.
        let numbers: Vec<f64> = l.split([',', '=', ' ']).filter_map(|w| w.trim().parse().ok()).collect();
        (numbers[0] - 1.0) * numbers[1]
    });
    let duration = duration.unwrap_or_else(|| panic!("no AT2 header in {}", record_file.display()));
    let scenario = write(
        dir.path(),
        "one.toml",
        &format!(
            "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n{belfry}\n[ground]\ntype = \"record\"\nfile = '{}'\nscale = {}\n[simulation]\nduration = {}\n",
            record_file.display(),
            row[scale],
            duration + 2.0
        ),
    );
    let run_out = dir.path().join("run");
    let r = rocking(&["run", arg(&scenario), "--out", arg(&run_out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    let summary: serde_json::Value = serde_json::from_str(&read(&run_out.join("summary.json"))).unwrap_or_else(|e| panic!("{e}"));
    let expected = summary["max_seat_impulse_ratio"].as_f64().unwrap_or_else(|| panic!("no ratio in {summary}"));
    let got: f64 = row[ratio].parse().unwrap_or_else(|e| panic!("{}: {e}", row[ratio]));
    assert!((got - expected).abs() <= 1e-12 * expected.abs().max(1.0), "{got} against {expected}");
    // The report warns exactly when a ratio of the runs at λ = 1 exceeds 1 (the scan's runs may add more).
    let report = read(&out.join("report.html"));
    let above: bool = rows.iter().any(|r| r[ratio].parse::<f64>().is_ok_and(|x| x > 1.0));
    if above {
        assert!(report.contains("break the model's assumption") || report.contains("breaks the model's assumption"));
    }
}

#[test]
fn a_record_given_twice_to_spectrum_is_refused() {
    let dir = tempdir();
    let record = write(dir.path(), "step.csv", "time,acceleration\n0,0\n0.01,0.3\n0.02,0\n");
    let again = dir.path().join(".").join("step.csv");
    let r = rocking(&["spectrum", arg(&record), arg(&again), "--out", arg(&dir.path().join("out"))]);
    assert_eq!(r.code, Some(1), "{r:?}");
    assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
    assert!(r.stderr.contains("is given twice"), "{r:?}");
}
