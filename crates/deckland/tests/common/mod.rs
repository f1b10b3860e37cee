//! Helpers shared by the closed-loop tests of the moderate sea.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::Simulation;

/// The default (realistic) scenario with `seed` in the moderate sea of docs/model.md §3.6
/// (heave 1.0 m, pitch 0.75° RMS).
pub fn moderate_sea(seed: u64) -> Scenario {
    let mut scenario = Scenario {
        seed,
        ..Scenario::default()
    };
    scenario.environment.ship.heave_rms_m = 1.0;
    scenario.environment.ship.pitch_rms_deg = 0.75;
    scenario
}

/// The sample standard deviation (m) of the touchdown distances of `scenario(seed)` for
/// seeds 1–40, over the runs that touched down, and their number.
pub fn touchdown_spread(scenario: impl Fn(u64) -> Scenario) -> (f64, usize) {
    let distances: Vec<f64> = (1..=40)
        .filter_map(|seed| {
            let summary = Simulation::new(&scenario(seed))
                .unwrap()
                .run(&mut SummaryRecorder);
            summary.touchdown.map(|t| t.distance_from_aim_m)
        })
        .collect();
    let n = distances.len() as f64;
    let mean = distances.iter().sum::<f64>() / n;
    let variance = distances.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (variance.sqrt(), distances.len())
}
