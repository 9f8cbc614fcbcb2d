//! `rocking assess`: the verdict of the kinematic checks in assessment.json
//! against the numbers worked out by hand for a 4 m × 12 m tower on subsoil B
//! (as in rocking-assess's tests), capacity.csv's ends, and bad input refused
//! with one line naming the file and the key (exit 1).

use crate::util::{arg, read, rocking, root, tempdir, write};
use serde_json::Value;

/// The tests' tower (b = 2 m, h = 6 m) on the assessment file's example site,
/// subsoil B, shared with the tests of rocking-assess and of Python; its
/// `[assessment]` is the last table, to which a test appends the record set.
pub fn tower_on_b() -> String {
    read(&root().join("crates/rocking-assess/tests/data/tower_on_b.toml"))
}

/// Copies the synthetic records kt_01–kt_03.AT2 into `dir/folder`.
pub fn synthetic_records(dir: &std::path::Path, folder: &str) {
    std::fs::create_dir_all(dir.join(folder)).unwrap_or_else(|e| panic!("{e}"));
    for k in 1..=3 {
        let text = read(&root().join(format!("data/records/synthetic/kt_0{k}.AT2")));
        write(dir, &format!("{folder}/kt_0{k}.AT2"), &text);
    }
}

/// `text` with `from` replaced by `to`, `from` being in it.
fn edited(text: &str, from: &str, to: &str) -> String {
    assert!(text.contains(from), "no {from:?} in the tests' assessment file");
    text.replace(from, to)
}

fn number(v: &Value, path: &[&str]) -> f64 {
    let mut x = v;
    for p in path {
        x = &x[*p];
    }
    x.as_f64().unwrap_or_else(|| panic!("{path:?} is not a number in {v}"))
}

#[test]
fn the_verdict_is_the_hand_computed_one() {
    let dir = tempdir();
    let file = write(dir.path(), "assess.toml", &tower_on_b());
    let out = dir.path().join("out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let json: Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
    let g = 9.81;
    let a0 = g / 3.0 / 1.35;
    // Exact to the last bits or so: the capacity is a few arithmetic operations.
    let close = |x: f64, y: f64, tol: f64| assert!((x - y).abs() <= tol * y.abs(), "{x} vs {y}");
    close(number(&json, &["capacity", "a0_star_m_s2"]), a0, 1e-15);
    close(number(&json, &["capacity", "d0_m"]), 2.0, 1e-15);
    close(
        number(&json, &["capacity", "T_SLV_s"]),
        1.68 * std::f64::consts::PI * (0.8 / (0.6 * a0)).sqrt(),
        1e-14,
    );
    // SS of the SLV site: 1.4 − 0.4·2.47·0.155 = 1.247, clamped at 1.2.
    close(number(&json, &["sites", "SLV", "SS"]), 1.2, 1e-15);
    let checks = json["checks"].as_array().unwrap_or_else(|| panic!("no checks"));
    assert_eq!(checks.len(), 4);
    let methods: Vec<&str> = checks.iter().filter_map(|c| c["method"].as_str()).collect();
    assert_eq!(methods, ["activation", "linear_kinematic", "nonlinear_kinematic", "nonlinear_kinematic"]);
    // SLD activation: 1.008 ag² − 1.4 ag + a0*/g = 0, lesser root (SS on its slope);
    // bisected to 1e-12 g, so 1e-9 relative holds.
    let a = a0 / g;
    let act = (1.4 - (1.96 - 4.0 * 1.008 * a).sqrt()) / 2.016;
    close(number(&checks[0], &["ag_capacity_g"]), act, 1e-9);
    close(number(&checks[0], &["zeta_E"]), act / 0.062, 1e-9);
    // SLV linear: q = 2 times the activation's; the least ζ_E of the four, but
    // information: the non-linear kinematic checks carry the verdict of SLV
    // and SLC (the most refined computed), and SLC's is the worse (4.68 against
    // 5.04, worked out by hand in rocking-assess's tests/verdict_by_hand.rs).
    close(number(&checks[1], &["ag_capacity_g"]), 2.0 * act, 1e-9);
    close(number(&checks[1], &["zeta_E"]), 2.0 * act / 0.155, 1e-9);
    for key in ["limit_state", "method", "zeta_E", "ag_capacity_g"] {
        assert_eq!(json["governing"][key], checks[3][key], "{key}");
    }
    assert_eq!(json["governing"]["verdict_basis"], "most_refined");
    assert_eq!(json["damage"], checks[0]);
    assert_eq!(checks[1]["unit"], "g");
    assert_eq!(checks[2]["unit"], "m");
    assert!(checks.iter().all(|c| c["holds"] == Value::Bool(true)));
    // capacity.csv: the straight line from (0, a0*) to (d0, 0).
    let csv = read(&out.join("capacity.csv"));
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines[0], "d_star_m,a_star_m_s2");
    assert_eq!(lines.len(), 202);
    assert_eq!(lines[1], format!("0.0,{a0}"));
    assert_eq!(lines[201], "2.0,0.0");
    // The terminal names the governing check and the damage state's beside it.
    assert!(
        r.stdout
            .contains("governing: SLC nonlinear_kinematic, ζ_E = 4.68 (the most refined method computed)"),
        "{}",
        r.stdout
    );
    assert!(r.stdout.contains("damage: SLD activation, ζ_E = 3.34"), "{}", r.stdout);
}

