//! A proportional-derivative pitch law, registered only in the test build: it proves that
//! a law is one file plus one registry line, with nothing else edited. A scenario file
//! names it (`type = "proportional"`), the hardware sets tune it by name, and a campaign
//! flies it beside the compared laws (the tests of `monte_carlo::campaign`).
//!
//! δe = δe* + (K_P·(θ_ref − θ_m) + K_D·(q_r − q_m))/(∂q̇/∂δe): the PID of paper Eq. 37
//! without its integral, so it has no state.

use serde::{Deserialize, Serialize};

use crate::control::design::{LinearisedLaw, AxisPlantDerivatives};
use super::{AxisLaw, LinearLaw, PitchDesignContext, PitchLawDesign, PitchLawInputs};
use crate::parameters::{Bounds, ParameterError};

/// The gains of the proportional-derivative law.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ProportionalParameters {
    /// Proportional gain K_P (1/s²).
    pub proportional_per_s2: f64,
    /// Derivative gain K_D (1/s).
    pub derivative_per_s: f64,
}

impl Default for ProportionalParameters {
    /// The realistic PID's proportional and derivative gains (6.25 s⁻², 4.81 s⁻¹).
    fn default() -> Self {
        Self {
            proportional_per_s2: 6.25,
            derivative_per_s: 4.81,
        }
    }
}

impl PitchLawDesign for ProportionalParameters {
    type Law = ProportionalLaw;
    const LABEL: &'static str = "PD";

    fn validate(&self, section: &str) -> Result<(), ParameterError> {
        let gain = Bounds::closed(0.0, 1e4);
        gain.check(section, "proportional_per_s2", self.proportional_per_s2)?;
        gain.check(section, "derivative_per_s", self.derivative_per_s)
    }

    fn build(&self, context: &PitchDesignContext) -> Result<ProportionalLaw, ParameterError> {
        self.validate(super::law::SECTION)?;
        context.plant.validate()?;
        Ok(ProportionalLaw {
            gains: *self,
            plant: context.plant,
        })
    }

    fn linear_law(&self, plant: AxisPlantDerivatives) -> Option<LinearisedLaw> {
        Some(LinearisedLaw {
            law: linear(self, plant),
            speed_key: "proportional_per_s2",
            speed_value: self.proportional_per_s2,
            speed_advice: "smaller gains",
        })
    }
}

/// u = (K_P·(r − y) − K_D·q)/M_δ, no states.
fn linear(gains: &ProportionalParameters, plant: AxisPlantDerivatives) -> LinearLaw {
    let md = plant.control_power_per_s2;
    let mut law = LinearLaw::without_states();
    law.output_inputs[LinearLaw::COMMAND] = gains.proportional_per_s2 / md;
    law.output_inputs[LinearLaw::MEASURED_ANGLE] = -gains.proportional_per_s2 / md;
    law.output_inputs[LinearLaw::RATE] = -gains.derivative_per_s / md;
    law
}

/// The built proportional-derivative law.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ProportionalLaw {
    gains: ProportionalParameters,
    plant: AxisPlantDerivatives,
}

impl AxisLaw for ProportionalLaw {
    type Inputs = PitchLawInputs;

    fn label(&self) -> &str {
        "PD"
    }

    fn state_names(&self) -> &'static [&'static str] {
        &[]
    }

    fn surface_command_rad(&self, _state: &[f64], inputs: &PitchLawInputs) -> f64 {
        let control = self.gains.proportional_per_s2
            * (inputs.theta_ref_rad - inputs.theta_measured_rad)
            + self.gains.derivative_per_s
                * (inputs.theta_ref_rate_radps - inputs.pitch_rate_measured_radps);
        inputs.elevator_trim_rad + control / self.plant.control_power_per_s2
    }

    fn derivative(&self, _state: &[f64], _inputs: &PitchLawInputs, _rate: &mut [f64]) {}

    fn linear_law(&self) -> Option<LinearLaw> {
        Some(linear(&self.gains, self.plant))
    }
}
