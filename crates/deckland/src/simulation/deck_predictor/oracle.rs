//! The `oracle` deck predictor: the minimum-variance prediction at the estimated
//! touchdown time from the ship model's *true* state, which no aircraft can know (studies
//! and the paper's set).

use super::{DeckPredictor, DeckQuery, UncertaintyHold};
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
    hold: UncertaintyHold,
}

impl Oracle {
    /// The oracle forecasting with `propagator`, its anchor shaped by `shaping` (the
    /// realistic set's) or not (the paper's).
    pub(crate) fn new(propagator: ShipMotionPropagator, shaping: Option<AnchorShaping>) -> Self {
        Self {
            propagator,
            shaping,
            hold: UncertaintyHold::new(None),
        }
    }

    /// The same, the forecast's σ worked out once per frame of a computer at `rate_hz`
    /// and held over it (`None`: at every step).
    pub(crate) fn with_uncertainty_frames(mut self, rate_hz: Option<f64>) -> Self {
        self.hold = UncertaintyHold::new(rate_hz);
        self
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
                query.shaped_reference(&self.propagator, &truth, 0.0, shaping, &mut self.hold)
            }
        }
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}
