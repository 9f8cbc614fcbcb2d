//! The non-linear dynamic checks (Circolare 2019 §C8.7.1.2.1.9): the record
//! set fitted to the life-safety and collapse spectra (5%, each record its own
//! scale, NTC 2018 §3.2.3.6), every record run through the full model (the
//! tower, and the building sliding if the scenario has one) for its duration
//! plus `free_after`; the response of a record is the largest control-point
//! displacement `d*(θ) = R (sin α − sin(α − |θ|))` over the run, overturning
//! counting as beyond d0. The check holds at a factor λ on every scale when no
//! record reaches d0 and the mean of the responses (the largest, with fewer
//! than 7 records) is at most d_LS. Its capacity is `λ ag` for the largest λ
//! at which it holds below the first failure: λ scanned, the first change
//! bisected to [`LAMBDA_TOLERANCE`]; the response need not grow with λ, so the
//! scan's first failure is the one reported, and the whole scan is kept for the
//! report (the mean response against λ).
//!
//! With blocks on the tower, each mechanism (the tower with the blocks on it,
//! each block with those above it) has its own check on the same runs: its
//! control point is its own block's `θ_k` (relative to the block below) over
//! its own capacity's `R`, `α`, and a record makes it collapse when its block
//! or one below it overturned. A block above it that overturned ends the run:
//! its response is then its largest d* up to then. The set at λ = 1 and the
//! scan are run once for all of them; each bisects its own first failure.

use crate::capacity::Capacity;
use crate::check::{Check, Method, Unit};
use crate::input::{AssessmentInput, LambdaScan};
use crate::search::AgCapacity;
use crate::site::Role;
use rayon::prelude::*;
use rocking::{GroundMotion, Record};
use rocking_codes::{fit_record_set, response_spectrum, FittedSet, LimitState, PeriodGrid, SetRule, DEFAULT_DAMPING_PCT};
use rocking_scenario::{Case, Error, Fault, RecordCache, RunOptions, Scenario};
use std::sync::atomic::{AtomicBool, Ordering};

/// The bisection of λ stops when the bracket is this narrow.
pub const LAMBDA_TOLERANCE: f64 = 1e-3;

/// The periods of the response spectra: 100, log-spaced from 0.02 s to the
/// larger of 4 s and the fitting range's end.
/// The periods (s) of the record set's spectra when the fitting range ends at
/// `range_to`: 100 log-spaced from 0.02 s to the larger of 4 s and `range_to`.
pub fn set_periods(range_to: f64) -> Result<Vec<f64>, rocking_codes::Error> {
    PeriodGrid {
        from: 0.02,
        to: range_to.max(4.0),
        count: 100,
    }
    .periods()
}

/// One record of the set, ready to run: its case with the record at scale 1 (m/s²).
#[derive(Debug, Clone)]
pub struct SetRecord {
    /// The file, relative to the assessment file's folder.
    pub path: String,
    /// Its file name, the column names of the outputs.
    pub name: String,
    /// The case of the record at scale 1.
    case: Case,
    /// The record (m/s²).
    record: Record,
    /// Its pseudo-acceleration spectrum at 5% (g) at [`RecordSet::periods`].
    pub psa_g: Vec<f64>,
}

/// The record set of an assessment, read once, with its spectra.
#[derive(Debug, Clone)]
pub struct RecordSet {
    /// The periods of the spectra (s).
    pub periods: Vec<f64>,
    /// The fitting range (s).
    pub range: (f64, f64),
    /// The records, in the file's order.
    pub records: Vec<SetRecord>,
}

/// The response of one record at one scale.
#[derive(Debug, Clone, PartialEq)]
pub struct RecordResponse {
    /// The largest control-point displacement d* (m); `None` when the tower overturned.
    pub max_displacement: Option<f64>,
    /// Whether the tower overturned.
    pub overturned: bool,
    /// The building's largest slip (m); `None` without a building.
    pub max_slip: Option<f64>,
    /// With blocks on the tower, the largest `|M_imp| / (V_imp B_j / 2)` of a
    /// seated interface through an impact elsewhere (0 without one): above 1
    /// the model's assumption that the interface stays seated is violated
    /// (docs/src/model.md). `None` for a tower alone.
    pub max_seat_impulse_ratio: Option<f64>,
}

