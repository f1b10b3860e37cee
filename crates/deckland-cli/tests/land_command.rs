//! `deckland land` and `deckland sink`: output files, JSON contract, refusal to overwrite.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{assert_success, deckland, file_size, scratch, succeeded_json, summary_json};
use serde_json::Value;

#[test]
fn land_writes_every_result_and_prints_the_json_summary() {
    let dir = scratch("land");
    let out = dir.to_str().unwrap();
    let output = deckland(["land", "--conditions", "ideal", "--out", out, "--json"]);
    let v = succeeded_json(&output);
    assert_eq!(v["outcome"], "trap");
    assert_eq!(v["wire"], 3);
    for field in [
        "time_s",
        "distance_from_aim_m",
        "sink_rate_mps",
        "pitch_deg",
        "airspeed_mps",
    ] {
        assert!(v["touchdown"][field].is_number(), "touchdown.{field}");
    }
    for field in [
        "ramp_clearance_m",
        "glide_path_error_rms_m",
        "glide_path_error_max_m",
    ] {
        assert!(v[field].is_number(), "{field}");
    }
    let summary = summary_json(&dir);
    assert_eq!(summary, v);
    let csv = std::fs::read_to_string(dir.join("approach.csv")).unwrap();
    let header = csv.lines().next().unwrap();
    for column in [
        "time_s",
        "hook_height_m",
        "glide_path_error_m",
        "theta_deg",
        "elevator_deg",
    ] {
        assert!(header.split(',').any(|c| c == column), "column {column}");
    }
    // The default is the 3-D approach: in still air the deck moves away at the ship's
    // 7.7 m/s, 9° off the final bearing, so the hook closes the 1500 m at
    // 69.1·cos 3.5° − 7.7·cos 9° = 61.4 m/s: about 24.4 s at one row per 10 ms.
    let rows = csv.lines().count() - 1;
    assert!((2300..2600).contains(&rows), "{rows} rows");
    let scenario = std::fs::read_to_string(dir.join("scenario.toml")).unwrap();
    assert!(scenario.contains("seed = 1") && scenario.contains("[control.guidance]"));
    assert_trap_sheet(&dir.join("trap_sheet.csv"), &v);
    for stem in [
        "altitude",
        "glide_path_error",
        "pitch",
        "controls",
        "airspeed",
        "wind",
        "plan_view",
        "cross_track",
    ] {
        assert!(
            file_size(&dir.join(format!("{stem}.png"))) > 10_000,
            "{stem}.png"
        );
        assert!(
            file_size(&dir.join(format!("{stem}.svg"))) > 10_000,
            "{stem}.svg"
        );
    }
    let leftovers: Vec<_> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .filter(|e| e.file_name().to_string_lossy().starts_with(".partial-"))
        .collect();
    assert!(leftovers.is_empty());

    // A second run into the same folder is refused without --force, allowed with it.
    let again = deckland(["land", "--conditions", "ideal", "--out", out]);
    assert!(!again.status.success());
    assert!(String::from_utf8_lossy(&again.stderr).contains("--force"));
    let forced = deckland(["land", "--conditions", "ideal", "--out", out, "--force"]);
    assert!(forced.status.success());
    let text = String::from_utf8(forced.stdout).unwrap();
    assert!(text.contains("trap (wire 3)"), "{text}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_six_dof_run_draws_the_plan_view_and_the_cross_track_plot() {
    let dir = scratch("run-6dof-lineup");
    let scenario = dir.with_extension("toml");
    std::fs::write(&scenario, "[aircraft]\nmodel = \"6dof\"\n").unwrap();
    let output = deckland([
        "run",
        scenario.to_str().unwrap(),
        "--seed",
        "1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_success(&output);
    for (stem, text) in [
        ("plan_view", "landing centreline abeam the hook"),
        ("cross_track", "offset from the landing area"),
    ] {
        let svg = std::fs::read_to_string(dir.join(format!("{stem}.svg"))).unwrap();
        assert!(svg.contains(text), "{stem}.svg lacks {text:?}");
        assert!(
            file_size(&dir.join(format!("{stem}.png"))) > 10_000,
            "{stem}.png"
        );
    }
    std::fs::remove_dir_all(&dir).unwrap();
    std::fs::remove_file(&scenario).unwrap();
}

#[test]
fn land_adverse_pid_runs_and_reports_an_outcome() {
    let dir = scratch("land-pid");
    let output = deckland([
        "land",
        "--controller",
        "pid",
        "--seed",
        "3",
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    let v = succeeded_json(&output);
    assert_eq!(v["controller"], "PID");
    assert_eq!(v["seed"], 3);
    assert!(v["outcome"].is_string());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn sink_tracks_a_ramped_command_and_reports_the_paper_step_as_diverged() {
    let dir = scratch("sink");
    let out = dir.to_str().unwrap();
    let output = deckland([
        "sink",
        "--sink-rate",
        "5",
        "--seconds",
        "25",
        "--out",
        out,
        "--json",
    ]);
    let v = succeeded_json(&output);
    assert_eq!(v["outcome"], "completed");
    assert_eq!(v["metrics"]["settled"], true);
    assert!(v["metrics"]["steady_state_error"].as_f64().unwrap().abs() < 0.1);
    assert!(file_size(&dir.join("sink_rate.png")) > 10_000);
    // The paper's 10 m/s step without shaping drives α out of the model's range.
    let step = deckland(["sink", "--ramp-s", "0", "--out", out, "--force", "--json"]);
    let v = succeeded_json(&step);
    assert_eq!(v["outcome"], "diverged");
    assert!(v["reason"].as_str().unwrap().contains("angle of attack"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// `trap_sheet.csv` holds a row every 0.5 s of the pass before the ramp, each in its
/// LSO window (blank beyond ¾ nmi), with the pass's grade as summary.json has it.
fn assert_trap_sheet(path: &std::path::Path, summary: &Value) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|c| *c == name).unwrap();
    let (time, range, window, grade) = (
        column("time_s"),
        column("range_to_ramp_m"),
        column("window"),
        column("grade"),
    );
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    // The 1440 m to the ramp at 61.4 m/s: about 23.5 s, 48 rows.
    assert!((44..52).contains(&rows.len()), "{} rows", rows.len());
    for pair in rows.windows(2) {
        let dt: f64 = pair[1][time].parse::<f64>().unwrap() - pair[0][time].parse::<f64>().unwrap();
        assert!((dt - 0.5).abs() < 1e-6, "{dt}");
    }
    for row in &rows {
        let d: f64 = row[range].parse().unwrap();
        let expected = match d {
            d if d > 1389.0 => "",
            d if d > 926.0 => "X",
            d if d > 463.0 => "IM",
            d if d > 185.2 => "IC",
            _ => "AR",
        };
        assert_eq!(row[window], expected, "{d} m");
        assert_eq!(row[grade], summary["lso_grade"]["grade"].as_str().unwrap());
        assert!(row
            .iter()
            .all(|cell| !cell.contains("NaN") && !cell.contains("inf")));
    }
}
