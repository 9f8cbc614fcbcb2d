//! The whole assessment of a file: the capacity, the kinematic checks and,
//! with a record set, the dynamic checks; what `rocking assess` writes and
//! `rocking.assess` returns.

use crate::capacity::Capacity;
use crate::check::{verdict, verdicts, Check, Method, Verdict};
use crate::dynamic::{dynamic_checks_ticking, most_runs_of, DynamicCheck, RecordSet};
use crate::input::AssessmentInput;
use crate::outputs::{assessment_json, capacity_csv, check_json, records_csv, spectra_csv, support_json, verdict_json};
use crate::site::Role;
use rocking_scenario::{Error, RecordCache};
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Mutex, PoisonError};

/// The outcome of an assessment.
#[derive(Debug, Clone)]
pub struct Assessment {
    /// The tower's capacity (with blocks on it, the whole stack turning as one).
    pub capacity: Capacity,
    /// The tower's kinematic checks: activation, linear, non-linear (life safety, collapse).
    pub checks: Vec<Check>,
    /// The record set, if the file has one.
    pub set: Option<RecordSet>,
    /// The tower's dynamic checks (life safety, collapse), with a record set.
    pub dynamic: Vec<DynamicCheck>,
    /// The mechanism of each block on the tower, the lowest first (none for a tower alone).
    pub blocks: Vec<BlockMechanism>,
    /// The method named to carry the verdict (`assessment.verdict_method`);
    /// `None`: the most refined computed.
    pub verdict_method: Option<Method>,
    /// Whether a dynamic check on an incompatible set may carry the verdict (`assessment.accept_incompatible_set`).
    pub accept_incompatible_set: bool,
    /// The principal direction of these checks.
    pub direction: Direction,
    /// The assessment in the other principal direction (every body turned a
    /// quarter), when a body's depth differs from its width
    /// ([`AssessmentInput::turned`]); the verdict is the worse of the two.
    pub turned: Option<Box<Assessment>>,
}

/// A principal direction of the tower's plan.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Direction {
    /// The file's: rocking across each body's `width` (in the plane of the width).
    Width,
    /// The other: rocking across each body's `depth` (the bodies turned a quarter).
    Depth,
}

impl Direction {
    /// `"width"` or `"depth"`: the dimension the body rocks across.
    pub fn as_str(self) -> &'static str {
        match self {
            Self::Width => "width",
            Self::Depth => "depth",
        }
    }
}

/// The mechanism of a block on the tower (the belfry on its shaft): the block
/// and those above it turning as one rigid body about a corner of its base.
/// Its kinematic checks take the ground's spectra for the motion of the
/// shaft's top: the tower and the building are rigid, so that while the
/// tower stands (and the building sticks) its top moves with the ground.
#[derive(Debug, Clone)]
pub struct BlockMechanism {
    /// The block's name.
    pub name: String,
    /// Its position above the tower (1 the first).
    pub block: usize,
    /// Its capacity.
    pub capacity: Capacity,
    /// Its kinematic checks, as the tower's.
    pub checks: Vec<Check>,
    /// Its dynamic checks, on the tower's runs, its own θ the control point.
    pub dynamic: Vec<DynamicCheck>,
}

/// A mechanism's name, capacity and checks: the tower's or a block's.
#[derive(Debug, Clone, Copy)]
pub struct MechanismView<'a> {
    /// `"tower"` or the block's name.
    pub name: &'a str,
    /// 0 for the tower, else the block's position above it.
    pub block: usize,
    /// Its capacity.
    pub capacity: &'a Capacity,
    /// Its kinematic checks.
    pub checks: &'a [Check],
    /// Its dynamic checks.
    pub dynamic: &'a [DynamicCheck],
    /// Whether a dynamic check on an incompatible set may carry its verdict.
    pub accept_incompatible_set: bool,
    /// The principal direction it rocks in.
    pub direction: Direction,
}

impl Assessment {
    /// Runs every check of `input` (the dynamic ones on rayon's current pool).
    pub fn run(input: &AssessmentInput) -> Result<Self, Error> {
        Self::run_cached(input, &RecordCache::with_capacity(input.file.records.len()))
    }

