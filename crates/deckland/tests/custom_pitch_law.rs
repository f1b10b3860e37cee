//! A user's own pitch law flies through the public API exactly as a registered one: the
//! paper's PID (Eq. 37) written again outside the library, as an `AxisLaw` on the pitch
//! axis with its own state, gives bit-identical runs and campaigns to the registered PID,
//! and its linear description, written from the same equations, is assessed by the design
//! code like the registered PID's. The comparison is independent of any number the
//! program prints: two separately written implementations of the same law must agree to
//! the last bit. Such a law needs no registration: this is how a law outside the library
//! flies (a law inside it is one file plus one registry line, see `control::pitch`).

use std::sync::atomic::AtomicBool;
use std::sync::Arc;

use deckland::aircraft::ElevatorActuatorParameters;
use deckland::control::design::{assess_loop, ActuatorKeys, AxisHardware, SensorNoise};
use deckland::control::pitch::{
    AxisLaw, AxisPlantDerivatives, ElevatorSaturation, LinearLaw, PidParameters,
    PitchControllerParameters, PitchDesignContext, PitchLaw, PitchLawInputs,
};
use deckland::experiments::{fly_approach, fly_approach_with_law};
use deckland::monte_carlo::{run_campaign, CampaignSpec, ControllerVariant};
use deckland::parameters::ParameterError;
use deckland::scenario::Scenario;
use deckland::sensors::PitchNoiseParameters;
use deckland::simulation::{PitchLawFactory, Simulation};

/// Paper Eq. 37 with conditional-integration anti-windup, written from the equations.
#[derive(Debug)]
struct HandWrittenPid {
    gains: PidParameters,
    control_power_per_s2: f64,
}

impl AxisLaw for HandWrittenPid {
    type Inputs = PitchLawInputs;

    fn label(&self) -> &str {
        "hand-written PID"
    }

    fn state_names(&self) -> &'static [&'static str] {
        &["integral"]
    }

    fn surface_command_rad(&self, state: &[f64], inputs: &PitchLawInputs) -> f64 {
        let error = inputs.theta_ref_rad - inputs.theta_measured_rad;
        let u = self.gains.proportional_per_s2 * error + self.gains.integral_per_s3 * state[0]
            - self.gains.derivative_per_s * inputs.pitch_rate_measured_radps;
        inputs.elevator_trim_rad + u / self.control_power_per_s2
    }

    fn derivative(&self, _state: &[f64], inputs: &PitchLawInputs, rate: &mut [f64]) {
        let error = inputs.theta_ref_rad - inputs.theta_measured_rad;
        let drift = self.gains.integral_per_s3 * error / self.control_power_per_s2;
        let frozen = match inputs.elevator_saturation {
            ElevatorSaturation::NotSaturated => false,
            ElevatorSaturation::AtLowerLimit => drift < 0.0,
            ElevatorSaturation::AtUpperLimit => drift > 0.0,
        };
        rate[0] = if frozen { 0.0 } else { error };
    }

    /// Eq. 37 in its linear limit, written from the equations: ż = r − y,
    /// u = (K_P·(r − y) + K_I·z − K_D·q)/M_δ; the two unused states are placeholders.
    fn linear_law(&self) -> Option<LinearLaw> {
        let md = self.control_power_per_s2;
        let g = &self.gains;
        Some(LinearLaw {
            state_matrix: [[0.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]],
            input_matrix: [[1.0, -1.0, 0.0, 0.0], [0.0; 4], [0.0; 4]],
            output_states: [g.integral_per_s3 / md, 0.0, 0.0],
            output_inputs: [
                g.proportional_per_s2 / md,
                -g.proportional_per_s2 / md,
                -g.derivative_per_s / md,
                0.0,
            ],
        })
    }
}

fn factory() -> Arc<PitchLawFactory> {
    Arc::new(
        |context: &PitchDesignContext| -> Result<Box<dyn PitchLaw>, ParameterError> {
            Ok(Box::new(HandWrittenPid {
                gains: PidParameters::default(),
                control_power_per_s2: context.plant.control_power_per_s2,
            }))
        },
    )
}

