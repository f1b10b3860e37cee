//! The wind model: the mean wind, the free-air turbulence with its state and random
//! streams, and the carrier air wake, summed at the aircraft (paper §3.4; docs/model.md
//! §3.2). The wind's types and the wake's formulas are in [`super::wind`], the turbulence
//! process in [`super::turbulence`]; this module composes them.

use super::turbulence::Turbulence;
use super::wind::{mean_wind, periodic_wake, steady_wake, Wind, WindComponents, WindParameters};
use crate::parameters::{Bounds, ParameterError};
use crate::random::RandomStreams;

/// The wind model: mean wind, turbulence with its state and streams, and the wake
/// (docs/model.md §3.2).
#[derive(Debug, Clone)]
pub struct WindModel {
    parameters: WindParameters,
    ship_forward_speed_mps: f64,
    turbulence: Turbulence,
}

impl WindModel {
    /// The wind for these parameters and ship speed (m/s), turbulence started from its
    /// stationary distribution with the `turbulence_u` and `turbulence_w` streams.
    pub fn new(
        parameters: WindParameters,
        ship_forward_speed_mps: f64,
        streams: &RandomStreams,
    ) -> Result<Self, ParameterError> {
        parameters.validate()?;
        Bounds::closed(0.0, 30.0).check(
            "environment.ship",
            "forward_speed_mps",
            ship_forward_speed_mps,
        )?;
        Ok(Self {
            parameters,
            ship_forward_speed_mps,
            turbulence: Turbulence::new(&parameters, streams),
        })
    }

    /// The parameters the model was built from.
    pub fn parameters(&self) -> &WindParameters {
        &self.parameters
    }

    /// Advances the turbulence by `dt` (s) for an aircraft flying at `airspeed_mps` (m/s):
    /// its time constant is τ = L/V. Call once per step, outside the RK4 stages.
    pub fn advance(&mut self, dt: f64, airspeed_mps: f64) {
        self.turbulence.advance(dt, airspeed_mps);
    }

    /// Every component at time `time_s` (s) and X = `distance_aft_m` (m, positive aft).
    pub fn components(&self, time_s: f64, distance_aft_m: f64) -> WindComponents {
        let p = &self.parameters;
        let wake = p.wake_weight(distance_aft_m);
        let scaled = |w: Wind| Wind {
            x_mps: wake * w.x_mps,
            y_mps: wake * w.y_mps,
            z_mps: wake * w.z_mps,
        };
        WindComponents {
            mean: if p.mean_wind {
                mean_wind(p.wind_over_deck_mps, self.ship_forward_speed_mps)
            } else {
                Wind::default()
            },
            turbulence: self.turbulence.wind(),
            steady_wake: if p.steady_wake && wake > 0.0 {
                scaled(steady_wake(distance_aft_m))
            } else {
                Wind::default()
            },
            periodic_wake: if p.periodic_wake && wake > 0.0 {
                scaled(periodic_wake(time_s, distance_aft_m, p))
            } else {
                Wind::default()
            },
        }
    }

    /// The total wind at time `time_s` (s) and X = `distance_aft_m` (m, positive aft).
    pub fn wind(&self, time_s: f64, distance_aft_m: f64) -> Wind {
        self.components(time_s, distance_aft_m).total()
    }
}
