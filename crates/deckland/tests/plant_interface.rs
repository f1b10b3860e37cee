//! The plant interface from a scenario file: `[aircraft] model` chooses the plant the
//! loop flies, the 6-DOF's own sections are read and checked with named errors, and the
//! loop lays out the chosen plant's named states.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::six_dof::{SixDofAircraft, SixDofState};
use deckland::aircraft::{Aircraft, Plant, PlantModel};
use deckland::recording::SummaryRecorder;
use deckland::scenario::{load_scenario, Scenario};
use deckland::simulation::{Outcome, Simulation, Stop};

#[test]
fn the_model_key_chooses_the_plant_and_its_named_states() {
    let scenario = load_scenario("[aircraft]\nmodel = \"6dof\"\n", "six.toml").unwrap();
    assert_eq!(scenario.aircraft.model, PlantModel::SixDof);
    let simulation = Simulation::new(&scenario).unwrap();
    let layout = simulation.system().layout();
    assert_eq!(layout.aircraft.len, SixDofState::DIMENSION);
    assert_eq!(
        layout
            .states
            .state_name(layout.aircraft.offset + 3)
            .as_deref(),
        Some("aircraft.p_radps")
    );
    assert_eq!(simulation.system().plant().model(), PlantModel::SixDof);
    // The 6-DOF is the realistic default (the 3-D approach); "3dof" chooses the
    // longitudinal model, with its ten states.
    let default = Simulation::new(&load_scenario("", "default.toml").unwrap()).unwrap();
    assert_eq!(default.system().plant().model(), PlantModel::SixDof);
    let three = load_scenario("[aircraft]\nmodel = \"3dof\"\n", "three.toml").unwrap();
    let three = Simulation::new(&three).unwrap();
    assert_eq!(three.system().layout().aircraft.len, 10);
    assert_eq!(three.system().plant().model(), PlantModel::ThreeDof);
    assert_eq!(three.system().plant().state_units(), Aircraft::STATE_UNITS);
    assert_eq!(SixDofAircraft::SURFACES, ["elevator", "aileron", "rudder"]);
}

#[test]
fn an_unknown_model_is_refused_naming_the_key_and_the_choices() {
    let error = load_scenario("[aircraft]\nmodel = \"4dof\"\n", "bad.toml").unwrap_err();
    let text = error.to_string();
    assert_eq!(error.field(), "aircraft.model", "{text}");
    assert!(
        text.contains("4dof") && text.contains("3dof") && text.contains("6dof"),
        "{text}"
    );
}

#[test]
fn the_papers_set_flies_the_three_dof_model() {
    let error = load_scenario(
        "hardware = \"paper\"\n[aircraft]\nmodel = \"6dof\"\n",
        "paper.toml",
    )
    .unwrap_err();
    assert_eq!(error.field(), "aircraft.model", "{error}");
    assert!(error.to_string().contains("paper"), "{error}");
}

#[test]
fn the_six_dof_sections_are_read_and_checked_with_named_errors() {
    let text = "[aircraft]\nmodel = \"6dof\"\n\n[aircraft.lateral]\nspan_m = 12.0\n\n\
                [aircraft.rudder_actuator]\nnatural_frequency_rad_s = 40.0\n\
                damping_ratio = 0.7\ntravel_deg = 20.0\n";
    let scenario = load_scenario(text, "six.toml").unwrap();
    assert_eq!(scenario.aircraft.lateral.span_m, 12.0);
    // Left out of the section: the default inertia; left out of the rudder: no rate limit.
    assert_eq!(scenario.aircraft.lateral.roll_inertia_kg_m2, 31_184.0);
    assert_eq!(scenario.aircraft.rudder_actuator.travel_deg, 20.0);
    assert_eq!(scenario.aircraft.rudder_actuator.rate_limit_degps, None);
    for (key, section, value) in [
        ("span_m", "lateral", "0.5"),
        ("yaw_inertia_kg_m2", "lateral", "-3.0"),
        ("product_of_inertia_xz_kg_m2", "lateral", "1e6"),
    ] {
        let text = format!("[aircraft.{section}]\n{key} = {value}\n");
        let error = load_scenario(&text, "bad.toml").unwrap_err();
        assert_eq!(
            error.field(),
            format!("aircraft.{section}.{key}"),
            "{error}"
        );
        assert_eq!(error.line(), Some(2), "{error}");
    }
    let text = "[aircraft.aileron_actuator]\nnatural_frequency_rad_s = 30.0\n\
                damping_ratio = 0.5\ntravel_deg = 90.0\n";
    let error = load_scenario(text, "bad.toml").unwrap_err();
    assert_eq!(
        error.field(),
        "aircraft.aileron_actuator.travel_deg",
        "{error}"
    );
    // An aileron too fast for the time step is refused on the time step, for the 6-DOF.
    let text = "time_step_s = 0.005\n[aircraft]\nmodel = \"6dof\"\n\
                [aircraft.aileron_actuator]\nnatural_frequency_rad_s = 150.0\n\
                damping_ratio = 0.5\ntravel_deg = 25.0\n";
    let error = load_scenario(text, "fast.toml").unwrap_err();
    assert_eq!(error.field(), "time_step_s", "{error}");
}

#[test]
fn the_six_dof_lands_with_its_lateral_signals_on_the_bus() {
    let mut scenario = Scenario {
        seed: 3,
        ..Scenario::default()
    };
    scenario.aircraft.model = PlantModel::SixDof;
    let mut simulation = Simulation::new(&scenario).unwrap();
    let first = simulation.signals();
    assert_eq!(first.phi_rad, Some(0.0));
    assert_eq!(first.rudder_command_rad, Some(0.0));
    assert!(first.beta_rad.is_some() && first.hook_y_m == Some(0.0));
    while !matches!(simulation.step(&mut SummaryRecorder), Stop::Ended(_)) {}
    let summary = simulation.summary().unwrap();
    assert!(
        !matches!(summary.outcome, Outcome::Diverged | Outcome::Timeout),
        "{summary:?}"
    );
    assert!(summary.end_time_s > 20.0, "{summary:?}");
}
