//! Every key of a scenario file, written once: its unit, default, valid range,
//! meaning and an example.
//!
//! The parser's unknown-key checks take their lists from [`SCENARIO_KEYS`]
//! (a key missing here is refused by the parser), and `rocking keys --markdown`
//! prints [`keys_markdown`], the reference page of the documentation
//! (`docs/src/reference/keys.md`), so that the page and the parser cannot
//! drift apart. The ranges are those the parser and the library enforce.

use crate::ground::GroundKind;
use crate::sweep::SWEEPABLE_KEYS;
use std::fmt::Write;

/// What a key takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KeyKind {
    /// A number (an integer is accepted: `width = 4`).
    Number,
    /// A string, often one of a fixed set.
    Text,
    /// A list of `[x, y]` pairs of numbers.
    Points,
    /// A table of keys of its own (`ground.vertical`).
    Table,
    /// A list of strings or numbers (`assessment.records`, `assessment.period_range`).
    List,
}

impl KeyKind {
    fn as_str(self) -> &'static str {
        match self {
            KeyKind::Number => "number",
            KeyKind::Text => "string",
            KeyKind::Points => "list of [x, y]",
            KeyKind::Table => "table",
            KeyKind::List => "list",
        }
    }
}

/// The documentation of one scenario key.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KeyDoc {
    /// The dotted key: `"tower.width"`, or `"name"` at the top level.
    pub key: &'static str,
    /// What it takes.
    pub kind: KeyKind,
    /// Its unit (empty for a dimensionless number or a string).
    pub unit: &'static str,
    /// Its default, or when it is required.
    pub default: &'static str,
    /// The values accepted.
    pub range: &'static str,
    /// What it means.
    pub meaning: &'static str,
    /// A value as written in a scenario file (TOML).
    pub example: &'static str,
}

impl KeyDoc {
    /// The section (`"tower"`), or `None` for a top-level key.
    pub fn section(&self) -> Option<&'static str> {
        self.key.split_once('.').map(|(s, _)| s)
    }
    /// The key within its section (`"width"`).
    pub fn name(&self) -> &'static str {
        self.key.split_once('.').map_or(self.key, |(_, k)| k)
    }
}

pub(crate) const fn key(
    key: &'static str,
    kind: KeyKind,
    unit: &'static str,
    default: &'static str,
    range: &'static str,
    meaning: &'static str,
    example: &'static str,
) -> KeyDoc {
    KeyDoc {
        key,
        kind,
        unit,
        default,
        range,
        meaning,
        example,
    }
}

use KeyKind::{Number, Points, Table, Text};

