//! The pitch-law interface: what every pitch controller reads, owns and produces, and how
//! the registered laws are listed (docs/model.md §4–5; paper Eq. 26–37).

use std::fmt;

use serde::{Deserialize, Serialize};

use crate::aircraft::ElevatorActuatorParameters;
use crate::parameters::ParameterError;
use crate::sensors::PitchNoiseParameters;

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

/// Which position limit the elevator actuator sits on (docs/model.md §2.6: −25°…+10°).
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

/// The signals a pitch law reads at one instant (docs/model.md §5); angles in rad, rates in
/// rad/s.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PitchLawInputs {
    /// Commanded pitch attitude θ_ref (rad), from the sink-rate controller.
    pub theta_ref_rad: f64,
    /// Rate of the commanded attitude q_r (rad/s) when the command is a shaped trajectory
    /// (docs/model.md §5.2, feed-forward); 0 for a plain command.
    pub theta_ref_rate_radps: f64,
    /// Acceleration of the commanded attitude q̇_r (rad/s²); 0 for a plain command.
    pub theta_ref_acceleration_radps2: f64,
    /// Measured pitch attitude θ_m (rad), noise included (docs/model.md §3.3).
    pub theta_measured_rad: f64,
    /// How old the measurement is (s): 0 when read continuously; with a flight-control
    /// computer, the time since the middle of the samples it averaged.
    pub measurement_age_s: f64,
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

/// A pitch-attitude control law: θ_ref → elevator command. The O-PD, the PID and a
/// user's own law are peers behind this trait.
///
/// A law owns a continuous state of `state_names().len()` numbers, which the simulation
/// integrates with the plant (RK4, all stages): it calls
/// [`PitchLaw::elevator_command_rad`] for the actuator command and
/// [`PitchLaw::derivative`] for the state's rate, both with the same state and inputs.
/// Both must be pure functions of their arguments (no interior mutability), so that a
/// run is reproducible.
pub trait PitchLaw: fmt::Debug + Send + Sync {
    /// Short label for tables and plots, e.g. `O-PD`.
    fn label(&self) -> &str;

    /// Names of the law's continuous states (their number is the state's dimension).
    fn state_names(&self) -> &'static [&'static str];

    /// The state for a start in trim; the default is all zeros.
    fn initial_state(&self, _inputs: &PitchLawInputs, state: &mut [f64]) {
        state.fill(0.0);
    }

    /// The elevator command δe (rad), not limited: the actuator applies its limits.
    fn elevator_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64;

    /// The time derivative of the state, written into `rate`.
    fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]);

    /// The law's estimate of the pitch disturbance d_θ (rad/s²), if it has one.
    fn disturbance_estimate_radps2(&self, _state: &[f64]) -> Option<f64> {
        None
    }
}

/// What a pitch law is designed from: the plant at trim, the hardware and the sensor.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchDesignContext {
    /// The pitch-plant derivatives at the trim point.
    pub plant: PitchPlantDerivatives,
    /// The elevator actuator the law drives.
    pub actuator: ElevatorActuatorParameters,
    /// The pitch-attitude sensor's noise.
    pub pitch_noise: PitchNoiseParameters,
    /// The integration step of the simulation (s).
    pub time_step_s: f64,
}

/// The parameters of a registered pitch law: how they are checked and how the law is
/// built from them. Implemented once per law, beside the law.
pub trait PitchLawDesign {
    /// The law these parameters build.
    type Law: PitchLaw + Clone;

    /// Short label for tables and plots, e.g. `O-PD`.
    const LABEL: &'static str;

    /// Checks every parameter; `section` is the dotted path of the pitch section.
    fn validate(&self, section: &str) -> Result<(), ParameterError>;

    /// Builds the law for a plant and its hardware.
    fn build(&self, context: &PitchDesignContext) -> Result<Self::Law, ParameterError>;

    /// The law in its linear limit on the reduced pitch loop, with the parameter that sets
    /// its speed, for the check that the stabilator's rate limit can follow it
    /// ([`super::design::check_pitch_tuning`]); `None` (the default): not checked.
    fn linear_law(&self, _plant: PitchPlantDerivatives) -> Option<super::design::LinearisedLaw> {
        None
    }
}

