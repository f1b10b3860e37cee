//! At the start of a flight-computer frame the run loop evaluates the loop once, for the
//! frame's commands and the step's signals and rate together, where the taps say that
//! holding a command they already gave changes nothing (`Taps::idempotent`). Taps that
//! do not say so take the loop's general path: the frame's commands from one
//! evaluation, then the step's own evaluation with the commands held. Both paths must fly
//! the same run, bit for bit.

mod common;

use common::crosswind;
use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{LoopBreak, NoTaps, Overrides, Simulation, Stop, Taps};

/// The taps `T`, not declared idempotent: the general path, two evaluations per frame.
struct TwoEvaluations<'a, T: Taps>(&'a T);

impl<T: Taps> Taps for TwoEvaluations<'_, T> {
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        self.0.tap(at, computed)
    }
}

/// Steps two runs of `scenario` side by side, one with `taps` and one with the same
/// taps on the general path, to the end (at most `steps`), comparing every stop, the
/// state after every step and the summaries.
fn assert_same_run<T: Taps>(scenario: &Scenario, taps: &T, steps: usize) {
    assert!(
        taps.idempotent(),
        "the taps under test take the one-evaluation path"
    );
    let general = TwoEvaluations(taps);
    assert!(!general.idempotent());
    let mut once = Simulation::new(scenario).expect("valid");
    let mut twice = Simulation::new(scenario).expect("valid");
    for step in 0..steps {
        let a = once.step_with(&mut SummaryRecorder, taps);
        let b = twice.step_with(&mut SummaryRecorder, &general);
        assert_eq!(a, b, "step {step}");
        assert_eq!(
            once.state().iter().map(|v| v.to_bits()).collect::<Vec<_>>(),
            twice
                .state()
                .iter()
                .map(|v| v.to_bits())
                .collect::<Vec<_>>(),
            "state after step {step}"
        );
        if matches!(a, Stop::Ended(_)) {
            break;
        }
    }
    assert_eq!(once.summary(), twice.summary());
}

#[test]
fn a_frame_evaluated_once_flies_the_run_of_two_evaluations() {
    // The default approach flies the flight computer (80 Hz on 1-ms steps); seed 1 waves
    // off, so the wave-off's commands are held by frames too.
    for seed in [1, 3] {
        let scenario = Scenario {
            seed,
            ..Scenario::default()
        };
        assert_eq!(scenario.control.flight_computer_rate_hz, Some(80.0));
        assert_same_run(&scenario, &NoTaps, 60_000);
    }
}

#[test]
fn a_frame_evaluated_once_flies_the_run_of_two_evaluations_with_overrides() {
    let scenario = Scenario {
        seed: 3,
        ..Scenario::default()
    };
    let overrides = Overrides {
        pitch_command_rad: Some(0.1),
        thrust_n: Some(60_000.0),
        ..Overrides::default()
    };
    assert_same_run(&scenario, &overrides, 8000);
}

#[test]
fn a_frame_evaluated_once_flies_the_run_of_two_evaluations_in_the_3d_approach() {
    // The crosswind approach: the lateral laws' aileron and rudder commands are held by
    // the frames too, and the lineup guidance runs at them.
    let scenario = crosswind();
    assert!(scenario.control.flight_computer_rate_hz.is_some());
    assert_same_run(&scenario, &NoTaps, 30_000);
    let overrides = Overrides {
        bank_command_rad: Some(0.02),
        rudder_rad: Some(0.0),
        ..Overrides::default()
    };
    assert_same_run(&scenario, &overrides, 3000);
}