/// Every key of a scenario, section by section, in the order the parser lists
/// them in its errors.
pub const SCENARIO_KEYS: &[KeyDoc] = &[
    key(
        "name",
        Text,
        "",
        "the file stem",
        "any string",
        "A name for the scenario, repeated in the outputs.",
        "\"tower on church\"",
    ),
    // [tower]
    key(
        "tower.width",
        Number,
        "m",
        "required (or radius and alpha)",
        "> 0",
        "Width B of the tower in the plane of rocking.",
        "4.0",
    ),
    key(
        "tower.height",
        Number,
        "m",
        "required (or radius and alpha)",
        "> 0",
        "Height H of the tower above the springing level.",
        "12.0",
    ),
    key("tower.mass", Number, "kg", "required (or density)", "> 0", "Mass m2 of the tower.", "1.5e5"),
    key(
        "tower.density",
        Number,
        "kg/m³",
        "instead of mass",
        "> 0; not with mass",
        "Density of the masonry: the mass is density × volume of the section.",
        "1800.0",
    ),
    key("tower.depth", Number, "m", "= width", "> 0", "Depth D out of the plane of rocking.", "4.0"),
    key(
        "tower.section",
        Text,
        "",
        "\"solid\"",
        "\"solid\" or \"hollow\"",
        "A uniform prism, or a tube open at both ends (outer B × D, wall thickness t).",
        "\"hollow\"",
    ),
    key(
        "tower.wall_thickness",
        Number,
        "m",
        "required for \"hollow\"; refused for \"solid\"",
        "> 0 and 2t < min(width, depth)",
        "Wall thickness t of a hollow section.",
        "0.8",
    ),
    key(
        "tower.inertia_pivot",
        Number,
        "kg·m²",
        "the section's: solid (m2/3)(B² + H²); hollow by parallel axes",
        "> m2 R²; required with radius and alpha",
        "Moment of inertia I_O about a base corner; overrides the section's value.",
        "1.2e7",
    ),
    key(
        "tower.restitution",
        Number,
        "",
        "Housner's r = 1 − 2 m2 R² sin²α / I_O",
        "0 ≤ r ≤ 1",
        "Ratio r of the angular velocities after and before an impact (not the energy ratio r²).",
        "0.85",
    ),
    key(
        "tower.points",
        Points,
        "m",
        "none (the top centre is always reported)",
        "finite coordinates",
        "Extra points (x, y) in tower coordinates (origin at the base centre) whose motion is reported.",
        "[[0.0, 12.0], [2.0, 6.0]]",
    ),
    key(
        "tower.radius",
        Number,
        "m",
        "instead of width and height",
        "> 0; with mass, inertia_pivot and alpha",
        "R, the distance from a base corner to the centre of mass.",
        "6.32",
    ),
    key(
        "tower.alpha",
        Number,
        "rad",
        "instead of width and height",
        "0 < α < π/2; with mass, inertia_pivot and radius",
        "Slenderness angle α = atan(b/h).",
        "0.3217",
    ),
    // [building]
    key(
        "building.mass",
        Number,
        "kg",
        "required",
        "> 0",
        "Mass m1 of the building without the tower.",
        "2.0e6",
    ),
    key(
        "building.mu_static",
        Number,
        "",
        "required",
        "≥ 0",
        "Static friction coefficient μs of the foundation.",
        "1.25",
    ),
    key(
        "building.mu_kinetic",
        Number,
        "",
        "= mu_static",
        "0 ≤ μk ≤ μs",
        "Kinetic friction coefficient μk of the foundation.",
        "1.0",
    ),
    key(
        "building.normal_force",
        Text,
        "",
        "\"constant\"",
        "\"constant\" or \"dynamic\"",
        "Normal force on the foundation: M g (the paper's), or M g plus the tower's inertial term.",
        "\"dynamic\"",
    ),
    // [ground]
    key(
        "ground.type",
        Text,
        "",
        "required",
        "\"harmonic\", \"sine-pulse\", \"cosine-pulse\", \"rectangular-pulse\", \"ricker\", \"record\", \"none\"",
        "The kind of horizontal ground acceleration.",
        "\"harmonic\"",
    ),
    key(
        "ground.amplitude",
        Number,
        "g",
        "required (or amplitude_ratio)",
        "≥ 0 for a harmonic (its phase gives the sign); any finite value for a pulse",
        "Peak ground acceleration A, in units of simulation.g.",
        "0.5",
    ),
    key(
        "ground.amplitude_ratio",
        Number,
        "",
        "instead of amplitude",
        "as amplitude; needs a [tower]",
        "A / tan α: the amplitude as a multiple of the tower's uplift acceleration g tan α.",
        "1.5",
    ),
    key(
        "ground.frequency",
        Number,
        "Hz",
        "required (or frequency_ratio)",
        "> 0",
        "Frequency f of the harmonic or of the pulse.",
        "5.0",
    ),
    key(
        "ground.frequency_ratio",
        Number,
        "",
        "instead of frequency",
        "> 0; needs a [tower]",
        "ω / p with ω = 2π f: the frequency as a multiple of the tower's frequency parameter p.",
        "2.0",
    ),
    key(
        "ground.duration",
        Number,
        "s",
        "harmonic: simulation.duration; rectangular-pulse: required",
        "> 0",
        "How long the harmonic shakes, or how long the rectangular pulse lasts; then a_g = 0.",
        "10.0",
    ),
    key(
        "ground.phase",
        Number,
        "rad",
        "0",
        "finite",
        "Phase φ of the harmonic: a_g = A g sin(2π f t + φ).",
        "1.5708",
    ),
    key(
        "ground.t0",
        Number,
        "s",
        "1.5 / frequency",
        "> 0",
        "Centre t0 of the Ricker wavelet, which lasts 0 ≤ t ≤ 2 t0.",
        "0.3",
    ),
    key(
        "ground.file",
        Text,
        "",
        "required for a record (or `text`)",
        "a non-empty path, relative to the scenario file's folder",
        "The accelerogram to read.",
        "\"../../data/records/elcentro_1940_ns.AT2\"",
    ),
    key(
        "ground.text",
        Text,
        "",
        "instead of `file`",
        "the content of a record file (AT2, ESM or CSV)",
        "The accelerogram itself, for callers without files (the page in the browser); errors name it `<text>`.",
        "\"time,acceleration\\n0,0\\n0.01,0.1\\n\"",
    ),
    key(
        "ground.format",
        Text,
        "",
        "guessed from the content",
        "\"at2\", \"esm\" or \"csv\"",
        "Layout of the record: PEER NGA AT2, ESM/ITACA ASCII, or CSV.",
        "\"at2\"",
    ),
    key(
        "ground.scale",
        Number,
        "",
        "1",
        "finite (negative mirrors the record)",
        "Factor applied to every sample of the record.",
        "1.5",
    ),
    key(
        "ground.units",
        Text,
        "",
        "\"g\"",
        "\"g\", \"m/s2\" or \"cm/s2\"; CSV only",
        "Units of the acceleration column of a CSV record.",
        "\"cm/s2\"",
    ),
    key(
        "ground.dt",
        Number,
        "s",
        "the CSV's time column",
        "> 0; CSV only",
        "Time step of a CSV record that has one acceleration column.",
        "0.01",
    ),
    key(
        "ground.vertical",
        Table,
        "",
        "none (no vertical motion)",
        "a table with the keys of [ground] above, but vertical",
        "Vertical ground acceleration a_v, positive upwards, written `[ground.vertical]`: any type, with the same keys, units and ranges as the horizontal motion (amplitudes in g). Gravity becomes g + a_v in the tower's equation, the normal force, the uplift and slip thresholds and the pivot reactions; where g + a_v reaches 0 the run stops with an error giving the instant. Its keys sweep as `ground.vertical.KEY`.",
        "{ type = \"harmonic\", amplitude = 0.2, frequency = 8.0 }",
    ),
    // [initial]
    key(
        "initial.theta",
        Number,
        "rad",
        "0",
        "|θ| < π/2; not with theta_over_alpha",
        "Initial rotation θ of the tower (> 0 leans towards +x).",
        "0.05",
    ),
    key(
        "initial.theta_over_alpha",
        Number,
        "",
        "instead of theta",
        "|ratio · α| < π/2; needs a [tower]",
        "Initial rotation as a multiple of α.",
        "0.5",
    ),
    key(
        "initial.theta_dot",
        Number,
        "rad/s",
        "0",
        "finite; non-zero needs a [tower]",
        "Initial angular velocity θ̇ of the tower.",
        "0.0",
    ),
    // [simulation]
    key(
        "simulation.duration",
        Number,
        "s",
        "20",
        "> 0",
        "Simulated time, shaking and free motion after it.",
        "20.0",
    ),
    key(
        "simulation.g",
        Number,
        "m/s²",
        "9.81",
        "> 0",
        "Gravity; also the unit of every acceleration given in g.",
        "9.81",
    ),
    key(
        "simulation.output_dt",
        Number,
        "s",
        "0.005",
        "> 0 and duration / output_dt ≤ 1e7",
        "Spacing of the rows of history.csv (events are written at their exact instants).",
        "0.005",
    ),
    key(
        "simulation.rtol",
        Number,
        "",
        "1e-8",
        "> 0",
        "Relative tolerance of the integrator (DOP853), per step.",
        "1e-8",
    ),
    key(
        "simulation.atol",
        Number,
        "",
        "1e-10",
        "> 0",
        "Absolute tolerance of the integrator (rad, rad/s, m, m/s).",
        "1e-10",
    ),
];