/// An assessment on the hazard grid: the site's parameters come from the grid.
#[test]
fn a_grid_site_outside_the_grid_is_refused() {
    let dir = tempdir();
    let grid = root().join("data/hazard/synthetic_grid.txt");
    let site = format!(
        "[site]\ncode = \"ntc2018\"\nsoil = \"C\"\ngrid = \"{}\"\nlon = 14.42\nlat = 41.04\nVN = 50\nCU = 1.5\n",
        arg(&grid)
    );
    let text = format!("[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n{site}");
    let file = write(dir.path(), "grid.toml", &text);
    let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("out"))]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let file = write(dir.path(), "outside.toml", &text.replace("lon = 14.42", "lon = 15.9"));
    let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("out2"))]);
    assert_eq!(r.code, Some(1));
    assert!(
        r.stderr.starts_with("error: ") && r.stderr.contains("outside.toml: site.lon:") && r.stderr.contains("outside the hazard grid"),
        "{}",
        r.stderr
    );
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
}

#[test]
fn bad_input_is_one_line_naming_the_key() {
    let dir = tempdir();
    std::fs::create_dir_all(dir.path().join("records")).unwrap_or_else(|e| panic!("{e}"));
    let record = read(&root().join("data/records/elcentro_1940_ns.AT2"));
    write(dir.path(), "records/one.AT2", &record);
    write(dir.path(), "records/two.AT2", &record);
    let base = tower_on_b();
    let slc = "[site.SLC]\nag = 0.196\nF0 = 2.50\nTc_star = 0.37\n";
    let tower = "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5";
    // (what, the text edited from, to, the message after the file's name)
    let edits: [(&str, &str, &str, &str); 8] = [
        ("missing limit state", slc, "", "site.SLC: missing [site.SLC]"),
        (
            "FC below 1",
            "confidence_factor = 1.35",
            "confidence_factor = 0.9",
            "assessment.confidence_factor: must be >= 1",
        ),
        ("q zero", "q = 2.0", "q = 0", "assessment.q: must be a finite number > 0"),
        (
            "a typo",
            "confidence_factor",
            "confidence_facter",
            "assessment.confidence_facter: unknown key (did you mean `confidence_factor`?)",
        ),
        (
            "two records",
            "q = 2.0",
            "records = [\"records/*.AT2\"]",
            "assessment.records: a record set needs at least 3 records",
        ),
        (
            "a duration",
            "[site]\n",
            "[simulation]\nduration = 5.0\n[site]\n",
            "simulation.duration: a dynamic check runs each record",
        ),
        (
            "no tower",
            tower,
            "[building]\nmass = 1e6\nmu_static = 0.5",
            "tower: an assessment needs a [tower]",
        ),
        ("soil", "soil = \"B\"", "soil = \"F\"", "site.soil: unknown category \"F\""),
    ];
    let mut cases: Vec<(&str, String, &str)> = edits
        .iter()
        .map(|&(what, from, to, expected)| (what, edited(&base, from, to), expected))
        .collect();
    let tables = "[site.SLD]\nag = 0.062\nF0 = 2.52\nTc_star = 0.30\n[site.SLV]\nag = 0.155\nF0 = 2.47\nTc_star = 0.36\n";
    let grid = format!("grid = \"{}\"\n", arg(&root().join("data/hazard/synthetic_grid.txt")));
    cases.push((
        "a grid without the site",
        edited(&edited(&base, tables, &grid), slc, ""),
        "site.lon: required with grid",
    ));
    cases.push((
        "a ground",
        format!("{base}\n[ground]\ntype = \"none\"\n"),
        "ground: an assessment file has no [ground]",
    ));
    for (what, text, expected) in cases {
        let file = write(dir.path(), "bad.toml", &text);
        let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("out"))]);
        assert_eq!(r.code, Some(1), "{what}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{what}: {}", r.stderr);
        assert!(r.stderr.contains(&format!("bad.toml: {expected}")), "{what}: {}", r.stderr);
        assert!(!dir.path().join("out/assessment.json").exists(), "{what}: wrote outputs");
    }
}

