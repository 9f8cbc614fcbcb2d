//! Fragility studies (README, "Fragility studies"): a scenario without
//! `[ground]` plus a `[study]` table naming a suite of records (glob
//! patterns), an intensity measure and its levels, and limit states. Every
//! (record, level) is one case: the record scaled so that its measure equals
//! the level, run on the sweep's engine (all cores, rows in order, flat
//! memory, cancellation, a failing case fills `error`).
//!
//! The outputs' columns are in one place here: [`Study::header`] for
//! `stripes.csv`, [`FRAGILITY_HEADER`] and [`FRACTIONS_HEADER`]; a
//! [`Tally`] counts the exceedances as the rows stream by.

mod fit;
mod limit;
mod measure;
mod risk;

pub use fit::{fit, fit_until, log_likelihood, probability, Fit, Stripe, INTERRUPTED, METHOD};
pub use limit::{LimitState, Tally, Threshold, FRACTIONS_HEADER, FRAGILITY_HEADER};
pub use measure::{pga, pgv, Measure};
pub use risk::{Risk, StudySite, FIFTY_YEARS, HAZARD_HEADER, RISK_HEADER};

use crate::error::{closest, ErrorKind, Fault};
use crate::ground::RecordCache;
use crate::read::{as_number, with_article};
use crate::sweep::{is_stopped, one_line, run_cases, summary_template, Cases, Until};
use crate::{summary_fields, Cell, Error, Finished, Row, RunError, RunOptions, Scenario, ERROR_COLUMN};
use rocking::{GroundMotion, Record, RecordFormat};
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use toml::{Table, Value};

/// The keys of `[study]`.
pub const STUDY_KEYS: &[&str] = &[
    "records",
    "format",
    "units",
    "dt",
    "measure",
    "levels",
    "free_after",
    "limit_state",
    "max_cases",
];
/// Seconds simulated after the end of each record when `free_after` is not given.
pub const DEFAULT_FREE_AFTER: f64 = 10.0;
/// The first columns of `stripes.csv`, before the summary's fields.
pub const CASE_COLUMNS: [&str; 3] = ["record", "level", "scale"];

/// One record of a study: its path and its measure unscaled.
#[derive(Debug, Clone)]
pub struct StudyRecord {
    /// The path as the glob gave it, relative to the study file (`/` separated).
    pub path: String,
    /// The record's intensity measure at scale 1 (units of the measure, > 0).
    pub measure: f64,
    /// The time of its last sample (s).
    pub duration: f64,
    /// The `[ground]` table of its cases, without `scale`.
    ground: Table,
}

/// A validated fragility study.
#[derive(Debug, Clone)]
pub struct Study {
    origin: PathBuf,
    name: String,
    base: Table,
    records: Vec<StudyRecord>,
    measure: Measure,
    levels: Vec<f64>,
    free_after: f64,
    limit_states: Vec<LimitState>,
    summary_keys: Vec<String>,
    cache: RecordCache,
    site: Option<StudySite>,
}

impl Study {
    /// Parses and validates the TOML text of a study file; reads every record
    /// once for its measure. `origin` names the file in errors and is the
    /// folder of the glob patterns.
    pub fn from_toml_str(text: &str, origin: &Path) -> Result<Self, Error> {
        Self::from_table(crate::parse_toml(text, origin)?, origin)
    }

    /// A study from a JSON object with the structure of the TOML file (as a Python dict gives it).
    pub fn from_json(value: serde_json::Value, origin: &Path) -> Result<Self, Error> {
        let table = crate::json::to_table(value).map_err(|f| f.in_file(origin))?;
        Self::from_table(table, origin)
    }

