//! The reduction check in the closed loop (issue 26, target "Reduction"): with its
//! lateral states at rest and its aileron and rudder held at neutral, the 6-DOF aircraft
//! (`[aircraft] model = "6dof"`) flies the 3-DOF trajectory under the same longitudinal
//! cascade, on a calm approach and on a longitudinal-only adverse one (turbulence, air
//! wake, ship heave and pitch, pitch-sensor noise), to 1e-9 relative.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::{AircraftState, PlantModel};
use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{RunSummary, Simulation, Stop};

/// One step of a flight: the longitudinal state, the commands and the lateral signals.
struct Sample {
    time_s: f64,
    state: AircraftState,
    elevator_command_rad: f64,
    thrust_command_n: f64,
    lateral: [Option<f64>; 8],
}

/// Flies `scenario` with `model`, sampling every step, and returns the samples and the
/// summary.
fn fly(mut scenario: Scenario, model: PlantModel) -> (Vec<Sample>, RunSummary) {
    scenario.aircraft.model = model;
    // The 6-DOF in the 3-DOF's environment, lateral surfaces held at trim (the 3-D
    // approach, on by default, flies lineup in a 3-D environment).
    scenario.approach.three_dimensional = false;
    let mut simulation = Simulation::new(&scenario).unwrap();
    let mut samples = Vec::new();
    loop {
        let signals = simulation.signals();
        samples.push(Sample {
            time_s: simulation.time_s(),
            state: simulation.system().aircraft_state(simulation.state()),
            elevator_command_rad: signals.elevator_command_rad,
            thrust_command_n: signals.thrust_command_n,
            lateral: [
                signals.y_m,
                signals.hook_y_m,
                signals.phi_rad,
                signals.psi_rad,
                signals.p_radps,
                signals.r_radps,
                signals.beta_rad,
                signals.aileron_command_rad,
            ],
        });
        if let Stop::Ended(_) = simulation.step(&mut SummaryRecorder) {
            break;
        }
    }
    let summary = simulation.summary().unwrap().clone();
    (samples, summary)
}

/// The largest difference |a − b| / max(|b|, scale) over the two flights, per quantity:
/// x, h, θ, u, w, q, elevator, thrust, elevator command, thrust command. The scales are
/// each quantity's size in an approach (a quantity through zero is compared with it).
fn worst_relative_differences(six: &[Sample], three: &[Sample]) -> [f64; 10] {
    let scales = [1000.0, 10.0, 0.1, 70.0, 5.0, 0.1, 0.1, 1e4, 0.1, 1e4];
    let values = |s: &Sample| {
        [
            s.state.x_m,
            s.state.h_m,
            s.state.theta_rad,
            s.state.u_mps,
            s.state.w_mps,
            s.state.q_radps,
            s.state.elevator_rad,
            s.state.total_thrust_n(),
            s.elevator_command_rad,
            s.thrust_command_n,
        ]
    };
    let mut worst = [0.0_f64; 10];
    for (a, b) in six.iter().zip(three) {
        assert_eq!(a.time_s, b.time_s);
        for (i, (x, y)) in values(a).iter().zip(values(b)).enumerate() {
            worst[i] = worst[i].max((x - y).abs() / y.abs().max(scales[i]));
        }
    }
    worst
}

fn assert_the_six_dof_flies_the_three_dof_trajectory(scenario: Scenario) {
    let (three, three_summary) = fly(scenario, PlantModel::ThreeDof);
    let (six, six_summary) = fly(scenario, PlantModel::SixDof);
    assert_eq!(six.len(), three.len(), "the runs end at different steps");
    assert_eq!(six_summary.outcome, three_summary.outcome);
    // The approach goes somewhere: it ends on the deck, some 25 s after the start.
    assert!(three.len() > 15_000, "{} steps", three.len());
    let worst = worst_relative_differences(&six, &three);
    let names = [
        "x", "h", "θ", "u", "w", "q", "δe", "thrust", "δe cmd", "T cmd",
    ];
    let listed: Vec<String> = worst.iter().map(|d| format!("{d:.1e}")).collect();
    eprintln!(
        "largest relative differences {} over {} steps",
        listed.join(" "),
        three.len()
    );
    for (name, difference) in names.iter().zip(worst) {
        assert!(
            difference <= 1e-9,
            "{name}: largest relative difference {difference:e}"
        );
    }
    // The lateral states stay at rest, and the 3-DOF has none.
    for sample in &six {
        for value in sample.lateral {
            assert_eq!(value, Some(0.0));
        }
    }
    assert!(three.iter().all(|s| s.lateral.iter().all(Option::is_none)));
}

#[test]
fn calm_approach_reduces_to_the_three_dof() {
    let mut scenario = Scenario::default();
    let env = &mut scenario.environment;
    env.ship.enabled = false;
    env.wind.turbulence = false;
    env.wind.steady_wake = false;
    env.wind.periodic_wake = false;
    env.pitch_noise.enabled = false;
    assert_the_six_dof_flies_the_three_dof_trajectory(scenario);
}

#[test]
fn adverse_longitudinal_approach_reduces_to_the_three_dof() {
    // The realistic default: Dryden turbulence, steady and periodic air wake, ship heave
    // and pitch, pitch-sensor noise, the 80 Hz flight computer and the stabilator's rate
    // limit; all of it longitudinal.
    for seed in [1, 6] {
        let scenario = Scenario {
            seed,
            ..Scenario::default()
        };
        assert!(scenario.environment.wind.turbulence && scenario.environment.ship.enabled);
        assert_the_six_dof_flies_the_three_dof_trajectory(scenario);
    }
}

#[test]
fn direct_lift_flies_the_six_dof_as_the_three_dof() {
    let mut scenario = Scenario {
        seed: 3,
        ..Scenario::default()
    };
    scenario.control.direct_lift.enabled = true;
    assert_the_six_dof_flies_the_three_dof_trajectory(scenario);
}
