//! A scenario: parsed and validated from a TOML table, then built into the
//! library's model, ground motion, initial state and settings.

use crate::block::BlockNames;
use crate::error::{Error, ErrorKind, Fault};
use crate::ground::{self, GroundInfo, GroundSpec, RecordCache};
use crate::read::{with_article, Section};
use crate::{building, simulation, tower};
use rocking::{GroundMotion, Initial, Model, Settings};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The sections of a scenario.
pub const SECTIONS: &[&str] = &["tower", "block", "building", "ground", "initial", "simulation"];
/// The keys of a scenario outside any section.
pub const TOP_LEVEL_KEYS: &[&str] = &["name"];

/// A validated scenario. Every value is checked when it is parsed; only a
/// ground-motion record is read later, by [`Scenario::build`].
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    origin: PathBuf,
    name: String,
    model: Model,
    points: Vec<(f64, f64)>,
    ground: GroundSpec,
    /// `[ground.vertical]`, if given.
    vertical: Option<GroundSpec>,
    initial: Initial,
    settings: Settings,
    output_dt: f64,
    blocks: BlockNames,
}

/// A scenario built into the library's objects, ready to run.
#[derive(Debug, Clone, PartialEq)]
pub struct Case {
    /// The scenario's `name` (default: the file stem).
    pub name: String,
    /// The scenario file (or origin).
    pub file: PathBuf,
    /// Tower, building and gravity.
    pub model: Model,
    /// The ground acceleration (m/s²).
    pub ground: GroundMotion,
    /// The ground motion as resolved from the scenario (for reports).
    pub ground_info: GroundInfo,
    /// The vertical ground acceleration (m/s², positive upwards), if given.
    pub vertical: Option<GroundMotion>,
    /// The vertical motion as resolved from the scenario (for reports).
    pub vertical_info: Option<GroundInfo>,
    /// Initial rotation and angular velocity.
    pub initial: Initial,
    /// Duration and tolerances.
    pub settings: Settings,
    /// Spacing of the history rows (s).
    pub output_dt: f64,
    /// Extra points `(x, y)` of the tower (m, tower coordinates) to report.
    pub points: Vec<(f64, f64)>,
    /// Input files read besides the scenario (a ground-motion record).
    pub inputs: Vec<PathBuf>,
    /// The names of the blocks on the tower (`[[block]]`), the lowest first.
    pub blocks: BlockNames,
}

/// Parses TOML text into a table, with a syntax error reported on one line
/// with its line and column.
pub fn parse_toml(text: &str, origin: &Path) -> Result<Table, Error> {
    text.parse::<Table>().map_err(|e| syntax_fault(text, &e).in_file(origin))
}

fn syntax_fault(text: &str, e: &toml::de::Error) -> Fault {
    let message = e.message().lines().map(str::trim).filter(|l| !l.is_empty()).collect::<Vec<_>>().join("; ");
    let kind = match e.span() {
        Some(span) => {
            let before = text.get(..span.start).unwrap_or(text);
            let line_start = before.rfind('\n').map_or(0, |i| i + 1);
            ErrorKind::Syntax {
                line: before.matches('\n').count() + 1,
                column: before[line_start..].chars().count() + 1,
                message,
            }
        }
        None => ErrorKind::Invalid(message),
    };
    Fault { key: None, kind }
}

impl Scenario {
    /// Parses and validates the TOML text of a scenario file. `origin` is the
    /// file: it names the file in errors and is the folder of relative record paths.
    pub fn from_toml_str(text: &str, origin: &Path) -> Result<Self, Error> {
        Self::from_table(parse_toml(text, origin)?, origin)
    }

    /// Validates a scenario given as a TOML table (a sweep sets dotted keys with
    /// [`crate::set_dotted`] first).
    pub fn from_table(table: Table, origin: &Path) -> Result<Self, Error> {
        Self::parse(&table, origin).map_err(|f| f.in_file(origin))
    }

    /// Validates a scenario given as a JSON object with the same structure as
    /// the TOML file (`null` stands for an absent key).
    pub fn from_json(value: serde_json::Value, origin: &Path) -> Result<Self, Error> {
        let table = crate::json::to_table(value).map_err(|f| f.in_file(origin))?;
        Self::from_table(table, origin)
    }

