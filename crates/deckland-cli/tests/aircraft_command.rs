//! `deckland aircraft`: the F/A-18 printed as a definition file, checked, and flown from
//! a scenario that names it relative to its own folder (issue 41, item 3).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;
use common::{assert_no_panic, assert_refused, assert_success, deckland, scratch};

#[test]
fn the_printed_fa18_is_a_commented_definition_with_its_mass() {
    let output = deckland(["aircraft", "--print-default"]);
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert_eq!(text, deckland::scenario::FA18_DEFINITION_TOML);
    let mass = text
        .lines()
        .find(|l| l.starts_with("mass_kg"))
        .expect("a mass_kg key");
    assert!(mass.contains("# mass (kg)"), "{mass}");
    assert_unique_keys_parse(&text);
}

fn assert_unique_keys_parse(text: &str) {
    let table: toml::Table = toml::from_str(text).unwrap();
    for section in ["parameters", "lateral", "engines", "aerodynamics", "hook"] {
        assert!(table.contains_key(section), "{section}");
    }
}

#[test]
fn a_scenario_flies_a_definition_beside_it_and_a_bad_one_is_named() {
    let folder = scratch("aircraft-definition");
    std::fs::create_dir_all(folder.join("aircraft")).unwrap();
    let light = deckland::scenario::FA18_DEFINITION_TOML.replacen(
        "mass_kg = 15000.0",
        "mass_kg = 14000.0",
        1,
    );
    std::fs::write(folder.join("aircraft/light.toml"), &light).unwrap();
    std::fs::write(
        folder.join("light-scenario.toml"),
        "[aircraft]\ndefinition = \"aircraft/light.toml\"\n",
    )
    .unwrap();
    // Relative to the scenario's folder, not to the working folder.
    let output = deckland([
        "scenario",
        "--check",
        folder.join("light-scenario.toml").to_str().unwrap(),
    ]);
    assert_no_panic(&output);
    assert_success(&output);
    let output = deckland([
        "aircraft",
        "--check",
        folder.join("aircraft/light.toml").to_str().unwrap(),
    ]);
    assert!(String::from_utf8_lossy(&output.stdout).contains("14000 kg"));

    let bad = light.replacen("span_m = 11.405", "span_m = 0.0", 1);
    std::fs::write(folder.join("aircraft/light.toml"), bad).unwrap();
    let output = deckland([
        "scenario",
        "--check",
        folder.join("light-scenario.toml").to_str().unwrap(),
    ]);
    assert_refused(&output, 1, &["light.toml", "`lateral.span_m`", "line 20"]);
    let _ = std::fs::remove_dir_all(&folder);
}
