//! Parsing a scenario: defaults, alternatives, and every class of error, each
//! checked by the key it names and the one line it prints.

use crate::{get_dotted, remove_dotted, set_dotted, summary_json, summary_scalars, ErrorKind, GroundKind, RunOptions, Scenario};
use approx::assert_relative_eq;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

const ORIGIN: &str = "dir/s.toml";

/// The bell tower on its church, shaken for two seconds.
const BASE: &str = concat!(
    "name = \"t\"\n",
    include_str!("../tests/data/church.toml"),
    r#"
[ground]
type = "harmonic"
amplitude = 0.5
frequency = 5.0
duration = 2.0

[simulation]
duration = 2.0
"#
);

fn table(text: &str) -> Table {
    text.parse::<Table>().unwrap_or_else(|e| panic!("test TOML: {e}"))
}

/// A TOML value written as in a file (`"4"`, `"\"hollow\""`, `"nan"`).
fn value(text: &str) -> Value {
    table(&format!("v = {text}")).remove("v").unwrap_or_else(|| panic!("no value in {text}"))
}

/// The one `[[block]]` of an edited scenario (a 2 m × 5 m block of 30 t on
/// the tower), made on the first edit of a `block.` key.
fn the_block(t: &mut Table) -> &mut Table {
    let blocks = t
        .entry(crate::block::BLOCK)
        .or_insert_with(|| Value::Array(vec![Value::Table(table("width = 2.0\nheight = 5.0\nmass = 3.0e4\n"))]));
    match blocks.as_array_mut().and_then(|a| a.first_mut()).and_then(Value::as_table_mut) {
        Some(block) => block,
        None => panic!("test TOML: block is not an array of tables"),
    }
}

/// How an error names the key `key` of the edits: a key of the block
/// (`block.width`) by the block's default name (`block2.width`).
fn named(key: &str) -> String {
    match key.strip_prefix("block.") {
        Some(rest) => format!("block2.{rest}"),
        None => key.to_string(),
    }
}

/// BASE with dotted keys set (`Some`) or removed (`None`); a `block.` key is
/// set in the scenario's one `[[block]]` ([`the_block`]).
fn edited(edits: &[(&str, Option<&str>)]) -> Table {
    let mut t = table(BASE);
    for (key, v) in edits {
        if let Some(rest) = key.strip_prefix("block.") {
            let block = the_block(&mut t);
            match v {
                Some(v) => block.insert(rest.to_string(), value(v)),
                None => block.remove(rest),
            };
            continue;
        }
        match v {
            Some(v) => {
                set_dotted(&mut t, key, value(v)).unwrap_or_else(|e| panic!("{e}"));
            }
            None => {
                remove_dotted(&mut t, key);
            }
        }
    }
    t
}

fn parse(edits: &[(&str, Option<&str>)]) -> Result<Scenario, crate::Error> {
    Scenario::from_table(edited(edits), Path::new(ORIGIN))
}

fn ok(edits: &[(&str, Option<&str>)]) -> Scenario {
    parse(edits).unwrap_or_else(|e| panic!("{e}"))
}

/// The error of a scenario that must fail: checks that it is one line that
/// starts with the file and the key, and returns the message.
fn fails(edits: &[(&str, Option<&str>)], key: &str) -> String {
    let e = match parse(edits) {
        Ok(_) => panic!("{edits:?} parsed but should fail on {key}"),
        Err(e) => e,
    };
    check_line(&e, key)
}

/// Values read from the file or defaulted, not computed, arrive bit for bit.
#[track_caller]
fn same(actual: f64, expected: f64) {
    assert_eq!(actual.to_bits(), expected.to_bits(), "{actual} is not {expected}");
}

fn check_line(e: &crate::Error, key: &str) -> String {
    let line = e.to_string();
    assert!(!line.contains('\n'), "not one line: {line}");
    assert_eq!(e.key(), Some(key), "{line}");
    let prefix = format!("{ORIGIN}: {key}: ");
    assert!(line.starts_with(&prefix), "{line} does not start with {prefix}");
    line[prefix.len()..].to_string()
}

#[test]
fn the_base_scenario_parses_with_its_values() {
    let s = ok(&[]);
    assert_eq!(s.name(), "t");
    let d = s.model().derived();
    assert_relative_eq!(d.alpha.unwrap_or(0.0), (1.0f64 / 3.0).atan(), max_relative = 1e-15);
    assert_eq!(d.slip_acceleration_g, Some(1.25));
    let case = s.build().unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(case.ground_info.kind, GroundKind::Harmonic);
    assert_eq!(case.ground_info.amplitude_g, Some(0.5));
    assert_eq!(case.ground_info.frequency_hz, Some(5.0));
    assert_eq!(case.ground_info.end_time_s, Some(2.0));
    // The amplitude in g becomes m/s² with simulation.g.
    assert_relative_eq!(case.ground.peak().0, 0.5 * 9.81, max_relative = 1e-12);
    same(case.settings.duration, 2.0);
    assert!(case.inputs.is_empty());
}