impl RecordResponse {
    /// The response as the check reads it: d*, or d0 and beyond when it overturned.
    pub fn displacement_or(&self, d0: f64) -> f64 {
        self.max_displacement.unwrap_or(d0).max(if self.overturned { d0 } else { 0.0 })
    }
}

/// The responses of the set at one λ and the check's verdict there.
#[derive(Debug, Clone, PartialEq)]
pub struct LambdaPoint {
    /// λ.
    pub lambda: f64,
    /// Each record's response, or the one line of its failure.
    pub responses: Vec<Result<RecordResponse, String>>,
    /// The mean (7 records or more) or the largest response (m), overturning counted as d0.
    pub combined: f64,
    /// Whether the check holds: every record ran, none reached d0, the combined response at most d_LS.
    pub holds: bool,
    /// Whether every record ran.
    pub complete: bool,
}

impl LambdaPoint {
    /// The records (their indices in the set) whose response reaches `d0`:
    /// each one alone makes the check fail at this λ (a block that overturns
    /// reaches it too, [`RecordResponse::displacement_or`]).
    pub fn reaching_d0(&self, d0: f64) -> Vec<usize> {
        self.responses
            .iter()
            .enumerate()
            .filter(|(_, r)| r.as_ref().is_ok_and(|r| r.displacement_or(d0) >= d0))
            .map(|(i, _)| i)
            .collect()
    }
}

/// The non-linear dynamic check of one limit state.
#[derive(Debug, Clone)]
pub struct DynamicCheck {
    /// The limit state (SLV or SLC; SD or NC).
    pub limit_state: LimitState,
    /// The target spectrum (5%, g) at the set's periods.
    pub target_g: Vec<f64>,
    /// With a `[support]`, the code's floor spectrum of the support's top
    /// (5%, g) at the set's periods ([`crate::floor_spectrum_at`]).
    pub floor_g: Option<Vec<f64>>,
    /// With a `[support]`, the mean floor spectrum computed on its top (5%,
    /// g): each record at its fitted scale through the support alone
    /// ([`crate::support_top_motion`]), the pseudo-acceleration of the top's
    /// absolute acceleration, averaged over the set.
    pub floor_mean_g: Option<Vec<f64>>,
    /// The set fitted to it.
    pub fitted: FittedSet,
    /// The responses at λ = 1 (the fitted scales).
    pub at_one: LambdaPoint,
    /// The scan, then the bisection's points, in the order run.
    pub scan: Vec<LambdaPoint>,
    /// The bracket `(holds, fails)` of λ found, `None` when it held over the whole scan.
    pub bracket: Option<(f64, f64)>,
    /// The verdict; `None` when a record failed to run (the check could not be completed).
    pub check: Option<Check>,
    /// Why it could not be completed.
    pub error: Option<String>,
    /// Whether the mechanism stands on an elastic support that these runs
    /// leave out (the coupled model is not in the engine yet): the check is at
    /// ground level, not at height, and carries no verdict.
    pub below_support: bool,
}

impl DynamicCheck {
    /// Whether its set is compatible with the code's spectrum (NTC 2018
    /// §3.2.3.6): the mean of the scaled set within 0.90–1.30 of the target
    /// over the fitting range. A check on an incompatible set is not valid.
    pub fn is_valid(&self) -> bool {
        self.fitted.compatibility.holds
    }

    /// The check, if it may carry the verdict: completed, and valid unless
    /// `accept_incompatible_set` (`assessment.accept_incompatible_set`).
    /// A check run at ground level under a mechanism that stands on a support
    /// ([`DynamicCheck::below_support`]) never does.
    pub fn verdict_check(&self, accept_incompatible_set: bool) -> Option<Check> {
        self.check.filter(|_| !self.below_support && (accept_incompatible_set || self.is_valid()))
    }
}

/// The combined response of a set (m): the mean of the responses with at least 7
/// records, the largest with 3 to 6 (NTC 2018 §7.3.5), overturning counted as d0.
pub fn combined_response(responses: &[f64], rule: SetRule) -> f64 {
    match rule {
        SetRule::Mean => responses.iter().sum::<f64>() / responses.len() as f64,
        SetRule::Largest => responses.iter().copied().fold(0.0, f64::max),
    }
}

