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
use std::sync::LazyLock;

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
    /// `true` or `false` (`assessment.accept_incompatible_set`).
    Boolean,
}

impl KeyKind {
    fn as_str(self) -> &'static str {
        match self {
            KeyKind::Number => "number",
            KeyKind::Text => "string",
            KeyKind::Points => "list of [x, y]",
            KeyKind::Table => "table",
            KeyKind::List => "list",
            KeyKind::Boolean => "boolean",
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
    /// Its symbol, in a plot's legend (`A = 0.5 g`) and beside a
    /// dimensionless field of the page's form (`μs`); its name where it has none.
    pub symbol: &'static str,
    /// Its name in words, for a plot's axis (`ground frequency`, shown as
    /// `ground frequency (Hz)`).
    pub label: &'static str,
    /// The default as a field of the page's form shows it when the key is
    /// absent (`0`, `= width`); empty where the key is required or one of
    /// two alternatives. For a key with [`choices`](Self::choices), a
    /// non-empty placeholder is an extra first choice, "absent" (`(guess)`).
    pub placeholder: &'static str,
    /// The values of a string key that takes one of a fixed set, in the
    /// order the parser lists them; empty for any other key.
    pub choices: &'static [&'static str],
    /// The library's parameter this key sets: an error of the library about
    /// it names this key ([`crate::key_of`]).
    pub parameter: Option<rocking::Parameter>,
    /// Whether the page's form has a field for it (the page takes a record
    /// by its own button, and a tower by its geometry).
    pub on_form: bool,
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
    /// Whether a sweep can vary it: a number or a string (not a list or a table).
    pub fn is_sweepable(&self) -> bool {
        matches!(self.kind, KeyKind::Number | KeyKind::Text)
    }
    /// With its symbol and its words for a plot (see [`symbol`](Self::symbol), [`label`](Self::label)).
    pub(crate) const fn shown(self, symbol: &'static str, label: &'static str) -> Self {
        Self { symbol, label, ..self }
    }
    /// With the default a form's field shows (see [`placeholder`](Self::placeholder)).
    pub(crate) const fn placeholder(self, placeholder: &'static str) -> Self {
        Self { placeholder, ..self }
    }
    /// Taking one of `choices`.
    pub(crate) const fn choices(self, choices: &'static [&'static str]) -> Self {
        Self { choices, ..self }
    }
    /// Setting the library's `parameter`.
    pub(crate) const fn sets(self, parameter: rocking::Parameter) -> Self {
        Self {
            parameter: Some(parameter),
            ..self
        }
    }
    /// Without a field on the page's form.
    pub(crate) const fn off_form(self) -> Self {
        Self { on_form: false, ..self }
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
        symbol: "",
        label: "",
        placeholder: "",
        choices: &[],
        parameter: None,
        on_form: true,
    }
}

use rocking::Parameter as P;
use KeyKind::{Number, Points, Table, Text};

/// Every key of a scenario, section by section, in the order the parser lists
/// them in its errors: the top level's and the tower's ([`TOWER_KEYS`]),
/// those of `[[block]]` (most described by the tower's, [`block_keys`]), then
/// [`OTHER_KEYS`]. Built once, on first use.
pub static SCENARIO_KEYS: LazyLock<Vec<KeyDoc>> = LazyLock::new(|| {
    let mut keys = TOWER_KEYS.to_vec();
    keys.extend(block_keys());
    keys.extend_from_slice(OTHER_KEYS);
    keys
});