#[test]
fn defaults_apply_to_absent_keys() {
    let s = ok(&[("simulation", None), ("name", None), ("ground.duration", None), ("building.mu_kinetic", None)]);
    assert_eq!(s.name(), "s", "the file stem names an unnamed scenario");
    let case = s.build().unwrap_or_else(|e| panic!("{e}"));
    same(case.settings.duration, 20.0);
    same(case.settings.rtol, 1e-8);
    same(case.settings.atol, 1e-10);
    same(case.output_dt, 0.005);
    same(case.model.gravity(), 9.81);
    // A harmonic without a duration shakes for the whole run.
    assert_eq!(case.ground_info.end_time_s, Some(20.0));
    assert_eq!(case.model.building().map(|b| b.mu_kinetic()), Some(1.25));
    same(case.initial.theta, 0.0);
    same(case.initial.theta_dot, 0.0);
}

#[test]
fn gravity_converts_amplitudes_given_in_g() {
    let case = ok(&[("simulation.g", Some("10"))]).build().unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(case.ground.peak().0, 5.0, max_relative = 1e-12);
}

#[test]
fn integers_are_accepted_for_numbers() {
    let a = ok(&[("tower.width", Some("4")), ("tower.mass", Some("150000"))]);
    assert_eq!(a.model(), ok(&[]).model());
}

#[test]
fn ratios_resolve_against_the_tower() {
    let s = ok(&[
        ("ground.amplitude", None),
        ("ground.amplitude_ratio", Some("1.5")),
        ("ground.frequency", None),
        ("ground.frequency_ratio", Some("2")),
    ]);
    let case = s.build().unwrap_or_else(|e| panic!("{e}"));
    let d = case.model.derived();
    // a = 1.5 tan α = 1.5 / 3 g; f = 2 p / 2π.
    assert_relative_eq!(case.ground_info.amplitude_g.unwrap_or(0.0), 0.5, max_relative = 1e-14);
    let p = d.p.unwrap_or(0.0);
    assert_relative_eq!(
        case.ground_info.frequency_hz.unwrap_or(0.0),
        2.0 * p / (2.0 * std::f64::consts::PI),
        max_relative = 1e-14
    );
}

#[test]
fn theta_over_alpha_scales_with_alpha() {
    let s = ok(&[("initial.theta_over_alpha", Some("0.5")), ("initial.theta_dot", Some("-0.1"))]);
    let case = s.build().unwrap_or_else(|e| panic!("{e}"));
    let alpha = case.model.derived().alpha.unwrap_or(0.0);
    assert_relative_eq!(case.initial.theta, 0.5 * alpha, max_relative = 1e-15);
    same(case.initial.theta_dot, -0.1);
}

#[test]
fn a_tower_by_its_properties_equals_the_same_tower_by_geometry() {
    let geometry = ok(&[]);
    let t = geometry.model().tower().copied().unwrap_or_else(|| panic!("no tower"));
    let text = |x: f64| format!("{x:e}");
    let props = ok(&[
        ("tower.width", None),
        ("tower.height", None),
        ("tower.inertia_pivot", Some(&text(t.inertia_pivot()))),
        ("tower.radius", Some(&text(t.radius()))),
        ("tower.alpha", Some(&text(t.alpha()))),
    ]);
    let u = props.model().tower().copied().unwrap_or_else(|| panic!("no tower"));
    assert_relative_eq!(u.restitution(), t.restitution(), max_relative = 1e-14);
    assert_relative_eq!(u.frequency_parameter(9.81), t.frequency_parameter(9.81), max_relative = 1e-14);
    let msg = fails(&[("tower.radius", Some("6.0")), ("tower.alpha", Some("0.3"))], "tower.width");
    assert!(msg.contains("either width and height, or radius and alpha"), "{msg}");
    let msg = fails(
        &[("tower.width", None), ("tower.height", None), ("tower.radius", Some("6.0"))],
        "tower.inertia_pivot",
    );
    assert!(msg.starts_with("required"), "{msg}");
}

#[test]
fn density_gives_the_mass() {
    let s = ok(&[("tower.mass", None), ("tower.density", Some("1800")), ("tower.depth", Some("5"))]);
    let mass = s.model().tower().map(|t| t.mass()).unwrap_or(0.0);
    assert_relative_eq!(mass, 1800.0 * 4.0 * 5.0 * 12.0, max_relative = 1e-14);
    let msg = fails(&[("tower.density", Some("1800"))], "tower.density");
    assert_eq!(msg, "give either mass or density, not both");
    let msg = fails(&[("tower.mass", None)], "tower.mass");
    assert!(msg.starts_with("required"), "{msg}");
}

