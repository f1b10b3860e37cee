//! The wave-off's flight in a heavy sea's wake on the 3-D approach (docs/model.md §9):
//! its α floor must act before the 40 °/s stabilator can no longer stop a push-over.
#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use deckland::monte_carlo::dispersed_run_scenario;
use deckland::scenario::load_scenario;
use deckland::simulation::Outcome;

/// Run 128 of `deckland campaign scenarios/heavy-sea.toml --runs 3000 --seed 5151` (seed
/// 8636934081132346416, sea factor 1.02) waves off at t = 24.62 s. At 25.5–25.95 s the
/// climb overshoots its 5 m/s and the sink-rate loop takes the pitch command down at
/// 16°/s; the stabilator runs to +10° (nose down). The wake's updraft then turns to a
/// downdraft, and reversing the stabilator to full nose-up at 40°/s takes 0.9 s, in which
/// the nose falls at 12°/s and α by about 7°: with the floor at α_min = 2°, α reaches the
/// aerodynamic model's −5° at 26.90 s and the run ends diverged. With the floor at 4°
/// the aircraft climbs away, α staying above −4°.
#[test]
fn a_wave_off_in_the_wake_stops_its_push_over_in_time() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenarios/heavy-sea.toml"
    );
    let heavy = load_scenario(&std::fs::read_to_string(path).unwrap(), "heavy-sea.toml").unwrap();
    let seed = 8_636_934_081_132_346_416;
    // The campaign run with this seed, flown alone.
    let (scenario, _) = dispersed_run_scenario(&heavy, seed);
    assert_eq!(scenario.control.wave_off.min_alpha_deg, 4.0, "the default");
    let fly = |min_alpha_deg: f64| {
        let mut scenario = scenario;
        scenario.control.wave_off.min_alpha_deg = min_alpha_deg;
        common::fly_lowest_alpha_deg(&scenario)
    };
    let (low, _) = fly(2.0);
    assert_eq!(low.outcome, Outcome::Diverged, "{low:?}");
    let (default, lowest) = fly(4.0);
    assert_eq!(default.outcome, Outcome::WaveOff, "{default:?}");
    assert!(lowest > -4.0, "α fell to {lowest:.2}°");
}

/// Run 58 of `deckland campaign FILE --runs 400 --seed 90210` (seed
/// 1272364221688779689), FILE `scenarios/sea-state-6.toml` with the early check of the
/// first release (`[control.wave_off.recovery] foul_deck_time_to_go_s = 10.0`), waves
/// off on `foul_deck_motion` at t = 15.1 s, 10 s from the deck. At full thrust
/// throughout, the aircraft accelerates from 68 to 109 m/s in 7.5 s, the climb
/// overshoots its 5 m/s sevenfold, and α falls below the aerodynamic model's −5° at
/// 22.7 s: the run ends diverged. With the wave-off's airspeed limit (10 m/s over the
/// approach airspeed, the default) the thrust comes off above it, by m/τ_e per m/s: the
/// run ends a wave-off, its airspeed at most 9 m/s over the limit (it reaches 86.5 m/s
/// against 79.1 m/s: about its 7.5 m/s² times the engines' 0.625 s) and α above −2°.
#[test]
fn an_early_wave_off_holds_its_airspeed_and_climbs_away() {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../scenarios/sea-state-6.toml"
    );
    let text = std::fs::read_to_string(path).unwrap()
        + "\n[control.wave_off.recovery]\nfoul_deck_time_to_go_s = 10.0\n";
    let sea = load_scenario(&text, "sea-state-6-early.toml").unwrap();
    assert_eq!(sea.control.wave_off.climb_out_airspeed_margin_mps, 0.0);
    let (scenario, _) = dispersed_run_scenario(&sea, 1_272_364_221_688_779_689);
    let fly = |margin_mps: f64| {
        let mut scenario = scenario;
        scenario.control.wave_off.climb_out_airspeed_margin_mps = margin_mps;
        let recorder =
            common::fly_recorded(deckland::simulation::Simulation::new(&scenario).unwrap());
        let highest = |f: fn(&deckland::simulation::Signals) -> f64| {
            recorder
                .samples
                .iter()
                .map(f)
                .fold(f64::NEG_INFINITY, f64::max)
        };
        let fastest = highest(|s| s.airspeed_mps);
        let lowest_alpha = -highest(|s| -s.alpha_rad.to_degrees());
        (recorder.summary.unwrap(), fastest, lowest_alpha)
    };
    let (full, fastest, _) = fly(0.0);
    assert_eq!(full.outcome, Outcome::Diverged, "{full:?}");
    assert!(fastest > 100.0, "{fastest} m/s");
    let (limited, fastest, lowest_alpha) = fly(10.0);
    assert_eq!(limited.outcome, Outcome::WaveOff, "{limited:?}");
    let limit_mps = scenario.approach.airspeed_mps + 10.0;
    assert!(
        fastest < limit_mps + 9.0,
        "{fastest} m/s against {limit_mps}"
    );
    assert!(lowest_alpha > -2.0, "α fell to {lowest_alpha:.2}°");
}
