//! Observer-based PD pitch controller, "O-PD" (paper Eq. 30–36, corrected in docs/model.md §5).
//!
//! The augmented observer (docs/model.md §4) estimates the pitch-attitude deviation, the pitch
//! rate and the lumped disturbance d_θ of the pitch dynamics θ̈ = (∂q̇/∂q)·Δq +
//! (∂q̇/∂δe)·Δδe + d_θ. The equivalent control U = K_P·e_θ + K_D·ė_θ, with
//! e_θ = θ_ref − θ and ė_θ = −x2, is turned into an elevator deflection that also
//! cancels the estimated disturbance: Δδe = (U − x3)/(∂q̇/∂δe) (Eq. 35), δe = δe* + Δδe
//! (Eq. 36). The error then obeys ë + (K_D − ∂q̇/∂q)·ė + K_P·e = 0 (from Eq. 29).
//!
//! No anti-windup is needed: the observer's known input uses the actuator's *actual*
//! position, so a saturated elevator shows up as a correctly estimated plant, not as a
//! growing disturbance estimate.

use serde::{Deserialize, Serialize};

use crate::control::design::{LinearisedLaw, AxisPlantDerivatives};
use super::law::{PitchDesignContext, PitchLawDesign, PitchLawInputs, SECTION};
use crate::control::{AxisLaw, LinearLaw};
use crate::estimation::{AugmentedObserver, FractionalPower, ObserverParameters, ObserverState};
use crate::parameters::{Bounds, ParameterError, check_ranges};

mod design;
mod tabulated;

pub use design::{
    assess_feedback, design_observer_pd, linear_observer_pd, FeedbackAssessment, PitchDesign,
};

/// Which pitch attitude the O-PD proportional term compares with θ_ref.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PitchFeedback {
    /// The measured attitude θ_m, as in the paper's Eq. 30 (noise passes to the elevator
    /// through K_P).
    #[default]
    Measured,
    /// The observer's estimate θ* + x1 (filters measurement noise; usual in
    /// active-disturbance-rejection control). A project choice, not in the paper.
    ObserverEstimate,
}

/// What a user chooses for the O-PD pitch loop (docs/model.md §5): the closed-loop error
/// dynamics s² + 2ζω_n·s + ω_n² with ω_n = 4/(T_2%·ζ), plus the observer tuning.
///
/// With the default ζ = √2 the error dynamics are overdamped (poles −3.9 and −22.8 rad/s),
/// so the 2 % settling time is governed by the slow pole and is about 1.05 s, not T_2%:
/// the formula ω_n = 4/(T_2%·ζ) (paper Eq. 34) is the underdamped envelope rule. The
/// paper reports 1.11 s (Fig. 10).
///
/// The rule ignores the elevator actuator. Behind the paper's actuator (30.74 rad/s,
/// ζ = 0.509) the default gains (K_D = 26.5 /s) leave a closed-loop mode near
/// −0.43 ± 28.7i rad/s (damping ≈ 0.015), so small steps ring for seconds; T_2% = 0.5 s
/// with ζ = 1 (K_P = 64, K_D = 15.85) damps it to ≈ 0.19 and settles in ≈ 0.75 s
/// (tests/pitch_closed_loop.rs). The defaults stay the paper's.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ObserverPdParameters {
    /// Design settling time T_2% (s) in ω_n = 4/(T_2%·ζ) (paper Eq. 34; the paper flies 0.3 s, the realistic set 1.6 s).
    pub settling_time_s: f64,
    /// Damping ratio ζ of the error dynamics (dimensionless; paper: √2).
    pub damping_ratio: f64,
    /// Pitch attitude used in the proportional term (default: measured, as the paper).
    pub pitch_feedback: PitchFeedback,
    /// Tuning of the augmented observer (docs/model.md §4).
    pub observer: ObserverParameters,
}

