//! A pitch-attitude step from level trim, outer loops off (paper §5, Fig. 10–12): the
//! step response of θ and what it asked of the elevator.

use serde::Serialize;

use super::ExperimentError;
use crate::metrics::{actuator_activity, step_response_metrics, total_variation, StepResponseSpec};
use crate::recording::TimeSeriesRecorder;
use crate::scenario::{Mission, Scenario};
use crate::simulation::{ActuatorActivity, Outcome, RunSummary, Signals, Simulation};

/// Time of the step after the start (s).
pub const PITCH_STEP_TIME_S: f64 = 1.0;
/// How often the step is recorded (s): every 2 ms, since the slowest-damped mode of the
/// paper's design (near 28.7 rad/s) has a 0.22 s period.
pub const PITCH_STEP_RECORD_INTERVAL_S: f64 = 0.002;
/// Half-width of the settling band as a fraction of the step (paper: 2 %).
pub const SETTLING_BAND_FRACTION: f64 = 0.02;
/// Tolerance of "the elevator sits on a position limit" (deg).
const LIMIT_TOLERANCE_DEG: f64 = 1e-6;

/// The step to fly: `step_deg` nose-up at [`PITCH_STEP_TIME_S`], `seconds` of flight,
/// from level trim 1000 m aft of the ship at 150 m ([`Mission::pitch_step`]), commanded
/// as the scenario's hardware set commands steps (jerk-limited on the realistic
/// hardware, a step in the paper's set).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchStep {
    /// Step size (deg), positive nose-up.
    pub step_deg: f64,
    /// Length of the run (s).
    pub seconds: f64,
    /// How often the run is recorded and measured (s).
    pub record_interval_s: f64,
}

impl PitchStep {
    /// A step of `step_deg` lasting `seconds`, recorded every
    /// [`PITCH_STEP_RECORD_INTERVAL_S`].
    pub fn new(step_deg: f64, seconds: f64) -> Self {
        Self {
            step_deg,
            seconds,
            record_interval_s: PITCH_STEP_RECORD_INTERVAL_S,
        }
    }
}

/// The step response on the true pitch angle θ and the elevator's activity.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PitchStepResponse {
    /// The pitch law's label.
    pub controller: String,
    /// From the step to the last entry into θ* + D ± 2 % of |D| (s), when settled.
    pub settling_time_s: Option<f64>,
    /// How long the command takes to reach θ* + D after the step (s): the duration of
    /// the jerk-limited reference (the prefilter) on the realistic hardware, 0 for the
    /// paper's step.
    pub reference_duration_s: f64,
    /// Settling measured from the end of the reference instead of the step (s): the
    /// settling time less [`Self::reference_duration_s`] (negative when θ settles into
    /// the band before the reference ends), when settled.
    pub settling_after_reference_s: Option<f64>,
    /// Whether θ settled into the band for good.
    pub settled: bool,
    /// Why it did not settle (outside the band at the end, dwell too short, diverged).
    pub not_settled_reason: Option<String>,
    /// Overshoot beyond the target, in % of the step.
    pub overshoot_pct: f64,
    /// 10–90 % rise time (s).
    pub rise_time_s: Option<f64>,
    /// Mean error over the last second (deg).
    pub steady_state_error_deg: Option<f64>,
    /// Largest |δe| (deg).
    pub max_elevator_deg: f64,
    /// Largest |δe − δe*| (deg).
    pub max_elevator_change_deg: f64,
    /// Time on either position limit (s).
    pub elevator_saturation_s: f64,
    /// Total travel Σ|Δδe| (deg).
    pub elevator_total_variation_deg: f64,
    /// How the run ended (`completed`, or `diverged`).
    pub outcome: &'static str,
    /// What the elevator and the engines did over the whole run.
    pub actuator: ActuatorActivity,
}

