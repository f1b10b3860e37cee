//! The measured response of a lateral step, and the flown step: its samples and
//! response.

use serde::Serialize;

use super::spec::{LateralSample, LateralStep, LateralStepError};
use super::{LATERAL_SETTLING_BAND_FRACTION, LATERAL_STEP_TIME_S, RATE_LIMIT_TOLERANCE_DEGPS};
use crate::aircraft::six_dof::SixDofAircraft;
use crate::control::design::command_shaping::JerkLimitedStep;
use crate::control::lateral::LateralChannel;
use crate::metrics::{root_mean_square, step_response_metrics, StepResponseSpec};

/// A flown lateral step.
#[derive(Debug, Clone)]
pub struct LateralStepRun {
    /// The recorded samples.
    pub samples: Vec<LateralSample>,
    /// The measured response.
    pub response: LateralStepResponse,
}

/// What a set of lateral steps flew and measured: the document `deckland step --axis
/// roll|yaw --json` prints (without its output folder) and the Python package returns.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LateralStepReport {
    /// The axis stepped.
    pub axis: super::spec::LateralAxis,
    /// `ideal` or `adverse`.
    pub conditions: &'static str,
    /// Step size (deg).
    pub step_deg: f64,
    /// Seed of the random streams.
    pub seed: u64,
    /// Length of the run (s).
    pub seconds: f64,
    /// Time of the step (s).
    pub step_time_s: f64,
    /// Trim airspeed (m/s).
    pub airspeed_mps: f64,
    /// Half-width of the settling band (% of the step).
    pub settling_band_pct: f64,
    /// The aileron's rate limit (deg/s); `None` when it has none.
    pub aileron_rate_limit_degps: Option<f64>,
    /// The rudder's rate limit (deg/s); `None` when it has none.
    pub rudder_rate_limit_degps: Option<f64>,
    /// Each pair of laws' response, in the order flown.
    pub controllers: Vec<LateralStepResponse>,
}

impl LateralStepReport {
    /// The report of `step` flown on `setup` with the responses `controllers`.
    pub fn new(
        setup: &super::LateralSetup,
        step: &LateralStep,
        controllers: Vec<LateralStepResponse>,
    ) -> Self {
        Self {
            axis: step.axis,
            conditions: if step.adverse { "adverse" } else { "ideal" },
            step_deg: step.step_deg,
            seed: step.seed,
            seconds: step.seconds,
            step_time_s: LATERAL_STEP_TIME_S,
            airspeed_mps: setup.trim.speed_mps,
            settling_band_pct: LATERAL_SETTLING_BAND_FRACTION * 100.0,
            aileron_rate_limit_degps: setup.aircraft.aileron().parameters().rate_limit_degps,
            rudder_rate_limit_degps: setup.aircraft.rudder().parameters().rate_limit_degps,
            controllers,
        }
    }
}

/// The measured response of one pair of laws.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LateralStepResponse {
    /// The stepped channel's law label.
    pub controller: String,
    /// From the step to the last entry into the ±5 % band (s), when settled.
    pub settling_time_s: Option<f64>,
    /// Whether the stepped angle settled into the band for good.
    pub settled: bool,
    /// Why it did not settle.
    pub not_settled_reason: Option<String>,
    /// Overshoot beyond the target (% of the step).
    pub overshoot_pct: f64,
    /// 10–90 % rise time (s).
    pub rise_time_s: Option<f64>,
    /// Duration of the shaped command (s).
    pub reference_duration_s: f64,
    /// Largest |β| from the step on (deg) (the commanded β subtracted on the yaw axis).
    pub max_sideslip_error_deg: f64,
    /// Largest |φ − φ_ref| of the unstepped bank channel (deg) on the yaw axis, else of
    /// the stepped one after settling (0 when not settled).
    pub max_bank_error_deg: f64,
    /// RMS of the aileron rate from the step on (deg/s).
    pub aileron_rate_rms_degps: f64,
    /// Share of the time from the step on that the aileron sits on its rate limit (–).
    pub aileron_rate_limited_fraction: f64,
    /// Largest |δa| (deg).
    pub max_aileron_deg: f64,
    /// RMS of the rudder rate from the step on (deg/s).
    pub rudder_rate_rms_degps: f64,
    /// Largest |δr| (deg).
    pub max_rudder_deg: f64,
    /// `completed`, or `diverged`.
    pub outcome: &'static str,
}

