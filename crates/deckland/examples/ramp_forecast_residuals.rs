//! How well the ramp score of `deckland rare` forecasts the hook's clearance over the
//! ramp (docs/rare-events.md): for each scenario, over its first RUNS approaches (seeds
//! 0 to RUNS − 1, no dispersions), the clearance flown less the score's forecast ĉ made
//! τ seconds before the crossing (mean and SD over the approaches), beside the spread σ
//! the score divides by. A score that ranks flights well misses by about σ with a mean
//! near 0; splitting crawls where the mean moves along the approach by more than the
//! SD.
//!
//! `cargo run --release -p deckland --example ramp_forecast_residuals -- [RUNS] FILE...`
//! (default 60 runs). The forecast is read back from two scores of the same flight
//! (`deckland::rare::ramp_forecast`), as the test
//! `the_ramp_forecast_misses_by_about_its_own_spread` does.

use deckland::rare::ramp_forecast::RampForecastTrace;
use deckland::scenario::{load_scenario, Scenario};

/// Horizons before the crossing (s).
const HORIZONS_S: [f64; 10] = [0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 20.0];

/// Mean and SD of flown − ĉ, and the mean σ, τ before the crossing; and how many flights.
fn residuals(flights: &[RampForecastTrace], ahead_s: f64) -> (f64, f64, f64, usize) {
    let rows: Vec<(f64, f64)> = flights.iter().filter_map(|f| f.miss(ahead_s)).collect();
    let n = rows.len() as f64;
    let mean = rows.iter().map(|r| r.0).sum::<f64>() / n;
    let sd = (rows.iter().map(|r| (r.0 - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
    let sigma = rows.iter().map(|r| r.1).sum::<f64>() / n;
    (mean, sd, sigma, rows.len())
}

fn main() {
    let mut args: Vec<String> = std::env::args().skip(1).collect();
    let runs = match args.first().and_then(|a| a.parse::<u64>().ok()) {
        Some(runs) => {
            args.remove(0);
            runs
        }
        None => 60,
    };
    println!(
        "| scenario | τ (s) | flown − ĉ: mean (m) | SD (m) | σ of the score (m) | approaches |"
    );
    println!("|---|---|---|---|---|---|");
    for file in &args {
        let text = std::fs::read_to_string(file).expect("a readable scenario file");
        let base = load_scenario(&text, file).expect("a valid scenario file");
        let flights: Vec<RampForecastTrace> = (0..runs)
            .map(|seed| {
                RampForecastTrace::fly(&Scenario { seed, ..base }).expect("a valid scenario")
            })
            .collect();
        for ahead_s in HORIZONS_S {
            let (mean, sd, sigma, n) = residuals(&flights, ahead_s);
            println!("| `{file}` | {ahead_s} | {mean:+.2} | {sd:.2} | {sigma:.2} | {n} |");
        }
    }
}
