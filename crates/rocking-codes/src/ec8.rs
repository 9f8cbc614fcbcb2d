//! The horizontal elastic spectrum of EN 1998-1:2004 (§3.2.2.2) and its
//! displacement spectrum (Annex A).
//!
//! `ag = γI agR` (g) on ground type A; the ground type and the spectrum type
//! (1: large earthquakes, Ms > 5.5; 2: smaller ones) fix `S`, `TB`, `TC`, `TD`
//! (Tables 3.2 and 3.3, the recommended values).

use crate::elastic::{check_damping, damping_correction, displacement_corner_te, displacement_spectrum, DisplacementInputs, Soil};
use crate::error::{invalid, positive, within, Error};

/// The spectrum type of EN 1998-1 §3.2.2.2(2).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Ec8Type {
    /// Type 1: the earthquakes that contribute most to the hazard have Ms > 5.5.
    Type1,
    /// Type 2: Ms ≤ 5.5.
    Type2,
}

impl Ec8Type {
    /// From the number 1 or 2.
    pub fn from_number(n: f64) -> Result<Self, Error> {
        if (n - 1.0).abs() < f64::EPSILON {
            Ok(Ec8Type::Type1)
        } else if (n - 2.0).abs() < f64::EPSILON {
            Ok(Ec8Type::Type2)
        } else {
            Err(invalid("spectrum_type", format!("must be 1 or 2, got {n}")))
        }
    }
    /// 1 or 2.
    pub fn number(self) -> u8 {
        match self {
            Ec8Type::Type1 => 1,
            Ec8Type::Type2 => 2,
        }
    }
}

/// The soil factor and corner periods of a ground type.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8Parameters {
    /// Soil factor `S`.
    pub s: f64,
    /// `TB` (s).
    pub tb: f64,
    /// `TC` (s).
    pub tc: f64,
    /// `TD` (s).
    pub td: f64,
}

/// `S`, `TB`, `TC`, `TD` of a ground type and spectrum type (EN 1998-1 §3.2.2.2,
/// Table 3.2 for type 1, Table 3.3 for type 2, the recommended values).
pub fn ec8_parameters(soil: Soil, kind: Ec8Type) -> Ec8Parameters {
    let (s, tb, tc, td) = match (kind, soil) {
        (Ec8Type::Type1, Soil::A) => (1.00, 0.15, 0.4, 2.0),
        (Ec8Type::Type1, Soil::B) => (1.20, 0.15, 0.5, 2.0),
        (Ec8Type::Type1, Soil::C) => (1.15, 0.20, 0.6, 2.0),
        (Ec8Type::Type1, Soil::D) => (1.35, 0.20, 0.8, 2.0),
        (Ec8Type::Type1, Soil::E) => (1.40, 0.15, 0.5, 2.0),
        (Ec8Type::Type2, Soil::A) => (1.00, 0.05, 0.25, 1.2),
        (Ec8Type::Type2, Soil::B) => (1.35, 0.05, 0.25, 1.2),
        (Ec8Type::Type2, Soil::C) => (1.50, 0.10, 0.25, 1.2),
        (Ec8Type::Type2, Soil::D) => (1.80, 0.10, 0.30, 1.2),
        (Ec8Type::Type2, Soil::E) => (1.60, 0.05, 0.25, 1.2),
    };
    Ec8Parameters { s, tb, tc, td }
}

/// The plateau's amplification of EN 1998-1 (2.5), the place of NTC's `F0`.
pub const EC8_AMPLIFICATION: f64 = 2.5;

/// The EN 1998-1 horizontal elastic spectrum of one site and limit state at one damping.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Ec8Spectrum {
    ag: f64,
    soil: Soil,
    kind: Ec8Type,
    damping_pct: f64,
    eta: f64,
    parameters: Ec8Parameters,
}

impl Ec8Spectrum {
    /// The spectrum of design ground acceleration `ag = γI agR` (g, in (0, 2]) on
    /// `soil`, of spectrum type `kind`, at `damping_pct` (% of critical, [0, 100)).
    pub fn new(ag: f64, soil: Soil, kind: Ec8Type, damping_pct: f64) -> Result<Self, Error> {
        positive("ag", ag)?;
        within("ag", ag, 0.0, 2.0)?;
        let damping_pct = check_damping(damping_pct)?;
        Ok(Self {
            ag,
            soil,
            kind,
            damping_pct,
            eta: damping_correction(damping_pct),
            parameters: ec8_parameters(soil, kind),
        })
    }

    /// The same site at another damping (% of critical).
    pub fn with_damping(&self, damping_pct: f64) -> Result<Self, Error> {
        Self::new(self.ag, self.soil, self.kind, damping_pct)
    }

    /// The same site with another `ag` (g).
    pub fn with_ag(&self, ag: f64) -> Result<Self, Error> {
        Self::new(ag, self.soil, self.kind, self.damping_pct)
    }

    /// The horizontal elastic spectrum `Se(T)` (g) at `T ≥ 0` (s) (EN 1998-1
    /// §3.2.2.2, eqs. 3.2–3.5):
    ///
    /// ```text
    /// 0 ≤ T ≤ TB:   Se = ag S [1 + T/TB (2.5 η − 1)]
    /// TB ≤ T ≤ TC:  Se = 2.5 ag S η
    /// TC ≤ T ≤ TD:  Se = 2.5 ag S η TC / T
    /// TD ≤ T:       Se = 2.5 ag S η TC TD / T²
    /// ```
    pub fn se(&self, period: f64) -> f64 {
        let Ec8Parameters { s, tb, tc, td } = self.parameters;
        let t = period;
        let plateau = self.plateau();
        if t < tb {
            self.ag * s * (1.0 + t / tb * (EC8_AMPLIFICATION * self.eta - 1.0))
        } else if t < tc {
            plateau
        } else if t < td {
            plateau * tc / t
        } else {
            plateau * tc * td / (t * t)
        }
    }

    /// The elastic displacement spectrum `SDe(T)` (m) at `T ≥ 0` (s), gravity `g`
    /// (m/s²) (EN 1998-1 Annex A): the branches of
    /// [`displacement_spectrum`](crate::displacement_spectrum) with 2.5 for F0.
    pub fn sde(&self, period: f64, g: f64) -> f64 {
        let p = self.parameters;
        displacement_spectrum(
            period,
            self.se(period) * g,
            &DisplacementInputs {
                ag_s: self.ag * g * p.s,
                amplification: EC8_AMPLIFICATION,
                eta: self.eta,
                tc: p.tc,
                td: p.td,
                te: displacement_corner_te(self.soil),
            },
        )
    }

    /// The plateau `2.5 ag S η` (g).
    pub fn plateau(&self) -> f64 {
        EC8_AMPLIFICATION * self.ag * self.parameters.s * self.eta
    }
    /// `ag` (g).
    pub fn ag(&self) -> f64 {
        self.ag
    }
    /// The ground type.
    pub fn soil(&self) -> Soil {
        self.soil
    }
    /// The spectrum type.
    pub fn kind(&self) -> Ec8Type {
        self.kind
    }
    /// The damping (% of critical).
    pub fn damping_pct(&self) -> f64 {
        self.damping_pct
    }
    /// Damping correction η.
    pub fn eta(&self) -> f64 {
        self.eta
    }
    /// `S`, `TB`, `TC`, `TD`.
    pub fn parameters(&self) -> Ec8Parameters {
        self.parameters
    }
}
