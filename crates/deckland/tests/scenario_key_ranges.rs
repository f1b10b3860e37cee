//! Every key's range, table-driven (issue 14, class 1 "keys without an upper bound" and
//! class 6 "errors name the wrong field"): for every numeric key of the serialised
//! default scenario — and of the scenario variants that have other keys (PID pitch
//! control, the pitch-step and sink-rate missions, the paper's hardware set) —
//! ±1e300, ±∞ and NaN are refused with an error naming exactly that key, and the key's
//! line in the file.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::scenario::{load_scenario, Mission, PitchCommand, Scenario, ScenarioError, MAX_SEED};
use toml::Value;

/// The scenario variants whose serialised forms together hold every key.
fn variants() -> Vec<(&'static str, Scenario)> {
    let mut pid = Scenario::default();
    pid.control.pitch = PitchControllerParameters::Pid(PidParameters::default());
    let mut pitch_step = Scenario::default();
    pitch_step.mission = Mission::pitch_step(2.0, 6.0, PitchCommand::JerkLimited);
    let mut sink_rate = Scenario::default();
    sink_rate.mission = Mission::sink_rate(10.0, 5.0, 20.0);
    vec![
        ("default", Scenario::default()),
        ("pid", pid),
        ("pitch_step", pitch_step),
        ("sink_rate", sink_rate),
        ("paper", Scenario::paper()),
    ]
}

/// The dotted paths of every numeric leaf (floats, integers, and arrays of floats by
/// element) of `table`.
fn numeric_keys(prefix: &str, table: &toml::Table, out: &mut Vec<(String, Option<usize>)>) {
    for (key, value) in table {
        let path = if prefix.is_empty() {
            key.clone()
        } else {
            format!("{prefix}.{key}")
        };
        match value {
            Value::Float(_) | Value::Integer(_) => out.push((path, None)),
            Value::Array(items) => {
                for (index, item) in items.iter().enumerate() {
                    if matches!(item, Value::Float(_) | Value::Integer(_)) {
                        out.push((path.clone(), Some(index)));
                    }
                }
            }
            Value::Table(inner) => numeric_keys(&path, inner, out),
            _ => {}
        }
    }
}

/// `table` with the leaf at `path` (element `index` of an array) set to `value`.
fn with_value(table: &toml::Table, path: &str, index: Option<usize>, value: Value) -> toml::Table {
    let mut table = table.clone();
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop().unwrap();
    let mut cursor = &mut table;
    for part in parts {
        cursor = cursor.get_mut(part).unwrap().as_table_mut().unwrap();
    }
    match index {
        None => {
            cursor.insert(last.to_owned(), value);
        }
        Some(i) => cursor.get_mut(last).unwrap().as_array_mut().unwrap()[i] = value,
    }
    table
}

/// Loads `table` as a file and returns the error, which must name `path` and its line.
fn refused(table: &toml::Table, path: &str, what: &str) -> ScenarioError {
    let text = toml::to_string(table).unwrap();
    let error = match load_scenario(&text, "mutated.toml") {
        Ok(_) => panic!("{path} = {what} was accepted"),
        Err(error) => error,
    };
    assert_eq!(
        error.field(),
        path,
        "{path} = {what}: the error names another field: {error}"
    );
    assert!(
        error.line().is_some(),
        "{path} = {what}: the error has no line: {error}"
    );
    error
}