impl RecordSet {
    /// Reads the records of the assessment (each as `[ground]` reads a record,
    /// format guessed) and computes their spectra. `t_slc` (s) stretches the
    /// default fitting range.
    pub fn read(input: &AssessmentInput, t_slc: f64) -> Result<Self, Error> {
        Self::read_cached(input, t_slc, &RecordCache::with_capacity(input.file.records.len()))
    }

    /// As [`RecordSet::read`], each record taken from `cache` when it was read
    /// before (the towers of an inventory read each record file once).
    pub fn read_cached(input: &AssessmentInput, t_slc: f64, cache: &RecordCache) -> Result<Self, Error> {
        let origin = input.origin();
        let range = input.fitting_range(t_slc);
        let periods = set_periods(range.1).map_err(|e| Fault::invalid("assessment.period_range", e.to_string()).in_file(origin))?;
        let g = input.model().gravity();
        let records = input
            .file
            .records
            .par_iter()
            .map(|entry| {
                let path = &entry.path;
                // The record's duration is not known before it is read: a first case reads it.
                let read = |duration: f64| {
                    Scenario::from_table(input.record_table(entry, duration)?, origin)
                        .and_then(|s| s.build_cached(cache))
                        .map_err(|mut e| {
                            // The keys of the record's [ground] are the set's.
                            let key = match e.fault.key.as_deref() {
                                Some("ground.units") => "assessment.units",
                                Some("ground.dt") => "assessment.dt",
                                _ => "assessment.records",
                            };
                            e.fault.key = Some(key.into());
                            // A record given as text is named by its name, not as a text.
                            if let (rocking_scenario::ErrorKind::Record { path: named, .. }, Some(_)) = (&mut e.fault.kind, &entry.text) {
                                *named = path.into();
                            }
                            // The message names the record (that of a file that
                            // cannot be read does; one of the case built on it may not).
                            if !e.fault.kind.to_string().contains(entry.name()) {
                                e.fault.kind = rocking_scenario::ErrorKind::Invalid(format!("{path}: {}", e.fault.kind));
                            }
                            e
                        })
                };
                let first = read(1.0)?;
                let GroundMotion::Record(record) = &first.ground else {
                    return Err(Fault::invalid("assessment.records", format!("{path} is not a record")).in_file(origin));
                };
                let record = record.clone();
                let case = read(record.duration() + input.file.free_after)?;
                let psa_g = response_spectrum(&record, &periods, DEFAULT_DAMPING_PCT)
                    .map_err(|e| {
                        // Too many steps over a period range the file gives: that range is named.
                        let key = match e {
                            rocking_codes::Error::InvalidParameter { name: "periods", .. } if input.file.period_range.is_some() => "assessment.period_range",
                            _ => "assessment.records",
                        };
                        Fault::invalid(key, format!("{path}: {e}")).in_file(origin)
                    })?
                    .into_iter()
                    .map(|a| a / g)
                    .collect();
                let name = entry.name().to_string();
                Ok(SetRecord {
                    path: path.clone(),
                    name,
                    case,
                    record,
                    psa_g,
                })
            })
            // Collected in order before the first failure is taken: a parallel
            // collect into a `Result` stops at whichever failure a thread meets
            // first, and the message would name a different record run to run.
            .collect::<Vec<Result<SetRecord, Error>>>()
            .into_iter()
            .collect::<Result<Vec<_>, Error>>()?;
        Ok(Self { periods, range, records })
    }

    /// Runs record `i` at `scale` on its fitted record: the tower's response
    /// (`capacity` the tower's), or the one line of its failure.
    pub fn run(&self, i: usize, scale: f64, capacity: &Capacity) -> Result<RecordResponse, String> {
        Ok(self.run_mechanisms(i, scale, &[(0, capacity)])?.remove(0))
    }

