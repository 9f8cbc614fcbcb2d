//! What an assessment needs from its file, validated: the file's `[site]` and
//! `[assessment]` as the scenario crate reads them
//! ([`rocking_scenario::AssessmentFile`], whose keys are in the key table),
//! and what the checks add: the scenario's own sections valid, with a
//! `[tower]` and without `simulation.duration`; the damage, life-safety and
//! collapse limit states all given; FC ≥ 1; a record set of 0 or at least 3.

use crate::capacity::{Capacity, CurveKind};
use crate::check::{Check, Method};
use crate::height::SupportModes;
use crate::outputs::number;
use crate::site::{Role, Site};
use rocking_scenario::{AssessmentFile, Error, ErrorKind, Fault, Scenario, SetEntry, VerdictMethod};
use std::path::{Path, PathBuf};
use toml::{Table, Value};

/// The scan of the factor λ on every record's fitted scale (the dynamic checks).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LambdaScan {
    /// The first λ (> 0).
    pub from: f64,
    /// The last λ (> from).
    pub to: f64,
    /// The step (> 0).
    pub step: f64,
}

impl LambdaScan {
    /// How many values of λ the scan has (as a number: a range of 10³⁰⁰ steps is counted, not listed).
    fn count(&self) -> f64 {
        ((self.to - self.from) / self.step + 1e-6).floor() + 1.0
    }

    /// The values of λ: from, from + step, … up to `to` (within a millionth of a
    /// step), each kept as computed (`from + k·step`: never rounded, so that a
    /// λ of 1e-13 stays 1e-13 and one of 1e300 stays finite).
    pub fn values(&self) -> Vec<f64> {
        let n = (self.count() - 1.0).max(0.0) as usize;
        (0..=n).map(|k| self.from + k as f64 * self.step).collect()
    }

    /// Refuses a scan that cannot be represented, naming its key: more than
    /// [`MAX_LAMBDA_VALUES`] values, a step lost in the rounding of `from`
    /// (two λ the same), or a `to` above [`MAX_LAMBDA`].
    fn check(&self) -> Result<(), Fault> {
        if self.count() > MAX_LAMBDA_VALUES as f64 {
            return Err(Fault::invalid(
                "assessment.lambda",
                format!("{:.4e} values of λ, more than {MAX_LAMBDA_VALUES}: widen the step", self.count()),
            ));
        }
        if self.from + self.step <= self.from {
            return Err(Fault::invalid(
                "assessment.lambda.step",
                format!(
                    "{} is lost in the rounding of from = {}: two values of λ would be the same",
                    number(self.step),
                    number(self.from)
                ),
            ));
        }
        if self.to > MAX_LAMBDA {
            return Err(Fault::invalid(
                "assessment.lambda.to",
                format!(
                    "{} is above {MAX_LAMBDA:.0e}: λ scales the fitted records, and a record scaled so far is no ground motion (its run overflows)",
                    number(self.to)
                ),
            ));
        }
        Ok(())
    }
}

/// The most values of λ a scan may have.
pub const MAX_LAMBDA_VALUES: usize = 10_000;

/// The largest λ a scan may reach: ten thousand times the records fitted to
/// the site (a scan that finds no failure below it reports `ζ_E ≥ λ`).
pub const MAX_LAMBDA: f64 = 1e4;

/// A validated assessment: the file, its scenario and its site.
#[derive(Debug, Clone)]
pub struct AssessmentInput {
    /// The file as the scenario crate reads it.
    pub file: AssessmentFile,
    /// The scenario's sections, validated with no ground motion.
    scenario: Scenario,
    /// The three limit states' spectra (5%).
    pub site: Site,
    /// The λ scan.
    pub lambda: LambdaScan,
    /// The support's modes at each limit state, with a `[support]`: the
    /// kinematic checks take the floor spectrum of its top.
    pub support: Option<SupportModes>,
}

impl AssessmentInput {
    /// Parses and validates the TOML text of an assessment file; `origin` names
    /// the file in errors and is the folder of the grid and the records.
    pub fn from_toml_str(text: &str, origin: &Path) -> Result<Self, Error> {
        Self::new(AssessmentFile::from_toml_str(text, origin)?)
    }

