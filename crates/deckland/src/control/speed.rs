//! Speed controller: thrust from the airspeed error (paper §4.3, Eq. 38–42).
//!
//! T = T* + m·(K_PV·e_V + K_IV·∫e_V), e_V = V_ref − V_T. With ė_V ≈ −T/m + d (Eq. 39)
//! the error obeys s² + K_PV·s + K_IV = 0 (Eq. 41 with K_DV = 0), so the gains follow
//! from a natural frequency ω and damping ratio ζ: K_IV = ω², K_PV = 2ζω. The derivative
//! term of Eq. 40 is left out: it would need the airspeed rate, which the engine lag
//! (0.625 s) makes pointless at these bandwidths. The default ω = 0.25 rad/s sits well
//! below the engine's 1/0.625 = 1.6 rad/s, so the lag costs little phase (about 9°).

use super::loop_controller::{LoopController, LoopGains};
use crate::parameters::{Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// What a user chooses for the speed loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SpeedControllerParameters {
    /// Natural frequency ω of the airspeed error dynamics (rad/s); default 0.25.
    pub natural_frequency_radps: f64,
    /// Damping ratio ζ of the airspeed error dynamics (–); default 1.0.
    pub damping_ratio: f64,
}

impl Default for SpeedControllerParameters {
    fn default() -> Self {
        Self {
            natural_frequency_radps: 0.25,
            damping_ratio: 1.0,
        }
    }
}

impl SpeedControllerParameters {
    /// Checks both design values are finite and positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.speed";
        Bounds::positive_up_to(10.0).check(
            SECTION,
            "natural_frequency_radps",
            self.natural_frequency_radps,
        )?;
        Bounds::closed(0.1, 5.0).check(SECTION, "damping_ratio", self.damping_ratio)
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
}

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
        }
    }

    /// Thrust command (N) for an airspeed error e_V (m/s) and its integral (m).
    #[inline]
    pub fn thrust_command_n(&self, error_mps: f64, integral_m: f64) -> f64 {
        self.trim_thrust_n + self.mass_kg * self.loop_controller.output(error_mps, integral_m, 0.0)
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
