//! `[support]`: the elastic structure a tower stands on (the church under a
//! tower that rises from its roof, the shaft under a belfry), described by
//! its modes alone (without the tower and the blocks on it): each mode's
//! period, damping, participation `Γ_k` (the shape normalised to 1 where the
//! tower stands) and effective mass.
//!
//! ```toml
//! [support]
//! mass = 1.5e6        # kg, the support's whole mass
//! period = 0.35       # s, of the support alone
//! damping = 0.05      # fraction of critical (default 0.05)
//! shape = "sdof"      # "sdof" | "linear" | "cantilever": one mode's Γ and effective mass
//! # or its modes one by one (instead of period, damping, shape), at most 6:
//! # [[support.mode]]
//! # period = 0.35; damping = 0.05; participation = 1.566; effective_mass = 0.613
//! ```
//!
//! An assessment file takes it for the checks at height (the floor spectra of
//! the Circolare 2019, §C7.2.3); a scenario's run does not simulate it.

use crate::error::{ErrorKind, Fault};
use crate::read::{as_number, positive, with_article, Section};
use toml::{Table, Value};

/// The keys of `[support]`.
pub const SUPPORT_KEYS: &[&str] = &["mass", "period", "damping", "shape", "mode"];
/// The keys of each `[[support.mode]]`.
pub const SUPPORT_MODE_KEYS: &[&str] = &["period", "damping", "participation", "effective_mass"];
/// The damping of the support's modes when not given: 5% of critical.
pub const DEFAULT_SUPPORT_DAMPING: f64 = 0.05;
/// The most modes a support may have.
pub const MAX_SUPPORT_MODES: usize = 6;

/// One mode of the support alone.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SupportMode {
    /// `T_k` (s), > 0.
    pub period: f64,
    /// `ζ_k`, a fraction of critical in [0, 1).
    pub damping: f64,
    /// `Γ_k`, the shape normalised to 1 where the tower stands; not 0.
    pub participation: f64,
    /// `m_eff,k / m_s`, a fraction of the support's mass in (0, 1].
    pub effective_mass: f64,
}

/// A named shape of one mode (model: "An elastic support").
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SupportShape {
    /// A mass on a spring: `Γ = 1`, `m_eff = m_s`.
    Sdof,
    /// Uniform mass, shape `z/H`: `Γ = 1.5`, `m_eff = 0.75 m_s`.
    Linear,
    /// The first mode of a uniform Euler–Bernoulli cantilever: `Γ = 1.5660`, `m_eff = 0.6131 m_s`.
    Cantilever,
}

impl SupportShape {
    /// The shapes and their names, in the parser's order.
    pub const ALL: [(&'static str, SupportShape); 3] = [
        ("sdof", SupportShape::Sdof),
        ("linear", SupportShape::Linear),
        ("cantilever", SupportShape::Cantilever),
    ];

    /// Its name: `sdof`, `linear`, `cantilever`.
    pub fn as_str(self) -> &'static str {
        match self {
            SupportShape::Sdof => "sdof",
            SupportShape::Linear => "linear",
            SupportShape::Cantilever => "cantilever",
        }
    }

    /// `Γ` of the mode, the shape 1 at the top.
    pub fn participation(self) -> f64 {
        match self {
            SupportShape::Sdof => 1.0,
            // Shape z/H, uniform mass: L = m/2, M = m/3, Γ = L/M = 3/2.
            SupportShape::Linear => 1.5,
            // The first mode of a uniform cantilever, tip normalised to 1.
            SupportShape::Cantilever => 1.5660,
        }
    }

    /// `m_eff / m_s` of the mode.
    pub fn effective_mass(self) -> f64 {
        match self {
            SupportShape::Sdof => 1.0,
            // L²/M = (m/2)²/(m/3) = 3m/4.
            SupportShape::Linear => 0.75,
            SupportShape::Cantilever => 0.6131,
        }
    }
}

/// The support: its mass and its modes, validated.
#[derive(Debug, Clone, PartialEq)]
pub struct Support {
    /// `m_s` (kg), > 0.
    pub mass: f64,
    /// Its modes (1 to [`MAX_SUPPORT_MODES`]), in the order given.
    pub modes: Vec<SupportMode>,
    /// The named shape of its one mode, when given by `shape`.
    pub shape: Option<SupportShape>,
}