    /// As [`Assessment::run`], the records taken from `cache` when read before
    /// (one read of each record file for all the towers of an inventory).
    pub fn run_cached(input: &AssessmentInput, cache: &RecordCache) -> Result<Self, Error> {
        Self::run_observed(input, cache, &|_, _| {})
    }

    /// As [`Assessment::run_cached`], `progress(done, most)` told after each
    /// record's run of the dynamic checks, in order (`done` is 1, 2, 3, …):
    /// the runs done, and the most there can be ([`most_runs`] of each check).
    pub fn run_observed(input: &AssessmentInput, cache: &RecordCache, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Self, Error> {
        let done = Self::run_until(input, cache, progress, &AtomicBool::new(false))?;
        Ok(done.expect("an assessment never halted ends"))
    }

    /// As [`Assessment::run_observed`], stopped once `halted` is set (Ctrl-C
    /// in the Python package): no record's run begins after it, and the
    /// assessment is `None`, whatever it had done.
    ///
    /// A tower whose depth differs from its width (or a block's) is assessed
    /// in both principal directions, the file's first; the progress counts
    /// the runs of both.
    pub fn run_until(
        input: &AssessmentInput,
        cache: &RecordCache,
        progress: &(dyn Fn(usize, usize) + Sync),
        halted: &AtomicBool,
    ) -> Result<Option<Self>, Error> {
        let told = AtomicUsize::new(0);
        let first = |done: usize, most: usize| {
            told.store(done, Ordering::Relaxed);
            progress(done, most);
        };
        let Some(mut done) = Self::run_direction(input, cache, &first, halted, Direction::Width)? else {
            return Ok(None);
        };
        if let Some(turned) = input.turned()? {
            let before = told.load(Ordering::Relaxed);
            let then = |done: usize, most: usize| progress(before + done, before + most);
            match Self::run_direction(&turned, cache, &then, halted, Direction::Depth)? {
                Some(other) => done.turned = Some(Box::new(other)),
                None => return Ok(None),
            }
        }
        Ok(Some(done))
    }

    /// The assessment of `input` in one principal `direction`.
    fn run_direction(
        input: &AssessmentInput,
        cache: &RecordCache,
        progress: &(dyn Fn(usize, usize) + Sync),
        halted: &AtomicBool,
        direction: Direction,
    ) -> Result<Option<Self>, Error> {
        let capacity = input.capacity()?;
        let checks = input.kinematic_checks(&capacity)?;
        let mut blocks = (1..=input.blocks().len())
            .map(|k| {
                let capacity = input.block_capacity(k)?;
                Ok(BlockMechanism {
                    name: input.blocks().name(k).to_string(),
                    block: k,
                    checks: input.kinematic_checks(&capacity)?,
                    capacity,
                    dynamic: Vec::new(),
                })
            })
            .collect::<Result<Vec<_>, Error>>()?;
        let (set, dynamic) = if input.file.records.is_empty() {
            (None, Vec::new())
        } else {
            // One fitting range for every mechanism: stretched to the longest T_SLC.
            let set = RecordSet::read_cached(input, input.longest_t_slc()?, cache)?;
            let roles = [Role::LifeSafety, Role::Collapse];
            let mechanisms: Vec<(usize, &Capacity)> = std::iter::once((0, &capacity)).chain(blocks.iter().map(|b| (b.block, &b.capacity))).collect();
            let most = roles.len() * most_runs_of(set.records.len(), &input.lambda, mechanisms.len());
            // Counted and told under one lock, so that the counts are told in
            // order even when two runs end at once (a progress bar never
            // steps back).
            let done = Mutex::new(0);
            let tick = || {
                let mut done = done.lock().unwrap_or_else(PoisonError::into_inner);
                *done += 1;
                progress(*done, most);
            };
            let mut per_role = roles
                .into_iter()
                .map(|role| dynamic_checks_ticking(input, &set, &mechanisms, role, &tick, halted))
                .collect::<Result<Vec<_>, _>>()?;
            // Regrouped by mechanism: the tower's first, then each block's.
            let mut by_mechanism: Vec<Vec<DynamicCheck>> = (0..mechanisms.len()).map(|_| Vec::new()).collect();
            for checks in &mut per_role {
                for (m, check) in checks.drain(..).enumerate() {
                    by_mechanism[m].push(check);
                }
            }
            let mut by_mechanism = by_mechanism.into_iter();
            let tower = by_mechanism.next().unwrap_or_default();
            for (block, dynamic) in blocks.iter_mut().zip(by_mechanism) {
                block.dynamic = dynamic;
            }
            (Some(set), tower)
        };
        if halted.load(Ordering::Relaxed) {
            return Ok(None);
        }
        Ok(Some(Self {
            capacity,
            checks,
            set,
            dynamic,
            blocks,
            verdict_method: input.verdict_method(),
            accept_incompatible_set: input.file.accept_incompatible_set,
            direction,
            turned: None,
        }))
    }

    /// Every mechanism: the tower's, then each block's.
    pub fn mechanisms(&self) -> Vec<MechanismView<'_>> {
        let tower = MechanismView {
            name: "tower",
            block: 0,
            capacity: &self.capacity,
            checks: &self.checks,
            dynamic: &self.dynamic,
            accept_incompatible_set: self.accept_incompatible_set,
            direction: self.direction,
        };
        std::iter::once(tower)
            .chain(self.blocks.iter().map(|b| MechanismView {
                name: &b.name,
                block: b.block,
                capacity: &b.capacity,
                checks: &b.checks,
                dynamic: &b.dynamic,
                accept_incompatible_set: self.accept_incompatible_set,
                direction: self.direction,
            }))
            .collect()
    }