/// The top-level key and those of `[tower]`, in the parser's order.
const TOWER_KEYS: &[KeyDoc] = &[
    key(
        "name",
        Text,
        "",
        "the file stem",
        "any string",
        "A name for the scenario, repeated in the outputs.",
        "\"tower on church\"",
    )
    .shown("name", "scenario name")
    .off_form(),
    // [tower]
    key(
        "tower.width",
        Number,
        "m",
        "required (or radius and alpha)",
        "> 0",
        "Width B of the tower in the plane of rocking.",
        "4.0",
    )
    .shown("B", "tower width B")
    .sets(P::TowerWidth),
    key(
        "tower.height",
        Number,
        "m",
        "required (or radius and alpha)",
        "> 0",
        "Height H of the tower above the springing level.",
        "12.0",
    )
    .shown("H", "tower height H")
    .sets(P::TowerHeight),
    key("tower.mass", Number, "kg", "required (or density)", "> 0", "Mass m2 of the tower.", "1.5e5")
        .shown("m2", "tower mass m2")
        .sets(P::TowerMass),
    key(
        "tower.density",
        Number,
        "kg/m³",
        "instead of mass",
        "> 0; not with mass",
        "Density of the masonry: the mass is density × volume of the section.",
        "1800.0",
    )
    .shown("ρ", "tower density")
    .sets(P::TowerDensity),
    key("tower.depth", Number, "m", "= width", "> 0", "Depth D out of the plane of rocking.", "4.0")
        .shown("depth", "tower depth")
        .placeholder("= width")
        .sets(P::TowerDepth),
    key(
        "tower.section",
        Text,
        "",
        "\"solid\"",
        "\"solid\" or \"hollow\"",
        "A uniform prism, or a tube open at both ends (outer B × D, wall thickness t).",
        "\"hollow\"",
    )
    .shown("section", "tower section")
    .choices(&["solid", "hollow"]),
    key(
        "tower.wall_thickness",
        Number,
        "m",
        "required for \"hollow\"; refused for \"solid\"",
        "> 0 and 2t < min(width, depth)",
        "Wall thickness t of a hollow section.",
        "0.8",
    )
    .shown("t", "tower wall thickness")
    .sets(P::TowerWallThickness),
    key(
        "tower.compressive_strength",
        Number,
        "MPa",
        "none: infinitely strong, the tower rocks on its base's edges",
        "> 0; not with radius and alpha, nor with [[block]]",
        "Compressive strength f_m of the masonry: the tower rocks on the centroid of the strip along its base's edge that carries its weight at 0.85 f_d (f_d = f_m in a run, f_m / FC in an assessment), not on the edge.",
        "2.0",
    )
    .shown("f_m", "masonry compressive strength"),
    key(
        "tower.inertia_pivot",
        Number,
        "kg·m²",
        "the section's: solid (m2/3)(B² + H²); hollow by parallel axes",
        "> m2 R²; required with radius and alpha",
        "Moment of inertia I_O about a base corner; overrides the section's value.",
        "1.2e7",
    )
    .shown("I_O", "moment of inertia I_O")
    .placeholder("the section's")
    .sets(P::TowerInertiaPivot),
    key(
        "tower.restitution",
        Number,
        "",
        "Housner's r = 1 − 2 m2 R² sin²α / I_O",
        "0 ≤ r ≤ 1",
        "Ratio r of the angular velocities after and before an impact (not the energy ratio r²).",
        "0.85",
    )
    .shown("r", "restitution r")
    .placeholder("Housner's")
    .sets(P::TowerRestitution),
    key(
        "tower.points",
        Points,
        "m",
        "none (the top centre is always reported)",
        "finite coordinates",
        "Extra points (x, y) in tower coordinates (origin at the base centre) whose motion is reported.",
        "[[0.0, 12.0], [2.0, 6.0]]",
    )
    .shown("points", "extra tower points"),
    key(
        "tower.radius",
        Number,
        "m",
        "instead of width and height",
        "> 0; with mass, inertia_pivot and alpha",
        "R, the distance from a base corner to the centre of mass.",
        "6.32",
    )
    .shown("R", "tower radius R")
    .sets(P::TowerRadius)
    .off_form(),
    key(
        "tower.alpha",
        Number,
        "rad",
        "instead of width and height",
        "0 < α < π/2; with mass, inertia_pivot and radius",
        "Slenderness angle α = atan(b/h).",
        "0.3217",
    )
    .shown("α", "slenderness angle α")
    .sets(P::TowerAlpha)
    .off_form(),
];