/// A flown pitch step.
#[derive(Debug, Clone)]
pub struct PitchStepRun {
    /// The signals every [`PITCH_STEP_RECORD_INTERVAL_S`].
    pub samples: Vec<Signals>,
    /// How the run ended.
    pub summary: RunSummary,
    /// The measured response.
    pub response: PitchStepResponse,
}

/// Flies `step` with `scenario`'s aircraft, environment and pitch law and measures θ.
pub fn fly_pitch_step(
    scenario: &Scenario,
    step: &PitchStep,
) -> Result<PitchStepRun, ExperimentError> {
    let mut scenario = *scenario;
    scenario.mission = Mission::pitch_step(
        step.step_deg,
        step.seconds,
        scenario.hardware.pitch_command(),
    );
    let label = scenario.control.pitch.label().to_owned();
    let mut recorder = TimeSeriesRecorder::every(step.record_interval_s);
    let summary = Simulation::new(&scenario)?.run(&mut recorder);
    let samples = recorder.samples;
    let response = measure_pitch_step(&scenario, step, label, &samples, &summary)?;
    Ok(PitchStepRun {
        samples,
        summary,
        response,
    })
}

/// What a pitch step's response reports of the elevator, measured or not.
struct ElevatorUse {
    /// Largest deflection (deg).
    max_elevator_deg: f64,
    /// Largest deflection from trim (deg).
    max_elevator_change_deg: f64,
    /// Time on either position limit (s).
    elevator_saturation_s: f64,
}

/// Measures θ and the elevator in the `samples` of `step` flown by the pitch law
/// `label` to the end `summary` describes.
fn measure_pitch_step(
    scenario: &Scenario,
    step: &PitchStep,
    label: String,
    samples: &[Signals],
    summary: &RunSummary,
) -> Result<PitchStepResponse, ExperimentError> {
    let first = samples.first().ok_or(ExperimentError::NoSamples)?;
    let trim_deg = first.theta_ref_rad.to_degrees();
    let elevator_trim_deg = first.elevator_rad.to_degrees();
    let time: Vec<f64> = samples.iter().map(|s| s.time_s).collect();
    let theta_deg: Vec<f64> = samples.iter().map(|s| s.theta_rad.to_degrees()).collect();
    let elevator_deg: Vec<f64> = samples
        .iter()
        .map(|s| s.elevator_rad.to_degrees())
        .collect();

    let mut spec = StepResponseSpec::new(PITCH_STEP_TIME_S, trim_deg, trim_deg + step.step_deg);
    spec.settling_band_fraction = SETTLING_BAND_FRACTION;
    let metrics = step_response_metrics(&time, &theta_deg, &spec);
    let actuator = &scenario.aircraft.elevator_actuator;
    let activity = actuator_activity(
        &time,
        &elevator_deg,
        actuator.min_deflection_deg,
        actuator.max_deflection_deg,
        LIMIT_TOLERANCE_DEG,
    )?;
    let max_elevator_change_deg = elevator_deg
        .iter()
        .fold(0.0_f64, |peak, e| peak.max((e - elevator_trim_deg).abs()));
    let diverged = (summary.outcome == Outcome::Diverged).then(|| {
        format!(
            "the simulation diverged at t = {:.3} s: {}",
            summary.end_time_s,
            summary.reason.clone().unwrap_or_default()
        )
    });
    let elevator = ElevatorUse {
        max_elevator_deg: activity.peak_abs,
        max_elevator_change_deg,
        elevator_saturation_s: activity.time_at_lower_limit_s + activity.time_at_upper_limit_s,
    };
    let reference_duration_s = reference_duration_s(samples, trim_deg + step.step_deg);
    Ok(match metrics {
        Ok(metrics) => {
            let not_settled_reason = diverged.or(metrics.not_settled_reason);
            let settling_time_s = metrics
                .settling_time_s
                .filter(|_| not_settled_reason.is_none());
            PitchStepResponse {
                controller: label,
                settled: not_settled_reason.is_none(),
                settling_time_s,
                reference_duration_s,
                settling_after_reference_s: settling_time_s.map(|t| t - reference_duration_s),
                not_settled_reason,
                overshoot_pct: metrics.overshoot_pct,
                rise_time_s: metrics.rise_time_s,
                steady_state_error_deg: metrics.steady_state_error,
                max_elevator_deg: elevator.max_elevator_deg,
                max_elevator_change_deg: elevator.max_elevator_change_deg,
                elevator_saturation_s: elevator.elevator_saturation_s,
                elevator_total_variation_deg: total_variation(&elevator_deg)?,
                outcome: summary.outcome.name(),
                actuator: summary.actuator,
            }
        }
        // A record that cannot be measured (diverged before the step, non-finite values)
        // is reported as not settled, with the reason.
        Err(error) => unmeasured_response(
            label,
            diverged.unwrap_or_else(|| error.to_string()),
            reference_duration_s,
            &elevator,
            activity.total_variation,
            summary,
        ),
    })
}

