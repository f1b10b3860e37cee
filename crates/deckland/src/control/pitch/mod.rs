//! Pitch-attitude controllers: θ_ref → elevator command (MODEL.md §5; paper §4.2).
//!
//! Two interchangeable controllers behind one interface, [`PitchController`]:
//! the observer-based PD ([`ObserverPdController`], paper Eq. 30–36) and the PID it is
//! compared with ([`PidController`], paper Eq. 37). Both are plant-independent: they
//! take the pitch-plant derivatives from the linearisation at trim
//! ([`PitchPlantDerivatives`]) and the signals of one instant ([`PitchControlInputs`]).
//!
//! Each controller has a three-element continuous state ([`PitchControllerState`]) that
//! the simulation integrates with the plant: call [`PitchController::derivative`] in every
//! RK4 stage and [`PitchController::elevator_command_rad`] for the actuator command.
//! Everything here is pure and allocation-free.

mod inputs;
mod observer_pd;
mod pid;

use serde::{Deserialize, Serialize};

pub use inputs::{ControlError, ElevatorSaturation, PitchControlInputs, PitchPlantDerivatives};
pub use observer_pd::{ObserverPdController, ObserverPdGains, ObserverPdParameters, PitchFeedback};
pub use pid::{PidController, PidParameters, PidState};

use crate::estimation::ObserverState;

/// Choice and tuning of the pitch controller, as written in a scenario (MODEL.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(tag = "type", rename_all = "snake_case", deny_unknown_fields)]
pub enum PitchControllerParameters {
    /// Observer-based PD (paper Eq. 30–36).
    ObserverPd(ObserverPdParameters),
    /// PID for comparison (paper Eq. 37).
    Pid(PidParameters),
}

impl Default for PitchControllerParameters {
    /// The paper's proposed controller, O-PD, with its default design.
    fn default() -> Self {
        Self::ObserverPd(ObserverPdParameters::default())
    }
}

/// Either pitch controller (MODEL.md §5), so the landing cascade can take both.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PitchController {
    /// Observer-based PD (paper Eq. 30–36).
    ObserverPd(ObserverPdController),
    /// PID for comparison (paper Eq. 37).
    Pid(PidController),
}

/// Continuous state of a pitch controller; three numbers for the integrator.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum PitchControllerState {
    /// O-PD: observer estimates x1 = Δθ (rad), x2 = Δq (rad/s), x3 = d_θ (rad/s²).
    ObserverPd(ObserverState),
    /// PID: integral of the pitch error (rad·s).
    Pid(PidState),
}

impl PitchControllerState {
    /// The state as an array: O-PD `[x1, x2, x3]`; PID `[∫e_θ dt, 0, 0]`.
    #[inline]
    pub fn to_array(&self) -> [f64; 3] {
        match self {
            Self::ObserverPd(observer) => observer.to_array(),
            Self::Pid(pid) => [pid.pitch_error_integral_rad_s, 0.0, 0.0],
        }
    }

    /// The observer's disturbance estimate d̂_θ = x3 (rad/s²); `None` for the PID.
    pub fn disturbance_estimate_radps2(&self) -> Option<f64> {
        match self {
            Self::ObserverPd(observer) => Some(observer.x3),
            Self::Pid(_) => None,
        }
    }

    /// The observer's pitch-rate estimate Δq̂ = x2 (rad/s); `None` for the PID.
    pub fn pitch_rate_estimate_radps(&self) -> Option<f64> {
        match self {
            Self::ObserverPd(observer) => Some(observer.x2),
            Self::Pid(_) => None,
        }
    }

    /// The observer's pitch-deviation estimate Δθ̂ = x1 (rad); `None` for the PID.
    pub fn pitch_deviation_estimate_rad(&self) -> Option<f64> {
        match self {
            Self::ObserverPd(observer) => Some(observer.x1),
            Self::Pid(_) => None,
        }
    }

    /// The PID's pitch-error integral (rad·s); `None` for the O-PD.
    pub fn pitch_error_integral_rad_s(&self) -> Option<f64> {
        match self {
            Self::ObserverPd(_) => None,
            Self::Pid(pid) => Some(pid.pitch_error_integral_rad_s),
        }
    }
}

impl PitchController {
    /// Builds the controller chosen in `parameters` for the given plant derivatives.
    pub fn new(
        parameters: &PitchControllerParameters,
        plant: PitchPlantDerivatives,
    ) -> Result<Self, ControlError> {
        Ok(match parameters {
            PitchControllerParameters::ObserverPd(p) => {
                Self::ObserverPd(ObserverPdController::new(p, plant)?)
            }
            PitchControllerParameters::Pid(p) => Self::Pid(PidController::new(p, plant)?),
        })
    }

