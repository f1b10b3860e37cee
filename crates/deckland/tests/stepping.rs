//! The stepping interface of `Simulation` as the Python package's `Approach` uses it:
//! what the next step starts from, looked at between steps without changing the run.

use deckland::recording::{SummaryRecorder, TimeSeriesRecorder};
use deckland::scenario::Scenario;
use deckland::simulation::{NoTaps, Overrides, Signals, Simulation, Stop};

/// The signals the next step starts from, as `Approach` observes them.
fn next_step_signals(simulation: &mut Simulation) -> Signals {
    let held = simulation.next_step_inputs();
    let mut rate = vec![0.0; simulation.state().len()];
    simulation.system().evaluate(
        simulation.time_s(),
        simulation.state(),
        &held,
        &NoTaps,
        &mut rate,
    )
}

/// Regression: `Simulation::signals` before the first step panicked in an approach (no
/// deck reference held yet). It now shows the signals the first step starts from.
#[test]
fn regression_signals_before_the_first_step_are_those_of_the_first_step() {
    let scenario = Scenario::default();
    let simulation = Simulation::new(&scenario).expect("valid");
    let before = simulation.signals();

    let mut recorder = TimeSeriesRecorder::every(scenario.time_step_s);
    let mut stepped = simulation.clone();
    stepped.step(&mut recorder);
    assert_eq!(recorder.samples[0], before);
    // Looking did not draw from the random streams: the run is unchanged.
    let looked_at = simulation.run(&mut SummaryRecorder);
    let fresh = Simulation::new(&scenario)
        .expect("valid")
        .run(&mut SummaryRecorder);
    assert_eq!(looked_at, fresh);
}

#[test]
fn the_next_step_starts_from_the_signals_looked_at_and_the_run_is_unchanged() {
    let scenario = Scenario {
        seed: 5,
        ..Scenario::default()
    };
    let expected = Simulation::new(&scenario)
        .expect("valid")
        .run(&mut SummaryRecorder);
    let mut simulation = Simulation::new(&scenario).expect("valid");
    let mut recorder = TimeSeriesRecorder::every(scenario.time_step_s);
    let mut looked_at = Vec::new();
    loop {
        // Look every 20 steps, as `Approach` does, with no override.
        let step = recorder.samples.len();
        if step % 20 == 0 {
            looked_at.push((step, next_step_signals(&mut simulation)));
            assert!(simulation.next_step_inputs().deck.is_some());
        }
        if let Stop::Ended(_) = simulation.step_with(&mut recorder, &Overrides::default()) {
            break;
        }
    }
    assert_eq!(simulation.summary(), Some(&expected));
    assert!(looked_at.len() > 1000);
    for (step, signals) in looked_at {
        assert_eq!(recorder.samples[step], signals, "step {step}");
    }
    // After the end: the signals of the last step, again.
    let last = recorder.samples.last().expect("samples");
    assert_eq!(&next_step_signals(&mut simulation), last);
}
