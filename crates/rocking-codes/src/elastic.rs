//! What the NTC 2018 and EN 1998-1 elastic spectra share: the damping
//! correction η, the subsoil (ground type) categories A–E and the long-period
//! displacement spectrum.

use crate::error::{invalid, Error};
use std::f64::consts::PI;
use std::fmt;
use std::str::FromStr;

/// Dampings accepted, in percent of critical: `[0, MAX_DAMPING_PCT)`. The
/// response spectra need an underdamped oscillator; the codes' spectra are
/// written for small dampings, and η is bounded below by 0.55 (ξ ≥ 28%).
pub const MAX_DAMPING_PCT: f64 = 100.0;

/// The damping correction factor `η = max(0.55, sqrt(10 / (5 + ξ)))`, ξ in percent
/// (NTC 2018 §3.2.3.2.1, eq. 3.2.6; EN 1998-1 §3.2.2.2(3), eq. 3.6): 1 at 5%.
pub fn damping_correction(damping_pct: f64) -> f64 {
    (10.0 / (5.0 + damping_pct)).sqrt().max(0.55)
}

/// Checks a damping ratio given in percent of critical: `[0, 100)`.
pub fn check_damping(damping_pct: f64) -> Result<f64, Error> {
    if damping_pct.is_finite() && (0.0..MAX_DAMPING_PCT).contains(&damping_pct) {
        Ok(damping_pct)
    } else {
        Err(invalid("damping", format!("must be a percentage of critical in [0, 100), got {damping_pct}")))
    }
}

/// Subsoil category (NTC 2018 §3.2.2, Tab. 3.2.II) or ground type (EN 1998-1
/// §3.1.2, Table 3.1): A rock, B very dense sand or stiff clay, C dense to medium
/// sand or clay, D loose soil, E a shallow soft layer on rock.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Soil {
    /// Rock or very stiff ground (`vs,eq > 800 m/s`).
    A,
    /// Very dense sand, gravel or stiff clay (360–800 m/s).
    B,
    /// Dense or medium-dense sand, gravel or stiff clay (180–360 m/s).
    C,
    /// Loose-to-medium soil (100–180 m/s).
    D,
    /// A layer of C or D, at most 20 m thick (NTC: 30 m), on rock.
    E,
}

impl Soil {
    /// All five, in order.
    pub const ALL: [Soil; 5] = [Soil::A, Soil::B, Soil::C, Soil::D, Soil::E];

    /// The letter.
    pub fn as_str(self) -> &'static str {
        match self {
            Soil::A => "A",
            Soil::B => "B",
            Soil::C => "C",
            Soil::D => "D",
            Soil::E => "E",
        }
    }
}

impl fmt::Display for Soil {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for Soil {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        Soil::ALL
            .into_iter()
            .find(|c| c.as_str().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| invalid("soil", format!("unknown category {s:?}: expected A, B, C, D or E")))
    }
}

/// The period `TE` (s) where the displacement spectrum leaves `Se (T/2π)²`:
/// 4.5 s (A), 5.0 s (B), 6.0 s (C, D, E) (NTC 2018 §3.2.3.2.3, Tab. 3.2.VII;
/// EN 1998-1 Annex A, Table A.1).
pub fn displacement_corner_te(soil: Soil) -> f64 {
    match soil {
        Soil::A => 4.5,
        Soil::B => 5.0,
        Soil::C | Soil::D | Soil::E => 6.0,
    }
}

/// The period `TF` (s) beyond which the displacement spectrum is the peak ground
/// displacement `dg`: 10 s for every soil (NTC 2018 Tab. 3.2.VII; EN 1998-1 Table A.1).
pub const DISPLACEMENT_CORNER_TF: f64 = 10.0;

/// The quantities of an elastic acceleration spectrum the displacement spectrum needs.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DisplacementInputs {
    /// `ag S` (m/s²).
    pub ag_s: f64,
    /// The plateau's amplification: `F0` (NTC) or 2.5 (EN 1998-1).
    pub amplification: f64,
    /// η.
    pub eta: f64,
    /// `TC` (s).
    pub tc: f64,
    /// `TD` (s).
    pub td: f64,
    /// `TE` (s).
    pub te: f64,
}

/// The elastic displacement spectrum `SDe(T)` (m) from the acceleration spectrum
/// `se` (m/s²) at `T` (NTC 2018 §3.2.3.2.3, eq. 3.2.13 and Tab. 3.2.VII; EN 1998-1
/// Annex A, with 2.5 in place of F0):
///
/// ```text
/// T ≤ TE:        SDe = Se(T) (T / 2π)²
/// TE < T ≤ TF:   SDe = 0.025 ag S TC TD [F0 η + (1 − F0 η)(T − TE)/(TF − TE)]
/// T > TF:        SDe = dg = 0.025 ag S TC TD
/// ```
pub fn displacement_spectrum(period: f64, se: f64, d: &DisplacementInputs) -> f64 {
    let dg = 0.025 * d.ag_s * d.tc * d.td;
    let tf = DISPLACEMENT_CORNER_TF;
    if period <= d.te {
        se * (period / (2.0 * PI)).powi(2)
    } else if period <= tf {
        let f0_eta = d.amplification * d.eta;
        dg * (f0_eta + (1.0 - f0_eta) * (period - d.te) / (tf - d.te))
    } else {
        dg
    }
}
