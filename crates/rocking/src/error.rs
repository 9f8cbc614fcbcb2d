//! Errors of the library: invalid input (caught when a model is built) and
//! numerical failures (during a run).

/// Everything that can go wrong in building a model or running it.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is outside its valid range; `name` is the parameter, `reason` what is wrong.
    #[error("{name}: {reason}")]
    InvalidParameter {
        /// Name of the parameter (the scenario key where there is one).
        name: &'static str,
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

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!("must be a finite number > 0, got {value}"),
        })
    }
}

/// Checks that `value` is finite and not negative.
pub(crate) fn non_negative(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value >= 0.0 {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!("must be a finite number >= 0, got {value}"),
        })
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(Error::InvalidParameter {
            name,
            reason: format!("must be a finite number, got {value}"),
        })
    }
}
