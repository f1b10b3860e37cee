//! `Simulation::step` says why it stopped: stepping a run to its end gives the same
//! result as `run`, the events come as values in the order they happened, and the end
//! comes with its typed reason; what the next step starts from can be looked at between
//! steps (as the Python package's `Approach` does) without changing the run.

use deckland::recording::{SummaryRecorder, TimeSeriesRecorder};
use deckland::scenario::Scenario;
use deckland::simulation::{
    EndReason, Event, NoTaps, Outcome, Overrides, Signals, Simulation, Stop,
};

/// The default scenario with seed 3, which traps (seed 1 waves off:
/// `a_wave_off_is_an_event_then_the_end`).
fn default_approach() -> Scenario {
    Scenario {
        seed: 3,
        ..Scenario::papers_sea()
    }
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
    // The default approach with seed 3 crosses the ramp, then traps.
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
    let scenario = Scenario::papers_sea();
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
        ..Scenario::papers_sea()
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
        if step.is_multiple_of(20) {
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

/// Regression: with the flight-control computer (the realistic default, 80 Hz), the
/// frame's commands were computed without the step's overrides, so a pitch command
/// given from outside never reached the pitch law. Three seconds of a pitch command
/// 4° above trim must bring θ to within 1° of it (the pitch loop settles in about 1.6 s),
/// where the cascade alone holds θ near trim.
#[test]
fn regression_a_pitch_command_reaches_the_flight_computer() {
    let scenario = Scenario::papers_sea();
    assert!(scenario.control.flight_computer_rate_hz.is_some());
    let mut simulation = Simulation::new(&scenario).expect("valid");
    let trim_theta_rad = simulation.signals().theta_ref_rad;
    let command = trim_theta_rad + 4f64.to_radians();
    let overrides = Overrides {
        pitch_command_rad: Some(command),
        ..Overrides::default()
    };
    for _ in 0..3000 {
        simulation.step_with(&mut SummaryRecorder, &overrides);
    }
    let theta_rad = simulation.signals().theta_rad;
    assert!(
        (theta_rad - command).abs() < 1f64.to_radians(),
        "θ {:.2}° against the command {:.2}°",
        theta_rad.to_degrees(),
        command.to_degrees()
    );
}

#[test]
fn a_wave_off_is_an_event_then_the_end() {
    // The default scenario, seed 6, on the estimator: the wave-off decision is an event,
    // the hook then crosses the ramp and passes the last wire in the air, which ends the
    // run as a wave-off with the decision's reason (with the fixed ramp limits, 2.5-m
    // margin and 1.5-m wave-off limit: the risk-aware clearance flies this pass higher).
    let mut scenario = Scenario {
        seed: 6,
        ..Scenario::papers_sea()
    };
    scenario.control.flight_path.ramp_clearance_margin_m = 2.5;
    scenario.control.flight_path.ramp_strike_probability_limit = 0.0;
    scenario.control.wave_off.min_ramp_clearance_m = 1.5;
    scenario.control.wave_off.max_ramp_strike_probability = 0.0;
    let mut simulation = Simulation::new(&scenario).expect("valid");
    let mut events = Vec::new();
    let end = loop {
        match simulation.step(&mut SummaryRecorder) {
            Stop::Running => {}
            Stop::Event(event) => events.push(event),
            Stop::Ended(reason) => break reason,
        }
    };
    assert!(matches!(events[0], Event::WaveOff { .. }), "{events:?}");
    assert!(
        matches!(events[1], Event::RampCrossing { clearance_m, .. } if clearance_m > 0.0),
        "{events:?}"
    );
    assert!(
        matches!(events[2], Event::PassedLastWire { .. }),
        "{events:?}"
    );
    let Event::WaveOff { time_s, decision } = events[0] else {
        unreachable!()
    };
    assert_eq!(
        end,
        EndReason::WaveOff {
            decided_at_s: time_s,
            decision
        }
    );
    assert_eq!(simulation.wave_off_decision(), Some((time_s, decision)));
}

/// A copy of a flight made at any step flies on as the original does, to the bit (a
/// rare-event branch is such a copy, docs/rare-events.md). The default's 80-Hz flight
/// computer has frames of 12.5 steps, so a copy at step 10 006 is made inside one, where
/// the 3-D approach carries the view of the deck it computed at the frame's start.
#[test]
fn a_copy_made_inside_a_frame_flies_on_as_the_original() {
    let scenario = Scenario {
        seed: 3,
        ..Scenario::default()
    };
    let mut original = Simulation::new(&scenario).expect("valid");
    for _ in 0..10_006 {
        original.step(&mut SummaryRecorder);
    }
    let mut copy = original.clone();
    for _ in 0..2_000 {
        original.step(&mut SummaryRecorder);
        copy.step(&mut SummaryRecorder);
    }
    let bits = |simulation: &Simulation| -> Vec<u64> {
        simulation.state().iter().map(|x| x.to_bits()).collect()
    };
    assert_eq!(bits(&original), bits(&copy));
    assert_eq!(original.signals(), copy.signals());
}