#[test]
fn hollow_towers_need_a_wall_and_solid_ones_refuse_it() {
    let hollow = ok(&[("tower.section", Some("\"hollow\"")), ("tower.wall_thickness", Some("0.8"))]);
    let solid = ok(&[]);
    let (h, s) = (hollow.model().derived(), solid.model().derived());
    // Same mass, the mass further out: a larger I_O.
    assert!(h.inertia_pivot > s.inertia_pivot, "{h:?} {s:?}");
    let msg = fails(&[("tower.section", Some("\"hollow\""))], "tower.wall_thickness");
    assert!(msg.starts_with("required for section = \"hollow\""), "{msg}");
    let msg = fails(&[("tower.wall_thickness", Some("0.8"))], "tower.wall_thickness");
    assert_eq!(msg, "applies only to section = \"hollow\"");
    let msg = fails(
        &[("tower.section", Some("\"hollow\"")), ("tower.wall_thickness", Some("2.5"))],
        "tower.wall_thickness",
    );
    assert!(msg.contains("leaves no hollow"), "{msg}");
    fails(&[("tower.section", Some("\"round\""))], "tower.section");
}

#[test]
fn extra_points_are_read_and_checked() {
    let case = ok(&[("tower.points", Some("[[0.0, 12], [-2, 6.5]]"))])
        .build()
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(case.points, vec![(0.0, 12.0), (-2.0, 6.5)]);
    let msg = fails(&[("tower.points", Some("[[0.0, 12], [1.0]]"))], "tower.points[1]");
    assert_eq!(msg, "expected a pair [x, y] of numbers, got an array");
    fails(&[("tower.points", Some("[[0.0, nan]]"))], "tower.points[0]");
    fails(&[("tower.points", Some("3"))], "tower.points");
}

#[test]
fn syntax_errors_give_line_and_column_on_one_line() {
    let text = "name = \"x\"\n[tower]\nwidth = = 4\n";
    let e = Scenario::from_toml_str(text, Path::new(ORIGIN)).err().unwrap_or_else(|| panic!("parsed"));
    let line = e.to_string();
    assert!(!line.contains('\n'), "{line}");
    assert!(line.starts_with("dir/s.toml: line 3, column "), "{line}");
    assert!(matches!(e.kind(), ErrorKind::Syntax { line: 3, .. }), "{e:?}");
    // A duplicate key is a TOML error too, with its line.
    let e = Scenario::from_toml_str("[tower]\nwidth = 4\nwidth = 5\n", Path::new(ORIGIN)).err();
    assert!(matches!(e.as_ref().map(|e| e.kind()), Some(ErrorKind::Syntax { line: 3, .. })), "{e:?}");
}

#[test]
fn a_missing_ground_section_is_an_error() {
    let msg = fails(&[("ground", None)], "ground");
    assert!(msg.starts_with("missing section [ground]"), "{msg}");
    let msg = fails(&[("ground.type", None)], "ground.type");
    assert!(msg.starts_with("required: one of \"harmonic\""), "{msg}");
    let msg = fails(&[("ground.type", Some("\"harmonik\""))], "ground.type");
    assert!(msg.starts_with("\"harmonik\" is not one of \"harmonic\""), "{msg}");
}

#[test]
fn unknown_sections_and_keys_are_named_with_the_valid_ones() {
    let msg = fails(&[("towr.width", Some("4"))], "towr");
    assert_eq!(
        msg,
        "unknown section (did you mean `tower`?); valid sections: tower, block, building, ground, initial, simulation"
    );
    let msg = fails(&[("tower.hieght", Some("12"))], "tower.hieght");
    assert!(
        msg.starts_with("unknown key (did you mean `height`?); valid keys: width, height, mass"),
        "{msg}"
    );
    let msg = fails(&[("nmae", Some("\"x\""))], "nmae");
    assert!(msg.starts_with("unknown key (did you mean `name`?)"), "{msg}");
    fails(&[("simulation.dt", Some("0.01"))], "simulation.dt");
    fails(&[("initial.omega", Some("0.01"))], "initial.omega");
    fails(&[("building.friction", Some("0.5"))], "building.friction");
    let msg = fails(&[("ground.amplitud", Some("0.5"))], "ground.amplitud");
    assert!(
        msg.contains("valid keys: type, amplitude, amplitude_ratio, frequency, frequency_ratio, duration, phase"),
        "{msg}"
    );
}

#[test]
fn wrong_types_name_what_was_expected() {
    assert_eq!(fails(&[("tower.width", Some("\"4\""))], "tower.width"), "expected a number, got a string");
    assert_eq!(fails(&[("tower.height", Some("true"))], "tower.height"), "expected a number, got a boolean");
    assert_eq!(fails(&[("ground.type", Some("3"))], "ground.type"), "expected a string, got an integer");
    assert_eq!(fails(&[("name", Some("[1]"))], "name"), "expected a string, got an array");
    assert_eq!(fails(&[("tower", Some("3"))], "tower"), "expected a table (a [section]), got an integer");
}

