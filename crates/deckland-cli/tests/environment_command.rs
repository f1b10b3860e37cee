//! Runs `deckland environment` end to end and checks what it writes.

mod common;

use common::{assert_success, deckland, scratch};
use std::ffi::OsStr;
use std::fs;
use std::path::Path;
use std::process::{Command, Output};

#[test]
fn environment_command_writes_csv_and_plots() {
    let out = scratch("environment");
    let result = run_environment(&out, &[]);
    assert_success(&result);
    let stdout = String::from_utf8_lossy(&result.stdout);
    assert!(
        stdout.contains("heave") && stdout.contains("RMS"),
        "{stdout}"
    );

    // 5 s recorded every 10 ms, both ends included: 501 rows.
    let mut reader = csv::Reader::from_path(out.join("environment.csv")).expect("CSV exists");
    let headers = reader.headers().expect("header").clone();
    for column in [
        "time_s",
        "heave_m",
        "pitch_deg",
        "landing_point_height_m",
        "wind_x_mps",
        "wind_z_mps",
        "turbulence_x_mps",
        "steady_wake_x_mps",
        "periodic_wake_x_mps",
    ] {
        assert!(
            headers.iter().any(|h| h == column),
            "missing column {column}"
        );
    }
    let rows: Vec<csv::StringRecord> = reader.records().map(|r| r.expect("valid row")).collect();
    assert_eq!(rows.len(), 501);
    let time = |row: &csv::StringRecord| -> f64 { row[0].parse().expect("number") };
    assert_eq!(time(&rows[0]), 0.0);
    assert!((time(&rows[500]) - 5.0).abs() < 1e-9);
    for row in &rows {
        for field in row.iter() {
            let value: f64 = field.parse().expect("numeric field");
            assert!(value.is_finite());
        }
    }
    // Steady wake at the default 400 m aft: u2 = 0.002·400 = 0.8 m/s (paper Eq. 21).
    let steady = headers
        .iter()
        .position(|h| h == "steady_wake_x_mps")
        .expect("column");
    assert_eq!(rows[0][steady].parse::<f64>().expect("number"), 0.8);

    for stem in [
        "landing_point_motion",
        "wind_x",
        "ship_motion",
        "wind_components",
    ] {
        let png = fs::read(out.join(format!("{stem}.png"))).expect("PNG exists");
        assert!(
            png.starts_with(b"\x89PNG\r\n\x1a\n"),
            "{stem}.png is not a PNG"
        );
        assert!(png.len() > 10_000, "{stem}.png is only {} bytes", png.len());
        let svg = fs::read_to_string(out.join(format!("{stem}.svg"))).expect("SVG exists");
        assert!(
            svg.contains("<svg") && svg.contains("time (s)"),
            "{stem}.svg lacks its axes"
        );
        assert!(svg.len() > 10_000, "{stem}.svg is only {} bytes", svg.len());
    }
    let partial = fs::read_dir(&out)
        .expect("folder")
        .filter_map(Result::ok)
        .any(|e| e.file_name().to_string_lossy().starts_with(".partial"));
    assert!(!partial, "a temporary file was left behind");
    let _ = fs::remove_dir_all(&out);
}

#[test]
fn environment_command_refuses_a_used_folder_unless_forced() {
    let out = scratch("refuse");
    assert!(run_environment(&out, &[]).status.success());
    let refused = run_environment(&out, &[]);
    assert!(!refused.status.success());
    assert!(String::from_utf8_lossy(&refused.stderr).contains("--force"));
    assert!(run_environment(&out, &["--force"]).status.success());
    let _ = fs::remove_dir_all(&out);
}

#[test]
fn environment_command_rejects_bad_arguments() {
    let out = scratch("bad");
    let result = Command::new(env!("CARGO_BIN_EXE_deckland"))
        .args(["environment", "--seconds=-1", "--out"])
        .arg(&out)
        .output()
        .expect("the deckland binary runs");
    assert!(!result.status.success());
    assert!(String::from_utf8_lossy(&result.stderr).contains("--seconds"));
    let _ = fs::remove_dir_all(&out);
}

fn run_environment(out: &Path, extra: &[&str]) -> Output {
    let mut args: Vec<&OsStr> = ["environment", "--seconds", "5", "--out"]
        .iter()
        .map(OsStr::new)
        .collect();
    args.push(out.as_os_str());
    args.extend(extra.iter().map(OsStr::new));
    deckland(args)
}
