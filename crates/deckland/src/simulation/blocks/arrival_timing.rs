//! The arrival-timing block: once per step, after the guidance computer, the airspeed
//! reference of the speed loop is moved by a bounded, rate-limited change that shifts
//! the touchdown towards a predicted lull of the deck's motion
//! ([`crate::control::ArrivalTiming`]; docs/landing-design.md, "Timing the touchdown to
//! a lull"). It reads the Kalman filter of the `estimator` deck predictor, and does
//! nothing with the others.

use crate::control::{ArrivalTiming, ArrivalTimingInputs, ArrivalTimingParameters};
use crate::environment::{ShipMotion, ShipMotionEstimate, ShipMotionPropagator};
use crate::estimation::DeckMotionEstimator;

/// The block's parts: the timing law, a forecast reaching its planning window, and the
/// approach airspeed it changes.
#[derive(Debug, Clone)]
pub(crate) struct ArrivalTimingBlock {
    timing: ArrivalTiming,
    propagator: ShipMotionPropagator,
    nominal_airspeed_mps: f64,
}

impl ArrivalTimingBlock {
    /// The block for `parameters` and `ship`'s filters about the approach airspeed `airspeed_mps`, with the
    /// ship data link's `latency_s`; `None` when it is off.
    pub(crate) fn new(
        parameters: ArrivalTimingParameters,
        ship: &ShipMotion,
        airspeed_mps: f64,
        latency_s: f64,
    ) -> Option<Self> {
        parameters.enabled().then(|| Self {
            timing: ArrivalTiming::new(parameters),
            propagator: ShipMotionPropagator::new(
                ship,
                parameters.start_time_to_go_s + parameters.window_s + latency_s + 1.0,
            ),
            nominal_airspeed_mps: airspeed_mps,
        })
    }
}

impl ArrivalTimingBlock {
    /// The airspeed reference (m/s) after one step of the timing law on `inputs`: each
    /// arrival shifted by τ is scored by the expected squared vertical velocity of the
    /// `ship`'s landing point `arm_m` (m) aft of its pitch centre, the Kalman `filter`'s
    /// forecast mean squared plus its variance.
    pub(crate) fn airspeed_reference_mps(
        &mut self,
        inputs: &ArrivalTimingInputs,
        ship: &ShipMotion,
        filter: &DeckMotionEstimator,
        arm_m: f64,
    ) -> f64 {
        let propagator = &self.propagator;
        let time_to_go_s = inputs.time_to_go_s;
        let age_s = inputs.time_s - filter.time_s();
        let mut estimate: Option<ShipMotionEstimate> = None;
        let score = |shift_s: f64| {
            let estimate = estimate.get_or_insert_with(|| filter.estimate());
            let lead_s = age_s + (time_to_go_s + shift_s).max(0.0);
            let forecast = propagator.forecast_mean(ship, estimate, lead_s);
            let mean = forecast.deck_point_climb_rate_mps(arm_m);
            let point = (arm_m, forecast.pitch_rad);
            let sigma = propagator.deck_point_sigma(ship, estimate, lead_s, point, 1);
            mean * mean + sigma * sigma
        };
        let change_mps = self.timing.step(inputs, score);
        self.nominal_airspeed_mps + change_mps
    }

    /// The timing law's change of the airspeed reference now (m/s).
    pub(crate) fn speed_change_mps(&self) -> f64 {
        self.timing.speed_change_mps()
    }
}