/// The keys of a scenario after `[[block]]`: `[building]`, `[ground]`,
/// `[initial]` and `[simulation]`, in the parser's order.
const OTHER_KEYS: &[KeyDoc] = &[
    // [building]
    key(
        "building.mass",
        Number,
        "kg",
        "required",
        "> 0",
        "Mass m1 of the building without the tower.",
        "2.0e6",
    ).shown("m1", "building mass m1").sets(P::BuildingMass),
    key(
        "building.mu_static",
        Number,
        "",
        "required",
        "≥ 0",
        "Static friction coefficient μs of the foundation.",
        "1.25",
    ).shown("μs", "static friction μs").sets(P::BuildingMuStatic),
    key(
        "building.mu_kinetic",
        Number,
        "",
        "= mu_static",
        "0 ≤ μk ≤ μs",
        "Kinetic friction coefficient μk of the foundation.",
        "1.0",
    ).shown("μk", "kinetic friction μk").placeholder("= μs").sets(P::BuildingMuKinetic),
    key(
        "building.normal_force",
        Text,
        "",
        "\"constant\"",
        "\"constant\" or \"dynamic\"",
        "Normal force on the foundation: M g (the paper's), or M g plus the tower's inertial term.",
        "\"dynamic\"",
    ).shown("normal force", "normal force").choices(&["constant", "dynamic"]),
    // [ground]
    key(
        "ground.type",
        Text,
        "",
        "required",
        "\"harmonic\", \"sine-pulse\", \"cosine-pulse\", \"rectangular-pulse\", \"ricker\", \"record\", \"none\"",
        "The kind of horizontal ground acceleration.",
        "\"harmonic\"",
    ).shown("type", "ground motion type").choices(&["harmonic", "sine-pulse", "cosine-pulse", "rectangular-pulse", "ricker", "record", "none"]),
    key(
        "ground.amplitude",
        Number,
        "g",
        "required (or amplitude_ratio)",
        "≥ 0 for a harmonic (its phase gives the sign); any finite value for a pulse",
        "Peak ground acceleration A, in units of simulation.g.",
        "0.5",
    ).shown("A", "ground amplitude").sets(P::GroundAmplitude),
    key(
        "ground.amplitude_ratio",
        Number,
        "",
        "instead of amplitude",
        "as amplitude; needs a [tower]",
        "A / tan α: the amplitude as a multiple of the tower's uplift acceleration g tan α.",
        "1.5",
    ).shown("A/tan α", "amplitude ratio a_p/(g tan α)"),
    key(
        "ground.frequency",
        Number,
        "Hz",
        "required (or frequency_ratio)",
        "> 0",
        "Frequency f of the harmonic or of the pulse.",
        "5.0",
    ).shown("f", "ground frequency").sets(P::GroundFrequency),
    key(
        "ground.frequency_ratio",
        Number,
        "",
        "instead of frequency",
        "> 0; needs a [tower]",
        "ω / p with ω = 2π f: the frequency as a multiple of the tower's frequency parameter p.",
        "2.0",
    ).shown("ω/p", "frequency ratio ω/p"),
    key(
        "ground.duration",
        Number,
        "s",
        "harmonic: simulation.duration; rectangular-pulse: required",
        "> 0",
        "How long the harmonic shakes, or how long the rectangular pulse lasts; then a_g = 0.",
        "10.0",
    ).shown("duration", "shaking duration").sets(P::GroundDuration),
    key(
        "ground.phase",
        Number,
        "rad",
        "0",
        "finite",
        "Phase φ of the harmonic: a_g = A g sin(2π f t + φ).",
        "1.5708",
    ).shown("φ", "ground phase").placeholder("0").sets(P::GroundPhase),
    key(
        "ground.t0",
        Number,
        "s",
        "1.5 / frequency",
        "> 0",
        "Centre t0 of the Ricker wavelet, which lasts 0 ≤ t ≤ 2 t0.",
        "0.3",
    ).shown("t0", "pulse centre t0").placeholder("1.5 / f").sets(P::GroundRickerCentre),
    key(
        "ground.file",
        Text,
        "",
        "required for a record (or `text`)",
        "a non-empty path, relative to the scenario file's folder",
        "The accelerogram to read.",
        "\"../../data/records/elcentro_1940_ns.AT2\"",
    ).shown("file", "record file").off_form(),
    key(
        "ground.text",
        Text,
        "",
        "instead of `file`",
        "the content of a record file (AT2, ESM or CSV)",
        "The accelerogram itself, for callers without files (the page in the browser); errors name it `<text>`.",
        "\"time,acceleration\\n0,0\\n0.01,0.1\\n\"",
    ).shown("text", "record text").off_form(),
    key(
        "ground.format",
        Text,
        "",
        "guessed from the content",
        "\"at2\", \"esm\" or \"csv\"",
        "Layout of the record: PEER NGA AT2, ESM/ITACA ASCII, or CSV.",
        "\"at2\"",
    ).shown("format", "record format").placeholder("guess").choices(&["at2", "esm", "csv"]),
    key(
        "ground.scale",
        Number,
        "",
        "1",
        "finite (negative mirrors the record)",
        "Factor applied to every sample of the record.",
        "1.5",
    ).shown("scale", "record scale").placeholder("1"),
    key(
        "ground.units",
        Text,
        "",
        "\"g\"",
        "\"g\", \"m/s2\" or \"cm/s2\"; CSV only",
        "Units of the acceleration column of a CSV record.",
        "\"cm/s2\"",
    ).shown("units", "record units").placeholder("g").choices(&["g", "m/s2", "cm/s2"]),
    key(
        "ground.dt",
        Number,
        "s",
        "the CSV's time column",
        "> 0; CSV only",
        "Time step of a CSV record that has one acceleration column.",
        "0.01",
    ).shown("dt", "record time step"),
    key(
        "ground.vertical",
        Table,
        "",
        "none (no vertical motion)",
        "a table with the keys of [ground] above, but vertical",
        "Vertical ground acceleration a_v, positive upwards, written `[ground.vertical]`: any type, with the same keys, units and ranges as the horizontal motion (amplitudes in g). Gravity becomes g + a_v in the tower's equation, the normal force, the uplift and slip thresholds and the pivot reactions; where g + a_v reaches 0 the run stops with an error giving the instant. Its keys sweep as `ground.vertical.KEY`.",
        "{ type = \"harmonic\", amplitude = 0.2, frequency = 8.0 }",
    ).shown("a_v", "vertical ground motion"),
    // [initial]
    key(
        "initial.theta",
        Number,
        "rad",
        "0",
        "|θ| < π/2; not with theta_over_alpha",
        "Initial rotation θ of the tower (> 0 leans towards +x).",
        "0.05",
    ).shown("θ0", "initial rotation θ0").placeholder("0").sets(P::InitialTheta),
    key(
        "initial.theta_over_alpha",
        Number,
        "",
        "instead of theta",
        "|ratio · α| < π/2; needs a [tower]",
        "Initial rotation as a multiple of α.",
        "0.5",
    ).shown("θ0/α", "initial rotation θ0/α").placeholder("0"),
    key(
        "initial.theta_dot",
        Number,
        "rad/s",
        "0",
        "finite; non-zero needs a [tower]",
        "Initial angular velocity θ̇ of the tower.",
        "0.0",
    ).shown("θ̇0", "initial angular velocity").placeholder("0").sets(P::InitialThetaDot),
    // [simulation]
    key(
        "simulation.duration",
        Number,
        "s",
        "20",
        "> 0",
        "Simulated time, shaking and free motion after it.",
        "20.0",
    ).shown("duration", "duration").placeholder("20").sets(P::Duration),
    key(
        "simulation.g",
        Number,
        "m/s²",
        "9.81",
        "> 0",
        "Gravity; also the unit of every acceleration given in g.",
        "9.81",
    ).shown("g", "gravity g").placeholder("9.81").sets(P::Gravity),
    key(
        "simulation.output_dt",
        Number,
        "s",
        "0.005",
        "> 0 and duration / output_dt ≤ 1e7",
        "Spacing of the rows of history.csv (events are written at their exact instants).",
        "0.005",
    ).shown("output_dt", "output interval").placeholder("0.005"),
    key(
        "simulation.rtol",
        Number,
        "",
        "1e-8",
        "> 0",
        "Relative tolerance of the integrator (DOP853), per step.",
        "1e-8",
    ).shown("rtol", "relative tolerance").placeholder("1e-8").sets(P::RelativeTolerance),
    key(
        "simulation.atol",
        Number,
        "",
        "1e-10",
        "> 0",
        "Absolute tolerance of the integrator (rad, rad/s, m, m/s).",
        "1e-10",
    ).shown("atol", "absolute tolerance").placeholder("1e-10").sets(P::AbsoluteTolerance),
];

