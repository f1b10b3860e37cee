//! Parameter checking: one error shape for every parameter of a scenario.
//!
//! A [`ParameterError`] carries the parameter's dotted path in the scenario file
//! (`aircraft.elevator_actuator.rate_limit_degps`), the value given and what is allowed.
//! Each parameter struct checks its own fields where it is defined, with the path of its
//! section; the scenario's `Scenario::validate` calls every section in turn.
//!
//! Every number has a finite physical range ([`Bounds`]): a value far outside what an
//! aircraft, a ship or a controller can have is refused before a run starts, never
//! discovered as an overflow, a huge allocation or a hang during one.

use std::fmt;

/// A parameter that is not allowed: its dotted path, its value and what is allowed.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("`{path}` = {value} is not allowed: expected {allowed}")]
pub struct ParameterError {
    /// The dotted path of the parameter in a scenario file, e.g. `environment.ship.heave_rms_m`.
    pub path: String,
    /// The value given, as written (numbers in Rust's shortest round-trip form).
    pub value: String,
    /// What is allowed, in words or as an interval, e.g. `a value in [0, 50]`.
    pub allowed: String,
}

impl ParameterError {
    /// The error for `section.key` (or `key` alone when `section` is empty).
    pub fn new(
        section: &str,
        key: &str,
        value: impl fmt::Debug,
        allowed: impl fmt::Display,
    ) -> Self {
        Self {
            path: join(section, key),
            value: format!("{value:?}"),
            allowed: allowed.to_string(),
        }
    }
}

/// `value` as an error message shows it: Rust's shortest round-trip form between 10⁻⁴
/// and 10¹⁵ in magnitude (and 0), scientific notation outside (`1e308`, `5e-324`), so that
/// a huge or tiny value never prints as hundreds of digits.
pub fn readable_number(value: f64) -> String {
    let magnitude = value.abs();
    if !value.is_finite() || magnitude == 0.0 || (1e-4..1e15).contains(&magnitude) {
        format!("{value}")
    } else {
        format!("{value:e}")
    }
}

/// `section.key`, or `key` when `section` is empty.
pub fn join(section: &str, key: &str) -> String {
    if section.is_empty() {
        key.to_owned()
    } else if key.is_empty() {
        section.to_owned()
    } else {
        format!("{section}.{key}")
    }
}

/// An interval of allowed values; each end may be open or closed. Infinite ends are not
/// used for parameters (every parameter has a physical range), but are representable.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Bounds {
    /// Lower bound.
    pub min: f64,
    /// Whether the lower bound itself is allowed.
    pub min_inclusive: bool,
    /// Upper bound.
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

    /// The interval (0, max]: a positive value up to `max`.
    pub const fn positive_up_to(max: f64) -> Self {
        Self {
            min: 0.0,
            min_inclusive: false,
            max,
            max_inclusive: true,
        }
    }

    /// The same interval without its lower end.
    pub const fn exclusive_min(self) -> Self {
        Self {
            min_inclusive: false,
            ..self
        }
    }

    /// The same interval without its upper end.
    pub const fn exclusive_max(self) -> Self {
        Self {
            max_inclusive: false,
            ..self
        }
    }

    /// Whether `value` lies in the interval (NaN never does).
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

    /// Checks that `value` is finite and in the interval; the error names `section.key`.
    pub fn check(self, section: &str, key: &str, value: f64) -> Result<(), ParameterError> {
        if value.is_finite() && self.contains(value) {
            Ok(())
        } else {
            Err(ParameterError::new(
                section,
                key,
                value,
                format_args!("a value in {self}"),
            ))
        }
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
                readable_number(value)
            }
        };
        write!(f, "{open}{}, {}{close}", bound(self.min), bound(self.max))
    }
}