/// The keys of `section` (`"tower"`), without the section, in table order:
/// what the parser accepts there.
pub(crate) fn section_keys(section: &str) -> Vec<&'static str> {
    SCENARIO_KEYS.iter().filter(|k| k.section() == Some(section)).map(KeyDoc::name).collect()
}

/// Whether `section.name` is a scenario key: what [`section_keys`] answers,
/// without building the list (a sweep asks for every case).
pub(crate) fn is_section_key(section: &str, name: &str) -> bool {
    SCENARIO_KEYS
        .iter()
        .any(|k| k.key.strip_prefix(section).and_then(|rest| rest.strip_prefix('.')) == Some(name))
}

/// The ground types and the keys each takes, as the parser checks them.
fn ground_types_of(name: &str) -> Vec<&'static str> {
    crate::ground::KINDS
        .iter()
        .filter(|(_, kind)| kind.keys().contains(&name) && *kind != GroundKind::None || name == "type" || name == crate::ground::VERTICAL)
        .map(|(type_name, _)| *type_name)
        .collect()
}

/// Escapes `|` for a Markdown table cell.
fn cell(text: &str) -> String {
    text.replace('|', "\\|")
}

/// The reference page of every scenario and sweep key, in Markdown
/// (`rocking keys --markdown`; committed as `docs/src/reference/keys.md`).
pub fn keys_markdown() -> String {
    let mut out = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(out, "<!-- Generated by `rocking keys --markdown` from the table the parser checks keys against");
    let _ = writeln!(out, "     (crates/rocking-scenario/src/keys.rs); edit that table, not this page. -->");
    let _ = writeln!(out);
    let _ = writeln!(out, "# Scenario and sweep keys");
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "Every key a scenario file accepts, with its unit, default, the values accepted and an example. \
         A key not listed here, a key of another ground type, or a value outside its range is refused \
         with one line naming the file, the key and what is wrong (exit code 1). \
         Numbers may be written as integers (`width = 4`). Accelerations \"in g\" use `simulation.g`."
    );
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "A scenario needs `[ground]` and a `[tower]` or a `[building]` (or both): a tower without a building \
         rocks on a fixed base; a building without a tower is a sliding block."
    );
    let mut current: Option<Option<&str>> = None;
    for doc in SCENARIO_KEYS {
        if current != Some(doc.section()) {
            current = Some(doc.section());
            let _ = writeln!(out);
            match doc.section() {
                None => {
                    let _ = writeln!(out, "## Top level");
                }
                Some(s) => {
                    let _ = writeln!(out, "## `[{s}]`");
                }
            }
            let _ = writeln!(out);
            if doc.section() == Some("ground") {
                let _ = writeln!(
                    out,
                    "The keys each `type` takes are listed under \"types\"; any other ground key is refused for that type."
                );
                let _ = writeln!(out);
                let _ = writeln!(out, "| key | takes | unit | default | valid | types | meaning | example |");
                let _ = writeln!(out, "|---|---|---|---|---|---|---|---|");
            } else {
                let _ = writeln!(out, "| key | takes | unit | default | valid | meaning | example |");
                let _ = writeln!(out, "|---|---|---|---|---|---|---|");
            }
        }
        let types = if doc.section() == Some("ground") {
            format!(" {} |", ground_types_of(doc.name()).join(", "))
        } else {
            String::new()
        };
        key_row(&mut out, doc, &types);
    }
    let _ = writeln!(out);
    let _ = writeln!(out, "## `[sweep]`");
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "A sweep file is a scenario plus a `[sweep]` table. Each of its keys is a dotted scenario key, quoted \
         (`\"ground.frequency\"`), and its value is one of:"
    );
    let _ = writeln!(out);
    let _ = writeln!(out, "| value | meaning | example |");
    let _ = writeln!(out, "|---|---|---|");
    let _ = writeln!(out, "| a list | these values, in this order | `[0.3, 0.5, 0.7]` |");
    let _ = writeln!(
        out,
        "| `{{ from, to, steps }}` | `steps` (≥ 2, or 1 when from = to) values evenly spaced, both ends included | `{{ from = 3.0, to = 7.0, steps = 41 }}` |"
    );
    let _ = writeln!(
        out,
        "| `{{ from, to, step }}` | from, from + step, … to; the step (> 0) must divide the range | `{{ from = 1.0, to = 7.0, step = 0.25 }}` |"
    );
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "An axis has at most {} values. Every combination of the axes is one case. The keys that can be swept are \
         the scalar keys above (every key but `tower.points`):",
        crate::MAX_AXIS_VALUES
    );
    let _ = writeln!(out);
    let sweepable: Vec<String> = SWEEPABLE_KEYS.iter().map(|k| format!("`{k}`")).collect();
    let _ = writeln!(out, "{}.", sweepable.join(", "));
    let _ = writeln!(out);
    let pairs: Vec<String> = crate::sweep::axis::ALTERNATIVES.iter().map(|(a, b)| format!("`{a}` and `{b}`")).collect();
    let _ = writeln!(
        out,
        "An axis on one of two alternatives ({}) replaces the other in the base scenario; two axes on the same pair are an error.",
        pairs.join(", ")
    );
    assessment_keys_markdown(&mut out);
    out
}