impl Default for ObserverPdParameters {
    /// The design for the realistic stabilator (40 °/s; docs/pitch-step.md): T_2% = 1.6 s,
    /// ζ = 1, the observer's attitude fed back, observer ε = 0.2
    /// ([`design_observer_pd`] finds it admissible).
    fn default() -> Self {
        Self {
            settling_time_s: 1.6,
            damping_ratio: 1.0,
            pitch_feedback: PitchFeedback::ObserverEstimate,
            observer: ObserverParameters {
                epsilon: 0.2,
                ..ObserverParameters::default()
            },
        }
    }
}

impl ObserverPdParameters {
    /// The paper's design (§4.2.2): T_2% = 0.3 s, ζ = √2, the measured attitude fed back,
    /// observer ε = 0.03 (docs/observer-bandwidth.md).
    pub fn paper() -> Self {
        Self {
            settling_time_s: 0.3,
            damping_ratio: std::f64::consts::SQRT_2,
            pitch_feedback: PitchFeedback::Measured,
            observer: ObserverParameters::default(),
        }
    }
}

impl ObserverPdParameters {
    /// Checks the design parameters (T_2% in [0.05, 30] s, ζ in [0.1, 5]) and the
    /// observer, naming `section.key`.
    pub fn validate(&self, section: &str) -> Result<(), ParameterError> {
        check_ranges!(section, self, {
            settling_time_s: Bounds::closed(0.05, 30.0),
            damping_ratio: Bounds::closed(0.1, 5.0),
        });
        self.observer
            .validate_in(&crate::parameters::join(section, "observer"))
    }
}

impl PitchLawDesign for ObserverPdParameters {
    type Law = ObserverPdController;
    const LABEL: &'static str = "O-PD";

    fn validate(&self, section: &str) -> Result<(), ParameterError> {
        ObserverPdParameters::validate(self, section)
    }

    fn build(&self, context: &PitchDesignContext) -> Result<ObserverPdController, ParameterError> {
        ObserverPdController::new(self, context.plant)
    }

    fn paper_tuning() -> Self {
        ObserverPdParameters::paper()
    }

    fn linear_law(&self, plant: AxisPlantDerivatives) -> Option<LinearisedLaw> {
        let gains =
            ObserverPdGains::design(self.settling_time_s, self.damping_ratio, plant.rate_damping_per_s)
                .ok()?;
        Some(LinearisedLaw {
            law: linear_observer_pd(&gains, &self.observer, self.pitch_feedback, plant),
            speed_key: "settling_time_s",
            speed_value: self.settling_time_s,
            speed_advice: "a longer settling_time_s",
        })
    }
}

/// O-PD equivalent-control gains (paper Eq. 30; K_P in 1/s², K_D in 1/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ObserverPdGains {
    /// Proportional gain K_P = ω_n² (1/s²).
    pub proportional_per_s2: f64,
    /// Derivative gain K_D = 2ζω_n + ∂q̇/∂q (1/s).
    pub derivative_per_s: f64,
}

impl ObserverPdGains {
    /// Design rule of docs/model.md §5 (paper Eq. 31–34 corrected): ω_n = 4/(T_2%·ζ),
    /// K_P = ω_n², K_D = 2ζω_n + ∂q̇/∂q. With T_2% = 0.3 s, ζ = √2, ∂q̇/∂q = −0.15 /s
    /// this gives K_P = 88.89 /s², K_D = 26.52 /s (the paper's values).
    pub fn design(
        settling_time_s: f64,
        damping_ratio: f64,
        rate_damping_per_s: f64,
    ) -> Result<Self, ParameterError> {
        let natural_frequency_radps = 4.0 / (settling_time_s * damping_ratio);
        let gains = Self {
            proportional_per_s2: natural_frequency_radps * natural_frequency_radps,
            derivative_per_s: 2.0 * damping_ratio * natural_frequency_radps + rate_damping_per_s,
        };
        gains.validate()?;
        Ok(gains)
    }

    /// Checks that both gains are finite.
    pub fn validate(&self) -> Result<(), ParameterError> {
        for (key, value) in [
            ("proportional_per_s2", self.proportional_per_s2),
            ("derivative_per_s", self.derivative_per_s),
        ] {
            if !value.is_finite() {
                return Err(ParameterError::new(
                    "O-PD gains",
                    key,
                    value,
                    "a finite gain",
                ));
            }
        }
        Ok(())
    }
}

