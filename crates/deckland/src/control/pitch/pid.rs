//! PID pitch controller for comparison (paper Eq. 37; docs/model.md §5).
//!
//! Same equivalent-control form as the O-PD but without the observer:
//! U = K_P·e_θ + K_I·∫e_θ dt + K_D·ė_θ with e_θ = θ_ref − θ_m and ė_θ = −q_m
//! (derivative on the measured pitch rate, so a step in θ_ref gives no derivative kick),
//! and Δδe = U/(∂q̇/∂δe), δe = δe* + Δδe.
//!
//! **Anti-windup (conditional integration)**: when enabled, the integrator is frozen
//! while the elevator actuator sits on a position limit *and* integrating the current
//! error would push the command further into that limit; it keeps integrating when the
//! error would pull the elevator back off the limit.

use serde::{Deserialize, Serialize};

use crate::control::design::{LinearisedLaw, AxisPlantDerivatives};
use super::law::{ElevatorSaturation, PitchDesignContext, PitchLawDesign, PitchLawInputs, SECTION};
use crate::control::{AxisLaw, LinearLaw};
use crate::parameters::{Bounds, ParameterError};

/// PID gains and options (paper Eq. 37; gains as printed in paper §4.2.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct PidParameters {
    /// Proportional gain K_P (1/s²; paper: 57.01).
    pub proportional_per_s2: f64,
    /// Integral gain K_I (1/s³; paper: 50).
    pub integral_per_s3: f64,
    /// Derivative gain K_D (1/s; paper: 17.19).
    pub derivative_per_s: f64,
    /// Freeze the integrator while the elevator saturates and the error pushes further
    /// into the limit (default true; docs/model.md §5).
    pub anti_windup: bool,
}

impl Default for PidParameters {
    /// The gains for the realistic stabilator (docs/pitch-step.md): the O-PD's PD
    /// (K_P = 6.25 s⁻², K_D = 4.81 s⁻¹) and a slow integral K_I = 0.25 s⁻³, anti-windup
    /// on. The integral is kept slow for the loop above it: at K_I = 1 the sink-rate loop
    /// keeps 41.7° of phase margin, at 0.25 it keeps 47.4° (`--example margins`).
    fn default() -> Self {
        Self {
            proportional_per_s2: 6.25,
            integral_per_s3: 0.25,
            derivative_per_s: 4.81,
            anti_windup: true,
        }
    }
}

impl PidParameters {
    /// The paper's gains (§4.2.3): K_P = 57.01, K_I = 50, K_D = 17.19, anti-windup on.
    pub fn paper() -> Self {
        Self {
            proportional_per_s2: 57.01,
            integral_per_s3: 50.0,
            derivative_per_s: 17.19,
            anti_windup: true,
        }
    }
}

impl PidParameters {
    /// Checks that every gain lies in [0, 10⁴] (in its unit), naming `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        let gain = Bounds::closed(0.0, 1e4);
        gain.check(section, "proportional_per_s2", self.proportional_per_s2)?;
        gain.check(section, "integral_per_s3", self.integral_per_s3)?;
        gain.check(section, "derivative_per_s", self.derivative_per_s)
    }
}

impl PitchLawDesign for PidParameters {
    type Law = PidController;
    const LABEL: &'static str = "PID";

    fn validate(&self, section: &str) -> Result<(), ParameterError> {
        PidParameters::validate(self, section)
    }

    fn build(&self, context: &PitchDesignContext) -> Result<PidController, ParameterError> {
        PidController::new(self, context.plant)
    }

    fn paper_tuning() -> Self {
        PidParameters::paper()
    }

    fn linear_law(&self, plant: AxisPlantDerivatives) -> Option<LinearisedLaw> {
        Some(LinearisedLaw {
            law: linear_pid(self, plant),
            speed_key: "proportional_per_s2",
            speed_value: self.proportional_per_s2,
            speed_advice: "smaller gains",
        })
    }
}