#[test]
fn out_of_range_numbers_are_named() {
    assert_eq!(fails(&[("tower.width", Some("-4"))], "tower.width"), "must be a finite number > 0, got -4");
    assert_eq!(fails(&[("tower.height", Some("nan"))], "tower.height"), "must be a finite number > 0, got NaN");
    assert_eq!(fails(&[("tower.mass", Some("inf"))], "tower.mass"), "must be a finite number > 0, got inf");
    assert_eq!(
        fails(&[("ground.frequency", Some("0"))], "ground.frequency"),
        "must be a finite number > 0, got 0"
    );
    assert_eq!(
        fails(&[("ground.duration", Some("-1"))], "ground.duration"),
        "must be a finite number > 0, got -1"
    );
    assert_eq!(
        fails(&[("ground.amplitude", Some("-0.5"))], "ground.amplitude"),
        "must be a finite number >= 0, got -0.5"
    );
    assert_eq!(fails(&[("ground.phase", Some("inf"))], "ground.phase"), "must be a finite number, got inf");
    assert_eq!(
        fails(&[("simulation.duration", Some("0"))], "simulation.duration"),
        "must be a finite number > 0, got 0"
    );
    assert_eq!(
        fails(&[("simulation.duration", Some("-3"))], "simulation.duration"),
        "must be a finite number > 0, got -3"
    );
    fails(&[("simulation.g", Some("-inf"))], "simulation.g");
    fails(&[("simulation.rtol", Some("0"))], "simulation.rtol");
    fails(&[("simulation.atol", Some("-1e-10"))], "simulation.atol");
    fails(&[("simulation.output_dt", Some("0"))], "simulation.output_dt");
    let msg = fails(&[("simulation.output_dt", Some("1e-9"))], "simulation.output_dt");
    assert!(msg.contains("history rows"), "{msg}");
    fails(&[("tower.restitution", Some("1.5"))], "tower.restitution");
    fails(&[("tower.depth", Some("0"))], "tower.depth");
    fails(&[("building.mass", Some("-inf"))], "building.mass");
}

#[test]
fn friction_must_be_non_negative_and_kinetic_below_static() {
    let msg = fails(&[("building.mu_kinetic", Some("1.5"))], "building.mu_kinetic");
    assert!(msg.starts_with("1.5 exceeds mu_static = 1.25"), "{msg}");
    assert_eq!(
        fails(&[("building.mu_static", Some("-0.1"))], "building.mu_static"),
        "must be a finite number >= 0, got -0.1"
    );
    fails(&[("building.mu_kinetic", Some("-0.1"))], "building.mu_kinetic");
    fails(&[("building.mu_static", None)], "building.mu_static");
    fails(&[("building.normal_force", Some("\"variable\""))], "building.normal_force");
    let dynamic = ok(&[("building.normal_force", Some("\"dynamic\""))]);
    assert_eq!(dynamic.model().building().map(|b| b.normal_force()), Some(rocking::NormalForce::Dynamic));
}

#[test]
fn the_initial_rotation_must_be_below_a_right_angle() {
    let msg = fails(&[("initial.theta", Some("1.6"))], "initial.theta");
    assert!(msg.contains("below π/2"), "{msg}");
    fails(&[("initial.theta", Some("-2"))], "initial.theta");
    // α ≈ 0.32: 5 α > π/2.
    fails(&[("initial.theta_over_alpha", Some("5"))], "initial.theta_over_alpha");
    let msg = fails(
        &[("initial.theta", Some("0.1")), ("initial.theta_over_alpha", Some("0.1"))],
        "initial.theta_over_alpha",
    );
    assert_eq!(msg, "give either theta or theta_over_alpha, not both");
    fails(&[("initial.theta_dot", Some("nan"))], "initial.theta_dot");
    // Without a tower nothing can rotate.
    fails(&[("tower", None), ("initial.theta_dot", Some("0.1"))], "initial.theta_dot");
    fails(&[("tower", None), ("initial.theta_over_alpha", Some("0.1"))], "initial.theta_over_alpha");
}

#[test]
fn a_scenario_needs_a_tower_or_a_building() {
    let msg = fails(&[("tower", None), ("building", None)], "tower");
    assert_eq!(msg, "a scenario needs a [tower], a [building], or both");
    // Either alone is fine.
    assert!(ok(&[("tower", None)]).model().tower().is_none());
    assert!(ok(&[("building", None)]).model().building().is_none());
}