/// The name of a block, and its moment of inertia about its own centre of
/// mass: the keys of `[[block]]` the tower has not.
const BLOCK_NAME: KeyDoc = key(
    "block.name",
    Text,
    "",
    "block2, block3, … in order (the tower is block 1)",
    "letters, digits and _ (not first a digit), at most 32 characters; unique; not a section's name nor \"tower\"",
    "The block's name: it prefixes the block's outputs (`belfry_max_abs_theta_rad`) and its sweep keys (`belfry.width`).",
    "\"belfry\"",
)
.shown("name", "block name")
.off_form();

/// See [`BLOCK_NAME`].
const BLOCK_INERTIA_CENTRE: KeyDoc = key(
    "block.inertia_centre",
    Number,
    "kg·m²",
    "the section's: solid m (B² + H²)/12; hollow by parallel axes",
    "> 0",
    "Moment of inertia of the block about its own centre of mass; overrides the section's value.",
    "2.1e5",
)
.shown("J", "block moment of inertia")
.placeholder("the section's")
.off_form();

/// A key of `[[block]]` described by the tower's key of the same name: a
/// block is given as the tower is, by its outer dimensions.
struct AsTower {
    /// The key's name in both sections (`width`).
    name: &'static str,
    /// A value for a block, as written in a scenario file.
    example: &'static str,
    /// A bound of a block's alone, added to the tower's (empty if none).
    also: &'static str,
}

