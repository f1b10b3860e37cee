//! The pitch axis's part of the law interface: what a pitch law reads
//! ([`PitchLawInputs`]), what it is designed from ([`PitchDesignContext`]), how its
//! scenario parameters build it ([`PitchLawDesign`]), and how the registered laws are
//! listed (docs/model.md §4–5; paper Eq. 26–37). The axis-generic part is
//! [`crate::control::AxisLaw`].

use serde::{Deserialize, Serialize};

use super::design::{LinearisedLaw, PitchPlantDerivatives};
use crate::aircraft::ElevatorActuatorParameters;
use crate::control::AxisLaw;
use crate::parameters::ParameterError;
use crate::sensors::PitchNoiseParameters;

/// Where the pitch law sits in a scenario file.
pub const SECTION: &str = "control.pitch";

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

/// A pitch-attitude control law: an [`AxisLaw`] that reads [`PitchLawInputs`] and
/// commands the elevator (θ_ref → δe). Every such law is one, without a line of its own:
/// implement [`AxisLaw`] with `type Inputs = PitchLawInputs`. `dyn PitchLaw` holds a
/// user's own law ([`super::BuiltPitchLaw::Custom`]).
pub trait PitchLaw: AxisLaw<Inputs = PitchLawInputs> {}

impl<T: AxisLaw<Inputs = PitchLawInputs> + ?Sized> PitchLaw for T {}

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
/// built from them. Implemented once per law, beside the law; [`Default`] is the law's
/// tuning for the realistic hardware set.
pub trait PitchLawDesign: Default {
    /// The law these parameters build.
    type Law: PitchLaw + Clone;

    /// Short label for tables and plots, e.g. `O-PD`.
    const LABEL: &'static str;

    /// Checks every parameter; `section` is the dotted path of the pitch section.
    fn validate(&self, section: &str) -> Result<(), ParameterError>;

    /// Builds the law for a plant and its hardware.
    fn build(&self, context: &PitchDesignContext) -> Result<Self::Law, ParameterError>;

    /// The law's tuning for the paper's hardware set; the default: [`Default`].
    fn paper_tuning() -> Self {
        Self::default()
    }

    /// The law in its linear limit on the reduced pitch loop, with the parameter that sets
    /// its speed, for the check that the stabilator's rate limit can follow it
    /// ([`super::design::check_pitch_tuning`]); `None` (the default): not checked.
    fn linear_law(&self, _plant: PitchPlantDerivatives) -> Option<LinearisedLaw> {
        None
    }
}

/// Which tuning of a law a hardware set flies.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LawTuning {
    /// The realistic hardware set's: the parameters' [`Default`].
    Realistic,
    /// The paper's hardware set's: [`PitchLawDesign::paper_tuning`].
    Paper,
}

