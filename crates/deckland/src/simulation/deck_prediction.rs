//! The deck-motion predictor block: where the glide path expects the landing point to be
//! (docs/model.md §5, deck-motion compensation; see [`crate::control::FlightPathGenerator`]).

use crate::control::{DeckMotionFilter, DeckReference, FlightPathGenerator};
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, ShipMotion, ShipMotionPredictor, ShipMotionState,
    ShipPose, ShipPoseRate,
};

/// Names of the `filter_lead` predictor's states.
const FILTER_STATE_NAMES: &[&str] = &["landing_point_height_m", "landing_point_climb_rate_mps"];

/// How the landing point is predicted for the glide path, with the predictor's own state.
#[derive(Debug, Clone, PartialEq)]
pub enum DeckPredictor {
    /// The minimum-variance prediction at the estimated touchdown time from the ship
    /// model's *true* state: an oracle, no state of its own.
    Model(ShipMotionPredictor),
    /// A critically damped low-pass filter on the landing point's height (two states)
    /// with a linear lead.
    FilterLead(DeckMotionFilter),
}

/// The ship's motion at one instant, as the predictor reads it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DeckView<'a> {
    pub ship_model: &'a ShipMotion,
    pub ship_state: &'a ShipMotionState,
    pub deck: &'a DeckGeometry,
    pub pose: &'a ShipPose,
    pub rate: &'a ShipPoseRate,
}

impl DeckPredictor {
    /// Names of the predictor's continuous states.
    pub fn state_names(&self) -> &'static [&'static str] {
        match self {
            Self::Model(_) => &[],
            Self::FilterLead(_) => FILTER_STATE_NAMES,
        }
    }

    /// The state at the start: the filter on the current landing point.
    pub(crate) fn initial_state(&self, view: &DeckView<'_>, state: &mut [f64]) {
        if let Self::FilterLead(_) = self {
            state[0] = view.deck.aim_point(view.pose).h_m;
            state[1] = view
                .deck
                .velocity_along_deck(view.pose, view.rate, 0.0)
                .h_mps;
        }
    }

    /// The predictor's state rate, given the landing point's true height (m).
    #[inline(always)]
    pub(crate) fn derivative(&self, state: &[f64], aim_height_m: f64, rate: &mut [f64]) {
        if let Self::FilterLead(filter) = self {
            let d = filter.derivative([state[0], state[1]], aim_height_m);
            rate[0] = d[0];
            rate[1] = d[1];
        }
    }

    /// The deck reference for the flight-path generator: the mean landing point and the
    /// predicted moving one (the model's prediction at the touchdown time, with rate
    /// zero; or the filtered height and rate).
    #[inline]
    pub(crate) fn deck_reference(
        &self,
        view: &DeckView<'_>,
        state: &[f64],
        flight_path: &FlightPathGenerator,
        hook_x_m: f64,
        hook_x_rate_mps: f64,
    ) -> DeckReference {
        let (pose, rate, deck) = (view.pose, view.rate, view.deck);
        // Ship level and at its mean height: the aim point sits 81 m aft of the pitch
        // centre at deck height (no trigonometry needed).
        let mean_aim = EarthPoint {
            x_m: pose.pitch_centre_x_m - deck.landing_point_aft_of_pitch_centre_m,
            h_m: deck.deck_height_m,
        };
        let mean_aim_velocity = EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps,
            h_mps: 0.0,
        };
        let (aim, aim_velocity) = match self {
            Self::Model(predictor) => {
                let horizon_s = flight_path.time_to_go_s(
                    hook_x_m,
                    hook_x_rate_mps,
                    mean_aim.x_m,
                    mean_aim_velocity.x_mps,
                );
                let predicted = predictor.predict(view.ship_model, view.ship_state, horizon_s);
                let predicted_pose = ShipPose {
                    heave_m: predicted.heave_m,
                    pitch_rad: predicted.pitch_rad,
                    ..*pose
                };
                (deck.aim_point(&predicted_pose), mean_aim_velocity)
            }
            Self::FilterLead(_) => {
                let aim = deck.aim_point(pose);
                (
                    EarthPoint {
                        x_m: aim.x_m,
                        h_m: state[0],
                    },
                    EarthVelocity {
                        x_mps: deck.velocity_along_deck(pose, rate, 0.0).x_mps,
                        h_mps: state[1],
                    },
                )
            }
        };
        DeckReference {
            mean_aim,
            mean_aim_velocity,
            aim,
            aim_velocity,
        }
    }
}
