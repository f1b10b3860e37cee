//! Helpers shared by the integration tests: the moderate sea, a recorded flight, module
//! graphs.

#![allow(clippy::unwrap_used)] // tests fail loudly by design
// Each test file that shares this module uses some of its helpers.
#![allow(dead_code)]

use deckland::recording::SummaryRecorder;
use deckland::scenario::{load_scenario, DispersionParameters, Scenario};
use deckland::simulation::Simulation;

/// The default (realistic) scenario with `seed` in the moderate sea of docs/model.md §3.6:
/// the filter ship at heave 1.0 m, pitch 0.75° RMS.
pub fn moderate_sea(seed: u64) -> Scenario {
    let mut scenario = Scenario {
        seed,
        ..Scenario::papers_sea()
    };
    scenario.environment.ship.heave_rms_m = 1.0;
    scenario.environment.ship.pitch_rms_deg = 0.75;
    scenario
}

/// The 3-D approach of `scenarios/crosswind.toml` (6-DOF, angled deck, crosswind).
pub fn crosswind() -> Scenario {
    let text = include_str!("../../../../scenarios/crosswind.toml");
    load_scenario(text, "crosswind.toml").unwrap()
}

/// Every dispersion of a campaign on, as the campaign and shard tests disperse their
/// short approach: start height and airspeed σ 1 m and 1 m/s, sea state log-σ 0.2, wind
/// over deck σ 2 m/s.
pub fn every_dispersion() -> DispersionParameters {
    DispersionParameters {
        start_height_offset_sd_m: 1.0,
        airspeed_error_sd_mps: 1.0,
        sea_state_log_sd: 0.2,
        wind_over_deck_sd_mps: 2.0,
    }
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

/// Flies `simulation` to the end, recording every signal each 10 ms, with its summary.
pub fn fly_recorded(simulation: Simulation) -> deckland::recording::TimeSeriesRecorder {
    let mut recorder = deckland::recording::TimeSeriesRecorder::every(0.01);
    let summary = simulation.run(&mut recorder);
    recorder.summary = Some(summary);
    recorder
}

/// Flies `scenario` recording each 10 ms: its summary and the lowest angle of attack
/// (deg) on the way.
pub fn fly_lowest_alpha_deg(scenario: &Scenario) -> (deckland::simulation::RunSummary, f64) {
    let recorder = fly_recorded(Simulation::new(scenario).unwrap());
    let lowest = recorder
        .samples
        .iter()
        .map(|s| s.alpha_rad.to_degrees())
        .fold(f64::INFINITY, f64::min);
    (recorder.summary.unwrap(), lowest)
}

/// A cycle through the last node of `path` in a module graph, if there is one
/// (depth-first search).
pub fn cycle_from(
    graph: &std::collections::BTreeMap<String, std::collections::BTreeSet<String>>,
    path: &mut Vec<String>,
) -> Option<Vec<String>> {
    let current = path.last()?.clone();
    for next in graph.get(&current).into_iter().flatten() {
        if let Some(position) = path.iter().position(|m| m == next) {
            let mut cycle = path[position..].to_vec();
            cycle.push(next.clone());
            return Some(cycle);
        }
        path.push(next.clone());
        if let Some(cycle) = cycle_from(graph, path) {
            return Some(cycle);
        }
        path.pop();
    }
    None
}
