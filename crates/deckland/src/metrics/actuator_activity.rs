//! Actuator activity of a recorded command or position (e.g. the elevator): peak
//! magnitude, time spent on the position limits, and total variation (paper §5 compares
//! the controllers' elevator activity).

use serde::Serialize;

use super::{check_record, check_signal, MetricsError};

/// Largest |value| of a signal (signal's unit).
pub fn peak_abs(signal: &[f64]) -> Result<f64, MetricsError> {
    check_signal(signal)?;
    Ok(signal.iter().fold(0.0_f64, |peak, v| peak.max(v.abs())))
}

/// Total variation `Σ|x[i+1] − x[i]|` (signal's unit): the total travel, a measure of
/// actuator activity that grows with chatter as well as with large moves.
pub fn total_variation(signal: &[f64]) -> Result<f64, MetricsError> {
    check_signal(signal)?;
    Ok(signal.windows(2).map(|w| (w[1] - w[0]).abs()).sum())
}

/// Time spent on each position limit (s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LimitTime {
    /// Time at or beyond the lower limit (s).
    pub lower_s: f64,
    /// Time at or beyond the upper limit (s).
    pub upper_s: f64,
}

/// Time the signal spends within `tolerance` of (or beyond) each limit (s), counting
/// each sample as held until the next one (sample-and-hold; the last sample adds no
/// time).
pub fn time_at_limits_s(
    time: &[f64],
    signal: &[f64],
    lower_limit: f64,
    upper_limit: f64,
    tolerance: f64,
) -> Result<LimitTime, MetricsError> {
    check_record(time, signal)?;
    check_limits(lower_limit, upper_limit, tolerance)?;
    let mut limit_time = LimitTime {
        lower_s: 0.0,
        upper_s: 0.0,
    };
    for i in 0..signal.len().saturating_sub(1) {
        let held_s = time[i + 1] - time[i];
        if signal[i] <= lower_limit + tolerance {
            limit_time.lower_s += held_s;
        } else if signal[i] >= upper_limit - tolerance {
            limit_time.upper_s += held_s;
        }
    }
    Ok(limit_time)
}

/// Summary of an actuator signal's activity (units of the signal; times in s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ActuatorActivity {
    /// Largest |value| (signal's unit).
    pub peak_abs: f64,
    /// Time within tolerance of the lower limit (s).
    pub time_at_lower_limit_s: f64,
    /// Time within tolerance of the upper limit (s).
    pub time_at_upper_limit_s: f64,
    /// Total variation Σ|Δx| (signal's unit).
    pub total_variation: f64,
}

/// Peak magnitude, time at each limit and total variation of one record.
pub fn actuator_activity(
    time: &[f64],
    signal: &[f64],
    lower_limit: f64,
    upper_limit: f64,
    tolerance: f64,
) -> Result<ActuatorActivity, MetricsError> {
    let limit_time = time_at_limits_s(time, signal, lower_limit, upper_limit, tolerance)?;
    Ok(ActuatorActivity {
        peak_abs: peak_abs(signal)?,
        time_at_lower_limit_s: limit_time.lower_s,
        time_at_upper_limit_s: limit_time.upper_s,
        total_variation: total_variation(signal)?,
    })
}

/// Checks that the limits are finite and ordered and the tolerance finite and ≥ 0.
fn check_limits(lower: f64, upper: f64, tolerance: f64) -> Result<(), MetricsError> {
    let invalid = |field, value, requirement| MetricsError::InvalidParameter {
        field,
        value,
        requirement,
    };
    if !lower.is_finite() {
        return Err(invalid("lower_limit", lower, "must be finite"));
    }
    if !(upper.is_finite() && upper > lower) {
        return Err(invalid(
            "upper_limit",
            upper,
            "must be finite and above the lower limit",
        ));
    }
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(invalid("tolerance", tolerance, "must be finite and >= 0"));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peak_and_total_variation_of_a_known_signal() {
        let signal = [0.0, 1.0, -2.0, 0.5];
        assert_eq!(peak_abs(&signal), Ok(2.0));
        assert_eq!(total_variation(&signal), Ok(1.0 + 3.0 + 2.5));
    }

    #[test]
    fn time_at_limits_counts_held_samples() {
        let time = [0.0, 0.1, 0.2, 0.3, 0.4, 0.5];
        let signal = [-0.436, -0.436, 0.0, 0.175, 0.175, 0.175];
        let limits = time_at_limits_s(&time, &signal, -0.436, 0.175, 1e-6).expect("valid");
        assert!((limits.lower_s - 0.2).abs() < 1e-12, "{limits:?}");
        assert!((limits.upper_s - 0.2).abs() < 1e-12, "{limits:?}");
        let activity = actuator_activity(&time, &signal, -0.436, 0.175, 1e-6).expect("valid");
        assert_eq!(activity.peak_abs, 0.436);
    }

    #[test]
    fn bad_records_are_errors() {
        assert_eq!(peak_abs(&[]), Err(MetricsError::EmptyRecord));
        assert!(matches!(
            total_variation(&[0.0, f64::NAN]),
            Err(MetricsError::NonFiniteSample { index: 1, .. })
        ));
        assert!(matches!(
            time_at_limits_s(&[0.0, 1.0], &[0.0], -1.0, 1.0, 0.0),
            Err(MetricsError::LengthMismatch { .. })
        ));
        assert!(matches!(
            time_at_limits_s(&[0.0, 1.0], &[0.0, 0.0], 1.0, -1.0, 0.0),
            Err(MetricsError::InvalidParameter {
                field: "upper_limit",
                ..
            })
        ));
    }
}
