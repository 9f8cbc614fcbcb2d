//! `[simulation]` and `[initial]`: how long and how finely to run, and the
//! tower's initial state.

use crate::error::{ErrorKind, Fault};
use crate::read::{finite, positive, Section};
use rocking::{Initial, Settings, Tower};
use std::f64::consts::FRAC_PI_2;

/// Default simulated time (s).
pub const DEFAULT_DURATION: f64 = 20.0;
/// Default gravity (m/s²).
pub const DEFAULT_G: f64 = 9.81;
/// Default spacing of history rows (s).
pub const DEFAULT_OUTPUT_DT: f64 = 0.005;
/// At most this many history rows, so that a tiny `output_dt` cannot exhaust memory.
pub const MAX_HISTORY_ROWS: f64 = 1e7;

/// The run's settings, gravity and the history spacing.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct SimulationSpec {
    pub(crate) settings: Settings,
    pub(crate) g: f64,
    pub(crate) output_dt: f64,
}

/// `[simulation]`, every key optional; `None` for an absent section.
pub(crate) fn parse(s: Option<&Section<'_>>) -> Result<SimulationSpec, Fault> {
    let defaults = Settings::default();
    let Some(s) = s else {
        return Ok(SimulationSpec {
            settings: Settings {
                duration: DEFAULT_DURATION,
                ..defaults
            },
            g: DEFAULT_G,
            output_dt: DEFAULT_OUTPUT_DT,
        });
    };
    s.only_scenario_keys()?;
    let value = |key: &str, default: f64| -> Result<f64, Fault> { Ok(s.number(key)?.unwrap_or(default)) };
    // Duration and tolerances are checked by the library (one set of rules and
    // messages); gravity by `Model::new`. Only the history spacing is this crate's.
    let settings = Settings {
        duration: value("duration", DEFAULT_DURATION)?,
        rtol: value("rtol", defaults.rtol)?,
        atol: value("atol", defaults.atol)?,
    };
    settings.validate()?;
    let duration = settings.duration;
    let output_dt = positive(&s.key("output_dt"), value("output_dt", DEFAULT_OUTPUT_DT)?)?;
    let rows = duration / output_dt;
    if rows > MAX_HISTORY_ROWS {
        return Err(Fault::invalid(
            s.key("output_dt"),
            format!("{output_dt} s over a duration of {duration} s gives {rows:.3e} history rows, more than {MAX_HISTORY_ROWS:.0e}"),
        ));
    }
    Ok(SimulationSpec {
        settings,
        g: value("g", DEFAULT_G)?,
        output_dt,
    })
}

/// `[initial]`: `theta` (rad) or `theta_over_alpha`, and `theta_dot` (rad/s); default at rest.
pub(crate) fn parse_initial(s: Option<&Section<'_>>, tower: Option<&Tower>) -> Result<Initial, Fault> {
    let Some(s) = s else { return Ok(Initial::default()) };
    s.only_scenario_keys()?;
    s.exclusive("theta", "theta_over_alpha")?;
    let (theta_key, theta) = match (s.number("theta")?, s.number("theta_over_alpha")?) {
        (Some(theta), _) => ("theta", finite(&s.key("theta"), theta)?),
        (None, Some(ratio)) => {
            let key = s.key("theta_over_alpha");
            let ratio = finite(&key, ratio)?;
            let tower = tower.ok_or_else(|| Fault::new(&key, ErrorKind::NotApplicable("needs a [tower]: it is a multiple of the tower's α".into())))?;
            ("theta_over_alpha", ratio * tower.alpha())
        }
        (None, None) => ("theta", 0.0),
    };
    if theta.abs() >= FRAC_PI_2 {
        return Err(Fault::invalid(
            s.key(theta_key),
            format!("the initial rotation must be below π/2 = {FRAC_PI_2} rad in magnitude (the tower would lie flat), got {theta} rad"),
        ));
    }
    let theta_dot = finite(&s.key("theta_dot"), s.number("theta_dot")?.unwrap_or(0.0))?;
    if tower.is_none() {
        let moving = [(theta_key, theta), ("theta_dot", theta_dot)].into_iter().find(|&(_, v)| v.abs() > 0.0);
        if let Some((key, _)) = moving {
            return Err(Fault::new(s.key(key), ErrorKind::NotApplicable("an initial rotation needs a [tower]".into())));
        }
    }
    Ok(Initial { theta, theta_dot })
}
