//! `rocking assess`: the verdict of the kinematic checks in assessment.json
//! against the numbers worked out by hand for a 4 m × 12 m tower on subsoil B
//! (as in rocking-assess's tests), capacity.csv's ends, and bad input refused
//! with one line naming the file and the key (exit 1).

use crate::util::{arg, read, rocking, root, tempdir, write};
use serde_json::Value;

/// A tower (b = 2 m, h = 6 m) on the assessment file's example site, subsoil B.
pub const ASSESS: &str = r#"name = "tower on B"
[tower]
width = 4.0
height = 12.0
mass = 1.5e5

[site]
code = "ntc2018"
soil = "B"
topography = "T1"
[site.SLD]
ag = 0.062
F0 = 2.52
Tc_star = 0.30
[site.SLV]
ag = 0.155
F0 = 2.47
Tc_star = 0.36
[site.SLC]
ag = 0.196
F0 = 2.50
Tc_star = 0.37

[assessment]
confidence_factor = 1.35
q = 2.0
"#;

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
    let file = write(dir.path(), "assess.toml", ASSESS);
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
    // SLV linear: q = 2 times the activation's; the least ζ_E of the four, so governing.
    close(number(&checks[1], &["ag_capacity_g"]), 2.0 * act, 1e-9);
    close(number(&checks[1], &["zeta_E"]), 2.0 * act / 0.155, 1e-9);
    assert_eq!(json["governing"], checks[1]);
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
    // The terminal names the governing check.
    assert!(r.stdout.contains("governing: SLV linear_kinematic"), "{}", r.stdout);
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
    let cases: [(&str, String, &str); 9] = [
        (
            "missing limit state",
            ASSESS.replace("[site.SLC]\nag = 0.196\nF0 = 2.50\nTc_star = 0.37\n", ""),
            "site.SLC: missing [site.SLC]",
        ),
        (
            "FC below 1",
            ASSESS.replace("confidence_factor = 1.35", "confidence_factor = 0.9"),
            "assessment.confidence_factor: must be >= 1",
        ),
        ("q zero", ASSESS.replace("q = 2.0", "q = 0"), "assessment.q: must be a finite number > 0"),
        (
            "a typo",
            ASSESS.replace("confidence_factor", "confidence_facter"),
            "assessment.confidence_facter: unknown key (did you mean `confidence_factor`?)",
        ),
        (
            "two records",
            ASSESS.replace("q = 2.0", "records = [\"records/*.AT2\"]"),
            "assessment.records: a record set needs at least 3 records",
        ),
        (
            "a duration",
            ASSESS.replace("[site]", "[simulation]\nduration = 5.0\n[site]"),
            "simulation.duration: a dynamic check runs each record",
        ),
        (
            "no tower",
            ASSESS.replace("[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5", "[building]\nmass = 1e6\nmu_static = 0.5"),
            "tower: an assessment needs a [tower]",
        ),
        (
            "a ground",
            format!("{ASSESS}\n[ground]\ntype = \"none\"\n"),
            "ground: an assessment file has no [ground]",
        ),
        ("soil", ASSESS.replace("soil = \"B\"", "soil = \"F\""), "site.soil: unknown category \"F\""),
    ];
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
    std::fs::create_dir_all(dir.path().join("records")).unwrap_or_else(|e| panic!("{e}"));
    for k in 1..=3 {
        let text = read(&root().join(format!("data/records/synthetic/kt_0{k}.AT2")));
        write(dir.path(), &format!("records/kt_0{k}.AT2"), &text);
    }
    let text = ASSESS.replace(
        "q = 2.0",
        "q = 2.0\nrecords = [\"records/*.AT2\"]\nfree_after = 2.0\nlambda = { from = 0.5, to = 2.0, step = 0.5 }",
    );
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
    for name in ["report.html", "assessment.json"] {
        let committed = read(&root().join("docs/src/figures/assess").join(name));
        let generated = read(&dir.path().join(name));
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