    fn parse(table: &Table, origin: &Path) -> Result<Self, Fault> {
        for (key, value) in table {
            if TOP_LEVEL_KEYS.contains(&key.as_str()) || SECTIONS.contains(&key.as_str()) {
                continue;
            }
            if key == "support" {
                return Err(Fault::new(
                    key,
                    ErrorKind::NotApplicable(
                        "is not simulated by a run yet: an assessment file takes it for the checks at height (the floor spectra of the Circolare 2019)".into(),
                    ),
                ));
            }
            let kind = if value.is_table() {
                ErrorKind::unknown_section(key, SECTIONS)
            } else {
                let mut valid = TOP_LEVEL_KEYS.to_vec();
                valid.extend(SECTIONS.iter().copied());
                ErrorKind::unknown_key(key, &valid)
            };
            return Err(Fault::new(key, kind));
        }
        let section = |name: &'static str| table.get(name).map(|v| Section::new(name, v)).transpose();
        let name = match table.get("name") {
            None => origin.file_stem().map_or_else(|| "scenario".to_string(), |s| s.to_string_lossy().into_owned()),
            Some(Value::String(s)) => s.clone(),
            Some(other) => {
                return Err(Fault::new(
                    "name",
                    ErrorKind::WrongType {
                        expected: "a string",
                        got: with_article(other),
                    },
                ))
            }
        };
        let (tower_section, building_section, ground_section) = (section("tower")?, section("building")?, section("ground")?);
        let Some(ground_section) = ground_section else {
            return Err(Fault::new(
                "ground",
                ErrorKind::Missing("missing section [ground]: give its type (\"harmonic\", \"record\", …; \"none\" for free motion from [initial])".into()),
            ));
        };
        let sim = simulation::parse(section("simulation")?.as_ref())?;
        let (tower, points) = match &tower_section {
            Some(s) => {
                let (t, p) = tower::parse(s, sim.g)?;
                (Some(t), p)
            }
            None => (None, Vec::new()),
        };
        let building = building_section.as_ref().map(building::parse).transpose()?;
        if tower.is_none() && building.is_none() {
            return Err(Fault::new(
                "tower",
                ErrorKind::Missing("a scenario needs a [tower], a [building], or both".into()),
            ));
        }
        let (blocks, block_names) = crate::block::parse(table, tower.as_ref())?;
        if !blocks.is_empty() {
            if tower_section.as_ref().is_some_and(|s| s.has("compressive_strength")) {
                return Err(Fault::new(
                    "tower.compressive_strength",
                    ErrorKind::NotApplicable("applies to a tower alone: with [[block]] above it the blocks rock on their bases' edges (remove it)".into()),
                ));
            }
            if tower_section.as_ref().is_some_and(|s| s.has("restitution")) {
                return Err(Fault::new(
                    "tower.restitution",
                    ErrorKind::NotApplicable(
                        "applies to a tower alone: with [[block]] above it, every impact follows the stack's law of generalised momentum (remove it)".into(),
                    ),
                ));
            }
            if ground_section.has(crate::ground::VERTICAL) {
                return Err(Fault::new(
                    "ground.vertical",
                    ErrorKind::NotApplicable("is not taken with [[block]]: a stack runs under a horizontal ground motion only".into()),
                ));
            }
        }
        let model = Model::new(tower, building, sim.g)?.with_blocks(&blocks)?;
        let folder = origin.parent().unwrap_or(Path::new(""));
        let cx = ground::Context {
            tower: tower.as_ref(),
            g: sim.g,
            duration: sim.settings.duration,
            folder,
        };
        let (ground, vertical) = ground::parse(&ground_section, &cx)?;
        let initial = simulation::parse_initial(section("initial")?.as_ref(), tower.as_ref())?;
        Ok(Self {
            origin: origin.to_path_buf(),
            name,
            model,
            points,
            ground,
            vertical,
            initial,
            settings: sim.settings,
            output_dt: sim.output_dt,
            blocks: block_names,
        })
    }

    /// The scenario's name (default: the file stem).
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The file (or origin) the scenario came from.
    pub fn origin(&self) -> &Path {
        &self.origin
    }
    /// Tower, building and gravity.
    pub fn model(&self) -> &Model {
        &self.model
    }
    /// The names of the blocks on the tower (`[[block]]`), the lowest first.
    pub fn blocks(&self) -> &BlockNames {
        &self.blocks
    }
    /// The record file the scenario reads, if any (resolved against its folder).
    pub fn record_file(&self) -> Option<&Path> {
        self.ground.record_file()
    }

    /// The record file of `[ground.vertical]`, if any (resolved against its folder).
    pub fn vertical_record_file(&self) -> Option<&Path> {
        self.vertical.as_ref().and_then(GroundSpec::record_file)
    }

    /// Whether the scenario has a vertical ground motion (`[ground.vertical]`).
    pub fn has_vertical(&self) -> bool {
        self.vertical.is_some()
    }

    /// Builds the case: reads the ground-motion record if there is one.
    pub fn build(&self) -> Result<Case, Error> {
        self.build_with(None)
    }

    /// As [`Scenario::build`], taking the record from `cache` if it was read
    /// before with the same file, format, CSV options and g (and keeping it there).
    pub fn build_cached(&self, cache: &RecordCache) -> Result<Case, Error> {
        self.build_with(Some(cache))
    }

    /// As [`Scenario::build`], taking the record from `cache` if it was read before.
    pub(crate) fn build_with(&self, cache: Option<&RecordCache>) -> Result<Case, Error> {
        let g = self.model.gravity();
        let (ground, ground_info) = self.ground.load(g, cache).map_err(|f| f.in_file(&self.origin))?;
        let (vertical, vertical_info) = match &self.vertical {
            Some(spec) => {
                let (motion, info) = spec.load(g, cache).map_err(|f| f.in_file(&self.origin))?;
                (Some(motion), Some(info))
            }
            None => (None, None),
        };
        Ok(Case {
            name: self.name.clone(),
            file: self.origin.clone(),
            model: self.model.clone(),
            ground,
            ground_info,
            vertical,
            vertical_info,
            initial: self.initial,
            settings: self.settings,
            output_dt: self.output_dt,
            blocks: self.blocks,
            points: self.points.clone(),
            inputs: self
                .record_file()
                .into_iter()
                .chain(self.vertical_record_file())
                .map(Path::to_path_buf)
                .collect(),
        })
    }
}