/// Lists the registered pitch laws: one line each, `Variant("type name", module::Parameters)`,
/// where `Parameters: PitchLawDesign`, optionally behind one `#[cfg(...)]`. Declares each
/// law's module (its file beside the registry) and generates the scenario's tagged
/// [`super::PitchControllerParameters`] (`type = "type name"`) and
/// [`super::BuiltPitchLaw`], which dispatches to the registered laws without dynamic calls
/// and holds a user's own law as a trait object. These are the only `match`es over the
/// registered laws: code elsewhere names a law by its type name.
macro_rules! pitch_laws {
    ($( $(#[doc = $doc:literal])* $(#[cfg($cfg:meta)])? $variant:ident($name:literal, $module:ident :: $parameters:ident) ),+ $(,)?) => {
        $( $(#[cfg($cfg)])? pub mod $module; )+

        /// Choice and tuning of the pitch law, as written in a scenario (`type` names it).
        #[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
        #[serde(tag = "type", deny_unknown_fields)]
        pub enum PitchControllerParameters {
            $( $(#[doc = $doc])* $(#[cfg($cfg)])? #[serde(rename = $name)] $variant($module::$parameters), )+
        }

        impl PitchControllerParameters {
            /// The `type` names of the registered laws, as written in a scenario.
            pub const TYPE_NAMES: &'static [&'static str] = &[$( $(#[cfg($cfg)])? $name ),+];

            /// The `type` name of the chosen law, as written in a scenario.
            pub fn type_name(&self) -> &'static str {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(_) => $name, )+
                }
            }

            /// The registered law named `type_name` with the given tuning; `None` when no
            /// law of that name is registered.
            pub fn registered(type_name: &str, tuning: $crate::control::pitch::LawTuning) -> Option<Self> {
                $(
                    $(#[cfg($cfg)])?
                    if type_name == $name {
                        return Some(Self::$variant(match tuning {
                            $crate::control::pitch::LawTuning::Realistic => Default::default(),
                            $crate::control::pitch::LawTuning::Paper => {
                                <$module::$parameters as $crate::control::pitch::PitchLawDesign>::paper_tuning()
                            }
                        }));
                    }
                )+
                None
            }

            /// The same law with the given tuning.
            pub fn retuned(&self, tuning: $crate::control::pitch::LawTuning) -> Self {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(_) => Self::$variant(match tuning {
                        $crate::control::pitch::LawTuning::Realistic => Default::default(),
                        $crate::control::pitch::LawTuning::Paper => {
                            <$module::$parameters as $crate::control::pitch::PitchLawDesign>::paper_tuning()
                        }
                    }), )+
                }
            }

            /// Short label for tables and plots, e.g. `O-PD`.
            pub fn label(&self) -> &'static str {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(_) => <$module::$parameters as $crate::control::pitch::PitchLawDesign>::LABEL, )+
                }
            }

            /// Checks every parameter of the chosen law (section `control.pitch`).
            pub fn validate(&self) -> Result<(), $crate::parameters::ParameterError> {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(p) => $crate::control::pitch::PitchLawDesign::validate(p, Self::SECTION), )+
                }
            }

            /// The chosen law in its linear limit, for the rate-limit check (`None`: a law
            /// that is not checked).
            pub fn linear_law(
                &self,
                plant: $crate::control::pitch::PitchPlantDerivatives,
            ) -> Option<$crate::control::pitch::design::LinearisedLaw> {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(p) => $crate::control::pitch::PitchLawDesign::linear_law(p, plant), )+
                }
            }

            /// Builds the chosen law for a plant and its hardware.
            pub fn build(
                &self,
                context: &$crate::control::pitch::PitchDesignContext,
            ) -> Result<BuiltPitchLaw, $crate::parameters::ParameterError> {
                Ok(match self {
                    $( $(#[cfg($cfg)])? Self::$variant(p) => BuiltPitchLaw::$variant(
                        $crate::control::pitch::PitchLawDesign::build(p, context)?,
                    ), )+
                })
            }
        }

        /// A built pitch law: a registered one (called without dynamic dispatch) or a
        /// user's own.
        #[derive(Debug, Clone)]
        pub enum BuiltPitchLaw {
            $( $(#[doc = $doc])* $(#[cfg($cfg)])? $variant(<$module::$parameters as $crate::control::pitch::PitchLawDesign>::Law), )+
            /// A user's own law.
            Custom(std::sync::Arc<dyn PitchLaw>),
        }

        impl $crate::control::AxisLaw for BuiltPitchLaw {
            type Inputs = PitchLawInputs;

            fn label(&self) -> &str {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::label(law), )+
                    Self::Custom(law) => law.label(),
                }
            }

            fn state_names(&self) -> &'static [&'static str] {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::state_names(law), )+
                    Self::Custom(law) => law.state_names(),
                }
            }

            fn initial_state(&self, inputs: &PitchLawInputs, state: &mut [f64]) {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::initial_state(law, inputs, state), )+
                    Self::Custom(law) => law.initial_state(inputs, state),
                }
            }

            #[inline]
            fn surface_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::surface_command_rad(law, state, inputs), )+
                    Self::Custom(law) => law.surface_command_rad(state, inputs),
                }
            }

            #[inline]
            fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::derivative(law, state, inputs, rate), )+
                    Self::Custom(law) => law.derivative(state, inputs, rate),
                }
            }

            #[inline]
            fn disturbance_estimate_radps2(&self, state: &[f64]) -> Option<f64> {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::disturbance_estimate_radps2(law, state), )+
                    Self::Custom(law) => law.disturbance_estimate_radps2(state),
                }
            }

            fn linear_law(&self) -> Option<$crate::control::LinearLaw> {
                match self {
                    $( $(#[cfg($cfg)])? Self::$variant(law) => $crate::control::AxisLaw::linear_law(law), )+
                    Self::Custom(law) => law.linear_law(),
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
    fn saturation_is_classified_against_the_limits() {
        let (lower, upper) = (-0.436, 0.175);
        let classify = |p| ElevatorSaturation::from_position(p, lower, upper, 1e-6);
        assert_eq!(classify(0.0), ElevatorSaturation::NotSaturated);
        assert_eq!(classify(lower), ElevatorSaturation::AtLowerLimit);
        assert_eq!(classify(upper + 1.0), ElevatorSaturation::AtUpperLimit);
    }
}
