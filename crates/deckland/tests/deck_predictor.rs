//! The deck-motion predictors in the closed loop: the `oracle` flies the `estimator`'s
//! design with the ship's true state in place of the estimate, so that the two differ
//! only in what they know (docs/model.md §5.7).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::control::DeckMotionPredictor;
use deckland::recording::{SummaryRecorder, TimeSeriesRecorder};
use deckland::scenario::Scenario;
use deckland::simulation::Simulation;

/// The default (realistic) scenario in the moderate sea of docs/model.md §3.6 with
/// `predictor`.
fn moderate_sea(seed: u64, predictor: DeckMotionPredictor) -> Scenario {
    let mut scenario = Scenario {
        seed,
        ..Scenario::default()
    };
    scenario.environment.ship.heave_rms_m = 1.0;
    scenario.environment.ship.pitch_rms_deg = 0.75;
    scenario.control.flight_path.deck_motion_predictor = predictor;
    scenario
}

/// The largest jump of the glide path's climb rate between two 10-ms samples (m/s):
/// the second difference of the path's height over the sample time.
fn largest_path_rate_jump(scenario: &Scenario) -> f64 {
    let dt = 0.01;
    let mut recorder = TimeSeriesRecorder::every(dt);
    Simulation::new(scenario).unwrap().run(&mut recorder);
    let heights: Vec<f64> = recorder
        .samples
        .iter()
        .filter_map(|s| s.path_height_m)
        .collect();
    heights
        .windows(3)
        .map(|w| ((w[2] - w[1]) - (w[1] - w[0])).abs() / dt)
        .fold(0.0, f64::max)
}

/// Before the `oracle` shaped its anchor as the `estimator` does, its path jumped by
/// 0.19–0.28 m in single 10-ms samples (a climb rate jumping by 19–28 m/s, seeds 1–5):
/// the forecast from the true state moves with the noise that drives the ship. With the
/// shared anchor filter both stay below 5 m/s; what remains is the designed kink where
/// the path starts to shed its ramp-aware raise (raise × closure / ramp distance, about
/// 1 m/s per metre of raise).
#[test]
fn the_oracle_flies_the_estimators_smooth_path() {
    for seed in 1..=5 {
        for predictor in [DeckMotionPredictor::Estimator, DeckMotionPredictor::Oracle] {
            let jump = largest_path_rate_jump(&moderate_sea(seed, predictor));
            assert!(jump < 5.0, "seed {seed}, {predictor:?}: {jump:.2} m/s");
        }
    }
}

/// Standard deviation of the touchdown distances of seeds 1–40 in the moderate sea with
/// `predictor`, over the runs that touched down.
fn touchdown_spread(predictor: DeckMotionPredictor) -> f64 {
    let distances: Vec<f64> = (1..=40)
        .filter_map(|seed| {
            let summary = Simulation::new(&moderate_sea(seed, predictor))
                .unwrap()
                .run(&mut SummaryRecorder);
            summary.touchdown.map(|t| t.distance_from_aim_m)
        })
        .collect();
    let n = distances.len() as f64;
    let mean = distances.iter().sum::<f64>() / n;
    let variance = distances.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1.0);
    variance.sqrt()
}

/// Knowing the ship's true state can only help the same design: over 1000 runs the
/// oracle's touchdown σ is 5.67 m against the estimator's 6.52 m (0.87×;
/// docs/no-oracle-results.md), over these 40 seeds 5.10 against 5.70 m. The oracle that
/// flew its unfiltered forecast scattered more than the estimator (1000 runs: 6.97
/// against 6.52 m; 6.75 against 6.35 m without wind), which made the comparison say that
/// estimation cost nothing.
#[test]
fn perfect_knowledge_of_the_ship_tightens_the_same_designs_touchdowns() {
    let estimator = touchdown_spread(DeckMotionPredictor::Estimator);
    let oracle = touchdown_spread(DeckMotionPredictor::Oracle);
    assert!(
        oracle < 0.95 * estimator,
        "touchdown σ {oracle:.2} m on the oracle against {estimator:.2} m on the estimator"
    );
}
