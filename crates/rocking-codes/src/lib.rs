//! # rocking-codes
//!
//! What the seismic codes ask of an assessment's input: the elastic spectra of
//! NTC 2018 (§3.2.3) and EN 1998-1 (§3.2.2), the site parameters of a limit
//! state from the NTC hazard grid (Allegato A), the response spectra of records
//! (exact for the piecewise-linear record, Nigam & Jennings 1969), and record
//! sets fitted to a code spectrum with the NTC compatibility check (§3.2.3.6).
//!
//! Units: periods in s, dampings in % of critical, site accelerations `ag` and
//! code spectra `Se` in g, displacement spectra in m; a record's response
//! spectrum is in the record's own units (m/s²).
//!
//! The transcendental functions are libm's, as in the engine: the same bits on
//! every target, so that the page (WebAssembly) gives the command's numbers.
//!
//! ```
//! use rocking_codes::{fit_record_set, response_spectrum, CodeSpectrum, NtcSite, NtcSpectrum, PeriodGrid, Soil, Topography};
//! use rocking::Record;
//!
//! // The SLV spectrum of a site on subsoil B, flat ground, at 5% damping.
//! let site = NtcSite::new(0.155, 2.47, 0.36)?;
//! let slv = CodeSpectrum::Ntc(NtcSpectrum::new(site, Soil::B, Topography::T1, 5.0)?);
//! assert!((slv.se(0.3) - 0.155 * 1.2 * 2.47).abs() < 1e-12); // the plateau ag S η F0, SS clamped at 1.20
//!
//! // Three records (here: 4 s of decaying harmonics), their spectra, the set fitted over 0.15–2 s.
//! let g = 9.81;
//! let records: Vec<Record> = [1.5, 2.5, 4.0]
//!     .iter()
//!     .map(|f: &f64| {
//!         let a = (0..800).map(|k| { let t = k as f64 * 0.005; (2.0 * std::f64::consts::PI * f * t).sin() * (-0.5 * t).exp() }).collect();
//!         Record::uniform(0.005, a)
//!     })
//!     .collect::<Result<_, _>>()?;
//! let periods = PeriodGrid { from: 0.02, to: 4.0, count: 100 }.periods()?;
//! let spectra = records.iter().map(|r| Ok(response_spectrum(r, &periods, 5.0)?.iter().map(|a| a / g).collect()))
//!     .collect::<Result<Vec<Vec<f64>>, rocking_codes::Error>>()?;
//! let target: Vec<f64> = periods.iter().map(|&t| slv.se(t)).collect();
//! let set = fit_record_set(&periods, &spectra, &target, (0.15, 2.0))?;
//! assert_eq!(set.scales.len(), 3);
//! println!("scales {:?}, mean/target in [{}, {}]", set.scales, set.compatibility.least_ratio, set.compatibility.greatest_ratio);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

mod code;
mod ec8;
mod elastic;
mod error;
mod fit;
mod floor;
mod grid;
mod hazard;
mod ntc;
mod oscillator;
mod response;

pub use code::{return_period, CodeSpectrum, LimitState};
pub use ec8::{ec8_parameters, Ec8Parameters, Ec8Spectrum, Ec8Type, EC8_AMPLIFICATION};
pub use elastic::{
    check_damping, damping_correction, displacement_corner_te, displacement_spectrum, DisplacementInputs, Soil, DISPLACEMENT_CORNER_TF, MAX_DAMPING_PCT,
};
pub use error::Error;
pub use fit::{
    compatibility, default_period_range, fit_record_set, fitted_scale, periods_in_range, set_rule, Compatibility, FittedSet, SetRule, COMPATIBILITY_LOWER,
    COMPATIBILITY_UPPER, DEFAULT_RANGE_FROM, DEFAULT_RANGE_TO, MIN_RECORDS, RECORDS_FOR_MEAN,
};
pub use floor::{
    ec8_floor_spectrum, floor_acceleration, floor_amplification, floor_spectrum, modal_floor_acceleration, modal_floor_spectrum, FLOOR_PLATEAU_END,
    FLOOR_PLATEAU_START,
};
pub use grid::{
    great_circle_distance_km, inverse_distance_weighting, log_log_interpolation, log_log_return_period, GridNode, HazardGrid, Island, ReturnPeriodOfAg,
    SiteHazard, EARTH_RADIUS_KM, GRID_RETURN_PERIODS, LATTICE_ROW,
};
pub use hazard::{
    power_law_frequency, power_law_segment_frequency, power_law_through, probability_in_period, standard_normal_cdf, surface_pga, HazardCurve, HazardPoint,
    LimitStateFrequency,
};
pub use ntc::{ntc_cc, ntc_corner_periods, ntc_ss, NtcSite, NtcSpectrum, Topography};
pub use oscillator::NigamJennings;
pub use response::{
    oscillator_response, pseudo_acceleration, response_spectrum, OscillatorResponse, PeriodGrid, DEFAULT_DAMPING_PCT, DEFAULT_PERIODS, MAX_PERIODS, MAX_STEPS,
};
