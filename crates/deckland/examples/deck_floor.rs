//! What no forecast of the deck can see, and what it costs (docs/deck-prediction.md, "The
//! deck's velocity and the ramp"): the physics floor of the landing point's and the
//! ramp's height and vertical velocity in three seas, the least share of approaches a
//! system deciding on the ship's exact state must wave off to keep hard landings at
//! 0.1 %, and the clearance over the forecast ramp that keeps ramp strikes at 10⁻⁴.
//!
//! `cargo run --release -p deckland --example deck_floor`

use deckland::analysis::{
    deck_point_floor, deck_point_stationary_sigma, hard_landing_decision_bound,
    ramp_clearance_for_strike_rate,
};
use deckland::environment::{DeckGeometry, ShipMotion, ShipMotionParameters};

/// Horizons of the floor tables (s).
const HORIZONS_S: [f64; 6] = [0.25, 0.5, 1.0, 1.4, 2.0, 2.5];
/// Decision horizons before touchdown (s): 2.5 s is the wave-off's commit point.
const DECISIONS_S: [f64; 4] = [0.5, 1.0, 1.5, 2.5];
/// Upward deck velocities that make a touchdown hard (m/s): the 7.6-m/s limit less a
/// hook sinking at 3.8, 3.4 and 3.0 m/s.
const MARGINS_MPS: [f64; 3] = [3.8, 4.2, 4.6];
/// The hard-landing rate allowed (issue 25: 0.1 %) and a ramp-strike rate that 3000
/// approaches would show as 0 with 74 % probability (10⁻⁴).
const HARD_LANDING_RATE: f64 = 0.001;
const RAMP_STRIKE_RATE: f64 = 1e-4;
/// The time from the wave-off's commit point to the ramp (s, docs/landing-design.md) and
/// the most direct lift can add to the hook's climb (m/s²: ±0.15 of C_L at 69 m/s).
const COMMIT_TO_RAMP_S: f64 = 1.4;
const DIRECT_LIFT_ACCELERATION_MPS2: f64 = 1.18;

fn main() {
    let deck = DeckGeometry::default();
    let landing_arm = deck.landing_point_aft_of_pitch_centre_m;
    let ramp_arm = landing_arm + deck.ramp_aft_of_aim_point_m;
    for (name, heave_rms_m, pitch_rms_deg) in [
        ("A moderate sea", 1.0, 0.75),
        ("The paper's sea (default)", 2.0, 1.5),
        ("A heavy sea", 3.0, 2.5),
    ] {
        let ship = ShipMotion::new(ShipMotionParameters {
            heave_rms_m,
            pitch_rms_deg,
            ..ShipMotionParameters::default()
        })
        .expect("a valid sea");
        println!("## {name}: heave {heave_rms_m} m, pitch {pitch_rms_deg}° RMS\n");
        println!(
            "| horizon (s) | landing point: height σ (m) | its velocity σ (m/s) | ramp: height σ \
             (m) | its velocity σ (m/s) |"
        );
        println!("|---|---|---|---|---|");
        for horizon in HORIZONS_S {
            let landing = deck_point_floor(&ship, landing_arm, horizon);
            let ramp = deck_point_floor(&ship, ramp_arm, horizon);
            println!(
                "| {horizon} | {:.2} | {:.2} | {:.2} | {:.2} |",
                landing.height_sigma_m,
                landing.climb_rate_sigma_mps,
                ramp.height_sigma_m,
                ramp.climb_rate_sigma_mps
            );
        }
        let landing = deck_point_stationary_sigma(&ship, landing_arm);
        let ramp = deck_point_stationary_sigma(&ship, ramp_arm);
        println!(
            "| stationary | {:.2} | {:.2} | {:.2} | {:.2} |\n",
            landing.0, landing.1, ramp.0, ramp.1
        );

        println!(
            "Hard landings at most {:.1} %: the share of approaches the best rule must wave \
             off, deciding on the ship's exact state this long before touchdown\n",
            100.0 * HARD_LANDING_RATE
        );
        print!("| margin (m/s) | hard landings with no decision |");
        for decision in DECISIONS_S {
            print!(" {decision} s |");
        }
        println!("\n|---|---|{}", "---|".repeat(DECISIONS_S.len()));
        for margin in MARGINS_MPS {
            let mut without = f64::NAN;
            let cells: Vec<String> = DECISIONS_S
                .iter()
                .map(|&decision| {
                    let unforeseen =
                        deck_point_floor(&ship, landing_arm, decision).climb_rate_sigma_mps;
                    let bound = hard_landing_decision_bound(
                        landing.1,
                        unforeseen,
                        margin,
                        HARD_LANDING_RATE,
                    )
                    .expect("σ below the stationary σ");
                    without = bound.rate_without_decision;
                    format!(" {:.1} % |", 100.0 * bound.wave_off_fraction)
                })
                .collect();
            println!("| {margin} | {:.2} % |{}", 100.0 * without, cells.concat());
        }
        let ramp_floor = deck_point_floor(&ship, ramp_arm, COMMIT_TO_RAMP_S).height_sigma_m;
        let recovery = 0.5 * DIRECT_LIFT_ACCELERATION_MPS2 * COMMIT_TO_RAMP_S.powi(2);
        println!(
            "\nRamp strikes at most {RAMP_STRIKE_RATE:e}: clearance over the ramp forecast \
             {COMMIT_TO_RAMP_S} s ahead (unforeseen σ {ramp_floor:.2} m), with {recovery:.2} m \
             of climb by direct lift after it: {:.2} m\n",
            ramp_clearance_for_strike_rate(ramp_floor, recovery, RAMP_STRIKE_RATE)
        );
    }
}
