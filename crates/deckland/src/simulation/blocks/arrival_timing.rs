//! The arrival-timing block: once per step, after the guidance computer, the airspeed
//! reference of the speed loop is moved by a bounded, rate-limited change that shifts
//! the touchdown towards a predicted lull of the deck's motion
//! ([`crate::control::ArrivalTiming`]; docs/landing-design.md, "Timing the touchdown to
//! a lull"). It reads the Kalman filter of the `estimator` deck predictor, and does
//! nothing with the others.

use crate::aircraft::AircraftState;
use crate::control::{ArrivalTiming, ArrivalTimingInputs, ArrivalTimingParameters, DeckReference};
use crate::environment::{ShipMotionEstimate, ShipMotionPropagator};
use crate::simulation::closed_loop::ClosedLoop;
use crate::simulation::outer_loops::OuterLoops;

/// The block's parts: the timing law, a forecast reaching its planning window, and the
/// approach airspeed it changes.
#[derive(Debug, Clone)]
pub(crate) struct ArrivalTimingBlock {
    timing: ArrivalTiming,
    propagator: ShipMotionPropagator,
    nominal_airspeed_mps: f64,
}

impl ArrivalTimingBlock {
    /// The block for `parameters` about the approach airspeed `airspeed_mps`, with the
    /// ship data link's `latency_s`; `None` when it is off.
    pub(crate) fn new(
        parameters: ArrivalTimingParameters,
        airspeed_mps: f64,
        latency_s: f64,
    ) -> Option<Self> {
        parameters.enabled().then(|| Self {
            timing: ArrivalTiming::new(parameters),
            propagator: ShipMotionPropagator::new(
                parameters.start_time_to_go_s + parameters.window_s + latency_s + 1.0,
            ),
            nominal_airspeed_mps: airspeed_mps,
        })
    }
}

impl ClosedLoop {
    /// One step of the arrival-timing block at `t` (step `dt`) for the aircraft in
    /// `aircraft` and the guidance computer's `deck` reference: the change of the
    /// airspeed reference moves, and the reference with it. Without the block, outside an
    /// approach, or without a Kalman forecast, nothing changes.
    pub(crate) fn arrival_timing_step(
        &mut self,
        t: f64,
        dt: f64,
        aircraft: &AircraftState,
        deck: Option<&DeckReference>,
        waving_off: bool,
    ) {
        let (Some(block), Some(deck), OuterLoops::Approach { flight_path, .. }, Some(filter)) = (
            self.arrival_timing.as_mut(),
            deck,
            &self.outer,
            self.deck_predictor.estimator(),
        ) else {
            return;
        };
        let (sin_t, cos_t) = aircraft.theta_rad.sin_cos();
        let (hook_x_m, _) = self.hook.position_trig(aircraft, sin_t, cos_t);
        let (hook_x_rate_mps, _) = self.hook.velocity_trig(aircraft, sin_t, cos_t);
        let aim_x_m = deck.mean_aim.x_m + flight_path.parameters().touchdown_correction_m;
        let time_to_go_s = flight_path.time_to_go_s(
            hook_x_m,
            hook_x_rate_mps,
            aim_x_m,
            deck.mean_aim_velocity.x_mps,
        );
        let inputs = ArrivalTimingInputs {
            time_s: t,
            dt,
            time_to_go_s,
            closure_mps: hook_x_rate_mps - deck.mean_aim_velocity.x_mps,
            waving_off,
        };
        // The expected squared vertical velocity of the landing point at the arrival
        // shifted by τ: the Kalman forecast's mean squared plus its variance.
        let (ship, propagator) = (&self.ship, &block.propagator);
        let arm_m = self.deck.landing_point_aft_of_pitch_centre_m;
        let age_s = t - filter.time_s();
        let mut estimate: Option<ShipMotionEstimate> = None;
        let score = |shift_s: f64| {
            let estimate = estimate.get_or_insert_with(|| filter.estimate());
            let lead_s = age_s + (time_to_go_s + shift_s).max(0.0);
            let forecast = propagator.forecast_mean(ship, estimate, lead_s);
            let mean = forecast.deck_point_climb_rate_mps(arm_m);
            let sigma =
                propagator.deck_point_sigma(ship, estimate, lead_s, arm_m, forecast.pitch_rad, 1);
            mean * mean + sigma * sigma
        };
        let change_mps = block.timing.step(&inputs, score);
        self.airspeed_reference_mps = block.nominal_airspeed_mps + change_mps;
    }

    /// The arrival-timing block's change of the airspeed reference now (m/s); `None`
    /// without the block.
    pub fn arrival_timing_speed_change_mps(&self) -> Option<f64> {
        self.arrival_timing
            .as_ref()
            .map(|block| block.timing.speed_change_mps())
    }
}
