//! Assessment files: a scenario without `[ground]` (the tower, optionally the
//! building, `[simulation]`), plus `[site]` (the code, the soil and the site
//! parameters of each limit state) and `[assessment]` (the confidence factor,
//! the behaviour factor, the capacity curve, the record set of the dynamic
//! checks and its fitting range).
//!
//! This module reads `[site]` and `[assessment]`; the scenario's own sections
//! are kept as a table ([`AssessmentFile::scenario`]) for the tower's capacity.

mod columns;
mod keys;
mod site;
pub(crate) use site::parse as parse_site;

pub use columns::{code_spectra_columns, record_names, record_spectra_in_g, same_record_twice, SpectrumColumn, SpectrumKind};
pub use keys::ASSESSMENT_KEY_DOCS;
pub use site::{Code, GridCache, Site, SiteSource, DEFAULT_NOMINAL_LIFE, DEFAULT_USE_COEFFICIENT, EC8_STATE_KEYS, NTC_STATE_KEYS, OFFICIAL_GRID, SITE_KEYS};

use crate::error::{ErrorKind, Fault};
use crate::read::{as_number, non_negative, positive, with_article, Section};
use crate::support::{Support, SupportMode};
use crate::{Error, DEFAULT_G};
use rocking::{CsvOptions, Record, RecordFormat};
use rocking_codes::LimitState;
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The keys of `[assessment]`.
pub const ASSESSMENT_KEYS: &[&str] = &[
    "confidence_factor",
    "knowledge_level",
    "q",
    "capacity",
    "records",
    "units",
    "dt",
    "period_range",
    "free_after",
    "lambda",
    "verdict_method",
    "accept_incompatible_set",
    "support",
];
/// The sections of an assessment file besides a scenario's (less `[ground]`).
pub const ASSESSMENT_SECTIONS: &[&str] = &["site", "assessment", "support"];
/// The keys of each `[assessment.support.<LS>]`.
pub const SUPPORT_STATE_KEYS: &[&str] = &["period_factor", "damping"];

/// The support's values at one ultimate limit state (`[assessment.support.SLV]`,
/// §C8.7.1.2.1.4 of the Circolare 2019: at the ultimate limit states a masonry
/// building's equivalent period grows and its damping rises).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportState {
    /// Every `T_k` of the support multiplied by it (> 0; 1 when not given).
    pub period_factor: f64,
    /// Every `ζ_k` replaced by it (a fraction in [0, 1)), when given.
    pub damping: Option<f64>,
}

impl Default for SupportState {
    fn default() -> Self {
        Self {
            period_factor: 1.0,
            damping: None,
        }
    }
}

/// The confidence factor FC when not given (knowledge level LC1, Circolare §C8.5.4).
pub const DEFAULT_CONFIDENCE_FACTOR: f64 = 1.35;
/// The behaviour factor q of the linear kinematic check when not given (Circolare §C8.7.1.2.1.7).
pub const DEFAULT_Q: f64 = 2.0;
/// Seconds run after each record in the dynamic checks when not given.
pub const DEFAULT_ASSESSMENT_FREE_AFTER: f64 = 10.0;
/// The scan of the record set's multiplier λ when not given: from, to, step.
pub const DEFAULT_LAMBDA: (f64, f64, f64) = (0.05, 3.0, 0.05);

/// The capacity curve of the mechanism.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Capacity {
    /// `a*(d) = a0* (1 − d/d0)`, the Circolare's worked cases (the default).
    Linear,
    /// The rigid block's exact curve.
    Exact,
}

/// The method that carries the verdict of the life-safety and collapse
/// limit states, when the engineer names one (`assessment.verdict_method`);
/// without it, the most refined method computed carries it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum VerdictMethod {
    /// The linear kinematic check (life safety only).
    LinearKinematic,
    /// The non-linear kinematic check.
    NonlinearKinematic,
    /// The non-linear dynamic check (needs a record set).
    NonlinearDynamic,
}