/// The O-PD pitch controller (paper Eq. 30, 35, 36; docs/model.md §4–5). Its state is the
/// observer's [`ObserverState`] (Δθ in rad, Δq in rad/s, d_θ in rad/s²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ObserverPdController {
    gains: ObserverPdGains,
    plant: AxisPlantDerivatives,
    observer: AugmentedObserver,
    pitch_feedback: PitchFeedback,
    /// The observer's fractional power by tables ([`ObserverPdController::with_tabulated_power`]);
    /// `None`: the library's `pow`.
    power: Option<FractionalPower>,
}

impl ObserverPdController {
    /// Designs the gains from `parameters` (settling time, damping) and the plant
    /// derivatives, and builds the observer.
    pub fn new(
        parameters: &ObserverPdParameters,
        plant: AxisPlantDerivatives,
    ) -> Result<Self, ParameterError> {
        parameters.validate(SECTION)?;
        plant.validate()?;
        let gains = ObserverPdGains::design(
            parameters.settling_time_s,
            parameters.damping_ratio,
            plant.rate_damping_per_s,
        )?;
        Self::with_gains(gains, parameters.observer, parameters.pitch_feedback, plant)
    }

    /// Builds the controller from explicit gains instead of the design rule.
    pub fn with_gains(
        gains: ObserverPdGains,
        observer: ObserverParameters,
        pitch_feedback: PitchFeedback,
        plant: AxisPlantDerivatives,
    ) -> Result<Self, ParameterError> {
        plant.validate()?;
        gains.validate()?;
        Ok(Self {
            gains,
            plant,
            observer: AugmentedObserver::new(observer)?,
            pitch_feedback,
            power: None,
        })
    }

    /// The gains in use.
    pub fn gains(&self) -> &ObserverPdGains {
        &self.gains
    }

    /// The plant derivatives the controller was built for.
    pub fn plant(&self) -> &AxisPlantDerivatives {
        &self.plant
    }

    /// The augmented observer inside the controller.
    pub fn observer(&self) -> &AugmentedObserver {
        &self.observer
    }

    /// Observer state for a start at trim: x1 = θ_m − θ* (rad), x2 = 0, x3 = 0.
    pub fn initial_state(&self, theta_measured_rad: f64, theta_trim_rad: f64) -> ObserverState {
        ObserverState {
            x1: theta_measured_rad - theta_trim_rad,
            x2: 0.0,
            x3: 0.0,
        }
    }

    /// Elevator command δe = δe* + (U − x3)/(∂q̇/∂δe) (rad; paper Eq. 35–36) with
    /// U = K_P·(θ_ref − θ) + K_D·(q_r − x2) + q̇_r − M_q·q_r, the paper's law about a moving
    /// reference (q_r = q̇_r = 0 for a plain command: the paper's U); not limited: the
    /// actuator applies its position limits (docs/model.md §2.6).
    #[inline]
    pub fn elevator_command_rad(&self, state: &ObserverState, inputs: &PitchLawInputs) -> f64 {
        let theta_rad = match self.pitch_feedback {
            PitchFeedback::Measured => inputs.theta_measured_rad,
            PitchFeedback::ObserverEstimate => inputs.theta_trim_rad + state.x1,
        };
        let pitch_error_rad = inputs.theta_ref_rad - theta_rad;
        let pitch_error_rate_radps = inputs.theta_ref_rate_radps - state.x2;
        // Feed-forward of a shaped reference: q̇_r − M_q·q_r (zero for a plain command).
        let feed_forward = inputs.theta_ref_acceleration_radps2
            - self.plant.rate_damping_per_s * inputs.theta_ref_rate_radps;
        let equivalent_control = self.gains.proportional_per_s2 * pitch_error_rad
            + self.gains.derivative_per_s * pitch_error_rate_radps
            + feed_forward;
        inputs.elevator_trim_rad
            + (equivalent_control - state.x3) / self.plant.control_power_per_s2
    }

