//! Parametric sweeps (docs/src/reference/keys.md, "[sweep]"): a scenario plus a `[sweep]`
//! table of dotted scenario keys and their values; every combination is one
//! case, run in parallel, each giving one [`Row`] in a fixed order.
//!
//! The rules and an example are on [`Sweep`]; the order of rows and the
//! memory bound on [`Sweep::run`].

pub(crate) mod axis;
mod engine;
mod row;
mod shard;

#[cfg(test)]
mod tests;

pub use axis::{Axis, AxisSpec, MAX_AXIS_VALUES, SWEEPABLE_KEYS};
pub(crate) use engine::{is_stopped, Until};
pub use engine::{run_cases, Cases, Finished, RunError, WINDOW};
pub use row::{csv_line, spreadsheet_text, Cell, Row};
pub use shard::Shard;

use crate::columns::{summary_names, Layout, SUMMARY};
use crate::error::{Error, ErrorKind, Fault};
use crate::ground::RecordCache;
use crate::{set_dotted, RunOptions, Scenario};
use axis::{alternative, axis_name};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The field of `summary.json` that `sweep.csv` leaves out (it differs from run to run).
pub const WALL_TIME_KEY: &str = "wall_time_s";
/// The last column of `sweep.csv`: the message of a failed case, empty otherwise.
pub const ERROR_COLUMN: &str = "error";

/// A validated sweep: a base scenario and its axes; every combination of
/// the axes' values is one case.
///
/// ```
/// use rocking_scenario::{Cell, Sweep};
/// use std::path::Path;
/// use std::sync::atomic::AtomicBool;
///
/// let text = r#"
///     [tower]
///     width = 0.5
///     height = 2.0
///     mass = 500.0
///
///     [ground]
///     type = "sine-pulse"
///     amplitude = 0.5
///     frequency = 2.0
///
///     [simulation]
///     duration = 2.0
///
///     [sweep]
///     "ground.amplitude" = [0.2, 0.5]                          # g: tan α = 0.25
///     "ground.frequency" = { from = 1.0, to = 3.0, step = 1.0 } # Hz: 1, 2, 3
/// "#;
/// let sweep = Sweep::from_toml_str(text, Path::new("block-sweep.toml"))?;
/// assert_eq!(sweep.len(), 6);
/// let header = sweep.header();
/// assert_eq!(&header[..3], ["ground.amplitude", "ground.frequency", "name"]);
/// assert_eq!(header.last().map(String::as_str), Some("error"));
///
/// // Columns, in case order whatever the number of threads.
/// let column = header.iter().position(|h| h == "max_theta_over_alpha").unwrap_or(0);
/// let mut peaks = Vec::new();
/// let cancel = AtomicBool::new(false);
/// let done = sweep.run(Some(2), &cancel, |row| {
///     peaks.push(row.cells[column].as_f64());
///     Ok::<(), std::convert::Infallible>(())
/// })?;
/// assert_eq!((done.written, done.failed, done.cancelled), (6, 0, false));
/// assert_eq!(peaks[..3], [Some(0.0), Some(0.0), Some(0.0)]); // 0.2 g < 0.25 g: no uplift
/// assert!(peaks[3..].iter().all(|p| p.is_some_and(|p| p > 0.0)));
/// # Ok::<(), Box<dyn std::error::Error>>(())
/// ```
///
/// ## Rules
///
/// - Axis keys are the scalar keys of a scenario ([`SWEEPABLE_KEYS`]); an
///   unknown key, a section, `tower.points`, a value of the wrong type, an
///   empty list or a bad range is an error naming `sweep."key"`, found before
///   anything runs. Keys may be quoted (`"ground.frequency" = …`) or written
///   as TOML dotted keys (`ground.frequency = …`). Values are a list or a
///   range; how a range is expanded (and a `step` that does not divide it) is
///   on [`AxisSpec`].
/// - An axis on a key with an alternative (`ground.amplitude` /
///   `ground.amplitude_ratio`, `ground.frequency` / `ground.frequency_ratio`,
///   `initial.theta` / `initial.theta_over_alpha`, `tower.mass` /
///   `tower.density`) removes the other from the base scenario: a scenario
///   giving `amplitude` can be swept over `amplitude_ratio`. Two axes on the
///   same pair are an error.
/// - Case `i` sets every axis to its value (the first axis varies slowest)
///   with [`crate::set_dotted`], then parses, builds and runs the scenario. A
///   case that fails (a bad combination such as `mu_kinetic > mu_static`, or a
///   numerical failure) gives a row with its one-line message in `error` and
///   every result empty; the others go on.
/// - A record file is read and parsed once, by the first case that needs it,
///   and shared by the cases that differ only in other keys (`ground.scale`
///   among them); a few records are kept when `ground.file` is swept.
/// - The sweep is refused before running when no case at all can be parsed
///   and built (the base scenario itself is wrong: the error is that of the
///   first case), or when the first case's record file cannot be read (and
///   `ground.file` is not swept).
/// - Columns ([`Sweep::header`]): the axis keys, then every scalar field of
///   `summary.json` ([`crate::summary_scalars`]) except `wall_time_s`, then
///   `error`. The wall time is left out so that the rows depend on nothing but
///   the inputs: the same file whatever the number of threads.
#[derive(Debug, Clone)]
pub struct Sweep {
    origin: PathBuf,
    name: String,
    base: Table,
    axes: Vec<Axis>,
    len: usize,
    summary_keys: Vec<String>,
    layout: Layout,
    inputs: Vec<PathBuf>,
    /// Records read by the cases so far, shared by the workers.
    records: RecordCache,
}