    /// Every mechanism in both principal directions: this direction's, then the turned one's.
    pub fn mechanisms_both_ways(&self) -> Vec<MechanismView<'_>> {
        let mut all = self.mechanisms();
        if let Some(turned) = &self.turned {
            all.extend(turned.mechanisms());
        }
        all
    }

    /// The governing mechanism and its verdict: the least ζ_E of every
    /// mechanism's [`MechanismView::verdict`] in both principal directions
    /// (the tower's first and the file's direction first, so that they
    /// govern a tie). The damage state's activation is not part of it.
    pub fn governing_verdict(&self) -> Option<(MechanismView<'_>, Verdict)> {
        self.mechanisms_both_ways()
            .into_iter()
            .filter_map(|m| m.verdict(self.verdict_method).map(|v| (m, v)))
            .reduce(|best, x| if x.1.check.zeta_e < best.1.check.zeta_e { x } else { best })
    }

    /// The governing mechanism and check: [`Assessment::governing_verdict`]'s.
    pub fn governing_mechanism(&self) -> Option<(MechanismView<'_>, Check)> {
        self.governing_verdict().map(|(m, v)| (m, v.check))
    }

    /// Every completed check of every mechanism, the tower's first, each
    /// mechanism's kinematic ones before its dynamic ones.
    pub fn completed(&self) -> Vec<Check> {
        self.mechanisms().iter().flat_map(MechanismView::completed).collect()
    }

    /// The governing check: the verdict of least ζ_E of every mechanism.
    pub fn governing(&self) -> Option<Check> {
        self.governing_mechanism().map(|(_, c)| c)
    }

    /// The damage state's check that governs, reported beside the verdict:
    /// the activation of least ζ_E of every mechanism (the tower's first).
    pub fn damage(&self) -> Option<(MechanismView<'_>, Check)> {
        self.mechanisms_both_ways()
            .into_iter()
            .filter_map(|m| m.checks.iter().find(|c| c.method == Method::Activation).map(|c| (m, *c)))
            .reduce(|best, x| if x.1.zeta_e < best.1.zeta_e { x } else { best })
    }

    /// The record set and the tower's dynamic checks, if any.
    pub fn dynamic_part(&self) -> Option<(&RecordSet, &[DynamicCheck])> {
        self.set.as_ref().map(|s| (s, self.dynamic.as_slice()))
    }

    /// `assessment.json`. With blocks on the tower, `mechanisms` holds each
    /// mechanism's `name`, `block` (0 the tower), `capacity`, `checks`
    /// (kinematic, then dynamic) and `dynamic`, the tower's first (its own are
    /// the top-level ones too), and `governing` names its `mechanism`.
    pub fn json(&self, input: &AssessmentInput) -> serde_json::Value {
        let mut out = assessment_json(
            input.name(),
            &self.capacity,
            &input.site,
            &self.checks,
            self.dynamic_part(),
            (self.verdict_method, self.accept_incompatible_set),
        );
        // With a [support], the support's modes at each limit state.
        if let (Some(support), serde_json::Value::Object(map)) = (&input.support, &mut out) {
            let values = |state| {
                let v = input.file.support_state(state);
                (v.period_factor, v.damping)
            };
            map.insert("support".into(), support_json(&input.site, support, &values));
        }
        if self.blocks.is_empty() && self.turned.is_none() {
            return out;
        }
        let mechanisms: Vec<serde_json::Value> = self
            .mechanisms()
            .iter()
            .map(|m| {
                let dynamic = self.set.as_ref().map(|set| (set, m.dynamic));
                let one = assessment_json(
                    input.name(),
                    m.capacity,
                    &input.site,
                    m.checks,
                    dynamic,
                    (self.verdict_method, self.accept_incompatible_set),
                );
                serde_json::json!({
                    "name": m.name,
                    "block": m.block,
                    "capacity": one["capacity"],
                    "checks": one["checks"],
                    "governing": one["governing"],
                    "verdicts": one["verdicts"],
                    "damage": one["damage"],
                    "dynamic": one["dynamic"],
                })
            })
            .collect();
        if let serde_json::Value::Object(map) = &mut out {
            if !self.blocks.is_empty() {
                map.insert("mechanisms".into(), serde_json::Value::Array(mechanisms));
            }
            if let Some(turned) = &self.turned {
                // The turned bodies have this input's name and site: only their plan differs.
                map.insert("direction".into(), serde_json::json!(self.direction.as_str()));
                map.insert("other_direction".into(), turned.json(input));
            }
            // The governing verdict and damage check of every mechanism (in both directions), named.
            let both = self.turned.is_some();
            let named = |found: Option<(MechanismView<'_>, serde_json::Value)>| {
                found.map_or(serde_json::Value::Null, |(m, mut g)| {
                    if let serde_json::Value::Object(g) = &mut g {
                        g.insert("mechanism".into(), serde_json::json!(m.name));
                        if both {
                            g.insert("direction".into(), serde_json::json!(m.direction.as_str()));
                        }
                    }
                    g
                })
            };
            map.insert("governing".into(), named(self.governing_verdict().map(|(m, v)| (m, verdict_json(&v)))));
            map.insert("damage".into(), named(self.damage().map(|(m, c)| (m, check_json(&c)))));
        }
        out
    }

    /// `capacity.csv`.
    pub fn capacity_csv(&self) -> String {
        capacity_csv(&self.capacity)
    }

    /// `records.csv` and `spectra.csv`, with a record set.
    pub fn set_csvs(&self) -> Option<(String, String)> {
        let blocks: Vec<(&str, &[DynamicCheck])> = self.blocks.iter().map(|b| (b.name.as_str(), b.dynamic.as_slice())).collect();
        self.set
            .as_ref()
            .map(|s| (records_csv(s, &self.dynamic, &blocks), spectra_csv(s, &self.dynamic)))
    }
}

impl MechanismView<'_> {
    /// Its completed checks, the kinematic ones first.
    pub fn completed(&self) -> Vec<Check> {
        let mut all = self.checks.to_vec();
        all.extend(self.dynamic.iter().filter_map(|d| d.check));
        all
    }

    /// The checks that may carry its verdict: the kinematic ones and the
    /// completed dynamic ones on a compatible set (or on any, when accepted:
    /// [`DynamicCheck::verdict_check`]).
    pub fn verdict_candidates(&self) -> Vec<Check> {
        let mut all = self.checks.to_vec();
        all.extend(self.dynamic.iter().filter_map(|d| d.verdict_check(self.accept_incompatible_set)));
        all
    }

    /// The verdict of each of its ultimate limit states ([`verdicts`]), `named` the method named to carry it.
    pub fn verdicts(&self, named: Option<Method>) -> Vec<Verdict> {
        verdicts(&self.verdict_candidates(), named)
    }

    /// Its verdict: the least ζ_E of its limit states' ([`verdict`]).
    pub fn verdict(&self, named: Option<Method>) -> Option<Verdict> {
        verdict(&self.verdict_candidates(), named)
    }
}
