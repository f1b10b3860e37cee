//! An axis's plant at trim as the laws and the design see it: the derivatives of the
//! angular acceleration (rate damping and control power), the pitch axis's optional
//! short-period coupling through the angle of attack, the surface actuator without its
//! limits, and the scenario keys of that actuator (docs/model.md §2.6, §4).

use serde::{Deserialize, Serialize};

use crate::parameters::ParameterError;

/// The derivatives of an axis's angular acceleration ω̇ = ∂ω̇/∂ω·ω + ∂ω̇/∂δ·δ at trim, from
/// the linearisation (pitch: M_q, M_δe, paper Eq. 26, docs/model.md §4; roll: L_p, L_δa;
/// yaw: N_r, N_δr), not hard-coded.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AxisPlantDerivatives {
    /// Rate damping ∂ω̇/∂ω (1/s), negative for a stable airframe (pitch M_q; paper:
    /// −0.15).
    pub rate_damping_per_s: f64,
    /// Control power ∂ω̇/∂δ (1/s²); must be nonzero (pitch M_δe, negative for positive
    /// trailing-edge-down elevator, about −1.9 at the landing trim).
    pub control_power_per_s2: f64,
}

/// The paper's pitch-axis derivatives (Eq. 14: M_q = −0.15 s⁻¹, M_δe = −1.93 s⁻²), which
/// the laws' tests design for.
#[cfg(test)]
pub(crate) const PAPER_PITCH_PLANT: AxisPlantDerivatives = AxisPlantDerivatives {
    rate_damping_per_s: -0.15,
    control_power_per_s2: -1.93,
};

impl AxisPlantDerivatives {
    /// The name under which the derivatives appear in errors: they are not set in a
    /// scenario but computed from the linearisation at trim.
    pub const SECTION: &'static str = "linearisation at trim";

    /// Checks that both derivatives are finite and ∂q̇/∂δe ≠ 0.
    pub fn validate(&self) -> Result<(), ParameterError> {
        if !self.rate_damping_per_s.is_finite() {
            return Err(ParameterError::new(
                Self::SECTION,
                "rate_damping_per_s",
                self.rate_damping_per_s,
                "a finite rate damping",
            ));
        }
        if !(self.control_power_per_s2.is_finite() && self.control_power_per_s2 != 0.0) {
            return Err(ParameterError::new(
                Self::SECTION,
                "control_power_per_s2",
                self.control_power_per_s2,
                "a finite, nonzero control power",
            ));
        }
        Ok(())
    }
}

/// Linear second-order surface actuator (docs/model.md §2.6) without its limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearActuator {
    /// Natural frequency ω_a (rad/s).
    pub natural_frequency_radps: f64,
    /// Damping ratio ζ_a (–).
    pub damping_ratio: f64,
}

/// The short-period coupling through the angle of attack, from the linearisation at trim
/// (`deckland linearize`: the α̇ and q̇ rows).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AngleOfAttackCoupling {
    /// ∂α̇/∂α = Z_α (1/s), negative (lift curve slope).
    pub dalphadot_dalpha_per_s: f64,
    /// ∂α̇/∂δe = Z_δ (1/s).
    pub dalphadot_delevator_per_s: f64,
    /// ∂q̇/∂α = M_α (1/s²), negative for a statically stable airframe.
    pub dqdot_dalpha_per_s2: f64,
}

/// The scenario keys of an axis's actuator limits, with which a design names the hardware
/// that limits it.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ActuatorKeys {
    /// The key of the lower stop (deg).
    pub min_deflection: &'static str,
    /// The key of the upper stop (deg).
    pub max_deflection: &'static str,
    /// The key of the rate limit (deg/s).
    pub rate_limit: &'static str,
}

impl ActuatorKeys {
    /// The stabilator of the longitudinal aircraft (`aircraft.elevator_actuator`).
    pub const ELEVATOR: Self = Self {
        min_deflection: "aircraft.elevator_actuator.min_deflection_deg",
        max_deflection: "aircraft.elevator_actuator.max_deflection_deg",
        rate_limit: "aircraft.elevator_actuator.rate_limit_degps",
    };
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_elevator_effectiveness_is_rejected() {
        let plant = AxisPlantDerivatives {
            rate_damping_per_s: -0.15,
            control_power_per_s2: 0.0,
        };
        let error = plant.validate().expect_err("zero");
        assert!(error.path.ends_with("control_power_per_s2"), "{error}");
    }

    #[test]
    fn non_finite_damping_derivative_is_named() {
        let plant = AxisPlantDerivatives {
            rate_damping_per_s: f64::NAN,
            control_power_per_s2: -1.9,
        };
        let message = plant.validate().expect_err("NaN").to_string();
        assert!(message.contains("rate_damping_per_s"), "{message}");
    }
}