impl Sweep {
    /// Parses and validates the TOML text of a sweep file: a scenario plus a
    /// `[sweep]` table. `origin` names the file in errors and is the folder of
    /// relative record paths.
    pub fn from_toml_str(text: &str, origin: &Path) -> Result<Self, Error> {
        Self::from_table(crate::parse_toml(text, origin)?, origin)
    }

    /// A sweep from a table holding a scenario and its `[sweep]` table.
    pub fn from_table(mut table: Table, origin: &Path) -> Result<Self, Error> {
        let sweep = match table.remove("sweep") {
            Some(Value::Table(t)) => t,
            Some(other) => {
                return Err(Fault::new(
                    "sweep",
                    ErrorKind::WrongType {
                        expected: "a table (a [sweep] section)",
                        got: crate::read::with_article(&other),
                    },
                )
                .in_file(origin))
            }
            None => {
                return Err(Fault::new(
                    "sweep",
                    ErrorKind::Missing("missing section [sweep]: give the swept keys and their values, e.g. \"ground.frequency\" = [3.0, 5.0]".into()),
                )
                .in_file(origin))
            }
        };
        let mut sweep = sweep;
        let max_cases = match sweep.remove(MAX_CASES_KEY) {
            None => DEFAULT_MAX_CASES,
            Some(Value::Integer(n)) if n > 0 => usize::try_from(n).unwrap_or(usize::MAX),
            Some(other) => {
                return Err(Fault::invalid(
                    format!("sweep.{MAX_CASES_KEY}"),
                    format!("must be a whole number > 0, got {}", crate::read::with_article(&other)),
                )
                .in_file(origin))
            }
        };
        let mut axes = Vec::new();
        flatten_axes(&sweep, "", &mut axes).map_err(|f| f.in_file(origin))?;
        Self::from_parts_capped(table, axes, origin, max_cases)
    }

    /// A sweep from a JSON object with the structure of the TOML file (a
    /// scenario plus a `sweep` object), as a Python dict gives it.
    pub fn from_json(value: serde_json::Value, origin: &Path) -> Result<Self, Error> {
        let table = crate::json::to_table(value).map_err(|f| f.in_file(origin))?;
        Self::from_table(table, origin)
    }

    /// A sweep from a base scenario (without `[sweep]`) and its axes in order
    /// (the first varies slowest). Checks every axis, then parses the cases in
    /// order until one can be built: if none can, the first case's error.
    pub fn from_parts(base: Table, axes: Vec<(String, AxisSpec)>, origin: &Path) -> Result<Self, Error> {
        Self::from_parts_capped(base, axes, origin, DEFAULT_MAX_CASES)
    }

