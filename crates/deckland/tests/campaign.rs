//! Monte Carlo campaigns: identical results on any thread count, failed runs as data,
//! a clean early stop.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use deckland::control::SinkRateControllerParameters;
use deckland::monte_carlo::{run_campaign, run_seed, CampaignSpec, RunFailure, RunRecord};
use deckland::scenario::Scenario;
use deckland::simulation::Outcome;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};

/// Adverse conditions, a short approach (600 m) and every dispersion on.
fn short_dispersed_scenario() -> Scenario {
    let mut scenario = Scenario::default();
    scenario.approach.start_range_m = 600.0;
    scenario.dispersion = common::every_dispersion();
    scenario
}

fn no_progress(_: &RunRecord) {}

#[test]
fn one_and_two_threads_give_identical_records() {
    let spec = CampaignSpec::new(short_dispersed_scenario(), 20, 7);
    let never = AtomicBool::new(false);
    let one = run_campaign(&spec, 1, &no_progress, &never).unwrap();
    let two = run_campaign(&spec, 2, &no_progress, &never).unwrap();
    assert_eq!(one, two);
    assert!(!one.partial);
    assert_eq!(one.records.len(), 20);
    for (index, record) in one.records.iter().enumerate() {
        assert_eq!(record.run_index, index as u64);
        assert_eq!(record.seed, run_seed(7, index as u64));
    }
    // The dispersions are drawn per run: they differ between runs.
    assert_ne!(one.records[0].dispersion, one.records[1].dispersion);
    let statistics = &one.statistics()[0];
    assert_eq!(statistics.runs, 20);
    assert!(statistics.boarding.count > 0, "{statistics:?}");
}

#[test]
fn comparing_controllers_flies_the_same_seeds_and_dispersions_under_each() {
    let spec = CampaignSpec::new(short_dispersed_scenario(), 3, 11).comparing_pitch_controllers();
    let result = run_campaign(&spec, 2, &no_progress, &AtomicBool::new(false)).unwrap();
    assert_eq!(result.controller_labels, ["O-PD", "PID"]);
    assert_eq!(result.records.len(), 6);
    for pair in result.records.chunks(2) {
        assert_eq!((pair[0].controller, pair[1].controller), (0, 1));
        assert_eq!(pair[0].seed, pair[1].seed);
        assert_eq!(pair[0].dispersion, pair[1].dispersion);
    }
    assert_eq!(result.statistics().len(), 2);
}

#[test]
fn a_campaign_that_always_diverges_completes_and_reports_it() {
    // Sink-rate gains of the wrong sign (positive feedback of the climb-rate error) and
    // a start 15 m below the glide path: the aircraft dives into the sea, every run diverges.
    let mut scenario = Scenario::default();
    scenario.control.sink_rate = SinkRateControllerParameters {
        proportional_rad_per_mps: -0.035,
        integral_rad_per_m: -0.012,
        ..SinkRateControllerParameters::default()
    };
    scenario.approach.start_height_offset_m = -15.0;
    let spec = CampaignSpec::new(scenario, 4, 1);
    let result = run_campaign(&spec, 2, &no_progress, &AtomicBool::new(false)).unwrap();
    assert_eq!(result.records.len(), 4);
    let statistics = &result.statistics()[0];
    assert_eq!(statistics.boarding.count, 0, "{statistics:?}");
    assert_eq!(statistics.divergence.count, 4, "{statistics:?}");
    assert_eq!(statistics.divergence.rate, 1.0);
    assert!(statistics.divergence.ci95_low > 0.5 && statistics.divergence.ci95_high == 1.0);
    for record in &result.records {
        assert_eq!(record.outcome_name(), "diverged", "{:?}", record.result);
        assert!(record.failure_reason().is_some());
    }
}

#[test]
fn invalid_dispersed_scenarios_are_rows_with_their_reason() {
    let mut scenario = Scenario::default();
    scenario.approach.start_range_m = 400.0;
    scenario.environment.wind.wind_over_deck_mps = 39.0;
    scenario.dispersion.wind_over_deck_sd_mps = 10.0; // about half the draws exceed 40 m/s
    let spec = CampaignSpec::new(scenario, 8, 3);
    let result = run_campaign(&spec, 2, &no_progress, &AtomicBool::new(false)).unwrap();
    assert_eq!(result.records.len(), 8);
    let invalid: Vec<_> = result
        .records
        .iter()
        .filter(|r| matches!(r.result, Err(RunFailure::Invalid(_))))
        .collect();
    assert!(
        !invalid.is_empty() && invalid.len() < 8,
        "{}",
        invalid.len()
    );
    for record in invalid {
        assert_eq!(record.outcome_name(), "invalid");
        let reason = record.failure_reason().unwrap();
        assert!(reason.contains("wind_over_deck_mps"), "{reason}");
    }
    assert_eq!(
        result.statistics()[0].invalid.count,
        result.records.iter().filter(|r| r.result.is_err()).count() as u64
    );
}

#[test]
fn a_stop_request_keeps_the_finished_runs_and_marks_the_result_partial() {
    let mut scenario = Scenario::default().ideal();
    scenario.approach.start_range_m = 400.0;
    let spec = CampaignSpec::new(scenario, 50, 5);
    let stop = AtomicBool::new(false);
    let finished = AtomicUsize::new(0);
    let stop_after_three = |_: &RunRecord| {
        if finished.fetch_add(1, Ordering::SeqCst) + 1 >= 3 {
            stop.store(true, Ordering::SeqCst);
        }
    };
    let result = run_campaign(&spec, 2, &stop_after_three, &stop).unwrap();
    assert!(result.partial);
    assert!(
        (3..=4).contains(&result.records.len()),
        "{}",
        result.records.len()
    );
    assert!(result
        .records
        .windows(2)
        .all(|w| w[0].run_index < w[1].run_index));
    assert!(result
        .records
        .iter()
        .all(|r| r.result.as_ref().is_ok_and(|s| s.outcome == Outcome::Trap)));
}
