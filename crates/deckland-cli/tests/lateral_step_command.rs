//! Runs `deckland step --axis roll|yaw` end to end: the JSON document, the CSV and the
//! plots of a 10° bank step, and the errors for a bad axis and a bad step.
#![allow(clippy::unwrap_used)]

mod common;

use common::{deckland, scratch, succeeded_json, ROLL_STEP};

#[test]
fn a_roll_step_writes_json_csv_and_plots() {
    let out = scratch("lateral");
    let out_text = out.to_str().unwrap();
    let result = deckland(
        [
            &ROLL_STEP[..],
            &["--seconds", "5", "--json", "--out", out_text, "--force"],
        ]
        .concat(),
    );
    let report = succeeded_json(&result);
    assert_eq!(report["axis"], "roll");
    assert_eq!(report["step_deg"], 10.0);
    assert_eq!(report["settling_band_pct"], 5.0);
    assert_eq!(report["aileron_rate_limit_degps"], 100.0);
    let controllers = report["controllers"].as_array().unwrap();
    assert_eq!(controllers.len(), 2);
    let opd = controllers
        .iter()
        .find(|c| c["controller"] == "O-PD")
        .unwrap();
    assert_eq!(opd["settled"], true, "{opd}");
    assert!(opd["settling_time_s"].as_f64().unwrap() <= 2.0, "{opd}");
    for file in [
        "step.csv",
        "step_bank.png",
        "step_bank.svg",
        "step_surfaces.png",
        "step_surfaces.svg",
    ] {
        assert!(out.join(file).is_file(), "{file} missing");
    }
    let csv = std::fs::read_to_string(out.join("step.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    assert!(
        header.starts_with("time_s,opd_bank_deg,opd_bank_command_deg,opd_sideslip_deg"),
        "{header}"
    );
    assert!(header.contains("pid_aileron_rate_degps"), "{header}");
    // 5 s every 2 ms, and the header.
    assert_eq!(csv.lines().count(), 2502);
    let _ = std::fs::remove_dir_all(&out);
}

#[test]
fn a_bad_axis_is_refused_with_the_choices() {
    let result = deckland(["step", "--axis", "bank"]);
    assert!(!result.status.success());
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(
        stderr.contains("invalid value 'bank' for '--axis <AXIS>'")
            && stderr.contains("pitch, roll, yaw"),
        "{stderr}"
    );
}

#[test]
fn a_lateral_step_out_of_range_is_refused_by_name() {
    let result = deckland(["step", "--axis", "yaw", "--step-deg", "40"]);
    assert!(!result.status.success());
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(
        stderr.contains("--step-deg") && stderr.contains("yaw") && stderr.contains("40"),
        "{stderr}"
    );
    let result = deckland([&ROLL_STEP[..], &["--epsilon", "0.1"]].concat());
    assert!(!result.status.success());
    assert!(String::from_utf8_lossy(&result.stderr).contains("--epsilon"));
}

/// The settling time of the PID's 10° bank step with `extra` arguments, and the report.
fn pid_bank_step(extra: &[&str]) -> (f64, serde_json::Value) {
    let out = scratch("lateral-scenario");
    let mut arguments = vec![
        "step",
        "--axis",
        "roll",
        "--controller",
        "pid",
        "--step-deg",
        "10",
        "--seconds",
        "8",
        "--json",
        "--force",
        "--out",
        out.to_str().unwrap(),
    ];
    arguments.extend_from_slice(extra);
    let result = deckland(arguments);
    let report = succeeded_json(&result);
    let _ = std::fs::remove_dir_all(&out);
    let settling = report["controllers"][0]["settling_time_s"]
        .as_f64()
        .unwrap();
    (settling, report)
}

/// A scenario file's roll law and lateral actuators fly the step: a PID tuned for
/// ω_n = 2 rad/s (K_P = ω_n², K_D = 2ζω_n + L_p with ζ = 1, L_p = −1.16 /s) settles
/// about twice as slowly as the registered one (ω_n = 4 rad/s), and the file's aileron
/// rate limit is the one reported.
#[test]
fn a_scenario_files_roll_law_and_actuators_fly_the_step() {
    let (designed, report) = pid_bank_step(&[]);
    assert_eq!(report["aileron_rate_limit_degps"], 100.0);
    let folder = scratch("lateral-scenario-file");
    std::fs::create_dir_all(&folder).unwrap();
    let file = folder.join("slow-roll.toml");
    std::fs::write(
        &file,
        "[aircraft.aileron_actuator]\nnatural_frequency_rad_s = 30.74\ndamping_ratio = 0.509\n\
         travel_deg = 25.0\nrate_limit_degps = 60.0\n\n\
         [control.roll]\ntype = \"pid\"\nproportional_per_s2 = 4.0\nintegral_per_s3 = 0.0\n\
         derivative_per_s = 2.84\n",
    )
    .unwrap();
    let (slow, report) = pid_bank_step(&["--scenario", file.to_str().unwrap()]);
    assert_eq!(report["aileron_rate_limit_degps"], 60.0);
    assert!(
        slow > 1.5 * designed,
        "the file's slower PID settles in {slow} s, the designed one in {designed} s"
    );
    let _ = std::fs::remove_dir_all(&folder);
}

#[test]
fn a_lateral_step_refuses_the_paper_set_and_names_a_bad_lateral_key() {
    let result = deckland([&ROLL_STEP[..], &["--hardware", "paper"]].concat());
    assert!(!result.status.success());
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(
        stderr.contains("--hardware paper") && stderr.contains("roll"),
        "{stderr}"
    );
    let folder = scratch("lateral-bad-key");
    std::fs::create_dir_all(&folder).unwrap();
    let file = folder.join("bad.toml");
    std::fs::write(&file, "[control.yaw.observer]\nepsilon = 0.0\n").unwrap();
    let result = deckland([
        "step",
        "--axis",
        "yaw",
        "--step-deg",
        "2",
        "--scenario",
        file.to_str().unwrap(),
    ]);
    assert!(!result.status.success());
    let stderr = String::from_utf8_lossy(&result.stderr);
    assert!(
        stderr.contains("line 2") && stderr.contains("control.yaw.observer.epsilon"),
        "{stderr}"
    );
    let _ = std::fs::remove_dir_all(&folder);
}
