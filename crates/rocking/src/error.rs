//! Errors of the library: invalid input (caught when a model is built) and
//! numerical failures (during a run).

/// Everything that can go wrong in building a model or running it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is outside its valid range; `parameter` is which one, `reason` what is wrong.
    #[error("{parameter}: {reason}")]
    InvalidParameter {
        /// The parameter at fault (a front end maps it to the name its user wrote).
        parameter: Parameter,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A ground-motion record could not be read.
    #[error(transparent)]
    Record(#[from] crate::RecordError),
    /// The integrator could not make progress.
    #[error("integration failed at t = {time} s: step size too small")]
    StepSizeTooSmall {
        /// Time (s) where the step size collapsed.
        time: f64,
    },
    /// The right-hand side became non-finite (a singular coupled system, e.g. a
    /// Painlevé configuration of the dynamic normal force).
    #[error("integration failed at t = {time} s: {reason}")]
    Singular {
        /// Time (s) of the failure.
        time: f64,
        /// What became singular.
        reason: String,
    },
    /// Regime switches piled up at one instant without the motion advancing.
    #[error("regime switches do not settle at t = {time} s (last: {last})")]
    Chattering {
        /// Time (s) of the pile-up.
        time: f64,
        /// The last transition tried.
        last: &'static str,
    },
    /// The effective gravity `g + a_v` reached zero: the ground falls faster
    /// than gravity and the bodies lose contact.
    #[error("the ground falls faster than gravity at t = {time} s (g + a_v <= 0): the bodies lose contact, which the model does not describe")]
    FreeFall {
        /// The first instant where `g + a_v <= 0` (s).
        time: f64,
    },
    /// An observer stopped the run (an interruption such as Ctrl-C).
    #[error("stopped at t = {time} s")]
    Stopped {
        /// Time (s) of the step or event that was refused.
        time: f64,
    },
    /// An observer failed (its message, e.g. a file that could not be written).
    #[error("{message}")]
    Observer {
        /// Time (s) of the step or event being observed.
        time: f64,
        /// The observer's one-line message.
        message: String,
    },
}

impl Error {
    /// The error of a run that an observer ended at `time`.
    pub(crate) fn halted(halt: crate::observer::Halt, time: f64) -> Self {
        match halt {
            crate::observer::Halt::Stop => Error::Stopped { time },
            crate::observer::Halt::Fail(message) => Error::Observer { time, message },
        }
    }
}

/// The parameters a model, a ground motion or a run is built from, named for
/// errors. The library knows no file format: a front end (the scenario crate)
/// maps each to the key its user wrote.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
#[non_exhaustive]
pub enum Parameter {
    /// The tower's width `B` (m).
    TowerWidth,
    /// The tower's height `H` (m).
    TowerHeight,
    /// The tower's depth, out of plane (m).
    TowerDepth,
    /// The wall thickness of a hollow tower (m).
    TowerWallThickness,
    /// The tower's mass `m2` (kg).
    TowerMass,
    /// The tower's density (kg/m³).
    TowerDensity,
    /// The tower's moment of inertia about a base corner `I0` (kg·m²).
    TowerInertiaPivot,
    /// The distance `R` from a base corner to the centre of mass (m).
    TowerRadius,
    /// The slenderness angle `α` (rad).
    TowerAlpha,
    /// The coefficient of restitution `r`.
    TowerRestitution,
    /// The building's mass `m1` (kg).
    BuildingMass,
    /// The static friction coefficient `μs`.
    BuildingMuStatic,
    /// The kinetic friction coefficient `μk`.
    BuildingMuKinetic,
    /// The peak ground acceleration (m/s²).
    GroundAmplitude,
    /// The ground motion's frequency (Hz).
    GroundFrequency,
    /// The length of the ground motion (s).
    GroundDuration,
    /// The phase of a harmonic ground motion (rad).
    GroundPhase,
    /// The centre of a Ricker wavelet `t0` (s).
    GroundRickerCentre,
    /// Gravity `g` (m/s²).
    Gravity,
    /// The simulated time (s).
    Duration,
    /// The integrator's relative tolerance.
    RelativeTolerance,
    /// The integrator's absolute tolerance.
    AbsoluteTolerance,
    /// The initial rotation `θ(0)` (rad).
    InitialTheta,
    /// The initial angular velocity `θ̇(0)` (rad/s).
    InitialThetaDot,
    /// The bodies of a model (a tower, a building, or both).
    Bodies,
    /// The blocks stacked on the tower.
    Blocks,
}

impl Parameter {
    /// Every parameter, for front ends that map each to a name.
    pub const ALL: &'static [Parameter] = &[
        Self::TowerWidth,
        Self::TowerHeight,
        Self::TowerDepth,
        Self::TowerWallThickness,
        Self::TowerMass,
        Self::TowerDensity,
        Self::TowerInertiaPivot,
        Self::TowerRadius,
        Self::TowerAlpha,
        Self::TowerRestitution,
        Self::BuildingMass,
        Self::BuildingMuStatic,
        Self::BuildingMuKinetic,
        Self::GroundAmplitude,
        Self::GroundFrequency,
        Self::GroundDuration,
        Self::GroundPhase,
        Self::GroundRickerCentre,
        Self::Gravity,
        Self::Duration,
        Self::RelativeTolerance,
        Self::AbsoluteTolerance,
        Self::InitialTheta,
        Self::InitialThetaDot,
        Self::Bodies,
        Self::Blocks,
    ];

    /// A description in words (`the tower's width B`), for users of the library itself.
    pub fn description(self) -> &'static str {
        match self {
            Self::TowerWidth => "the tower's width B",
            Self::TowerHeight => "the tower's height H",
            Self::TowerDepth => "the tower's depth",
            Self::TowerWallThickness => "the tower's wall thickness",
            Self::TowerMass => "the tower's mass",
            Self::TowerDensity => "the tower's density",
            Self::TowerInertiaPivot => "the tower's moment of inertia about a base corner",
            Self::TowerRadius => "the tower's radius R",
            Self::TowerAlpha => "the tower's slenderness angle α",
            Self::TowerRestitution => "the coefficient of restitution r",
            Self::BuildingMass => "the building's mass",
            Self::BuildingMuStatic => "the static friction coefficient μs",
            Self::BuildingMuKinetic => "the kinetic friction coefficient μk",
            Self::GroundAmplitude => "the ground motion's amplitude",
            Self::GroundFrequency => "the ground motion's frequency",
            Self::GroundDuration => "the ground motion's duration",
            Self::GroundPhase => "the ground motion's phase",
            Self::GroundRickerCentre => "the centre of the Ricker wavelet t0",
            Self::Gravity => "gravity g",
            Self::Duration => "the simulated duration",
            Self::RelativeTolerance => "the relative tolerance",
            Self::AbsoluteTolerance => "the absolute tolerance",
            Self::InitialTheta => "the initial rotation",
            Self::InitialThetaDot => "the initial angular velocity",
            Self::Bodies => "the bodies of the model",
            Self::Blocks => "the blocks stacked on the tower",
        }
    }
}

