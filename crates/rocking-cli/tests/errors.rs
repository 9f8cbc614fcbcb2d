//! Every class of bad input: exit 1, one line on stderr naming the file and
//! the key, never a panic or a backtrace; bad usage exits 2.

use crate::util::{arg, rocking, rocking_in, scenario_with, tempdir, write, SCENARIO};

/// Runs `run` and `check` on `text` saved as `name`; both must fail with one
/// line that names the file and contains every one of `needles`.
fn bad(name: &str, text: &str, needles: &[&str]) {
    let dir = tempdir();
    let file = write(dir.path(), name, text);
    write(dir.path(), "bad.csv", "time,acceleration\n0.0,0.0\n0.01,0.1x\n0.02,0.0\n");
    for command in ["run", "check"] {
        // Run from the scenario's folder so that an output folder, were one made, is inside the temp dir.
        let r = rocking_in(dir.path(), &[command, arg(&file)]);
        let context = format!("rocking {command} {name}: {r:?}");
        assert_eq!(r.code, Some(1), "{context}");
        let lines: Vec<&str> = r.stderr.lines().collect();
        assert_eq!(lines.len(), 1, "{context}");
        let line = lines[0];
        assert!(line.starts_with("error: "), "{context}");
        assert!(line.contains(name), "the file is not named: {line}");
        for needle in needles {
            assert!(line.contains(needle), "{needle:?} not in: {line}");
        }
        let lower = r.stderr.to_lowercase();
        assert!(!lower.contains("panicked") && !lower.contains("backtrace"), "{context}");
        assert!(r.stdout.is_empty(), "{context}");
    }
    assert!(!dir.path().join("out").exists(), "a failed run created its output folder");
}

#[test]
fn missing_ground_section() {
    let text = SCENARIO.split("[ground]").next().unwrap_or_default().to_string() + "[simulation]\nduration = 1.0\n";
    bad("no-ground.toml", &text, &["ground", "missing section [ground]"]);
}

#[test]
fn unknown_section() {
    bad(
        "section.toml",
        &format!("{SCENARIO}\n[towr]\nwidth = 4.0\n"),
        &["towr", "unknown section", "did you mean `tower`"],
    );
}

#[test]
fn unknown_key_is_named_with_the_valid_keys() {
    bad(
        "typo.toml",
        &scenario_with("height = 12.0", "hieght = 12.0"),
        &["tower.hieght", "unknown key", "did you mean `height`", "valid keys: width, height"],
    );
}

#[test]
fn string_where_a_number_is_expected() {
    bad(
        "string.toml",
        &scenario_with("width = 4.0", "width = \"4.0\""),
        &["tower.width: expected a number, got a string"],
    );
}

#[test]
fn negative_width() {
    bad(
        "negative.toml",
        &scenario_with("width = 4.0", "width = -4"),
        &["tower.width: must be a finite number > 0, got -4"],
    );
}

#[test]
fn nan_and_infinity() {
    bad("nan.toml", &scenario_with("height = 12.0", "height = nan"), &["tower.height", "NaN"]);
    bad("inf.toml", &scenario_with("amplitude = 0.6", "amplitude = inf"), &["ground.amplitude", "inf"]);
    bad("neginf.toml", &scenario_with("mass = 2.0e6", "mass = -inf"), &["building.mass", "-inf"]);
}

#[test]
fn zero_frequency() {
    bad(
        "zero-f.toml",
        &scenario_with("frequency = 5.0", "frequency = 0"),
        &["ground.frequency", "> 0, got 0"],
    );
}

#[test]
fn zero_or_negative_duration() {
    bad(
        "zero-d.toml",
        &scenario_with("duration = 1.0", "duration = 0.0"),
        &["simulation.duration", "got 0"],
    );
    bad(
        "neg-d.toml",
        &scenario_with("duration = 1.0", "duration = -2"),
        &["simulation.duration", "got -2"],
    );
    bad(
        "neg-gd.toml",
        &scenario_with("frequency = 5.0", "frequency = 5.0\nduration = -1"),
        &["ground.duration", "got -1"],
    );
}