impl Support {
    /// The first period `T_1` (s): the longest of the modes'.
    pub fn first_period(&self) -> f64 {
        self.modes.iter().map(|m| m.period).fold(0.0, f64::max)
    }
}

/// A damping of the support: finite, in [0, 1).
fn damping(key: &str, value: f64) -> Result<f64, Fault> {
    if value.is_finite() && (0.0..1.0).contains(&value) {
        Ok(value)
    } else {
        Err(Fault::invalid(
            key,
            format!("must be a fraction of critical in [0, 1) (0.05 for 5%), got {value}"),
        ))
    }
}

/// Parses `[support]`.
pub(crate) fn parse(value: &Value) -> Result<Support, Fault> {
    let s = Section::new("support", value)?;
    s.only(SUPPORT_KEYS)?;
    let mass = positive("support.mass", s.required_number("mass", "the support's whole mass (kg)")?)?;
    let Some(modes) = s.get("mode") else {
        let period = positive(
            "support.period",
            s.required_number("period", "the support's period (s), or its modes as [[support.mode]]")?,
        )?;
        let damping = damping("support.damping", s.number("damping")?.unwrap_or(DEFAULT_SUPPORT_DAMPING))?;
        let shape = s.choice("shape", &SupportShape::ALL)?.unwrap_or(SupportShape::Sdof);
        return Ok(Support {
            mass,
            modes: vec![SupportMode {
                period,
                damping,
                participation: shape.participation(),
                effective_mass: shape.effective_mass(),
            }],
            shape: Some(shape),
        });
    };
    for k in ["period", "damping", "shape"] {
        if s.has(k) {
            return Err(Fault::new(
                format!("support.{k}"),
                ErrorKind::NotApplicable("is not taken with [[support.mode]]: give each mode's own keys (remove it)".into()),
            ));
        }
    }
    let Value::Array(items) = modes else {
        return Err(Fault::new(
            "support.mode",
            ErrorKind::WrongType {
                expected: "an array of tables ([[support.mode]])",
                got: with_article(modes),
            },
        ));
    };
    if items.is_empty() || items.len() > MAX_SUPPORT_MODES {
        return Err(Fault::invalid(
            "support.mode",
            format!("a support has 1 to {MAX_SUPPORT_MODES} modes, got {}", items.len()),
        ));
    }
    let modes = items
        .iter()
        .enumerate()
        .map(|(i, item)| parse_mode(i + 1, item))
        .collect::<Result<Vec<_>, _>>()?;
    let total: f64 = modes.iter().map(|m| m.effective_mass).sum();
    // A rounding's worth above 1 is the whole mass written in decimals (0.613 + 0.188 + …).
    if total > 1.0 + 1e-9 {
        return Err(Fault::invalid(
            "support.mode",
            format!("the modes' effective masses sum to {total} of the support's mass, more than 1"),
        ));
    }
    Ok(Support { mass, modes, shape: None })
}