fn with_registered_pid(seed: u64) -> Scenario {
    let mut scenario = Scenario {
        seed,
        ..Scenario::default()
    };
    scenario.control.pitch = PitchControllerParameters::Pid(PidParameters::default());
    scenario
}

#[test]
fn a_hand_written_pid_flies_bit_identical_to_the_registered_one() {
    let law = factory();
    for seed in [1, 2] {
        let scenario = with_registered_pid(seed);
        let registered = fly_approach(&scenario).expect("valid");
        let own = fly_approach_with_law(&scenario, &*law).expect("valid");
        assert_eq!(registered.summary, own.summary, "seed {seed}");
        assert_eq!(registered.samples.len(), own.samples.len());
        let last = (registered.samples.last(), own.samples.last());
        assert_eq!(
            last.0.map(|s| s.elevator_rad),
            last.1.map(|s| s.elevator_rad)
        );
    }
}

/// The design code assesses a user's law from its linear description alone, exactly as
/// the registered PID's.
#[test]
fn the_design_code_assesses_a_user_law_like_the_registered_one() {
    let context = PitchDesignContext {
        plant: AxisPlantDerivatives {
            rate_damping_per_s: -0.1891,
            control_power_per_s2: -1.9675,
        },
        actuator: ElevatorActuatorParameters::default(),
        pitch_noise: PitchNoiseParameters::default(),
        time_step_s: 0.001,
    };
    let own = HandWrittenPid {
        gains: PidParameters::default(),
        control_power_per_s2: context.plant.control_power_per_s2,
    };
    let registered = PitchControllerParameters::Pid(PidParameters::default())
        .build(&context)
        .expect("valid");
    let (own_law, registered_law) = (own.linear_law(), registered.linear_law());
    assert_eq!(own_law, registered_law);
    let hardware = AxisHardware {
        actuator: context.actuator,
        actuator_keys: ActuatorKeys::ELEVATOR,
        surface_trim_rad: (-8.17f64).to_radians(),
        plant: context.plant,
        coupling: None,
        control_delay_s: 1.5 / 80.0,
    };
    let noise = SensorNoise::from_parameters(&context.pitch_noise, 0.001);
    let assessed = assess_loop(&hardware, &noise, &own_law.expect("linear"), 1.2);
    assert!(assessed.closed_loop_max_real_part < 0.0, "{assessed:?}");
    let margin = assessed.margins.phase_margin_deg.expect("a crossover");
    assert!(margin > 0.0, "{assessed:?}");
}

#[test]
fn a_user_law_gets_its_own_state_slot_and_label() {
    let scenario = with_registered_pid(1);
    let simulation = Simulation::with_pitch_law(&scenario, &*factory()).expect("valid");
    let layout = simulation.system().layout();
    assert_eq!(layout.pitch_law.len, 1);
    assert_eq!(simulation.system().pitch_law().label(), "hand-written PID");
    let name = layout.states.state_name(layout.pitch_law.offset);
    assert_eq!(name.as_deref(), Some("pitch_law.integral"));
}

#[test]
fn a_campaign_flies_a_user_law_beside_a_registered_one_on_the_same_seeds() {
    let scenario = with_registered_pid(7);
    let mut spec = CampaignSpec::new(scenario, 4, 7);
    spec.controllers
        .push(ControllerVariant::custom("hand-written PID", factory()));
    let result = run_campaign(&spec, 2, &|_| {}, &AtomicBool::new(false)).expect("valid");
    assert_eq!(result.records.len(), 8);
    for pair in result.records.chunks(2) {
        assert_eq!(pair[0].seed, pair[1].seed);
        assert_eq!(pair[0].result, pair[1].result, "run {}", pair[0].run_index);
    }
    assert_eq!(result.controller_labels, ["PID", "hand-written PID"]);
}