    /// As [`Sweep::from_parts`], refusing more than `max_cases` cases in all.
    pub fn from_parts_capped(mut base: Table, axes: Vec<(String, AxisSpec)>, origin: &Path, max_cases: usize) -> Result<Self, Error> {
        let fail = |f: Fault| f.in_file(origin);
        if axes.is_empty() {
            return Err(fail(Fault::new(
                "sweep",
                ErrorKind::Missing("no swept key: give at least one, e.g. \"ground.frequency\" = [3.0, 5.0]".into()),
            )));
        }
        let blocks = crate::block::names(&base).map_err(fail)?;
        let mut expanded: Vec<Axis> = Vec::with_capacity(axes.len());
        for (key, spec) in &axes {
            if expanded.iter().any(|a| a.key() == key) {
                return Err(fail(Fault::invalid(axis_name(key), "is swept twice")));
            }
            if let Some(other) = alternative(key).filter(|alt| expanded.iter().any(|a| a.key() == *alt)) {
                return Err(fail(Fault::new(
                    axis_name(key),
                    ErrorKind::NotApplicable(format!("sweep either {other} or {key}, not both")),
                )));
            }
            expanded.push(spec.expand_with(key, &blocks).map_err(fail)?);
        }
        for a in &expanded {
            if let Some(other) = alternative(a.key()) {
                crate::remove_dotted(&mut base, other);
            }
        }
        let len = expanded.iter().try_fold(1usize, |n, a| n.checked_mul(a.len())).ok_or_else(|| {
            fail(Fault::invalid(
                "sweep",
                format!(
                    "{} values: too many combinations to count",
                    expanded.iter().map(|a| a.len().to_string()).collect::<Vec<_>>().join(" × ")
                ),
            ))
        })?;
        if len > max_cases {
            return Err(fail(Fault::invalid(
                "sweep",
                format!(
                    "{} values make {len} cases, more than {max_cases}; to run them knowingly, raise the limit with `{MAX_CASES_KEY} = {len}` in [sweep]",
                    expanded.iter().map(|a| a.len().to_string()).collect::<Vec<_>>().join(" × ")
                ),
            )));
        }
        let name = match base.get("name") {
            Some(Value::String(s)) => s.clone(),
            _ => origin.file_stem().map_or_else(|| "sweep".to_string(), |s| s.to_string_lossy().into_owned()),
        };
        // Known without a run: the optional fields follow the base scenario
        // (extra points add history columns only, not summary fields; a
        // vertical motion, in the base or set by an axis, adds one).
        let layout = Layout {
            vertical: matches!(crate::get_dotted(&base, "ground.vertical"), Some(Value::Table(_)))
                || expanded.iter().any(|a| a.key().starts_with("ground.vertical.")),
            blocks,
            ..Layout::default()
        };
        let mut sweep = Self {
            origin: origin.to_path_buf(),
            name,
            base,
            axes: expanded,
            len,
            summary_keys: summary_names(&layout),
            layout,
            inputs: Vec::new(),
            records: RecordCache::default(),
        };
        sweep.inputs = sweep.first_buildable_case()?;
        Ok(sweep)
    }

    /// The input files of the first case that builds (a ground-motion record),
    /// for `--out` checks. At most [`DEFAULT_MAX_CASES`] cases are tried: all
    /// of them in a sweep of no more (case 0 first), else as many spread over
    /// the sweep by [`spread_cases`] (a raised `max_cases` of 10⁹ cases all
    /// invalid searched for hours without a word).
    fn first_buildable_case(&self) -> Result<Vec<PathBuf>, Error> {
        let mut first_error = None;
        for index in spread_cases(self.len, DEFAULT_MAX_CASES) {
            match self.scenario(index).and_then(|s| s.build_with(Some(&self.records))) {
                Ok(case) => return Ok(case.inputs),
                Err(e) => {
                    // A record that cannot be read fails every case that reads it: say so now.
                    let file_level = matches!(e.kind(), ErrorKind::Read { .. } | ErrorKind::Record { .. });
                    let swept = e.key().is_some_and(|k| self.axes.iter().any(|a| a.key() == k));
                    if file_level && !swept {
                        return Err(e);
                    }
                    first_error.get_or_insert(e);
                }
            }
        }
        Err(first_error.unwrap_or_else(|| Fault::invalid("sweep", "no case").in_file(&self.origin)))
    }

