//! Step-response figures of merit of a recorded signal: rise time, settling time,
//! overshoot, steady-state error (the paper's Fig. 10–12 comparison of O-PD and PID).
//!
//! All percentages are of the step size |target − initial| and in the step direction;
//! all times are measured from the step time and interpolated linearly between samples.

use serde::{Deserialize, Serialize};

use super::{check_record, MetricsError};

/// What a step response is measured against.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StepResponseSpec {
    /// Time of the step (s); samples before it are ignored.
    pub step_time_s: f64,
    /// Value before the step (signal's unit).
    pub initial_value: f64,
    /// Commanded value after the step (signal's unit); must differ from the initial value.
    pub target: f64,
    /// Half-width of the settling band as a fraction of the step size (default 0.02).
    pub settling_band_fraction: f64,
    /// Final window over which the steady-state error is averaged (s; default 1 s).
    pub steady_state_window_s: f64,
    /// How long the signal must stay in the band before the end of the record for the
    /// response to count as settled (s; default 0.5 s): shorter means "record too short".
    pub confirmation_time_s: f64,
}

impl StepResponseSpec {
    /// A step at `step_time_s` from `initial_value` to `target` with the defaults: 2 %
    /// band, 1 s steady-state window, 0.5 s confirmation time.
    pub fn new(step_time_s: f64, initial_value: f64, target: f64) -> Self {
        Self {
            step_time_s,
            initial_value,
            target,
            settling_band_fraction: 0.02,
            steady_state_window_s: 1.0,
            confirmation_time_s: 0.5,
        }
    }

    /// Checks the spec: finite values, a nonzero step, band in (0, 1), window > 0,
    /// confirmation time ≥ 0.
    pub fn validate(&self) -> Result<(), MetricsError> {
        let invalid = |field, value, requirement| MetricsError::InvalidParameter {
            field,
            value,
            requirement,
        };
        for (field, value) in [
            ("step_time_s", self.step_time_s),
            ("initial_value", self.initial_value),
            ("target", self.target),
        ] {
            if !value.is_finite() {
                return Err(invalid(field, value, "must be finite"));
            }
        }
        if self.target == self.initial_value {
            return Err(invalid(
                "target",
                self.target,
                "must differ from initial_value",
            ));
        }
        let band = self.settling_band_fraction;
        if !(band > 0.0 && band < 1.0) {
            return Err(invalid(
                "settling_band_fraction",
                band,
                "must lie in (0, 1)",
            ));
        }
        let window = self.steady_state_window_s;
        if !(window.is_finite() && window > 0.0) {
            return Err(invalid(
                "steady_state_window_s",
                window,
                "must be finite and > 0",
            ));
        }
        let confirmation = self.confirmation_time_s;
        if !(confirmation.is_finite() && confirmation >= 0.0) {
            return Err(invalid(
                "confirmation_time_s",
                confirmation,
                "must be finite and >= 0",
            ));
        }
        Ok(())
    }
}

/// Whether a response settled, and when or why not.
#[derive(Debug, Clone, PartialEq)]
pub enum Settling {
    /// Settled: after `time_s` (s from the step) the signal stays in the band to the end.
    Settled {
        /// Settling time from the step (s).
        time_s: f64,
    },
    /// Did not settle within the record.
    NotSettled {
        /// Why, with the numbers.
        reason: String,
    },
}

/// Step-response figures of merit of one record (serialises with these field names).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct StepResponseMetrics {
    /// Settling time from the step to the last exit from the band (s); `None` if not settled.
    pub settling_time_s: Option<f64>,
    /// Whether the signal stays in the band from the settling time to the end of the record.
    pub settled: bool,
    /// Why the response did not settle; `None` when settled.
    pub not_settled_reason: Option<String>,
    /// 10–90 % rise time (s); `None` if the signal never reaches 90 % of the step.
    pub rise_time_s: Option<f64>,
    /// Time from the step to the first 10 % crossing (s); `None` if never reached.
    pub rise_start_s: Option<f64>,
    /// Overshoot beyond the target in the step direction, % of the step size (≥ 0).
    pub overshoot_pct: f64,
    /// Mean of (target − signal) over the final window (signal's unit); `None` when the
    /// record after the step is shorter than the window.
    pub steady_state_error: Option<f64>,
}

impl StepResponseMetrics {
    /// The settling result as an enum.
    pub fn settling(&self) -> Settling {
        match (self.settling_time_s, &self.not_settled_reason) {
            (Some(time_s), None) => Settling::Settled { time_s },
            (_, reason) => Settling::NotSettled {
                reason: reason.clone().unwrap_or_default(),
            },
        }
    }
}

