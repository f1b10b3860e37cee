//! Pitch-attitude control laws: θ_ref → elevator command (docs/model.md §5; paper §4.2).
//!
//! Every law implements [`PitchLaw`]: the observer-based PD ([`ObserverPdController`],
//! paper Eq. 30–36), the PID it is compared with ([`PidController`], paper Eq. 37) and any
//! law a user writes (see `examples/custom_pitch_law.rs`). A law is plant-independent: it
//! is designed from the pitch-plant derivatives at trim and the hardware
//! ([`PitchDesignContext`]) and reads the signals of one instant ([`PitchLawInputs`]).
//!
//! **Adding a law** to the scenario file takes one file beside this one (its parameters
//! implementing [`PitchLawDesign`], its controller implementing [`PitchLaw`]) and one
//! line in the registry below, which also declares the file's module. A law used only from code needs no registration: wrap it in
//! [`BuiltPitchLaw::Custom`].

pub mod command_shaping;
pub mod design;
mod law;

pub use law::{
    ElevatorSaturation, PitchDesignContext, PitchLaw, PitchLawDesign, PitchLawInputs,
    PitchPlantDerivatives,
};
pub use observer_pd::{ObserverPdController, ObserverPdGains, ObserverPdParameters, PitchFeedback};
pub use pid::{PidController, PidParameters, PidState};

// The registry of pitch laws that a scenario can name: one line each, `Variant("type
// name", module::Parameters)`; the macro declares the module (its file beside this one).
law::pitch_laws! {
    /// Observer-based PD (paper Eq. 30–36).
    ObserverPd("observer_pd", observer_pd::ObserverPdParameters),
    /// PID for comparison (paper Eq. 37).
    Pid("pid", pid::PidParameters),
}

impl PitchControllerParameters {
    /// Where the pitch law sits in a scenario file.
    pub const SECTION: &'static str = "control.pitch";
}

impl Default for PitchControllerParameters {
    /// The paper's proposed controller, O-PD, designed for the realistic stabilator.
    fn default() -> Self {
        Self::ObserverPd(ObserverPdParameters::default())
    }
}

impl PitchControllerParameters {
    /// The same law with the paper's tuning (its gains, its O-PD design).
    pub fn paper_tuning(&self) -> Self {
        match self {
            Self::ObserverPd(_) => Self::ObserverPd(ObserverPdParameters::paper()),
            Self::Pid(_) => Self::Pid(PidParameters::paper()),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const PLANT: PitchPlantDerivatives = PitchPlantDerivatives {
        dqdot_dq_per_s: -0.15,
        dqdot_delevator_per_s2: -1.93,
    };

    fn context() -> PitchDesignContext {
        PitchDesignContext {
            plant: PLANT,
            actuator: Default::default(),
            pitch_noise: Default::default(),
            time_step_s: 0.001,
        }
    }

    #[test]
    fn registered_laws_build_with_their_state_and_label() {
        let opd = PitchControllerParameters::default()
            .build(&context())
            .expect("valid");
        assert_eq!(opd.label(), "O-PD");
        assert_eq!(opd.state_names().len(), 3);
        let pid = PitchControllerParameters::Pid(PidParameters::default())
            .build(&context())
            .expect("valid");
        assert_eq!(pid.label(), "PID");
        assert_eq!(pid.state_names(), &["pitch_error_integral_rad_s"]);
        assert_eq!(
            PitchControllerParameters::TYPE_NAMES,
            &["observer_pd", "pid"]
        );
    }

    #[test]
    fn the_disturbance_estimate_is_the_observer_state_x3() {
        let opd = PitchControllerParameters::default()
            .build(&context())
            .expect("valid");
        assert_eq!(opd.disturbance_estimate_radps2(&[0.1, 0.2, 0.3]), Some(0.3));
        let pid = PitchControllerParameters::Pid(PidParameters::default())
            .build(&context())
            .expect("valid");
        assert_eq!(pid.disturbance_estimate_radps2(&[0.1]), None);
    }

    #[test]
    fn parameters_deserialise_from_a_tagged_table() {
        let parameters: PitchControllerParameters =
            serde_json::from_str(r#"{"type": "pid", "anti_windup": false}"#).expect("valid");
        let PitchControllerParameters::Pid(pid) = parameters else {
            panic!("expected PID, got {parameters:?}");
        };
        assert!(!pid.anti_windup);
        // Keys left out take the realistic PID's gains (docs/pitch-step.md).
        assert_eq!(pid.proportional_per_s2, 6.25);
    }

    #[test]
    fn a_custom_law_is_called_through_the_built_law() {
        #[derive(Debug)]
        struct Proportional;
        impl PitchLaw for Proportional {
            fn label(&self) -> &str {
                "P"
            }
            fn state_names(&self) -> &'static [&'static str] {
                &[]
            }
            fn elevator_command_rad(&self, _: &[f64], inputs: &PitchLawInputs) -> f64 {
                -2.0 * (inputs.theta_ref_rad - inputs.theta_measured_rad)
            }
            fn derivative(&self, _: &[f64], _: &PitchLawInputs, _: &mut [f64]) {}
        }
        let law = BuiltPitchLaw::Custom(std::sync::Arc::new(Proportional));
        let inputs = PitchLawInputs {
            theta_ref_rad: 0.1,
            ..PitchLawInputs::default()
        };
        assert_eq!(law.label(), "P");
        assert!((law.elevator_command_rad(&[], &inputs) + 0.2).abs() < 1e-15);
    }
}
