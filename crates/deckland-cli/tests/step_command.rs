//! Runs `deckland step` end to end: the JSON document, the CSV, the plots, the settling of
//! the O-PD in ideal conditions, and the errors for bad options.
#![allow(clippy::unwrap_used)]

mod common;

use common::{deckland, scratch, succeeded_json};
use std::ffi::OsStr;
use std::fs;
use std::path::Path;
use std::process::Output;

fn controller<'a>(report: &'a serde_json::Value, name: &str) -> &'a serde_json::Value {
    report["controllers"]
        .as_array()
        .unwrap()
        .iter()
        .find(|c| c["controller"] == name)
        .unwrap_or_else(|| panic!("no {name} in {report}"))
}

#[test]
fn step_command_writes_json_csv_and_plots() {
    let out = scratch("json");
    let result = run_step(&out, &["--seconds", "4", "--json"]);
    let report = succeeded_json(&result);
    assert_eq!(report["conditions"], "ideal");
    assert_eq!(report["step_deg"], 2.0);
    assert_eq!(report["seed"], 1);
    assert_eq!(report["controllers"].as_array().unwrap().len(), 2);
    for name in ["O-PD", "PID"] {
        let c = controller(&report, name);
        for field in [
            "controller",
            "settling_time_s",
            "settled",
            "not_settled_reason",
            "overshoot_pct",
            "rise_time_s",
            "steady_state_error_deg",
            "max_elevator_deg",
            "elevator_saturation_s",
        ] {
            assert!(c.get(field).is_some(), "{name} lacks {field}: {c}");
        }
        // A settled response has a time and no reason; an unsettled one the reverse.
        let settled = c["settled"].as_bool().unwrap();
        assert_eq!(c["settling_time_s"].is_number(), settled, "{c}");
        assert_eq!(c["not_settled_reason"].is_string(), !settled, "{c}");
        // The actuator stops at −25°/+10°; a 2° step saturates it briefly (≈ 0.1 s).
        let peak = c["max_elevator_deg"].as_f64().unwrap();
        assert!(peak > 8.17 && peak <= 25.0 + 1e-9, "{name}: {peak}");
        let saturated = c["elevator_saturation_s"].as_f64().unwrap();
        assert!((0.0..1.0).contains(&saturated), "{name}: {saturated}");
    }

    // 4 s recorded every 2 ms, both ends included: 2001 rows; 1 + 2 × 6 columns.
    let mut reader = csv::Reader::from_path(out.join("step.csv")).unwrap();
    let headers = reader.headers().unwrap().clone();
    assert_eq!(headers.len(), 13, "{headers:?}");
    assert_eq!(&headers[0], "time_s");
    for prefix in ["opd", "pid"] {
        for column in [
            "theta_deg",
            "theta_ref_deg",
            "theta_measured_deg",
            "elevator_deg",
            "elevator_command_deg",
            "disturbance_estimate_radps2",
        ] {
            let name = format!("{prefix}_{column}");
            assert!(headers.iter().any(|h| h == name), "missing column {name}");
        }
    }
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.unwrap()).collect();
    assert_eq!(rows.len(), 2001);
    let value = |row: &csv::StringRecord, column: &str| -> f64 {
        let index = headers.iter().position(|h| h == column).unwrap();
        row[index].parse().unwrap()
    };
    assert_eq!(value(&rows[0], "time_s"), 0.0);
    assert!((value(&rows[2000], "time_s") - 4.0).abs() < 1e-9);
    // The reference steps by 2° at 1 s.
    let step = value(&rows[2000], "opd_theta_ref_deg") - value(&rows[0], "opd_theta_ref_deg");
    assert!((step - 2.0).abs() < 1e-9, "{step}");
    // The PID has no disturbance estimate: empty fields.
    let pid_estimate = headers
        .iter()
        .position(|h| h == "pid_disturbance_estimate_radps2")
        .unwrap();
    assert!(rows.iter().all(|r| r[pid_estimate].is_empty()));

    for stem in ["step_pitch", "step_elevator"] {
        let png = fs::metadata(out.join(format!("{stem}.png"))).unwrap();
        assert!(png.len() > 20_000, "{stem}.png is {} bytes", png.len());
        let svg = fs::read_to_string(out.join(format!("{stem}.svg"))).unwrap();
        assert!(svg.len() > 20_000 && svg.contains("<svg"), "{stem}.svg");
        assert!(svg.contains("time (s)"), "{stem}.svg has no axis label");
    }
    let _ = fs::remove_dir_all(&out);
}

/// Measured (ideal, 2° step, seed 1, ε = 0.03): O-PD settles to ±2 % in 1.150 s after the
/// step with 0.4 % overshoot; the PID in 3.140 s with 15.7 % overshoot.
#[test]
fn opd_settles_within_two_seconds_in_ideal_conditions() {
    let out = scratch("settles");
    let result = run_step(&out, &["--controller", "both", "--json"]);
    let report = succeeded_json(&result);
    let opd = controller(&report, "O-PD");
    assert_eq!(opd["settled"], true, "{opd}");
    let settling = opd["settling_time_s"].as_f64().unwrap();
    assert!(settling > 0.5 && settling < 2.0, "{settling}");
    let overshoot = opd["overshoot_pct"].as_f64().unwrap();
    assert!(overshoot < 10.0, "{overshoot}");
    // The paper's claim that the O-PD settles faster than the PID holds here.
    let pid = controller(&report, "PID");
    let pid_settling = pid["settling_time_s"].as_f64().unwrap();
    assert!(
        settling < pid_settling,
        "O-PD {settling} s, PID {pid_settling} s"
    );
    let _ = fs::remove_dir_all(&out);
}

fn assert_clear_error(extra: &[&str], option: &str) {
    let out = scratch(&format!("error{}", option.trim_start_matches('-')));
    let result = run_step(&out, extra);
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(!result.status.success(), "{extra:?} was accepted");
    assert_eq!(result.status.code(), Some(1), "{extra:?}: {stderr}");
    assert!(stderr.contains(option), "{extra:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{extra:?}: {stderr}");
    // Nothing is written for a rejected option.
    assert!(!out.exists(), "{extra:?} created {}", out.display());
}

#[test]
fn invalid_options_give_clear_errors() {
    assert_clear_error(&["--step-deg", "50"], "--step-deg");
    assert_clear_error(&["--step-deg", "0"], "--step-deg");
    assert_clear_error(&["--seconds", "0"], "--seconds");
    assert_clear_error(&["--seconds", "NaN"], "--seconds");
    assert_clear_error(&["--seconds", "-3"], "--seconds");
    assert_clear_error(&["--epsilon", "1.5"], "--epsilon");
}

fn run_step(out: &Path, extra: &[&str]) -> Output {
    let mut args: Vec<&OsStr> = vec![OsStr::new("step"), OsStr::new("--out"), out.as_os_str()];
    args.extend(extra.iter().map(OsStr::new));
    deckland(args)
}
