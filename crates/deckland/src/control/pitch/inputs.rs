//! What the pitch controllers read: plant derivatives at trim, the signals of one
//! control step, and the validation errors (MODEL.md §4–5; paper Eq. 26–37).

use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::estimation::ObserverError;

/// Pitch-plant derivatives from the linearisation at trim (paper Eq. 26; MODEL.md §4:
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
    /// Checks that both derivatives are finite and ∂q̇/∂δe ≠ 0.
    pub fn validate(&self) -> Result<(), ControlError> {
        check_finite("dqdot_dq_per_s", self.dqdot_dq_per_s)?;
        check_finite("dqdot_delevator_per_s2", self.dqdot_delevator_per_s2)?;
        if self.dqdot_delevator_per_s2 == 0.0 {
            return Err(ControlError::ZeroElevatorEffectiveness);
        }
        Ok(())
    }
}

/// Which position limit the elevator actuator sits on (MODEL.md §2.6: −25°…+10°).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ElevatorSaturation {
    /// The actuator is inside its travel.
    #[default]
    NotSaturated,
    /// At the lower (most negative, trailing-edge-up, nose-up) position limit.
    AtLowerLimit,
    /// At the upper (most positive, trailing-edge-down, nose-down) position limit.
    AtUpperLimit,
}

impl ElevatorSaturation {
    /// Classifies an actuator position (rad) against its limits (rad): at a limit when
    /// within `tolerance_rad` of it or beyond it.
    pub fn from_position(
        position_rad: f64,
        lower_limit_rad: f64,
        upper_limit_rad: f64,
        tolerance_rad: f64,
    ) -> Self {
        if position_rad <= lower_limit_rad + tolerance_rad {
            Self::AtLowerLimit
        } else if position_rad >= upper_limit_rad - tolerance_rad {
            Self::AtUpperLimit
        } else {
            Self::NotSaturated
        }
    }
}

/// The signals a pitch controller reads at one instant (MODEL.md §5); angles in rad,
/// rates in rad/s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PitchControlInputs {
    /// Commanded pitch attitude θ_ref (rad), from the sink-rate controller.
    pub theta_ref_rad: f64,
    /// Measured pitch attitude θ_m (rad), noise included (MODEL.md §3.3).
    pub theta_measured_rad: f64,
    /// Measured pitch rate q (rad/s); used by the PID's derivative term only.
    pub pitch_rate_measured_radps: f64,
    /// Actual elevator position δe (rad) from the actuator (not the command).
    pub elevator_actual_rad: f64,
    /// Trim pitch attitude θ* (rad) about which the plant was linearised.
    pub theta_trim_rad: f64,
    /// Trim elevator δe* (rad).
    pub elevator_trim_rad: f64,
    /// Which position limit, if any, the elevator actuator sits on.
    pub elevator_saturation: ElevatorSaturation,
}

/// Why a controller could not be built from its parameters (MODEL.md §5).
#[derive(Debug, Clone, PartialEq, Error)]
pub enum ControlError {
    /// A gain, derivative or design parameter is NaN or infinite.
    #[error("controller parameter `{field}` must be finite, got {value}")]
    NonFinite {
        /// Name of the parameter.
        field: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A design parameter (settling time, damping ratio) is zero or negative.
    #[error("controller parameter `{field}` must be > 0, got {value}")]
    NonPositive {
        /// Name of the parameter.
        field: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A parameter lies outside its allowed range.
    #[error("controller parameter `{field}` = {value} is out of range: expected {expected}")]
    OutOfRange {
        /// Name of the parameter.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
    /// A PID gain is negative.
    #[error("controller gain `{field}` must be >= 0, got {value}")]
    NegativeGain {
        /// Name of the gain.
        field: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// ∂q̇/∂δe is zero, so the elevator cannot move the pitch rate.
    #[error("pitch plant derivative `dqdot_delevator_per_s2` must be nonzero, got 0")]
    ZeroElevatorEffectiveness,
    /// The O-PD controller's observer parameters are invalid.
    #[error("invalid observer of the O-PD pitch controller: {0}")]
    Observer(#[from] ObserverError),
}

/// Rejects a non-finite value, naming the field.
pub(crate) fn check_finite(field: &'static str, value: f64) -> Result<(), ControlError> {
    if value.is_finite() {
        Ok(())
    } else {
        Err(ControlError::NonFinite { field, value })
    }
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
        assert_eq!(
            plant.validate(),
            Err(ControlError::ZeroElevatorEffectiveness)
        );
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

    #[test]
    fn saturation_is_classified_against_the_limits() {
        let (lower, upper) = (-0.436, 0.175);
        let classify = |p| ElevatorSaturation::from_position(p, lower, upper, 1e-6);
        assert_eq!(classify(0.0), ElevatorSaturation::NotSaturated);
        assert_eq!(classify(lower), ElevatorSaturation::AtLowerLimit);
        assert_eq!(classify(upper + 1.0), ElevatorSaturation::AtUpperLimit);
    }
}
