//! Splitting on approaches (docs/rare-events.md): a flight that reached the event, flown
//! again from the start along its branches, reaches it again, bit for bit; the result
//! does not depend on the thread count, nor on where the repetitions are flown; bad
//! requests are named.

use deckland::rare::{
    estimate_rate, estimate_rate_batched, fly_repetition, replay_event_flight, run, AmsError,
    ApproachFlight, EventThresholds, RareEvent, RareRequest, Settings,
};
use deckland::scenario::Scenario;

/// The paper's set in the paper's sea with the longitudinal aircraft: fast, and the
/// hook often crosses the ramp less than 3 m above it.
fn scenario() -> Scenario {
    Scenario {
        seed: 17,
        ..Scenario::paper()
    }
}

#[test]
fn a_flight_that_reached_the_event_reaches_it_again_when_replayed() {
    let scenario = scenario();
    let thresholds = EventThresholds::of(&scenario).with(RareEvent::RampStrike, 2.0);
    let start = ApproachFlight::new(&scenario, RareEvent::RampStrike, thresholds).expect("valid");
    let settings = Settings {
        particles: 8,
        killed_per_iteration: 2,
        checkpoint_every: 1000,
        ..Settings::new(0.0)
    };
    let result = run(&start, &settings, 5, 10_000_000).expect("runs");
    assert!(!result.events.is_empty(), "{result:?}");
    for particle in &result.events {
        let flight = replay_event_flight(&scenario, thresholds, RareEvent::RampStrike, particle)
            .expect("valid")
            .expect("recorded");
        let clearance = flight.summary.ramp_clearance_m.expect("crossed the ramp");
        assert!(clearance < 2.0, "replayed clearance {clearance} m");
        // Recorded as `land` records: every 10 ms from the start.
        assert_eq!(flight.samples[0].time_s, 0.0);
        assert!((flight.samples[1].time_s - 0.01).abs() < 1e-9);
    }
}

/// A branch replays from the copy before it: where the copies are taken must not change
/// the flights, also for the default's 3-D approach in the seaway, whose lateral part keeps
/// state of its own (a view of the deck, the last roll measurement). A copy every 100
/// steps and one every 1000 give the same run, the sparser one replaying more steps.
#[test]
fn where_the_copies_are_taken_does_not_change_a_three_dimensional_run() {
    let scenario = Scenario {
        seed: 23,
        ..Scenario::default()
    };
    // In sea state 5 the hook crosses the ramp 3.7 m above it, with a spread of 0.2 m:
    // 3.6 m is reached by a few levels.
    let thresholds = EventThresholds::of(&scenario).with(RareEvent::RampStrike, 3.6);
    let start = ApproachFlight::new(&scenario, RareEvent::RampStrike, thresholds).expect("valid");
    let runs: Vec<_> = [100, 1000]
        .into_iter()
        .map(|checkpoint_every| {
            let settings = Settings {
                particles: 6,
                killed_per_iteration: 2,
                checkpoint_every,
                ..Settings::new(0.0)
            };
            run(&start, &settings, 9, 10_000_000).expect("runs")
        })
        .collect();
    assert!(
        runs[0].estimate.is_some() && runs[0].iterations > 0,
        "{:?}",
        runs[0]
    );
    assert_eq!(runs[0].estimate, runs[1].estimate);
    assert_eq!(runs[0].levels, runs[1].levels);
    assert_eq!(runs[0].events, runs[1].events);
    assert!(runs[0].steps < runs[1].steps);
}

#[test]
fn the_estimate_is_the_same_on_one_and_on_two_threads() {
    let request = RareRequest {
        threshold: Some(1.0),
        particles: 8,
        max_runs: 300,
        ..RareRequest::new(RareEvent::RampStrike, 3)
    };
    let on = |threads| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool")
            .install(|| estimate_rate(&scenario(), &request, |_, _| {}))
            .expect("estimate")
    };
    let one = on(1);
    assert!(one.estimate.repetitions >= 1);
    assert_eq!(one, on(2));
}

#[test]
fn repetitions_flown_one_by_one_elsewhere_give_the_same_estimate() {
    // What Dask's workers do (deckland.dask.rare): each repetition flown by itself from the
    // scenario and the request, the batches driven by estimate_rate_batched.
    let request = RareRequest {
        threshold: Some(1.0),
        particles: 8,
        max_runs: 300,
        ..RareRequest::new(RareEvent::RampStrike, 3)
    };
    let whole = estimate_rate(&scenario(), &request, |_, _| {}).expect("estimate");
    let mut batches = Vec::new();
    let batched = estimate_rate_batched(
        &scenario(),
        &request,
        |repetitions, share| {
            batches.push(repetitions.clone());
            repetitions
                .map(|r| {
                    fly_repetition(&scenario(), &request, r, share)
                        .map_err(|e| AmsError::Batch(e.to_string()))
                })
                .collect()
        },
        |_, _| {},
    )
    .expect("estimate");
    assert_eq!(whole, batched);
    assert_eq!(batches.first(), Some(&(0..8)));
    // A batch that does not come back whole ends the estimate with a named error.
    let short = estimate_rate_batched(&scenario(), &request, |_, _| Vec::new(), |_, _| {});
    assert!(
        matches!(&short, Err(e) if e.to_string().contains("0 runs came back for the 8 repetitions from 0")),
        "{short:?}"
    );
}

#[test]
fn bad_requests_are_named() {
    let scenario = scenario();
    let error = |request: RareRequest| {
        estimate_rate(&scenario, &request, |_, _| {})
            .expect_err("refused")
            .to_string()
    };
    let base = RareRequest::new(RareEvent::RampStrike, 1);
    let message = error(RareRequest {
        target_rel_error: 0.0,
        ..base
    });
    assert!(message.contains("target_rel_error"), "{message}");
    let message = error(RareRequest {
        threshold: Some(-1e9),
        ..base
    });
    assert!(
        message.contains("threshold") && message.contains("-1000000000"),
        "{message}"
    );
    let message = error(RareRequest {
        threshold: Some(1.0),
        ..RareRequest::new(RareEvent::Lost, 1)
    });
    assert!(message.contains("no threshold"), "{message}");
    let message = error(RareRequest::new(RareEvent::OffCentre, 1));
    assert!(
        message.contains("3-D approach") && message.contains("`cross_track_m`"),
        "{message}"
    );
    // Only the ramp's score has a calibration.
    let message = error(RareRequest {
        calibration_runs: 10,
        ..RareRequest::new(RareEvent::HardLanding, 1)
    });
    assert!(
        message.contains("rare.calibration_runs") && message.contains("hard_landing"),
        "{message}"
    );
    let message = error(RareRequest {
        calibration_runs: 1_000_000,
        ..base
    });
    assert!(message.contains("rare.calibration_runs"), "{message}");
}
