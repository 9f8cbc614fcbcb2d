//! The site of an assessment: the elastic spectrum (5% damping) of each of the
//! three limit states the checks read, of NTC 2018 (SLD, SLV, SLC) or of
//! EN 1998 (DL, SD, NC, which take their places).

use crate::error::{invalid, Error};
use rocking_codes::{CodeSpectrum, LimitState};

/// The part a limit state plays in the checks.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Role {
    /// Damage: SLD (NTC) or DL (EN 1998-3): the activation check.
    Damage,
    /// Life safety: SLV or SD: the linear and non-linear checks at `d_SLV`.
    LifeSafety,
    /// Collapse: SLC or NC: the non-linear checks at `d_SLC`.
    Collapse,
}

impl Role {
    /// The three, in the order of the checks.
    pub const ALL: [Role; 3] = [Role::Damage, Role::LifeSafety, Role::Collapse];

    /// The limit state of this role in the NTC (`ntc = true`) or EN 1998-3.
    pub fn limit_state(self, ntc: bool) -> LimitState {
        match (self, ntc) {
            (Role::Damage, true) => LimitState::Sld,
            (Role::LifeSafety, true) => LimitState::Slv,
            (Role::Collapse, true) => LimitState::Slc,
            (Role::Damage, false) => LimitState::Dl,
            (Role::LifeSafety, false) => LimitState::Sd,
            (Role::Collapse, false) => LimitState::Nc,
        }
    }
}

/// The elastic spectra (5% damping) of the damage, life-safety and collapse
/// limit states of one site, all of the same code.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Site {
    spectra: [CodeSpectrum; 3],
}

impl Site {
    /// The site of the three spectra (damage, life safety, collapse), each at 5%
    /// damping and all of the same code.
    pub fn new(damage: CodeSpectrum, life_safety: CodeSpectrum, collapse: CodeSpectrum) -> Result<Self, Error> {
        let spectra = [damage, life_safety, collapse];
        let ntc = matches!(damage, CodeSpectrum::Ntc(_));
        if spectra.iter().any(|s| matches!(s, CodeSpectrum::Ntc(_)) != ntc) {
            return Err(invalid("site", "the three limit states must be of the same code"));
        }
        if let Some(s) = spectra.iter().find(|s| (s.damping_pct() - 5.0).abs() > 1e-12) {
            return Err(invalid("site", format!("the site's spectra are at 5% damping, got {}%", s.damping_pct())));
        }
        Ok(Self { spectra })
    }

    /// Whether the site is of NTC 2018 (else EN 1998).
    pub fn is_ntc(&self) -> bool {
        matches!(self.spectra[0], CodeSpectrum::Ntc(_))
    }

    /// The spectrum (5%) of a role.
    pub fn spectrum(&self, role: Role) -> CodeSpectrum {
        self.spectra[role as usize]
    }

    /// The limit state of a role in this site's code.
    pub fn limit_state(&self, role: Role) -> LimitState {
        role.limit_state(self.is_ntc())
    }
}
