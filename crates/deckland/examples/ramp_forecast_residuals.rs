//! How well the ramp score of `deckland rare` forecasts the hook's clearance over the
//! ramp (docs/rare-events.md): for each scenario, over its first RUNS approaches (seeds
//! 0 to RUNS − 1, no dispersions), the clearance flown less the score's forecast ĉ made
//! τ seconds before the crossing (mean and SD over the approaches), beside the spread σ
//! the score divides by. A score that ranks flights well misses by about σ with a mean
//! near 0; splitting crawls where the mean moves along the approach by more than the
//! SD.
//!
//! `cargo run --release -p deckland --example ramp_forecast_residuals -- [RUNS] FILE...`
//! (default 60 runs). The forecast is read back from two scores of the same flight whose
//! thresholds differ by 40 m, as the test `the_ramp_forecast_misses_by_about_its_own_spread`
//! does: far below the event each score is x = (c − ĉ)/σ.

use deckland::rare::score::{EventScore, EventThresholds, RareEvent};
use deckland::scenario::{load_scenario, Scenario};
use deckland::simulation::{Event, Recorder, RunSummary, Signals, Simulation};

/// Horizons before the crossing (s).
const HORIZONS_S: [f64; 10] = [0.25, 0.5, 1.0, 2.0, 3.0, 4.0, 6.0, 8.0, 12.0, 20.0];

/// Two scores of one flight, and the ramp crossing's time and clearance (s, m).
struct Pair {
    one: EventScore,
    two: EventScore,
    crossing: Option<(f64, f64)>,
}

impl Recorder for Pair {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0)
    }
    fn sample(&mut self, signals: &Signals) {
        self.one.sample(signals);
        self.two.sample(signals);
    }
    fn event(&mut self, event: &Event) {
        if let Event::RampCrossing {
            time_s,
            clearance_m,
        } = event
        {
            self.crossing = Some((*time_s, *clearance_m));
        }
        self.one.event(event);
        self.two.event(event);
    }
    fn finish(&mut self, summary: &RunSummary) {
        self.one.finish(summary);
        self.two.finish(summary);
    }
}

/// One flight's forecasts (time, ĉ, σ) at every step before the crossing, and the
/// crossing's time and clearance, if the hook crossed the ramp.
type Forecasts = (Vec<(f64, f64, f64)>, Option<(f64, f64)>);

fn fly(scenario: &Scenario) -> Forecasts {
    let (c1, c2) = (-60.0, -100.0);
    let mut simulation = Simulation::new(scenario).expect("a valid scenario");
    let score = |c, simulation: &Simulation| {
        let thresholds = EventThresholds::of(scenario).with(RareEvent::RampStrike, c);
        EventScore::new(RareEvent::RampStrike, thresholds, scenario, simulation)
    };
    let mut pair = Pair {
        one: score(c1, &simulation),
        two: score(c2, &simulation),
        crossing: None,
    };
    let mut forecasts = Vec::new();
    loop {
        pair.one.observe(&simulation);
        pair.two.observe(&simulation);
        let time_s = simulation.time_s();
        let ended = simulation.advance(&mut pair).is_some();
        if ended || pair.crossing.is_some() {
            break;
        }
        let (x1, x2) = (pair.one.score(), pair.two.score());
        let sigma_m = (c1 - c2) / (x1 - x2);
        forecasts.push((time_s, c1 - x1 * sigma_m, sigma_m));
    }
    (forecasts, pair.crossing)
}

/// Mean and SD of flown − ĉ, and the mean σ, τ before the crossing; and how many flights.
fn residuals(flights: &[Forecasts], ahead_s: f64) -> (f64, f64, f64, usize) {
    let rows: Vec<(f64, f64)> = flights
        .iter()
        .filter_map(|(forecasts, crossing)| {
            let (crossing_s, clearance_m) = (*crossing)?;
            let &(_, forecast, sigma) = forecasts
                .iter()
                .rev()
                .find(|(t, _, _)| crossing_s - t >= ahead_s)?;
            Some((clearance_m - forecast, sigma))
        })
        .collect();
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
        let flights: Vec<Forecasts> = (0..runs)
            .map(|seed| fly(&Scenario { seed, ..base }))
            .collect();
        for ahead_s in HORIZONS_S {
            let (mean, sd, sigma, n) = residuals(&flights, ahead_s);
            println!("| `{file}` | {ahead_s} | {mean:+.2} | {sd:.2} | {sigma:.2} | {n} |");
        }
    }
}