/// The PID in its linear limit about trim, as the design code's [`LinearLaw`]: one
/// state, the integral z (the other two are placeholders), on the measured attitude,
/// with the derivative on the (noise-free) pitch rate,
///
/// ```text
/// ż = r − y;  u = (K_P·(r − y) + K_I·z − K_D·q)/M_δ
/// ```
pub fn linear_pid(parameters: &PidParameters, plant: AxisPlantDerivatives) -> LinearLaw {
    let md = plant.control_power_per_s2;
    let (kp, ki, kd) = (
        parameters.proportional_per_s2,
        parameters.integral_per_s3,
        parameters.derivative_per_s,
    );
    let mut law = LinearLaw::without_states();
    law.state_matrix[0][0] = 0.0;
    law.input_matrix[0][LinearLaw::COMMAND] = 1.0;
    law.input_matrix[0][LinearLaw::MEASURED_ANGLE] = -1.0;
    law.output_states[0] = ki / md;
    law.output_inputs[LinearLaw::COMMAND] = kp / md;
    law.output_inputs[LinearLaw::MEASURED_ANGLE] = -kp / md;
    law.output_inputs[LinearLaw::RATE] = -kd / md;
    law
}

/// State of the PID pitch controller (paper Eq. 37).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct PidState {
    /// Integral of the pitch error ∫e_θ dt (rad·s).
    pub pitch_error_integral_rad_s: f64,
}

/// The PID pitch controller (paper Eq. 37; docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PidController {
    parameters: PidParameters,
    plant: AxisPlantDerivatives,
}

impl PidController {
    /// Builds the controller after validating gains and plant derivatives.
    pub fn new(
        parameters: &PidParameters,
        plant: AxisPlantDerivatives,
    ) -> Result<Self, ParameterError> {
        parameters.validate(SECTION)?;
        plant.validate()?;
        Ok(Self {
            parameters: *parameters,
            plant,
        })
    }

    /// The gains and options in use.
    pub fn parameters(&self) -> &PidParameters {
        &self.parameters
    }

    /// The plant derivatives the controller was built for.
    pub fn plant(&self) -> &AxisPlantDerivatives {
        &self.plant
    }

    /// State for a start at trim: empty integrator.
    pub fn initial_state(&self) -> PidState {
        PidState::default()
    }

    /// Elevator command δe = δe* + U/(∂q̇/∂δe) (rad; paper Eq. 37 in the form of
    /// Eq. 35–36), not limited: the actuator applies its position limits.
    #[inline]
    pub fn elevator_command_rad(&self, state: &PidState, inputs: &PitchLawInputs) -> f64 {
        let pitch_error_rad = inputs.theta_ref_rad - inputs.theta_measured_rad;
        // The same feed-forward of a shaped reference as the O-PD's (zero for a plain
        // command, which leaves the paper's Eq. 37).
        let feed_forward = inputs.theta_ref_acceleration_radps2
            - self.plant.rate_damping_per_s * inputs.theta_ref_rate_radps;
        let equivalent_control = self.parameters.proportional_per_s2 * pitch_error_rad
            + self.parameters.integral_per_s3 * state.pitch_error_integral_rad_s
            + self.parameters.derivative_per_s
                * (inputs.theta_ref_rate_radps - inputs.pitch_rate_measured_radps)
            + feed_forward;
        inputs.elevator_trim_rad + equivalent_control / self.plant.control_power_per_s2
    }

    /// Integrator derivative: e_θ (rad), or 0 while anti-windup freezes it.
    #[inline]
    pub fn derivative(&self, _state: &PidState, inputs: &PitchLawInputs) -> PidState {
        let pitch_error_rad = inputs.theta_ref_rad - inputs.theta_measured_rad;
        let frozen = self.parameters.anti_windup
            && self.integration_pushes_into_limit(pitch_error_rad, inputs.elevator_saturation);
        PidState {
            pitch_error_integral_rad_s: if frozen { 0.0 } else { pitch_error_rad },
        }
    }

