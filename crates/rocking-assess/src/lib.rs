//! # rocking-assess
//!
//! The assessment of a tower to the code: its capacity as one rigid block
//! overturning on its springing level and the checks of the Circolare 21
//! gennaio 2019 n. 7 (§C8.7.1.2.1, local mechanisms) with the spectra of
//! NTC 2018 or EN 1998-1: the activation of the mechanism (damage state), the
//! linear kinematic check with the behaviour factor q (life safety: q times
//! the activation's capacity), the
//! non-linear kinematic checks on the displacement spectrum (life safety,
//! collapse). Each check gives the least `ag` at which it stops holding and
//! `ζ_E = a_g,capacity / a_g`. The verdict of the life-safety and collapse
//! states is carried by one method each ([`verdicts`]): the one the file names,
//! else the most refined computed; the damage state's activation is reported
//! beside it.
//!
//! A town's towers are assessed the same way, one row of a CSV each, by
//! [`Inventory`] (`rocking inventory`), their GeoJSON and ranking by [`Town`].
//!
//! Units: lengths in m, spectral accelerations in m/s², site accelerations
//! `ag` in g, periods in s.
//!
//! ```
//! use rocking_assess::{kinematic_checks, verdict, Capacity, CurveKind, Site};
//! use rocking_codes::{CodeSpectrum, NtcSite, NtcSpectrum, Soil, Topography};
//!
//! // A tower 4 m wide and 12 m tall (b = 2 m, h = 6 m), 150 t, FC = 1.35.
//! let capacity = Capacity::new(1.5e5, 40f64.sqrt(), (1.0f64 / 3.0).atan(), 9.81, 1.35, CurveKind::Linear)?;
//! assert!((capacity.a0_star - 9.81 / 3.0 / 1.35).abs() < 1e-12);
//! assert!((capacity.d0 - 2.0).abs() < 1e-12);
//!
//! // Its site on subsoil B, flat ground.
//! let state = |ag, f0, tc| -> Result<CodeSpectrum, rocking_codes::Error> {
//!     Ok(CodeSpectrum::Ntc(NtcSpectrum::new(NtcSite::new(ag, f0, tc)?, Soil::B, Topography::T1, 5.0)?))
//! };
//! let site = Site::new(state(0.062, 2.52, 0.30)?, state(0.155, 2.47, 0.36)?, state(0.196, 2.50, 0.37)?)?;
//! let checks = kinematic_checks(&capacity, &site, 2.0)?;
//! // The verdict: of SLV and SLC, the worse by the most refined method computed
//! // (here the non-linear kinematic one); the SLD's activation is reported beside it.
//! let worst = verdict(&checks, None).expect("an ultimate limit state").check;
//! assert_eq!(worst.method, rocking_assess::Method::NonlinearKinematic);
//! println!("{} {}: ζ_E = {:.2}", worst.limit_state, worst.method, worst.zeta_e);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod assess;
mod capacity;
mod check;
mod dynamic;
mod error;
mod height;
mod input;
mod inventory;
mod kinematic;
mod outputs;
mod search;
mod site;
mod town;

pub use assess::{Assessment, BlockMechanism, Direction, MechanismView};
pub use capacity::{
    activation_acceleration, activation_multiplier, collapse_displacement, exact_acceleration_at, exact_capacity_curve, linear_capacity_curve,
    rigid_column_centre, secant_period_slc, secant_period_slv, ultimate_displacement_slc, ultimate_displacement_slv, Capacity, CurveKind,
    DEFAULT_CONFIDENCE_FACTOR,
};
pub use check::{acceleration_ratio, least_zeta_e, verdict, verdicts, Check, Level, Method, MethodText, Unit, Verdict};
pub use dynamic::{
    combined_response, dynamic_check, dynamic_check_ticking, dynamic_checks_ticking, most_runs, most_runs_of, set_periods, DynamicCheck, LambdaPoint,
    RecordResponse, RecordSet, SetRecord, Tick, LAMBDA_TOLERANCE,
};
pub use error::Error;
pub use height::{
    activation_check_at_height, first_period, floor_displacement_demand, floor_spectrum_at, kinematic_checks_at_height, linear_kinematic_check_at_height,
    nonlinear_kinematic_check_at_height, peak_floor_acceleration, support_top_motion, SupportModes, EC8_HEIGHT_RATIO,
};
pub use input::{AssessmentInput, LambdaScan, MAX_LAMBDA, MAX_LAMBDA_VALUES};
pub use inventory::{calling_pool, Inventory, InventoryError, OnAssessed};
pub use kinematic::{
    activation_check, activation_demand, check_q, corner_periods, displacement_demand, kinematic_checks, linear_kinematic_capacity, linear_kinematic_check,
    linear_kinematic_demand, nonlinear_kinematic_check, soil_factor, DEFAULT_Q, NONLINEAR_DAMPING_COLLAPSE_PCT, NONLINEAR_DAMPING_LIFE_SAFETY_PCT,
};
pub use outputs::{
    assessment_json, capacity_csv, capacity_json, check_json, d0_meaning, dynamic_check_json, dynamic_json, records_csv, spectra_csv, spectrum_json,
    support_json, verdict_json, Quantity, CAPACITY_HEADER, CAPACITY_POINTS, CAPACITY_QUANTITIES, RECORDS_HEADER, SEAT_IMPULSE_COLUMN,
};
pub use search::{least_failing_ag, AgCapacity, AG_SCAN_STEP, AG_SEARCH_TOP};
pub use site::{Role, Site};
pub use town::{
    decimals, degrees, ranking, rounded, shapefile_aliases, shapefile_safe, Ranked, Town, AG_DECIMALS, DEGREE_DECIMALS, IDENTITY, LOWER_BOUND,
    SHAPEFILE_NAME_MAX, ZETA_DECIMALS,
};