    /// From the file's table (a Python dict gives one); `origin` names it in errors.
    pub fn from_table(table: Table, origin: &Path) -> Result<Self, Error> {
        Self::new(AssessmentFile::from_table(table, origin)?)
    }

    /// Validates what the checks need of a parsed file.
    pub fn new(file: AssessmentFile) -> Result<Self, Error> {
        let origin = file.origin().to_path_buf();
        let fail = |f: Fault| f.in_file(&origin);
        if matches!(file.scenario.get("simulation"), Some(Value::Table(s)) if s.contains_key("duration")) {
            return Err(fail(Fault::new(
                "simulation.duration",
                ErrorKind::NotApplicable("a dynamic check runs each record plus assessment.free_after: remove simulation.duration".into()),
            )));
        }
        let scenario = Scenario::from_table(with_ground(&file.scenario, none_ground(), 1.0, file.confidence_factor), &origin)?;
        if scenario.model().tower().is_none() {
            return Err(fail(Fault::new(
                "tower",
                ErrorKind::Missing("an assessment needs a [tower]: the capacity is that of the tower rocking on its springing level".into()),
            )));
        }
        if file.confidence_factor < 1.0 {
            return Err(fail(Fault::invalid(
                "assessment.confidence_factor",
                format!("must be >= 1 (FC: 1.35, 1.2 or 1 for knowledge levels LC1–LC3), got {}", file.confidence_factor),
            )));
        }
        if !file.records.is_empty() && file.records.len() < rocking_codes::MIN_RECORDS {
            return Err(fail(Fault::invalid(
                "assessment.records",
                format!(
                    "a record set needs at least {} records (7 for the mean response to be used), got {}",
                    rocking_codes::MIN_RECORDS,
                    file.records.len()
                ),
            )));
        }
        if file.verdict_method == Some(VerdictMethod::NonlinearDynamic) && file.records.is_empty() {
            return Err(fail(Fault::invalid(
                "assessment.verdict_method",
                "\"nonlinear_dynamic\" needs a record set (assessment.records): without one no dynamic check is computed",
            )));
        }
        let ntc = file.site.code == rocking_scenario::Code::Ntc2018;
        let spectra = Role::ALL
            .map(|role| {
                let state = role.limit_state(ntc);
                file.site.spectrum(state).copied().ok_or_else(|| {
                    fail(Fault::new(
                        format!("site.{state}"),
                        ErrorKind::Missing(format!(
                            "missing [site.{state}]: an assessment checks {} (give each its table, or a hazard grid)",
                            Role::ALL.map(|r| r.limit_state(ntc).as_str()).join(", ")
                        )),
                    ))
                })
            })
            .into_iter()
            .collect::<Result<Vec<_>, Error>>()?;
        let site = Site::new(spectra[0], spectra[1], spectra[2]).map_err(|e| fail(Fault::invalid("site", e.to_string())))?;
        let (from, to, step) = file.lambda;
        let lambda = LambdaScan { from, to, step };
        lambda.check().map_err(fail)?;
        let support = match &file.support {
            None => None,
            Some(_) => {
                let [damage, life_safety, collapse] = Role::ALL.map(|role| file.support_modes(role.limit_state(ntc)).unwrap_or_default());
                Some(SupportModes::new(damage, life_safety, collapse).map_err(|e| fail(Fault::invalid("support", e.to_string())))?)
            }
        };
        Ok(Self {
            file,
            scenario,
            site,
            lambda,
            support,
        })
    }

