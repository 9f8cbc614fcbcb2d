//! Errors of the capacity and the checks.

/// What can go wrong in building a tower's capacity or checking it. Each
/// message is one line naming the quantity and what is wrong; a front end adds
/// the file and the key the user wrote.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is outside its valid range.
    #[error("{name}: {reason}")]
    InvalidParameter {
        /// The parameter, by its symbol (`confidence_factor`, `q`, `b`…).
        name: &'static str,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A code spectrum could not be built.
    #[error(transparent)]
    Code(#[from] rocking_codes::Error),
}

/// An [`Error::InvalidParameter`] for `name`.
pub(crate) fn invalid(name: &'static str, reason: impl Into<String>) -> Error {
    Error::InvalidParameter { name, reason: reason.into() }
}