#[test]
fn keys_of_another_ground_type_do_not_apply() {
    let msg = fails(&[("ground.type", Some("\"sine-pulse\""))], "ground.duration");
    assert!(msg.starts_with("does not apply to type = \"sine-pulse\""), "{msg}");
    let msg = fails(
        &[("ground.type", Some("\"record\"")), ("ground.duration", None), ("ground.amplitude", None)],
        "ground.frequency",
    );
    assert!(
        msg.starts_with("does not apply to type = \"record\" (its keys: type, file, text, format, scale, units, dt, vertical)"),
        "{msg}"
    );
    fails(&[("ground.t0", Some("1.0"))], "ground.t0");
    fails(&[("ground.amplitude_ratio", Some("1.0"))], "ground.amplitude_ratio");
    let msg = fails(
        &[("tower", None), ("ground.amplitude", None), ("ground.amplitude_ratio", Some("2"))],
        "ground.amplitude_ratio",
    );
    assert!(msg.starts_with("needs a [tower]"), "{msg}");
    fails(
        &[("tower", None), ("ground.frequency", None), ("ground.frequency_ratio", Some("2"))],
        "ground.frequency_ratio",
    );
    fails(&[("ground.amplitude", None)], "ground.amplitude");
    fails(&[("ground.frequency", None)], "ground.frequency");
}

#[test]
fn every_ground_type_parses() {
    let pulse = |kind: &str| {
        ok(&[("ground.type", Some(kind)), ("ground.duration", None)])
            .build()
            .unwrap_or_else(|e| panic!("{e}"))
    };
    // One cycle of 5 Hz lasts 0.2 s.
    assert_relative_eq!(pulse("\"sine-pulse\"").ground.end_time(), 0.2, max_relative = 1e-15);
    assert_relative_eq!(pulse("\"cosine-pulse\"").ground.peak().1, 0.0);
    let ricker = ok(&[("ground.type", Some("\"ricker\"")), ("ground.duration", None), ("ground.t0", Some("0.5"))]);
    assert_eq!(ricker.build().map(|c| c.ground.end_time()).ok(), Some(1.0));
    let rect = ok(&[
        ("ground.type", Some("\"rectangular-pulse\"")),
        ("ground.frequency", None),
        ("ground.amplitude", Some("-0.7")),
    ]);
    let case = rect.build().unwrap_or_else(|e| panic!("{e}"));
    same(case.ground.end_time(), 2.0);
    assert_relative_eq!(case.ground.acceleration(1.0), -0.7 * 9.81, max_relative = 1e-15);
    let msg = fails(
        &[
            ("ground.type", Some("\"rectangular-pulse\"")),
            ("ground.frequency", None),
            ("ground.duration", None),
        ],
        "ground.duration",
    );
    assert!(msg.starts_with("required"), "{msg}");
    let none = ok(&[("ground", Some("{ type = \"none\" }")), ("initial.theta", Some("0.1"))]);
    assert_eq!(none.build().map(|c| c.ground).ok(), Some(rocking::GroundMotion::None));
    fails(&[("ground", Some("{ type = \"none\", amplitude = 1.0 }"))], "ground.amplitude");
}

/// A folder with a scenario's record files.
fn record_dir(files: &[(&str, &str)]) -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
    for (name, text) in files {
        std::fs::write(dir.path().join(name), text).unwrap_or_else(|e| panic!("{e}"));
    }
    dir
}

fn record_scenario(dir: &Path, ground: &str) -> Result<Scenario, crate::Error> {
    let mut t = edited(&[("ground", Some(ground))]);
    set_dotted(&mut t, "simulation.duration", Value::Float(1.0)).unwrap_or_else(|e| panic!("{e}"));
    Scenario::from_table(t, &dir.join("s.toml"))
}

#[test]
fn records_are_read_relative_to_the_scenario_and_scaled() {
    let dir = record_dir(&[("a.csv", "time,acceleration\n0.0,0.0\n0.1,0.2\n0.2,-0.4\n0.3,0.0\n")]);
    let s = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", scale = 2.0 }").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.record_file(), Some(dir.path().join("a.csv").as_path()));
    let case = s.build().unwrap_or_else(|e| panic!("{e}"));
    let info = case.ground_info.record.clone().unwrap_or_else(|| panic!("no record info"));
    assert_eq!(info.samples, 4);
    assert_eq!(info.format, rocking::RecordFormat::Csv);
    // Values in g by default, times the scale: peak 2 × 0.4 g at 0.2 s.
    let (peak, at) = case.ground.peak();
    assert_relative_eq!(peak, 0.8 * 9.81, max_relative = 1e-14);
    assert_relative_eq!(at, 0.2);
    assert_eq!(case.inputs, vec![dir.path().join("a.csv")]);
    // Units apply to CSV: the same file in cm/s².
    let s = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", units = \"cm/s2\" }").unwrap_or_else(|e| panic!("{e}"));
    assert_relative_eq!(s.build().map(|c| c.ground.peak().0).unwrap_or(0.0), 0.004, max_relative = 1e-14);
}