    /// Runs record `i` at `scale`: the response of each mechanism `(k, capacity)`
    /// (block `k`, 0 the tower) in order, or the one line of the run's failure.
    pub fn run_mechanisms(&self, i: usize, scale: f64, mechanisms: &[(usize, &Capacity)]) -> Result<Vec<RecordResponse>, String> {
        let r = &self.records[i];
        let mut case = r.case.clone();
        case.ground = GroundMotion::Record(r.record.scaled(scale));
        let outcome = case.run(RunOptions::SUMMARY).map_err(|e| e.fault.to_string())?;
        let s = &outcome.summary;
        let max_slip = case.model.building().map(|_| s.max_abs_slip);
        Ok(mechanisms
            .iter()
            .map(|&(k, capacity)| {
                let (theta, overturned) = block_response(s, k);
                RecordResponse {
                    max_displacement: (!overturned).then(|| capacity.displacement_at_rotation(theta)),
                    overturned,
                    max_slip,
                    max_seat_impulse_ratio: s.stack.as_ref().map(|stack| stack.max_seat_impulse_ratio),
                }
            })
            .collect())
    }
}

/// The largest `|θ_k|` (rad) of block `k` (0 the tower) over a run, and
/// whether its mechanism collapsed: block `k` or a block under it overturned.
fn block_response(summary: &rocking::Summary, k: usize) -> (f64, bool) {
    match &summary.stack {
        None => (summary.max_abs_theta(), summary.overturned()),
        Some(stack) => {
            let theta = if k == 0 {
                stack.tower().max_abs_theta
            } else {
                stack.blocks()[k - 1].max_abs_theta
            };
            (theta, stack.overturned_block.is_some_and(|fell| fell <= k))
        }
    }
}

/// Told after each record's run of a dynamic check (a progress bar's tick).
pub type Tick<'a> = &'a (dyn Fn() + Sync);

/// The most record runs of one dynamic check with `records` records and the
/// scan `lambda`: the set at λ = 1, at every λ of the scan, and at each step
/// of the bisection (a bracket no wider than the scan's step, its first λ,
/// or the gap from the scan's last λ below 1 up to 1, halved down to
/// [`LAMBDA_TOLERANCE`]). Fewer are run when the check holds
/// over the whole scan, or a record fails.
pub fn most_runs(records: usize, lambda: &LambdaScan) -> usize {
    most_runs_of(records, lambda, 1)
}

/// As [`most_runs`] for the checks of `mechanisms` mechanisms on the same
/// runs: the set at λ = 1 and the scan once, a bisection each.
pub fn most_runs_of(records: usize, lambda: &LambdaScan, mechanisms: usize) -> usize {
    let below_one = lambda.values().into_iter().filter(|&l| l < 1.0).fold(0.0, f64::max);
    let mut width = lambda.step.max(lambda.from).max(1.0 - below_one);
    let mut halvings = 0;
    while width > LAMBDA_TOLERANCE {
        width *= 0.5;
        halvings += 1;
    }
    records * (1 + lambda.values().len() + mechanisms * halvings)
}

/// A mechanism of a dynamic check: its block (0 the tower), its capacity and
/// its ultimate displacement `d_LS` of the check's limit state.
#[derive(Clone, Copy)]
struct Control<'a> {
    block: usize,
    capacity: &'a Capacity,
    d_ls: f64,
}

