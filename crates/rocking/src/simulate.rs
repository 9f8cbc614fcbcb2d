//! The entry points of a run: its settings, the initial state, and
//! [`simulate`], which checks them and hands the run to the engine
//! (`engine/`).

use crate::equations::Kernel;
use crate::error::{positive, Error, Parameter};
use crate::ground::GroundMotion;
use crate::model::Model;
use crate::observer::Observer;
use crate::regime::{Pivot, TowerRegime};
use crate::response::Summary;
use std::f64::consts::FRAC_PI_2;

/// Angular velocity (rad/s) below which an impact ends the rocking: the
/// cascade of ever smaller impacts is cut there, in finite time.
pub const REST_ANGULAR_VELOCITY: f64 = 1e-9;

/// The model's end of accumulating impacts (impact → rest): an impact whose
/// angular velocity after it, `theta_dot_after` (rad/s), is below
/// [`REST_ANGULAR_VELOCITY`] sets its block down. The tower's impacts, the
/// building's slip after one and every interface of a stack ask it here.
/// The fall back of a grazing uplift (a block back slower than the
/// threshold while the input still lifts it) asks it of the velocity before
/// the impact, and sets the block down without the impact law: the same
/// threshold, read one instant earlier.
#[inline]
pub fn impact_ends_at_rest(theta_dot_after: f64) -> bool {
    theta_dot_after.abs() < REST_ANGULAR_VELOCITY
}

/// How long and how accurately to integrate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    /// Total simulated time (s), > 0.
    pub duration: f64,
    /// Relative tolerance of the integrator (default `1e-8`).
    pub rtol: f64,
    /// Absolute tolerance (rad, rad/s, m, m/s; default `1e-10`).
    pub atol: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            duration: 20.0,
            rtol: 1e-8,
            atol: 1e-10,
        }
    }
}

/// Tightest relative tolerance: 100 machine epsilons (SciPy's floor for its
/// DOP853); below it the error estimate is rounding noise.
pub const MIN_RTOL: f64 = 100.0 * f64::EPSILON;
/// Loosest relative tolerance. Measured on `examples/tower-on-church.toml`
/// (210 impacts): rtol 1e-6 gives the max θ/α of 1e-8 to 6 digits, 3e-6 is
/// already 46% off and 1e-4 twice as large; a looser run is not an answer.
pub const MAX_RTOL: f64 = 1e-6;
/// Tightest absolute tolerance (rad, rad/s, m, m/s): far below any motion of
/// a body of metres, and above the range where the error scale of a state at
/// rest (`atol` alone) underflows the error estimate.
pub const MIN_ATOL: f64 = 1e-30;
/// Loosest absolute tolerance: a micro-radian (or micrometre) of error per
/// step is already the size of the rotations an impact cascade leaves.
pub const MAX_ATOL: f64 = 1e-6;

impl Settings {
    /// Checks the settings: `duration > 0`, `rtol` in [[`MIN_RTOL`], [`MAX_RTOL`]],
    /// `atol` in [[`MIN_ATOL`], [`MAX_ATOL`]] (where DOP853's error control means
    /// something). [`simulate`] calls it; a front end may call it earlier.
    pub fn validate(&self) -> Result<(), Error> {
        positive(Parameter::Duration, self.duration)?;
        let rtol = positive(Parameter::RelativeTolerance, self.rtol)?;
        let atol = positive(Parameter::AbsoluteTolerance, self.atol)?;
        if !(MIN_RTOL..=MAX_RTOL).contains(&rtol) {
            return Err(Error::InvalidParameter {
                parameter: Parameter::RelativeTolerance,
                reason: format!(
                    "must be between {MIN_RTOL:.1e} (100 machine epsilons, below which the error estimate is rounding noise) and {MAX_RTOL:.0e} (beyond which impacts and slips are misplaced), got {rtol:e}"
                ),
            });
        }
        if !(MIN_ATOL..=MAX_ATOL).contains(&atol) {
            return Err(Error::InvalidParameter {
                parameter: Parameter::AbsoluteTolerance,
                reason: format!(
                    "must be between {MIN_ATOL:.0e} and {MAX_ATOL:.0e} (rad, rad/s, m, m/s; outside it the error control either cannot be met or no longer controls anything), got {atol:e}"
                ),
            });
        }
        Ok(())
    }
}

/// Initial rotation and angular velocity of the tower; the building starts at rest.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Initial {
    /// `θ(0)` (rad), `|θ| < π/2`.
    pub theta: f64,
    /// `θ̇(0)` (rad/s).
    pub theta_dot: f64,
}

/// Runs `model` under `ground` from `initial` and reports to `observer`. A
/// model with blocks on its tower ([`Model::with_blocks`]) runs as a stack:
/// the summary's tower quantities are the tower's (block 1), and
/// [`Summary::stack`] holds the blocks'; samples carry every block's state
/// ([`crate::Sample::stack`]) and events say whose they are ([`crate::Event::block`]).
pub fn simulate(model: &Model, ground: &GroundMotion, initial: Initial, settings: &Settings, observer: &mut impl Observer) -> Result<Summary, Error> {
    simulate_with_vertical(model, ground, None, initial, settings, observer)
}

/// Runs `model` under the horizontal `ground` and, if given, the vertical
/// ground acceleration `vertical` (`a_v`, positive upwards: the effective
/// gravity is `g + a_v`, docs/src/model.md, "Vertical ground acceleration"). Where
/// `g + a_v <= 0` the run stops with [`Error::FreeFall`] at that instant.
pub fn simulate_with_vertical(
    model: &Model,
    ground: &GroundMotion,
    vertical: Option<&GroundMotion>,
    initial: Initial,
    settings: &Settings,
    observer: &mut impl Observer,
) -> Result<Summary, Error> {
    settings.validate()?;
    crate::error::finite(Parameter::InitialTheta, initial.theta)?;
    crate::error::finite(Parameter::InitialThetaDot, initial.theta_dot)?;
    if initial.theta.abs() >= FRAC_PI_2 {
        return Err(Error::InvalidParameter {
            parameter: Parameter::InitialTheta,
            reason: format!("|θ| must be below π/2 (overturned), got {}", initial.theta),
        });
    }
    if let Some(stack) = model.stack() {
        return crate::stack::simulate(model, &stack, ground, vertical, initial, settings, observer);
    }
    let kernel = Kernel::new(model);
    if !kernel.has_tower && (initial.theta != 0.0 || initial.theta_dot != 0.0) {
        return Err(Error::InvalidParameter {
            parameter: Parameter::InitialTheta,
            reason: "an initial rotation needs a [tower]".into(),
        });
    }
    let tower = if initial.theta != 0.0 {
        TowerRegime::Rocking(Pivot::of_sign(initial.theta))
    } else if initial.theta_dot != 0.0 {
        TowerRegime::Rocking(Pivot::of_sign(initial.theta_dot))
    } else {
        TowerRegime::Rest
    };
    // Without a building the slip stays zero: integrate (θ, θ̇) only, which
    // halves the linear algebra of every step.
    if kernel.has_building {
        crate::engine::run::<_, 4>(&kernel, ground, vertical, settings, tower, initial, observer)
    } else {
        crate::engine::run::<_, 2>(&kernel, ground, vertical, settings, tower, initial, observer)
    }
}
