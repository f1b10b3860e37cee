//! Performance metrics of recorded signals: step-response figures of merit, actuator
//! activity (paper §5 compares controllers by settling time and elevator use), and the
//! root mean square and median of a set of values.
//!
//! Every function takes plain slices `(time, signal)` so it works on any recorded
//! channel. Invalid records (empty, mismatched lengths, non-finite samples, time not
//! strictly increasing) are reported as a [`MetricsError`] naming what was wrong;
//! a valid record whose response does not settle is reported in the metrics themselves
//! ([`StepResponseMetrics::settled`] and the reason), not as an error.

mod actuator_activity;
pub mod lso_grade;
mod statistics;
mod step_response;
mod trap_sheet;

use thiserror::Error;

pub use actuator_activity::{
    actuator_activity, peak_abs, time_at_limits_s, total_variation, ActuatorActivity, LimitTime,
};
pub use lso_grade::{grade_pass, Grade, GradeThresholds, LsoGrade, PassEnd, WindowFlight};
pub use statistics::{median, root_mean_square};
pub use step_response::{step_response_metrics, Settling, StepResponseMetrics, StepResponseSpec};
pub use trap_sheet::{
    PositionDeviation, TrapSheet, TrapSheetPosition, TrapSheetRecorder, NAUTICAL_MILE_M,
};

/// Why a record or a metric specification could not be evaluated.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MetricsError {
    /// The record has no samples.
    #[error("the record is empty")]
    EmptyRecord,
    /// Time and signal have different lengths.
    #[error("time has {time_len} samples but the signal has {signal_len}")]
    LengthMismatch {
        /// Number of time samples.
        time_len: usize,
        /// Number of signal samples.
        signal_len: usize,
    },
    /// A sample is NaN or infinite.
    #[error("{channel} sample {index} is not finite: {value}")]
    NonFiniteSample {
        /// "time" or "signal".
        channel: &'static str,
        /// Index of the first offending sample.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Time does not strictly increase.
    #[error("time must strictly increase, but sample {index} ({} s) does not exceed the previous one", crate::parameters::readable_number(*value))]
    TimeNotIncreasing {
        /// Index of the first offending sample.
        index: usize,
        /// Its time (s).
        value: f64,
    },
    /// The record ends before the step time.
    #[error("the record ends at {} s, before the step time {} s", crate::parameters::readable_number(*end_time_s), crate::parameters::readable_number(*step_time_s))]
    RecordEndsBeforeStep {
        /// Step time (s).
        step_time_s: f64,
        /// Time of the last sample (s).
        end_time_s: f64,
    },
    /// A parameter of the metric is invalid.
    #[error("metric parameter `{field}` is invalid: {} ({requirement})", crate::parameters::readable_number(*value))]
    InvalidParameter {
        /// Name of the parameter.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// What it must satisfy.
        requirement: &'static str,
    },
}

/// Checks that a signal is non-empty and finite.
fn check_signal(signal: &[f64]) -> Result<(), MetricsError> {
    if signal.is_empty() {
        return Err(MetricsError::EmptyRecord);
    }
    check_finite_samples("signal", signal)
}

/// Checks that `(time, signal)` is a non-empty record of equal lengths, all finite,
/// with strictly increasing time.
fn check_record(time: &[f64], signal: &[f64]) -> Result<(), MetricsError> {
    if time.len() != signal.len() {
        return Err(MetricsError::LengthMismatch {
            time_len: time.len(),
            signal_len: signal.len(),
        });
    }
    check_signal(signal)?;
    check_finite_samples("time", time)?;
    for (index, pair) in time.windows(2).enumerate() {
        if pair[1] <= pair[0] {
            return Err(MetricsError::TimeNotIncreasing {
                index: index + 1,
                value: pair[1],
            });
        }
    }
    Ok(())
}

/// Reports the first non-finite sample of `values`.
fn check_finite_samples(channel: &'static str, values: &[f64]) -> Result<(), MetricsError> {
    match values.iter().position(|v| !v.is_finite()) {
        Some(index) => Err(MetricsError::NonFiniteSample {
            channel,
            index,
            value: values[index],
        }),
        None => Ok(()),
    }
}