#[test]
fn record_errors_name_the_file_key_and_line() {
    let dir = record_dir(&[("bad.csv", "time,acceleration\n0.0,0.0\n0.1,0.1x\n")]);
    let build_error = |ground: &str| -> crate::Error {
        match record_scenario(dir.path(), ground).and_then(|s| s.build()) {
            Ok(_) => panic!("{ground} built"),
            Err(e) => e,
        }
    };
    let file = dir.path().join("s.toml");
    let e = build_error("{ type = \"record\", file = \"missing.AT2\" }");
    let line = e.to_string();
    assert!(line.starts_with(&format!("{}: ground.file: cannot read ", file.display())), "{line}");
    assert!(line.ends_with("missing.AT2: No such file or directory"), "{line}");
    let e = build_error("{ type = \"record\", file = \"bad.csv\", format = \"csv\" }");
    assert!(matches!(e.kind(), ErrorKind::Record { .. }), "{e:?}");
    let line = e.to_string();
    assert!(line.contains("ground.file: ") && line.contains("bad.csv: line 3"), "{line}");
    assert!(!line.contains('\n'));
    // Keys of CSV files refused for other formats, given or guessed.
    let e = record_scenario(dir.path(), "{ type = \"record\", file = \"x.AT2\", format = \"at2\", dt = 0.01 }").err();
    assert_eq!(e.as_ref().and_then(|e| e.key()), Some("ground.dt"), "{e:?}");
    let e = record_scenario(dir.path(), "{ type = \"record\" }").err();
    assert_eq!(e.as_ref().and_then(|e| e.key()), Some("ground.file"), "{e:?}");
    let e = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", format = \"xls\" }").err();
    assert_eq!(e.as_ref().and_then(|e| e.key()), Some("ground.format"), "{e:?}");
    let e = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", scale = nan }").err();
    assert_eq!(e.as_ref().and_then(|e| e.key()), Some("ground.scale"), "{e:?}");
}