    /// A study from a table holding a scenario (without `[ground]` and
    /// `simulation.duration`) and its `[study]` table.
    pub fn from_table(mut table: Table, origin: &Path) -> Result<Self, Error> {
        let fail = |f: Fault| f.in_file(origin);
        let study = match table.remove("study") {
            Some(Value::Table(t)) => t,
            Some(other) => {
                return Err(fail(Fault::new(
                    "study",
                    ErrorKind::WrongType {
                        expected: "a table (a [study] section)",
                        got: with_article(&other),
                    },
                )))
            }
            None => {
                return Err(fail(Fault::new(
                    "study",
                    ErrorKind::Missing("missing section [study]: give records, measure, levels and limit states".into()),
                )))
            }
        };
        if table.contains_key("ground") {
            return Err(fail(Fault::new(
                "ground",
                ErrorKind::NotApplicable("a study takes its ground motions from study.records: remove [ground]".into()),
            )));
        }
        let site_table = table.remove("site");
        let simulation = match table.get("simulation") {
            Some(Value::Table(t)) => Some(t),
            _ => None,
        };
        if simulation.is_some_and(|s| s.contains_key("duration")) {
            return Err(fail(Fault::new(
                "simulation.duration",
                ErrorKind::NotApplicable("a study's case lasts its record plus study.free_after: remove simulation.duration".into()),
            )));
        }
        if let Some(k) = study.keys().find(|k| !STUDY_KEYS.contains(&k.as_str())) {
            return Err(fail(Fault::new(format!("study.{k}"), ErrorKind::unknown_key(k, STUDY_KEYS))));
        }
        // The fields of the study's runs: with blocks on the tower, the stack's and each block's.
        let layout = crate::columns::Layout {
            blocks: crate::block::names(&table).map_err(fail)?,
            ..Default::default()
        };
        let template = summary_template(&layout);
        let measure = parse_measure(&study).map_err(fail)?;
        let levels = parse_levels(&study).map_err(fail)?;
        let free_after = match study.get("free_after") {
            None => DEFAULT_FREE_AFTER,
            Some(v) => match as_number(v) {
                Some(x) if x.is_finite() && x >= 0.0 => x,
                Some(x) => return Err(fail(Fault::invalid("study.free_after", format!("must be a finite number >= 0 (s), got {x}")))),
                None => {
                    return Err(fail(Fault::new(
                        "study.free_after",
                        ErrorKind::WrongType {
                            expected: "a number (s)",
                            got: with_article(v),
                        },
                    )))
                }
            },
        };
        let limit_states = limit::parse(study.get("limit_state"), &template).map_err(fail)?;
        let ground_keys = ground_keys(&study).map_err(fail)?;
        let folder = origin.parent().unwrap_or(Path::new("")).to_path_buf();
        let site = site_table.map(|v| risk::parse(&v, &folder, measure)).transpose().map_err(fail)?;
        let paths = glob_records("study", study.get("records"), &folder).map_err(fail)?;
        // Counted before a record is read: records × levels cases.
        let max_cases = parse_max_cases(&study).map_err(fail)?;
        let cases = paths.len().saturating_mul(levels.len());
        if cases > max_cases {
            return Err(fail(Fault::invalid(
                "study",
                format!(
                    "{} records × {} levels make {cases} cases, more than {max_cases}; to run them knowingly, raise the limit with `max_cases = {cases}` in [study]",
                    paths.len(),
                    levels.len()
                ),
            )));
        }
        let name = match table.get("name") {
            Some(Value::String(s)) => s.clone(),
            _ => origin.file_stem().map_or_else(|| "study".to_string(), |s| s.to_string_lossy().into_owned()),
        };
        let mut this = Self {
            origin: origin.to_path_buf(),
            name,
            base: table,
            records: Vec::with_capacity(paths.len()),
            measure,
            levels,
            free_after,
            limit_states,
            summary_keys: template.into_iter().map(|(k, _)| k).collect(),
            cache: RecordCache::default(),
            site,
        };
        for path in paths {
            let record = this.read_record(path, &ground_keys, &folder)?;
            this.records.push(record);
        }
        this.check_scales()?;
        // The longest record's case: a free_after too long for the history's
        // spacing shows there (its output_dt alone passed with each record).
        let longest = (0..this.records.len()).max_by(|&a, &b| this.records[a].duration.total_cmp(&this.records[b].duration));
        if let Some(first) = longest.and_then(|k| this.case_table(k * this.levels.len())) {
            let case = Scenario::from_table(first, &this.origin)
                .and_then(|s| s.build())
                .map_err(|e| this.free_after_error(e))
                .map_err(study_error)?;
            let derived = case.model.derived();
            limit::check_fields(&this.limit_states, derived.alpha.is_some(), derived.slip_acceleration_g.is_some()).map_err(fail)?;
        }
        Ok(this)
    }

