//! Errors raised when an aircraft model is built from invalid parameters.

/// A model parameter outside its physical range.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum AircraftError {
    /// A parameter is non-finite or outside its allowed range.
    #[error("aircraft parameter `{field}` = {value} is invalid: expected {expected}")]
    InvalidParameter {
        /// The parameter's name, as in the scenario file.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn require_positive(field: &'static str, value: f64) -> Result<(), AircraftError> {
    if value.is_finite() && value > 0.0 {
        Ok(())
    } else {
        Err(AircraftError::InvalidParameter {
            field,
            value,
            expected: "a finite value greater than zero",
        })
    }
}

/// Checks that `value` is finite.
pub(crate) fn require_finite(field: &'static str, value: f64) -> Result<(), AircraftError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(AircraftError::InvalidParameter {
            field,
            value,
            expected: "a finite number",
        })
    }
}
