//! Your own block on the loop's signal bus: a discrete vertical gust, flown into the
//! default approach.
//!
//! `cargo run --release -p deckland --example custom_block [AMPLITUDE_MPS]` (default 3).
//!
//! A block ([`deckland::simulation::Block`]) names the registered signals it reads and
//! writes ([`deckland::simulation::SIGNALS`]), may have continuous states of its own, and
//! sits at one of the loop's insertion points ([`BlockPosition`]): here after the wind
//! is sampled and before the aircraft reads it, so the gust reaches the aerodynamics
//! through the air-relative velocity, as wind must (docs/model.md §2.4), and every
//! recorder sees it in `wind.z_mps`. The one line that adds it to a run is
//! `Simulation::builder(&scenario).block(BlockPosition::AirMass, Arc::new(gust))`.
//!
//! The gust is MIL-F-8785C's discrete "1 − cosine" shape (§3.7.2.3):
//! W_z = (A/2)·(1 − cos(π·s/d)) for 0 ≤ s ≤ 2d, s the distance flown into it.

use std::sync::Arc;

use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{Block, BlockPosition, SignalId, Signals, Simulation};

/// A 1 − cosine vertical gust (positive down: a downdraft) of peak `amplitude_mps`, its
/// half-length `half_length_m`, starting `start_range_m` before the ship's pitch centre.
#[derive(Debug)]
struct DiscreteGust {
    amplitude_mps: f64,
    half_length_m: f64,
    start_range_m: f64,
}

impl Block for DiscreteGust {
    fn name(&self) -> &'static str {
        "discrete_gust"
    }

    fn reads(&self) -> &'static [SignalId] {
        &[SignalId::DistanceAft, SignalId::WindZ]
    }

    fn writes(&self) -> &'static [SignalId] {
        &[SignalId::WindZ]
    }

    fn outputs(&self, _time_s: f64, _state: &[f64], bus: &mut Signals) {
        let into_m = self.start_range_m - bus.distance_aft_m;
        if (0.0..=2.0 * self.half_length_m).contains(&into_m) {
            let shape = 1.0 - (std::f64::consts::PI * into_m / self.half_length_m).cos();
            bus.wind.z_mps += 0.5 * self.amplitude_mps * shape;
        }
    }
}

fn main() {
    let amplitude_mps: f64 = std::env::args()
        .nth(1)
        .map_or(3.0, |a| a.parse().expect("AMPLITUDE_MPS: a number in m/s"));
    let scenario = Scenario::default();
    let plain = Simulation::new(&scenario)
        .expect("the default scenario flies")
        .run(&mut SummaryRecorder);
    let gust = DiscreteGust {
        amplitude_mps,
        half_length_m: 60.0,
        start_range_m: 700.0,
    };
    let gusted = Simulation::builder(&scenario)
        .block(BlockPosition::AirMass, Arc::new(gust))
        .build()
        .expect("the gust reads only what is written before it")
        .run(&mut SummaryRecorder);
    println!("default approach, seed {}:", scenario.seed);
    for (label, summary) in [("without the gust", &plain), ("with the gust", &gusted)] {
        println!(
            "  {label:<18} {:<14} glide-path error RMS {:.2} m, max {:.2} m",
            summary.outcome.name(),
            summary.glide_path_error_rms_m.unwrap_or(f64::NAN),
            summary.glide_path_error_max_m.unwrap_or(f64::NAN),
        );
    }
}
