//! The `oracle` deck predictor: the minimum-variance prediction at the estimated
//! touchdown time from the ship model's *true* state, which no aircraft can know (studies
//! and the paper's set).

use super::{DeckPredictor, DeckQuery};
use crate::control::DeckReference;
use crate::environment::{ShipMotionEstimate, ShipMotionPropagator, ShipPose};
use crate::simulation::anchor_shaping::AnchorShaping;

/// The oracle. With `shaping` it also forecasts the ramp and the deck's rate (for
/// ramp-aware guidance and the wave-off decision) and shapes the anchor as the estimator
/// does; without, it is the paper's (the prediction itself, with rate zero).
#[derive(Debug, Clone)]
pub struct Oracle {
    propagator: ShipMotionPropagator,
    shaping: Option<AnchorShaping>,
}

impl Oracle {
    /// The oracle forecasting with `propagator`, its anchor shaped by `shaping` (the
    /// realistic set's) or not (the paper's).
    pub(crate) fn new(propagator: ShipMotionPropagator, shaping: Option<AnchorShaping>) -> Self {
        Self {
            propagator,
            shaping,
        }
    }
}

impl DeckPredictor for Oracle {
    #[inline]
    fn deck_reference(&mut self, query: &DeckQuery<'_>, _state: &[f64]) -> DeckReference {
        let view = query.view;
        match &mut self.shaping {
            None => {
                let predicted =
                    self.propagator
                        .predict(view.ship_model, view.ship_state, query.time_to_go_s);
                let predicted_pose = ShipPose {
                    heave_m: predicted.heave_m,
                    pitch_rad: predicted.pitch_rad,
                    ..*view.pose
                };
                query.unshaped(
                    view.deck.aim_point(&predicted_pose),
                    query.mean_aim_velocity,
                )
            }
            Some(shaping) => {
                let truth = ShipMotionEstimate {
                    mean: *view.ship_state,
                    ..ShipMotionEstimate::default()
                };
                query.shaped_reference(&self.propagator, &truth, 0.0, shaping)
            }
        }
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}