    /// Refuses a level that no record can be scaled to: a scale (the level
    /// over the record's measure) that is not a finite number > 0.
    fn check_scales(&self) -> Result<(), Error> {
        for record in &self.records {
            for &level in &self.levels {
                let scale = level / record.measure;
                if !(scale.is_finite() && scale > 0.0) {
                    return Err(Fault::invalid(
                        "study.levels",
                        format!(
                            "{} over the {} {} of {} gives a scale of {scale}: a level must give every record a finite scale",
                            ryu::Buffer::new().format(level),
                            self.measure.as_str(),
                            ryu::Buffer::new().format(record.measure),
                            record.path
                        ),
                    )
                    .in_file(&self.origin));
                }
            }
        }
        Ok(())
    }

    /// An error of the history's spacing in the longest case, named as
    /// `study.free_after` (what made the case that long).
    fn free_after_error(&self, e: Error) -> Error {
        if e.fault.key.as_deref() != Some("simulation.output_dt") {
            return e;
        }
        Fault::invalid(
            "study.free_after",
            format!("{} s after each record: simulation.output_dt = {}", self.free_after, e.fault.kind),
        )
        .in_file(&self.origin)
    }

    /// Reads one record: its format (for the CSV-only keys), motion and measure.
    fn read_record(&self, path: String, keys: &GroundKeys, folder: &Path) -> Result<StudyRecord, Error> {
        let file = folder.join(&path);
        let format = match keys.format {
            Some(f) => f,
            None => {
                let text = crate::file::read_text(&file, crate::ground::MAX_RECORD_BYTES).map_err(|e| {
                    Fault::new(
                        "study.records",
                        ErrorKind::Read {
                            path: file.clone(),
                            reason: crate::error::io_reason(&e),
                            os_error: e.raw_os_error(),
                        },
                    )
                    .in_file(&self.origin)
                })?;
                Record::guess_format(&text)
                    .map_err(|source| Fault::new("study.records", ErrorKind::Record { path: file.clone(), source }).in_file(&self.origin))?
            }
        };
        let mut ground = Table::new();
        ground.insert("type".into(), Value::String("record".into()));
        ground.insert("file".into(), Value::String(path.clone()));
        if let Some(name) = &keys.format_name {
            ground.insert("format".into(), Value::String(name.clone()));
        }
        if format == RecordFormat::Csv {
            for (k, v) in &keys.csv {
                ground.insert(k.clone(), v.clone());
            }
        }
        let table = self.table_with(&ground, 1.0, 0.0);
        let case = Scenario::from_table(table, &self.origin)
            .and_then(|s| s.build_with(Some(&self.cache)))
            .map_err(study_error)?;
        let GroundMotion::Record(record) = &case.ground else {
            return Err(Fault::invalid("study.records", format!("{path} is not a record")).in_file(&self.origin));
        };
        let tan_alpha = case.model.derived().alpha.map(f64::tan);
        if self.measure == Measure::PgaRatio && tan_alpha.is_none() {
            return Err(Fault::new(
                "study.measure",
                ErrorKind::NotApplicable("\"pga_ratio\" is PGA / (g tan α) of the tower: it needs a [tower]".into()),
            )
            .in_file(&self.origin));
        }
        let measure = self.measure.of(record, case.model.gravity(), tan_alpha);
        if !(measure.is_finite() && measure > 0.0) {
            return Err(Fault::invalid(
                "study.records",
                format!(
                    "{}: its {} is {measure}: a record must have a measure > 0 to be scaled to a level",
                    file.display(),
                    self.measure.as_str()
                ),
            )
            .in_file(&self.origin));
        }
        Ok(StudyRecord {
            path,
            measure,
            duration: record.duration(),
            ground,
        })
    }

