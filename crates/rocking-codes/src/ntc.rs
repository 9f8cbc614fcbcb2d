//! The horizontal elastic spectrum of NTC 2018 (D.M. 17 gennaio 2018,
//! §3.2.3.2.1) and its displacement spectrum (§3.2.3.2.3).
//!
//! Site parameters of a limit state: `ag` (g), `F0`, `Tc*` (s); the subsoil
//! category fixes the stratigraphic amplification `SS` and the coefficient `CC`
//! (Tab. 3.2.IV), the topographic category `ST` (Tab. 3.2.V); `S = SS ST`,
//! `TC = CC Tc*`, `TB = TC/3`, `TD = 4 ag/g + 1.6` s.

use crate::elastic::{check_damping, damping_correction, displacement_corner_te, displacement_spectrum, DisplacementInputs, Soil};
use crate::error::{invalid, positive, within, Error};
use std::fmt;
use std::str::FromStr;

/// The site parameters of one limit state (NTC 2018 §3.2, Allegato A).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NtcSite {
    /// Peak ground acceleration on rock `ag` (g), > 0.
    pub ag: f64,
    /// Maximum amplification of the spectrum on rock `F0`, > 0 (the grid's are 2.2–3.0).
    pub f0: f64,
    /// Period `Tc*` (s) at the start of the plateau's end on rock, > 0.
    pub tc_star: f64,
}

impl NtcSite {
    /// Checks each parameter: `ag` in (0, 2] g, `F0` and `Tc*` > 0.
    pub fn new(ag: f64, f0: f64, tc_star: f64) -> Result<Self, Error> {
        positive("ag", ag)?;
        within("ag", ag, 0.0, 2.0)?;
        positive("F0", f0)?;
        positive("Tc_star", tc_star)?;
        Ok(Self { ag, f0, tc_star })
    }
}

/// Topographic category (NTC 2018 §3.2.2, Tab. 3.2.III) or a given `ST`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Topography {
    /// Flat ground, slopes and isolated reliefs of mean inclination i ≤ 15°: ST = 1.0.
    T1,
    /// Slopes with i > 15°: ST = 1.2.
    T2,
    /// Ridges much narrower at the crest than at the base, 15° ≤ i ≤ 30°: ST = 1.2.
    T3,
    /// Ridges much narrower at the crest than at the base, i > 30°: ST = 1.4.
    T4,
    /// A given amplification `ST` in [1.0, 1.4] (e.g. on the flank, between the
    /// crest's value and 1 at the base).
    Factor(f64),
}

impl Topography {
    /// A given `ST`, checked: [1.0, 1.4].
    pub fn factor(st: f64) -> Result<Self, Error> {
        within("ST", st, 1.0, 1.4).map(Topography::Factor)
    }

    /// The topographic amplification `ST` (NTC 2018 §3.2.3.2.1, Tab. 3.2.V, at the crest).
    pub fn st(self) -> f64 {
        match self {
            Topography::T1 => 1.0,
            Topography::T2 | Topography::T3 => 1.2,
            Topography::T4 => 1.4,
            Topography::Factor(st) => st,
        }
    }
}

impl fmt::Display for Topography {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Topography::T1 => f.write_str("T1"),
            Topography::T2 => f.write_str("T2"),
            Topography::T3 => f.write_str("T3"),
            Topography::T4 => f.write_str("T4"),
            Topography::Factor(st) => write!(f, "ST = {st}"),
        }
    }
}

impl FromStr for Topography {
    type Err = Error;
    fn from_str(s: &str) -> Result<Self, Error> {
        match s.trim().to_ascii_uppercase().as_str() {
            "T1" => Ok(Topography::T1),
            "T2" => Ok(Topography::T2),
            "T3" => Ok(Topography::T3),
            "T4" => Ok(Topography::T4),
            _ => Err(invalid(
                "topography",
                format!("unknown category {s:?}: expected T1, T2, T3 or T4 (or a number ST)"),
            )),
        }
    }
}

/// The stratigraphic amplification `SS` (NTC 2018 §3.2.3.2.1, Tab. 3.2.IV), `ag` in g:
///
/// | A | B | C | D | E |
/// |---|---|---|---|---|
/// | 1.00 | 1.00 ≤ 1.40 − 0.40 F0 ag ≤ 1.20 | 1.00 ≤ 1.70 − 0.60 F0 ag ≤ 1.50 | 0.90 ≤ 2.40 − 1.50 F0 ag ≤ 1.80 | 1.00 ≤ 2.00 − 1.10 F0 ag ≤ 1.60 |
pub fn ntc_ss(soil: Soil, ag: f64, f0: f64) -> f64 {
    let (base, slope, low, high) = match soil {
        Soil::A => return 1.0,
        Soil::B => (1.40, 0.40, 1.00, 1.20),
        Soil::C => (1.70, 0.60, 1.00, 1.50),
        Soil::D => (2.40, 1.50, 0.90, 1.80),
        Soil::E => (2.00, 1.10, 1.00, 1.60),
    };
    (base - slope * f0 * ag).clamp(low, high)
}

/// The coefficient `CC` of the subsoil, `TC = CC Tc*` (NTC 2018 §3.2.3.2.1, Tab. 3.2.IV):
/// A 1.00, B 1.10 Tc*^−0.20, C 1.05 Tc*^−0.33, D 1.25 Tc*^−0.50, E 1.15 Tc*^−0.40.
pub fn ntc_cc(soil: Soil, tc_star: f64) -> f64 {
    match soil {
        Soil::A => 1.0,
        Soil::B => 1.10 * libm::pow(tc_star, -0.20),
        Soil::C => 1.05 * libm::pow(tc_star, -0.33),
        Soil::D => 1.25 * libm::pow(tc_star, -0.50),
        Soil::E => 1.15 * libm::pow(tc_star, -0.40),
    }
}