/// One record of an assessment's set: a file (matched by a glob pattern of
/// `assessment.records`), or its content given as text with its name
/// (`records = [{ name = "elcentro.AT2", text = "…" }, …]`, as the page gives
/// the files a user picks). Either is read by the reader of `[ground]`'s records.
#[derive(Debug, Clone, PartialEq)]
pub struct SetEntry {
    /// The file, relative to the assessment file's folder; or the name given with the text.
    pub path: String,
    /// The record's content, when given as text; `None` for a file.
    pub text: Option<std::sync::Arc<str>>,
}

impl SetEntry {
    /// The file name (the outputs' column and row name).
    pub fn name(&self) -> &str {
        self.path.rsplit('/').next().unwrap_or(&self.path)
    }
}

/// The `[site]` and `[assessment]` of an assessment file, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct AssessmentFile {
    origin: PathBuf,
    /// The site and its limit states' spectra (5%).
    pub site: Site,
    /// FC, > 0.
    pub confidence_factor: f64,
    /// q, > 0.
    pub q: f64,
    /// The capacity curve.
    pub capacity: Capacity,
    /// The method named to carry the verdict; `None`: the most refined computed.
    pub verdict_method: Option<VerdictMethod>,
    /// Whether a dynamic check on a set outside NTC 2018 §3.2.3.6's band may still carry the verdict.
    pub accept_incompatible_set: bool,
    /// The records of the set, in order; empty without a set.
    pub records: Vec<SetEntry>,
    /// `units` and `dt` of the set's CSV records (as `[ground]` takes them for a CSV record).
    pub csv: CsvOptions,
    /// `units` and `dt` as written, for the `[ground]` of each CSV record of the set.
    csv_keys: Table,
    /// The fitting range (s), if given.
    pub period_range: Option<(f64, f64)>,
    /// Seconds run after each record (≥ 0).
    pub free_after: f64,
    /// The multiplier scan (from, to, step).
    pub lambda: (f64, f64, f64),
    /// Gravity (m/s²): `simulation.g`, or 9.81.
    pub g: f64,
    /// The elastic support under the tower (`[support]`), if given: the checks
    /// take the floor spectrum of its top (Circolare 2019 §C7.2.3).
    pub support: Option<Support>,
    /// The support's values of each ultimate limit state given
    /// (`[assessment.support.<LS>]`); the others keep the support's own.
    pub support_states: Vec<(LimitState, SupportState)>,
    /// The scenario's own sections (name, tower, building, simulation…), not validated here.
    pub scenario: Table,
}

impl AssessmentFile {
    /// Parses the TOML text of an assessment file; `origin` names the file in
    /// errors and is the folder of the grid and the records.
    pub fn from_toml_str(text: &str, origin: &Path) -> Result<Self, Error> {
        Self::from_table(crate::parse_toml(text, origin)?, origin)
    }

    /// Validates an assessment file given as a TOML table (from a dict in Python);
    /// `origin` names it in errors and its folder resolves relative paths.
    pub fn from_table(table: Table, origin: &Path) -> Result<Self, Error> {
        Self::from_table_on(table, origin, &GridCache::default())
    }

    /// As [`AssessmentFile::from_table`], the hazard grid taken from `grids`
    /// when it was read before (the towers of an inventory read it once).
    pub fn from_table_on(table: Table, origin: &Path, grids: &GridCache) -> Result<Self, Error> {
        Self::parse(table, origin, grids).map_err(|f| f.in_file(origin))
    }