    /// The base scenario with `ground` (scaled by `scale`) and a duration of the record's plus `free_after`.
    fn table_with(&self, ground: &Table, scale: f64, duration: f64) -> Table {
        let mut table = self.base.clone();
        let mut ground = ground.clone();
        ground.insert("scale".into(), Value::Float(scale));
        table.insert("ground".into(), Value::Table(ground));
        if duration > 0.0 {
            let simulation = table.entry("simulation").or_insert_with(|| Value::Table(Table::new()));
            if let Value::Table(s) = simulation {
                s.insert("duration".into(), Value::Float(duration));
            }
        }
        table
    }

    /// The number of cases: records × levels.
    pub fn len(&self) -> usize {
        self.records.len() * self.levels.len()
    }
    /// Never true: a study has at least one record and one level.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The base scenario's `name` (default: the file stem).
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The study file (or origin).
    pub fn origin(&self) -> &Path {
        &self.origin
    }
    /// The records, in case order.
    pub fn records(&self) -> &[StudyRecord] {
        &self.records
    }
    /// The record files (resolved), for `--out` checks.
    pub fn inputs(&self) -> Vec<PathBuf> {
        let folder = self.origin.parent().unwrap_or(Path::new(""));
        self.records.iter().map(|r| folder.join(&r.path)).collect()
    }
    /// The intensity measure.
    pub fn measure(&self) -> Measure {
        self.measure
    }
    /// The levels, in case order.
    pub fn levels(&self) -> &[f64] {
        &self.levels
    }
    /// Seconds simulated after each record.
    pub fn free_after(&self) -> f64 {
        self.free_after
    }
    /// The limit states, in file order.
    pub fn limit_states(&self) -> &[LimitState] {
        &self.limit_states
    }
    /// The site and its hazard curve, when the study names one (`[site]`).
    pub fn site(&self) -> Option<&StudySite> {
        self.site.as_ref()
    }

    /// The columns of `stripes.csv`: `record`, `level`, `scale`, the scalar
    /// fields of `summary.json` as in `sweep.csv`, then `error`.
    pub fn header(&self) -> Vec<String> {
        let mut h: Vec<String> = CASE_COLUMNS.iter().map(|s| s.to_string()).collect();
        h.extend(self.summary_keys.iter().cloned());
        h.push(ERROR_COLUMN.to_string());
        h
    }

    /// The header as one line of CSV.
    pub fn csv_header(&self) -> String {
        crate::csv_line(self.header().iter().map(String::as_str))
    }

    /// The record and level of case `index` (records vary slowest), `None` past the end.
    pub fn case(&self, index: usize) -> Option<(&StudyRecord, f64)> {
        let n = self.levels.len();
        let record = self.records.get(index / n.max(1))?;
        Some((record, self.levels[index % n]))
    }

    /// The scale of case `index`: its level over its record's measure.
    pub fn scale(&self, index: usize) -> Option<f64> {
        self.case(index).map(|(r, level)| level / r.measure)
    }

    /// The scenario table of case `index`: the base, `[ground]` the record
    /// with its `scale`, `simulation.duration` the record's plus `free_after`.
    pub fn case_table(&self, index: usize) -> Option<Table> {
        let (record, level) = self.case(index)?;
        Some(self.table_with(&record.ground, level / record.measure, record.duration + self.free_after))
    }

