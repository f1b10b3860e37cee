//! The sweeps behind the default outer-loop design (docs/landing-design.md): boarding
//! statistics over seeds 1–N in adverse conditions for several sink-rate gains, guidance
//! gains and deck-motion predictors, plus the paper's gain set in ideal conditions.
//! `cargo run --release -p deckland --example outer_loop_sweep [N]` (default 50).

use deckland::control::{DeckPredictorKind, GuidanceParameters, SinkRateControllerParameters};
use deckland::experiments::fly_seeds;
use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{Outcome, RunSummary, SetupError, Simulation};

mod support;

fn row(label: &str, results: &[RunSummary]) {
    let count = |o: Outcome| results.iter().filter(|r| r.outcome == o).count();
    let distances: Vec<f64> = results
        .iter()
        .filter_map(|r| r.touchdown.map(|t| t.distance_from_aim_m))
        .collect();
    let n = distances.len().max(1) as f64;
    let mean = distances.iter().sum::<f64>() / n;
    let sd =
        (distances.iter().map(|d| (d - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0)).sqrt();
    println!(
        "| {label} | {:.0} % | {} | {} | {} | {} | {} | {mean:+.1} ± {sd:.1} |",
        100.0 * count(Outcome::Trap) as f64 / results.len() as f64,
        count(Outcome::Bolter),
        count(Outcome::RampStrike),
        count(Outcome::HardLanding),
        count(Outcome::Diverged),
        count(Outcome::WaveOff),
    );
}

fn main() -> Result<(), SetupError> {
    let seeds = support::seeds_from_args();
    let count = seeds.len();
    println!("| configuration (adverse, O-PD, seeds 1–{count}) | trap | bolter | ramp strike | hard | diverged | wave-off | touchdown from aim (m) |");
    println!("|---|---|---|---|---|---|---|---|");
    for predictor in [
        DeckPredictorKind::Estimator,
        DeckPredictorKind::Oracle,
        DeckPredictorKind::FilterLead,
    ] {
        for (kps, kis) in [(0.05, 0.02), (0.035, 0.012), (0.025, 0.008)] {
            for kpz in [0.3, 0.5] {
                let mut base = Scenario::default();
                base.control.flight_path.deck_motion_predictor = predictor;
                base.control.sink_rate.proportional_rad_per_mps = kps;
                base.control.sink_rate.integral_rad_per_m = kis;
                base.control.guidance.proportional_per_s = kpz;
                let label = format!("{predictor:?} predictor, K_Ps {kps}, K_Is {kis}, K_Pz {kpz}");
                row(&label, &fly_seeds(&base, &seeds)?);
            }
        }
    }
    for (conditions, base, offset_m) in [
        ("ideal, on the path", Scenario::default().ideal(), 0.0),
        (
            "ideal, 5 m above the path",
            Scenario::default().ideal(),
            5.0,
        ),
        ("adverse, seed 1", Scenario::default(), 0.0),
    ] {
        let mut paper = base;
        paper.approach.start_height_offset_m = offset_m;
        paper.control.sink_rate = SinkRateControllerParameters::paper();
        paper.control.guidance = GuidanceParameters::paper();
        let summary = Simulation::new(&paper)?.run(&mut SummaryRecorder);
        println!(
            "Paper gains (K_Ps 0.0061, K_Is 0.018, K_Pz 1, K_Iz 0.5, K_Dz 0.01), {conditions}: {} at {:.1} s ({})",
            summary.outcome.name(),
            summary.end_time_s,
            summary.reason.as_deref().unwrap_or("-")
        );
    }
    Ok(())
}
