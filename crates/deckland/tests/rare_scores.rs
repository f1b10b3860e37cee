//! Each event's score reaches 0 along a flight exactly when the flight's outcome, as the
//! campaign judges it, is that event (docs/rare-events.md): the reference is the run's
//! own summary (its outcome, ramp clearance and touchdown), a separate path from the
//! score's forecasts. Thresholds are moved so that each event happens in some of the
//! flights and not in others.

use std::sync::Arc;

use deckland::monte_carlo::{dispersed_run_scenario, run_seed};
use deckland::rare::ramp_forecast::RampForecastTrace;
use deckland::rare::score::{EventScore, EventThresholds, RareEvent};
use deckland::rare::RampCalibration;
use deckland::scenario::{load_scenario, Scenario};
use deckland::simulation::{Outcome, RunSummary, Simulation};

/// Flies `scenario` with the score of `event` (the ramp's calibrated by `calibration`),
/// returning the running maximum of the score and the run's summary.
fn fly(
    scenario: &Scenario,
    event: RareEvent,
    thresholds: EventThresholds,
    calibration: Option<Arc<RampCalibration>>,
) -> (f64, RunSummary) {
    let mut simulation = Simulation::new(scenario).expect("valid");
    let mut score = EventScore::new(event, thresholds, scenario, &simulation)
        .with_ramp_calibration(calibration);
    let mut maximum = f64::NEG_INFINITY;
    loop {
        score.observe(&simulation);
        if simulation.advance(&mut score).is_some() {
            break;
        }
        maximum = maximum.max(score.score());
    }
    maximum = maximum.max(score.score());
    assert!(score.finished());
    (maximum, simulation.summary().expect("ended").clone())
}

/// Whether the summary shows `event` under `thresholds`, as the campaign's columns do.
fn happened(summary: &RunSummary, event: RareEvent, thresholds: &EventThresholds) -> bool {
    let ramp = summary
        .ramp_clearance_m
        .is_some_and(|c| c < thresholds.ramp_clearance_m);
    let touchdown = summary.touchdown.filter(|_| !ramp);
    let hard = touchdown.is_some_and(|t| t.sink_rate_mps > thresholds.hard_landing_sink_rate_mps);
    let off_centre = touchdown
        .and_then(|t| t.lateral)
        .is_some_and(|l| l.offset_m.abs() > thresholds.off_centre_m);
    let diverged = summary.outcome == Outcome::Diverged;
    match event {
        RareEvent::RampStrike => ramp,
        RareEvent::HardLanding => hard,
        RareEvent::OffCentre => off_centre,
        RareEvent::Divergence => diverged,
        RareEvent::Lost => ramp || hard || off_centre || diverged,
    }
}

/// Checks the score (the ramp's calibrated by `calibration`) against the summary over
/// `seeds` flights of `base`, and that the event happened in some and not in all.
fn check_with(
    base: Scenario,
    event: RareEvent,
    thresholds: EventThresholds,
    seeds: u64,
    calibration: Option<Arc<RampCalibration>>,
) {
    let mut count = 0;
    for seed in 0..seeds {
        let scenario = Scenario { seed, ..base };
        let (maximum, summary) = fly(&scenario, event, thresholds, calibration.clone());
        let expected = happened(&summary, event, &thresholds);
        assert_eq!(
            maximum >= 0.0,
            expected,
            "{} seed {seed}: score {maximum}, summary {summary:?}",
            event.name()
        );
        count += usize::from(expected);
    }
    assert!(
        count > 0 && count < seeds as usize,
        "{}: the event happened in {count} of {seeds} flights",
        event.name()
    );
}

/// [`check_with`] the plain score.
fn check(base: Scenario, event: RareEvent, thresholds: EventThresholds, seeds: u64) {
    check_with(base, event, thresholds, seeds, None);
}

#[test]
fn the_ramp_score_reaches_zero_exactly_when_the_hook_crosses_below_the_threshold() {
    let base = Scenario::papers_sea();
    let thresholds = EventThresholds::of(&base).with(RareEvent::RampStrike, 3.0);
    check(base, RareEvent::RampStrike, thresholds, 24);
}

#[test]
fn the_touchdown_scores_reach_zero_exactly_at_a_hard_or_off_centre_touchdown() {
    let base = Scenario::papers_sea();
    let thresholds = EventThresholds::of(&base)
        .with(RareEvent::HardLanding, 2.5)
        .with(RareEvent::OffCentre, 0.3);
    check(base, RareEvent::HardLanding, thresholds, 24);
    check(base, RareEvent::OffCentre, thresholds, 24);
    check(
        base,
        RareEvent::Lost,
        thresholds.with(RareEvent::RampStrike, 3.0),
        24,
    );
}