impl std::fmt::Display for Parameter {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.description())
    }
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(name: Parameter, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            parameter: name,
            reason: format!("must be a finite number > 0, got {value}"),
        })
    }
}

/// Checks that `value` is finite and within `[min, max]` (in `unit`): the
/// scales where the model's arithmetic (products like `m (B² + H²)`, time
/// scales like `√(R/g)`) neither overflows nor loses every digit. A value
/// outside is refused by its own name rather than by a derived quantity
/// turning infinite further on.
pub(crate) fn in_range(name: Parameter, value: f64, min: f64, max: f64, unit: &str) -> Result<f64, Error> {
    let value = positive(name, value)?;
    if (min..=max).contains(&value) {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            parameter: name,
            reason: format!("must be between {min:e} and {max:e} {unit} (beyond, the model's arithmetic overflows or loses its digits), got {value:e}"),
        })
    }
}

/// Lengths of a body (m): a tenth of a millimetre to a hundred kilometres.
pub(crate) const LENGTH_RANGE: (f64, f64) = (1e-4, 1e5);
/// Masses of a body (kg): a milligram to 1e15 kg (a mountain).
pub(crate) const MASS_RANGE: (f64, f64) = (1e-6, 1e15);
/// Densities (kg/m³): from a light foam to well above osmium's 2.26e4.
pub(crate) const DENSITY_RANGE: (f64, f64) = (1e-3, 1e5);
/// Moments of inertia (kg·m²): the products of the mass and length ranges, squared lengths.
pub(crate) const INERTIA_RANGE: (f64, f64) = (1e-15, 1e26);

/// Checks that `value` is finite and not negative.
pub(crate) fn non_negative(name: Parameter, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            parameter: name,
            reason: format!("must be a finite number >= 0, got {value}"),
        })
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite(name: Parameter, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            parameter: name,
            reason: format!("must be a finite number, got {value}"),
        })
    }
}