/// The response of a record that cannot be measured, not settled for `reason`; the
/// elevator's total variation (deg) as its activity measured it.
fn unmeasured_response(
    label: String,
    reason: String,
    reference_duration_s: f64,
    elevator: &ElevatorUse,
    elevator_total_variation_deg: f64,
    summary: &RunSummary,
) -> PitchStepResponse {
    PitchStepResponse {
        controller: label,
        settling_time_s: None,
        reference_duration_s,
        settling_after_reference_s: None,
        settled: false,
        not_settled_reason: Some(reason),
        overshoot_pct: f64::NAN,
        rise_time_s: None,
        steady_state_error_deg: None,
        max_elevator_deg: elevator.max_elevator_deg,
        max_elevator_change_deg: elevator.max_elevator_change_deg,
        elevator_saturation_s: elevator.elevator_saturation_s,
        elevator_total_variation_deg,
        outcome: summary.outcome.name(),
        actuator: summary.actuator,
    }
}

/// How long after [`PITCH_STEP_TIME_S`] the recorded command θ_ref first reaches
/// `target_deg` (within 10⁻⁹ of the step), staying there to the end (s); 0 for a step.
fn reference_duration_s(samples: &[Signals], target_deg: f64) -> f64 {
    let tolerance_deg = 1e-9 * target_deg.abs().max(1.0);
    let reached = samples
        .iter()
        .rposition(|s| (s.theta_ref_rad.to_degrees() - target_deg).abs() > tolerance_deg)
        .and_then(|last_off| samples.get(last_off + 1))
        .map_or(PITCH_STEP_TIME_S, |s| s.time_s);
    (reached - PITCH_STEP_TIME_S).max(0.0)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// θ_ref (deg) at 1 ms steps: trim 5° until the step at 1 s, a ramp to 7° that ends
    /// at 1.5 s, then 7°.
    fn ramp_samples() -> Vec<Signals> {
        (0..3000)
            .map(|i| {
                let time_s = f64::from(i) * 1e-3;
                let theta_deg = 5.0 + 2.0 * ((time_s - 1.0) / 0.5).clamp(0.0, 1.0);
                Signals {
                    time_s,
                    theta_ref_rad: theta_deg.to_radians(),
                    ..Signals::default()
                }
            })
            .collect()
    }

    #[test]
    fn the_reference_duration_is_where_the_command_reaches_the_target() {
        let duration = reference_duration_s(&ramp_samples(), 7.0);
        assert!((duration - 0.5).abs() < 2e-3, "{duration}");
        // A step reaches the target at once.
        let step: Vec<Signals> = ramp_samples()
            .into_iter()
            .map(|mut s| {
                s.theta_ref_rad = if s.time_s >= 1.0 { 7.0_f64 } else { 5.0 }.to_radians();
                s
            })
            .collect();
        assert_eq!(reference_duration_s(&step, 7.0), 0.0);
    }
}