#[test]
fn the_divergence_score_reaches_zero_exactly_when_the_run_diverges() {
    // A minimum airspeed 3 m/s under the approach speed: some flights fall below it.
    let mut base = Scenario::papers_sea();
    base.outcome.min_airspeed_mps = base.approach.airspeed_mps - 3.0;
    check(base, RareEvent::Divergence, EventThresholds::of(&base), 24);
}

#[test]
fn event_names_round_trip_and_an_unknown_one_is_named() {
    for event in RareEvent::ALL {
        assert_eq!(RareEvent::from_name(event.name()), Ok(event));
    }
    let error = RareEvent::from_name("crash").expect_err("unknown");
    assert!(
        error.contains("`crash`") && error.contains("ramp_strike"),
        "{error}"
    );
}

/// The ramp score is a forecast of the clearance in units of how far it may miss, so
/// that splitting can rank flights by it (docs/rare-events.md): over 100 approaches in
/// the paper's adverse conditions, the clearance flown, against the forecast made 0.5,
/// 2 and 5 s before the crossing, misses by z = (flown − ĉ)/σ with a mean within 0.6 of
/// 0 and an SD within 0.75–1.35 (3000 approaches measured 0.47 and 1.1 at 0.5–1 s ahead,
/// the worst). A forecast that missed by twice its spread, as one carrying the ramp at
/// its present rate does, fails. The reference is the crossing the flight reports, a
/// separate path from the score.
#[test]
fn the_ramp_forecast_misses_by_about_its_own_spread() {
    let base = Scenario::paper();
    let flights: Vec<_> = (0..100)
        .map(|seed| RampForecastTrace::fly(&Scenario { seed, ..base }).expect("valid"))
        .collect();
    for ahead_s in [0.5, 2.0, 5.0] {
        let z: Vec<f64> = flights
            .iter()
            .filter_map(|flight| flight.miss(ahead_s))
            .map(|(miss_m, sigma_m)| miss_m / sigma_m)
            .collect();
        let n = z.len() as f64;
        let mean = z.iter().sum::<f64>() / n;
        let sd = (z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        assert!(n >= 90.0, "{n} flights crossed the ramp");
        eprintln!("{ahead_s} s ahead: z mean {mean:.3}, SD {sd:.3} over {n} flights");
        assert!(
            mean.abs() < 0.6 && (0.75..1.35).contains(&sd),
            "{ahead_s} s ahead: z mean {mean:.3}, SD {sd:.3} over {n} flights"
        );
    }
}

/// Calibrated (`--calibrate-score`), the ramp score still reaches 0 exactly when the hook
/// crosses below the threshold: the calibration moves the forecast and its spread, never
/// the decision. Calibrated on 20 flights of other seeds.
#[test]
fn the_calibrated_ramp_score_reaches_zero_exactly_when_the_hook_crosses_below_the_threshold() {
    let base = Scenario::papers_sea();
    let calibration = RampCalibration::fly(&base, 99, 20).expect("flights crossed the ramp");
    let thresholds = EventThresholds::of(&base).with(RareEvent::RampStrike, 3.0);
    let calibration = Some(Arc::new(calibration));
    check_with(
        base,
        RareEvent::RampStrike,
        thresholds,
        24,
        calibration.clone(),
    );
    check_with(base, RareEvent::Lost, thresholds, 24, calibration);
}

/// The calibration is each bin's mean and sample SD of the clearance flown less the
/// forecast, computed by hand here for two flights and two bins; a flight that never
/// crossed the ramp does not count, and beyond the last bin the last one holds.
#[test]
fn the_calibration_is_the_mean_and_spread_of_the_misses_in_each_bin() {
    let trace = |crossing: Option<(f64, f64)>, forecasts: [(f64, f64); 2]| RampForecastTrace {
        forecasts: forecasts.iter().map(|&(_, c)| (0.0, c, 1.0)).collect(),
        ahead_s: forecasts.iter().map(|&(ahead, _)| ahead).collect(),
        crossing,
    };
    let traces = [
        trace(Some((10.0, 3.0)), [(0.15, 3.5), (0.05, 2.9)]),
        trace(Some((10.0, 2.0)), [(0.15, 1.0), (0.05, 2.2)]),
        trace(None, [(0.15, 50.0), (0.05, 50.0)]),
    ];
    let calibration = RampCalibration::of(&traces).expect("two crossings");
    assert_eq!(calibration.flights, 2);
    // Bin 0: misses 0.1 and −0.2; bin 1: −0.5 and 1.0.
    let (mean, spread) = calibration.at(0.05);
    assert!((mean - -0.05).abs() < 1e-12, "{mean}");
    assert!((spread - 0.045_f64.sqrt()).abs() < 1e-12, "{spread}");
    let (mean, spread) = calibration.at(0.15);
    assert!((mean - 0.25).abs() < 1e-12, "{mean}");
    assert!((spread - 1.125_f64.sqrt()).abs() < 1e-12, "{spread}");
    assert_eq!(calibration.at(30.0), calibration.at(0.15));
    assert!((calibration.spread_now_m() - 0.045_f64.sqrt()).abs() < 1e-12);
    assert!(RampCalibration::of(&traces[1..]).is_none());
}

/// The calibrated forecast misses fresh flights by about its own spread with a mean near
/// 0 in sea state 5, where the plain one misses by −0.8 m, six of the flights' SDs but
/// only 1.2 of the σ it divides by, 4 s before the crossing (docs/rare-events.md):
/// calibrated on 40 flights, checked on 40 others at 0.5, 2 and 4 s ahead, z = (flown −
/// ĉ − mean)/spread has |mean| < 0.8 (the calibration's own mean is uncertain by about
/// 0.3 of a spread over 40 flights) and an SD of 0.6–1.6; the plain forecast's z =
/// (flown − ĉ)/σ, 4 s ahead, has an SD below 0.4. The reference is the crossing each
/// flight reports.
#[test]
fn the_calibrated_ramp_forecast_misses_fresh_flights_by_about_its_spread() {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenarios/sea-state-5.toml"
    ))
    .expect("shipped");
    let base = load_scenario(&text, "sea-state-5.toml").expect("valid");
    let calibration = RampCalibration::fly(&base, 7, 40).expect("flights crossed the ramp");
    let flights: Vec<_> = (0..40)
        .map(|i| {
            let (flown, _) = dispersed_run_scenario(&base, run_seed(8, i));
            RampForecastTrace::fly(&flown).expect("valid")
        })
        .collect();
    // (calibrated z, plain z) of each flight that crossed, `ahead_s` before the crossing.
    let misses = |ahead_s: f64| -> Vec<(f64, f64)> {
        flights
            .iter()
            .filter_map(|flight| {
                let (crossing_s, clearance_m) = flight.crossing?;
                let k = flight
                    .forecasts
                    .iter()
                    .rposition(|(t, _, _)| crossing_s - t >= ahead_s)?;
                let (_, forecast_m, sigma_m) = flight.forecasts[k];
                let (mean_m, spread_m) = calibration.at(flight.ahead_s[k]);
                let miss_m = clearance_m - forecast_m;
                Some(((miss_m - mean_m) / spread_m, miss_m / sigma_m))
            })
            .collect()
    };
    let mean_sd = |z: &[f64]| {
        let n = z.len() as f64;
        let mean = z.iter().sum::<f64>() / n;
        let sd = (z.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        (mean, sd)
    };
    for ahead_s in [0.5, 2.0, 4.0] {
        let rows = misses(ahead_s);
        assert!(rows.len() >= 38, "{} flights crossed the ramp", rows.len());
        let calibrated: Vec<f64> = rows.iter().map(|r| r.0).collect();
        let (mean, sd) = mean_sd(&calibrated);
        eprintln!("{ahead_s} s ahead: calibrated z mean {mean:.3}, SD {sd:.3}");
        assert!(
            mean.abs() < 0.8 && (0.6..1.6).contains(&sd),
            "{ahead_s} s ahead: z mean {mean:.3}, SD {sd:.3}"
        );
    }
    let plain: Vec<f64> = misses(4.0).iter().map(|r| r.1).collect();
    let (mean, sd) = mean_sd(&plain);
    eprintln!("4 s ahead: plain z mean {mean:.3}, SD {sd:.3}");
    assert!(sd < 0.4, "plain z mean {mean:.3}, SD {sd:.3}");
}

/// The calibration's flights give the same calibration, to the bit, on one thread and
/// on three.
#[test]
fn the_calibration_does_not_depend_on_the_thread_count() {
    let base = Scenario::papers_sea();
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a pool");
        pool.install(|| RampCalibration::fly(&base, 5, 6))
    };
    let one = on(1).expect("flights crossed the ramp");
    assert_eq!(Some(one.clone()), on(3));
    assert_eq!(one.flights, 6);
}