    /// The number of cases (the product of the axes' lengths, >= 1).
    pub fn len(&self) -> usize {
        self.len
    }
    /// Never true: a sweep has at least one case.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }
    /// The axes, in order (the first varies slowest).
    pub fn axes(&self) -> &[Axis] {
        &self.axes
    }
    /// The swept keys, in order.
    pub fn axis_keys(&self) -> Vec<String> {
        self.axes.iter().map(|a| a.key().to_string()).collect()
    }
    /// The base scenario's `name` (default: the file stem).
    pub fn name(&self) -> &str {
        &self.name
    }
    /// The sweep file (or origin).
    pub fn origin(&self) -> &Path {
        &self.origin
    }
    /// Input files the cases read besides the sweep file (the first case's record).
    pub fn inputs(&self) -> &[PathBuf] {
        &self.inputs
    }

    /// The columns: the axis keys, the scalar fields of `summary.json`
    /// (flattened: `time_in_regime_s.rest`, …) without `wall_time_s`, and `error`.
    pub fn header(&self) -> Vec<String> {
        let mut h = self.axis_keys();
        h.extend(self.summary_keys.iter().cloned());
        h.push(ERROR_COLUMN.to_string());
        h
    }

    /// The header as one line of CSV.
    pub fn csv_header(&self) -> String {
        csv_line(self.header().iter().map(String::as_str))
    }

    /// The axis values of case `index` (`None` past the end).
    pub fn case_values(&self, index: usize) -> Option<Vec<&Value>> {
        if index >= self.len {
            return None;
        }
        let mut rest = index;
        let mut values = vec![None; self.axes.len()];
        for (slot, axis) in values.iter_mut().zip(&self.axes).rev() {
            *slot = axis.values().get(rest % axis.len());
            rest /= axis.len();
        }
        values.into_iter().collect()
    }

    /// The scenario table of case `index`: the base with every axis set.
    pub fn case_table(&self, index: usize) -> Result<Table, Error> {
        let values = self
            .case_values(index)
            .ok_or_else(|| Fault::invalid("sweep", format!("case {index} does not exist: the sweep has {} cases", self.len)).in_file(&self.origin))?;
        let mut table = self.base.clone();
        for (axis, value) in self.axes.iter().zip(values) {
            if crate::block::set_key(&mut table, &self.layout.blocks, axis.key(), value.clone()) {
                continue;
            }
            set_dotted(&mut table, axis.key(), value.clone()).map_err(|e| Fault::invalid(axis.key(), e.to_string()).in_file(&self.origin))?;
        }
        Ok(table)
    }

    /// The parsed scenario of case `index`.
    pub fn scenario(&self, index: usize) -> Result<Scenario, Error> {
        Scenario::from_table(self.case_table(index)?, &self.origin)
    }

    /// Runs case `index` on this thread: its row (with `error` filled if it failed).
    pub fn run_case(&self, index: usize) -> Row {
        self.run_case_until(index, &|| false).unwrap_or_else(|| self.failed_row(index, "stopped"))
    }

    /// Runs case `index` as [`Sweep::run_case`] does, stopping it at its next
    /// event once `halted()` is true: `None` for a case so stopped.
    fn run_case_until(&self, index: usize, halted: &dyn Fn() -> bool) -> Option<Row> {
        let outcome = self
            .scenario(index)
            .and_then(|s| s.build_with(Some(&self.records)))
            .and_then(|case| case.run_observed(RunOptions::SUMMARY, &mut Until(halted)));
        let outcome = match outcome {
            Ok(outcome) => outcome,
            Err(e) if is_stopped(&e) => return None,
            // The file is the sweep's: the message names the key and what is wrong.
            Err(e) => return Some(self.failed_row(index, &e.fault.to_string())),
        };
        let mut cells = self.axis_cells(index);
        // The fields come in the order of `summary_keys`.
        cells.extend(SUMMARY.iter().filter(|f| (f.present)(&self.layout)).map(|f| (f.read)(&outcome)));
        cells.extend(crate::columns::block_fields_of(&outcome).into_iter().map(|(_, cell)| cell));
        debug_assert_eq!(cells.len(), self.axes.len() + self.summary_keys.len());
        cells.push(Cell::Empty);
        Some(Row { index, cells })
    }

    /// The row of case `index` that failed with `message`: its axis values, empty results, the message.
    fn failed_row(&self, index: usize, message: &str) -> Row {
        let mut cells = self.axis_cells(index);
        cells.extend(std::iter::repeat_n(Cell::Empty, self.summary_keys.len()));
        cells.push(Cell::Text(one_line(message)));
        Row { index, cells }
    }

