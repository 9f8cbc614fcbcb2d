//! # rocking-scenario
//!
//! Scenario files of the `rocking` simulator (docs/src/reference/keys.md):
//! TOML (or JSON) in, a validated [`rocking::Model`], ground motion, initial
//! state and settings out; a run gives an [`Outcome`] and its `summary.json`.
//! No printing, no command line: the `rocking` binary and the bindings use it.
//! A [`Sweep`] (docs/src/reference/keys.md, "[sweep]") runs every combination of values
//! of some keys in parallel, one [`Row`] per case in a fixed order. A
//! [`Study`] (README, "Fragility studies") runs a suite of records
//! scaled to levels of an intensity measure on the same engine, counts the
//! exceedances of its limit states ([`Tally`]) and fits lognormal fragility
//! curves ([`fit_fragility`]).
//!
//! ## Keys: what is required, what defaults
//!
//! | section | required | optional (default) |
//! |---|---|---|
//! | top level | | `name` (the file stem) |
//! | `[tower]` by geometry | `width`, `height`, `mass` or `density` | `depth` (= width), `section` ("solid"), `wall_thickness` (required for "hollow", refused for "solid"), `inertia_pivot` (the section's), `restitution` (Housner's), `points` (none) |
//! | `[tower]` by properties | `mass`, `inertia_pivot`, `radius`, `alpha` | `restitution`, `points` |
//! | `[building]` | `mass`, `mu_static` | `mu_kinetic` (= mu_static), `normal_force` ("constant") |
//! | `[ground]` | `type`; then per type below | |
//! | "harmonic" | `amplitude` or `amplitude_ratio`, `frequency` or `frequency_ratio` | `duration` (simulation.duration), `phase` (0) |
//! | "sine-pulse", "cosine-pulse" | amplitude, frequency (or their ratios) | |
//! | "ricker" | amplitude, frequency (or their ratios) | `t0` (1.5 / frequency) |
//! | "rectangular-pulse" | amplitude (or ratio), `duration` | |
//! | "record" | `file` (or `text`: the file's content) | `format` (guessed), `scale` (1), `units` ("g", CSV only), `dt` (CSV only) |
//! | "none" | | |
//! | `[initial]` | | `theta` or `theta_over_alpha` (0), `theta_dot` (0) |
//! | `[simulation]` | | `duration` (20 s), `g` (9.81), `output_dt` (0.005 s), `rtol` (1e-8), `atol` (1e-10) |
//!
//! `[ground]` is required, and so is a `[tower]` or a `[building]` (or both).
//! A key of another ground type, an unknown key or an unknown section is an error.
//!
//! ## Ranges beyond "a finite number > 0"
//!
//! Where the arithmetic or the integrator stops meaning anything, a value is
//! refused by its own key (the constants are in the library):
//!
//! - `simulation.rtol` in [2.2e-14, 1e-6] (100 machine epsilons, SciPy's
//!   floor for DOP853; above 1e-6 the impacts of `examples/tower-on-church.toml`
//!   move enough to change max θ/α by 50% at 3e-6 and 100% at 1e-4);
//!   `simulation.atol` in [1e-30, 1e-6] (rad, rad/s, m, m/s).
//! - `simulation.g` at most 1e3 m/s².
//! - lengths of `[tower]` in [1e-4, 1e5] m, masses of `[tower]` and
//!   `[building]` in [1e-6, 1e15] kg, `tower.density` in [1e-3, 1e5] kg/m³,
//!   `tower.inertia_pivot` in [1e-15, 1e26] kg·m².
//! - a harmonic of at most 1e6 cycles (`frequency` × `duration`); a peak
//!   ground acceleration (`amplitude`, or a record's peak times `scale`) of at
//!   most 100 g.
//! - a record file: a regular file (not a device or a pipe) of at most 640 MiB.
//! - a sweep: at most 1e6 cases unless `[sweep]` sets `max_cases`.
//!
//! Every error is one line naming the file, the dotted key and what is wrong:
//!
//! ```
//! use rocking_scenario::{summary_json, RunOptions, Scenario};
//! use std::path::Path;
//!
//! let text = r#"
//!     [tower]
//!     width = 4
//!     height = 12.0
//!     mass = 1.5e5
//!
//!     [ground]
//!     type = "sine-pulse"
//!     amplitude = 0.6   # g: above tan α = 1/3, the tower rocks
//!     frequency = 1.0
//!
//!     [simulation]
//!     duration = 3.0
//! "#;
//! let scenario = Scenario::from_toml_str(text, Path::new("block.toml"))?;
//! let outcome = scenario.build()?.run(RunOptions::SUMMARY)?;
//! let summary = summary_json(&outcome, 0.0);
//! assert!(summary["max_theta_over_alpha"].as_f64().is_some_and(|x| x > 0.0));
//! assert!(summary["max_abs_slip_m"].is_null()); // no building
//!
//! let bad = Scenario::from_toml_str(&text.replace("width = 4", "width = -4"), Path::new("block.toml"));
//! assert_eq!(bad.map(|_| ()).map_err(|e| e.to_string()), Err("block.toml: tower.width: must be a finite number > 0, got -4".to_string()));
//! # Ok::<(), rocking_scenario::Error>(())
//! ```

