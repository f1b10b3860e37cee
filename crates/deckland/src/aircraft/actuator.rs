//! Second-order elevator (stabilator) actuator with position and optional rate limits
//! (docs/model.md §2.6, paper §3.6).
//!
//! Effects, in the order they are applied:
//! 1. the command is limited to the position limits (so the actuator never aims beyond
//!    them);
//! 2. the second-order dynamics δ̈ = ω_n²(δ_c − δ) − 2ζω_n·δ̇ (ω_n = 30.74 rad/s,
//!    ζ = 0.509);
//! 3. the rate limit, if set, clamps δ̇ (F/A-18 stabilator 40°/s, the realistic default;
//!    none in the paper's set);
//! 4. the position limits act on the actuator's *position*: at a limit, motion further
//!    out is stopped (rate and acceleration outward set to zero), and after each step
//!    the position is clamped ([`ElevatorActuator::constrain`]).

use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Elevator actuator parameters, in the units a user reads from a data sheet.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ElevatorActuatorParameters {
    /// Natural frequency ω_n (rad/s); 30.74 rad/s (paper §3.6, ref. \[13\]).
    pub natural_frequency_rad_s: f64,
    /// Damping ratio ζ (–); 0.509 (paper §3.6).
    pub damping_ratio: f64,
    /// Lowest deflection (deg, trailing edge up); −25° (paper §2.2.1.2).
    pub min_deflection_deg: f64,
    /// Highest deflection (deg, trailing edge down); +10° (paper §2.2.1.2).
    pub max_deflection_deg: f64,
    /// Rate limit (deg/s): 40 °/s for the F/A-18 stabilator (the actuator model of the
    /// NASA F/A-18 HARV simulation, Messina et al., NASA TM-110216, 1996); `None` is the
    /// paper's ideal actuator (docs/model.md §2.6).
    pub rate_limit_degps: Option<f64>,
}

impl Default for ElevatorActuatorParameters {
    fn default() -> Self {
        Self {
            natural_frequency_rad_s: 30.74,
            damping_ratio: 0.509,
            min_deflection_deg: -25.0,
            max_deflection_deg: 10.0,
            rate_limit_degps: Some(40.0),
        }
    }
}

impl ElevatorActuatorParameters {
    /// Checks the dynamics and the limits against their physical ranges: natural
    /// frequency 1–300 rad/s, damping 0.05–5, lower limit in [−60°, 0°), upper limit in
    /// (0°, 60°], rate limit in (0, 500] °/s.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.elevator_actuator";
        check_ranges!(SECTION, self, {
            natural_frequency_rad_s: Bounds::closed(1.0, 300.0),
            damping_ratio: Bounds::closed(0.05, 5.0),
            min_deflection_deg: Bounds::closed(-60.0, 0.0).exclusive_max(),
            max_deflection_deg: Bounds::positive_up_to(60.0),
        });
        if let Some(rate) = self.rate_limit_degps {
            Bounds::positive_up_to(500.0).check(SECTION, "rate_limit_degps", rate)?;
        }
        Ok(())
    }
}

/// Which position limit, if any, the actuator sits on.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ActuatorLimit {
    /// Between the limits.
    Free,
    /// At the lowest (trailing-edge-up, most negative) deflection.
    Lower,
    /// At the highest (trailing-edge-down) deflection.
    Upper,
}

/// The actuator model in radians, built from [`ElevatorActuatorParameters`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ElevatorActuator {
    parameters: ElevatorActuatorParameters,
    omega_squared: f64,
    two_zeta_omega: f64,
    min_rad: f64,
    max_rad: f64,
    rate_limit_radps: f64,
}

impl ElevatorActuator {
    /// Builds the actuator after validating its parameters.
    pub fn new(parameters: ElevatorActuatorParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        let omega = parameters.natural_frequency_rad_s;
        Ok(Self {
            parameters,
            omega_squared: omega * omega,
            two_zeta_omega: 2.0 * parameters.damping_ratio * omega,
            min_rad: parameters.min_deflection_deg.to_radians(),
            max_rad: parameters.max_deflection_deg.to_radians(),
            rate_limit_radps: parameters
                .rate_limit_degps
                .map_or(f64::INFINITY, f64::to_radians),
        })
    }

    /// The parameters the model was built from.
    pub fn parameters(&self) -> &ElevatorActuatorParameters {
        &self.parameters
    }

    /// Lowest deflection (rad).
    #[inline]
    pub fn min_rad(&self) -> f64 {
        self.min_rad
    }

    /// Highest deflection (rad).
    #[inline]
    pub fn max_rad(&self) -> f64 {
        self.max_rad
    }

    /// Which limit a deflection (rad) sits on, within 10⁻⁹ rad.
    #[inline]
    pub fn limit_at(&self, position_rad: f64) -> ActuatorLimit {
        const TOLERANCE: f64 = 1e-9;
        if position_rad <= self.min_rad + TOLERANCE {
            ActuatorLimit::Lower
        } else if position_rad >= self.max_rad - TOLERANCE {
            ActuatorLimit::Upper
        } else {
            ActuatorLimit::Free
        }
    }

