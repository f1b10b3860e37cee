//! `deckland rare` end to end: what it writes, and that bad input and an unreachable
//! event are named, never a silent zero.

mod common;

use common::{deckland, scratch, succeeded_json, summary_json};
use std::fs;
use std::path::Path;
use std::process::Output;

const PAPER: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../scenarios/paper-adverse.toml"
);

/// `deckland rare` on the paper's adverse set for the hook less than `threshold` m over
/// the ramp, with 8 particles and at most `max_runs` approaches, into `out`.
fn rare_ramp(threshold: &str, max_runs: &str, out: &Path, more: &[&str]) -> Output {
    let mut args = vec![
        "rare",
        PAPER,
        "--event",
        "ramp_strike",
        "--threshold",
        threshold,
        "--particles",
        "8",
        "--max-runs",
        max_runs,
        "--out",
        out.to_str().expect("utf-8"),
    ];
    args.extend_from_slice(more);
    deckland(args)
}

#[test]
fn rare_writes_the_estimate_the_levels_and_the_flights_that_reached_the_event() {
    let out = scratch("rare");
    let result = rare_ramp("1.0", "150", &out, &["--save-flights", "1", "--json"]);
    let printed = succeeded_json(&result);
    let written = summary_json(&out);
    for summary in [&printed, &written] {
        let p = summary["estimate"]["probability"]
            .as_f64()
            .expect("a probability");
        assert!(p > 0.0 && p < 1.0, "{summary}");
        assert_eq!(summary["request"]["event"], "ramp_strike");
        assert_eq!(summary["thresholds"]["ramp_clearance_m"], 1.0);
    }
    assert!(printed["folder"]
        .as_str()
        .is_some_and(|f| f.ends_with("rare")));
    let levels = fs::read_to_string(out.join("levels.csv")).expect("levels.csv");
    assert!(levels.starts_with("repetition,iteration,level\n") && levels.lines().count() > 2);
    for file in ["levels.png", "levels.svg", "report.html", "scenario.toml"] {
        assert!(out.join(file).is_file(), "{file}");
    }
    // The saved flight reached the event: its hook crossed less than 1 m above the ramp.
    let flight = out.join("event_flights/01");
    let summary = summary_json(&flight);
    let clearance = summary["summary"]["ramp_clearance_m"]
        .as_f64()
        .expect("crossed");
    assert!(clearance < 1.0, "{clearance}");
    assert!(flight.join("approach.csv").is_file() && flight.join("approach.png").is_file());
}

#[test]
fn an_event_no_flight_can_reach_is_said_so_not_a_silent_zero() {
    let out = scratch("rare-unreachable");
    // The hook 29 m below the ramp: no approach of the paper's sea goes there.
    let result = rare_ramp("-29", "300", &out, &[]);
    let stderr = String::from_utf8_lossy(&result.stderr);
    let stdout = String::from_utf8_lossy(&result.stdout);
    // Either every repetition went extinct (said, with the highest level reached), or
    // the budget ran out first (an error that says so).
    assert!(
        stderr.contains("no repetition reached the event")
            || stderr.contains("no repetition completed"),
        "stdout: {stdout}\nstderr: {stderr}"
    );
}

#[test]
fn bad_options_are_named() {
    for (args, expected) in [
        (vec!["--event", "crash"], "`crash`"),
        (
            vec!["--event", "ramp_strike", "--threshold", "99"],
            "threshold",
        ),
        (vec!["--event", "off_centre"], "3-D approach"),
        (vec!["--event", "lost", "--threshold", "1"], "no threshold"),
        (
            vec!["--event", "ramp_strike", "--target-rel-error", "0"],
            "target_rel_error",
        ),
    ] {
        let out = scratch("rare-bad");
        let mut all = vec!["rare", PAPER, "--out", out.to_str().expect("utf-8")];
        all.extend(args.iter().copied());
        let result = deckland(&all);
        let stderr = String::from_utf8_lossy(&result.stderr);
        assert!(!result.status.success(), "{args:?} accepted");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}