    /// Observer derivative (docs/model.md §4) with y = θ_m − θ* and
    /// h_θ = (∂q̇/∂q)·x2 + (∂q̇/∂δe)·(δe_actual − δe*); a sampled reading's age τ is
    /// compensated to first order (the innovation compares x1 − τ·x2 with y).
    #[inline]
    pub fn derivative(&self, state: &ObserverState, inputs: &PitchLawInputs) -> ObserverState {
        let exponent = self.observer.power_exponent();
        self.derivative_with_power(state, inputs, |magnitude| magnitude.powf(exponent))
    }

    /// [`ObserverPdController::derivative`] with the observer's fractional power evaluated
    /// by `power` ([`AugmentedObserver::derivative_with_power`]); the same operations
    /// otherwise.
    #[inline(always)]
    pub fn derivative_with_power(
        &self,
        state: &ObserverState,
        inputs: &PitchLawInputs,
        power: impl FnOnce(f64) -> f64,
    ) -> ObserverState {
        // A reading `age` seconds old is compared with the estimate brought back to its
        // time, x1 − age·x2: the same as the measurement brought forward by age·x2.
        let measurement = inputs.theta_measured_rad - inputs.theta_trim_rad
            + inputs.measurement_age_s * state.x2;
        let known_input = self.plant.rate_damping_per_s * state.x2
            + self.plant.control_power_per_s2
                * (inputs.elevator_actual_rad - inputs.elevator_trim_rad);
        self.observer
            .derivative_with_power(state, measurement, known_input, power)
    }
}

/// The observer's state names: x1 = Δθ̂ (rad), x2 = Δq̂ (rad/s), x3 = d̂_θ (rad/s²).
const STATE_NAMES: &[&str] = &[
    "pitch_deviation_estimate_rad",
    "pitch_rate_estimate_radps",
    "disturbance_estimate_radps2",
];

#[inline]
fn observer_state(state: &[f64]) -> ObserverState {
    ObserverState {
        x1: state[0],
        x2: state[1],
        x3: state[2],
    }
}

impl AxisLaw for ObserverPdController {
    type Inputs = PitchLawInputs;

    fn label(&self) -> &str {
        "O-PD"
    }