    fn parse(mut table: Table, origin: &Path, grids: &GridCache) -> Result<Self, Fault> {
        let folder = origin.parent().unwrap_or(Path::new("")).to_path_buf();
        if table.contains_key("ground") {
            return Err(Fault::new(
                "ground",
                ErrorKind::NotApplicable("an assessment file has no [ground]: the records of its dynamic checks are assessment.records".into()),
            ));
        }
        let mut valid: Vec<&'static str> = crate::SECTIONS.iter().copied().filter(|s| *s != "ground").collect();
        valid.extend(crate::TOP_LEVEL_KEYS.iter().copied());
        valid.extend(ASSESSMENT_SECTIONS);
        if let Some(k) = table.keys().find(|k| !valid.contains(&k.as_str())) {
            return Err(Fault::new(k.clone(), ErrorKind::unknown_section(k, &valid)));
        }
        let site = match table.remove("site") {
            Some(v) => site::parse(&v, &folder, grids)?,
            None => {
                return Err(Fault::new(
                    "site",
                    ErrorKind::Missing("required: the [site] table (code, soil, the limit states' parameters)".into()),
                ))
            }
        };
        let empty = Value::Table(Table::new());
        let assessment_value = table.remove("assessment");
        let a = Section::new("assessment", assessment_value.as_ref().unwrap_or(&empty))?;
        a.only(ASSESSMENT_KEYS)?;
        // The knowledge level sets FC (Circolare 2019 §C8.5.4, Table C8.5.IV) unless FC is given.
        let level_factor = a.choice("knowledge_level", &[("LC1", 1.35), ("LC2", 1.2), ("LC3", 1.0)])?;
        let confidence_factor = positive(
            "assessment.confidence_factor",
            a.number("confidence_factor")?.or(level_factor).unwrap_or(DEFAULT_CONFIDENCE_FACTOR),
        )?;
        let q = positive("assessment.q", a.number("q")?.unwrap_or(DEFAULT_Q))?;
        let capacity = a
            .choice("capacity", &[("linear", Capacity::Linear), ("exact", Capacity::Exact)])?
            .unwrap_or(Capacity::Linear);
        let verdict_method = a.choice(
            "verdict_method",
            &[
                ("linear_kinematic", VerdictMethod::LinearKinematic),
                ("nonlinear_kinematic", VerdictMethod::NonlinearKinematic),
                ("nonlinear_dynamic", VerdictMethod::NonlinearDynamic),
            ],
        )?;
        let accept_incompatible_set = a.boolean("accept_incompatible_set")?.unwrap_or(false);
        let records = match a.get("records") {
            Some(Value::Array(items)) if items.iter().any(Value::is_table) => given_records(items)?,
            Some(v) => crate::study::glob_records("assessment", Some(v), &folder)?
                .into_iter()
                .map(|path| SetEntry { path, text: None })
                .collect(),
            None => Vec::new(),
        };
        let units = a.choice("units", &crate::ground::ACCELERATION_UNITS)?;
        let dt = a.number("dt")?.map(|dt| positive("assessment.dt", dt)).transpose()?;
        let csv = CsvOptions {
            units: units.unwrap_or_default(),
            dt,
        };
        let csv_keys: Table = ["units", "dt"]
            .into_iter()
            .filter_map(|k| a.get(k).map(|v| (k.to_string(), v.clone())))
            .collect();
        let period_range = match a.get("period_range") {
            None => None,
            Some(v) => Some(pair("assessment.period_range", v)?),
        };
        if let Some((from, to)) = period_range {
            if !(from > 0.0 && to > from) {
                return Err(Fault::invalid("assessment.period_range", format!("need 0 < from < to (s), got [{from}, {to}]")));
            }
        }
        let free_after = non_negative("assessment.free_after", a.number("free_after")?.unwrap_or(DEFAULT_ASSESSMENT_FREE_AFTER))?;
        let lambda = match a.get("lambda") {
            None => DEFAULT_LAMBDA,
            Some(v) => lambda(v)?,
        };
        let support = table.remove("support").map(|v| crate::support::parse(&v)).transpose()?;
        if support.is_some() && table.get("tower").and_then(|t| t.get("restitution")).is_some() {
            return Err(Fault::new(
                "tower.restitution",
                ErrorKind::NotApplicable("does not apply to a tower on a [support]: its impacts follow the law of generalised momentum (remove it)".into()),
            ));
        }
        let support_states = match a.get("support") {
            None => Vec::new(),
            Some(_) if support.is_none() => {
                return Err(Fault::new(
                    "assessment.support",
                    ErrorKind::NotApplicable("needs a [support]: the values of a limit state are those of the support under the tower".into()),
                ));
            }
            Some(v) => support_states(v, site.code)?,
        };
        if let Some(support) = &support {
            check_support_damping(support)?;
        }
        let g = match table.get("simulation").and_then(|s| s.get("g")) {
            Some(v) => positive(
                "simulation.g",
                as_number(v).ok_or_else(|| {
                    Fault::new(
                        "simulation.g",
                        ErrorKind::WrongType {
                            expected: "a number",
                            got: with_article(v),
                        },
                    )
                })?,
            )?,
            None => DEFAULT_G,
        };
        Ok(Self {
            origin: origin.to_path_buf(),
            site,
            confidence_factor,
            q,
            capacity,
            verdict_method,
            accept_incompatible_set,
            records,
            csv,
            csv_keys,
            period_range,
            free_after,
            lambda,
            g,
            support,
            support_states,
            scenario: table,
        })
    }