    /// Runs case `index` on this thread: its row (with `error` filled if it failed).
    pub fn run_case(&self, index: usize) -> Row {
        self.run_case_until(index, &|| false).unwrap_or_else(|| self.failed_row(index, "stopped"))
    }

    /// Runs case `index` as [`Study::run_case`] does, stopping it at its next
    /// event once `halted()` is true: `None` for a case so stopped.
    fn run_case_until(&self, index: usize, halted: &dyn Fn() -> bool) -> Option<Row> {
        let Some(table) = self.case_table(index) else {
            return Some(self.failed_row(index, "no such case"));
        };
        let outcome = Scenario::from_table(table, &self.origin)
            .and_then(|s| s.build_with(Some(&self.cache)))
            .and_then(|case| case.run_observed(RunOptions::SUMMARY, &mut Until(halted)));
        match outcome {
            Ok(outcome) => {
                let mut cells = self.case_cells(index);
                cells.extend(summary_fields(&outcome).into_iter().map(|(_, cell)| cell));
                cells.push(Cell::Empty);
                Some(Row { index, cells })
            }
            Err(e) if is_stopped(&e) => None,
            Err(e) => Some(self.failed_row(index, &e.fault.to_string())),
        }
    }

    fn failed_row(&self, index: usize, message: &str) -> Row {
        let mut cells = self.case_cells(index);
        cells.extend(std::iter::repeat_n(Cell::Empty, self.summary_keys.len()));
        cells.push(Cell::Text(one_line(message)));
        Row { index, cells }
    }

    fn case_cells(&self, index: usize) -> Vec<Cell> {
        let mut cells = Vec::with_capacity(CASE_COLUMNS.len() + self.summary_keys.len() + 1);
        match self.case(index) {
            Some((record, level)) => {
                cells.push(Cell::Text(record.path.clone()));
                cells.push(Cell::Float(level));
                cells.push(Cell::Float(level / record.measure));
            }
            None => cells.extend([Cell::Empty, Cell::Empty, Cell::Empty]),
        }
        cells
    }

    /// Runs every case as [`crate::Sweep::run`] does: `on_row` gets the rows
    /// in case order on the calling thread.
    pub fn run<E>(&self, threads: Option<usize>, cancel: &AtomicBool, on_row: impl FnMut(Row) -> Result<(), E>) -> Result<Finished, RunError<E>> {
        self.run_range(0..self.len(), threads, cancel, on_row)
    }

    /// Runs the cases `cases` (a shard: indices in the whole study, clipped to
    /// `0..len`) as [`Study::run`] runs them all, each row that of the whole study.
    pub fn run_range<E>(
        &self,
        cases: std::ops::Range<usize>,
        threads: Option<usize>,
        cancel: &AtomicBool,
        on_row: impl FnMut(Row) -> Result<(), E>,
    ) -> Result<Finished, RunError<E>> {
        run_cases(self, cases, threads, cancel, on_row)
    }

    /// A tally of exceedances for this study's limit states and levels.
    pub fn tally(&self) -> Tally {
        Tally::new(&self.limit_states, &self.levels, &self.header())
    }
}

impl Cases for Study {
    fn len(&self) -> usize {
        Study::len(self)
    }
    fn run_case_until(&self, index: usize, halted: &dyn Fn() -> bool) -> Option<Row> {
        Study::run_case_until(self, index, halted)
    }
    fn failed_row(&self, index: usize, message: &str) -> Row {
        Study::failed_row(self, index, message)
    }
}

/// An error of building a study's case, its `ground.*` key named as the `study.*` key the user wrote.
fn study_error(mut e: Error) -> Error {
    let renamed = match e.fault.key.as_deref() {
        Some("ground.file") => Some("study.records"),
        // The scale of a case is its level over its record's measure.
        Some("ground.scale") => Some("study.levels"),
        Some("ground.format") => Some("study.format"),
        Some("ground.units") => Some("study.units"),
        Some("ground.dt") => Some("study.dt"),
        Some("simulation.duration") => Some("study.free_after"),
        _ => None,
    };
    if let Some(key) = renamed {
        e.fault.key = Some(key.to_string());
    }
    e
}