    /// The file.
    pub fn origin(&self) -> &Path {
        self.file.origin()
    }
    /// The scenario's name (default: the file stem).
    pub fn name(&self) -> &str {
        self.scenario.name()
    }
    /// The tower, the building and gravity.
    pub fn model(&self) -> &rocking::Model {
        self.scenario.model()
    }
    /// The capacity curve chosen.
    pub fn curve(&self) -> CurveKind {
        match self.file.capacity {
            rocking_scenario::Capacity::Linear => CurveKind::Linear,
            rocking_scenario::Capacity::Exact => CurveKind::Exact,
        }
    }
    /// Whether the mechanisms stand on an elastic support (`[support]`): the
    /// kinematic checks are at height, the dynamic ones (on a rigid support)
    /// are reported at ground level and carry no verdict.
    pub fn at_height(&self) -> bool {
        self.support.is_some()
    }
    /// The method `assessment.verdict_method` names to carry the verdict; `None`: the most refined computed.
    pub fn verdict_method(&self) -> Option<Method> {
        self.file.verdict_method.map(|m| match m {
            VerdictMethod::LinearKinematic => Method::LinearKinematic,
            VerdictMethod::NonlinearKinematic => Method::NonlinearKinematic,
            VerdictMethod::NonlinearDynamic => Method::NonlinearDynamic,
        })
    }
    /// The input files besides the assessment file: the grid and the records.
    pub fn inputs(&self) -> Vec<PathBuf> {
        let mut inputs: Vec<PathBuf> = self
            .file
            .records
            .iter()
            .filter(|r| r.text.is_none())
            .map(|r| self.file.folder().join(&r.path))
            .collect();
        if let Some(path) = self.file.site.source.grid_file() {
            inputs.push(path.to_path_buf());
        }
        inputs
    }
    /// The scenario table of one record's run: the file's scenario with
    /// `[ground]` the record of the set `record` (a file relative to the
    /// file's folder or a text, a CSV record with the set's `units` and
    /// `dt`) and `simulation.duration` the given one.
    pub fn record_table(&self, record: &SetEntry, duration: f64) -> Result<Table, Error> {
        Ok(with_ground(
            &self.file.scenario,
            self.file.record_ground(record)?,
            duration,
            self.file.confidence_factor,
        ))
    }

    /// The assessment of the other principal direction: the tower and every
    /// block turned a quarter (each one's `width` and `depth` exchanged, a
    /// missing `depth` being the width), or `None` when every body's depth is
    /// its width (the same assessment) or the tower is given by `radius` and
    /// `alpha` (no plan).
    pub fn turned(&self) -> Result<Option<AssessmentInput>, Error> {
        let mut file = self.file.clone();
        let mut turned_any = false;
        let mut turn = |body: &mut Table| {
            let width = body.get("width").cloned();
            if let Some(width) = width {
                let depth = body.get("depth").cloned().unwrap_or_else(|| width.clone());
                let number = |v: &Value| v.as_float().or_else(|| v.as_integer().map(|i| i as f64));
                turned_any |= number(&depth) != number(&width);
                body.insert("width".into(), depth);
                body.insert("depth".into(), width);
            }
        };
        if let Some(Value::Table(tower)) = file.scenario.get_mut("tower") {
            turn(tower);
        }
        if let Some(Value::Array(blocks)) = file.scenario.get_mut("block") {
            for block in blocks.iter_mut() {
                if let Value::Table(block) = block {
                    turn(block);
                }
            }
        }
        if !turned_any {
            return Ok(None);
        }
        Self::new(file).map(Some)
    }

    /// The longest secant period at collapse T_SLC of the tower's mechanisms
    /// (the tower's and each block's): the dynamic checks' fitting range is
    /// stretched to it.
    pub fn longest_t_slc(&self) -> Result<f64, Error> {
        (1..=self.blocks().len()).try_fold(self.capacity()?.t_slc, |t, k| Ok(t.max(self.block_capacity(k)?.t_slc)))
    }

    /// The range of periods (s) over which the dynamic checks fit the record
    /// set when the longest T_SLC is `t_slc`: `assessment.period_range`, else
    /// the code's, stretched to cover `t_slc` ([`default_period_range`]).
    pub fn fitting_range(&self, t_slc: f64) -> (f64, f64) {
        self.file.period_range.unwrap_or_else(|| rocking_codes::default_period_range(Some(t_slc)))
    }

    /// The names of the blocks on the tower, the lowest first.
    pub fn blocks(&self) -> &rocking_scenario::BlockNames {
        self.scenario.blocks()
    }

