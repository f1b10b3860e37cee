//! Each event's score reaches 0 along a flight exactly when the flight's outcome, as the
//! campaign judges it, is that event (docs/rare-events.md): the reference is the run's
//! own summary (its outcome, ramp clearance and touchdown), a separate path from the
//! score's forecasts. Thresholds are moved so that each event happens in some of the
//! flights and not in others.

use deckland::rare::ramp_forecast::RampForecastTrace;
use deckland::rare::score::{EventScore, EventThresholds, RareEvent};
use deckland::scenario::Scenario;
use deckland::simulation::{Outcome, RunSummary, Simulation};

/// Flies `scenario` with the score of `event`, returning the running maximum of the score
/// and the run's summary.
fn fly(scenario: &Scenario, event: RareEvent, thresholds: EventThresholds) -> (f64, RunSummary) {
    let mut simulation = Simulation::new(scenario).expect("valid");
    let mut score = EventScore::new(event, thresholds, scenario, &simulation);
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

/// Checks the score against the summary over `seeds` flights of `base`, and that the
/// event happened in some and not in all.
fn check(base: Scenario, event: RareEvent, thresholds: EventThresholds, seeds: u64) {
    let mut count = 0;
    for seed in 0..seeds {
        let scenario = Scenario { seed, ..base };
        let (maximum, summary) = fly(&scenario, event, thresholds);
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