/// The section of the reference page on `[site]` and `[assessment]`.
fn assessment_keys_markdown(out: &mut String) {
    let _ = writeln!(out);
    let _ = writeln!(out, "## Assessment files: `[site]` and `[assessment]`");
    let _ = writeln!(out);
    let _ = writeln!(
        out,
        "An assessment file (read by `rocking spectrum --site`) is a scenario without `[ground]`, plus `[site]`, \
         with one table per limit state (`[site.SLV]`, `<LS>` below) or a hazard grid and the site's coordinates, \
         and `[assessment]`. See the chapter on spectra and record sets."
    );
    let _ = writeln!(out);
    let _ = writeln!(out, "| key | takes | unit | default | valid | meaning | example |");
    let _ = writeln!(out, "|---|---|---|---|---|---|---|");
    for doc in crate::assessment::ASSESSMENT_KEY_DOCS {
        key_row(out, doc, "");
    }
}

/// One row of a key table; `types` is the extra column of `[ground]` (`" harmonic, record |"`) or empty.
fn key_row(out: &mut String, doc: &KeyDoc, types: &str) {
    let unit = if doc.unit.is_empty() { "—" } else { doc.unit };
    let _ = writeln!(
        out,
        "| `{}` | {} | {} | {} | {} |{} {} | `{}` |",
        doc.key,
        doc.kind.as_str(),
        cell(unit),
        cell(doc.default),
        cell(doc.range),
        types,
        cell(doc.meaning),
        cell(doc.example)
    );
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::axis::STRING_KEYS;

    /// The sections of the table are the parser's sections, in the same order,
    /// and its top-level keys are the parser's.
    #[test]
    fn sections_and_top_level_keys_are_the_parsers() {
        let mut sections: Vec<&str> = Vec::new();
        for s in SCENARIO_KEYS.iter().filter_map(KeyDoc::section) {
            if !sections.contains(&s) {
                sections.push(s);
            }
        }
        assert_eq!(sections, crate::SECTIONS);
        let top: Vec<&str> = SCENARIO_KEYS.iter().filter(|k| k.section().is_none()).map(|k| k.key).collect();
        assert_eq!(top, crate::TOP_LEVEL_KEYS);
    }

    /// The membership test a sweep asks per case gives what the list answers,
    /// for every key of every section, for near misses (a prefix of a
    /// section's name, a key of another section) and for a nested key.
    #[test]
    fn membership_agrees_with_the_list_of_a_section() {
        let mut names: Vec<&str> = SCENARIO_KEYS.iter().map(KeyDoc::name).collect();
        names.extend(["widt", "width.x", "", "vertical.type", "tower"]);
        for section in crate::SECTIONS.iter().copied().chain(["towe", "ground.vertical", ""]) {
            let list = section_keys(section);
            for name in &names {
                assert_eq!(is_section_key(section, name), list.contains(name), "{section}.{name}");
            }
        }
        // Both sides are not trivially false: a known key is found.
        assert!(is_section_key("tower", "width") && !is_section_key("towe", "r.width"));
    }

    /// Every key a ground type accepts is in the table: adding a key to a
    /// type's list in `ground.rs` without documenting it fails here.
    #[test]
    fn every_key_of_every_ground_type_is_documented() {
        let documented = section_keys("ground");
        for (name, kind) in crate::ground::KINDS {
            for k in kind.keys() {
                assert!(
                    documented.contains(k),
                    "ground.{k} (type \"{name}\") is accepted by the parser but not in SCENARIO_KEYS"
                );
            }
        }
        // And every documented ground key is taken by some type.
        for k in &documented {
            assert!(!ground_types_of(k).is_empty(), "ground.{k} is documented but no type takes it");
        }
    }

    /// The sweepable keys are the scalar keys of the table, and the string
    /// axes its string keys.
    #[test]
    fn sweepable_and_string_keys_follow_the_table() {
        // The scalar keys, and those of [ground] again under ground.vertical.
        let scalar = |kind: Option<KeyKind>| -> Vec<String> {
            let of_kind = |k: &&KeyDoc| k.kind != Points && k.kind != Table && kind.is_none_or(|kind| k.kind == kind);
            let mut keys: Vec<String> = SCENARIO_KEYS.iter().filter(of_kind).map(|k| k.key.to_string()).collect();
            let vertical = SCENARIO_KEYS.iter().filter(of_kind).filter(|k| k.section() == Some("ground"));
            keys.extend(vertical.map(|k| format!("ground.vertical.{}", k.name())));
            keys.sort_unstable();
            keys
        };
        let mut sweepable: Vec<String> = SWEEPABLE_KEYS.iter().map(|k| k.to_string()).collect();
        sweepable.sort_unstable();
        assert_eq!(sweepable, scalar(None));
        let mut strings: Vec<String> = STRING_KEYS.iter().map(|k| k.to_string()).collect();
        strings.sort_unstable();
        assert_eq!(strings, scalar(Some(Text)));
    }

    /// Every example value is accepted where it stands: each key's example,
    /// set in a small scenario that can take it, parses (so the examples of
    /// the page are valid input).
    #[test]
    fn every_example_parses() {
        use crate::Scenario;
        use std::path::Path;
        let geometry = "[tower]\nwidth = 4.0\nheight = 12.0\nmass = 1.5e5\n";
        let properties = "[tower]\nmass = 1.5e5\ninertia_pivot = 1.2e7\nradius = 6.32\nalpha = 0.3217\n";
        let building = "[building]\nmass = 2.0e6\nmu_static = 1.25\n";
        let harmonic = "[ground]\ntype = \"harmonic\"\namplitude = 0.5\nfrequency = 5.0\n";
        for doc in SCENARIO_KEYS {
            let line = format!("{} = {}\n", doc.name(), doc.example);
            let (tower, ground) = match doc.key {
                "tower.radius" | "tower.alpha" | "tower.inertia_pivot" => (properties.replace(&format!("{} = ", doc.name()), "#"), harmonic.to_string()),
                "tower.mass" | "tower.width" | "tower.height" => (geometry.replace(&format!("{} = ", doc.name()), "#"), harmonic.to_string()),
                "tower.density" => (geometry.replace("mass = ", "#"), harmonic.to_string()),
                "tower.wall_thickness" => (format!("{geometry}section = \"hollow\"\n"), harmonic.to_string()),
                "tower.section" => (format!("{geometry}wall_thickness = 0.8\n"), harmonic.to_string()),
                "ground.amplitude_ratio" => (geometry.to_string(), harmonic.replace("amplitude = ", "#")),
                "ground.frequency_ratio" => (geometry.to_string(), harmonic.replace("frequency = ", "#")),
                "ground.amplitude" | "ground.frequency" => (geometry.to_string(), harmonic.replace(&format!("{} = ", doc.name()), "#")),
                "ground.t0" => (
                    geometry.to_string(),
                    "[ground]\ntype = \"ricker\"\namplitude = 0.5\nfrequency = 5.0\n".to_string(),
                ),
                "ground.format" | "ground.scale" => (geometry.to_string(), "[ground]\ntype = \"record\"\nfile = \"x.AT2\"\n".to_string()),
                "ground.units" | "ground.dt" => (
                    geometry.to_string(),
                    "[ground]\ntype = \"record\"\nfile = \"x.csv\"\nformat = \"csv\"\n".to_string(),
                ),
                "ground.file" | "ground.text" => (geometry.to_string(), "[ground]\ntype = \"record\"\n".to_string()),
                _ => (geometry.to_string(), harmonic.to_string()),
            };
            let text = format!("{tower}{building}{ground}");
            let text = match doc.section() {
                _ if text.contains(&line) => text,
                None => format!("{line}{text}"),
                Some(s) if text.contains(&format!("[{s}]\n")) => text.replacen(&format!("[{s}]\n"), &format!("[{s}]\n{line}"), 1),
                Some(s) => format!("{text}[{s}]\n{line}"),
            };
            let parsed = Scenario::from_toml_str(&text, Path::new("example.toml"));
            assert!(
                parsed.is_ok(),
                "the example of {} does not parse: {:?}\n{text}",
                doc.key,
                parsed.err().map(|e| e.to_string())
            );
        }
    }
}