    /// The support's modes at the limit state `state`: its own, every period
    /// times the state's `period_factor` and every damping its `damping`
    /// when `[assessment.support.<state>]` gives them; `None` without a support.
    pub fn support_modes(&self, state: LimitState) -> Option<Vec<SupportMode>> {
        let support = self.support.as_ref()?;
        let values = self.support_state(state);
        Some(
            support
                .modes
                .iter()
                .map(|m| SupportMode {
                    period: m.period * values.period_factor,
                    damping: values.damping.unwrap_or(m.damping),
                    ..*m
                })
                .collect(),
        )
    }

    /// The support's values at `state` (the support's own when not given).
    pub fn support_state(&self, state: LimitState) -> SupportState {
        self.support_states.iter().find(|(s, _)| *s == state).map(|(_, v)| *v).unwrap_or_default()
    }

    /// The file.
    pub fn origin(&self) -> &Path {
        &self.origin
    }

    /// The folder the file's relative paths start from.
    pub fn folder(&self) -> &Path {
        self.origin.parent().unwrap_or(Path::new(""))
    }

    /// Reads the record set (m/s²), each record as `[ground]` would read it,
    /// format guessed, a CSV record with the set's `units` and `dt`.
    pub fn read_records(&self) -> Result<Vec<(String, Record)>, Error> {
        self.records
            .iter()
            .map(|entry| {
                let file = self.folder().join(&entry.path);
                let text = match &entry.text {
                    Some(text) => Ok(std::borrow::Cow::Borrowed(&**text)),
                    None => read_record_text(&file).map(std::borrow::Cow::Owned),
                };
                text.and_then(|text| parse_record_guessed(&text, &file, &self.csv, self.g))
                    .map(|r| (entry.path.clone(), r))
                    .map_err(|kind| Fault::new("assessment.records", kind).in_file(&self.origin))
            })
            .collect()
    }
}

impl AssessmentFile {
    /// The `[ground]` table of the record `path` of the set (relative to the
    /// file's folder): `type = "record"`, its `file`, and, when it reads as a
    /// CSV record (format guessed), the set's `units` and `dt` (an AT2 or ESM
    /// file carries its own). An error names `assessment.records` and the file.
    pub fn record_ground(&self, entry: &SetEntry) -> Result<Table, Error> {
        let mut ground = Table::new();
        ground.insert("type".into(), Value::String("record".into()));
        match &entry.text {
            Some(text) => ground.insert("text".into(), Value::String(text.to_string())),
            None => ground.insert("file".into(), Value::String(entry.path.clone())),
        };
        if !self.csv_keys.is_empty() {
            let file = self.folder().join(&entry.path);
            let text = match &entry.text {
                Some(text) => text.to_string(),
                None => read_record_text(&file).map_err(|kind| Fault::new("assessment.records", kind).in_file(&self.origin))?,
            };
            let format = Record::guess_format(&text)
                .map_err(|source| Fault::new("assessment.records", ErrorKind::Record { path: file, source }).in_file(&self.origin))?;
            if format == RecordFormat::Csv {
                ground.extend(self.csv_keys.clone());
            }
        }
        Ok(ground)
    }
}