/// With a record set: records.csv has one row per limit state and record, spectra.csv
/// the code spectrum, each scaled record and the mean per limit state; a record
/// that cannot be read is named.
#[test]
fn the_dynamic_checks_write_their_tables() {
    let dir = tempdir();
    synthetic_records(dir.path(), "records");
    let text = tower_on_b() + "records = [\"records/*.AT2\"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 2.0, step = 0.5 }\n";
    let file = write(dir.path(), "assess.toml", &text);
    let out = dir.path().join("out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out), "--threads", "1"]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    let records = read(&out.join("records.csv"));
    let lines: Vec<&str> = records.lines().collect();
    assert_eq!(
        lines[0],
        "limit_state,record,scale,max_control_displacement_m,overturned,max_building_slip_m,error"
    );
    assert_eq!(lines.len(), 1 + 2 * 3);
    assert!(
        lines[1].starts_with("SLV,records/kt_01.AT2,") && lines[4].starts_with("SLC,records/kt_01.AT2,"),
        "{records}"
    );
    let spectra = read(&out.join("spectra.csv"));
    let header = spectra.lines().next().unwrap_or_default();
    assert_eq!(
        header,
        "period_s,Se_SLV_g,PSA_SLV_kt_01.AT2_g,PSA_SLV_kt_02.AT2_g,PSA_SLV_kt_03.AT2_g,PSA_SLV_mean_g,Se_SLC_g,PSA_SLC_kt_01.AT2_g,PSA_SLC_kt_02.AT2_g,PSA_SLC_kt_03.AT2_g,PSA_SLC_mean_g"
    );
    let json: Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
    let methods: Vec<&str> = json["checks"]
        .as_array()
        .map(|c| c.iter().filter_map(|c| c["method"].as_str()).collect())
        .unwrap_or_default();
    assert_eq!(methods.iter().filter(|m| **m == "nonlinear_dynamic").count(), 2);

    write(dir.path(), "records/kt_04.AT2", "not a record\n");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(1));
    assert!(r.stderr.contains("assessment.records") && r.stderr.contains("kt_04.AT2"), "{}", r.stderr);
    assert_eq!(r.stderr.lines().count(), 1, "{}", r.stderr);
}

