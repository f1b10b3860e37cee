//! Boarding statistics over seeds 1–N in adverse conditions for O-PD and PID pitch
//! control, with and without deck-motion compensation:
//! `cargo run --release -p deckland --example boarding [N]` (default 50).
//!
//! Prints a markdown table; each seed's run is independent and deterministic, so the
//! table is the same however the work is split between threads.

use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::experiments::fly_seeds;
use deckland::scenario::Scenario;
use deckland::simulation::{Outcome, SetupError};

mod support;

fn mean_and_sd(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0).max(1.0);
    (mean, variance.sqrt())
}

fn main() -> Result<(), SetupError> {
    let seeds = support::seeds_from_args();
    println!("| pitch control | deck compensation | boarded (trap) | bolter | ramp strike | hard landing | diverged | touchdown from aim (m), mean ± sd | touchdown sink rate (m/s), mean ± sd |");
    println!("|---|---|---|---|---|---|---|---|---|");
    for (name, pitch) in [
        ("O-PD", PitchControllerParameters::default()),
        (
            "PID",
            PitchControllerParameters::Pid(PidParameters::default()),
        ),
    ] {
        for compensation in [true, false] {
            let mut base = Scenario::default();
            base.control.pitch = pitch;
            base.control.flight_path.deck_motion_compensation = compensation;
            let results = fly_seeds(&base, &seeds)?;
            let count_of = |o: Outcome| results.iter().filter(|r| r.outcome == o).count();
            let touchdowns: Vec<_> = results.iter().filter_map(|r| r.touchdown).collect();
            let (d_mean, d_sd) = mean_and_sd(
                &touchdowns
                    .iter()
                    .map(|t| t.distance_from_aim_m)
                    .collect::<Vec<_>>(),
            );
            let (s_mean, s_sd) = mean_and_sd(
                &touchdowns
                    .iter()
                    .map(|t| t.sink_rate_mps)
                    .collect::<Vec<_>>(),
            );
            println!(
                "| {name} | {} | {}/{} ({:.0} %) | {} | {} | {} | {} | {d_mean:+.1} ± {d_sd:.1} (n = {}) | {s_mean:.2} ± {s_sd:.2} |",
                if compensation { "on" } else { "off" },
                count_of(Outcome::Trap),
                results.len(),
                100.0 * count_of(Outcome::Trap) as f64 / results.len() as f64,
                count_of(Outcome::Bolter),
                count_of(Outcome::RampStrike),
                count_of(Outcome::HardLanding),
                count_of(Outcome::Diverged),
                touchdowns.len(),
            );
        }
    }
    Ok(())
}