/// The keys of `[[block]]` described by the tower's, in the tower's order.
const AS_TOWER: &[AsTower] = &[
    AsTower {
        name: "width",
        example: "2.4",
        also: "at most the width of the block below (the tower's for the first)",
    },
    AsTower {
        name: "height",
        example: "6.0",
        also: "",
    },
    AsTower {
        name: "mass",
        example: "6.0e4",
        also: "",
    },
    AsTower {
        name: "density",
        example: "1800.0",
        also: "",
    },
    AsTower {
        name: "depth",
        example: "2.4",
        also: "",
    },
    AsTower {
        name: "section",
        example: "\"hollow\"",
        also: "",
    },
    AsTower {
        name: "wall_thickness",
        example: "0.6",
        also: "",
    },
];

/// The tower's words in the texts of its keys, each with a block's in its
/// place, in the order they are exchanged: a block stands on the block below
/// (not on the springing level), has no alternative description by R and α,
/// and its mass is `m` (the tower's, in the model, `m2`).
const BLOCK_WORDS: &[(&str, &str)] = &[
    ("required (or radius and alpha)", "required"),
    ("the springing level", "the top of the block below"),
    ("the tower", "the block"),
    ("tower ", "block "),
    ("m2", "m"),
];

/// A text of a tower's key as a block's: [`BLOCK_WORDS`] exchanged. Kept for
/// the life of the program, as [`SCENARIO_KEYS`] is, so leaking the few
/// texts (built once) costs nothing.
fn for_block(text: &'static str) -> &'static str {
    let exchanged = BLOCK_WORDS.iter().fold(text.to_string(), |t, (tower, block)| t.replace(tower, block));
    if exchanged == text {
        return text;
    }
    Box::leak(exchanged.into_boxed_str())
}

/// The keys of `[[block]]`, in the parser's order: the name, the tower's keys
/// of [`AS_TOWER`] in a block's words (unit, kind, choices and bounds the
/// tower's), and the moment of inertia about the centre of mass.
fn block_keys() -> Vec<KeyDoc> {
    let as_block = |tower: &KeyDoc, a: &AsTower| {
        let range = for_block(tower.range);
        KeyDoc {
            key: Box::leak(format!("{}.{}", crate::block::BLOCK, a.name).into_boxed_str()),
            default: for_block(tower.default),
            range: if a.also.is_empty() {
                range
            } else {
                Box::leak(format!("{range}; {}", a.also).into_boxed_str())
            },
            meaning: for_block(tower.meaning),
            example: a.example,
            symbol: for_block(tower.symbol),
            label: for_block(tower.label),
            // An error of the library about a block's parameter is named by
            // the block's key where the block is read (block.rs).
            parameter: None,
            // The page's form has fields of its own for each block.
            on_form: false,
            ..*tower
        }
    };
    let described = TOWER_KEYS.iter().filter_map(|tower| {
        AS_TOWER
            .iter()
            .find(|a| tower.key.strip_prefix("tower.") == Some(a.name))
            .map(|a| as_block(tower, a))
    });
    std::iter::once(BLOCK_NAME).chain(described).chain([BLOCK_INERTIA_CENTRE]).collect()
}

/// The keys of the vertical motion start so (`ground.vertical.amplitude`):
/// each is the key of `[ground]` after it, for the vertical motion.
pub const VERTICAL_PREFIX: &str = "ground.vertical.";

/// A dotted key found in [`SCENARIO_KEYS`]: its description, and whether it
/// is a key of the vertical motion (`ground.vertical.KEY`, described by
/// `ground.KEY`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct KeyRef {
    /// The description (of the horizontal key, for a vertical one).
    pub doc: &'static KeyDoc,
    /// Whether the key is of the vertical motion.
    pub vertical: bool,
}