    /// True when integrating `pitch_error_rad` would move the elevator command further
    /// into the limit the actuator sits on.
    #[inline]
    fn integration_pushes_into_limit(
        &self,
        pitch_error_rad: f64,
        saturation: ElevatorSaturation,
    ) -> bool {
        // Rate of change of the integral term's elevator contribution, up to a positive
        // factor: K_I·e/(∂q̇/∂δe).
        let command_drift =
            self.parameters.integral_per_s3 * pitch_error_rad / self.plant.control_power_per_s2;
        match saturation {
            ElevatorSaturation::NotSaturated => false,
            ElevatorSaturation::AtLowerLimit => command_drift < 0.0,
            ElevatorSaturation::AtUpperLimit => command_drift > 0.0,
        }
    }
}

impl AxisLaw for PidController {
    type Inputs = PitchLawInputs;

    fn label(&self) -> &str {
        "PID"
    }

    fn state_names(&self) -> &'static [&'static str] {
        &["pitch_error_integral_rad_s"]
    }

    #[inline]
    fn surface_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
        let state = PidState {
            pitch_error_integral_rad_s: state[0],
        };
        PidController::elevator_command_rad(self, &state, inputs)
    }

    #[inline]
    fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
        let state = PidState {
            pitch_error_integral_rad_s: state[0],
        };
        rate[0] = PidController::derivative(self, &state, inputs).pitch_error_integral_rad_s;
    }

    fn linear_law(&self) -> Option<LinearLaw> {
        Some(linear_pid(&self.parameters, self.plant))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::control::design::PAPER_PITCH_PLANT as PLANT;

    fn controller(anti_windup: bool) -> PidController {
        let parameters = PidParameters {
            anti_windup,
            ..PidParameters::default()
        };
        PidController::new(&parameters, PLANT).expect("valid")
    }

    #[test]
    fn integrator_freezes_only_when_pushing_into_the_limit() {
        let pid = controller(true);
        let state = pid.initial_state();
        // Nose-up error: the command moves trailing edge up, towards the lower limit.
        let nose_up = PitchLawInputs {
            theta_ref_rad: 0.1,
            ..PitchLawInputs::default()
        };
        let at = |elevator_saturation| PitchLawInputs {
            elevator_saturation,
            ..nose_up
        };
        let rate = |inputs| pid.derivative(&state, &inputs).pitch_error_integral_rad_s;
        assert_eq!(rate(at(ElevatorSaturation::NotSaturated)), 0.1);
        assert_eq!(rate(at(ElevatorSaturation::AtLowerLimit)), 0.0);
        assert_eq!(rate(at(ElevatorSaturation::AtUpperLimit)), 0.1);
        // Without anti-windup it always integrates.
        let free = controller(false);
        let inputs = at(ElevatorSaturation::AtLowerLimit);
        assert_eq!(
            free.derivative(&state, &inputs).pitch_error_integral_rad_s,
            0.1
        );
    }

    #[test]
    fn derivative_acts_on_the_measured_rate_and_command_includes_trim() {
        let pid = PidController::new(&PidParameters::paper(), PLANT).expect("valid");
        let inputs = PitchLawInputs {
            pitch_rate_measured_radps: 0.1,
            elevator_trim_rad: -0.143,
            ..PitchLawInputs::default()
        };
        let command = pid.elevator_command_rad(&pid.initial_state(), &inputs);
        // U = −17.19·0.1, Δδe = U/(−1.93) > 0: a nose-up rate is damped trailing edge down.
        assert!(
            (command - (-0.143 + 1.719 / 1.93)).abs() < 1e-12,
            "{command}"
        );
    }

    #[test]
    fn negative_and_non_finite_gains_are_named() {
        let bad = PidParameters {
            integral_per_s3: -1.0,
            ..PidParameters::default()
        };
        let error = PidController::new(&bad, PLANT).expect_err("neg");
        assert_eq!(error.path, "control.pitch.integral_per_s3");
        let bad = PidParameters {
            derivative_per_s: f64::INFINITY,
            ..PidParameters::default()
        };
        let error = PidController::new(&bad, PLANT).expect_err("inf");
        assert_eq!(error.path, "control.pitch.derivative_per_s");
        let huge = PidParameters {
            proportional_per_s2: 1e308,
            ..PidParameters::default()
        };
        let error = PidController::new(&huge, PLANT).expect_err("huge");
        assert_eq!(error.path, "control.pitch.proportional_per_s2");
    }
}
