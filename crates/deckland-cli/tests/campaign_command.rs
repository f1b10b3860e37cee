//! `deckland scenario`, `run` and `campaign`: files written, thread-count independence,
//! bad scenario files reported by file, line and field.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{
    assert_success, deckland, endless_campaign, scratch, short_dispersed_scenario, signal_after,
    succeeded_json, summary_json,
};
use deckland::monte_carlo::{LSO_RUN_COLUMNS, RUN_COLUMNS};
use serde_json::Value;
use std::path::PathBuf;

fn scenario(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../scenarios")
        .join(name)
        .display()
        .to_string()
}

#[test]
fn one_and_two_threads_write_byte_identical_runs_csv() {
    let dir = scratch("campaign-threads");
    let file = short_dispersed_scenario(&dir);
    let mut csv = Vec::new();
    for threads in ["1", "2"] {
        let out = dir.join(format!("threads-{threads}"));
        let output = deckland([
            "campaign",
            &file,
            "--runs",
            "20",
            "--seed",
            "42",
            "--threads",
            threads,
            "--out",
            out.to_str().unwrap(),
            "--json",
        ]);
        assert_success(&output);
        csv.push(std::fs::read(out.join("runs.csv")).unwrap());
        let summary: Value = serde_json::from_slice(&output.stdout).unwrap();
        assert_eq!(summary["partial"], false);
        assert_eq!(summary["finished_runs"], 20);
        // A 3-DOF campaign has neither lateral nor trap-sheet columns or statistics.
        let text = String::from_utf8(csv[csv.len() - 1].clone()).unwrap();
        // (The LSO's grade, the wave-off's criterion, the deck's share within the
        // recovery limits and the commit point's probabilities, the last columns, follow
        // `reason` directly.)
        assert!(text.lines().next().unwrap().ends_with(
            ",reason,lso_grade,lso_points,lso_comment,wave_off_criterion,deck_within_limits_pct,\
             commit_ramp_strike_probability,commit_hard_landing_probability,\
             commit_off_centre_probability,commit_ramp_clearance_m,commit_ramp_clearance_sigma_m"
        ));
        assert!(summary.get("trap_sheet").is_none() && summary.get("lateral").is_none());
        let opd = &summary["controllers"][0];
        assert_eq!(opd["controller"], "O-PD");
        assert_eq!(opd["runs"], 20);
        for rate in [
            "boarding",
            "bolter",
            "ramp_strike",
            "hard_landing",
            "divergence",
            "timeout",
        ] {
            let low = opd[rate]["ci95_low"].as_f64().unwrap();
            let high = opd[rate]["ci95_high"].as_f64().unwrap();
            let value = opd[rate]["rate"].as_f64().unwrap();
            assert!(low <= value && value <= high, "{rate}");
        }
        for field in ["mean", "standard_deviation", "p5", "p50", "p95"] {
            assert!(opd["touchdown_sink_rate_mps"][field].is_number(), "{field}");
            assert!(opd["touchdown_distance_m"][field].is_number(), "{field}");
        }
        for stem in ["touchdown_dispersion", "touchdown_histograms", "outcomes"] {
            for extension in ["png", "svg"] {
                assert!(
                    out.join(format!("{stem}.{extension}")).exists(),
                    "{stem}.{extension}"
                );
            }
        }
        // A 3-DOF campaign has no lineup to plot.
        assert!(!out.join("touchdown_plan.svg").exists());
    }
    assert_eq!(csv[0], csv[1], "runs.csv differs between 1 and 2 threads");
    let text = String::from_utf8(csv[0].clone()).unwrap();
    let header = text.lines().next().unwrap();
    for column in RUN_COLUMNS {
        assert!(header.split(',').any(|c| c == column), "column {column}");
    }
    assert_eq!(text.lines().count(), 21);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn compare_flies_both_controllers_on_the_same_seeds() {
    let dir = scratch("campaign-compare");
    let file = short_dispersed_scenario(&dir);
    let out = dir.join("out");
    let output = deckland([
        "campaign",
        &file,
        "--runs",
        "3",
        "--compare",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_success(&output);
    let table = String::from_utf8_lossy(&output.stdout);
    assert!(
        table.contains("O-PD (3 runs)") && table.contains("PID (3 runs)"),
        "{table}"
    );
    let summary = summary_json(&out);
    assert_eq!(summary["controllers"][1]["controller"], "PID");
    let csv = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let rows: Vec<Vec<&str>> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').collect())
        .collect();
    assert_eq!(rows.len(), 6);
    for pair in rows.chunks(2) {
        assert_eq!((pair[0][1], pair[1][1]), ("O-PD", "PID"));
        assert_eq!(pair[0][2], pair[1][2], "same seed");
    }

    // The paired differences, recomputed from runs.csv: PID − O-PD run by run.
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let touchdown = column("touchdown_distance_m");
    let differences: Vec<f64> = rows
        .chunks(2)
        .filter_map(|pair| {
            let a = pair[0][touchdown].parse::<f64>().ok()?;
            let b = pair[1][touchdown].parse::<f64>().ok()?;
            Some(b - a)
        })
        .collect();
    let mean = differences.iter().sum::<f64>() / differences.len() as f64;
    let line = table
        .lines()
        .find(|l| {
            l.trim_start()
                .starts_with("touchdown from the aim point (m)")
        })
        .unwrap_or_else(|| panic!("no paired touchdown line in:\n{table}"));
    assert!(
        line.contains(&format!("{mean:+.2} ±")),
        "mean paired difference {mean:+.2} not in `{line}`"
    );
    assert!(
        table.contains(&format!(
            "paired differences PID − O-PD, run by run on the same seed: {} pairs",
            3
        )),
        "{table}"
    );

    // Every outcome class has a row, the safe outcomes are totalled, and a quantity
    // with no sign (an RMS, a share of time) prints none.
    for row in [
        "invalid scenario",
        "safe: trap, bolter or wave-off",
        "wave-off (safe)",
    ] {
        assert!(
            table.lines().any(|l| l.trim_start().starts_with(row)),
            "{row}: {table}"
        );
    }
    for unsigned in [
        "touchdown sink rate (m/s): mean ± sd",
        "elevator rate RMS (deg/s): mean ± sd",
        "thrust rate RMS (kN/s): mean ± sd",
    ] {
        let line = table.lines().find(|l| l.contains(unsigned)).unwrap();
        assert!(!line.contains('+'), "a sign on `{line}`");
    }
    assert!(
        table.contains("if 1 event,") && !table.contains("1 events"),
        "{table}"
    );
    let rare = table
        .lines()
        .skip_while(|l| !l.contains("rare failures"))
        .skip(1)
        .take_while(|l| !l.contains("to show p <"))
        .collect::<Vec<_>>()
        .join("\n");
    assert!(
        !rare.contains("wave-off"),
        "a wave-off among the failures: {rare}"
    );

    // report.html holds the same: actuators, paired differences, a rare-events table.
    let page = std::fs::read_to_string(out.join("report.html")).unwrap();
    for part in [
        "Actuators",
        "elevator rate RMS (deg/s)",
        "Paired differences",
        "Rare events",
        "runs with it",
    ] {
        assert!(page.contains(part), "report.html lacks `{part}`");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn print_default_is_a_valid_scenario_file() {
    let output = deckland(["scenario", "--print-default"]);
    assert_success(&output);
    let text = String::from_utf8(output.stdout).unwrap();
    assert!(text.starts_with("# deckland scenario"), "{text}");
    let dir = scratch("print-default");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("default.toml");
    std::fs::write(&path, &text).unwrap();
    // The realistic default is the 3-D approach (issue 27, item 7): the 6-DOF aircraft,
    // the 9° angled deck, the ship at 15 kn = 7.7 m/s.
    assert!(text.contains("\nmodel = \"6dof\""), "{text}");
    assert!(text.contains("\nforward_speed_mps = 7.7 "), "{text}");
    let checked = deckland(["scenario", "--check", path.to_str().unwrap()]);
    assert_success(&checked);
    let said = String::from_utf8(checked.stdout).unwrap();
    assert!(
        said.contains("the 3-D carrier approach (model 6dof, deck angle 9°, ship at 7.7 m/s)"),
        "{said}"
    );
    let _ = std::fs::remove_dir_all(&dir);
    let checked = deckland(["scenario", "--check", &scenario("heavy-sea.toml")]);
    assert_success(&checked);
    let paper = deckland(["scenario", "--check", &scenario("paper-adverse.toml")]);
    assert_success(&paper);
    let said = String::from_utf8(paper.stdout).unwrap();
    assert!(
        said.contains("the longitudinal approach (model 3dof, ship at 0 m/s)"),
        "{said}"
    );
}

#[test]
fn run_flies_a_scenario_file_like_land() {
    let dir = scratch("run");
    let output = deckland([
        "run",
        &scenario("calm.toml"),
        "--out",
        dir.to_str().unwrap(),
        "--json",
    ]);
    let v = succeeded_json(&output);
    assert_eq!(v["outcome"], "trap");
    assert_eq!(v["conditions"], "calm.toml");
    for file in [
        "scenario.toml",
        "approach.csv",
        "summary.json",
        "altitude.png",
    ] {
        assert!(dir.join(file).exists(), "{file}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_bad_scenario_file_is_refused_with_file_line_and_field() {
    let dir = scratch("bad-scenario");
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("bad.toml");
    std::fs::write(&path, "seed = 3\n[environment.ship]\nheave_rms_m = -2.0\n").unwrap();
    for command in ["run", "campaign"] {
        let mut args = vec![command, path.to_str().unwrap()];
        if command == "campaign" {
            args.extend(["--runs", "2"]);
        }
        let output = deckland(&args);
        assert!(!output.status.success());
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(
            stderr.contains("bad.toml, line 3, field `environment.ship.heave_rms_m`")
                && stderr.contains("[0, 50]"),
            "{stderr}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Ctrl-C (SIGINT) stops the workers; the finished runs are written, sorted by index,
/// marked partial, and the command exits with status 130.
#[cfg(unix)]
#[test]
fn an_interrupted_campaign_keeps_a_consistent_partial_result() {
    let dir = scratch("campaign-interrupt");
    let out = dir.join("out");
    let child = endless_campaign(&scenario("paper-adverse.toml"), &out)
        .arg("--json")
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    let output = signal_after(child, "INT", 1500);
    assert_eq!(
        output.status.code(),
        Some(130),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let summary = summary_json(&out);
    assert_eq!(summary["partial"], true);
    let finished = summary["finished_runs"].as_u64().unwrap();
    assert!(finished < 100_000);
    assert_eq!(summary["controllers"][0]["runs"].as_u64(), Some(finished));
    let csv = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let indices: Vec<u64> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(indices.len() as u64, finished);
    assert!(
        indices.windows(2).all(|w| w[0] < w[1]),
        "sorted by run index"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// `run --seed S --disperse` with a campaign row's seed re-flies exactly that run.
#[test]
fn run_with_a_campaign_seed_and_disperse_reproduces_the_campaign_row() {
    let dir = scratch("campaign-reproduce");
    let file = short_dispersed_scenario(&dir);
    let out = dir.join("campaign");
    assert_success(&deckland([
        "campaign",
        &file,
        "--runs",
        "3",
        "--seed",
        "9",
        "--out",
        out.to_str().unwrap(),
        "--json",
    ]));
    let csv = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let header: Vec<&str> = csv.lines().next().unwrap().split(',').collect();
    let column = |name: &str| header.iter().position(|c| *c == name).unwrap();
    let row: Vec<&str> = csv.lines().nth(2).unwrap().split(',').collect();
    let single = dir.join("single");
    let output = deckland([
        "run",
        &file,
        "--seed",
        row[column("seed")],
        "--disperse",
        "--out",
        single.to_str().unwrap(),
        "--json",
    ]);
    let v = succeeded_json(&output);
    assert_eq!(v["outcome"], row[column("outcome")]);
    let expected: f64 = row[column("glide_path_error_rms_m")].parse().unwrap();
    assert_eq!(v["glide_path_error_rms_m"].as_f64(), Some(expected));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_three_d_campaign_adds_the_lateral_columns_and_the_touchdown_plan() {
    let dir = scratch("campaign-3d");
    let out = dir.join("crosswind");
    let output = deckland([
        "campaign",
        &scenario("crosswind.toml"),
        "--runs",
        "4",
        "--seed",
        "5",
        "--threads",
        "2",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_success(&output);
    let text = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let header = text.lines().next().unwrap();
    for column in [
        "touchdown_lateral_offset_m",
        "ramp_lineup_error_deg",
        "off_centre",
    ] {
        assert!(header.split(',').any(|c| c == column), "column {column}");
    }
    let svg = std::fs::read_to_string(out.join("touchdown_plan.svg")).unwrap();
    assert!(svg.contains("off-centre limit"), "touchdown_plan.svg");
    assert!(out.join("touchdown_plan.png").exists());
    let html = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(html.contains("Lineup (3-D approach)"), "report.html");
    assert!(
        html.contains("LSO trap sheet (3-D approach)"),
        "report.html"
    );
    assert!(
        String::from_utf8_lossy(&output.stdout).contains("LSO trap sheet"),
        "the printed statistics"
    );
    // The trap sheet's columns, every value finite, and its statistics in summary.json
    // those of the columns, recomputed here from runs.csv.
    common::assert_finite_csv(&text);
    let mut reader = csv::Reader::from_path(out.join("runs.csv")).unwrap();
    let columns: Vec<String> = reader
        .headers()
        .unwrap()
        .iter()
        .map(str::to_owned)
        .collect();
    let records: Vec<csv::StringRecord> = reader.records().map(Result::unwrap).collect();
    let summary: serde_json::Value =
        serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
    let positions = summary["trap_sheet"]["positions"].as_array().unwrap();
    let names: Vec<&str> = positions
        .iter()
        .map(|p| p["shorthand"].as_str().unwrap())
        .collect();
    assert_eq!(names, ["X", "IM", "IC", "AR"]);
    for (position, stem) in positions.iter().zip(["x", "im", "ic", "ar"]) {
        for deviation in ["glide_slope_mean_m", "lineup_peak_deg"] {
            let column = format!("trap_{stem}_{deviation}");
            let index = columns.iter().position(|c| *c == column).unwrap();
            let values: Vec<f64> = records
                .iter()
                .filter(|r| !r[index].is_empty())
                .map(|r| r[index].parse().unwrap())
                .collect();
            let n = values.len() as f64;
            let mean = values.iter().sum::<f64>() / n;
            let sd = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
            let statistics = &position[deviation];
            assert_eq!(statistics["count"], values.len(), "{column}");
            assert!(
                (statistics["mean"].as_f64().unwrap() - mean).abs() < 1e-12,
                "{column}"
            );
            let half = 1.959_964 * sd / n.sqrt();
            let low = statistics["mean_ci95_low"].as_f64().unwrap();
            assert!((low - (mean - half)).abs() < 1e-6, "{column}: {low}");
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 44, items 2 and 3: a campaign of the default scenario grades every pass in
/// `runs.csv` (the LSO's three columns near the end) and prints the greenie board; issue
/// 42, item 5: a column near the end is each run's share of time with the deck within
/// the recovery limits, whose mean and least the summary and the terminal give; issue
/// 45, item 1: the last three the probabilities the forecast gave at the commit point,
/// which the summary, the terminal and the page hold against the outcomes.
#[test]
fn a_default_campaign_grades_every_pass_and_prints_the_greenie_board() {
    let dir = scratch("campaign-greenie");
    std::fs::create_dir_all(&dir).unwrap();
    let default = deckland(["scenario", "--print-default"]);
    assert_success(&default);
    let file = dir.join("default.toml");
    std::fs::write(&file, &default.stdout).unwrap();
    let out = dir.join("out");
    let output = deckland([
        "campaign",
        file.to_str().unwrap(),
        "--runs",
        "6",
        "--seed",
        "3",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_success(&output);
    let printed = String::from_utf8(output.stdout).unwrap();
    for line in [
        "greenie board (LSO grades)",
        "OK ok",
        "(OK) fair",
        "B bolter",
        "-- no grade",
        "OWO own wave off",
        "C cut",
        "mean points (of 4)",
        "target wire",
        "top deviations, ",
    ] {
        assert!(printed.contains(line), "no `{line}` in:\n{printed}");
    }
    let text = std::fs::read_to_string(out.join("runs.csv")).unwrap();
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header: Vec<String> = reader.headers().unwrap().iter().map(String::from).collect();
    let n = header.len();
    assert_eq!(
        header[n - LSO_RUN_COLUMNS.len()..],
        LSO_RUN_COLUMNS,
        "{header:?}"
    );
    let grades = ["ok", "fair", "bolter", "no_grade", "own_wave_off", "cut"];
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (grade, points, share, criterion) = (
        column("lso_grade"),
        column("lso_points"),
        column("deck_within_limits_pct"),
        column("wave_off_criterion"),
    );
    let mut rows = 0;
    let mut deck_shares = Vec::new();
    let mut records = Vec::new();
    for record in reader.records() {
        let record = record.unwrap();
        rows += 1;
        assert!(grades.contains(&&record[grade]), "{record:?}");
        let points: f64 = record[points].parse().unwrap();
        assert!((0.0..=4.0).contains(&points), "{record:?}");
        let share: f64 = record[share].parse().unwrap();
        assert!((0.0..=100.0).contains(&share), "{record:?}");
        deck_shares.push(share);
        // The wave-off's criterion: the name the reason gives, else empty.
        let criterion = &record[criterion];
        let reason = &record[header.iter().position(|h| h == "reason").unwrap()];
        assert_eq!(
            criterion.is_empty(),
            !reason.contains("wave-off at t = "),
            "{record:?}"
        );
        assert!(criterion.is_empty() || reason.contains(&format!(" on {criterion}:")));
        records.push(record);
    }
    assert_eq!(rows, 6);
    let summary = summary_json(&out);
    let board = &summary["controllers"][0]["greenie_board"];
    assert_eq!(board["graded"], 6, "{board}");
    assert_eq!(board["target_wire"], 3, "{board}");
    // The deck's share: its mean and least over the rows, in summary.json and printed.
    let deck = &summary["controllers"][0]["deck_within_limits_pct"];
    let mean = deck_shares.iter().sum::<f64>() / deck_shares.len() as f64;
    let least = deck_shares.iter().copied().fold(f64::INFINITY, f64::min);
    assert!(
        (deck["mean"].as_f64().unwrap() - mean).abs() < 1e-9,
        "{deck}"
    );
    assert_eq!(deck["min"].as_f64().unwrap(), least, "{deck}");
    assert_eq!(deck["count"], 6, "{deck}");
    let line =
        format!("deck within the recovery limits: mean {mean:.1} % of the time (min {least:.1} %)");
    assert!(printed.contains(&line), "no `{line}` in:\n{printed}");
    // The ramp-strike margin: the hook's height over the ramp, summarised over the rows
    // that crossed it, in summary.json and on the terminal.
    let ramp_column = header.iter().position(|h| h == "ramp_clearance_m").unwrap();
    let clearances: Vec<f64> = records
        .iter()
        .filter_map(|r| r[ramp_column].parse().ok())
        .collect();
    let ramp = &summary["controllers"][0]["ramp_clearance_m"];
    assert_eq!(ramp["count"], clearances.len(), "{ramp}");
    let ramp_mean = clearances.iter().sum::<f64>() / clearances.len() as f64;
    assert!(
        (ramp["mean"].as_f64().unwrap() - ramp_mean).abs() < 1e-9,
        "{ramp}"
    );
    let least = clearances.iter().copied().fold(f64::INFINITY, f64::min);
    assert_eq!(ramp["min"].as_f64().unwrap(), least, "{ramp}");
    assert!(
        printed.contains("hook over the ramp (m): mean ± sd"),
        "{printed}"
    );
    let report = std::fs::read_to_string(out.join("report.html")).unwrap();
    assert!(report.contains("hook over the ramp (m, the ramp-strike margin)"));
    let board_at = report.find("<table class=\"greenie\">").expect("the board");
    let chart_at = report.find("<figure").expect("the outcome chart");
    assert!(board_at < chart_at, "the board is above the outcome chart");
    assert!(report.contains("background:#3c9a3c"), "OK in green");
    check_calibration(&header, &records, &summary["controllers"][0], &printed);
    assert!(
        report.contains("Calibration at the commit point"),
        "no calibration section"
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// Issue 45, item 1: the commit point's probabilities of the rows of a 3-D campaign
/// (`records`, with their `header`) in [0, 1], the ramp strike's, the hard landing's and
/// the off-centre one together or none; the controller's `calibration` in `summary.json`
/// counts the rows that have them, sums their probabilities and counts their outcomes,
/// and the terminal (`printed`) gives each criterion's line.
fn check_calibration(
    header: &[String],
    records: &[csv::StringRecord],
    statistics: &Value,
    printed: &str,
) {
    let column = |name: &str| header.iter().position(|h| h == name).unwrap();
    let (outcome, off_centre) = (column("outcome"), column("off_centre"));
    let first = column("commit_ramp_strike_probability");
    let mut sums = [0.0; 3];
    let mut events = [0_u64; 3];
    let mut reached = 0;
    let mut z = Vec::new();
    for record in records {
        let p: Vec<Option<f64>> = (first..first + 3).map(|i| record[i].parse().ok()).collect();
        // The clearance the ramp strike's is taken on, its σ and the clearance flown.
        let [c, sigma, flown]: [Option<f64>; 3] = [
            "commit_ramp_clearance_m",
            "commit_ramp_clearance_sigma_m",
            "ramp_clearance_m",
        ]
        .map(|name| record[column(name)].parse().ok());
        assert_eq!(c.is_some(), p[0].is_some(), "{record:?}");
        assert_eq!(sigma.is_some(), p[0].is_some(), "{record:?}");
        if let (Some(c), Some(sigma), Some(flown)) = (c, sigma, flown) {
            z.push((flown - c) / sigma);
        }
        let reached_it = p[0].is_some();
        assert!(p.iter().all(|q| q.is_some() == reached_it), "{record:?}");
        if !reached_it {
            continue;
        }
        reached += 1;
        let happened = [
            &record[outcome] == "ramp_strike",
            &record[outcome] == "hard_landing",
            &record[off_centre] == "true",
        ];
        for k in 0..3 {
            let p = p[k].unwrap();
            assert!((0.0..=1.0).contains(&p), "{record:?}");
            sums[k] += p;
            events[k] += u64::from(happened[k]);
        }
    }
    let calibration = &statistics["calibration"];
    assert_eq!(calibration["runs_at_commit"], reached, "{calibration}");
    assert!(reached > 0, "no run reached the commit point");
    for (k, key) in ["ramp_strike", "hard_landing", "off_centre"]
        .iter()
        .enumerate()
    {
        let criterion = &calibration[key];
        assert_eq!(criterion["runs"], reached, "{criterion}");
        let expected = criterion["expected_events"].as_f64().unwrap();
        assert!(
            (expected - sums[k]).abs() <= 1e-12 * (1.0 + sums[k]),
            "{criterion}"
        );
        assert_eq!(criterion["observed_events"], events[k], "{criterion}");
        let (low, high) = (
            &criterion["interval_95"]["low"],
            &criterion["interval_95"]["high"],
        );
        let within = (low.as_u64().unwrap()..=high.as_u64().unwrap()).contains(&events[k]);
        assert_eq!(criterion["calibrated"], within, "{criterion}");
        assert_eq!(
            criterion["bins"].as_array().unwrap().len(),
            7,
            "{criterion}"
        );
    }
    // The terminal's line of each criterion, its expected count as the CLI writes it
    // (one decimal from 0.1, else in powers of ten).
    for (key, name) in [
        ("ramp_strike", "ramp strike"),
        ("hard_landing", "hard landing"),
        ("off_centre", "off-centre touchdown"),
    ] {
        let criterion = &calibration[key];
        let expected = criterion["expected_events"].as_f64().unwrap();
        let expected = if expected == 0.0 {
            "0".to_owned()
        } else if expected >= 0.095 {
            format!("{expected:.1}")
        } else {
            format!("{expected:.1e}")
        };
        let line = format!(
            "{name}: predicted {expected} (95 %: {}–{}), observed {}",
            criterion["interval_95"]["low"],
            criterion["interval_95"]["high"],
            criterion["observed_events"]
        );
        assert!(printed.contains(&line), "no `{line}` in:\n{printed}");
    }
    // The clearance's standardised error, from the rows (CSV's shortest round-trip
    // numbers), and its line on the terminal.
    let error = &calibration["ramp_clearance_error"];
    if z.len() >= 2 {
        let mean = z.iter().sum::<f64>() / z.len() as f64;
        assert_eq!(error["runs"], z.len(), "{error}");
        assert!(
            (error["mean"].as_f64().unwrap() - mean).abs() < 1e-9,
            "{error}"
        );
        let line = format!("z = (flown − c)/σ_c over {} runs: mean {mean:+.2}", z.len());
        assert!(printed.contains(&line), "no `{line}` in:\n{printed}");
    } else {
        assert!(error.is_null(), "{error}");
    }
}