impl KeyRef {
    /// The words of a plot's axis: the description's, `vertical ` before a key of the vertical motion.
    pub fn label(&self) -> String {
        if self.vertical {
            format!("vertical {}", self.doc.label)
        } else {
            self.doc.label.to_string()
        }
    }
    /// The symbol of a plot's legend: the description's, ` (vertical)` after a key of the vertical motion.
    pub fn symbol(&self) -> String {
        if self.vertical {
            format!("{} (vertical)", self.doc.symbol)
        } else {
            self.doc.symbol.to_string()
        }
    }
}

/// The description of a dotted key (`tower.width`, `ground.vertical.amplitude`), if it is a scenario key.
pub fn describe_key(key: &str) -> Option<KeyRef> {
    let find = |key: &str| SCENARIO_KEYS.iter().find(|k| k.key == key);
    match key.strip_prefix(VERTICAL_PREFIX) {
        Some(name) => find(&format!("ground.{name}")).map(|doc| KeyRef { doc, vertical: true }),
        None => find(key).map(|doc| KeyRef { doc, vertical: false }),
    }
}

/// The key of the key table that describes the sweep key `key` of a block
/// named in `names` (`belfry.width` → `block.width`), if `key` is one.
pub(crate) fn block_axis_key(key: &str, names: &crate::block::BlockNames) -> Option<String> {
    let (name, rest) = key.split_once('.')?;
    names.position(name)?;
    Some(format!("{}.{rest}", crate::block::BLOCK))
}

/// The keys of the block named `name` as a sweep's axis or an inventory's
/// column gives them (`belfry.width`), in table order; not its `name`, which
/// names its outputs and cannot be set so.
pub fn named_block_keys(name: &str) -> Vec<String> {
    SCENARIO_KEYS
        .iter()
        .filter(|k| k.section() == Some(crate::block::BLOCK) && k.is_sweepable() && k.name() != "name")
        .map(|k| format!("{name}.{}", k.name()))
        .collect()
}

/// The keys a sweep can vary, in table order: the scalar keys (every one but
/// lists and tables), those of `[ground]` again for the vertical motion where
/// the table `ground.vertical` stands.
pub(crate) fn sweepable_keys() -> Vec<&'static str> {
    let mut keys = Vec::new();
    for doc in SCENARIO_KEYS.iter() {
        if doc.section() == Some(crate::block::BLOCK) {
            // Swept by the block's name (`belfry.width`): see [`block_axis_key`].
            continue;
        }
        if doc.is_sweepable() {
            keys.push(doc.key);
        } else if doc.key == VERTICAL_PREFIX.trim_end_matches('.') {
            // Built once (SWEEPABLE_KEYS holds them for the life of the
            // program), so leaking the few names costs nothing.
            let ground = SCENARIO_KEYS.iter().filter(|k| k.section() == Some("ground") && k.is_sweepable());
            keys.extend(ground.map(|k| &*Box::leak(format!("{VERTICAL_PREFIX}{}", k.name()).into_boxed_str())));
        }
    }
    keys
}

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