#[test]
fn every_numeric_key_refuses_huge_infinite_and_nan_values_naming_itself() {
    let mut checked = 0;
    let mut paths = std::collections::BTreeSet::new();
    let mut seen = std::collections::BTreeSet::new();
    for (variant, scenario) in variants() {
        let table: toml::Table = toml::from_str(&toml::to_string(&scenario).unwrap()).unwrap();
        // The variant itself is valid.
        load_scenario(&toml::to_string(&table).unwrap(), variant).unwrap();
        let mut keys = Vec::new();
        numeric_keys("", &table, &mut keys);
        for (path, index) in keys {
            // Each key once, in the first variant that has it.
            if !seen.insert((path.clone(), index)) {
                continue;
            }
            paths.insert(path.clone());
            let integer = matches!(
                index.map_or_else(
                    || path_value(&table, &path).clone(),
                    |i| path_value(&table, &path).as_array().unwrap()[i].clone()
                ),
                Value::Integer(_)
            );
            let values: Vec<(Value, &str)> = if integer {
                vec![
                    (Value::Integer(-1), "-1"),
                    (Value::Float(1e300), "1e300 (a float)"),
                ]
            } else {
                vec![
                    (Value::Float(1e300), "1e300"),
                    (Value::Float(-1e300), "-1e300"),
                    (Value::Float(f64::INFINITY), "inf"),
                    (Value::Float(f64::NEG_INFINITY), "-inf"),
                    (Value::Float(f64::NAN), "nan"),
                ]
            };
            for (value, what) in values {
                let error = refused(&with_value(&table, &path, index, value), &path, what);
                let message = error.to_string();
                assert!(
                    message.contains("expected"),
                    "{variant}: {path} = {what}: the error does not say what is allowed: {message}"
                );
                checked += 1;
            }
        }
    }
    // The table covers every section: a key missing from the serialised form would be
    // missing from this test.
    for expected in [
        "seed",
        "time_step_s",
        "max_time_s",
        "mission.step_deg",
        "mission.sink_rate_mps",
        "aircraft.parameters.mass_kg",
        "aircraft.elevator_actuator.rate_limit_degps",
        "aircraft.hook.aft_of_cg_m",
        "environment.deck.wire_positions_m",
        "control.pitch.settling_time_s",
        "control.pitch.observer.epsilon",
        "control.pitch.proportional_per_s2",
        "control.flight_path.compensation_window_s",
        "control.flight_path.compensation_blend_s",
        "approach.airspeed_mps",
        "outcome.min_airspeed_mps",
        "dispersion.sea_state_log_sd",
    ] {
        assert!(paths.contains(expected), "{expected} is not in the table");
    }
    assert!(checked > 250, "only {checked} values checked");
}

fn path_value<'a>(table: &'a toml::Table, path: &str) -> &'a Value {
    let mut parts = path.split('.');
    let mut value = table.get(parts.next().unwrap()).unwrap();
    for part in parts {
        value = value.get(part).unwrap();
    }
    value
}

#[test]
fn seeds_above_the_toml_integer_range_are_refused_by_validate() {
    let mut scenario = Scenario {
        seed: MAX_SEED,
        ..Scenario::default()
    };
    assert!(scenario.validate().is_ok());
    scenario.seed = MAX_SEED + 1;
    let error = scenario.validate().unwrap_err();
    assert_eq!(error.path, "seed");
}

/// Regression (issue 14, class 7): extra elements of `wire_positions_m`, even a string
/// and a table, were silently dropped and the file called valid.
#[test]
fn regression_wire_positions_with_extra_elements_are_refused() {
    for list in [
        r#"[-18.0, -6.0, 6.0, 18.0, "x", { a = 1 }]"#,
        "[-18.0, -6.0, 6.0, 18.0, 30.0]",
        "[-18.0, -6.0, 6.0]",
        r#"[-18.0, -6.0, 6.0, "18"]"#,
    ] {
        let text = format!("[environment.deck]\nwire_positions_m = {list}\n");
        let error = load_scenario(&text, "wires.toml").expect_err(list);
        assert_eq!(
            error.field(),
            "environment.deck.wire_positions_m",
            "{error}"
        );
        assert_eq!(error.line(), Some(2), "{error}");
    }
    let text = "[environment.deck]\nwire_positions_m = [-20.0, -5.0, 5.0, 20]\n";
    let scenario = load_scenario(text, "wires.toml").unwrap();
    assert_eq!(
        scenario.environment.deck.wire_positions_m,
        [-20.0, -5.0, 5.0, 20.0]
    );
}

/// Regression (issue 14, class 6): a tiny settling time was blamed on
/// `control.pitch.proportional_per_s2`, a huge damping ratio on `derivative_per_s`.
#[test]
fn regression_pitch_design_errors_name_the_design_key() {
    for (key, value) in [("settling_time_s", "1e-300"), ("damping_ratio", "1e308")] {
        let text = format!("[control.pitch]\ntype = \"observer_pd\"\n{key} = {value}\n");
        let error = load_scenario(&text, "pitch.toml").expect_err(key);
        assert_eq!(error.field(), format!("control.pitch.{key}"), "{error}");
        assert_eq!(error.line(), Some(3), "{error}");
    }
}

/// Regression (issue 14, class 6): syntax errors in sections after `[aircraft]` were
/// reported "near field `aircraft.<key>`".
#[test]
fn regression_syntax_errors_name_their_own_section() {
    let text = "[aircraft]\nconfiguration = \"landing\"\n\n[control.speed]  # thrust\ndamping_ratio = 1 m\n";
    let error = load_scenario(text, "syntax.toml").expect_err("syntax");
    assert_eq!(error.field(), "control.speed.damping_ratio", "{error}");
    assert_eq!(error.line(), Some(5));
}
