//! `Simulation::step` says why it stopped: stepping a run to its end gives the same
//! result as `run`, the events come as values in the order they happened, and the end
//! comes with its typed reason.

use deckland::recording::{SummaryRecorder, TimeSeriesRecorder};
use deckland::scenario::Scenario;
use deckland::simulation::{EndReason, Event, Outcome, Overrides, Simulation, Stop};

fn default_approach() -> Scenario {
    Scenario::default()
}

#[test]
fn stepping_to_the_end_equals_running_and_reports_events_in_order() {
    let scenario = default_approach();
    let expected = Simulation::new(&scenario)
        .expect("valid")
        .run(&mut SummaryRecorder);
    let mut simulation = Simulation::new(&scenario).expect("valid");
    let mut recorder = TimeSeriesRecorder::every(0.01);
    let mut events = Vec::new();
    let mut steps = 0_u64;
    let end = loop {
        match simulation.step(&mut recorder) {
            Stop::Running => steps += 1,
            Stop::Event(event) => events.push(event),
            Stop::Ended(reason) => break reason,
        }
        assert!(steps < 200_000, "the run did not end");
    };
    let summary = simulation.summary().expect("ended").clone();
    assert_eq!(summary, expected);
    assert_eq!(end.outcome(), summary.outcome);
    assert_eq!(end.description(), summary.reason);
    // The recorder saw the same events, and the run asks no more of step().
    assert_eq!(recorder.events, events);
    assert_eq!(simulation.step(&mut recorder), Stop::Ended(end.clone()));
    // The default approach (seed 1) crosses the ramp, then traps.
    assert_eq!(summary.outcome, Outcome::Trap);
    assert!(
        matches!(events[0], Event::RampCrossing { .. }),
        "{events:?}"
    );
    assert!(matches!(events[1], Event::Touchdown(_)), "{events:?}");
    assert!(matches!(end, EndReason::Trap { wire } if Some(wire) == summary.wire));
}

#[test]
fn overrides_that_replace_nothing_change_nothing() {
    let scenario = default_approach();
    let mut plain = Simulation::new(&scenario).expect("valid");
    let mut tapped = Simulation::new(&scenario).expect("valid");
    for _ in 0..5000 {
        let a = plain.step(&mut SummaryRecorder);
        let b = tapped.step_with(&mut SummaryRecorder, &Overrides::default());
        assert_eq!(a, b);
    }
    assert_eq!(plain.state(), tapped.state());
}

#[test]
fn a_full_thrust_override_reaches_the_engines_and_speeds_the_aircraft_up() {
    let scenario = default_approach();
    let mut simulation = Simulation::new(&scenario).expect("valid");
    let full = Overrides {
        thrust_n: Some(2.0 * 71_172.0),
        ..Overrides::default()
    };
    for _ in 0..5000 {
        simulation.step_with(&mut SummaryRecorder, &full);
    }
    // Five seconds of full thrust instead of the speed loop's trim thrust: the engines
    // spool up (0.625 s lag) and the aircraft accelerates.
    let signals = simulation.signals();
    assert!(signals.airspeed_mps > 72.0, "{}", signals.airspeed_mps);
    assert!(signals.thrust_n > 130_000.0, "{}", signals.thrust_n);
}