#[test]
fn kinetic_friction_above_static() {
    bad(
        "mu.toml",
        &scenario_with("mu_kinetic = 1.0", "mu_kinetic = 1.5"),
        &["building.mu_kinetic", "1.5 exceeds mu_static = 1.25"],
    );
}

#[test]
fn negative_friction() {
    bad(
        "neg-mu.toml",
        &scenario_with("mu_static = 1.25", "mu_static = -0.2"),
        &["building.mu_static", "got -0.2"],
    );
}

#[test]
fn initial_rotation_beyond_a_right_angle() {
    bad("theta.toml", &format!("{SCENARIO}\n[initial]\ntheta = 1.6\n"), &["initial.theta", "π/2"]);
}

#[test]
fn neither_tower_nor_building() {
    bad(
        "empty.toml",
        "[ground]\ntype = \"harmonic\"\namplitude = 0.5\nfrequency = 5.0\n",
        &["tower", "needs a [tower], a [building], or both"],
    );
}

#[test]
fn hollow_without_wall_thickness() {
    bad(
        "hollow.toml",
        &scenario_with("mass = 1.5e5", "mass = 1.5e5\nsection = \"hollow\""),
        &["tower.wall_thickness", "hollow"],
    );
}

#[test]
fn a_key_of_another_ground_type() {
    let text = scenario_with("type = \"harmonic\"", "type = \"record\"\nfile = \"x.csv\"").replace("amplitude = 0.6\n", "");
    bad("record-f.toml", &text, &["ground.frequency", "does not apply to type = \"record\""]);
}

fn record_scenario(file: &str) -> String {
    SCENARIO.split("[ground]").next().unwrap_or_default().to_string() + &format!("[ground]\ntype = \"record\"\nfile = \"{file}\"\n")
}

#[test]
fn record_file_missing() {
    bad(
        "nofile.toml",
        &record_scenario("records/x.AT2"),
        &["ground.file", "cannot read", "x.AT2", "No such file or directory"],
    );
}

#[test]
fn record_file_malformed() {
    bad("malformed.toml", &record_scenario("bad.csv"), &["ground.file", "bad.csv", "line 3"]);
}

#[test]
fn toml_syntax_error_gives_the_line() {
    let text = scenario_with("width = 4.0", "width = = 4.0");
    let line = text.lines().position(|l| l.starts_with("width = =")).map_or(0, |i| i + 1);
    bad("syntax.toml", &text, &[&format!("line {line}")]);
}

#[test]
fn a_missing_scenario_file_exits_1() {
    for command in ["run", "check"] {
        let r = rocking(&[command, "no/such/scenario.toml"]);
        assert_eq!(r.code, Some(1), "{r:?}");
        assert_eq!(r.stderr.lines().count(), 1, "{r:?}");
        assert!(r.stderr.contains("no/such/scenario.toml") && r.stderr.contains("No such file"), "{r:?}");
    }
}

#[test]
fn bad_usage_exits_2() {
    for args in [
        &[][..],
        &["run"][..],
        &["frobnicate", "x.toml"][..],
        &["run", "x.toml", "--bogus"][..],
        &["check"][..],
        &["run", "x.toml", "--out"][..],
    ] {
        let r = rocking(args);
        assert_eq!(r.code, Some(2), "rocking {args:?}: {r:?}");
        assert!(!r.stderr.contains("panicked"), "{r:?}");
    }
}

#[test]
fn help_exits_0_and_mentions_overwriting() {
    let r = rocking(&["run", "--help"]);
    assert_eq!(r.code, Some(0), "{r:?}");
    assert!(r.stdout.contains("overwritten"), "{}", r.stdout);
    assert!(r.stdout.contains("out/<scenario file stem>"), "{}", r.stdout);
}