/// Parses the `k`-th (1-based) `[[support.mode]]`.
fn parse_mode(k: usize, item: &Value) -> Result<SupportMode, Fault> {
    let prefix = format!("support.mode.{k}");
    let Value::Table(t) = item else {
        return Err(Fault::new(
            prefix,
            ErrorKind::WrongType {
                expected: "a table",
                got: with_article(item),
            },
        ));
    };
    if let Some(key) = t.keys().find(|key| !SUPPORT_MODE_KEYS.contains(&key.as_str())) {
        return Err(Fault::new(format!("{prefix}.{key}"), ErrorKind::unknown_key(key, SUPPORT_MODE_KEYS)));
    }
    let number = |t: &Table, key: &str| -> Result<Option<f64>, Fault> {
        match t.get(key) {
            None => Ok(None),
            Some(v) => as_number(v).map(Some).ok_or_else(|| {
                Fault::new(
                    format!("{prefix}.{key}"),
                    ErrorKind::WrongType {
                        expected: "a number",
                        got: with_article(v),
                    },
                )
            }),
        }
    };
    let required =
        |key: &str, what: &str| number(t, key)?.ok_or_else(|| Fault::new(format!("{prefix}.{key}"), ErrorKind::Missing(format!("required: {what}"))));
    let period = positive(&format!("{prefix}.period"), required("period", "the mode's period (s)")?)?;
    let damping = damping(&format!("{prefix}.damping"), number(t, "damping")?.unwrap_or(DEFAULT_SUPPORT_DAMPING))?;
    let participation = required("participation", "the mode's participation factor Γ (the shape 1 where the tower stands)")?;
    if !participation.is_finite() || participation == 0.0 {
        return Err(Fault::invalid(
            format!("{prefix}.participation"),
            format!("must be a finite number other than 0, got {participation}"),
        ));
    }
    let effective_mass = required("effective_mass", "the mode's effective mass, a fraction of the support's mass")?;
    if !(effective_mass.is_finite() && effective_mass > 0.0 && effective_mass <= 1.0) {
        return Err(Fault::invalid(
            format!("{prefix}.effective_mass"),
            format!("must be a fraction of the support's mass in (0, 1], got {effective_mass}"),
        ));
    }
    Ok(SupportMode {
        period,
        damping,
        participation,
        effective_mass,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse_text(text: &str) -> Result<Support, String> {
        let table: Table = text.parse().map_err(|e: toml::de::Error| e.to_string())?;
        let value = table.get("support").cloned().unwrap_or(Value::Table(Table::new()));
        parse(&value).map_err(|f| f.to_string())
    }

    #[test]
    fn one_mode_by_its_shape() {
        let s = parse_text("[support]\nmass = 1.5e6\nperiod = 0.35\nshape = \"cantilever\"\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.modes.len(), 1);
        assert_eq!(s.modes[0].participation.to_bits(), 1.5660f64.to_bits());
        assert_eq!(s.modes[0].effective_mass.to_bits(), 0.6131f64.to_bits());
        assert_eq!(s.modes[0].damping.to_bits(), 0.05f64.to_bits());
        assert_eq!(s.shape, Some(SupportShape::Cantilever));
        let sdof = parse_text("[support]\nmass = 1e6\nperiod = 0.3\n").unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((sdof.modes[0].participation, sdof.modes[0].effective_mass), (1.0, 1.0));
    }

    #[test]
    fn modes_by_hand() {
        let s = parse_text(
            "[support]\nmass = 1e6\n[[support.mode]]\nperiod = 0.5\nparticipation = 1.566\neffective_mass = 0.613\n\
             [[support.mode]]\nperiod = 0.08\ndamping = 0.1\nparticipation = -0.868\neffective_mass = 0.188\n",
        )
        .unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(s.modes.len(), 2);
        assert_eq!(s.modes[1].damping.to_bits(), 0.1f64.to_bits());
        assert_eq!(s.first_period().to_bits(), 0.5f64.to_bits());
    }

    #[test]
    fn refusals_name_the_key() {
        let e = |text: &str| parse_text(text).err().unwrap_or_default();
        assert!(e("[support]\nperiod = 0.3\n").starts_with("support.mass: required"));
        assert!(e("[support]\nmass = 1e6\nperiod = -0.3\n").starts_with("support.period: must be"));
        assert!(e("[support]\nmass = 1e6\nperiod = 0.3\ndamping = 1.0\n").starts_with("support.damping: must be a fraction"));
        assert!(e("[support]\nmass = 1e6\nperiod = 0.3\nshape = \"arch\"\n").starts_with("support.shape: \"arch\" is not one of"));
        assert!(e("[support]\nmass = 1e6\nperiods = 0.3\n").starts_with("support.periods: unknown key"));
        let mode = "[[support.mode]]\nperiod = 0.5\nparticipation = 1.2\neffective_mass = 0.6\n";
        assert!(e(&format!("[support]\nmass = 1e6\nshape = \"sdof\"\n{mode}")).starts_with("support.shape: is not taken with [[support.mode]]"));
        assert!(e(&format!("[support]\nmass = 1e6\n{mode}{mode}")).starts_with("support.mode: the modes' effective masses sum to 1.2"));
        assert!(e(&format!("[support]\nmass = 1e6\n{}", mode.repeat(7).replace("0.6", "0.1"))).starts_with("support.mode: a support has 1 to 6 modes, got 7"));
        assert!(e(&format!("[support]\nmass = 1e6\n{}", mode.replace("1.2", "0"))).starts_with("support.mode.1.participation: must be"));
        assert!(e("[support]\nmass = 1e6\n[[support.mode]]\nperiod = 0.5\neffective_mass = 0.6\n").starts_with("support.mode.1.participation: required"));
    }
}