    /// Derivatives (δ̇, δ̈) of position (rad) and rate (rad/s) for a command (rad).
    #[inline]
    pub fn derivative(&self, position_rad: f64, rate_radps: f64, command_rad: f64) -> (f64, f64) {
        let command = command_rad.clamp(self.min_rad, self.max_rad);
        let mut acceleration =
            self.omega_squared * (command - position_rad) - self.two_zeta_omega * rate_radps;
        let mut velocity = rate_radps.clamp(-self.rate_limit_radps, self.rate_limit_radps);
        if (velocity >= self.rate_limit_radps && acceleration > 0.0)
            || (velocity <= -self.rate_limit_radps && acceleration < 0.0)
        {
            acceleration = 0.0;
        }
        if position_rad >= self.max_rad && velocity >= 0.0 {
            velocity = 0.0;
            acceleration = acceleration.min(0.0);
        } else if position_rad <= self.min_rad && velocity <= 0.0 {
            velocity = 0.0;
            acceleration = acceleration.max(0.0);
        }
        (velocity, acceleration)
    }

    /// Clamps a position (rad) and rate (rad/s) after a step: a position beyond a limit is
    /// put back on it and its outward rate removed; the rate is held within its limit.
    #[inline]
    pub fn constrain(&self, position_rad: &mut f64, rate_radps: &mut f64) {
        *rate_radps = rate_radps.clamp(-self.rate_limit_radps, self.rate_limit_radps);
        if *position_rad > self.max_rad {
            *position_rad = self.max_rad;
            *rate_radps = rate_radps.min(0.0);
        } else if *position_rad < self.min_rad {
            *position_rad = self.min_rad;
            *rate_radps = rate_radps.max(0.0);
        }
    }
}

impl Default for ElevatorActuator {
    fn default() -> Self {
        Self::new(ElevatorActuatorParameters::default())
            .expect("the default actuator parameters are valid")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integration::{rk4_step, OdeSystem};

    struct Alone {
        actuator: ElevatorActuator,
        command: f64,
    }

    impl OdeSystem<2> for Alone {
        fn derivative(&self, _t: f64, x: &[f64; 2]) -> [f64; 2] {
            let (v, a) = self.actuator.derivative(x[0], x[1], self.command);
            [v, a]
        }
        fn constrain(&self, x: &mut [f64; 2]) {
            let [mut p, mut r] = *x;
            self.actuator.constrain(&mut p, &mut r);
            *x = [p, r];
        }
    }

    fn simulate(system: &Alone, seconds: f64) -> Vec<[f64; 2]> {
        let dt = 1e-4;
        let mut x = [0.0, 0.0];
        let mut out = vec![x];
        for k in 0..(seconds / dt).round() as usize {
            x = rk4_step(system, k as f64 * dt, &x, dt);
            out.push(x);
        }
        out
    }

    /// Small step within the limits: overshoot of a second-order system with ζ = 0.509
    /// is exp(−πζ/√(1−ζ²)) = 15.6 % (textbook formula, computed here independently).
    #[test]
    fn small_step_overshoot_matches_second_order_formula() {
        let actuator = ElevatorActuator::default();
        let command = 1.0_f64.to_radians();
        let trace = simulate(&Alone { actuator, command }, 1.0);
        let peak = trace.iter().map(|x| x[0]).fold(f64::MIN, f64::max);
        let zeta: f64 = 0.509;
        let expected = (-std::f64::consts::PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        let overshoot = peak / command - 1.0;
        assert!(
            (overshoot - expected).abs() < 1e-3,
            "{overshoot} vs {expected}"
        );
        assert!((trace.last().unwrap()[0] - command).abs() < 1e-6);
    }

    #[test]
    fn position_never_exceeds_limits_even_with_overshoot() {
        let actuator = ElevatorActuator::default();
        let trace = simulate(
            &Alone {
                actuator,
                command: 40f64.to_radians(),
            },
            1.0,
        );
        let max = trace.iter().map(|x| x[0]).fold(f64::MIN, f64::max);
        assert!(
            max <= 10f64.to_radians() + 1e-12,
            "max {}",
            max.to_degrees()
        );
        assert!((trace.last().unwrap()[0] - 10f64.to_radians()).abs() < 1e-9);
        let trace = simulate(
            &Alone {
                actuator,
                command: -24.5f64.to_radians(),
            },
            1.0,
        );
        let min = trace.iter().map(|x| x[0]).fold(f64::MAX, f64::min);
        assert!(
            min >= -25f64.to_radians() - 1e-12,
            "min {}",
            min.to_degrees()
        );
    }

    #[test]
    fn rate_limit_bounds_the_slew() {
        let actuator = ElevatorActuator::new(ElevatorActuatorParameters {
            rate_limit_degps: Some(40.0),
            ..Default::default()
        })
        .unwrap();
        let trace = simulate(
            &Alone {
                actuator,
                command: -20f64.to_radians(),
            },
            1.0,
        );
        let dt = 1e-4;
        let fastest = trace
            .windows(2)
            .map(|w| ((w[1][0] - w[0][0]) / dt).abs())
            .fold(0.0, f64::max);
        assert!(
            fastest <= 40f64.to_radians() * 1.0001,
            "{}",
            fastest.to_degrees()
        );
        // At 40°/s, 20° takes at least 0.5 s.
        let at_half_second = trace[(0.45 / dt) as usize][0];
        assert!(at_half_second > -20f64.to_radians() + 0.01);
    }

    #[test]
    fn invalid_limits_are_named() {
        let error = ElevatorActuator::new(ElevatorActuatorParameters {
            max_deflection_deg: -3.0,
            ..Default::default()
        })
        .unwrap_err();
        assert!(error.to_string().contains("max_deflection_deg"));
    }
}
