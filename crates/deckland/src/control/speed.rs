//! Speed controller: thrust from the airspeed error (paper §4.3, Eq. 38–42).
//!
//! T = T* + m·(K_PV·e_V + K_IV·∫e_V), e_V = V_ref − V_T. With ė_V ≈ −T/m + d (Eq. 39)
//! the error obeys s² + K_PV·s + K_IV = 0 (Eq. 41 with K_DV = 0), so the gains follow
//! from a natural frequency ω and damping ratio ζ: K_IV = ω², K_PV = 2ζω. The derivative
//! term of Eq. 40 is left out: it would need the airspeed rate, which the engine lag
//! (0.625 s) makes pointless at these bandwidths. The default ω = 0.25 rad/s sits well
//! below the engine's 1/0.625 = 1.6 rad/s, so the lag costs little phase (about 9°).
//!
//! **Airspeed filter** (realistic hardware, off in the paper's set): the airspeed fed back
//! can pass a first-order low-pass V̇_f = ω_f·(V_T − V_f). The free-air turbulence is a
//! Gauss–Markov process with no derivative; each 1-ms step moves the airspeed by about
//! σ_u·√(2dt/τ) ≈ 0.036 m/s, which K_PV turns into a jump of m·K_PV·0.036 ≈ 270 N of thrust
//! command: hundreds of kN/s of command rate that the engines only average. The filter
//! removes that without slowing the loop much: at 4 rad/s it costs about 7° of phase at
//! the loop's crossover near 0.46 rad/s (phase margin 49°; 41° at 2 rad/s).

use super::loop_controller::{LoopController, LoopGains};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// What a user chooses for the speed loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SpeedControllerParameters {
    /// Natural frequency ω of the airspeed error dynamics (rad/s); default 0.25.
    pub natural_frequency_radps: f64,
    /// Damping ratio ζ of the airspeed error dynamics (–); default 1.0.
    pub damping_ratio: f64,
    /// Bandwidth of the first-order filter on the airspeed fed back (rad/s); `None` feeds
    /// back the raw airspeed (the paper's set).
    pub airspeed_filter_frequency_radps: Option<f64>,
}

impl Default for SpeedControllerParameters {
    fn default() -> Self {
        Self {
            natural_frequency_radps: 0.25,
            damping_ratio: 1.0,
            airspeed_filter_frequency_radps: Some(4.0),
        }
    }
}

impl SpeedControllerParameters {
    /// Checks both design values are finite and positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.speed";
        check_ranges!(SECTION, self, {
            natural_frequency_radps: Bounds::positive_up_to(10.0),
            damping_ratio: Bounds::closed(0.1, 5.0),
        });
        if let Some(frequency) = self.airspeed_filter_frequency_radps {
            Bounds::closed(0.1, 100.0).check(
                SECTION,
                "airspeed_filter_frequency_radps",
                frequency,
            )?;
        }
        Ok(())
    }

    /// The paper's set: no filter on the airspeed.
    pub fn paper() -> Self {
        Self {
            airspeed_filter_frequency_radps: None,
            ..Self::default()
        }
    }

    /// Proportional gain K_PV = 2ζω (1/s).
    pub fn proportional_per_s(&self) -> f64 {
        2.0 * self.damping_ratio * self.natural_frequency_radps
    }

    /// Integral gain K_IV = ω² (1/s²).
    pub fn integral_per_s2(&self) -> f64 {
        self.natural_frequency_radps * self.natural_frequency_radps
    }
}

/// The speed loop about a trim thrust.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpeedController {
    loop_controller: LoopController,
    mass_kg: f64,
    trim_thrust_n: f64,
    filter_radps: Option<f64>,
}

/// The speed loop's state names: its integral, and the filtered airspeed when filtered.
const STATE_NAMES: [&str; 2] = ["airspeed_error_integral_m", "filtered_airspeed_mps"];

