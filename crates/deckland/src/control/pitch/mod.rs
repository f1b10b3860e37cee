//! Pitch-attitude control laws: θ_ref → elevator command (docs/model.md §5; paper §4.2).
//!
//! Every law is an [`AxisLaw`] reading [`PitchLawInputs`] (a [`PitchLaw`]): the
//! observer-based PD ([`ObserverPdController`], paper Eq. 30–36), the PID it is compared
//! with ([`PidController`], paper Eq. 37) and any law a user writes (see
//! `examples/custom_pitch_law.rs`). A law is plant-independent: it is designed from the
//! pitch-plant derivatives at trim and the hardware ([`PitchDesignContext`]), reads the
//! signals of one instant and describes itself in its linear limit ([`LinearLaw`]), from
//! which the axis-generic [`crate::control::design`] code (loop model, margins, rate-limit check) assesses
//! it without knowing which law it is.
//!
//! **Adding a law** to the scenario file takes one file beside this one (its parameters
//! implementing [`PitchLawDesign`], its controller implementing [`AxisLaw`]) and one line
//! in the registry below, which also declares the file's module; nothing else names the
//! registered laws (hardware sets and `--compare` choose them by their `type` name,
//! [`PitchControllerParameters::registered`]). A law used only from code, or written
//! outside this crate, needs no registration: wrap it in [`BuiltPitchLaw::Custom`], or
//! hand a factory to `Simulation::with_pitch_law` or a campaign's
//! `ControllerVariant::custom`.

mod law;

/// The command shaping of a step, at its former path (it lives in the axis-generic
/// [`crate::control::design`]).
pub use crate::control::design::command_shaping;
pub use crate::control::design::AxisPlantDerivatives;
pub use crate::control::law::{AxisLaw, LinearLaw};
pub use law::{
    ElevatorSaturation, LawTuning, PitchDesignContext, PitchLaw, PitchLawDesign, PitchLawInputs,
};
pub use observer_pd::{
    design_observer_pd, ObserverPdController, ObserverPdGains, ObserverPdParameters, PitchFeedback,
};
pub use pid::{PidController, PidParameters, PidState};

// The registry of pitch laws that a scenario can name: one line each, `Variant("type
// name", module::Parameters)`; the macro declares the module (its file beside this one).
law::pitch_laws! {
    /// Observer-based PD (paper Eq. 30–36).
    ObserverPd("observer_pd", observer_pd::ObserverPdParameters),
    /// PID for comparison (paper Eq. 37).
    Pid("pid", pid::PidParameters),
    /// A proportional-derivative law that exists only to prove the registration path.
    #[cfg(test)]
    Proportional("proportional", proportional::ProportionalParameters),
}

impl PitchControllerParameters {
    /// Where the pitch law sits in a scenario file.
    pub const SECTION: &'static str = law::SECTION;

    /// The laws a comparison flies (`--compare`), in order: the paper's O-PD against its
    /// PID (paper §4.2.3).
    pub const COMPARISON: [&'static str; 2] = ["observer_pd", "pid"];

    /// The same law with the paper's tuning (its gains, its O-PD design).
    pub fn paper_tuning(&self) -> Self {
        self.retuned(LawTuning::Paper)
    }
}

impl BuiltPitchLaw {
    /// The same law, an O-PD with its observer's fractional power from tables
    /// ([`ObserverPdController::with_tabulated_power`]): the 3-D approach's, as its
    /// lateral O-PDs. Other laws are returned unchanged.
    pub(crate) fn with_tabulated_observer_power(self) -> Self {
        match self {
            Self::ObserverPd(law) => Self::ObserverPd(law.with_tabulated_power()),
            other => other,
        }
    }
}

impl Default for PitchControllerParameters {
    /// The paper's proposed controller, O-PD, designed for the realistic stabilator.
    fn default() -> Self {
        Self::ObserverPd(ObserverPdParameters::default())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::control::design::PAPER_PITCH_PLANT as PLANT;

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
        // The test build registers a third law (`proportional.rs`).
        assert_eq!(
            PitchControllerParameters::TYPE_NAMES,
            &["observer_pd", "pid", "proportional"]
        );
    }

    #[test]
    fn laws_are_found_by_their_type_name_with_either_tuning() {
        for &name in PitchControllerParameters::TYPE_NAMES {
            for tuning in [LawTuning::Realistic, LawTuning::Paper] {
                let law = PitchControllerParameters::registered(name, tuning).expect(name);
                assert_eq!(law.type_name(), name);
                assert_eq!(law.retuned(tuning), law);
            }
        }
        assert_eq!(
            PitchControllerParameters::registered("pid", LawTuning::Paper),
            Some(PitchControllerParameters::Pid(PidParameters::paper()))
        );
        assert_eq!(
            PitchControllerParameters::registered("observer_pd", LawTuning::Realistic),
            Some(PitchControllerParameters::default())
        );
        assert_eq!(
            PitchControllerParameters::default().paper_tuning(),
            PitchControllerParameters::ObserverPd(ObserverPdParameters::paper())
        );
        assert_eq!(
            PitchControllerParameters::registered("lqr", LawTuning::Realistic),
            None
        );
    }

    #[test]
    fn the_compared_laws_are_registered() {
        for name in PitchControllerParameters::COMPARISON {
            assert!(
                PitchControllerParameters::TYPE_NAMES.contains(&name),
                "{name}"
            );
        }
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
        impl AxisLaw for Proportional {
            type Inputs = PitchLawInputs;
            fn label(&self) -> &str {
                "P"
            }
            fn state_names(&self) -> &'static [&'static str] {
                &[]
            }
            fn surface_command_rad(&self, _: &[f64], inputs: &PitchLawInputs) -> f64 {
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
        assert!((law.surface_command_rad(&[], &inputs) + 0.2).abs() < 1e-15);
    }
}