    /// Short name for tables and plots: "O-PD" or "PID".
    pub fn name(&self) -> &'static str {
        match self {
            Self::ObserverPd(_) => "O-PD",
            Self::Pid(_) => "PID",
        }
    }

    /// State for a start at trim: O-PD observer x1 = θ_m − θ* (rad), x2 = x3 = 0;
    /// PID integrator 0.
    pub fn initial_state(
        &self,
        theta_measured_rad: f64,
        theta_trim_rad: f64,
    ) -> PitchControllerState {
        match self {
            Self::ObserverPd(c) => PitchControllerState::ObserverPd(
                c.initial_state(theta_measured_rad, theta_trim_rad),
            ),
            Self::Pid(c) => PitchControllerState::Pid(c.initial_state()),
        }
    }

    /// Reads a state of this controller's kind from the integrator's array (inverse of
    /// [`PitchControllerState::to_array`]).
    #[inline]
    pub fn state_from_array(&self, x: &[f64; 3]) -> PitchControllerState {
        match self {
            Self::ObserverPd(_) => PitchControllerState::ObserverPd(ObserverState::from_array(x)),
            Self::Pid(_) => PitchControllerState::Pid(PidState {
                pitch_error_integral_rad_s: x[0],
            }),
        }
    }

    /// Elevator command (rad), not limited (paper Eq. 35–37). A state of the other
    /// controller's kind is read through its array layout.
    #[inline]
    pub fn elevator_command_rad(
        &self,
        state: &PitchControllerState,
        inputs: &PitchControlInputs,
    ) -> f64 {
        match self {
            Self::ObserverPd(c) => c.elevator_command_rad(&observer_state_of(state), inputs),
            Self::Pid(c) => c.elevator_command_rad(&pid_state_of(state), inputs),
        }
    }

    /// Time derivative of the controller state (O-PD: MODEL.md §4; PID: e_θ or 0 under
    /// anti-windup). A state of the other controller's kind is read through its array
    /// layout.
    #[inline]
    pub fn derivative(
        &self,
        state: &PitchControllerState,
        inputs: &PitchControlInputs,
    ) -> PitchControllerState {
        match self {
            Self::ObserverPd(c) => {
                PitchControllerState::ObserverPd(c.derivative(&observer_state_of(state), inputs))
            }
            Self::Pid(c) => PitchControllerState::Pid(c.derivative(&pid_state_of(state), inputs)),
        }
    }

    /// [`PitchController::derivative`] on the integrator's array representation.
    #[inline]
    pub fn derivative_array(&self, x: &[f64; 3], inputs: &PitchControlInputs) -> [f64; 3] {
        self.derivative(&self.state_from_array(x), inputs)
            .to_array()
    }
}

/// The observer state held in `state`, or its array read as one.
#[inline]
fn observer_state_of(state: &PitchControllerState) -> ObserverState {
    match state {
        PitchControllerState::ObserverPd(observer) => *observer,
        PitchControllerState::Pid(_) => ObserverState::from_array(&state.to_array()),
    }
}

/// The PID state held in `state`, or the first element of its array read as one.
#[inline]
fn pid_state_of(state: &PitchControllerState) -> PidState {
    match state {
        PitchControllerState::Pid(pid) => *pid,
        PitchControllerState::ObserverPd(observer) => PidState {
            pitch_error_integral_rad_s: observer.x1,
        },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLANT: PitchPlantDerivatives = PitchPlantDerivatives {
        dqdot_dq_per_s: -0.15,
        dqdot_delevator_per_s2: -1.93,
    };

    #[test]
    fn state_round_trips_through_the_array_for_both_kinds() {
        for parameters in [
            PitchControllerParameters::default(),
            PitchControllerParameters::Pid(PidParameters::default()),
        ] {
            let controller = PitchController::new(&parameters, PLANT).expect("valid");
            let array = [0.1, -0.2, 0.3];
            let state = controller.state_from_array(&array);
            let back = state.to_array();
            match controller {
                PitchController::ObserverPd(_) => assert_eq!(back, array),
                PitchController::Pid(_) => assert_eq!(back, [0.1, 0.0, 0.0]),
            }
        }
    }

    #[test]
    fn accessors_report_what_each_kind_has() {
        let opd = PitchController::new(&PitchControllerParameters::default(), PLANT).expect("ok");
        let state = opd.state_from_array(&[0.1, 0.2, 0.3]);
        assert_eq!(state.disturbance_estimate_radps2(), Some(0.3));
        assert_eq!(state.pitch_rate_estimate_radps(), Some(0.2));
        assert_eq!(state.pitch_deviation_estimate_rad(), Some(0.1));
        assert_eq!(state.pitch_error_integral_rad_s(), None);
        assert_eq!(opd.name(), "O-PD");
    }

    #[test]
    fn mismatched_state_is_read_through_its_array() {
        let pid = PitchController::new(
            &PitchControllerParameters::Pid(PidParameters::default()),
            PLANT,
        )
        .expect("ok");
        let foreign = PitchControllerState::ObserverPd(ObserverState {
            x1: 0.5,
            x2: 0.0,
            x3: 0.0,
        });
        let inputs = PitchControlInputs::default();
        let expected = pid.elevator_command_rad(&pid.state_from_array(&[0.5, 0.0, 0.0]), &inputs);
        assert_eq!(pid.elevator_command_rad(&foreign, &inputs), expected);
        assert!(expected.is_finite());
    }

    #[test]
    fn parameters_deserialise_from_a_tagged_table() {
        let parameters: PitchControllerParameters =
            serde_json::from_str(r#"{"type": "pid", "anti_windup": false}"#).expect("valid");
        let PitchControllerParameters::Pid(pid) = parameters else {
            panic!("expected PID, got {parameters:?}");
        };
        assert!(!pid.anti_windup);
        assert_eq!(pid.proportional_per_s2, 57.01);
    }
}
