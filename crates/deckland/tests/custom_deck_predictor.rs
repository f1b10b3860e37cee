//! A user's own deck predictor (`simulation::DeckPredictor`): one type and one line
//! (`Simulation::builder(..).deck_predictor(..)`), flown here.

mod common;

use deckland::control::{DeckPredictorKind, DeckReference};
use deckland::environment::{ShipMotionPropagator, ShipPose};
use deckland::scenario::Scenario;
use deckland::simulation::{DeckPredictor, DeckQuery, Simulation};

/// The paper's oracle written as a user would: the minimum-variance prediction of the ship
/// model's true state at the estimated touchdown time, the landing point of that pose, no
/// forecast of the ramp (docs/model.md §5.7).
#[derive(Debug, Clone)]
struct MyOracle {
    propagator: ShipMotionPropagator,
}

impl DeckPredictor for MyOracle {
    fn deck_reference(&mut self, query: &DeckQuery<'_>, _state: &[f64]) -> DeckReference {
        let view = query.view;
        let predicted =
            self.propagator
                .predict(view.ship_model, view.ship_state, query.time_to_go_s);
        let pose = ShipPose {
            heave_m: predicted.heave_m,
            pitch_rad: predicted.pitch_rad,
            ..*view.pose
        };
        query.unshaped(view.deck.aim_point(&pose), query.mean_aim_velocity)
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}

/// A predictor that ignores the ship: the path stays anchored on the mean deck.
#[derive(Debug, Clone)]
struct MeanDeck;

impl DeckPredictor for MeanDeck {
    fn deck_reference(&mut self, query: &DeckQuery<'_>, _state: &[f64]) -> DeckReference {
        query.unshaped(query.mean_aim, query.mean_aim_velocity)
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}

/// The built-in `oracle` without a forecast (not ramp-aware, no wave-off: the paper's).
fn paper_oracle_scenario() -> Scenario {
    let mut scenario = Scenario::default();
    let path = &mut scenario.control.flight_path;
    path.deck_motion_predictor = DeckPredictorKind::Oracle;
    path.ramp_aware = false;
    scenario.control.wave_off.enabled = false;
    scenario
}

use common::fly_recorded as fly;

#[test]
fn a_users_oracle_flies_bit_for_bit_as_the_built_in_one() {
    let scenario = paper_oracle_scenario();
    let built_in = fly(Simulation::new(&scenario).expect("valid"));
    let horizon_s = scenario.control.flight_path.compensation_window_s
        + scenario.control.flight_path.compensation_blend_s;
    let mine = MyOracle {
        propagator: ShipMotionPropagator::new(
            &scenario.environment.ship_motion().expect("valid"),
            horizon_s,
        ),
    };
    let flown = fly(Simulation::builder(&scenario)
        .deck_predictor(&mine)
        .build()
        .expect("valid"));
    assert_eq!(flown.summary, built_in.summary);
    assert_eq!(flown.samples, built_in.samples);
}

#[test]
fn a_predictor_blind_to_the_ship_keeps_the_path_on_the_mean_deck() {
    // Anchored on the mean deck, the path never follows the landing point: over the last
    // seconds the landing point moves by metres (2 m RMS heave) while the path's anchor
    // stays at the mean deck height.
    let scenario = paper_oracle_scenario();
    let blind = fly(Simulation::builder(&scenario)
        .deck_predictor(&MeanDeck)
        .build()
        .expect("valid"));
    let deck_height_m = scenario.environment.deck.deck_height_m;
    let slope = scenario
        .control
        .flight_path
        .glide_slope_deg
        .to_radians()
        .tan();
    for s in &blind.samples {
        let (Some(path_h), Some(_)) = (s.path_height_m, s.time_to_go_s) else {
            continue;
        };
        // The path stands (range to the mean aim point)·tan Γ above the mean deck.
        let range_m = s.ship.pitch_centre_x_m
            - scenario
                .environment
                .deck
                .landing_point_aft_of_pitch_centre_m
            - s.hook_x_m;
        assert!(
            (path_h - (deck_height_m + range_m * slope)).abs() < 1e-6,
            "at {} s the path is at {path_h} m",
            s.time_s
        );
    }
    let oracle = fly(Simulation::new(&scenario).expect("valid"));
    assert_ne!(blind.samples, oracle.samples);
}
