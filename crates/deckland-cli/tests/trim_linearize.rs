//! The `trim` and `linearize` commands: JSON contracts, tables and error exits.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::deckland;
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    let output = deckland(args);
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("stdout is one JSON document")
}

#[test]
fn trim_json_has_the_documented_fields_and_table_3_values() {
    let v = json(&["trim", "--json"]);
    for field in [
        "speed_mps",
        "gamma_deg",
        "alpha_deg",
        "theta_deg",
        "elevator_deg",
        "thrust_n",
        "throttle",
        "residuals",
    ] {
        assert!(v.get(field).is_some(), "missing {field}");
    }
    // Paper Table 3: α = θ = 7.1° at 69.1 m/s level.
    assert!((v["alpha_deg"].as_f64().unwrap() - 7.1).abs() < 0.01);
    assert!((v["theta_deg"].as_f64().unwrap() - 7.1).abs() < 0.01);
    let throttle = v["throttle"].as_f64().unwrap();
    let thrust = v["thrust_n"].as_f64().unwrap();
    assert!((throttle * 2.0 * 71_172.0 - thrust).abs() < 1e-6);
}

#[test]
fn trim_options_change_the_condition() {
    let v = json(&[
        "trim", "--speed", "75", "--gamma", "-3.5", "--config", "clean", "--json",
    ]);
    assert_eq!(v["speed_mps"].as_f64(), Some(75.0));
    assert!((v["gamma_deg"].as_f64().unwrap() + 3.5).abs() < 1e-12);
    assert_eq!(v["configuration"].as_str(), Some("clean"));
    let alpha = v["alpha_deg"].as_f64().unwrap();
    let theta = v["theta_deg"].as_f64().unwrap();
    assert!((theta - alpha + 3.5).abs() < 1e-9);
}

#[test]
fn linearize_json_has_matrices_eigenvalues_and_modes() {
    let v = json(&["linearize", "--json"]);
    assert_eq!(v["state_names"].as_array().unwrap().len(), 4);
    assert_eq!(v["input_names"].as_array().unwrap().len(), 2);
    let a = v["a"].as_array().unwrap();
    assert_eq!(a.len(), 4);
    assert!(a.iter().all(|row| row.as_array().unwrap().len() == 4));
    let b = v["b"].as_array().unwrap();
    assert!(b.iter().all(|row| row.as_array().unwrap().len() == 2));
    assert_eq!(v["eigenvalues"].as_array().unwrap().len(), 4);
    let modes = v["modes"].as_array().unwrap();
    let names: Vec<&str> = modes.iter().map(|m| m["name"].as_str().unwrap()).collect();
    assert_eq!(names, ["short_period", "phugoid"]);
    // docs/model.md §2.3: short period ≈ −0.385 ± 0.478i → ω_n ≈ 0.614 rad/s.
    let omega = modes[0]["natural_frequency_rad_s"].as_f64().unwrap();
    assert!((omega - (0.385f64.hypot(0.478))).abs() < 0.005, "{omega}");
}

#[test]
fn tables_are_readable() {
    let output = deckland(["linearize"]);
    assert!(output.status.success());
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(text.contains("short_period") && text.contains("phugoid"));
    assert!(text.contains("angle of attack"));
}

#[test]
fn unreachable_trim_fails_with_the_limit_named() {
    let output = deckland(["trim", "--gamma", "-20"]);
    assert!(!output.status.success());
    let stderr = String::from_utf8(output.stderr).unwrap();
    assert!(
        stderr.contains("thrust") && stderr.contains("lower limit"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"));
    // A request outside the solver's range names the option, not the library's field.
    let output = deckland(["trim", "--speed", "-5"]);
    assert!(!output.status.success());
    assert!(String::from_utf8(output.stderr)
        .unwrap()
        .contains("--speed -5.0 is not allowed"));
}

/// Regression: `linearize` printed "-0.000000" for entries that round to zero.
#[test]
fn linearize_prints_no_negative_zero() {
    let output = deckland(["linearize"]);
    assert!(output.status.success(), "{output:?}");
    let text = String::from_utf8_lossy(&output.stdout);
    for word in text.split_whitespace() {
        let magnitude = word.trim_start_matches(['-', '−']);
        let zero = !magnitude.is_empty() && magnitude.chars().all(|c| c == '0' || c == '.');
        assert!(
            !(zero && magnitude != word),
            "negative zero `{word}` in:\n{text}"
        );
    }
}

/// Regression: `scenario --check` said only "did not converge" for an approach airspeed
/// too low to trim, where `trim` names the angle of attack it needs. It now says that
/// too, and the lowest airspeed that trims.
#[test]
fn scenario_check_explains_an_untrimmable_airspeed_as_trim_does() {
    let dir = common::scratch("untrimmable-airspeed");
    let file = dir.join("slow.toml");
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(&file, "[approach]\nairspeed_mps = 40.0\n").unwrap();
    let check = deckland(["scenario", "--check", file.to_str().unwrap()]);
    common::assert_refused(
        &check,
        1,
        &[
            "approach.airspeed_mps",
            "trim needs angle of attack",
            "lowest airspeed that trims",
        ],
    );
    let trim = deckland(["trim", "--speed", "40", "--gamma", "-3.5"]);
    let trim_error = String::from_utf8_lossy(&trim.stderr);
    let reason = trim_error
        .split("γ = -3.5°: ")
        .nth(1)
        .expect("trim names the speed and angle")
        .trim();
    assert!(
        String::from_utf8_lossy(&check.stderr).contains(reason),
        "{check:?} lacks `{reason}`"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
