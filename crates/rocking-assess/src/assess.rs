//! The whole assessment of a file: the capacity, the kinematic checks and,
//! with a record set, the dynamic checks; what `rocking assess` writes and
//! `rocking.assess` returns.

use crate::capacity::Capacity;
use crate::check::{governing, Check};
use crate::dynamic::{dynamic_check_ticking, most_runs, DynamicCheck, RecordSet};
use crate::input::AssessmentInput;
use crate::outputs::{assessment_json, capacity_csv, records_csv, spectra_csv};
use crate::site::Role;
use rocking_scenario::{Error, RecordCache};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The outcome of an assessment.
#[derive(Debug, Clone)]
pub struct Assessment {
    /// The tower's capacity.
    pub capacity: Capacity,
    /// The kinematic checks: activation, linear, non-linear (life safety, collapse).
    pub checks: Vec<Check>,
    /// The record set, if the file has one.
    pub set: Option<RecordSet>,
    /// The dynamic checks (life safety, collapse), with a record set.
    pub dynamic: Vec<DynamicCheck>,
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
    /// record's run of the dynamic checks: the runs done, and the most there
    /// can be ([`most_runs`] of each check).
    pub fn run_observed(input: &AssessmentInput, cache: &RecordCache, progress: &(dyn Fn(usize, usize) + Sync)) -> Result<Self, Error> {
        let capacity = input.capacity()?;
        let checks = input.kinematic_checks(&capacity)?;
        let (set, dynamic) = if input.file.records.is_empty() {
            (None, Vec::new())
        } else {
            let set = RecordSet::read_cached(input, capacity.t_slc, cache)?;
            let roles = [Role::LifeSafety, Role::Collapse];
            let most = roles.len() * most_runs(set.records.len(), &input.lambda);
            let done = AtomicUsize::new(0);
            let tick = || progress(done.fetch_add(1, Ordering::Relaxed) + 1, most);
            let dynamic = roles
                .into_iter()
                .map(|role| dynamic_check_ticking(input, &set, &capacity, role, &tick))
                .collect::<Result<Vec<_>, _>>()?;
            (Some(set), dynamic)
        };
        Ok(Self {
            capacity,
            checks,
            set,
            dynamic,
        })
    }

    /// Every completed check, the kinematic ones first.
    pub fn completed(&self) -> Vec<Check> {
        let mut all = self.checks.clone();
        all.extend(self.dynamic.iter().filter_map(|d| d.check));
        all
    }

    /// The governing check: the least ζ_E of the completed checks.
    pub fn governing(&self) -> Option<Check> {
        governing(&self.completed()).copied()
    }

    /// The record set and the dynamic checks, if any.
    pub fn dynamic_part(&self) -> Option<(&RecordSet, &[DynamicCheck])> {
        self.set.as_ref().map(|s| (s, self.dynamic.as_slice()))
    }

    /// `assessment.json`.
    pub fn json(&self, input: &AssessmentInput) -> serde_json::Value {
        assessment_json(input.name(), &self.capacity, &input.site, &self.checks, self.dynamic_part())
    }

    /// `capacity.csv`.
    pub fn capacity_csv(&self) -> String {
        capacity_csv(&self.capacity)
    }

    /// `records.csv` and `spectra.csv`, with a record set.
    pub fn set_csvs(&self) -> Option<(String, String)> {
        self.set.as_ref().map(|s| (records_csv(s, &self.dynamic), spectra_csv(s, &self.dynamic)))
    }
}
