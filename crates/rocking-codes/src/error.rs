//! Errors of the code spectra, the hazard grid, the response spectra and the fits.

/// Everything that can go wrong in building a code spectrum, reading a hazard
/// grid, computing a response spectrum or fitting a record set. Each message is
/// one line naming the quantity (or the grid's row and column) and what is wrong;
/// a front end adds the file and the key the user wrote.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A parameter is outside its valid range.
    #[error("{name}: {reason}")]
    InvalidParameter {
        /// The parameter, by its symbol in the code (`ag`, `F0`, `damping`, `soil`…).
        name: &'static str,
        /// What is wrong, with the value.
        reason: String,
    },
    /// A line of a hazard-grid file is wrong.
    #[error("line {line}{}: {reason}", column.as_ref().map(|c| format!(", column {c}")).unwrap_or_default())]
    Grid {
        /// 1-based line number in the file.
        line: usize,
        /// The column at fault, by its header name (or its 1-based number), if one is.
        column: Option<String>,
        /// What is wrong.
        reason: String,
    },
    /// The hazard grid as a whole is wrong (empty, an irregular lattice).
    #[error("{0}")]
    GridShape(String),
    /// A site lies outside the hazard grid: no cell of four nodes holds it.
    #[error(
        "the site (lon {lon}, lat {lat}) is outside the hazard grid: no cell of four grid nodes contains it (the small islands outside the grid take Tabella 2's values: island = \"G1\" to \"G5\")"
    )]
    OutsideGrid {
        /// Longitude of the site (degrees east).
        lon: f64,
        /// Latitude of the site (degrees north).
        lat: f64,
    },
    /// A record set cannot be fitted (too few records, a period range outside the periods).
    #[error("{0}")]
    Fit(String),
}

/// An [`Error::InvalidParameter`] for `name`.
pub(crate) fn invalid(name: &'static str, reason: impl Into<String>) -> Error {
    Error::InvalidParameter { name, reason: reason.into() }
}

/// `Ok(value)` when it is finite and within `[low, high]`, else the error naming it.
pub(crate) fn within(name: &'static str, value: f64, low: f64, high: f64) -> Result<f64, Error> {
    if value.is_finite() && value >= low && value <= high {
        Ok(value)
    } else {
        Err(invalid(name, format!("must be a number in [{low}, {high}], got {value}")))
    }
}

/// `Ok(value)` when it is finite and > 0, else the error naming it.
pub(crate) fn positive(name: &'static str, value: f64) -> Result<f64, Error> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(invalid(name, format!("must be a finite number > 0, got {value}")))
    }
}