    fn state_names(&self) -> &'static [&'static str] {
        STATE_NAMES
    }

    fn initial_state(&self, inputs: &PitchLawInputs, state: &mut [f64]) {
        let initial = ObserverPdController::initial_state(
            self,
            inputs.theta_measured_rad,
            inputs.theta_trim_rad,
        );
        state.copy_from_slice(&initial.to_array());
    }

    #[inline]
    fn surface_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
        ObserverPdController::elevator_command_rad(self, &observer_state(state), inputs)
    }

    #[inline]
    fn derivative(&self, state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
        let state = observer_state(state);
        let derivative = match &self.power {
            None => ObserverPdController::derivative(self, &state, inputs),
            Some(power) => {
                self.derivative_with_power(&state, inputs, |magnitude| power.of(magnitude))
            }
        };
        rate.copy_from_slice(&derivative.to_array());
    }

    fn disturbance_estimate_radps2(&self, state: &[f64]) -> Option<f64> {
        Some(state[2])
    }

    fn linear_law(&self) -> Option<LinearLaw> {
        Some(linear_observer_pd(
            &self.gains,
            self.observer.parameters(),
            self.pitch_feedback,
            self.plant,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::control::design::PAPER_PITCH_PLANT as PAPER_PLANT;

    /// The default O-PD on the paper's pitch plant.
    pub(super) fn paper_controller() -> ObserverPdController {
        ObserverPdController::new(&ObserverPdParameters::default(), PAPER_PLANT).expect("ok")
    }

    /// Reference: paper §4.2.2 prints K_Pθ = 88.89 and K_Dθ = 26.5186 for T_2% = 0.3 s,
    /// ζ = √2, ∂q̇/∂q = −0.15 (Eq. 14). The rule gives 26.5167; the paper's last digits
    /// imply an unrounded ∂q̇/∂q ≈ −0.148, so K_D is checked to the two decimals
    /// docs/model.md §5 quotes (26.52).
    #[test]
    fn design_rule_reproduces_the_paper_gains() {
        let gains = ObserverPdGains::design(0.3, std::f64::consts::SQRT_2, -0.15).expect("valid");
        assert!(
            (gains.proportional_per_s2 - 88.89).abs() < 0.005,
            "{gains:?}"
        );
        assert!((gains.derivative_per_s - 26.52).abs() < 0.005, "{gains:?}");
    }

    #[test]
    fn invalid_design_parameters_are_named() {
        let cases = [
            (0.0, 1.0, "control.pitch.settling_time_s"),
            (0.3, -1.0, "control.pitch.damping_ratio"),
            (f64::NAN, 1.0, "control.pitch.settling_time_s"),
            (1e-300, 1.0, "control.pitch.settling_time_s"),
            (0.3, 1e308, "control.pitch.damping_ratio"),
        ];
        for (settling_time_s, damping_ratio, path) in cases {
            let parameters = ObserverPdParameters {
                settling_time_s,
                damping_ratio,
                ..ObserverPdParameters::default()
            };
            let error = ObserverPdController::new(&parameters, PAPER_PLANT).expect_err("invalid");
            assert_eq!(error.path, path, "{error}");
        }
    }

    #[test]
    fn at_trim_with_no_error_the_command_is_the_trim_elevator() {
        let controller = paper_controller();
        let inputs = PitchLawInputs {
            theta_ref_rad: 0.124,
            theta_measured_rad: 0.124,
            theta_trim_rad: 0.124,
            elevator_actual_rad: -0.143,
            elevator_trim_rad: -0.143,
            ..PitchLawInputs::default()
        };
        let state = controller.initial_state(inputs.theta_measured_rad, inputs.theta_trim_rad);
        assert_eq!(controller.elevator_command_rad(&state, &inputs), -0.143);
        assert_eq!(controller.derivative(&state, &inputs).to_array(), [0.0; 3]);
    }

    #[test]
    fn nose_up_command_and_disturbance_estimate_move_the_elevator_trailing_edge_up() {
        let controller = paper_controller();
        let inputs = PitchLawInputs {
            theta_ref_rad: 0.01,
            ..PitchLawInputs::default()
        };
        let state = ObserverState::default();
        assert!(controller.elevator_command_rad(&state, &inputs) < 0.0);
        // A nose-down disturbance estimate (x3 < 0) also needs trailing edge up.
        let disturbed = ObserverState { x3: -1.0, ..state };
        let inputs = PitchLawInputs::default();
        let command = controller.elevator_command_rad(&disturbed, &inputs);
        assert!((command - (1.0 / -1.93)).abs() < 1e-12, "{command}");
    }

    #[test]
    fn pitch_feedback_selects_measured_or_estimated_attitude() {
        let inputs = PitchLawInputs {
            theta_ref_rad: 0.2,
            theta_measured_rad: 0.15,
            theta_trim_rad: 0.1,
            ..PitchLawInputs::default()
        };
        // Estimate θ* + x1 = 0.13 differs from the measurement 0.15.
        let state = ObserverState {
            x1: 0.03,
            ..ObserverState::default()
        };
        let command = |pitch_feedback| {
            let parameters = ObserverPdParameters {
                pitch_feedback,
                ..ObserverPdParameters::default()
            };
            let controller = ObserverPdController::new(&parameters, PAPER_PLANT).expect("ok");
            let k_p = controller.gains().proportional_per_s2;
            (controller.elevator_command_rad(&state, &inputs), k_p)
        };
        let (measured, k_p) = command(PitchFeedback::Measured);
        assert!((measured - k_p * 0.05 / -1.93).abs() < 1e-12);
        let (estimated, _) = command(PitchFeedback::ObserverEstimate);
        assert!((estimated - k_p * 0.07 / -1.93).abs() < 1e-12);
    }

    #[test]
    fn zero_elevator_effectiveness_is_rejected() {
        let plant = AxisPlantDerivatives {
            control_power_per_s2: 0.0,
            ..PAPER_PLANT
        };
        let error = ObserverPdController::new(&ObserverPdParameters::default(), plant)
            .expect_err("zero effectiveness");
        assert!(error.path.ends_with("control_power_per_s2"), "{error}");
    }
}
