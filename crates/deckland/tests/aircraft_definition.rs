//! The aircraft as data (issue 41, item 3; docs/model.md "The aircraft as data"): the
//! F/A-18 ships as a definition file, a scenario flies another file with `[aircraft]
//! definition = "FILE"`, and a bad file is refused naming its file, line and key.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::AerodynamicData;
use deckland::recording::SummaryRecorder;
use deckland::scenario::{
    load_aircraft_definition, load_scenario_in, AircraftSection, Scenario, ScenarioError,
    FA18_DEFINITION_TOML,
};
use deckland::simulation::{Outcome, RunSummary, Simulation};
use std::path::PathBuf;

/// A new folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let folder =
        std::env::temp_dir().join(format!("deckland-aircraft-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&folder);
    std::fs::create_dir_all(&folder).unwrap();
    folder
}

fn fly(scenario: &Scenario) -> RunSummary {
    Simulation::new(scenario).unwrap().run(&mut SummaryRecorder)
}

/// The F/A-18 definition with `edit` applied to its text.
fn edited(edit: &[(&str, &str)]) -> String {
    let mut text = FA18_DEFINITION_TOML.to_owned();
    for (from, to) in edit {
        assert!(text.contains(from), "{from} is in the F/A-18 file");
        text = text.replacen(from, to, 1);
    }
    text
}

/// Loads `scenario` from a folder that also holds `aircraft.toml` = `definition`.
fn load_with(name: &str, scenario: &str, definition: &str) -> Result<Scenario, ScenarioError> {
    let folder = folder(name);
    std::fs::write(folder.join("aircraft.toml"), definition).unwrap();
    load_scenario_in(scenario, "scenario.toml", &folder)
}

/// Loads the scenario that only names `aircraft.toml` = `definition` as its aircraft.
fn load_definition(name: &str, definition: &str) -> Result<Scenario, ScenarioError> {
    load_with(
        name,
        "[aircraft]\ndefinition = \"aircraft.toml\"\n",
        definition,
    )
}

#[test]
fn the_shipped_fa18_file_is_the_built_in_aircraft_to_the_bit() {
    let definition = load_aircraft_definition(FA18_DEFINITION_TOML, "fa18.toml").unwrap();
    let mut section = AircraftSection::default();
    definition.apply_to(&mut section);
    assert_eq!(section, AircraftSection::default());
    // Equality of floats is not identity of bits (0.0 == −0.0): compare the bits too.
    let bits = |data: &AerodynamicData| {
        let value = serde_json::to_value(data).unwrap();
        format!("{value}")
    };
    assert_eq!(bits(&definition.aerodynamics), bits(&AerodynamicData::FA18));
    assert_eq!(
        definition.parameters.mass_kg.to_bits(),
        15_000.0_f64.to_bits()
    );
}

#[test]
fn flying_the_fa18_file_is_the_built_in_approach_bit_for_bit() {
    let scenario = load_definition("same", FA18_DEFINITION_TOML).unwrap();
    // The same file without the definition: the default but for the keys a file must
    // name (the wave-off's recovery keys, `WaveOffParameters::named_by_none`).
    let plain = deckland::scenario::load_scenario("", "plain.toml").unwrap();
    assert_eq!(scenario, plain);
    assert_eq!(scenario.aircraft, Scenario::default().aircraft);
    let built_in = fly(&plain);
    let from_file = fly(&scenario);
    assert_eq!(format!("{from_file:?}"), format!("{built_in:?}"));
}

/// A second aircraft, by editing numbers only: a lighter F/A-18 (13 000 kg, inertias
/// scaled by the mass ratio) with 10 % less pitch stiffness C_mα and a larger fin
/// (C_nβ's c0 +20 %). It trims, its laws are designed on its own linearisation, and it
/// flies the 3-D approach to the deck.
#[test]
fn an_edited_aircraft_file_flies_the_three_d_approach_with_no_code_change() {
    let definition = edited(&[
        ("mass_kg = 15000.0", "mass_kg = 13000.0"),
        (
            "pitch_inertia_kg_m2 = 205000.0",
            "pitch_inertia_kg_m2 = 177667.0",
        ),
        (
            "roll_inertia_kg_m2 = 31184.0",
            "roll_inertia_kg_m2 = 27026.0",
        ),
        (
            "yaw_inertia_kg_m2 = 230415.0",
            "yaw_inertia_kg_m2 = 199693.0",
        ),
        (
            "alpha = [-0.0866, 0.5110, -1.2897]",
            "alpha = [-0.0866, 0.4599, -1.2897]",
        ),
        (
            "beta = [0.0885, 0.0329, -0.3816]",
            "beta = [0.1062, 0.0329, -0.3816]",
        ),
    ]);
    let scenario = load_with(
        "light",
        "seed = 5\n[aircraft]\ndefinition = \"aircraft.toml\"\n",
        &definition,
    )
    .unwrap();
    assert_eq!(scenario.aircraft.parameters.mass_kg, 13_000.0);
    assert_eq!(
        scenario
            .aircraft
            .aerodynamics
            .pitching_moment
            .alpha
            .coefficients()[1],
        0.4599
    );
    let light = fly(&scenario);
    let heavy = fly(&Scenario {
        seed: 5,
        ..Scenario::default()
    });
    assert!(
        matches!(light.outcome, Outcome::Trap | Outcome::Bolter),
        "{:?}: {:?}",
        light.outcome,
        light.reason
    );
    assert_ne!(format!("{light:?}"), format!("{heavy:?}"));
    // A lighter aircraft trims at a lower α at the same airspeed: the data reached the
    // plant, not only the scenario.
    assert!(light.touchdown.is_some());
}

#[test]
fn a_scenario_written_out_keeps_another_aircraft_whole() {
    let definition = edited(&[("rudder = [0.2054, 0.4082", "rudder = [0.2154, 0.4082")]);
    let scenario = load_definition("written", &definition).unwrap();
    let written = toml::to_string(&scenario).unwrap();
    assert!(
        written.contains("[aircraft.aerodynamics.side_force]"),
        "{written}"
    );
    let folder = folder("written-again");
    let again = load_scenario_in(&written, "written.toml", &folder).unwrap();
    assert_eq!(again, scenario);
    // The F/A-18's data are left out of a written scenario, as before.
    let default = toml::to_string(&Scenario::default()).unwrap();
    assert!(!default.contains("aerodynamics"));
}

#[test]
fn a_bad_definition_is_named_by_its_file_line_and_key() {
    let definition = edited(&[("mass_kg = 15000.0", "mass_kg = 15000.0\nwingspan_ft = 37.4")]);
    let error = load_definition("unknown", &definition).unwrap_err();
    let message = error.to_string();
    assert!(message.contains("aircraft.toml"), "{message}");
    assert_eq!(error.field(), "parameters.wingspan_ft", "{message}");
    let line = FA18_DEFINITION_TOML
        .lines()
        .position(|l| l.starts_with("mass_kg"))
        .unwrap()
        + 2;
    assert_eq!(error.line(), Some(line), "{message}");

    let definition = edited(&[("mass_kg = 15000.0", "mass_kg = -1.0")]);
    let error = load_definition("range", &definition).unwrap_err();
    assert_eq!(error.field(), "parameters.mass_kg", "{error}");
    assert_eq!(error.line(), Some(line - 1), "{error}");
    assert!(error.to_string().contains("aircraft.toml"), "{error}");

    let definition = edited(&[(
        "alpha = [-0.0204, 5.677, -5.4246, 1.1645]",
        "alpha = [-0.0204, 5.677, -5.4246, 1.1645, 0, 0]",
    )]);
    let error = load_definition("terms", &definition).unwrap_err();
    assert!(error.to_string().contains("at most 5"), "{error}");
    assert_eq!(error.field(), "aerodynamics.lift.alpha", "{error}");

    let definition = edited(&[("[hook]", "[hooks]")]);
    let error = load_definition("section", &definition).unwrap_err();
    assert!(error.to_string().contains("hook"), "{error}");
}

#[test]
fn a_scenario_cannot_name_a_definition_and_set_its_data_too() {
    let scenario =
        "[aircraft]\ndefinition = \"aircraft.toml\"\n\n[aircraft.parameters]\nmass_kg = 14000.0\n";
    let error = load_with("both", scenario, FA18_DEFINITION_TOML).unwrap_err();
    assert_eq!(error.field(), "aircraft.parameters.mass_kg", "{error}");
    assert_eq!(error.line(), Some(5), "{error}");

    let error =
        load_with("missing", "[aircraft]\ndefinition = \"nowhere.toml\"\n", "").unwrap_err();
    assert_eq!(error.field(), "aircraft.definition", "{error}");
    assert!(error.to_string().contains("nowhere.toml"), "{error}");

    let error = load_with("number", "[aircraft]\ndefinition = 3\n", "").unwrap_err();
    assert_eq!(error.field(), "aircraft.definition", "{error}");
}

/// The key may stand anywhere TOML allows it; every other key keeps its line.
#[test]
fn the_definition_key_in_any_form_leaves_the_other_lines_in_place() {
    for scenario in [
        "aircraft.definition = \"aircraft.toml\"\nseed = -4\n",
        "aircraft = { model = \"6dof\", definition = \"aircraft.toml\" }\nseed = -4\n",
        "aircraft = { definition = \"aircraft.toml\", model = \"6dof\" }\nseed = -4\n",
    ] {
        let error = load_with("forms", scenario, FA18_DEFINITION_TOML).unwrap_err();
        assert_eq!(error.field(), "seed", "{scenario}: {error}");
        assert_eq!(error.line(), Some(2), "{scenario}: {error}");
    }
    let scenario = load_with(
        "paper",
        "hardware = \"paper\"\n[aircraft]\nmodel = \"3dof\"\ndefinition = \"aircraft.toml\"\n",
        FA18_DEFINITION_TOML,
    )
    .unwrap();
    // The definition's stabilator (40 °/s) is the aircraft's, also on the paper's set.
    assert_eq!(
        scenario.aircraft.elevator_actuator.rate_limit_degps,
        Some(40.0)
    );
}