/// `format`, `units` and `dt` of `[study]`, applied to each record's `[ground]`.
struct GroundKeys {
    format: Option<RecordFormat>,
    format_name: Option<String>,
    /// `units` and `dt`, for CSV files only.
    csv: Vec<(String, Value)>,
}

fn ground_keys(study: &Table) -> Result<GroundKeys, Fault> {
    let (format, format_name) = match study.get("format") {
        None => (None, None),
        Some(Value::String(s)) => {
            let f = match s.as_str() {
                "at2" => RecordFormat::At2,
                "esm" => RecordFormat::Esm,
                "csv" => RecordFormat::Csv,
                other => {
                    return Err(Fault::invalid(
                        "study.format",
                        format!("must be one of \"at2\", \"esm\", \"csv\", got \"{other}\""),
                    ))
                }
            };
            (Some(f), Some(s.clone()))
        }
        Some(other) => {
            return Err(Fault::new(
                "study.format",
                ErrorKind::WrongType {
                    expected: "a string (\"at2\", \"esm\" or \"csv\")",
                    got: with_article(other),
                },
            ))
        }
    };
    let csv = ["units", "dt"]
        .iter()
        .filter_map(|k| study.get(*k).map(|v| (k.to_string(), v.clone())))
        .collect();
    Ok(GroundKeys { format, format_name, csv })
}

/// `max_cases`: the most cases (records × levels) the study may have, as `[sweep]`'s.
fn parse_max_cases(study: &Table) -> Result<usize, Fault> {
    let key = "study.max_cases";
    match study.get("max_cases") {
        None => Ok(crate::DEFAULT_MAX_CASES),
        Some(Value::Integer(n)) => usize::try_from(*n)
            .ok()
            .filter(|&n| n >= 1)
            .ok_or_else(|| Fault::invalid(key, format!("must be a whole number >= 1, got {n}"))),
        Some(other) => Err(Fault::new(
            key,
            ErrorKind::WrongType {
                expected: "a whole number",
                got: with_article(other),
            },
        )),
    }
}

fn parse_measure(study: &Table) -> Result<Measure, Fault> {
    let names: Vec<&'static str> = Measure::ALL.iter().map(|(n, _)| *n).collect();
    match study.get("measure") {
        None => Err(Fault::new(
            "study.measure",
            ErrorKind::Missing("required: the intensity measure, \"pga\" (g), \"pgv\" (m/s) or \"pga_ratio\"".into()),
        )),
        Some(Value::String(s)) => Measure::ALL.iter().find(|(n, _)| n == s).map(|(_, m)| *m).ok_or_else(|| {
            Fault::invalid(
                "study.measure",
                format!(
                    "must be one of \"pga\", \"pgv\", \"pga_ratio\", got \"{s}\"{}",
                    closest(s, &names).map_or(String::new(), |c| format!(" (did you mean \"{c}\"?)"))
                ),
            )
        }),
        Some(other) => Err(Fault::new(
            "study.measure",
            ErrorKind::WrongType {
                expected: "a string (\"pga\", \"pgv\" or \"pga_ratio\")",
                got: with_article(other),
            },
        )),
    }
}

