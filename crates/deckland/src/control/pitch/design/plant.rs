//! The pitch plant at trim as the laws and the design see it: the derivatives of the
//! pitch acceleration, the short-period coupling through the angle of attack, and the
//! elevator actuator without its limits (docs/model.md §2.6, §4).

use serde::{Deserialize, Serialize};

use crate::parameters::ParameterError;

/// Pitch-plant derivatives from the linearisation at trim (paper Eq. 26; docs/model.md §4:
/// taken from the linearisation, not hard-coded).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PitchPlantDerivatives {
    /// Pitch damping ∂q̇/∂q (1/s), negative for a stable airframe (paper: −0.15).
    pub dqdot_dq_per_s: f64,
    /// Elevator effectiveness ∂q̇/∂δe (1/s²), negative for positive trailing-edge-down
    /// elevator (about −1.9 at the landing trim); must be nonzero.
    pub dqdot_delevator_per_s2: f64,
}

impl PitchPlantDerivatives {
    /// The name under which the derivatives appear in errors: they are not set in a
    /// scenario but computed from the linearisation at trim.
    pub const SECTION: &'static str = "linearisation at trim";

    /// Checks that both derivatives are finite and ∂q̇/∂δe ≠ 0.
    pub fn validate(&self) -> Result<(), ParameterError> {
        if !self.dqdot_dq_per_s.is_finite() {
            return Err(ParameterError::new(
                Self::SECTION,
                "dqdot_dq_per_s",
                self.dqdot_dq_per_s,
                "a finite pitch damping",
            ));
        }
        if !(self.dqdot_delevator_per_s2.is_finite() && self.dqdot_delevator_per_s2 != 0.0) {
            return Err(ParameterError::new(
                Self::SECTION,
                "dqdot_delevator_per_s2",
                self.dqdot_delevator_per_s2,
                "a finite, nonzero elevator effectiveness",
            ));
        }
        Ok(())
    }
}

/// Linear second-order elevator actuator (docs/model.md §2.6) without its limits.
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn zero_elevator_effectiveness_is_rejected() {
        let plant = PitchPlantDerivatives {
            dqdot_dq_per_s: -0.15,
            dqdot_delevator_per_s2: 0.0,
        };
        let error = plant.validate().expect_err("zero");
        assert!(error.path.ends_with("dqdot_delevator_per_s2"), "{error}");
    }

    #[test]
    fn non_finite_damping_derivative_is_named() {
        let plant = PitchPlantDerivatives {
            dqdot_dq_per_s: f64::NAN,
            dqdot_delevator_per_s2: -1.9,
        };
        let message = plant.validate().expect_err("NaN").to_string();
        assert!(message.contains("dqdot_dq_per_s"), "{message}");
    }
}