/// Checks fields of a parameter struct against their ranges, in the order written; the
/// first field out of range returns its [`ParameterError`], named `section.field` with the
/// field's own name (`stringify!`), so that a key in an error can never drift from the
/// field it checks. Expands to one [`Bounds::check`] call a field, each followed by `?`.
///
/// ```ignore
/// check_ranges!(SECTION, self, {
///     natural_frequency_rad_s: Bounds::closed(1.0, 300.0),
///     damping_ratio: Bounds::closed(0.05, 5.0),
/// });
/// ```
macro_rules! check_ranges {
    ($section:expr, $parameters:expr, { $($field:ident: $bounds:expr),+ $(,)? }) => {
        $($bounds.check($section, stringify!($field), $parameters.$field)?;)+
    };
}
pub(crate) use check_ranges;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_display_shows_open_and_closed_ends() {
        assert_eq!(Bounds::closed(0.0, 45.0).to_string(), "[0, 45]");
        assert_eq!(Bounds::positive_up_to(3.0).to_string(), "(0, 3]");
        assert_eq!(
            Bounds::closed(-1.0, 1.0).exclusive_max().to_string(),
            "[-1, 1)"
        );
    }

    #[test]
    fn check_names_the_dotted_path_the_value_and_the_range() {
        assert!(Bounds::positive_up_to(1.0).check("a", "b", 1.0).is_ok());
        let error = Bounds::closed(0.0, 50.0)
            .check("environment.ship", "heave_rms_m", -1.0)
            .expect_err("negative");
        assert_eq!(error.path, "environment.ship.heave_rms_m");
        assert_eq!(
            error.to_string(),
            "`environment.ship.heave_rms_m` = -1.0 is not allowed: expected a value in [0, 50]"
        );
    }

    #[test]
    fn non_finite_and_huge_values_are_refused_with_a_readable_value() {
        let bounds = Bounds::closed(0.0, 1e6);
        for (value, shown) in [(f64::NAN, "NaN"), (f64::INFINITY, "inf"), (1e300, "1e300")] {
            let error = bounds.check("", "x", value).expect_err("refused");
            assert_eq!(error.value, shown);
            assert_eq!(error.path, "x");
        }
    }

    /// Regression (issue 45): error messages printed 1e308 as a 309-digit integer.
    #[test]
    fn regression_huge_and_tiny_values_read_in_scientific_notation() {
        assert_eq!(readable_number(1e308), "1e308");
        assert_eq!(readable_number(-5e-324), "-5e-324");
        assert_eq!(readable_number(0.0), "0");
        assert_eq!(readable_number(12.5), "12.5");
        assert_eq!(readable_number(f64::NAN), "NaN");
        assert_eq!(Bounds::closed(0.0, 1e300).to_string(), "[0, 1e300]");
    }

    #[test]
    fn open_ends_exclude_their_bound() {
        let b = Bounds::positive_up_to(2.0);
        assert!(!b.contains(0.0));
        assert!(b.contains(2.0));
        assert!(!b.exclusive_max().contains(2.0));
    }

    #[derive(Debug)]
    struct Two {
        low_m: f64,
        high_s: f64,
    }

    fn check_two(two: &Two) -> Result<(), ParameterError> {
        check_ranges!("a.b", two, {
            low_m: Bounds::closed(0.0, 1.0),
            high_s: Bounds::positive_up_to(5.0).exclusive_max(),
        });
        Ok(())
    }

    #[test]
    fn check_ranges_names_the_first_field_out_of_range_by_its_own_name() {
        assert!(check_two(&Two {
            low_m: 1.0,
            high_s: 4.9
        })
        .is_ok());
        let both_bad = Two {
            low_m: -1.0,
            high_s: 5.0,
        };
        assert_eq!(check_two(&both_bad).expect_err("low").path, "a.b.low_m");
        let high_bad = Two {
            low_m: 0.5,
            high_s: 5.0,
        };
        let error = check_two(&high_bad).expect_err("high");
        assert_eq!(error.path, "a.b.high_s");
        assert_eq!(error.allowed, "a value in (0, 5)");
    }
}