/// The limit states whose spectra the dynamic checks fit the record set to: SLV,
/// SLC (NTC) or SD, NC (EC8).
pub fn dynamic_limit_states(code: Code) -> [LimitState; 2] {
    match code {
        Code::Ntc2018 => [LimitState::Slv, LimitState::Slc],
        Code::Ec8 => [LimitState::Sd, LimitState::Nc],
    }
}

/// The damping (% of critical) of the life-safety displacement spectrum in the
/// non-linear kinematic check (Circolare §C8.7.1.2.1.8).
pub const KINEMATIC_DAMPING_LIFE_SAFETY_PCT: f64 = 8.0;
/// The damping (% of critical) of the collapse displacement spectrum in the
/// non-linear kinematic check (Circolare §C8.7.1.2.1.8).
pub const KINEMATIC_DAMPING_COLLAPSE_PCT: f64 = 10.0;

/// The damping (%) of the non-linear kinematic check of a limit state
/// (Circolare §C8.7.1.2.1.8): 8% at SLV (SD), 10% at SLC (NC); `None` for the others.
pub fn kinematic_damping_pct(state: LimitState) -> Option<f64> {
    match state {
        LimitState::Slv | LimitState::Sd => Some(KINEMATIC_DAMPING_LIFE_SAFETY_PCT),
        LimitState::Slc | LimitState::Nc => Some(KINEMATIC_DAMPING_COLLAPSE_PCT),
        _ => None,
    }
}

/// Reads a record file as `[ground]` does with `format` guessed and no CSV
/// options (values in g, `g` in m/s²), or what is wrong with it.
pub fn read_record(path: &Path, g: f64) -> Result<Record, ErrorKind> {
    read_record_with(path, &CsvOptions::default(), g)
}

/// Reads a record file as [`read_record`] does, a CSV record with the
/// options `csv` (its `units`, and `dt` for one column); an AT2 or ESM file
/// carries its own.
pub fn read_record_with(path: &Path, csv: &CsvOptions, g: f64) -> Result<Record, ErrorKind> {
    parse_record_guessed(&read_record_text(path)?, path, csv, g)
}

/// The text of a record file, or what is wrong with it.
fn read_record_text(path: &Path) -> Result<String, ErrorKind> {
    crate::file::read_text(path, crate::ground::MAX_RECORD_BYTES).map_err(|e| ErrorKind::Read {
        path: path.to_path_buf(),
        reason: crate::error::io_reason(&e),
        os_error: e.raw_os_error(),
    })
}

/// Parses a record's text (of the file `path`, named in errors) as `[ground]`
/// does with `format` guessed and, for a CSV record, the options `csv`.
fn parse_record_guessed(text: &str, path: &Path, csv: &CsvOptions, g: f64) -> Result<Record, ErrorKind> {
    let record = |source| ErrorKind::Record {
        path: path.to_path_buf(),
        source,
    };
    let format = Record::guess_format(text).map_err(record)?;
    let parsed = Record::parse(text, Some(format), csv, g).map_err(record)?;
    // A record no ground motion could be is refused as `[ground]` refuses it.
    match crate::ground::peak_beyond_bound(&parsed, g) {
        Some(peak_g) => Err(ErrorKind::Invalid(crate::ground::too_strong(&format!("{} peaks at", path.display()), peak_g))),
        None => Ok(parsed),
    }
}

