//! How hard direct lift control works in the last seconds of an approach
//! (docs/model.md §5.9; docs/no-oracle-results.md, "What the moderate sea's σ is made of"):
//! over seeds 1–60 of the default scenario in a sea of the given heave and pitch RMS, the
//! share of the last 6 s before the run's end that the lift-coefficient increment spends
//! on its authority and on its rate limit, its mean and its mean magnitude.
//!
//! `cargo run --release -p deckland --example direct_lift_usage -- HEAVE_RMS_M PITCH_RMS_DEG
//! [K_H K_HDOT]`, e.g. `-- 1.0 0.75` for the moderate sea, `-- 2.0 1.5` for the paper's,
//! with direct lift's gains K_h (1/m) and K_ḣ (s/m) in place of the default's if given.

use std::error::Error;

use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::Simulation;

/// The sample interval of the recording (s).
const SAMPLE_S: f64 = 0.01;
/// The window before the run's end that is looked at (s).
const WINDOW_S: f64 = 6.0;
/// A sample within this share of a limit counts as on it.
const ON_LIMIT: f64 = 0.98;

fn main() -> Result<(), Box<dyn Error>> {
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|a| {
            a.parse::<f64>()
                .map_err(|e| format!("not a number: {a} ({e})"))
        })
        .collect::<Result<_, _>>()?;
    if args.len() != 2 && args.len() != 4 {
        return Err("usage: direct_lift_usage HEAVE_RMS_M PITCH_RMS_DEG [K_H K_HDOT]".into());
    }
    let (mut on_authority, mut on_rate_limit, mut samples) = (0_usize, 0_usize, 0_usize);
    let (mut sum, mut sum_magnitude) = (0.0, 0.0);
    for seed in 1..=60_u64 {
        let mut scenario = Scenario {
            seed,
            ..Scenario::default()
        };
        scenario.environment.ship.heave_rms_m = args[0];
        scenario.environment.ship.pitch_rms_deg = args[1];
        if let [_, _, gain, rate_gain] = args[..] {
            scenario.control.direct_lift.height_gain_per_m = gain;
            scenario.control.direct_lift.height_rate_gain_s_per_m = rate_gain;
        }
        let law = scenario.control.direct_lift;
        let mut recorder = TimeSeriesRecorder::every(SAMPLE_S);
        Simulation::new(&scenario)?.run(&mut recorder);
        let increments: Vec<f64> = recorder
            .samples
            .iter()
            .filter_map(|s| s.direct_lift_coefficient)
            .collect();
        let window = (WINDOW_S / SAMPLE_S) as usize;
        let first = increments.len().saturating_sub(window).max(1);
        for k in first..increments.len() {
            let (now, before) = (increments[k], increments[k - 1]);
            samples += 1;
            sum += now;
            sum_magnitude += now.abs();
            on_authority += usize::from(now.abs() > ON_LIMIT * law.max_lift_coefficient_increment);
            on_rate_limit +=
                usize::from(((now - before) / SAMPLE_S).abs() > ON_LIMIT * law.rate_limit_per_s);
        }
    }
    if samples == 0 {
        return Err("no run flew with direct lift control".into());
    }
    let share = |count: usize| 100.0 * count as f64 / samples as f64;
    println!(
        "last {WINDOW_S} s of seeds 1–60: on the authority {:.1} %, on the rate limit {:.1} %, \
         mean ΔC_L {:+.4}, mean |ΔC_L| {:.4}",
        share(on_authority),
        share(on_rate_limit),
        sum / samples as f64,
        sum_magnitude / samples as f64
    );
    Ok(())
}