mod assessment;
mod block;
mod building;
pub mod columns;
mod dotted;
mod error;
pub mod file;
mod ground;
mod json;
mod keys;
mod read;
mod run;
mod scenario;
mod simulation;
mod study;
mod summary;
mod support;
mod sweep;
mod tower;

#[cfg(test)]
mod tests;

pub use assessment::{
    code_spectra_columns, dynamic_limit_states, kinematic_damping_pct, read_record, read_record_with, record_names, record_spectra_in_g, same_record_twice,
    AssessmentFile, Capacity, Code, GridCache, SetEntry, Site, SiteSource, SpectrumColumn, SpectrumKind, SupportState, VerdictMethod, ASSESSMENT_KEYS,
    ASSESSMENT_KEY_DOCS, ASSESSMENT_SECTIONS, DEFAULT_ASSESSMENT_FREE_AFTER, DEFAULT_CONFIDENCE_FACTOR, DEFAULT_LAMBDA, DEFAULT_NOMINAL_LIFE, DEFAULT_Q,
    DEFAULT_USE_COEFFICIENT, EC8_STATE_KEYS, KINEMATIC_DAMPING_COLLAPSE_PCT, KINEMATIC_DAMPING_LIFE_SAFETY_PCT, NTC_STATE_KEYS, OFFICIAL_GRID, SITE_KEYS,
    SUPPORT_STATE_KEYS,
};
pub use block::{names as block_names, set_named_key, BlockNames, BLOCK, MAX_ABOVE};
pub use dotted::{get_dotted, remove_dotted, set_dotted, DottedKeyError};
pub use error::{closest, key_of, one_line, Error, ErrorKind, Fault};
pub use ground::{record_format_name, GroundInfo, GroundKind, RecordCache, RecordInfo, ACCELERATION_UNITS};
pub use keys::{describe_key, keys_json, keys_markdown, named_block_keys, KeyDoc, KeyKind, KeyRef, SCENARIO_KEYS, VERTICAL_PREFIX};
pub use run::{Outcome, RunOptions};
pub use scenario::{parse_toml, Case, Scenario, SECTIONS, TOP_LEVEL_KEYS};
pub use simulation::{DEFAULT_DURATION, DEFAULT_G, DEFAULT_OUTPUT_DT, MAX_HISTORY_ROWS};
pub use study::{
    fit as fit_fragility, fit_until as fit_fragility_until, log_likelihood, pga, pgv, probability as fragility_probability, Fit, LimitState, Measure, Risk,
    Stripe, Study, StudyRecord, StudySite, Tally, Threshold, CASE_COLUMNS, DEFAULT_FREE_AFTER, FIFTY_YEARS, FRACTIONS_HEADER, FRAGILITY_HEADER, HAZARD_HEADER,
    INTERRUPTED as FIT_INTERRUPTED, METHOD as FIT_METHOD, RISK_HEADER, STUDY_KEYS,
};
pub use summary::{summary_fields, summary_json, summary_scalars};
pub use support::{Support, SupportMode, SupportShape, DEFAULT_SUPPORT_DAMPING, MAX_SUPPORT_MODES, SUPPORT_KEYS, SUPPORT_MODE_KEYS};
pub use sweep::{
    csv_line, run_cases, spreadsheet_text, Axis, AxisSpec, Cases, Cell, Finished, Row, RunError, Shard, Sweep, DEFAULT_MAX_CASES, ERROR_COLUMN,
    MAX_AXIS_VALUES, MAX_CASES_KEY, SWEEPABLE_KEYS, WALL_TIME_KEY, WINDOW,
};
pub use tower::{hinge_inset, STRESS_BLOCK_FACTOR};
