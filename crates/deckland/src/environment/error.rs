//! Errors of the environment's parameters and models.

use std::fmt;

/// What went wrong with an environment parameter or model.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum EnvironmentError {
    /// A parameter is NaN or infinite.
    #[error("{field} must be a finite number, got {value}; allowed range {allowed}")]
    NotFinite {
        /// The parameter's path, e.g. `ship.heave_rms_m`.
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range, e.g. `[0, 45]`.
        allowed: Bounds,
    },
    /// A parameter lies outside its allowed range.
    #[error("{field} = {value} is outside the allowed range {allowed}")]
    OutOfRange {
        /// The parameter's path, e.g. `wind.turbulence_scale_m`.
        field: &'static str,
        /// The value given.
        value: f64,
        /// The allowed range.
        allowed: Bounds,
    },
    /// The arresting wires are not in order, or one lies aft of the ramp.
    #[error(
        "deck.wire_positions_m = {positions_m:?} must increase strictly from aft to forward, \
         every wire forward of the ramp at {ramp_m} m"
    )]
    WireOrder {
        /// The wire positions given (m along the deck from the aim point, positive forward).
        positions_m: Vec<f64>,
        /// The ramp's position on the same axis (m; negative).
        ramp_m: f64,
    },
    /// A shaping filter has no stationary covariance (it is not asymptotically stable).
    #[error("the {filter} shaping filter has no stationary covariance: it is not stable")]
    NoStationaryCovariance {
        /// Which filter.
        filter: &'static str,
    },
}

/// An interval of allowed parameter values; bounds may be open, closed or infinite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Lower bound (may be −∞).
    pub min: f64,
    /// Whether the lower bound itself is allowed.
    pub min_inclusive: bool,
    /// Upper bound (may be +∞).
    pub max: f64,
    /// Whether the upper bound itself is allowed.
    pub max_inclusive: bool,
}

impl Bounds {
    /// The closed interval [min, max].
    pub const fn closed(min: f64, max: f64) -> Self {
        Self {
            min,
            min_inclusive: true,
            max,
            max_inclusive: true,
        }
    }

    /// The interval [0, ∞): any finite non-negative value.
    pub const NON_NEGATIVE: Self = Self::closed(0.0, f64::INFINITY);

    /// The interval (0, ∞): any finite positive value.
    pub const POSITIVE: Self = Self {
        min: 0.0,
        min_inclusive: false,
        max: f64::INFINITY,
        max_inclusive: false,
    };

    /// The interval (−∞, ∞): any finite value.
    pub const FINITE: Self = Self::closed(f64::NEG_INFINITY, f64::INFINITY);

    /// Whether `value` lies in the interval.
    pub fn contains(&self, value: f64) -> bool {
        let above = if self.min_inclusive {
            value >= self.min
        } else {
            value > self.min
        };
        let below = if self.max_inclusive {
            value <= self.max
        } else {
            value < self.max
        };
        above && below
    }

    /// Checks that `value` is finite and in the interval, naming `field` in the error.
    pub fn check(self, field: &'static str, value: f64) -> Result<(), EnvironmentError> {
        if !value.is_finite() {
            return Err(EnvironmentError::NotFinite {
                field,
                value,
                allowed: self,
            });
        }
        if !self.contains(value) {
            return Err(EnvironmentError::OutOfRange {
                field,
                value,
                allowed: self,
            });
        }
        Ok(())
    }
}

impl fmt::Display for Bounds {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let open = if self.min_inclusive && self.min.is_finite() {
            '['
        } else {
            '('
        };
        let close = if self.max_inclusive && self.max.is_finite() {
            ']'
        } else {
            ')'
        };
        let bound = |value: f64| {
            if value == f64::INFINITY {
                "∞".to_owned()
            } else if value == f64::NEG_INFINITY {
                "−∞".to_owned()
            } else {
                format!("{value}")
            }
        };
        write!(f, "{open}{}, {}{close}", bound(self.min), bound(self.max))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_display_shows_open_and_closed_ends() {
        assert_eq!(Bounds::closed(0.0, 45.0).to_string(), "[0, 45]");
        assert_eq!(Bounds::POSITIVE.to_string(), "(0, ∞)");
        assert_eq!(Bounds::NON_NEGATIVE.to_string(), "[0, ∞)");
        assert_eq!(Bounds::FINITE.to_string(), "(−∞, ∞)");
    }

    #[test]
    fn check_rejects_non_finite_and_out_of_range_values() {
        assert!(Bounds::POSITIVE.check("x", 1.0).is_ok());
        assert!(matches!(
            Bounds::POSITIVE.check("x", 0.0),
            Err(EnvironmentError::OutOfRange { field: "x", .. })
        ));
        assert!(matches!(
            Bounds::FINITE.check("x", f64::NAN),
            Err(EnvironmentError::NotFinite { field: "x", .. })
        ));
        let message = Bounds::NON_NEGATIVE
            .check("ship.heave_rms_m", -1.0)
            .map_err(|e| e.to_string());
        assert_eq!(
            message,
            Err("ship.heave_rms_m = -1 is outside the allowed range [0, ∞)".to_owned())
        );
    }
}