/// `levels`: a list of numbers > 0, or `{ from, to, steps }` / `{ from, to, step }`
/// expanded as a sweep's range is.
fn parse_levels(study: &Table) -> Result<Vec<f64>, Fault> {
    let key = "study.levels";
    let value = study
        .get("levels")
        .ok_or_else(|| Fault::new(key, ErrorKind::Missing("required: a list of levels or a range { from, to, steps }".into())))?;
    let levels = match value {
        Value::Array(items) => {
            if items.is_empty() {
                return Err(Fault::invalid(key, "the list of levels is empty: give at least one"));
            }
            items
                .iter()
                .enumerate()
                .map(|(i, v)| {
                    as_number(v).ok_or_else(|| {
                        Fault::new(
                            format!("{key}[{i}]"),
                            ErrorKind::WrongType {
                                expected: "a number",
                                got: with_article(v),
                            },
                        )
                    })
                })
                .collect::<Result<Vec<f64>, Fault>>()?
        }
        Value::Table(_) => {
            // A range reads and expands as a sweep axis does; its errors name the study's key.
            let axis = crate::AxisSpec::from_toml("ground.amplitude", value)
                .and_then(|spec| spec.expand("ground.amplitude"))
                .map_err(|mut f| {
                    f.key = f.key.map(|k| k.replace("sweep.\"ground.amplitude\"", key));
                    f
                })?;
            axis.values().iter().filter_map(as_number).collect()
        }
        other => {
            return Err(Fault::new(
                key,
                ErrorKind::WrongType {
                    expected: "a list of levels or a range { from, to, steps } / { from, to, step }",
                    got: with_article(other),
                },
            ))
        }
    };
    if let Some((i, x)) = levels.iter().enumerate().find(|(_, x)| !(x.is_finite() && **x > 0.0)) {
        return Err(Fault::invalid(format!("{key}[{i}]"), format!("must be a finite number > 0, got {x}")));
    }
    Ok(levels)
}

/// The record files of `records` (glob patterns relative to `folder`), each
/// pattern's matches sorted, a file matched twice (by its canonical path)
/// kept once; paths relative to `folder`. A pattern that matches no file, and
/// a file name that is not UTF-8 where a pattern would match it, are errors.
/// `section` is the table of the key (`study`, `assessment`).
pub(crate) fn glob_records(section: &str, value: Option<&Value>, folder: &Path) -> Result<Vec<String>, Fault> {
    let key = &format!("{section}.records");
    let patterns: Vec<&str> = match value {
        None => {
            return Err(Fault::new(
                key,
                ErrorKind::Missing("required: glob patterns of the record files, e.g. [\"records/*.AT2\"]".into()),
            ))
        }
        Some(Value::String(s)) => vec![s.as_str()],
        Some(Value::Array(items)) => items
            .iter()
            .enumerate()
            .map(|(i, v)| match v {
                Value::String(s) => Ok(s.as_str()),
                other => Err(Fault::new(
                    format!("{key}[{i}]"),
                    ErrorKind::WrongType {
                        expected: "a string (a glob pattern)",
                        got: with_article(other),
                    },
                )),
            })
            .collect::<Result<_, _>>()?,
        Some(other) => {
            return Err(Fault::new(
                key,
                ErrorKind::WrongType {
                    expected: "a list of glob patterns",
                    got: with_article(other),
                },
            ))
        }
    };
    let mut paths: Vec<String> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for (i, pattern) in patterns.iter().enumerate() {
        let at = if patterns.len() > 1 { format!("{key}[{i}]") } else { key.to_string() };
        let found = matching_files(pattern, folder).map_err(|why| Fault::invalid(at.clone(), why))?;
        if found.is_empty() {
            return Err(Fault::invalid(
                at,
                format!("no file matches \"{pattern}\" (patterns are relative to the study file)"),
            ));
        }
        for path in found {
            // A file reached twice (two patterns, a link to it, a link to a folder) is one record.
            if seen.insert(std::fs::canonicalize(&path).unwrap_or_else(|_| path.clone())) {
                let relative = path.strip_prefix(folder).map(Path::to_path_buf).unwrap_or(path);
                paths.push(relative.to_string_lossy().replace('\\', "/"));
            }
        }
    }
    if paths.is_empty() {
        return Err(Fault::invalid(
            key,
            format!(
                "no file matches {} (patterns are relative to the {section} file)",
                patterns.iter().map(|p| format!("\"{p}\"")).collect::<Vec<_>>().join(", ")
            ),
        ));
    }
    Ok(paths)
}