    fn axis_cells(&self, index: usize) -> Vec<Cell> {
        let mut cells = Vec::with_capacity(self.axes.len() + self.summary_keys.len() + 1);
        cells.extend(self.case_values(index).unwrap_or_default().into_iter().map(Cell::from_toml));
        cells
    }
}

/// The axes of a `[sweep]` table. A quoted key (`"ground.frequency" = …`) is
/// the dotted key itself; an unquoted one (`ground.frequency = …`) arrives as a
/// nested table under a section name (and `ground.vertical.amplitude = …`
/// under `ground`, then `vertical`), and is flattened back.
fn flatten_axes(table: &Table, prefix: &str, out: &mut Vec<(String, AxisSpec)>) -> Result<(), Fault> {
    for (k, v) in table {
        let key = if prefix.is_empty() { k.clone() } else { format!("{prefix}.{k}") };
        let nested = (prefix.is_empty() && crate::scenario::SECTIONS.contains(&k.as_str())) || (prefix == "ground" && k == crate::ground::VERTICAL);
        match v {
            Value::Table(t) if nested => flatten_axes(t, &key, out)?,
            _ => {
                if out.iter().any(|(existing, _)| *existing == key) {
                    return Err(Fault::invalid(axis_name(&key), "is given twice"));
                }
                out.push((key.clone(), AxisSpec::from_toml(&key, v)?));
            }
        }
    }
    Ok(())
}

/// `text` on one line (a row of `sweep.csv` holds a one-line message).
pub(crate) fn one_line(text: &str) -> String {
    text.split(['\n', '\r']).map(str::trim).filter(|l| !l.is_empty()).collect::<Vec<_>>().join(" ")
}

/// The summary fields of every case of `layout`, named, with a cell of their
/// kind (text, flag or number), from the descriptors: known without a run.
pub(crate) fn summary_template(layout: &crate::columns::Layout) -> Vec<(String, Cell)> {
    let cell = |kind: crate::columns::Kind| match kind {
        crate::columns::Kind::Number => Cell::Float(0.0),
        crate::columns::Kind::Flag => Cell::Bool(false),
        crate::columns::Kind::Text => Cell::Text(String::new()),
    };
    let mut template: Vec<(String, Cell)> = crate::columns::SUMMARY
        .iter()
        .filter(|f| (f.present)(layout))
        .map(|f| (f.name.to_string(), cell(f.kind)))
        .collect();
    // Each block's fields, as summary_fields gives them (crate::columns::summary_names).
    for name in layout.blocks.iter() {
        template.extend(crate::columns::SUMMARY_BLOCKS.iter().map(|f| (format!("{name}_{}", f.suffix), cell(f.kind))));
    }
    template
}

/// `tried` case indices of `0..len` (all of them, in order, when `tried >=
/// len`), spread over the sweep: `j·s mod len` for `j = 0..tried`, with `s`
/// the least stride >= `len / tried` that is coprime with `len`, hence with
/// every axis's length (each divides `len`). The walk then leaves every
/// value of the fastest axis in turn (`j·s mod n` runs through all residues
/// of its length `n`) instead of sampling one of them at every step, as an
/// even stride that is a multiple of that length did.
pub fn spread_cases(len: usize, tried: usize) -> impl Iterator<Item = usize> {
    let tried = tried.min(len);
    let mut stride = len.div_ceil(tried.max(1)).max(1);
    while gcd(stride, len) != 1 {
        stride += 1;
    }
    (0..tried).map(move |j| usize::try_from(j as u128 * stride as u128 % len as u128).unwrap_or(0))
}

/// The greatest common divisor (Euclid).
fn gcd(mut a: usize, mut b: usize) -> usize {
    while b != 0 {
        (a, b) = (b, a % b);
    }
    a
}

/// The key of `[sweep]` that raises the cap on the number of cases (not an axis: it has no dot).
pub const MAX_CASES_KEY: &str = "max_cases";
/// Most cases a sweep may have unless its `[sweep]` table raises the cap with
/// `max_cases`: a million rows are about 0.3 GB of `sweep.csv`; 1e9 (which
/// started without a word) would be 230 GB. It also bounds the search for a
/// first valid case when every case is invalid (about 7 µs a case: seconds).
pub const DEFAULT_MAX_CASES: usize = 1_000_000;
