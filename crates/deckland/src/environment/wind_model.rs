//! The wind model: the mean wind, the free-air turbulence with its state and random
//! streams, and the carrier air wake, summed at the aircraft (paper §3.4; docs/model.md
//! §3.2). The wind's types and the wake's formulas are in [`super::wind`], the turbulence
//! process in [`super::turbulence`]; this module composes them.

use super::turbulence::Turbulence;
use super::turbulence_lateral::LateralTurbulence;
use super::wind::{
    mean_wind_over_angled_deck, periodic_wake, steady_wake, Wind, WindComponents, WindParameters,
};
use crate::parameters::{Bounds, ParameterError};
use crate::random::{RandomStreams, Reseed};

/// The wind model: mean wind, turbulence with its state and streams, and the wake
/// (docs/model.md §3.2).
#[derive(Debug, Clone)]
pub struct WindModel {
    parameters: WindParameters,
    ship_forward_speed_mps: f64,
    turbulence: Turbulence,
    /// The mean wind, constant: [`mean_wind_over_angled_deck`] for the deck angle δ the
    /// model is set up for (0 for the 3-DOF approach, where it is −(V_wd − V_ship) bit
    /// for bit), zero when the mean wind is off.
    mean: Wind,
    /// Lateral turbulence v1: on in the three-dimensional model (with turbulence on),
    /// off (zero, nothing drawn) in the longitudinal one.
    lateral_turbulence: LateralTurbulence,
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
            mean: Self::mean_wind(&parameters, ship_forward_speed_mps, 0.0),
            lateral_turbulence: LateralTurbulence::off(&parameters, streams),
        })
    }

    /// The mean wind for deck angle `deck_angle_rad` (rad), zero when it is off.
    fn mean_wind(
        parameters: &WindParameters,
        ship_forward_speed_mps: f64,
        deck_angle_rad: f64,
    ) -> Wind {
        if !parameters.mean_wind {
            return Wind::default();
        }
        mean_wind_over_angled_deck(
            parameters.wind_over_deck_mps,
            ship_forward_speed_mps,
            deck_angle_rad,
            parameters.crosswind_mps,
        )
    }

    /// The wind in three dimensions (docs/model.md §3.9): the mean wind set up over a
    /// deck angled `deck_angle_rad` (rad) to the final bearing
    /// ([`super::mean_wind_over_angled_deck`]) and lateral turbulence v1 from the
    /// `turbulence_v` stream; every other component and stream as before. Without this
    /// call (the 3-DOF approach) the deck angle is 0 and v1 is off (zero, nothing drawn).
    pub fn three_dimensional(mut self, deck_angle_rad: f64, streams: &RandomStreams) -> Self {
        self.mean = Self::mean_wind(
            &self.parameters,
            self.ship_forward_speed_mps,
            deck_angle_rad,
        );
        self.lateral_turbulence = LateralTurbulence::new(&self.parameters, streams);
        self
    }

    /// The parameters the model was built from.
    pub fn parameters(&self) -> &WindParameters {
        &self.parameters
    }

    /// Advances the turbulence by `dt` (s) for an aircraft flying at `airspeed_mps` (m/s):
    /// its time constant is τ = L/V. Call once per step, outside the RK4 stages.
    pub fn advance(&mut self, dt: f64, airspeed_mps: f64) {
        self.turbulence.advance(dt, airspeed_mps);
        self.lateral_turbulence.advance(dt, airspeed_mps);
    }

    /// Every component at time `time_s` (s) and X = `distance_aft_m` (m, positive aft).
    #[inline]
    pub fn components(&self, time_s: f64, distance_aft_m: f64) -> WindComponents {
        let p = &self.parameters;
        let wake = p.wake_weight(distance_aft_m);
        let scaled = |w: Wind| Wind {
            x_mps: wake * w.x_mps,
            y_mps: wake * w.y_mps,
            z_mps: wake * w.z_mps,
        };
        WindComponents {
            mean: self.mean,
            // Off, v1 is +0 and adds +0 to components that are never −0 (zero when
            // turbulence is off, a continuous random value when on): the same wind.
            turbulence: self.turbulence.wind() + self.lateral_turbulence.wind(),
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
    #[inline]
    pub fn wind(&self, time_s: f64, distance_aft_m: f64) -> Wind {
        self.components(time_s, distance_aft_m).total()
    }
}

impl Reseed for WindModel {
    fn reseed(&mut self, key: u64) {
        self.turbulence.reseed(key);
        self.lateral_turbulence.reseed(key);
    }
}