/// The records of `assessment.records` given as tables `{ name, text }`:
/// each name non-empty and unique.
fn given_records(items: &[Value]) -> Result<Vec<SetEntry>, Fault> {
    let mut entries: Vec<SetEntry> = Vec::with_capacity(items.len());
    for (i, item) in items.iter().enumerate() {
        let key = format!("assessment.records[{i}]");
        let Value::Table(t) = item else {
            return Err(Fault::new(
                &key,
                ErrorKind::WrongType {
                    expected: "a table { name, text } like the others (patterns and given records do not mix)",
                    got: with_article(item),
                },
            ));
        };
        if let Some(k) = t.keys().find(|k| !["name", "text"].contains(&k.as_str())) {
            return Err(Fault::new(format!("{key}.{k}"), ErrorKind::unknown_key(k, &["name", "text"])));
        }
        let string = |k: &str| match t.get(k) {
            None => Err(Fault::new(
                format!("{key}.{k}"),
                ErrorKind::Missing(format!("required: the record's {}", if k == "name" { "file name" } else { "content" })),
            )),
            Some(Value::String(s)) => Ok(s.as_str()),
            Some(other) => Err(Fault::new(
                format!("{key}.{k}"),
                ErrorKind::WrongType {
                    expected: "a string",
                    got: with_article(other),
                },
            )),
        };
        let name = string("name")?;
        if name.is_empty() {
            return Err(Fault::invalid(format!("{key}.name"), "must not be empty"));
        }
        let text = string("text")?;
        if entries.iter().any(|e| e.path == name) {
            return Err(Fault::invalid(format!("{key}.name"), format!("\"{name}\" is given twice")));
        }
        entries.push(SetEntry {
            path: name.to_string(),
            text: Some(text.into()),
        });
    }
    Ok(entries)
}

/// `[assessment.support]`: one table per ultimate limit state of the code
/// (SLV, SLC; EC8's SD, NC), each with `period_factor` and `damping`.
fn support_states(value: &Value, code: Code) -> Result<Vec<(LimitState, SupportState)>, Fault> {
    let t = Section::new("assessment.support", value)?;
    let states = dynamic_limit_states(code);
    let names: Vec<&'static str> = states.iter().map(|s| s.as_str()).collect();
    if let Some(k) = t.keys().find(|k| !names.contains(k)) {
        let why = if code.limit_states().iter().any(|s| s.as_str() == k) {
            format!(
                "the support's values may change at the ultimate limit states ({}) only: {k} keeps the support's own",
                names.join(", ")
            )
        } else {
            ErrorKind::unknown_key(k, &names).to_string()
        };
        return Err(Fault::invalid(format!("assessment.support.{k}"), why));
    }
    states
        .iter()
        .filter_map(|state| t.get(state.as_str()).map(|v| (*state, v)))
        .map(|(state, v)| {
            let prefix = format!("assessment.support.{state}");
            let Value::Table(s) = v else {
                return Err(Fault::new(
                    prefix,
                    ErrorKind::WrongType {
                        expected: "a table { period_factor, damping }",
                        got: with_article(v),
                    },
                ));
            };
            if let Some(k) = s.keys().find(|k| !SUPPORT_STATE_KEYS.contains(&k.as_str())) {
                return Err(Fault::new(format!("{prefix}.{k}"), ErrorKind::unknown_key(k, SUPPORT_STATE_KEYS)));
            }
            let number = |k: &str| -> Result<Option<f64>, Fault> {
                s.get(k)
                    .map(|v| {
                        as_number(v).ok_or_else(|| {
                            Fault::new(
                                format!("{prefix}.{k}"),
                                ErrorKind::WrongType {
                                    expected: "a number",
                                    got: with_article(v),
                                },
                            )
                        })
                    })
                    .transpose()
            };
            let period_factor = positive(&format!("{prefix}.period_factor"), number("period_factor")?.unwrap_or(1.0))?;
            let damping = number("damping")?;
            if let Some(d) = damping {
                if !(d.is_finite() && d > 0.0 && d < 1.0) {
                    return Err(Fault::invalid(
                        format!("{prefix}.damping"),
                        format!("must be a fraction of critical in (0, 1) (0.10 for 10%), got {d}"),
                    ));
                }
            }
            Ok((state, SupportState { period_factor, damping }))
        })
        .collect()
}

/// The floor spectrum of the Circolare 2019 ([C7.2.6]) divides by the square
/// root of each mode's damping: a support whose mode is undamped at a limit
/// state cannot be checked (the engine's coupled model can run it).
fn check_support_damping(support: &Support) -> Result<(), Fault> {
    for (k, mode) in support.modes.iter().enumerate() {
        if mode.damping > 0.0 {
            continue;
        }
        // The damage state always takes the support's own damping: a mode
        // undamped there is refused whatever the ultimate states give.
        let key = if support.shape.is_some() {
            "support.damping".to_string()
        } else {
            format!("support.mode.{}.damping", k + 1)
        };
        return Err(Fault::invalid(
            key,
            "must be > 0 in an assessment: the floor spectrum of the Circolare 2019 ([C7.2.6]) amplifies by 1.1 ξ^(-1/2), infinite at 0",
        ));
    }
    Ok(())
}

