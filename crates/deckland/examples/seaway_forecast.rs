//! How far ahead the landing point can be forecast, in sea states 3–6 (the carrier in a
//! seaway, docs/model.md §12) beside the paper's filter ship (§3.1): the RMS of the
//! landing point's height and vertical velocity, and the Kalman estimator's forecast
//! error against horizon, from the ship's sensed motion (§3.5).
//!
//! `cargo run --release -p deckland --example seaway_forecast [SECONDS]` (default 4000 s
//! of simulated ship motion per sea, seed 7).

use deckland::analysis::forecast_study;
use deckland::environment::seaway::SeawayParameters;
use deckland::environment::{ship_motion, ShipModelKind, ShipMotionParameters};
use deckland::sensors::ShipMotionSensingParameters;

/// The landing point's lever arm aft of the pitch centre (m, docs/model.md §2.7).
const LANDING_ARM_M: f64 = 81.0;
/// Horizons (s).
const HORIZONS_S: [f64; 6] = [0.5, 1.0, 2.5, 5.0, 7.5, 10.0];

fn main() {
    let seconds: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(4000.0);
    let seaway = |model| ShipMotionParameters {
        model,
        ..ShipMotionParameters::default()
    };
    let mut seas = vec![(
        "the paper's sea (filters, 2.0 m, 1.5°)".to_owned(),
        seaway(ShipModelKind::Filters),
        SeawayParameters::default(),
    )];
    for sea_state in 3..=6 {
        let parameters = SeawayParameters::sea_state(sea_state).expect("in the table");
        seas.push((
            format!(
                "sea state {sea_state} (H_s {} m, T_p {} s)",
                parameters.significant_wave_height_m, parameters.peak_period_s
            ),
            seaway(ShipModelKind::Seaway),
            parameters,
        ));
    }
    println!("Landing point ({LANDING_ARM_M} m aft of the pitch centre): RMS, and the Kalman estimator's forecast error as a share of it; {seconds} s per sea, seed 7\n");
    let header: Vec<String> = HORIZONS_S.iter().map(|h| format!("{h} s")).collect();
    println!(
        "| sea | height RMS (m) | climb-rate RMS (m/s) | climb-rate error at {} |",
        header.join(", ")
    );
    println!("|---|---|---|---|");
    for (name, ship, seaway) in seas {
        let model = ship_motion(&ship, &seaway).expect("a valid sea");
        let study = forecast_study(
            model,
            ShipMotionSensingParameters::default(),
            LANDING_ARM_M,
            &HORIZONS_S,
            seconds,
            7,
        )
        .expect("valid sensing");
        let shares: Vec<String> = study
            .errors
            .iter()
            .map(|e| {
                format!(
                    "{:.0} %",
                    100.0 * e.estimator_climb_rate_mps / study.climb_rate_rms_mps
                )
            })
            .collect();
        println!(
            "| {name} | {:.3} | {:.3} | {} |",
            study.height_rms_m,
            study.climb_rate_rms_mps,
            shares.join(", ")
        );
    }
}
