//! The `trim` and `linearize` commands: JSON contracts, tables and error exits.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, succeeded_json};
use serde_json::Value;

fn json(args: &[&str]) -> Value {
    succeeded_json(&deckland(args))
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

/// The crab in a steady crosswind, from the wind triangle alone: in level flight with no
/// sideslip the air-relative velocity is horizontal, of magnitude V, along the heading
/// ψ; the track stays on the final bearing (x) when V·sin ψ + W_y = 0, so
/// ψ = −asin(W_y/V), with wings level and the lateral surfaces at zero.
#[test]
fn six_dof_crab_heading_is_the_wind_triangle() {
    let v = json(&["trim", "--model", "6dof", "--crosswind", "5", "--json"]);
    let want = -(5.0f64 / 69.1).asin().to_degrees();
    let psi = v["psi_deg"].as_f64().unwrap();
    assert!(
        (psi - want).abs() < 1e-9,
        "ψ = {psi}°, wind triangle {want}°"
    );
    for level in ["phi_deg", "sideslip_deg", "aileron_deg", "rudder_deg"] {
        assert!(v[level].as_f64().unwrap().abs() < 1e-9, "{level}: {v}");
    }
    // The longitudinal trim is the 3-DOF model's (paper Table 3).
    let three = json(&["trim", "--json"]);
    for field in ["alpha_deg", "theta_deg", "elevator_deg", "thrust_n"] {
        let (a, b) = (v[field].as_f64().unwrap(), three[field].as_f64().unwrap());
        assert!(
            (a - b).abs() <= 1e-9 * b.abs().max(1.0),
            "{field}: {a} vs {b}"
        );
    }
}

/// `linearize --model 6dof`: the printed modes are the eigenvalues of the printed lateral
/// matrix (computed here from the characteristic polynomial's roots by a separate
/// method: the Dutch roll's ω_n² and 2ζω_n from the quadratic factor), and the
/// longitudinal block is the 3-DOF linearisation's.
#[test]
fn six_dof_modes_are_the_eigenvalues_of_the_printed_lateral_matrix() {
    let v = json(&["linearize", "--model", "6dof", "--json"]);
    let a: Vec<Vec<f64>> = v["lateral_a"]
        .as_array()
        .unwrap()
        .iter()
        .map(|row| {
            row.as_array()
                .unwrap()
                .iter()
                .map(|x| x.as_f64().unwrap())
                .collect()
        })
        .collect();
    let modes = &v["lateral_modes"];
    let re = modes["dutch_roll_eigenvalue"][0].as_f64().unwrap();
    let im = modes["dutch_roll_eigenvalue"][1].as_f64().unwrap();
    let roll = modes["roll_subsidence"]["eigenvalue_per_s"]
        .as_f64()
        .unwrap();
    let spiral = modes["spiral"]["eigenvalue_per_s"].as_f64().unwrap();
    // det(λI − A) at each printed eigenvalue vanishes (Laplace expansion, complex λ).
    let det = |lr: f64, li: f64| -> (f64, f64) {
        type C = (f64, f64);
        let mul = |x: C, y: C| (x.0 * y.0 - x.1 * y.1, x.0 * y.1 + x.1 * y.0);
        let m: Vec<Vec<C>> = (0..4)
            .map(|i| {
                (0..4)
                    .map(|j| {
                        let diag = if i == j { (lr, li) } else { (0.0, 0.0) };
                        (diag.0 - a[i][j], diag.1)
                    })
                    .collect()
            })
            .collect();
        fn det_rec(
            m: &[Vec<(f64, f64)>],
            mul: &dyn Fn((f64, f64), (f64, f64)) -> (f64, f64),
        ) -> (f64, f64) {
            if m.len() == 1 {
                return m[0][0];
            }
            let mut total = (0.0, 0.0);
            for col in 0..m.len() {
                let minor: Vec<Vec<(f64, f64)>> = m[1..]
                    .iter()
                    .map(|row| {
                        row.iter()
                            .enumerate()
                            .filter(|(j, _)| *j != col)
                            .map(|(_, x)| *x)
                            .collect()
                    })
                    .collect();
                let term = mul(m[0][col], det_rec(&minor, mul));
                let sign = if col % 2 == 0 { 1.0 } else { -1.0 };
                total = (total.0 + sign * term.0, total.1 + sign * term.1);
            }
            total
        }
        det_rec(&m, &mul)
    };
    for (lr, li) in [(re, im), (roll, 0.0), (spiral, 0.0)] {
        let (dr, di) = det(lr, li);
        assert!(
            dr.hypot(di) < 1e-9,
            "det(λI − A) at {lr} + {li}i = {dr} + {di}i"
        );
    }
    let omega = modes["dutch_roll_natural_frequency_radps"]
        .as_f64()
        .unwrap();
    let zeta = modes["dutch_roll_damping_ratio"].as_f64().unwrap();
    assert!((omega - re.hypot(im)).abs() < 1e-12);
    assert!((zeta + re / omega).abs() < 1e-12);
    // The approach's lateral modes are all stable (docs/six-dof.md).
    assert!(re < 0.0 && roll < 0.0 && spiral < 0.0);
    let three = json(&["linearize", "--json"]);
    for (six, key) in [("longitudinal_a", "a"), ("longitudinal_b", "b")] {
        let rows6 = v[six].as_array().unwrap();
        let rows3 = three[key].as_array().unwrap();
        for (r6, r3) in rows6.iter().zip(rows3) {
            for (x6, x3) in r6.as_array().unwrap().iter().zip(r3.as_array().unwrap()) {
                let (x6, x3) = (x6.as_f64().unwrap(), x3.as_f64().unwrap());
                assert!(
                    (x6 - x3).abs() < 1e-6 * x3.abs().max(1.0),
                    "{six}: {x6} vs {x3}"
                );
            }
        }
    }
}

#[test]
fn six_dof_options_are_refused_by_name() {
    for (args, message) in [
        (
            vec!["trim", "--sideslip", "3"],
            "--sideslip 3.0 needs --model 6dof",
        ),
        (
            vec!["linearize", "--crosswind", "2"],
            "--crosswind 2.0 needs --model 6dof",
        ),
        (
            vec!["trim", "--model", "6dof", "--sideslip", "40"],
            "--sideslip 40.0 is not allowed: expected a sideslip between -30 and +30 degrees",
        ),
        (
            vec!["trim", "--model", "6dof", "--sideslip", "25"],
            "trim needs rudder 36.40°, beyond its 30.0° limit by 6.40°",
        ),
        (
            vec!["trim", "--model", "6dof", "--crosswind", "90"],
            "--crosswind 90.0 is refused",
        ),
    ] {
        let output = deckland(&args);
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.contains(message), "{args:?}: {stderr}");
    }
}