#[test]
fn json_gives_the_same_scenario_as_toml() {
    let json = serde_json::json!({
        "name": "t",
        "tower": {"width": 4, "height": 12.0, "mass": 1.5e5, "depth": null},
        "building": {"mass": 2.0e6, "mu_static": 1.25, "mu_kinetic": 1.0},
        "ground": {"type": "harmonic", "amplitude": 0.5, "frequency": 5.0, "duration": 2.0},
        "simulation": {"duration": 2.0}
    });
    let from_json = Scenario::from_json(json, Path::new(ORIGIN)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(from_json, ok(&[]));
    let e = Scenario::from_json(serde_json::json!({"tower": {"width": "4"}, "ground": {"type": "none"}}), Path::new(ORIGIN)).err();
    assert_eq!(
        e.map(|e| e.to_string()).as_deref(),
        Some("dir/s.toml: tower.width: expected a number, got a string")
    );
}

#[test]
fn a_sweep_sets_dotted_keys_before_parsing() {
    let mut t = table(BASE);
    let old = set_dotted(&mut t, "ground.frequency", Value::Float(3.0)).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(old, Some(Value::Float(5.0)));
    assert_eq!(get_dotted(&t, "ground.frequency"), Some(&Value::Float(3.0)));
    let case = Scenario::from_table(t, Path::new(ORIGIN))
        .and_then(|s| s.build())
        .unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(case.ground_info.frequency_hz, Some(3.0));
}

/// The keys the outputs reference lists in summary.json.
const REQUIRED: &[&str] = &[
    "alpha_rad",
    "R_m",
    "p_rad_s",
    "restitution",
    "uplift_acceleration_g",
    "slip_acceleration_g",
    "max_abs_theta_rad",
    "max_theta_over_alpha",
    "max_abs_slip_m",
    "final_slip_m",
    "impacts",
    "overturned",
    "overturn_time_s",
    "first_uplift_time_s",
    "first_slip_time_s",
    "max_top_displacement_m",
    "max_top_abs_acceleration_m_s2",
    "max_pivot_friction_demand",
    "tower_uplift_detected",
    "time_in_regime_s",
    "wall_time_s",
];

#[test]
fn summary_has_every_key_and_nulls_for_absent_bodies() {
    let outcome = ok(&[]).build().and_then(|c| c.run(RunOptions::SUMMARY)).unwrap_or_else(|e| panic!("{e}"));
    let json = summary_json(&outcome, 0.25);
    for key in REQUIRED {
        assert!(json.get(key).is_some(), "missing {key}");
    }
    assert_eq!(json["wall_time_s"], 0.25);
    assert!(json["impacts"].as_u64().is_some_and(|n| n > 0), "0.5 g > tan α = 1/3 g: the tower rocks");
    assert_eq!(json["first_slip_time_s"], serde_json::Value::Null, "0.5 g < μs g: the church holds");
    let regimes = json["time_in_regime_s"].as_object().cloned().unwrap_or_default();
    assert_eq!(regimes.keys().collect::<Vec<_>>(), ["rest", "rocking", "sliding", "rocking_sliding"]);
    let total: f64 = regimes.values().filter_map(serde_json::Value::as_f64).sum();
    assert_relative_eq!(total, 2.0, max_relative = 1e-12);
    assert!(outcome.history.is_none() && outcome.events.is_empty());

    // A building alone: the tower's quantities do not exist.
    let alone = ok(&[("tower", None), ("ground.amplitude", Some("1.5"))]);
    let json = summary_json(&alone.build().and_then(|c| c.run(RunOptions::SUMMARY)).unwrap_or_else(|e| panic!("{e}")), 0.0);
    for key in [
        "alpha_rad",
        "R_m",
        "p_rad_s",
        "max_abs_theta_rad",
        "max_theta_over_alpha",
        "impacts",
        "max_top_displacement_m",
    ] {
        assert!(json[key].is_null(), "{key} = {}", json[key]);
    }
    assert_eq!(json["overturned"], false);
    assert!(json["max_abs_slip_m"].as_f64().is_some_and(|u| u > 0.0), "1.5 g > μs g: the church slides");
    // A fixed base: the slip's quantities do not exist.
    let fixed = ok(&[("building", None)]);
    let json = summary_json(&fixed.build().and_then(|c| c.run(RunOptions::SUMMARY)).unwrap_or_else(|e| panic!("{e}")), 0.0);
    for key in ["slip_acceleration_g", "max_abs_slip_m", "final_slip_m"] {
        assert!(json[key].is_null(), "{key} = {}", json[key]);
    }
}

#[test]
fn scalars_flatten_nested_objects() {
    let outcome = ok(&[]).build().and_then(|c| c.run(RunOptions::SUMMARY)).unwrap_or_else(|e| panic!("{e}"));
    let scalars = summary_scalars(&summary_json(&outcome, 1.0));
    let names: Vec<&str> = scalars.iter().map(|(k, _)| k.as_str()).collect();
    assert!(names.contains(&"time_in_regime_s.rocking"), "{names:?}");
    assert!(!names.contains(&"time_in_regime_s"), "{names:?}");
    assert_eq!(names.first(), Some(&"name"));
    assert!(scalars.iter().all(|(_, v)| !v.is_object() && !v.is_array()));
}

#[test]
fn history_and_events_are_recorded_when_asked() {
    let case = ok(&[("tower.points", Some("[[0.0, 12.0]]"))]).build().unwrap_or_else(|e| panic!("{e}"));
    let outcome = case.run(RunOptions::ALL).unwrap_or_else(|e| panic!("{e}"));
    let history = outcome.history.unwrap_or_else(|| panic!("no history"));
    // 2 s every 5 ms: 401 rows.
    assert_eq!(history.samples.len(), 401);
    // The extra point at the top centre moves exactly like the top centre.
    for (s, p) in history.samples.iter().zip(&history.point_values) {
        assert_relative_eq!(p[0].0, s.top_dx, epsilon = 1e-12);
    }
    assert_eq!(outcome.events.first().map(|e| e.kind), Some(rocking::EventKind::Uplift));
}

#[test]
fn the_origin_names_the_file_in_every_error() {
    let e = Scenario::from_toml_str("[ground]\ntype = \"none\"\n", &PathBuf::from("elsewhere/x.toml")).err();
    assert_eq!(
        e.map(|e| e.to_string()).as_deref(),
        Some("elsewhere/x.toml: tower: a scenario needs a [tower], a [building], or both")
    );
}

/// A sweep runs without a history, `rocking run` with one: their summaries must agree exactly.
#[test]
fn recording_the_history_does_not_change_the_summary() {
    let case = ok(&[("ground.amplitude", Some("1.5"))]).build().unwrap_or_else(|e| panic!("{e}"));
    let with = case.run(RunOptions::ALL).unwrap_or_else(|e| panic!("{e}"));
    let without = case.run(RunOptions::SUMMARY).unwrap_or_else(|e| panic!("{e}"));
    assert!(with.summary.first_slip_time.is_some(), "1.5 g: both bodies move");
    assert_eq!(summary_json(&with, 0.0), summary_json(&without, 0.0));
}

/// A record given as `text` (the web page, which has no files): the same
/// motion as the same content read from a file, so the same run.
#[test]
fn a_record_given_as_text_runs_as_the_same_file() {
    let content = "time,acceleration\n0.0,0.0\n0.1,0.5\n0.2,-0.6\n0.3,0.0\n";
    let dir = record_dir(&[("a.csv", content)]);
    let from_file = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", scale = 2.0 }");
    let quoted = toml::Value::String(content.into()).to_string();
    let from_text = record_scenario(dir.path(), &format!("{{ type = \"record\", text = {quoted}, scale = 2.0 }}"));
    let run = |s: Result<Scenario, crate::Error>| {
        let case = s.and_then(|s| s.build()).unwrap_or_else(|e| panic!("{e}"));
        let outcome = case.run(RunOptions::SUMMARY).unwrap_or_else(|e| panic!("{e}"));
        (
            case.ground_info.record.map(|r| (r.samples, r.format, r.duration_s)),
            summary_json(&outcome, 0.0),
        )
    };
    let (file_info, file_summary) = run(from_file);
    let (text_info, text_summary) = run(from_text);
    // Four samples, 0.3 s, guessed as CSV: what the content says, both ways.
    assert_eq!(file_info, Some((4, rocking::RecordFormat::Csv, 0.3)));
    // The same bytes through the same parser and the same run: equal to the last bit.
    assert_eq!(text_info, file_info);
    assert_eq!(text_summary, file_summary);
    // No file to guard against overwriting.
    let s = record_scenario(dir.path(), "{ type = \"record\", text = \"0.0\\n0.1\\n\", dt = 0.01 }").unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(s.record_file(), None);
    // Both, or a malformed text: one line naming ground.text.
    let e = record_scenario(dir.path(), "{ type = \"record\", file = \"a.csv\", text = \"0.0\" }").err();
    assert_eq!(e.as_ref().and_then(|e| e.key()), Some("ground.text"), "{e:?}");
    let e = record_scenario(
        dir.path(),
        "{ type = \"record\", text = \"time,acceleration\\n0.0,0.0\\n0.1,0.1x\\n\", format = \"csv\" }",
    )
    .and_then(|s| s.build())
    .err();
    let line = e.map(|e| e.to_string()).unwrap_or_default();
    assert!(line.contains("ground.text: ") && line.contains("line 3") && !line.contains('\n'), "{line}");
}

