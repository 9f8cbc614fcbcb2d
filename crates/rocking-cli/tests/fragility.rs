//! `rocking fragility`: stripes equal `rocking run` of the same scaled record
//! bit for bit; the counts of fractions.csv and fragility.csv are those of
//! the stripes; the rows do not depend on the thread count; bad studies fail
//! with one line.

use crate::util::{arg, assert_shards_merge_to_whole, csv_table, read, rocking, tempdir, write};
use serde_json::Value;
use std::path::Path;

/// The church's bodies (shared fixture) without [ground] or a duration.
const BODIES: &str = include_str!("../../rocking-scenario/tests/data/church.toml");

/// Two short CSV records (times, accelerations in g) and their last sample times.
fn records(dir: &Path) -> [(&'static str, f64); 2] {
    std::fs::create_dir_all(dir.join("records")).unwrap_or_else(|e| panic!("{e}"));
    // A 2 Hz burst of 1.5 s and a one-sided pulse with an uneven time step.
    let burst: String = (0..=75)
        .map(|k| {
            let t = 0.02 * k as f64;
            format!("{t},{}\n", 0.5 * (2.0 * std::f64::consts::PI * 2.0 * t).sin())
        })
        .collect();
    write(dir, "records/a_burst.csv", &format!("time,acceleration\n{burst}"));
    write(dir, "records/b_pulse.csv", "time,acceleration\n0.0,0.0\n0.1,0.3\n0.25,0.4\n0.5,-0.2\n0.8,0.0\n");
    [("records/a_burst.csv", 0.02 * 75.0), ("records/b_pulse.csv", 0.8)]
}

fn study(measure: &str) -> String {
    format!(
        "name = \"small study\"\n{BODIES}\n[simulation]\noutput_dt = 0.01\n\n[study]\nrecords = [\"records/*.csv\"]\nmeasure = \"{measure}\"\nlevels = [0.2, 0.45, 0.9]\nfree_after = 1.0\n\n[[study.limit_state]]\nname = \"half-alpha\"\nfield = \"max_theta_over_alpha\"\nabove = 0.5\n\n[[study.limit_state]]\nname = \"uplift\"\nfield = \"tower_uplift_detected\"\n"
    )
}

#[test]
fn every_stripe_equals_run_of_the_scaled_record_bit_for_bit() {
    for measure in ["pga", "pgv", "pga_ratio"] {
        let dir = tempdir();
        let files = records(dir.path());
        let study_file = write(dir.path(), "study.toml", &study(measure));
        let out = dir.path().join("out");
        let r = rocking(&["fragility", arg(&study_file), "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{}", r.stderr);
        let (header, rows) = csv_table(&out.join("stripes.csv"));
        assert_eq!(&header[..3], ["record", "level", "scale"]);
        assert_eq!(header.last().map(String::as_str), Some("error"));
        assert_eq!(rows.len(), 6, "2 records × 3 levels");
        for (i, row) in rows.iter().enumerate() {
            let (file, last) = files[i / 3];
            assert_eq!(row[0], file, "records in sorted order, levels fastest");
            assert_eq!(row[1], ["0.2", "0.45", "0.9"][i % 3]);
            assert_eq!(row[header.len() - 1], "", "case {i} failed");
            // The same case as a scenario: the record scaled by the row's scale,
            // lasting its last sample plus free_after.
            let scenario = format!(
                "name = \"small study\"\n{BODIES}\n[ground]\ntype = \"record\"\nfile = \"{file}\"\nscale = {}\n\n[simulation]\noutput_dt = 0.01\nduration = {:?}\n",
                row[2],
                last + 1.0
            );
            let case = write(dir.path(), &format!("case{i}.toml"), &scenario);
            let case_out = dir.path().join(format!("case{i}"));
            let r = rocking(&["run", arg(&case), "--out", arg(&case_out)]);
            assert_eq!(r.code, Some(0), "{}", r.stderr);
            let summary: Value = serde_json::from_str(&read(&case_out.join("summary.json"))).unwrap_or_else(|e| panic!("{e}"));
            for (column, cell) in header.iter().zip(row).skip(3).take(header.len() - 4) {
                let value = column
                    .split('.')
                    .try_fold(&summary, |v, k| v.get(k))
                    .unwrap_or_else(|| panic!("{column} not in summary.json"));
                match value {
                    Value::Null => assert_eq!(cell, "", "{measure} case {i} {column}"),
                    Value::Bool(b) => assert_eq!(cell, &b.to_string(), "{measure} case {i} {column}"),
                    Value::String(s) => assert_eq!(cell, s, "{measure} case {i} {column}"),
                    Value::Number(n) => {
                        let x: f64 = cell.parse().unwrap_or_else(|e| panic!("{measure} case {i} {column} = {cell:?}: {e}"));
                        let y = n.as_f64().unwrap_or(f64::NAN);
                        assert_eq!(x.to_bits(), y.to_bits(), "{measure} case {i} {column}: {x} vs {y}");
                    }
                    other => panic!("{column} is {other}"),
                }
            }
        }
    }
}

/// The scale of each row is the level over the record's measure, worked out
/// here from the samples: PGA the peak sample (g), PGV the exact integral of
/// the linear interpolant, pga_ratio PGA / tan α with tan α = 4/12.
#[test]
fn scales_are_levels_over_the_measures_of_the_records() {
    // b_pulse: samples (0, 0), (0.1, 0.3), (0.25, 0.4), (0.5, −0.2), (0.8, 0) in g.
    let g = 9.81;
    let pga = 0.4;
    // v peaks where a crosses zero in [0.25, 0.5]: at 0.25 + 0.25·0.4/0.6.
    let v = 0.5 * 0.3 * 0.1 + 0.5 * (0.3 + 0.4) * 0.15 + 0.5 * 0.4 * (0.25 * 0.4 / 0.6);
    for (measure, value) in [("pga", pga), ("pgv", v * g), ("pga_ratio", pga * 3.0)] {
        let dir = tempdir();
        records(dir.path());
        let study_file = write(dir.path(), "study.toml", &study(measure));
        let out = dir.path().join("out");
        let r = rocking(&["fragility", arg(&study_file), "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{}", r.stderr);
        let (_, rows) = csv_table(&out.join("stripes.csv"));
        for row in &rows[3..] {
            let (level, scale): (f64, f64) = (row[1].parse().unwrap_or(f64::NAN), row[2].parse().unwrap_or(f64::NAN));
            // A few roundings in the sums and the unit conversion.
            let relative = (scale * value / level - 1.0).abs();
            assert!(relative < 1e-14, "{measure}: scale {scale} × {value} != {level}");
        }
    }
}

#[test]
fn fractions_and_fragility_count_the_stripes() {
    let dir = tempdir();
    records(dir.path());
    let study_file = write(dir.path(), "study.toml", &study("pga"));
    let out = dir.path().join("out");
    let r = rocking(&["fragility", arg(&study_file), "--out", arg(&out), "--plot"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (header, rows) = csv_table(&out.join("stripes.csv"));
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no column {name}"));
    let (theta, uplift) = (column("max_theta_over_alpha"), column("tower_uplift_detected"));
    let (fh, fractions) = csv_table(&out.join("fractions.csv"));
    assert_eq!(fh, ["limit_state", "level", "cases", "exceeded"]);
    assert_eq!(fractions.len(), 2 * 3);
    for f in &fractions {
        let at_level: Vec<&Vec<String>> = rows.iter().filter(|r| r[1] == f[1]).collect();
        let exceeded = match f[0].as_str() {
            "half-alpha" => at_level.iter().filter(|r| r[theta].parse::<f64>().is_ok_and(|x| x > 0.5)).count(),
            "uplift" => at_level.iter().filter(|r| r[uplift] == "true").count(),
            other => panic!("unknown limit state {other}"),
        };
        assert_eq!((f[2].as_str(), f[3].parse::<usize>().ok()), ("2", Some(exceeded)), "{f:?}");
    }
    let (gh, fits) = csv_table(&out.join("fragility.csv"));
    assert_eq!(gh, ["limit_state", "median", "beta", "cases", "exceeded", "method"]);
    assert_eq!(fits.len(), 2);
    for fit in &fits {
        let total: usize = fractions.iter().filter(|f| f[0] == fit[0]).filter_map(|f| f[3].parse::<usize>().ok()).sum();
        assert_eq!((fit[3].as_str(), fit[4].parse::<usize>().ok()), ("6", Some(total)));
        // Six cases cannot overlap much: with or without a fit, method says which.
        assert!(fit[1].is_empty() == fit[5].starts_with("no fit"), "{fit:?}");
    }
    for f in ["ida.svg", "ida.png", "fragility.svg", "fragility.png"] {
        assert!(out.join(f).is_file(), "{f} missing");
    }
}

#[test]
fn the_rows_do_not_depend_on_the_thread_count() {
    let dir = tempdir();
    records(dir.path());
    let study_file = write(dir.path(), "study.toml", &study("pga"));
    let mut texts = Vec::new();
    for threads in ["1", "3"] {
        let out = dir.path().join(format!("out{threads}"));
        let r = rocking(&["fragility", arg(&study_file), "--out", arg(&out), "--threads", threads]);
        assert_eq!(r.code, Some(0), "{}", r.stderr);
        texts.push([
            read(&out.join("stripes.csv")),
            read(&out.join("fragility.csv")),
            read(&out.join("fractions.csv")),
        ]);
    }
    assert_eq!(texts[0], texts[1]);
}

#[test]
fn shards_merge_to_the_unsharded_stripes_and_fits() {
    let dir = tempdir();
    records(dir.path());
    let study_file = write(dir.path(), "study.toml", &study("pga"));
    let whole = dir.path().join("whole");
    let r = rocking(&["fragility", arg(&study_file), "--out", arg(&whole)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    // 2 records × 3 levels = 6 cases: 1, 3 and 4 shards (one of them of one case).
    let shard = |k: usize, n: usize, parts: &Path| {
        let out = parts.join(k.to_string());
        let r = rocking(&["fragility", arg(&study_file), "--out", arg(&out), "--shard", &format!("{k}/{n}")]);
        assert_eq!(r.code, Some(0), "{}", r.stderr);
        out
    };
    let fits_nothing = |_: usize, _: usize, out: &Path| assert!(!out.join("fragility.csv").exists(), "a shard fits nothing");
    let files = ["stripes.csv", "fragility.csv", "fractions.csv"];
    assert_shards_merge_to_whole(dir.path(), &whole, &files, &[1, 3, 4], shard, fits_nothing);
    // A study file changed after its shards ran: the stripes merge, the fits are refused.
    let shard = dir.path().join("changed/1");
    let r = rocking(&["fragility", arg(&study_file), "--out", arg(&shard), "--shard", "1/1"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    write(
        dir.path(),
        "study.toml",
        &study("pga").replace("levels = [0.2, 0.45, 0.9]", "levels = [0.2, 0.45, 1.0]"),
    );
    let r = rocking(&["merge", arg(&shard), "--out", arg(&dir.path().join("changed-merged"))]);
    assert_eq!(r.code, Some(1));
    assert!(r.stderr.contains("changed since the shards ran"), "{}", r.stderr);
}

#[test]
fn bad_studies_fail_with_one_line_naming_the_key() {
    let dir = tempdir();
    records(dir.path());
    write(dir.path(), "records/zero.csv", "time,acceleration\n0.0,0.0\n1.0,0.0\n");
    let base = study("pga");
    let cases: [(&str, String, &str); 6] = [
        ("zero", base.clone(), "zero.csv: its pga is 0"),
        (
            "nomatch",
            base.replace("records/*.csv", "nothing/*.AT2"),
            "study.records: no file matches \"nothing/*.AT2\"",
        ),
        (
            "field",
            base.replace("max_theta_over_alpha", "max_theta"),
            "study.limit_state[0].field: \"max_theta\" is not a numeric or boolean field",
        ),
        (
            "measure",
            base.replace("measure = \"pga\"", "measure = \"sa\""),
            "study.measure: must be one of",
        ),
        (
            "ground",
            format!("{base}\n[ground]\ntype = \"none\"\n"),
            "ground: a study takes its ground motions from study.records",
        ),
        (
            "level",
            base.replace("[0.2, 0.45, 0.9]", "[0.2, -1]"),
            "study.levels[1]: must be a finite number > 0, got -1",
        ),
    ];
    for (name, text, expected) in cases {
        let file = write(dir.path(), &format!("{name}.toml"), &text);
        let r = rocking(&["fragility", arg(&file), "--out", arg(&dir.path().join(name))]);
        assert_eq!(r.code, Some(1), "{name}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{name}: {}", r.stderr);
        assert!(
            r.stderr.contains(expected) && r.stderr.contains(&format!("{name}.toml")),
            "{name}: {}",
            r.stderr
        );
    }
}

/// The example study runs (a second or so): 12 records (El Centro, then the
/// 11 synthetic ones in sorted order) × 20 levels, a fit for each limit state
/// the suite exceeds, and its figures.
#[test]
fn the_example_study_runs() {
    let dir = tempdir();
    let r = rocking(&["fragility", "examples/fragility/tower-on-church.toml", "--out", arg(dir.path()), "--plot"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let (_, rows) = csv_table(&dir.path().join("stripes.csv"));
    assert_eq!(rows.len(), 12 * 20);
    let mut records: Vec<&str> = rows.iter().map(|r| r[0].as_str()).collect();
    records.dedup();
    assert_eq!(records[0], "../../data/records/elcentro_1940_ns.AT2");
    assert_eq!(
        records[1..],
        (1..=11).map(|k| format!("../../data/records/synthetic/kt_{k:02}.AT2")).collect::<Vec<_>>()
    );
    assert!(rows.iter().all(|r| r.last().is_some_and(String::is_empty)), "no case fails");
    let (_, fits) = csv_table(&dir.path().join("fragility.csv"));
    let names: Vec<&str> = fits.iter().map(|f| f[0].as_str()).collect();
    assert_eq!(names, ["half-alpha", "slide-2cm", "collapse"]);
    for f in ["ida.svg", "fragility.svg"] {
        assert!(read(&dir.path().join(f)).contains("bell tower on a sliding church"), "{f}");
    }
    // No site, no hazard: no risk figure.
    assert!(!dir.path().join("risk.svg").exists());
}

/// A study with a site and `--plot` draws the risk figure, whose legend gives
/// each fitted limit state's λ_LS and its share beyond 2475 years as
/// risk.csv has them, to the 3 significant digits it prints.
#[test]
fn a_study_with_a_site_draws_where_its_risk_comes_from() {
    let dir = tempdir();
    let r = rocking(&["fragility", "examples/fragility/risk-at-a-site.toml", "--out", arg(dir.path()), "--plot"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(dir.path().join("risk.png").exists());
    let svg = read(&dir.path().join("risk.svg"));
    assert!(svg.contains("bell tower on a sliding church: risk at a site"));
    let (header, rows) = csv_table(&dir.path().join("risk.csv"));
    let column = |name: &str| header.iter().position(|h| h == name).unwrap_or_else(|| panic!("no {name} in risk.csv"));
    let (name, frequency, above) = (column("limit_state"), column("annual_frequency"), column("share_above_2475y"));
    assert_eq!(rows.len(), 3);
    for row in &rows {
        let label = format!("{}: λ_LS = ", row[name]);
        let at = svg.find(&label).unwrap_or_else(|| panic!("no legend entry {label}"));
        let rest = &svg[at + label.len()..];
        let shown: f64 = rest.split(' ').next().and_then(|t| t.parse().ok()).unwrap_or_else(|| panic!("{rest}"));
        let expected: f64 = row[frequency].parse().unwrap_or_else(|e| panic!("{e}"));
        // Three significant digits: within half a unit of the third.
        assert!((shown - expected).abs() <= 5e-3 * expected, "{shown} against {expected}");
        let share = rest
            .split("per year, ")
            .nth(1)
            .and_then(|t| t.split('%').next())
            .and_then(|t| t.parse::<f64>().ok());
        let expected: f64 = 100.0 * row[above].parse::<f64>().unwrap_or_else(|e| panic!("{e}"));
        assert!(share.is_some_and(|s| (s - expected).abs() <= 5e-3 * expected), "{share:?} against {expected}");
    }
}

/// The output folder holds one run's files: a second run without `--plot`
/// removes the figures of a first run with it (they would describe other
/// stripes), keeps a file of the user's, and stripes.csv is the second run's.
#[test]
fn a_second_run_replaces_the_first_runs_files() {
    let dir = tempdir();
    records(dir.path());
    let file = write(dir.path(), "study.toml", &study("pga"));
    let out = dir.path().join("o");
    let r = rocking(&["fragility", arg(&file), "--out", arg(&out), "--plot"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(out.join("ida.svg").exists() && out.join("fragility.png").exists());
    write(&out, "notes.txt", "mine");
    let smaller = write(dir.path(), "smaller.toml", &study("pga").replace("levels = [0.2, 0.45, 0.9]", "levels = [0.2]"));
    let r = rocking(&["fragility", arg(&smaller), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{r:?}");
    for stale in ["ida.svg", "ida.png", "fragility.svg", "fragility.png"] {
        assert!(!out.join(stale).exists(), "{stale} of the first run is left");
    }
    assert_eq!(read(&out.join("notes.txt")), "mine");
    // Two records at one level: two stripes.
    assert_eq!(csv_table(&out.join("stripes.csv")).1.len(), 2);
    let leftovers: Vec<_> = std::fs::read_dir(&out)
        .unwrap_or_else(|e| panic!("{e}"))
        .filter_map(Result::ok)
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.') && n != crate::folder::MANIFEST)
        .collect();
    assert!(leftovers.is_empty(), "no staging folder is left: {leftovers:?}");
}
