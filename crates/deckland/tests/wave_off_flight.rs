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