/// The corner periods `(TB, TC, TD)` (s) of the NTC 2018 spectrum (§3.2.3.2.1,
/// eqs. 3.2.7–3.2.9): `TC = CC Tc*`, `TB = TC / 3`, `TD = 4.0 ag/g + 1.6`.
pub fn ntc_corner_periods(cc: f64, tc_star: f64, ag: f64) -> (f64, f64, f64) {
    let tc = cc * tc_star;
    (tc / 3.0, tc, 4.0 * ag + 1.6)
}

/// The NTC 2018 horizontal elastic spectrum of one site and limit state at one damping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NtcSpectrum {
    site: NtcSite,
    soil: Soil,
    topography: Topography,
    damping_pct: f64,
    ss: f64,
    cc: f64,
    eta: f64,
    tb: f64,
    tc: f64,
    td: f64,
}

impl NtcSpectrum {
    /// The spectrum of `site` on `soil` and `topography`, at `damping_pct` (% of
    /// critical, [0, 100); the code's spectrum is at 5%).
    pub fn new(site: NtcSite, soil: Soil, topography: Topography, damping_pct: f64) -> Result<Self, Error> {
        let site = NtcSite::new(site.ag, site.f0, site.tc_star)?;
        if let Topography::Factor(st) = topography {
            Topography::factor(st)?;
        }
        let damping_pct = check_damping(damping_pct)?;
        let cc = ntc_cc(soil, site.tc_star);
        let (tb, tc, td) = ntc_corner_periods(cc, site.tc_star, site.ag);
        Ok(Self {
            site,
            soil,
            topography,
            damping_pct,
            ss: ntc_ss(soil, site.ag, site.f0),
            cc,
            eta: damping_correction(damping_pct),
            tb,
            tc,
            td,
        })
    }

    /// The same site at another damping (% of critical).
    pub fn with_damping(&self, damping_pct: f64) -> Result<Self, Error> {
        Self::new(self.site, self.soil, self.topography, damping_pct)
    }

    /// The same site with another `ag` (g), `F0`, `Tc*`, soil and topography kept:
    /// `SS` and `TD` move with it.
    pub fn with_ag(&self, ag: f64) -> Result<Self, Error> {
        Self::new(NtcSite { ag, ..self.site }, self.soil, self.topography, self.damping_pct)
    }

    /// The horizontal elastic spectrum `Se(T)` (g) at the period `T ≥ 0` (s)
    /// (NTC 2018 §3.2.3.2.1, eq. 3.2.2):
    ///
    /// ```text
    /// 0 ≤ T < TB:   Se = ag S η F0 [T/TB + (1 − T/TB) / (η F0)]
    /// TB ≤ T < TC:  Se = ag S η F0
    /// TC ≤ T < TD:  Se = ag S η F0 TC / T
    /// TD ≤ T:       Se = ag S η F0 TC TD / T²
    /// ```
    pub fn se(&self, period: f64) -> f64 {
        let plateau = self.plateau();
        let t = period;
        if t < self.tb {
            let x = t / self.tb;
            plateau * (x + (1.0 - x) / (self.eta * self.site.f0))
        } else if t < self.tc {
            plateau
        } else if t < self.td {
            plateau * self.tc / t
        } else {
            plateau * self.tc * self.td / (t * t)
        }
    }

    /// The elastic displacement spectrum `SDe(T)` (m) at `T ≥ 0` (s), gravity `g`
    /// (m/s²) turning `ag` into m/s² (NTC 2018 §3.2.3.2.3, eq. 3.2.13, Tab. 3.2.VII):
    /// the branches of [`displacement_spectrum`](crate::displacement_spectrum).
    pub fn sde(&self, period: f64, g: f64) -> f64 {
        displacement_spectrum(
            period,
            self.se(period) * g,
            &DisplacementInputs {
                ag_s: self.site.ag * g * self.s(),
                amplification: self.site.f0,
                eta: self.eta,
                tc: self.tc,
                td: self.td,
                te: displacement_corner_te(self.soil),
            },
        )
    }

    /// The plateau `ag S η F0` (g).
    pub fn plateau(&self) -> f64 {
        self.site.ag * self.s() * self.eta * self.site.f0
    }
    /// The site parameters.
    pub fn site(&self) -> NtcSite {
        self.site
    }
    /// The subsoil category.
    pub fn soil(&self) -> Soil {
        self.soil
    }
    /// The topographic category.
    pub fn topography(&self) -> Topography {
        self.topography
    }
    /// The damping (% of critical).
    pub fn damping_pct(&self) -> f64 {
        self.damping_pct
    }
    /// Stratigraphic amplification `SS`.
    pub fn ss(&self) -> f64 {
        self.ss
    }
    /// Topographic amplification `ST`.
    pub fn st(&self) -> f64 {
        self.topography.st()
    }
    /// `S = SS ST`.
    pub fn s(&self) -> f64 {
        self.ss * self.st()
    }
    /// `CC`.
    pub fn cc(&self) -> f64 {
        self.cc
    }
    /// Damping correction η.
    pub fn eta(&self) -> f64 {
        self.eta
    }
    /// `TB` (s).
    pub fn tb(&self) -> f64 {
        self.tb
    }
    /// `TC` (s).
    pub fn tc(&self) -> f64 {
        self.tc
    }
    /// `TD` (s).
    pub fn td(&self) -> f64 {
        self.td
    }
}
