//! Reader stub, replaced by the full reader.
use super::{Record, RecordError};

pub(super) fn looks_like(_text: &str) -> bool {
    false
}

pub(super) fn parse(_text: &str, _g: f64) -> Result<Record, RecordError> {
    Err(RecordError::Invalid("reader not available".into()))
}