    /// The tower's capacity with the file's FC and curve (with blocks on it,
    /// the whole stack turning as one rigid body on the springing level).
    pub fn capacity(&self) -> Result<Capacity, Error> {
        self.block_capacity(0)
    }

    /// The capacity of the mechanism of block `k` (0 the tower, `k` the `k`-th
    /// block above it: the belfry on its shaft) with the file's FC and curve.
    pub fn block_capacity(&self, k: usize) -> Result<Capacity, Error> {
        let key = if k == 0 { "tower".to_string() } else { self.blocks().name(k).to_string() };
        Capacity::of_block(self.model(), k, self.file.confidence_factor, self.curve()).map_err(|e| Fault::invalid(key, e.to_string()).in_file(self.origin()))
    }

    /// The kinematic checks ([`crate::kinematic_checks`]): activation, linear,
    /// non-linear (two), each with finite numbers. A check whose numbers leave
    /// the floating-point range is refused, naming the key: the limit state's
    /// `ag` (1e-320 g, whose ζ_E = a_g,capacity / a_g overflows), its site (an
    /// `F0` of 1e308, whose demand does), or `assessment.q` (a `q` of 1e308).
    pub fn kinematic_checks(&self, capacity: &Capacity) -> Result<Vec<Check>, Error> {
        let checks = match &self.support {
            None => crate::kinematic_checks(capacity, &self.site, self.file.q),
            Some(support) => crate::kinematic_checks_at_height(capacity, &self.site, support, self.file.q),
        }
        .map_err(|e| Fault::invalid("assessment.q", e.to_string()).in_file(self.origin()))?;
        match checks.iter().find(|c| !c.is_finite()) {
            None => Ok(checks),
            Some(c) => {
                // The linear check's capacity is q times the activation's: q is at
                // fault when the check would be finite with q = 1. Else a ζ_E alone
                // out of range is its ag's fault (too small), a demand the spectrum's.
                let q_at_fault = c.method == Method::LinearKinematic && (c.capacity / self.file.q / c.ag).is_finite();
                let key = if q_at_fault {
                    "assessment.q".to_string()
                } else if c.demand.is_finite() && c.capacity.is_finite() {
                    format!("site.{}.ag", c.limit_state)
                } else {
                    format!("site.{}", c.limit_state)
                };
                let unit = c.unit.as_str();
                Err(Fault::invalid(
                    key,
                    format!(
                        "the {} {} check leaves the floating-point range: demand {} {unit}, capacity {} {unit}, ζ_E {}, at ag = {} g (q = {})",
                        c.limit_state,
                        c.method,
                        number(c.demand),
                        number(c.capacity),
                        number(c.zeta_e),
                        number(c.ag),
                        number(self.file.q)
                    ),
                )
                .in_file(self.origin()))
            }
        }
    }
}

fn none_ground() -> Table {
    let mut ground = Table::new();
    ground.insert("type".into(), Value::String("none".into()));
    ground
}

/// The scenario table `base` with `[ground]` and `simulation.duration` set.
/// The scenario of `base` under `ground` for `duration` s. A masonry strength
/// `tower.compressive_strength` (f_m) becomes its design value
/// `f_d = f_m / FC` (`confidence_factor`), the one the hinge is placed with.
fn with_ground(base: &Table, ground: Table, duration: f64, confidence_factor: f64) -> Table {
    let mut table = base.clone();
    if let Some(Value::Table(tower)) = table.get_mut("tower") {
        let f_m = match tower.get("compressive_strength") {
            Some(Value::Float(f)) => Some(*f),
            Some(Value::Integer(i)) => Some(*i as f64),
            _ => None,
        };
        if let Some(f_m) = f_m {
            tower.insert("compressive_strength".into(), Value::Float(f_m / confidence_factor));
        }
    }
    table.insert("ground".into(), Value::Table(ground));
    if let Value::Table(s) = table.entry("simulation").or_insert_with(|| Value::Table(Table::new())) {
        s.insert("duration".into(), Value::Float(duration));
    }
    table
}
