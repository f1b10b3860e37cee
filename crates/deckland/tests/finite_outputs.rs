//! Nothing non-finite reaches a recorder (issue 14, class 5), and the sink-rate test in
//! adverse conditions flies (class 8).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::experiments::{
    fly_pitch_step, fly_sink_rate, Conditions, PitchStep, SinkRateTracking,
};
use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{
    Divergence, EndReason, Outcome, Overrides, Signals, Simulation, Stop, SIGNAL_MAGNITUDE_LIMIT,
};

fn assert_finite(samples: &[Signals]) {
    for s in samples {
        for (name, value) in s.named_values() {
            assert!(
                value.is_none_or(f64::is_finite),
                "{name} = {value:?} at t = {}",
                s.time_s
            );
        }
    }
}

/// Flies the default approach with `overrides` from the first step; returns the end.
fn fly_with(overrides: Overrides) -> (EndReason, TimeSeriesRecorder) {
    let mut simulation = Simulation::new(&Scenario::default()).unwrap();
    let mut recorder = TimeSeriesRecorder::every(0.0);
    for _ in 0..100 {
        if let Stop::Ended(reason) = simulation.step_with(&mut recorder, &overrides) {
            return (reason, recorder);
        }
    }
    panic!("the run did not end");
}

/// Regression (issue 14, class 5): PID gains of 1e308 wrote `-inf` into
/// `elevator_command_deg` for 2.8 s of CSV rows; the run went on. A command that is not
/// finite now ends the run at once as diverged, naming the signal, and is never recorded.
#[test]
fn regression_a_non_finite_command_ends_the_run_naming_the_signal() {
    for (overrides, signal) in [
        (
            Overrides {
                elevator_rad: Some(f64::NEG_INFINITY),
                ..Overrides::default()
            },
            "elevator_command_rad",
        ),
        (
            Overrides {
                pitch_command_rad: Some(f64::NAN),
                ..Overrides::default()
            },
            "theta_ref_rad",
        ),
    ] {
        let (reason, recorder) = fly_with(overrides);
        assert_eq!(reason.outcome(), Outcome::Diverged);
        match &reason {
            EndReason::Diverged(Divergence::NonFiniteSignal { signal: named, .. }) => {
                assert_eq!(*named, signal)
            }
            other => panic!("{other:?}"),
        }
        let words = reason.description().unwrap();
        assert!(words.contains(signal), "{words}");
        assert!(
            recorder.samples.is_empty(),
            "the poisoned sample was recorded"
        );
        assert!(recorder.summary.is_some());
    }
}

/// A finite command beyond any physical size ends the run too, before unit conversions
/// could overflow it to ∞ in a file.
#[test]
fn a_command_beyond_any_physical_size_ends_the_run() {
    let (reason, recorder) = fly_with(Overrides {
        thrust_n: Some(10.0 * SIGNAL_MAGNITUDE_LIMIT),
        ..Overrides::default()
    });
    match reason {
        EndReason::Diverged(Divergence::SignalOutOfRange { signal, value, .. }) => {
            assert_eq!(signal, "thrust_command_n");
            assert_eq!(value, 1e13);
        }
        other => panic!("{other:?}"),
    }
    assert_finite(&recorder.samples);
}

/// Regression (issue 14, class 5): the pitch-step and sink-rate missions recorded NaN
/// for the glide path (no approach) and the climb-rate command (no climb-rate loop in a
/// pitch step). What does not apply is `None` now.
#[test]
fn regression_signals_that_do_not_apply_are_none_not_nan() {
    let step = fly_pitch_step(
        &Conditions::Ideal.apply(Scenario::default(), 1),
        &PitchStep::new(2.0, 2.0),
    )
    .unwrap();
    assert_finite(&step.samples);
    let first = step.samples.first().unwrap();
    assert_eq!(first.path_height_m, None);
    assert_eq!(first.time_to_go_s, None);
    assert_eq!(first.climb_rate_command_mps, None);

    let scenario = Conditions::Ideal.apply(Scenario::default(), 1);
    let mut simulation = Simulation::new(&scenario).unwrap();
    let mut recorder = TimeSeriesRecorder::every(0.01);
    for _ in 0..200 {
        simulation.step(&mut recorder);
    }
    assert_finite(&recorder.samples);
    let approach = recorder.samples.first().unwrap();
    assert!(approach.path_height_m.is_some() && approach.time_to_go_s.is_some());
    assert!(approach.climb_rate_command_mps.is_some());
}

/// Regression (issue 14, class 8): `deckland sink --conditions adverse` ended `diverged`
/// at t = 0.000 s for every seed and both controllers (α −5.3°): the test starts 20 km aft
/// of the ship, where the periodic air wake read literally is a 20.5 m/s vertical gust.
#[test]
fn regression_sink_rate_tracking_in_adverse_conditions_flies() {
    let tracking = SinkRateTracking {
        sink_rate_mps: 10.0,
        ramp_s: 5.0,
        seconds: 8.0,
    };
    for seed in 1..=3 {
        for pitch in [
            PitchControllerParameters::default(),
            PitchControllerParameters::Pid(PidParameters::default()),
        ] {
            let mut scenario = Conditions::Adverse.apply(Scenario::default(), seed);
            scenario.control.pitch = pitch;
            let run = fly_sink_rate(&scenario, &tracking).unwrap();
            assert_eq!(
                run.summary.outcome,
                Outcome::Completed,
                "seed {seed}, {}: {:?}",
                pitch.label(),
                run.summary.reason
            );
            // The disturbances still act: the sink rate is not the ideal one.
            assert!(run
                .samples
                .iter()
                .any(|s| s.sink_rate_error_mps.abs() > 0.01));
        }
    }
}
