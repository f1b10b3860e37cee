//! The pitch step of the full closed-loop simulation (paper §5, Fig. 10–11): the O-PD
//! settles in ideal conditions, and also with wind, air wake and turbulence when the
//! sensor noise is off. Numbers measured with this code are in the comments; the
//! assertions leave margins around them (docs/pitch-step.md).
#![allow(clippy::unwrap_used)]

use deckland::control::pitch::{ObserverPdParameters, PidParameters, PitchControllerParameters};
use deckland::metrics::{step_response_metrics, StepResponseMetrics, StepResponseSpec};
use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::{Mission, PitchCommand, Scenario};
use deckland::simulation::{Outcome, Simulation};

/// Flies a 2° step at t = 1 s for 6 s and measures θ (deg) with the 2 % band.
fn step_metrics(mut scenario: Scenario, pitch: PitchControllerParameters) -> StepResponseMetrics {
    scenario.control.pitch = pitch;
    scenario.mission = Mission::pitch_step(2.0, 6.0, PitchCommand::Step);
    let mut recorder = TimeSeriesRecorder::every(0.0);
    let summary = Simulation::new(&scenario).unwrap().run(&mut recorder);
    assert_eq!(summary.outcome, Outcome::Completed, "{summary:?}");
    let time: Vec<f64> = recorder.samples.iter().map(|s| s.time_s).collect();
    let theta_deg: Vec<f64> = recorder
        .samples
        .iter()
        .map(|s| s.theta_rad.to_degrees())
        .collect();
    let trim_deg = recorder.samples[0].theta_ref_rad.to_degrees();
    let spec = StepResponseSpec::new(1.0, trim_deg, trim_deg + 2.0);
    step_response_metrics(&time, &theta_deg, &spec).unwrap()
}

/// Measured: O-PD 1.150 s, 0.4 % overshoot; PID 3.140 s, 15.7 % (paper: O-PD 1.11 s).
#[test]
fn opd_settles_within_two_seconds_and_before_the_pid_in_ideal_conditions() {
    let ideal = Scenario::paper().ideal();
    let opd = step_metrics(
        ideal,
        PitchControllerParameters::ObserverPd(ObserverPdParameters::paper()),
    );
    let settling_s = opd.settling_time_s.unwrap();
    assert!(opd.settled);
    assert!(settling_s > 0.8 && settling_s < 2.0, "{opd:?}");
    assert!(opd.overshoot_pct < 10.0, "{opd:?}");
    let pid = step_metrics(
        ideal,
        PitchControllerParameters::Pid(PidParameters::paper()),
    );
    let pid_settling_s = pid.settling_time_s.unwrap();
    assert!(pid_settling_s > settling_s + 1.0, "{pid:?} vs {opd:?}");
}

/// Measured, seed 1: with wind, air wake, turbulence and deck motion but no sensor noise
/// the O-PD settles in 1.17 s (seeds 1–5: 1.16–1.17 s). With the noise on it does not
/// settle to ±2 % (docs/pitch-step.md), so that is not asserted.
#[test]
fn opd_settles_in_wind_without_sensor_noise() {
    let mut windy = Scenario::paper();
    windy.environment.pitch_noise.enabled = false;
    let opd = step_metrics(
        windy,
        PitchControllerParameters::ObserverPd(ObserverPdParameters::paper()),
    );
    assert!(opd.settled, "{opd:?}");
    let settling_s = opd.settling_time_s.unwrap();
    assert!(settling_s < 1.6, "{opd:?}");
}