impl SpeedController {
    /// The loop for an aircraft of `mass_kg` trimmed at `trim_thrust_n`, with the thrust
    /// limited to [0, `max_thrust_n`] (anti-windup at those limits).
    pub fn new(
        parameters: &SpeedControllerParameters,
        mass_kg: f64,
        trim_thrust_n: f64,
        max_thrust_n: f64,
    ) -> Self {
        Self {
            loop_controller: LoopController {
                gains: LoopGains {
                    proportional: parameters.proportional_per_s(),
                    integral: parameters.integral_per_s2(),
                    derivative: 0.0,
                },
                output_min: -trim_thrust_n / mass_kg,
                output_max: (max_thrust_n - trim_thrust_n) / mass_kg,
            },
            mass_kg,
            trim_thrust_n,
            filter_radps: parameters.airspeed_filter_frequency_radps,
        }
    }

    /// The names of the loop's states: ∫e_V, and V_f with the filter.
    pub fn state_names(&self) -> &'static [&'static str] {
        match self.filter_radps {
            None => &STATE_NAMES[..1],
            Some(_) => &STATE_NAMES,
        }
    }

    /// The state at a start at `airspeed_mps`: empty integral, filter settled.
    pub fn initial_state(&self, airspeed_mps: f64, state: &mut [f64]) {
        state[0] = 0.0;
        if self.filter_radps.is_some() {
            state[1] = airspeed_mps;
        }
    }

    /// The airspeed the loop feeds back (m/s): filtered, or `airspeed_mps` itself.
    #[inline]
    pub fn feedback_airspeed_mps(&self, state: &[f64], airspeed_mps: f64) -> f64 {
        match self.filter_radps {
            None => airspeed_mps,
            Some(_) => state[1],
        }
    }

    /// The state's rates for the error `error_mps` (m/s) of the fed-back airspeed and the
    /// true airspeed `airspeed_mps` (m/s).
    #[inline]
    pub fn derivative(&self, state: &[f64], error_mps: f64, airspeed_mps: f64, rate: &mut [f64]) {
        rate[0] = self.integral_rate(error_mps, state[0]);
        if let Some(omega) = self.filter_radps {
            rate[1] = omega * (airspeed_mps - state[1]);
        }
    }

    /// Thrust command (N) for an airspeed error e_V (m/s) and its integral (m).
    #[inline]
    pub fn thrust_command_n(&self, error_mps: f64, integral_m: f64) -> f64 {
        self.trim_thrust_n + self.mass_kg * self.loop_controller.output(error_mps, integral_m, 0.0)
    }

    /// The wave-off's thrust (N) at the airspeed error `error_mps` (reference minus
    /// airspeed): `full_n` up to `margin_mps` over the reference, then less by
    /// m·`gain_per_s` per m/s beyond, not below 0; `margin_mps` 0 is full thrust at any
    /// airspeed.
    #[inline]
    pub fn climb_out_thrust_n(
        &self,
        error_mps: f64,
        margin_mps: f64,
        gain_per_s: f64,
        full_n: f64,
    ) -> f64 {
        let over_mps = -error_mps - margin_mps;
        if margin_mps <= 0.0 || over_mps <= 0.0 {
            return full_n;
        }
        (full_n - self.mass_kg * gain_per_s * over_mps).max(0.0)
    }

    /// Rate of the integral state (m/s), frozen while the thrust is saturated.
    #[inline]
    pub fn integral_rate(&self, error_mps: f64, integral_m: f64) -> f64 {
        self.loop_controller
            .integral_rate(error_mps, integral_m, 0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gains_follow_the_second_order_design() {
        let p = SpeedControllerParameters {
            natural_frequency_radps: 0.3,
            damping_ratio: 0.8,
            airspeed_filter_frequency_radps: None,
        };
        assert!((p.proportional_per_s() - 0.48).abs() < 1e-15);
        assert!((p.integral_per_s2() - 0.09).abs() < 1e-15);
    }

    #[test]
    fn slow_aircraft_gets_more_thrust_within_limits() {
        let c = SpeedController::new(
            &SpeedControllerParameters::default(),
            15_000.0,
            26_000.0,
            142_344.0,
        );
        assert!(c.thrust_command_n(1.0, 0.0) > 26_000.0);
        assert_eq!(c.thrust_command_n(1e3, 0.0), 142_344.0);
        assert_eq!(c.thrust_command_n(-1e3, 0.0), 0.0);
        assert_eq!(c.integral_rate(1e3, 0.0), 0.0);
    }
}