/// Measures a step response (see [`StepResponseSpec`]): rise time 10–90 %, settling time
/// to the band (last exit from it), overshoot and steady-state error.
pub fn step_response_metrics(
    time: &[f64],
    signal: &[f64],
    spec: &StepResponseSpec,
) -> Result<StepResponseMetrics, MetricsError> {
    spec.validate()?;
    check_record(time, signal)?;
    let end_time_s = time[time.len() - 1];
    let Some(first) = time.iter().position(|&t| t >= spec.step_time_s) else {
        return Err(MetricsError::RecordEndsBeforeStep {
            step_time_s: spec.step_time_s,
            end_time_s,
        });
    };
    // Only the part of the record from the step on counts.
    let (time, signal) = (&time[first..], &signal[first..]);
    let step = spec.target - spec.initial_value;
    // Progress towards the target: 0 at the initial value, 1 at the target.
    let progress = |value: f64| (value - spec.initial_value) / step;

    let crossing = |level: f64| first_crossing_s(time, signal, &progress, level);
    let rise_start = crossing(0.1);
    let rise_end = crossing(0.9);

    let peak = signal
        .iter()
        .map(|&v| progress(v))
        .fold(f64::NEG_INFINITY, f64::max);
    let overshoot_pct = ((peak - 1.0) * 100.0).max(0.0);

    let settling = settling(time, signal, spec, &progress);

    let window_start_s = end_time_s - spec.steady_state_window_s;
    let steady_state_error = (window_start_s >= spec.step_time_s).then(|| {
        let in_window = time
            .iter()
            .zip(signal)
            .filter(|(&t, _)| t >= window_start_s);
        let (sum, count) = in_window.fold((0.0, 0_usize), |(sum, count), (_, &v)| {
            (sum + (spec.target - v), count + 1)
        });
        sum / count as f64
    });

    let (settling_time_s, not_settled_reason) = match settling {
        Settling::Settled { time_s } => (Some(time_s), None),
        Settling::NotSettled { reason } => (None, Some(reason)),
    };
    Ok(StepResponseMetrics {
        settling_time_s,
        settled: not_settled_reason.is_none(),
        not_settled_reason,
        rise_time_s: rise_start.zip(rise_end).map(|(start, end)| end - start),
        rise_start_s: rise_start.map(|t| t - spec.step_time_s),
        overshoot_pct,
        steady_state_error,
    })
}

/// First time (absolute, s) at which the progress reaches `level`, interpolated.
fn first_crossing_s(
    time: &[f64],
    signal: &[f64],
    progress: &impl Fn(f64) -> f64,
    level: f64,
) -> Option<f64> {
    let index = signal.iter().position(|&v| progress(v) >= level)?;
    if index == 0 {
        return Some(time[0]);
    }
    let (before, after) = (progress(signal[index - 1]), progress(signal[index]));
    let fraction = (level - before) / (after - before);
    Some(time[index - 1] + fraction * (time[index] - time[index - 1]))
}

/// Settling time from the step: the last exit from the band, interpolated to the band
/// edge; not settled if the last sample is outside or the dwell is too short.
fn settling(
    time: &[f64],
    signal: &[f64],
    spec: &StepResponseSpec,
    progress: &impl Fn(f64) -> f64,
) -> Settling {
    let band = spec.settling_band_fraction;
    let outside = |v: f64| (progress(v) - 1.0).abs() > band;
    let last = signal.len() - 1;
    let band_pct = band * 100.0;
    if outside(signal[last]) {
        return Settling::NotSettled {
            reason: format!(
                "outside the ±{band_pct} % band at the end of the record (t = {} s, {:.3} % of \
                 the step from the target)",
                time[last],
                (progress(signal[last]) - 1.0) * 100.0
            ),
        };
    }
    let entry_s = match signal.iter().rposition(|&v| outside(v)) {
        None => time[0],
        Some(j) => {
            let (before, after) = (progress(signal[j]) - 1.0, progress(signal[j + 1]) - 1.0);
            let edge = band.copysign(before);
            let fraction = (edge - before) / (after - before);
            time[j] + fraction * (time[j + 1] - time[j])
        }
    };
    let dwell_s = time[last] - entry_s;
    if dwell_s < spec.confirmation_time_s {
        return Settling::NotSettled {
            reason: format!(
                "record too short: inside the ±{band_pct} % band only for the last {dwell_s:.3} s, \
                 less than the {} s confirmation time",
                spec.confirmation_time_s
            ),
        };
    }
    Settling::Settled {
        time_s: entry_s - spec.step_time_s,
    }
}
