//! A code spectrum of either code, and the limit states it is given for.

use crate::ec8::Ec8Spectrum;
use crate::error::{invalid, Error};
use crate::ntc::NtcSpectrum;
use std::fmt;
use std::str::FromStr;

/// The elastic spectrum of a site and limit state, of NTC 2018 or of EN 1998-1.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum CodeSpectrum {
    /// NTC 2018 §3.2.3.2.
    Ntc(NtcSpectrum),
    /// EN 1998-1 §3.2.2.2.
    Ec8(Ec8Spectrum),
}

impl CodeSpectrum {
    /// `Se(T)` (g) at `T ≥ 0` (s).
    pub fn se(&self, period: f64) -> f64 {
        match self {
            CodeSpectrum::Ntc(s) => s.se(period),
            CodeSpectrum::Ec8(s) => s.se(period),
        }
    }
    /// `SDe(T)` (m) at `T ≥ 0` (s), gravity `g` (m/s²).
    pub fn sde(&self, period: f64, g: f64) -> f64 {
        match self {
            CodeSpectrum::Ntc(s) => s.sde(period, g),
            CodeSpectrum::Ec8(s) => s.sde(period, g),
        }
    }
    /// The same site at another damping (% of critical, [0, 100)).
    pub fn with_damping(&self, damping_pct: f64) -> Result<Self, Error> {
        Ok(match self {
            CodeSpectrum::Ntc(s) => CodeSpectrum::Ntc(s.with_damping(damping_pct)?),
            CodeSpectrum::Ec8(s) => CodeSpectrum::Ec8(s.with_damping(damping_pct)?),
        })
    }
    /// The same site with another `ag` (g), every other site parameter kept.
    pub fn with_ag(&self, ag: f64) -> Result<Self, Error> {
        Ok(match self {
            CodeSpectrum::Ntc(s) => CodeSpectrum::Ntc(s.with_ag(ag)?),
            CodeSpectrum::Ec8(s) => CodeSpectrum::Ec8(s.with_ag(ag)?),
        })
    }
    /// `ag` (g).
    pub fn ag(&self) -> f64 {
        match self {
            CodeSpectrum::Ntc(s) => s.site().ag,
            CodeSpectrum::Ec8(s) => s.ag(),
        }
    }
    /// The damping (% of critical).
    pub fn damping_pct(&self) -> f64 {
        match self {
            CodeSpectrum::Ntc(s) => s.damping_pct(),
            CodeSpectrum::Ec8(s) => s.damping_pct(),
        }
    }
}

/// A limit state: NTC 2018 §3.2.1 (SLO, SLD, SLV, SLC) or EN 1998-3 §2.1 (DL,
/// SD, NC, which take the places of SLD, SLV, SLC).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum LimitState {
    /// Operativity (SLO), P_VR = 81%.
    Slo,
    /// Damage (SLD), P_VR = 63%.
    Sld,
    /// Life safety (SLV), P_VR = 10%.
    Slv,
    /// Collapse prevention (SLC), P_VR = 5%.
    Slc,
    /// EN 1998-3 Damage Limitation.
    Dl,
    /// EN 1998-3 Significant Damage.
    Sd,
    /// EN 1998-3 Near Collapse.
    Nc,
}

impl LimitState {
    /// The NTC 2018 limit states, in order.
    pub const NTC: [LimitState; 4] = [LimitState::Slo, LimitState::Sld, LimitState::Slv, LimitState::Slc];
    /// The EN 1998-3 limit states, in order.
    pub const EC8: [LimitState; 3] = [LimitState::Dl, LimitState::Sd, LimitState::Nc];

    /// Its abbreviation: `SLV`, `NC`.
    pub fn as_str(self) -> &'static str {
        match self {
            LimitState::Slo => "SLO",
            LimitState::Sld => "SLD",
            LimitState::Slv => "SLV",
            LimitState::Slc => "SLC",
            LimitState::Dl => "DL",
            LimitState::Sd => "SD",
            LimitState::Nc => "NC",
        }
    }

    /// The probability `P_VR` of exceedance in the reference period (NTC 2018
    /// §3.2.1, Tab. 3.2.I): 0.81 (SLO), 0.63 (SLD), 0.10 (SLV), 0.05 (SLC);
    /// `None` for the EN 1998-3 states, whose return periods are national choices.
    pub fn probability_of_exceedance(self) -> Option<f64> {
        match self {
            LimitState::Slo => Some(0.81),
            LimitState::Sld => Some(0.63),
            LimitState::Slv => Some(0.10),
            LimitState::Slc => Some(0.05),
            LimitState::Dl | LimitState::Sd | LimitState::Nc => None,
        }
    }
}

impl fmt::Display for LimitState {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

impl FromStr for LimitState {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        LimitState::NTC
            .into_iter()
            .chain(LimitState::EC8)
            .find(|l| l.as_str().eq_ignore_ascii_case(s.trim()))
            .ok_or_else(|| {
                invalid(
                    "limit_state",
                    format!("unknown limit state {s:?}: expected SLO, SLD, SLV, SLC (NTC) or DL, SD, NC (EC8)"),
                )
            })
    }
}

/// The return period `TR = −VR / ln(1 − P_VR)` (years) of a probability `P_VR` of
/// exceedance in the reference period `VR = VN · CU` (years) (NTC 2018 §3.2.1 and
/// Allegato A; VN nominal life, §2.4.1; CU the class of use's coefficient, §2.4.3).
pub fn return_period(nominal_life: f64, use_coefficient: f64, probability: f64) -> f64 {
    let reference_period = nominal_life * use_coefficient;
    -reference_period / libm::log(1.0 - probability)
}
