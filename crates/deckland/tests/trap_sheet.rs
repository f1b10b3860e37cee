//! The landing signal officer's trap sheet of a 3-D approach (docs/model.md §10.8): the
//! four positions are graded from the hook's distance to the ramp, and a 3-DOF approach
//! has none.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::crosswind;
use deckland::metrics::TrapSheetPosition;
use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::Simulation;

#[test]
fn each_position_lasts_its_window_over_the_closing_speed() {
    // The hook closes on the ramp at the airspeed less the wind over the deck (the wind
    // over deck is by definition the air's speed relative to the ship, along the final
    // bearing): 69.1 − 10 = 59.1 m/s. Each window (¾–½, ½–¼, ¼–0.1, 0.1–0 nmi of
    // 1852 m) therefore holds its length / 59.1 m/s / 1 ms samples, give or take the
    // turbulence and the path's small angles (3 %).
    let scenario = crosswind();
    let closing_mps = scenario.approach.airspeed_mps - scenario.environment.wind.wind_over_deck_mps;
    let summary = Simulation::new(&scenario)
        .unwrap()
        .run(&mut SummaryRecorder);
    let sheet = summary.trap_sheet.expect("a 3-D approach has a trap sheet");
    let graded: Vec<TrapSheetPosition> = sheet.positions.iter().map(|p| p.position).collect();
    assert_eq!(graded, TrapSheetPosition::ALL);
    for p in &sheet.positions {
        let (outer, inner) = p.position.window_m();
        let expected = (outer - inner) / closing_mps / scenario.time_step_s;
        let ratio = p.samples as f64 / expected;
        assert!(
            (ratio - 1.0).abs() < 0.03,
            "{:?}: {} samples, {expected:.0} expected",
            p.position,
            p.samples
        );
        // The deviations are a lined-up approach's: within the off-centre limit.
        assert!(
            p.lineup_peak_m.abs() < 6.1 && p.glide_slope_peak_m.abs() < 3.0,
            "{p:?}"
        );
    }
}

#[test]
fn a_longitudinal_approach_has_no_trap_sheet() {
    let summary = Simulation::new(&Scenario::default().longitudinal())
        .unwrap()
        .run(&mut SummaryRecorder);
    assert!(summary.trap_sheet.is_none());
}
