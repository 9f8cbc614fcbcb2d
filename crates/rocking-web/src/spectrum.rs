//! A record's response spectrum for the page: the pseudo-acceleration
//! spectrum of the scenario's horizontal record, as `rocking spectrum RECORD`
//! computes it (Nigam & Jennings, exact for the piecewise-linear record, at the
//! command's default periods), and the record itself for its time history.

use rocking::GroundMotion;
use rocking_codes::{check_damping, DEFAULT_PERIODS};
use rocking_scenario::record_spectra_in_g;
use serde_json::json;
use wasm_bindgen::prelude::*;

/// The response spectrum of the scenario's record (`scenario`: JSON text, its
/// `[ground]` a record given as `text`) at `damping_pct` (% of critical): the
/// JSON text of `{ damping_pct, periods_s, psa_g, pga_g, pga_time_s,
/// peak_psa_g, peak_period_s, t_s, a_g }`, the spectrum at the 100 log-spaced
/// periods of 0.02–4 s of `rocking spectrum` and the record as the run reads it
/// (scaled, in g). The record and `g` are the scenario's, so that a record
/// with `scale = 1` in g gives the command's numbers bit for bit.
pub fn record_spectrum_json(scenario: &str, damping_pct: f64) -> Result<String, String> {
    let case = crate::scenario(scenario)?.build().map_err(|e| e.to_string())?;
    let GroundMotion::Record(record) = &case.ground else {
        return Err(format!(
            "{}: ground.type: a response spectrum is a record's: set ground.type = \"record\"",
            crate::ORIGIN
        ));
    };
    let damping = check_damping(damping_pct).map_err(|e| format!("damping: {}", reason(&e)))?;
    let periods = DEFAULT_PERIODS.periods().map_err(|e| e.to_string())?;
    let g = case.model.gravity();
    let psa = record_spectra_in_g(std::slice::from_ref(record), &periods, damping, g)
        .map_err(|e| e.to_string())?
        .remove(0);
    let (k, peak) = psa.iter().enumerate().fold((0, 0.0f64), |best, (k, &v)| if v > best.1 { (k, v) } else { best });
    let (pga, pga_time) = record.peak();
    Ok(json!({
        "damping_pct": damping,
        "periods_s": periods,
        "psa_g": psa,
        "pga_g": pga / g,
        "pga_time_s": pga_time,
        "peak_psa_g": peak,
        "peak_period_s": periods[k],
        "t_s": record.times(),
        "a_g": record.values().iter().map(|a| a / g).collect::<Vec<f64>>(),
    })
    .to_string())
}

/// What a library error says, without the parameter's own name (the page names its field).
fn reason(e: &rocking_codes::Error) -> String {
    match e {
        rocking_codes::Error::InvalidParameter { reason, .. } => reason.clone(),
        other => other.to_string(),
    }
}

/// See [`record_spectrum_json`].
#[wasm_bindgen(js_name = recordSpectrum)]
pub fn record_spectrum(scenario: &str, damping_pct: f64) -> Result<String, JsError> {
    record_spectrum_json(scenario, damping_pct).map_err(|e| JsError::new(&e))
}