/// The example's report and assessment.json shown in the docs are what the
/// command writes for it today (run from the repository's root, as
/// scripts/docs-assess-report.sh does, which regenerates them).
#[test]
fn the_docs_example_report_is_the_generated_one() {
    let dir = tempdir();
    let r = rocking(&["assess", "examples/sant-anna-cervino/assess.toml", "--out", arg(dir.path())]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    // The report's closing section is of the run (its date, the commit): left out.
    let of_the_run = |text: String| match (text.find("<section id=\"provenance\">"), text.find("</section>\n</body>")) {
        (Some(a), Some(b)) if a < b => format!("{}{}", &text[..a], &text[b + "</section>\n".len()..]),
        _ => text,
    };
    for name in ["report.html", "assessment.json"] {
        let committed = of_the_run(read(&root().join("docs/src/figures/assess").join(name)));
        let generated = of_the_run(read(&dir.path().join(name)));
        // Compared line by line so that a failure names the first line that differs.
        for (i, (c, g)) in committed.lines().zip(generated.lines()).enumerate() {
            assert!(
                c == g,
                "docs/src/figures/assess/{name} line {} differs from what rocking assess writes: run scripts/docs-assess-report.sh",
                i + 1
            );
        }
        assert_eq!(
            committed.lines().count(),
            generated.lines().count(),
            "docs/src/figures/assess/{name}: run scripts/docs-assess-report.sh"
        );
    }
}

/// The three synthetic records as one-column CSV files in m/s² (each AT2 value
/// in g times 9.81, written in full), sampled every 0.01 s as their AT2 files.
fn csv_records(dir: &std::path::Path) {
    std::fs::create_dir_all(dir.join("csv")).unwrap_or_else(|e| panic!("{e}"));
    for k in 1..=3 {
        let at2 = read(&root().join(format!("data/records/synthetic/kt_0{k}.AT2")));
        assert!(at2.lines().nth(3).is_some_and(|l| l.contains("DT= 0.0100 SEC")), "kt_0{k}.AT2's time step");
        let values: String = at2
            .lines()
            .skip(4)
            .flat_map(str::split_whitespace)
            .map(|v| format!("{}\n", v.parse::<f64>().unwrap_or_else(|e| panic!("{v}: {e}")) * 9.81))
            .collect();
        write(dir, &format!("csv/kt_0{k}.csv"), &values);
    }
}

/// A record set of CSV files takes `units` and `dt` as `[ground]` does for a
/// CSV record: the same records as CSV in m/s² every 0.01 s give the verdict
/// of their AT2 files to the last bit (the AT2 reader multiplies each value in
/// g by g = 9.81 m/s², the CSV reader reads those products back exactly, and
/// both sample at k·dt). Without `dt` a one-column file is refused, naming it.
#[test]
fn a_csv_record_set_takes_units_and_dt() {
    let dir = tempdir();
    synthetic_records(dir.path(), "at2");
    csv_records(dir.path());
    let set = "free_after = 2.0\nlambda = { from = 0.5, to = 2.0, step = 0.5 }\n";
    let run = |name: &str, records: &str| {
        let file = write(dir.path(), &format!("{name}.toml"), &format!("{}{records}{set}", tower_on_b()));
        let out = dir.path().join(format!("out-{name}"));
        let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
        assert_eq!(r.code, Some(0), "{name}: {}", r.stderr);
        let json: Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
        (json, read(&out.join("records.csv")))
    };
    let (at2, at2_rows) = run("at2", "records = [\"at2/*.AT2\"]\n");
    let (csv, csv_rows) = run("csv", "records = [\"csv/*.csv\"]\nunits = \"m/s2\"\ndt = 0.01\n");
    assert_eq!(csv["checks"], at2["checks"]);
    assert_eq!(
        csv_rows.replace("csv/", "").replace(".csv", ""),
        at2_rows.replace("at2/", "").replace(".AT2", "")
    );
    // Read in g (the default), the same files are 9.81 times stronger: each is
    // fitted to the spectrum with a scale 9.81 times smaller. The fit is linear
    // in the record, so the two agree but for the rounding of the spectra's
    // arithmetic (1e-12 relative is far above it, far below a wrong unit).
    let (_, in_g) = run("in_g", "records = [\"csv/*.csv\"]\ndt = 0.01\n");
    let scales = |rows: &str| -> Vec<f64> {
        rows.lines()
            .skip(1)
            .map(|l| l.split(',').nth(2).and_then(|x| x.parse().ok()).unwrap_or_else(|| panic!("{l}")))
            .collect()
    };
    let (in_m_s2, in_g) = (scales(&csv_rows), scales(&in_g));
    assert_eq!(in_m_s2.len(), 6);
    for (a, b) in in_m_s2.iter().zip(&in_g) {
        assert!((a / b / 9.81 - 1.0).abs() < 1e-12, "{a} {b}");
    }

    for (what, keys, expected) in [
        ("no dt", "units = \"m/s2\"\n", "assessment.records: "),
        ("a typo", "unit = \"m/s2\"\ndt = 0.01\n", "assessment.unit: unknown key (did you mean `units`?)"),
        ("a bad unit", "units = \"mm/s2\"\ndt = 0.01\n", "assessment.units: \"mm/s2\" is not one of"),
        ("a bad dt", "units = \"m/s2\"\ndt = -0.01\n", "assessment.dt: must be"),
    ] {
        let file = write(dir.path(), "bad.toml", &format!("{}records = [\"csv/*.csv\"]\n{keys}{set}", tower_on_b()));
        let r = rocking(&["assess", arg(&file), "--out", arg(&dir.path().join("bad"))]);
        assert_eq!(r.code, Some(1), "{what}: {}", r.stderr);
        assert_eq!(r.stderr.lines().count(), 1, "{what}: {}", r.stderr);
        assert!(r.stderr.contains(&format!("bad.toml: {expected}")), "{what}: {}", r.stderr);
        if what == "no dt" {
            assert!(r.stderr.contains("kt_01.csv"), "{what}: {}", r.stderr);
        }
        assert_eq!(files_in(&dir.path().join("bad")), 0, "{what}: wrote outputs");
    }
}

/// The number of entries of a folder, 0 when it does not exist.
pub fn files_in(folder: &std::path::Path) -> usize {
    std::fs::read_dir(folder).map_or(0, |entries| entries.count())
}

/// A belfry 1.6 m × 8 m of 20 t on the tests' tower: α0 = 0.8/4 = 0.2 against
/// the stack's 2/(1220/170) = 0.2787, so that the belfry governs, SLV linear
/// kinematic, ζ_E = 2 (0.2/1.35/1.2)/0.155 = 1.593; the terminal, the JSON and
/// the report say so, each mechanism with its own section.
#[test]
fn a_belfry_is_a_mechanism_of_its_own() {
    let dir = tempdir();
    let text = edited(
        &tower_on_b(),
        "[site]\n",
        "[[block]]\nname = \"belfry\"\nwidth = 1.6\nheight = 8.0\nmass = 2.0e4\n\n[site]\n",
    ) + "verdict_method = \"linear_kinematic\"\n";
    let file = write(dir.path(), "assess.toml", &text);
    let out = dir.path().join("out");
    let r = rocking(&["assess", arg(&file), "--out", arg(&out)]);
    assert_eq!(r.code, Some(0), "{}", r.stderr);
    assert!(
        r.stdout
            .contains("governing: belfry SLV linear_kinematic, ζ_E = 1.59 (named by assessment.verdict_method)"),
        "{}",
        r.stdout
    );
    let json: Value = serde_json::from_str(&read(&out.join("assessment.json"))).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(json["governing"]["mechanism"], "belfry");
    // The activation capacity on the branch SS = 1.2 is a0*/(1.2 g): the ratio is 2 · 0.2 / (1.35 · 1.2 · 0.155).
    let expected = 2.0 * 0.2 / (1.35 * 1.2 * 0.155);
    assert!((number(&json, &["governing", "zeta_E"]) - expected).abs() < 1e-9 * expected);
    assert!((number(&json["mechanisms"][0]["capacity"], &["alpha0"]) - 2.0 * 170.0 / 1220.0).abs() < 1e-14);
    assert!((number(&json["mechanisms"][1]["capacity"], &["m_star_kg"]) - 2.0e4).abs() < 1e-9);
    let report = read(&out.join("report.html"));
    for part in [
        "<h2>1. The mechanisms and their capacities</h2>",
        "<h3>tower</h3>",
        "<h3>belfry</h3>",
        "Capacity curve in the ADRS plane: belfry",
        "Verdict: belfry, SLV",
        "the ground's spectra for the motion of the shaft's top",
    ] {
        assert!(report.contains(part), "no {part:?} in the report");
    }
    // Each ADRS figure (one a mechanism) tells its kinds of point apart: each
    // has its legend entry, and the two limit states have two colours (the
    // life-safety one blue #0072B2, the collapse one vermilion #D55E00).
    let figures: Vec<&str> = report.split("Capacity curve in the ADRS plane: ").skip(1).collect();
    assert_eq!(figures.len(), 2, "one ADRS figure a mechanism");
    for figure in figures {
        let svg = &figure[..figure.find("</svg>").unwrap_or(figure.len())];
        for entry in [
            "ultimate d_SLV = 0.4 d0 = ",
            "ultimate d_SLC = 0.6 d0 = ",
            "SLV non-linear demand ",
            "SLC non-linear demand ",
        ] {
            assert!(svg.contains(entry), "no legend entry {entry:?} in the ADRS figure {svg}");
        }
        for color in ["fill=\"#0072B2\"", "fill=\"#D55E00\""] {
            assert!(svg.contains(color), "no point filled {color} in the ADRS figure");
        }
    }
}

/// The report's closing section (issue 47, item 1): the date the report was
/// made (SOURCE_DATE_EPOCH = 86,400 s: 1970-01-02 00:00:00 UTC, by hand),
/// the commit of the checkout the command was built from (`git rev-parse
/// HEAD`, asked here), each input file's SHA-256 as `sha256sum` computes it,
/// and the statement of NTC 2018 §10.2.
#[cfg(unix)]
#[test]
fn the_report_closes_with_what_made_it() {
    use std::process::Command;
    let dir = tempdir();
    let file = write(dir.path(), "assess.toml", &tower_on_b());
    let out = dir.path().join("out");
    let run = Command::new(env!("CARGO_BIN_EXE_rocking"))
        .args(["assess", arg(&file), "--out", arg(&out)])
        .env("SOURCE_DATE_EPOCH", "86400")
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    assert!(run.status.success(), "{}", String::from_utf8_lossy(&run.stderr));
    let report = read(&out.join("report.html"));
    let section = &report[report.find("<section id=\"provenance\">").unwrap_or_else(|| panic!("no closing section"))..];
    assert!(section.contains("<span id=\"made-on\">1970-01-02 00:00:00</span>"), "{section}");
    let git = Command::new("git")
        .args(["rev-parse", "HEAD"])
        .current_dir(root())
        .output()
        .unwrap_or_else(|e| panic!("{e}"));
    let commit = String::from_utf8_lossy(&git.stdout).trim().to_string();
    assert!(section.contains(&format!("<code id=\"commit\">{commit}</code>")), "{section}");
    let sum = Command::new("sha256sum").arg(&file).output().unwrap_or_else(|e| panic!("{e}"));
    let digest = String::from_utf8_lossy(&sum.stdout).split_whitespace().next().unwrap_or_default().to_string();
    assert_eq!(digest.len(), 64);
    assert!(section.contains(&format!("<code>sha256:{digest}</code>")), "{section}");
    assert!(section.contains("NTC 2018 §10.2") && section.contains("judgement of the engineer"), "{section}");
}