/// Every key as JSON (`rocking keys --json`, and the page, which builds its
/// form from it): `{ "scenario": [key, …], "assessment": [key, …] }`, each key
/// an object with every field of its [`KeyDoc`] (`kind` as the reference
/// writes it, `parameter` left out), `sweepable`, and for a key of
/// `[ground]` the ground types that take it (`types`).
pub fn keys_json() -> serde_json::Value {
    let doc_json = |doc: &KeyDoc| {
        let mut value = serde_json::json!({
            "key": doc.key,
            "section": doc.section(),
            "name": doc.name(),
            "kind": doc.kind.as_str(),
            "unit": doc.unit,
            "symbol": doc.symbol,
            "label": doc.label,
            "default": doc.default,
            "placeholder": doc.placeholder,
            "range": doc.range,
            "meaning": doc.meaning,
            "example": doc.example,
            "choices": doc.choices,
            "sweepable": doc.is_sweepable(),
            "on_form": doc.on_form,
        });
        if doc.section() == Some("ground") {
            value["types"] = serde_json::json!(ground_types_of(doc.name()));
        }
        value
    };
    serde_json::json!({
        "scenario": SCENARIO_KEYS.iter().map(doc_json).collect::<Vec<_>>(),
        "assessment": crate::assessment::ASSESSMENT_KEY_DOCS.iter().map(doc_json).collect::<Vec<_>>(),
    })
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
    for doc in SCENARIO_KEYS.iter() {
        if current != Some(doc.section()) {
            current = Some(doc.section());
            let _ = writeln!(out);
            match doc.section() {
                None => {
                    let _ = writeln!(out, "## Top level");
                }
                Some(crate::block::BLOCK) => {
                    let _ = writeln!(out, "## `[[block]]`");
                    let _ = writeln!(out);
                    let _ = writeln!(
                        out,
                        "Blocks stacked on the tower (a belfry on its shaft, the drums of a column), at most {}: each `[[block]]` \
                         stands centred on the one before it, the first on `[tower]`, and rocks on the one below (docs: the model, \
                         \"A stack of blocks\"). Each block adds outputs prefixed by its name (docs: outputs). A sweep varies a block's \
                         key by its name: `\"belfry.width\" = [2.0, 2.4]`. With blocks, `[tower] restitution` and `[ground.vertical]` \
                         are errors.",
                        crate::block::MAX_ABOVE
                    );
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

    /// The keys of `[[block]]` are the name, the tower's seven keys of a
    /// body's dimensions, mass and section in a block's words, and the
    /// moment of inertia about the centre of mass (listed here by hand).
    /// Each of the seven has the tower's kind, unit, choices and bounds, and
    /// no word of the tower's; every exchanged word is met; a sample of the
    /// texts is written out by hand.
    #[test]
    fn a_blocks_keys_are_described_by_the_towers() {
        let names = section_keys(crate::block::BLOCK);
        assert_eq!(
            names,
            [
                "name",
                "width",
                "height",
                "mass",
                "density",
                "depth",
                "section",
                "wall_thickness",
                "inertia_centre"
            ]
        );
        let doc = |key: &str| describe_key(key).map(|k| *k.doc).unwrap_or_else(|| panic!("{key} is not described"));
        let texts = |d: &KeyDoc| [d.default, d.range, d.meaning, d.symbol, d.label];
        for name in &names[1..8] {
            let (tower, block) = (doc(&format!("tower.{name}")), doc(&format!("block.{name}")));
            assert_eq!((block.kind, block.unit, block.choices), (tower.kind, tower.unit, tower.choices), "{name}");
            assert!(block.range.starts_with(tower.range), "{name}: {} against {}", block.range, tower.range);
            for text in [block.default, block.meaning, block.symbol, block.label] {
                assert!(
                    !text.contains("tower") && !text.contains("m2") && !text.contains("springing"),
                    "block.{name}: {text}"
                );
            }
        }
        for (word, _) in BLOCK_WORDS {
            let met = names[1..8]
                .iter()
                .any(|name| texts(&doc(&format!("tower.{name}"))).iter().any(|t| t.contains(word)));
            assert!(met, "no key of the tower says {word:?}");
        }
        let width = doc("block.width");
        assert_eq!(
            (width.default, width.range, width.meaning, width.label),
            (
                "required",
                "> 0; at most the width of the block below (the tower's for the first)",
                "Width B of the block in the plane of rocking.",
                "block width B"
            )
        );
        assert_eq!(doc("block.height").meaning, "Height H of the block above the top of the block below.");
        let mass = doc("block.mass");
        assert_eq!(
            (mass.default, mass.meaning, mass.symbol),
            ("required (or density)", "Mass m of the block.", "m")
        );
        assert_eq!(doc("block.depth").placeholder, "= width");
        assert_eq!(
            for_block("Mass m2 of the tower on the springing level."),
            "Mass m of the block on the top of the block below."
        );
    }

    /// Every scenario key has its symbol and its words, no two keys the
    /// same words; a hand-checked sample against the reference's units.
    #[test]
    fn every_key_has_a_symbol_and_a_label() {
        for doc in SCENARIO_KEYS.iter() {
            assert!(!doc.symbol.is_empty() && !doc.label.is_empty(), "{}", doc.key);
            assert_eq!(SCENARIO_KEYS.iter().filter(|k| k.label == doc.label).count(), 1, "{}", doc.label);
        }
        let shown = |key: &str| describe_key(key).map(|k| (k.symbol(), k.label(), k.doc.unit));
        assert_eq!(shown("tower.width"), Some(("B".into(), "tower width B".into(), "m")));
        assert_eq!(shown("building.mu_static"), Some(("μs".into(), "static friction μs".into(), "")));
        assert_eq!(
            shown("ground.vertical.frequency"),
            Some(("f (vertical)".into(), "vertical ground frequency".into(), "Hz"))
        );
        assert_eq!(shown("simulation.g"), Some(("g".into(), "gravity g".into(), "m/s²")));
        assert_eq!(shown("tower.points.x"), None);
    }

    /// The sweepable keys, counted by hand from the table: `name`, 12 of
    /// `[tower]` (all but `points`), 4 of `[building]`, 14 of `[ground]` and
    /// the same 14 of `[ground.vertical]`, 3 of `[initial]`, 5 of
    /// `[simulation]`; a sample of each kind is typed as its description
    /// says. (Their order is that of the committed reference page, which
    /// lists them: see the CLI's keys_reference test.)
    #[test]
    fn sweepable_keys_are_the_scalar_keys_of_the_table() {
        use crate::sweep::axis::{check_key, KeyType};
        assert_eq!(SWEEPABLE_KEYS.len(), 1 + 12 + 4 + 14 + 14 + 3 + 5);
        let vertical: Vec<&str> = SWEEPABLE_KEYS.iter().filter_map(|k| k.strip_prefix(VERTICAL_PREFIX)).collect();
        assert_eq!(vertical, section_keys("ground").into_iter().filter(|k| *k != "vertical").collect::<Vec<_>>());
        for (key, expected) in [
            ("name", KeyType::Text),
            ("tower.section", KeyType::Text),
            ("ground.vertical.units", KeyType::Text),
            ("tower.width", KeyType::Number),
            ("ground.vertical.t0", KeyType::Number),
            ("simulation.atol", KeyType::Number),
        ] {
            assert_eq!(check_key(key).ok(), Some(expected), "{key}");
        }
        for refused in ["tower.points", "ground.vertical", "ground.vertical.vertical", "ground.vertical.points", "tower"] {
            assert!(check_key(refused).is_err() && !SWEEPABLE_KEYS.contains(&refused), "{refused}");
        }
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
        for doc in SCENARIO_KEYS.iter() {
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
            let text = if doc.section() == Some(crate::block::BLOCK) {
                // A block of its own under the tower, its other keys as needed.
                let mut block = String::from("[[block]]\n");
                for (key, value) in [("width", "2.0"), ("height", "5.0"), ("mass", "3.0e4")] {
                    let alternative = key == "mass" && doc.name() == "density";
                    if doc.name() != key && !alternative {
                        block.push_str(&format!("{key} = {value}\n"));
                    }
                }
                if doc.name() == "wall_thickness" {
                    block.push_str("section = \"hollow\"\n");
                }
                if doc.name() == "section" {
                    block.push_str("wall_thickness = 0.3\n");
                }
                format!("{geometry}{block}{line}{building}{ground}")
            } else {
                let text = format!("{tower}{building}{ground}");
                match doc.section() {
                    _ if text.contains(&line) => text,
                    None => format!("{line}{text}"),
                    Some(s) if text.contains(&format!("[{s}]\n")) => text.replacen(&format!("[{s}]\n"), &format!("[{s}]\n{line}"), 1),
                    Some(s) => format!("{text}[{s}]\n{line}"),
                }
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