/// Folders of the system that hold no records and have no end when walked
/// (`/proc/self/root` leads back to `/`): never searched.
const SYSTEM_FOLDERS: [&str; 2] = ["/proc", "/sys"];

/// The regular files matching the glob `pattern` (relative to `folder`
/// unless absolute), sorted; or why the pattern cannot be searched.
///
/// The folders are walked by `walkdir`, following links but never into a
/// folder it is already inside (a cycle of links is walked once), no deeper
/// than the pattern reaches (any depth below a `**`), never into
/// [`SYSTEM_FOLDERS`]; each path is matched whole with `glob::Pattern` (`*`
/// stays within one folder). The glob crate's own walk skips a file name
/// that is not UTF-8 without a word, and follows a cycle of links until the
/// paths grow too long.
fn matching_files(pattern: &str, folder: &Path) -> Result<Vec<PathBuf>, String> {
    let options = glob::MatchOptions {
        require_literal_separator: true,
        ..glob::MatchOptions::new()
    };
    let is_wild = |c: &str| c.contains(['*', '?', '[']);
    let components: Vec<&str> = pattern.split('/').collect();
    let literal = components.iter().take_while(|c| !is_wild(c)).count();
    let full = |p: &str| {
        if folder.as_os_str().is_empty() || Path::new(pattern).is_absolute() {
            PathBuf::from(p)
        } else {
            folder.join(p)
        }
    };
    if literal == components.len() {
        // No wildcard: the file itself.
        let path = full(pattern);
        return Ok(if path.is_file() { vec![path] } else { Vec::new() });
    }
    let base_text = components[..literal].join("/");
    let base = match (base_text.is_empty(), Path::new(pattern).is_absolute()) {
        (true, true) => PathBuf::from("/"),
        (true, false) => full("."),
        _ => full(&base_text),
    };
    let canonical_base = std::fs::canonicalize(&base).unwrap_or_else(|_| base.clone());
    if let Some(system) = SYSTEM_FOLDERS.iter().find(|s| canonical_base.starts_with(s)) {
        return Err(format!("\"{pattern}\" searches {system}, which holds no records: give the records' folder"));
    }
    let rest = &components[literal..];
    let depth = if rest.contains(&"**") { usize::MAX } else { rest.len() };
    let matcher = glob::Pattern::new(&format!(
        "{}/{}",
        glob::Pattern::escape(&base.to_string_lossy()).trim_end_matches('/'),
        rest.join("/")
    ))
    .map_err(|e| format!("\"{pattern}\" is not a glob pattern: {e}"))?;
    let walk = walkdir::WalkDir::new(&base)
        .follow_links(true)
        .min_depth(1)
        .max_depth(depth)
        .into_iter()
        .filter_entry(|e| !(e.file_type().is_dir() && is_system(e.path())));
    let mut found = Vec::new();
    // Unreadable folders and cycles of links are passed over, as the shell's glob does.
    for entry in walk.flatten() {
        if !entry.file_type().is_file() {
            continue;
        }
        let path = entry.path();
        match path.to_str() {
            Some(text) if matcher.matches_with(text, options) => found.push(path.to_path_buf()),
            Some(_) => {}
            None if matcher.matches_with(&path.to_string_lossy(), options) => {
                return Err(format!(
                    "{}: a file name that is not UTF-8 (it cannot be named in stripes.csv): rename it",
                    path.display()
                ))
            }
            None => {}
        }
    }
    found.sort();
    Ok(found)
}

/// Whether the folder `path` is (or leads by links into) one of [`SYSTEM_FOLDERS`].
fn is_system(path: &Path) -> bool {
    let canonical = std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf());
    SYSTEM_FOLDERS.iter().any(|s| canonical.starts_with(s))
}
