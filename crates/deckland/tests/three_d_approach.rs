//! The 3-D carrier approach in the loop (issue 27; docs/model.md §10): a 6-DOF approach
//! lines up on the drifting centreline of the angled deck and reports its lateral
//! outcome; a 3-DOF approach has none.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::crosswind;
use deckland::aircraft::PlantModel;
use deckland::recording::{SummaryRecorder, TimeSeriesRecorder};
use deckland::scenario::Scenario;
use deckland::simulation::{Outcome, Simulation};

#[test]
fn a_crosswind_approach_lines_up_and_traps_near_the_centreline() {
    let scenario = crosswind();
    assert_eq!(scenario.aircraft.model, PlantModel::SixDof);
    let mut recorder = TimeSeriesRecorder::every(0.1);
    let summary = Simulation::new(&scenario).unwrap().run(&mut recorder);
    assert_eq!(summary.outcome, Outcome::Trap, "{:?}", summary.reason);
    let lateral = summary.touchdown.unwrap().lateral.unwrap();
    // The off-centre limit is 6.1 m; lineup brings the hook within 2 m.
    assert!(lateral.offset_m.abs() < 2.0, "{lateral:?}");
    assert!(!lateral.off_centre);
    assert!(lateral.bank_deg.abs() < 5.0);
    // It lands in the crab: with 5 m/s across at 69.1 m/s, asin(5/69.1) = 4.1°, nose
    // left into the wind from the left (docs/model.md §10.1).
    let crab = (5.0_f64 / 69.1).asin().to_degrees();
    assert!(
        (lateral.heading_to_centreline_deg + crab).abs() < 2.5,
        "{lateral:?}"
    );
    assert!(lateral.ramp_lineup_error_deg.is_some());
    // The centreline drifts right at V·sin δ = 7.7·sin 9° = 1.20 m/s.
    let first = recorder.samples.first().unwrap();
    let last = recorder.samples.last().unwrap();
    let drift = (last.lateral.aim_point_y_m.unwrap() - first.lateral.aim_point_y_m.unwrap())
        / (last.time_s - first.time_s);
    assert!(
        (drift - 7.7 * 9.0_f64.to_radians().sin()).abs() < 0.05,
        "{drift}"
    );
    // The hook followed it: it ends within 2 m of the centreline.
    assert!(last.lateral.cross_track_m.unwrap().abs() < 2.0);
}

#[test]
fn a_three_dof_approach_has_no_lateral_signals_or_outcome() {
    let scenario = Scenario {
        aircraft: deckland::scenario::AircraftSection {
            model: PlantModel::ThreeDof,
            ..crosswind().aircraft
        },
        ..crosswind()
    };
    let mut recorder = TimeSeriesRecorder::every(1.0);
    let summary = Simulation::new(&scenario).unwrap().run(&mut recorder);
    assert!(summary.touchdown.unwrap().lateral.is_none());
    assert!(recorder
        .samples
        .iter()
        .all(|s| s.lateral.cross_track_m.is_none() && s.lateral.bank_command_rad.is_none()));
}

#[test]
fn the_six_dof_with_the_3d_approach_off_holds_its_lateral_surfaces() {
    let mut scenario = crosswind();
    scenario.approach.three_dimensional = false;
    let summary = Simulation::new(&scenario)
        .unwrap()
        .run(&mut SummaryRecorder);
    assert!(summary.touchdown.unwrap().lateral.is_none());
}