/// A `[from, to]` pair of finite numbers.
fn pair(key: &str, value: &Value) -> Result<(f64, f64), Fault> {
    let wrong = || {
        Fault::new(
            key,
            ErrorKind::WrongType {
                expected: "a pair [from, to] of numbers",
                got: with_article(value),
            },
        )
    };
    let Value::Array(items) = value else { return Err(wrong()) };
    match items.iter().map(as_number).collect::<Option<Vec<f64>>>().as_deref() {
        Some(&[a, b]) if a.is_finite() && b.is_finite() => Ok((a, b)),
        _ => Err(wrong()),
    }
}

/// `{ from, to, step }` of the multiplier scan: 0 < from < to, step > 0.
fn lambda(value: &Value) -> Result<(f64, f64, f64), Fault> {
    let t = Section::new("assessment.lambda", value)?;
    t.only(&["from", "to", "step"])?;
    let (d_from, d_to, d_step) = DEFAULT_LAMBDA;
    let from = positive("assessment.lambda.from", t.number("from")?.unwrap_or(d_from))?;
    let to = positive("assessment.lambda.to", t.number("to")?.unwrap_or(d_to))?;
    let step = positive("assessment.lambda.step", t.number("step")?.unwrap_or(d_step))?;
    if to <= from {
        return Err(Fault::invalid("assessment.lambda.to", format!("must be > from ({from}), got {to}")));
    }
    Ok((from, to, step))
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use rocking_codes::CodeSpectrum;

    fn parse(text: &str) -> Result<AssessmentFile, Error> {
        // The repository's data/ folder: the grid's path is relative to the file.
        let origin = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/site.toml");
        AssessmentFile::from_toml_str(text, &origin)
    }

    fn message(text: &str) -> String {
        match parse(text) {
            Ok(_) => panic!("expected an error for {text}"),
            Err(e) => e.fault.to_string(),
        }
    }

    #[test]
    fn limit_states_from_tables() {
        let a = parse("[site]\nsoil = \"B\"\n[site.SLV]\nag = 0.155\nF0 = 2.47\nTc_star = 0.36\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(a.site.code, Code::Ntc2018);
        assert_eq!(a.site.spectra.len(), 1);
        let Some(CodeSpectrum::Ntc(slv)) = a.site.spectrum(LimitState::Slv) else {
            panic!("no SLV")
        };
        // SS = 1.40 − 0.40·2.47·0.155 = 1.24686, clamped to 1.20.
        assert_relative_eq!(slv.ss(), 1.2, max_relative = 1e-15);
        assert_relative_eq!(a.confidence_factor, 1.35, max_relative = 1e-15);
        assert!(a.records.is_empty());
    }

    #[test]
    fn the_official_grid_and_the_islands() {
        // Cervino, VN 50, CU 1.5: SLV at TR 711.8 years, ag 0.17612957238062965 g by
        // Allegato A by hand (rocking-codes' tests/official_grid.rs has the
        // computation); 1e-12 for the round-off of the weights and the log-log.
        let a = parse("[site]\nsoil = \"B\"\ngrid = \"ntc2018\"\nlon = 14.42\nlat = 41.04\nVN = 50\nCU = 1.5\n").unwrap_or_else(|e| panic!("{e}"));
        let slv = a.site.spectrum(LimitState::Slv).map(CodeSpectrum::ag).unwrap_or_default();
        assert_relative_eq!(slv, 0.17612957238062965, max_relative = 1e-12);
        assert_eq!(a.site.source.grid_file(), None);
        assert_eq!(a.site.source.reference_life(), Some((50.0, 1.5)));
        // Sardinia (G1), VN 50, CU 1: SLV at TR 474.56 years, between 201
        // (0.393 g/10) and 475 (0.500): 0.0393·(0.5/0.393)^(ln(474.56/201)/ln(475/201)) = 0.049987 g.
        let a = parse("[site]\nsoil = \"B\"\nisland = \"G1\"\n").unwrap_or_else(|e| panic!("{e}"));
        let slv = a.site.spectrum(LimitState::Slv).map(CodeSpectrum::ag).unwrap_or_default();
        let tr = -50.0 / (0.9f64).ln();
        let hand = 0.0393 * (0.5f64 / 0.393).powf((tr / 201.0).ln() / (475.0f64 / 201.0).ln());
        assert_relative_eq!(slv, hand, max_relative = 1e-12);
        assert_relative_eq!(hand, 0.049987, max_relative = 1e-5);
        assert!(message("[site]\nsoil = \"B\"\nisland = \"G1\"\nlon = 9.1\n").starts_with("site.lon: does not apply with island"));
        assert!(message("[site]\nsoil = \"B\"\nisland = \"G7\"\n").starts_with("site.island: \"G7\" is not a group of Tabella 2"));
        assert!(message("[site]\nsoil = \"B\"\ngrid = \"ntc2018\"\nlon = 9.11\nlat = 39.22\n")
            .starts_with("site.lon: the site (lon 9.11, lat 39.22) is outside the hazard grid"));
    }

    #[test]
    fn limit_states_from_the_synthetic_grid() {
        let a = parse("[site]\nsoil = \"C\"\ngrid = \"hazard/synthetic_grid.txt\"\nlon = 14.30\nlat = 40.95\nVN = 50\nCU = 1.0\n")
            .unwrap_or_else(|e| panic!("{e}"));
        let states: Vec<LimitState> = a.site.spectra.iter().map(|(s, _)| *s).collect();
        assert_eq!(states, [LimitState::Sld, LimitState::Slv, LimitState::Slc]);
        // On node 40001, SLC with VN CU = 50: TR = 974.79 years, just under 975:
        // ag = 0.2164 g there (the 975 column) to within the log-log step 1e-4.
        let slc = a.site.spectrum(LimitState::Slc).map(CodeSpectrum::ag).unwrap_or_default();
        assert_relative_eq!(slc, 0.2164, max_relative = 1e-4);
    }

    #[test]
    fn refusals_name_the_key() {
        assert!(message("[site]\nsoil = \"F\"\n[site.SLV]\nag = 0.1\nF0 = 2.5\nTc_star = 0.3\n").starts_with("site.soil: unknown category"));
        assert!(message("[site]\nsoil = \"B\"\n").starts_with("site: give the site parameters"));
        assert!(message("[site]\nsoil = \"B\"\n[site.SLV]\nag = 0.1\nF0 = 2.5\n").starts_with("site.SLV.Tc_star: required"));
        assert!(message("[site]\nsoil = \"B\"\n[site.SLV]\nag = -0.1\nF0 = 2.5\nTc_star = 0.3\n").starts_with("site.SLV.ag: must be"));
        assert!(message("[site]\nsoil = \"B\"\ngrid = \"hazard/synthetic_grid.txt\"\nlon = 9.0\nlat = 45.0\n")
            .starts_with("site.lon: the site (lon 9, lat 45) is outside the hazard grid"));
        assert!(message("[site]\nsoil = \"B\"\ncode = \"ec8\"\ntopography = \"T2\"\n[site.SD]\nag = 0.2\n").starts_with("site.topography: does not apply"));
        assert!(
            message("[site]\nsoil = \"B\"\n[site.SLV]\nag = 0.1\nF0 = 2.5\nTc_star = 0.3\n[assessment]\nrecord = []\n")
                .starts_with("assessment.record: unknown key (did you mean `records`?)")
        );
        assert!(
            message("[site]\nsoil = \"B\"\n[site.SLV]\nag = 0.1\nF0 = 2.5\nTc_star = 0.3\n[ground]\ntype = \"none\"\n")
                .starts_with("ground: an assessment file has no [ground]")
        );
    }
}