/// Runs of the set, one per (λ, record) pair in parallel: each run's responses, per mechanism.
/// Once `halted` is set the runs not yet begun are not run (each an error saying so).
fn runs(
    set: &RecordSet,
    scales: &[f64],
    lambdas: &[f64],
    controls: &[Control<'_>],
    tick: Tick<'_>,
    halted: &AtomicBool,
) -> Vec<Result<Vec<RecordResponse>, String>> {
    let n = scales.len();
    let mechanisms: Vec<(usize, &Capacity)> = controls.iter().map(|c| (c.block, c.capacity)).collect();
    (0..lambdas.len() * n)
        .into_par_iter()
        .map(|k| {
            if halted.load(Ordering::Relaxed) {
                return Err(HALTED.to_string());
            }
            let r = set.run_mechanisms(k % n, lambdas[k / n] * scales[k % n], &mechanisms);
            tick();
            r
        })
        .collect()
}

/// The error of a run that [`runs`] did not begin because it was halted.
const HALTED: &str = "stopped before it began";

/// The points of mechanism `m` of the runs at `lambdas` (in the order of [`runs`]).
fn points(runs: &[Result<Vec<RecordResponse>, String>], lambdas: &[f64], m: usize, rule: SetRule, control: Control<'_>) -> Vec<LambdaPoint> {
    let n = runs.len() / lambdas.len().max(1);
    lambdas
        .iter()
        .enumerate()
        .map(|(j, &lambda)| {
            let responses = runs[j * n..(j + 1) * n]
                .iter()
                .map(|r| r.as_ref().map(|all| all[m].clone()).map_err(Clone::clone))
                .collect();
            point(lambda, responses, rule, control.capacity, control.d_ls)
        })
        .collect()
}

fn point(lambda: f64, responses: Vec<Result<RecordResponse, String>>, rule: SetRule, capacity: &Capacity, d_ls: f64) -> LambdaPoint {
    let complete = responses.iter().all(Result::is_ok);
    let d: Vec<f64> = responses
        .iter()
        .filter_map(|r| r.as_ref().ok())
        .map(|r| r.displacement_or(capacity.d0))
        .collect();
    let combined = combined_response(&d, rule);
    let beyond = d.iter().any(|&x| x >= capacity.d0);
    LambdaPoint {
        lambda,
        responses,
        combined,
        holds: complete && !beyond && combined <= d_ls,
        complete,
    }
}

/// The non-linear dynamic check of the life-safety or collapse state `role`.
pub fn dynamic_check(input: &AssessmentInput, set: &RecordSet, capacity: &Capacity, role: Role) -> Result<DynamicCheck, Error> {
    dynamic_check_ticking(input, set, capacity, role, &|| {})
}

/// As [`dynamic_check`], `tick` told after each record's run (at most [`most_runs`]).
pub fn dynamic_check_ticking(input: &AssessmentInput, set: &RecordSet, capacity: &Capacity, role: Role, tick: Tick<'_>) -> Result<DynamicCheck, Error> {
    Ok(dynamic_checks_ticking(input, set, &[(0, capacity)], role, tick, &AtomicBool::new(false))?.remove(0))
}

/// The non-linear dynamic checks of the life-safety or collapse state `role`
/// of several mechanisms on the same runs, each `(k, capacity)` with its
/// control point block `k`'s θ (0 the tower), in order; `tick` told after
/// each record's run (at most [`most_runs_of`]). Once `halted` is set no
/// further run begins and the checks are left incomplete: the caller that
/// set it discards them.
pub fn dynamic_checks_ticking(
    input: &AssessmentInput,
    set: &RecordSet,
    mechanisms: &[(usize, &Capacity)],
    role: Role,
    tick: Tick<'_>,
    halted: &AtomicBool,
) -> Result<Vec<DynamicCheck>, Error> {
    let origin = input.origin();
    let spectrum = input.site.spectrum(role);
    let limit_state = input.site.limit_state(role);
    let d_ls = |c: &Capacity| match role {
        Role::LifeSafety => Ok(c.d_slv),
        Role::Collapse => Ok(c.d_slc),
        Role::Damage => Err(Fault::invalid("site", "the dynamic checks are of the life-safety and collapse states").in_file(origin)),
    };
    let controls = mechanisms
        .iter()
        .map(|&(block, capacity)| {
            Ok(Control {
                block,
                capacity,
                d_ls: d_ls(capacity)?,
            })
        })
        .collect::<Result<Vec<_>, Error>>()?;
    let target_g: Vec<f64> = set.periods.iter().map(|&t| spectrum.se(t)).collect();
    let floor_g = input
        .support
        .as_ref()
        .map(|s| {
            set.periods
                .iter()
                .map(|&t| crate::floor_spectrum_at(&spectrum, s.of(role), t, 5.0))
                .collect::<Result<Vec<f64>, _>>()
        })
        .transpose()
        .map_err(|e| Fault::invalid("support", e.to_string()).in_file(origin))?;
    let spectra: Vec<Vec<f64>> = set.records.iter().map(|r| r.psa_g.clone()).collect();
    let fitted_for_floor = |scales: &[f64]| -> Result<Option<Vec<f64>>, Error> {
        let Some(support) = &input.support else { return Ok(None) };
        let g = input.model().gravity();
        let mut mean = vec![0.0; set.periods.len()];
        for (r, scale) in set.records.iter().zip(scales) {
            let top = crate::support_top_motion(&r.record, support.of(role)).map_err(|e| Fault::invalid("support", e.to_string()).in_file(origin))?;
            let psa = rocking_codes::response_spectrum(&top, &set.periods, 5.0).map_err(|e| Fault::invalid("support", e.to_string()).in_file(origin))?;
            for (m, a) in mean.iter_mut().zip(psa) {
                *m += scale * a / g / scales.len() as f64;
            }
        }
        Ok(Some(mean))
    };
    let fitted =
        fit_record_set(&set.periods, &spectra, &target_g, set.range).map_err(|e| Fault::invalid("assessment.records", e.to_string()).in_file(origin))?;
    let rule = fitted.rule;
    let scales = fitted.scales.clone();
    let floor_mean_g = fitted_for_floor(&scales)?;
    // The set at λ = 1 and the scan: every (λ, record) pair in parallel, once for all mechanisms.
    let at_one_runs = runs(set, &scales, &[1.0], &controls, tick, halted);
    let lambdas = input.lambda.values();
    let scan_runs = runs(set, &scales, &lambdas, &controls, tick, halted);
    let ag = spectrum.ag();
    let incomplete = |p: &LambdaPoint| {
        p.responses
            .iter()
            .zip(&set.records)
            .find_map(|(r, rec)| r.as_ref().err().map(|e| format!("record {} at λ = {}: {e}", rec.path, p.lambda)))
    };
    let mut checks = Vec::with_capacity(controls.len());
    for (m, &control) in controls.iter().enumerate() {
        let at_one = points(&at_one_runs, &[1.0], m, rule, control).remove(0);
        let mut scan = points(&scan_runs, &lambdas, m, rule, control);
        let mut error = incomplete(&at_one);
        let mut bracket = None;
        let mut holds_at = 0.0;
        // The set at the site (λ = 1) is a point of the scan too: a failure
        // there below the scan's first failure brackets ζ_E under 1, so that a
        // scan ending without a failure is a lower bound that holds.
        let fails_at_one = at_one.complete && !at_one.holds;
        for p in &scan {
            if !p.complete {
                error = error.or_else(|| incomplete(p));
                break;
            }
            if fails_at_one && holds_at < 1.0 && p.lambda > 1.0 {
                bracket = Some((holds_at, 1.0));
                break;
            }
            if !p.holds {
                bracket = Some((holds_at, p.lambda));
                break;
            }
            holds_at = p.lambda;
        }
        if bracket.is_none() && error.is_none() && fails_at_one && holds_at < 1.0 {
            bracket = Some((holds_at, 1.0));
        }
        if let (Some((mut lo, mut hi)), None) = (bracket, &error) {
            while hi - lo > LAMBDA_TOLERANCE {
                let mid = 0.5 * (lo + hi);
                let p = points(&runs(set, &scales, &[mid], &[control], tick, halted), &[mid], 0, rule, control).remove(0);
                if !p.complete {
                    error = incomplete(&p);
                    break;
                }
                if p.holds {
                    lo = mid;
                } else {
                    hi = mid;
                }
                scan.push(p);
            }
            bracket = Some((lo, hi));
        }
        let check = error.is_none().then(|| {
            let ag_capacity = match bracket {
                Some((lo, _)) => AgCapacity::At(lo * ag),
                None => AgCapacity::AtLeast(input.lambda.to * ag),
            };
            Check::new(
                limit_state,
                Method::NonlinearDynamic,
                Unit::Displacement,
                at_one.combined,
                control.d_ls,
                ag,
                ag_capacity,
            )
        });
        checks.push(DynamicCheck {
            limit_state,
            target_g: target_g.clone(),
            floor_g: floor_g.clone(),
            floor_mean_g: floor_mean_g.clone(),
            fitted: fitted.clone(),
            at_one,
            scan,
            bracket,
            check,
            error,
            below_support: input.at_height(),
        });
    }
    Ok(checks)
}
