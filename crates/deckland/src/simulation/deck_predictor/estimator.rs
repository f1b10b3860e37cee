//! The `estimator` deck predictor (the default): the ship's sensed motion feeds a Kalman
//! filter, whose estimate is forecast to the hook's touchdown and ramp-crossing times
//! (docs/model.md §3.5, §5.7).

use super::{DeckPredictor, DeckQuery, DeckView, UncertaintyHold};
use crate::control::DeckReference;
use crate::environment::{ShipMotionEstimate, ShipMotionPropagator};
use crate::estimation::DeckMotionEstimator;
use crate::random::Reseed;
use crate::sensors::ShipMotionSensor;
use crate::simulation::anchor_shaping::AnchorShaping;

/// The `estimator` predictor's parts: the ship's sensing, the Kalman filter, the
/// forecast and the smoothing of the anchor (all discrete: updated once per step).
#[derive(Debug, Clone)]
pub struct Estimator {
    sensor: ShipMotionSensor,
    estimator: DeckMotionEstimator,
    propagator: ShipMotionPropagator,
    estimate: ShipMotionEstimate,
    shaping: AnchorShaping,
    hold: UncertaintyHold,
}

impl Estimator {
    /// The predictor with this sensing and filter, its anchor smoothed at
    /// `anchor_frequency_radps`.
    pub fn new(
        sensor: ShipMotionSensor,
        estimator: DeckMotionEstimator,
        propagator: ShipMotionPropagator,
        anchor_frequency_radps: f64,
    ) -> Self {
        let estimate = estimator.estimate();
        Self {
            sensor,
            estimator,
            propagator,
            estimate,
            shaping: AnchorShaping::new(anchor_frequency_radps),
            hold: UncertaintyHold::new(None),
        }
    }
}

impl Estimator {
    /// The same, working out the forecast's σ (for risk-aware guidance and the
    /// probabilistic wave-off) when `uncertainty`.
    pub fn with_uncertainty(mut self, uncertainty: bool) -> Self {
        self.shaping = self.shaping.with_uncertainty(uncertainty);
        self
    }

    /// The same, with the ramp's variance the path follows worked out from the time to
    /// go `followed_within_s` (s) on (`AnchorShaping::with_followed_variance`).
    pub fn with_followed_variance(
        mut self,
        followed_within_s: Option<f64>,
        follows_landing_point: bool,
        lift: Option<crate::control::LiftLoop>,
    ) -> Self {
        self.shaping =
            self.shaping
                .with_followed_variance(followed_within_s, follows_landing_point, lift);
        self
    }

    /// The same, the forecast's σ worked out once per frame of a computer at `rate_hz`
    /// and held over it (`None`: at every step).
    pub fn with_uncertainty_frames(mut self, rate_hz: Option<f64>) -> Self {
        self.hold = UncertaintyHold::new(rate_hz);
        self
    }
}

impl DeckPredictor for Estimator {
    /// The ship's inertial navigation samples the true motion, and the measurements that
    /// have arrived over the data link update the Kalman filter.
    fn observe(&mut self, time_s: f64, view: &DeckView<'_>) {
        let truth = view.ship_model.outputs(view.ship_state);
        self.sensor.sample(time_s, &truth);
        let mut updated = false;
        while let Some(measurement) = self.sensor.receive(time_s) {
            self.estimator.update(&measurement);
            updated = true;
        }
        if updated {
            self.estimate = self.estimator.estimate();
        }
    }

    /// The forecast of the estimate (its age added to the horizon), ramp-aware and shaped.
    #[inline]
    fn deck_reference(&mut self, query: &DeckQuery<'_>, _state: &[f64]) -> DeckReference {
        let age_s = query.hook.time_s - self.estimator.time_s();
        query.shaped_reference(
            &self.propagator,
            &self.estimate,
            age_s,
            &mut self.shaping,
            &mut self.hold,
        )
    }

    fn estimator(&self) -> Option<&DeckMotionEstimator> {
        Some(&self.estimator)
    }

    fn reseed(&mut self, key: u64) {
        self.sensor.reseed(key);
    }

    fn clone_box(&self) -> Box<dyn DeckPredictor> {
        Box::new(self.clone())
    }
}