/// The errors offer every key of the description (crate::SCENARIO_KEYS): a
/// key misspelt (one letter added) is refused with the key in the valid
/// list, and suggested where the suggestion rule allows (a key of more than
/// one letter), the vertical motion's keys included.
#[test]
fn a_misspelt_key_of_the_description_is_suggested() {
    let keys = crate::SCENARIO_KEYS.iter().filter(|k| k.section().is_some());
    let vertical_keys = crate::SCENARIO_KEYS.iter().filter(|k| k.section() == Some("ground") && k.is_sweepable());
    let all: Vec<(String, &str)> = keys
        .map(|k| (k.key.to_string(), k.name()))
        .chain(vertical_keys.map(|k| (format!("{}{}", crate::VERTICAL_PREFIX, k.name()), k.name())))
        .collect();
    assert_eq!(
        all.len(),
        40 + 9 + 14,
        "the table's keys in sections, [[block]]'s, and [ground]'s scalar keys again"
    );
    for (key, name) in all {
        let typo = format!("{key}x");
        let mut edits = vec![(typo.clone(), Some("1".to_string()))];
        // A motion lists the keys of its type: one that takes the key, without the base's keys it does not take.
        let motion = ["ground.vertical.", "ground."].into_iter().find(|m| key.starts_with(m));
        if let Some(motion) = motion {
            let (type_name, kind) = crate::ground::KINDS
                .iter()
                .find(|(_, kind)| kind.keys().contains(&name))
                .unwrap_or(&crate::ground::KINDS[0]);
            edits.push((format!("{motion}type"), Some(format!("\"{type_name}\""))));
            for base in ["amplitude", "frequency", "duration"] {
                let given = kind.keys().contains(&base) && (motion == "ground." || base == "amplitude");
                edits.push((format!("{motion}{base}"), given.then(|| "0.1".to_string())));
            }
        }
        let edits: Vec<(&str, Option<&str>)> = edits.iter().map(|(k, v)| (k.as_str(), v.as_deref())).collect();
        let msg = fails(&edits, &named(&typo));
        let valid = msg.split("valid keys: ").nth(1).unwrap_or_else(|| panic!("{typo}: {msg}"));
        assert!(valid.split(", ").any(|k| k == name), "{typo}: {msg}");
        if name.chars().count() > 1 {
            assert!(msg.starts_with(&format!("unknown key (did you mean `{name}`?)")), "{typo}: {msg}");
        }
    }
}

/// The choices of the description are the parser's: a value outside them is
/// refused with the parser's own list, which is the description's.
#[test]
fn the_choices_of_the_description_are_the_parsers() {
    let record: [(&str, Option<&str>); 5] = [
        ("ground.type", Some("\"record\"")),
        ("ground.file", Some("\"x.csv\"")),
        ("ground.amplitude", None),
        ("ground.frequency", None),
        ("ground.duration", None),
    ];
    let with_choices: Vec<_> = crate::SCENARIO_KEYS.iter().filter(|k| !k.choices.is_empty()).collect();
    let keys: Vec<&str> = with_choices.iter().map(|k| k.key).collect();
    assert_eq!(
        keys,
        [
            "tower.section",
            "block.section",
            "building.normal_force",
            "ground.type",
            "ground.format",
            "ground.units"
        ]
    );
    for doc in with_choices {
        let mut edits = vec![(doc.key, Some("\"nonsense\""))];
        if doc.key == "ground.format" || doc.key == "ground.units" {
            edits.extend(record);
        }
        let listed: Vec<String> = doc.choices.iter().map(|c| format!("\"{c}\"")).collect();
        assert_eq!(fails(&edits, &named(doc.key)), format!("\"nonsense\" is not one of {}", listed.join(", ")));
    }
}