pub(super) fn measure(
    step: &LateralStep,
    channel: LateralChannel,
    samples: &[LateralSample],
    shaped: &JerkLimitedStep,
    aircraft: &SixDofAircraft,
    diverged: bool,
) -> Result<LateralStepResponse, LateralStepError> {
    let after: Vec<&LateralSample> = samples
        .iter()
        .filter(|s| s.time_s >= LATERAL_STEP_TIME_S)
        .collect();
    let time: Vec<f64> = samples.iter().map(|s| s.time_s).collect();
    let (angle, initial, target): (Vec<f64>, f64, f64) = match channel {
        LateralChannel::Roll => (
            samples.iter().map(|s| s.bank_deg).collect(),
            samples[0].bank_command_deg,
            samples[0].bank_command_deg + step.step_deg,
        ),
        LateralChannel::Yaw => (
            samples.iter().map(|s| s.sideslip_deg).collect(),
            samples[0].sideslip_command_deg,
            samples[0].sideslip_command_deg + step.step_deg,
        ),
    };
    let aileron_limit = aircraft
        .aileron()
        .parameters()
        .rate_limit_degps
        .unwrap_or(f64::INFINITY);
    let max_abs =
        |f: &dyn Fn(&LateralSample) -> f64| after.iter().map(|s| f(s).abs()).fold(0.0, f64::max);
    let mut response = LateralStepResponse {
        controller: String::new(),
        settling_time_s: None,
        settled: false,
        not_settled_reason: None,
        overshoot_pct: 0.0,
        rise_time_s: None,
        reference_duration_s: shaped.duration_s(),
        max_sideslip_error_deg: max_abs(&|s| s.sideslip_deg - s.sideslip_command_deg),
        max_bank_error_deg: 0.0,
        aileron_rate_rms_degps: root_mean_square(after.iter().map(|s| s.aileron_rate_degps)),
        aileron_rate_limited_fraction: after
            .iter()
            .filter(|s| s.aileron_rate_degps.abs() >= aileron_limit - RATE_LIMIT_TOLERANCE_DEGPS)
            .count() as f64
            / after.len().max(1) as f64,
        max_aileron_deg: max_abs(&|s| s.aileron_deg),
        rudder_rate_rms_degps: root_mean_square(after.iter().map(|s| s.rudder_rate_degps)),
        max_rudder_deg: max_abs(&|s| s.rudder_deg),
        outcome: if diverged { "diverged" } else { "completed" },
    };
    if step.step_deg != 0.0 && !diverged {
        let spec = StepResponseSpec {
            settling_band_fraction: LATERAL_SETTLING_BAND_FRACTION,
            ..StepResponseSpec::new(LATERAL_STEP_TIME_S, initial, target)
        };
        let metrics = step_response_metrics(&time, &angle, &spec)?;
        response.settling_time_s = metrics.settling_time_s;
        response.settled = metrics.settled;
        response.not_settled_reason = metrics.not_settled_reason;
        response.overshoot_pct = metrics.overshoot_pct;
        response.rise_time_s = metrics.rise_time_s;
    } else if diverged {
        response.not_settled_reason = Some("diverged".to_owned());
    }
    response.max_bank_error_deg = match channel {
        LateralChannel::Yaw => max_abs(&|s| s.bank_deg - s.bank_command_deg),
        LateralChannel::Roll => match response.settling_time_s {
            Some(settle) if response.settled => after
                .iter()
                .filter(|s| s.time_s >= LATERAL_STEP_TIME_S + settle)
                .map(|s| (s.bank_deg - s.bank_command_deg).abs())
                .fold(0.0, f64::max),
            _ => 0.0,
        },
    };
    Ok(response)
}