/// Lists the registered pitch laws: one line each, `Variant("type name", Parameters)`,
/// where `Parameters: PitchLawDesign`. Generates the scenario's tagged
/// [`super::PitchControllerParameters`] (`type = "type name"`) and [`super::BuiltPitchLaw`],
/// which dispatches to the registered laws without dynamic calls and holds a user's own
/// law as a trait object.
macro_rules! pitch_laws {
    ($( $(#[$doc:meta])* $variant:ident($name:literal, $module:ident :: $parameters:ident) ),+ $(,)?) => {
        $( pub mod $module; )+

        /// Choice and tuning of the pitch law, as written in a scenario (`type` names it).
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(tag = "type", deny_unknown_fields)]
        pub enum PitchControllerParameters {
            $( $(#[$doc])* #[serde(rename = $name)] $variant($module::$parameters), )+
        }

        impl PitchControllerParameters {
            /// The `type` names of the registered laws, as written in a scenario.
            pub const TYPE_NAMES: &'static [&'static str] = &[$($name),+];

            /// Short label for tables and plots, e.g. `O-PD`.
            pub fn label(&self) -> &'static str {
                match self {
                    $( Self::$variant(_) => <$module::$parameters as $crate::control::pitch::PitchLawDesign>::LABEL, )+
                }
            }

            /// Checks every parameter of the chosen law (section `control.pitch`).
            pub fn validate(&self) -> Result<(), $crate::parameters::ParameterError> {
                match self {
                    $( Self::$variant(p) => $crate::control::pitch::PitchLawDesign::validate(p, Self::SECTION), )+
                }
            }

            /// The chosen law in its linear limit, for the rate-limit check (`None`: a law
            /// that is not checked).
            pub fn linear_law(
                &self,
                plant: $crate::control::pitch::PitchPlantDerivatives,
            ) -> Option<$crate::control::pitch::design::LinearisedLaw> {
                match self {
                    $( Self::$variant(p) => $crate::control::pitch::PitchLawDesign::linear_law(p, plant), )+
                }
            }

            /// Builds the chosen law for a plant and its hardware.
            pub fn build(
                &self,
                context: &$crate::control::pitch::PitchDesignContext,
            ) -> Result<BuiltPitchLaw, $crate::parameters::ParameterError> {
                Ok(match self {
                    $( Self::$variant(p) => BuiltPitchLaw::$variant(
                        $crate::control::pitch::PitchLawDesign::build(p, context)?,
                    ), )+
                })
            }
        }

        /// A built pitch law: a registered one (called without dynamic dispatch) or a
        /// user's own.
        #[derive(Debug, Clone)]
        pub enum BuiltPitchLaw {
            $( $(#[$doc])* $variant(<$module::$parameters as $crate::control::pitch::PitchLawDesign>::Law), )+
            /// A user's own law.
            Custom(std::sync::Arc<dyn PitchLaw>),
        }

        impl PitchLaw for BuiltPitchLaw {
            fn label(&self) -> &str {
                match self {
                    $( Self::$variant(law) => PitchLaw::label(law), )+
                    Self::Custom(law) => law.label(),
                }
            }

            fn state_names(&self) -> &'static [&'static str] {
                match self {
                    $( Self::$variant(law) => PitchLaw::state_names(law), )+
                    Self::Custom(law) => law.state_names(),
                }
            }

            fn initial_state(&self, inputs: &PitchLawInputs, state: &mut [f64]) {
                match self {
                    $( Self::$variant(law) => PitchLaw::initial_state(law, inputs, state), )+
                    Self::Custom(law) => law.initial_state(inputs, state),
                }
            }

            #[inline]
            fn elevator_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
                match self {
                    $( Self::$variant(law) => PitchLaw::elevator_command_rad(law, state, inputs), )+
                    Self::Custom(law) => law.elevator_command_rad(state, inputs),
                }
            }

            #[inline]
            fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
                match self {
                    $( Self::$variant(law) => PitchLaw::derivative(law, state, inputs, rate), )+
                    Self::Custom(law) => law.derivative(state, inputs, rate),
                }
            }

            #[inline]
            fn disturbance_estimate_radps2(&self, state: &[f64]) -> Option<f64> {
                match self {
                    $( Self::$variant(law) => PitchLaw::disturbance_estimate_radps2(law, state), )+
                    Self::Custom(law) => law.disturbance_estimate_radps2(state),
                }
            }
        }
    };
}

pub(crate) use pitch_laws;

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

    #[test]
    fn saturation_is_classified_against_the_limits() {
        let (lower, upper) = (-0.436, 0.175);
        let classify = |p| ElevatorSaturation::from_position(p, lower, upper, 1e-6);
        assert_eq!(classify(0.0), ElevatorSaturation::NotSaturated);
        assert_eq!(classify(lower), ElevatorSaturation::AtLowerLimit);
        assert_eq!(classify(upper + 1.0), ElevatorSaturation::AtUpperLimit);
    }
}
