//! One test per class of issue 14 ("every input class that a hostile test broke"),
//! through the binary: no input gives exit status 101, a signal or a hang; bad input is
//! refused naming the field or option and its value; nothing non-finite reaches a file;
//! JSON keys are unique. The library's tests pin the rest (`scenario_key_ranges`, the
//! `scenario_fuzz` property test, `finite_outputs`).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{
    assert_finite_csv, assert_no_panic, assert_refused, assert_unique_keys, deckland, deckland_in,
    endless_campaign, scratch, signal_after, summary_json, temporary_files,
};
use serde_json::Value;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The default scenario file with `key = …` lines replaced by `key = value`; a key
/// written `[section]key` is the first `key` after the line `[section]`.
fn scenario_with(dir: &Path, name: &str, edits: &[(&str, &str)]) -> PathBuf {
    fs::create_dir_all(dir).unwrap();
    let default = deckland(["scenario", "--print-default"]);
    let mut text = String::from_utf8(default.stdout).unwrap();
    for (key, value) in edits {
        let (from, key) = match key.split_once(']') {
            Some((section, key)) => (text.find(&format!("\n{section}]")).unwrap(), key),
            None => (0, *key),
        };
        let start = from
            + text[from..]
                .find(&format!("\n{key} = "))
                .unwrap_or_else(|| panic!("no `{key}` in the default file"))
            + 1;
        let end = start + text[start..].find('\n').unwrap();
        text.replace_range(start..end, &format!("{key} = {value}"));
    }
    let path = dir.join(name);
    fs::write(&path, text).unwrap();
    path
}

/// Runs `deckland run file --out dir/out`: the output folder and the command's output.
fn run_into_out(dir: &Path, file: &Path) -> (PathBuf, Output) {
    let out = dir.join("out");
    let run = deckland([
        "run",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    (out, run)
}

/// Regression (class 1): `compensation_window_s = 1e300` passed `scenario --check`, then
/// `run` panicked (index out of bounds); 1e15 aborted on a 1.6 EB allocation, 1e7 grew
/// to 6.4 GB. Both keys now have a physical upper bound, checked before anything flies.
#[test]
fn regression_keys_without_an_upper_bound_are_refused_before_flying() {
    let dir = scratch("class-1");
    for key in ["compensation_window_s", "compensation_blend_s"] {
        for value in ["1e300", "1e15", "1e7"] {
            let file = scenario_with(&dir, "big.toml", &[(key, value)]);
            let field = format!("control.flight_path.{key}");
            let check = deckland(["scenario", "--check", file.to_str().unwrap()]);
            assert_refused(&check, 1, &[&field, "line ", "expected a value in"]);
            let (out, run) = run_into_out(&dir, &file);
            assert_refused(&run, 1, &[&field]);
            assert!(!out.exists(), "no folder for a refused run");
        }
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 2): `deckland trim | true` and `scenario --print-default >
/// /dev/full` exited 101 with "failed printing to stdout". A reader that went away ends
/// the command quietly (status 0, as ripgrep does); a full device ends it with a message.
#[cfg(unix)]
#[test]
fn regression_a_closed_pipe_ends_quietly_and_a_full_stdout_says_so() {
    let dir = scratch("class-2");
    fs::create_dir_all(&dir).unwrap();
    let binary = env!("CARGO_BIN_EXE_deckland");
    for args in [
        "trim",
        "trim --json",
        "linearize",
        "scenario --print-default",
    ] {
        // `true` has exited (and closed the pipe) before deckland writes.
        let script = format!(
            "{{ sleep 0.3; '{binary}' {args} 2> '{err}'; echo $? > '{status}'; }} | true",
            err = dir.join("stderr").display(),
            status = dir.join("status").display(),
        );
        let shell = Command::new("sh").args(["-c", &script]).status().unwrap();
        assert!(shell.success());
        let status = fs::read_to_string(dir.join("status")).unwrap();
        let stderr = fs::read_to_string(dir.join("stderr")).unwrap();
        assert_eq!(status.trim(), "0", "{args}: {stderr}");
        assert_eq!(stderr, "", "{args}: quiet");
    }
    #[cfg(target_os = "linux")]
    for args in [
        &["scenario", "--print-default"][..],
        &["trim"][..],
        &["trim", "--json"][..],
    ] {
        let output = Command::new(binary)
            .args(args)
            .stdout(fs::File::create("/dev/full").unwrap())
            .output()
            .unwrap();
        assert_refused(
            &output,
            1,
            &["cannot write to standard output", "No space left on device"],
        );
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 3): `--runs 18446744073709551615` panicked with a capacity
/// overflow, `--runs 4294967296` aborted, `--threads 4294967296` spawned threads for
/// ever. Both options are bounded by clap, naming them, before anything else.
#[test]
fn regression_campaign_runs_and_threads_are_bounded() {
    let dir = scratch("class-3");
    let file = scenario_with(&dir, "s.toml", &[]);
    let file = file.to_str().unwrap();
    for (runs, threads, option) in [
        ("18446744073709551615", "1", "--runs"),
        ("4294967296", "1", "--runs"),
        ("100001", "1", "--runs"),
        ("0", "1", "--runs"),
        ("-1", "1", "--runs"),
        ("4", "4294967296", "--threads"),
        ("4", "257", "--threads"),
        ("4", "0", "--threads"),
    ] {
        let out = dir.join("out");
        let output = deckland([
            "campaign",
            file,
            "--runs",
            runs,
            "--threads",
            threads,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_refused(&output, 2, &[option]);
        assert!(!out.exists());
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 4): seeds of 2^63 or more failed for `land` and `run` only after
/// flying, with an error naming no option, and left an empty folder; `step` and
/// `environment` accepted them. One seed domain, 0 to 2^63 − 1, for every command,
/// checked first.
#[test]
fn regression_seeds_share_one_domain_checked_before_anything() {
    let dir = scratch("class-4");
    let file = scenario_with(&dir, "s.toml", &[]);
    let file = file.to_str().unwrap().to_owned();
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    for seed in ["9223372036854775808", "18446744073709551615", "-1"] {
        for command in [
            vec!["land"],
            vec!["run", &file],
            vec!["step"],
            vec!["sink"],
            vec!["environment"],
            vec!["campaign", &file, "--runs", "1"],
        ] {
            let mut args = command.clone();
            args.extend(["--seed", seed, "--out", out]);
            let output = deckland(&args);
            assert_refused(
                &output,
                2,
                &["--seed", "0 to 2⁶³ − 1 = 9223372036854775807"],
            );
            assert!(!Path::new(out).exists(), "{command:?}: folder created");
        }
    }
    // The largest seed flies, and a file's seed is held to the same domain.
    let largest = deckland([
        "environment",
        "--seconds",
        "0.1",
        "--seed",
        "9223372036854775807",
        "--out",
        out,
    ]);
    assert!(largest.status.success(), "{largest:?}");
    let big = dir.join("big-seed.toml");
    fs::write(&big, "seed = 9223372036854775808\n").unwrap();
    let check = deckland(["scenario", "--check", big.to_str().unwrap()]);
    assert_refused(&check, 1, &["seed", "line 1"]);
    // A seed a file can hold but outside the domain, in the domain's words.
    for (value, name) in [("-1", "negative"), ("1.5", "fraction")] {
        let file = dir.join(format!("{name}-seed.toml"));
        fs::write(&file, format!("seed = {value}\n")).unwrap();
        let check = deckland(["scenario", "--check", file.to_str().unwrap()]);
        assert_refused(
            &check,
            1,
            &["seed", "line 1", "an integer from 0 to 2⁶³ − 1"],
        );
        assert!(
            !String::from_utf8_lossy(&check.stderr).contains("u64"),
            "{check:?}"
        );
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 5): `step --epsilon 1e-150`, inside the documented range, ended
/// with "signal sample 1 is not finite: NaN"; the pitch-step and sink-rate missions
/// wrote NaN into CSV columns. Options are checked with the library's ranges (naming
/// the option), and no CSV holds a non-finite value.
#[test]
fn regression_no_option_leads_to_non_finite_output() {
    let dir = scratch("class-5");
    let out = dir.join("out");
    let out_text = out.to_str().unwrap();
    for (args, option) in [
        (vec!["step", "--epsilon", "1e-150"], "--epsilon"),
        (vec!["step", "--epsilon", "0.005"], "--epsilon"),
        (vec!["step", "--step-deg", "nan"], "--step-deg"),
        (vec!["step", "--seconds", "inf"], "--seconds"),
        (vec!["sink", "--ramp-s", "nan"], "--ramp-s"),
        (vec!["sink", "--sink-rate", "1e300"], "--sink-rate"),
        (vec!["sink", "--seconds", "-5"], "--seconds"),
        (vec!["environment", "--seconds", "1e300"], "--seconds"),
        (
            vec!["environment", "--distance-aft", "nan"],
            "--distance-aft",
        ),
        (vec!["environment", "--airspeed", "-1"], "--airspeed"),
        (vec!["trim", "--speed", "1e300"], "--speed"),
        (vec!["trim", "--gamma", "nan"], "--gamma"),
        (vec!["linearize", "--speed", "inf"], "--speed"),
    ] {
        let mut args = args.clone();
        args.extend(["--out", out_text]);
        // trim and linearize take no --out.
        if args[0] == "trim" || args[0] == "linearize" {
            args.truncate(args.len() - 2);
        }
        let output = deckland(&args);
        assert_refused(&output, 1, &[option]);
        assert!(!out.exists(), "{args:?}: folder created");
    }
    // The smallest ε the 1 ms step resolves flies, and every CSV is finite.
    let step = deckland([
        "step",
        "--epsilon",
        "0.006",
        "--conditions",
        "adverse",
        "--seconds",
        "3",
        "--out",
        out_text,
    ]);
    assert!(step.status.success(), "{step:?}");
    assert_finite_csv(&fs::read_to_string(out.join("step.csv")).unwrap());
    let sink = deckland(["sink", "--seconds", "6", "--out", out_text, "--force"]);
    assert!(sink.status.success(), "{sink:?}");
    assert_finite_csv(&fs::read_to_string(out.join("sink.csv")).unwrap());
    let land = deckland(["land", "--out", out_text, "--force"]);
    assert!(land.status.success(), "{land:?}");
    assert_finite_csv(&fs::read_to_string(out.join("approach.csv")).unwrap());
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (classes 6 and 7): errors named the wrong field, and `wire_positions_m`
/// with extra elements (a string, a table) was "valid".
#[test]
fn regression_scenario_errors_name_the_field_and_wrong_types_are_refused() {
    let dir = scratch("class-6-7");
    for (key, value, field) in [
        ("settling_time_s", "1e-300", "control.pitch.settling_time_s"),
        (
            "[control.pitch]damping_ratio",
            "1e308",
            "control.pitch.damping_ratio",
        ),
        (
            "[aircraft.elevator_actuator]damping_ratio",
            "1e308",
            "aircraft.elevator_actuator.damping_ratio",
        ),
        (
            "wire_positions_m",
            r#"[-18.0, -6.0, 6.0, 18.0, "x", { a = 1 }]"#,
            "environment.deck.wire_positions_m",
        ),
        (
            "wire_positions_m",
            "[-18.0, -6.0, 6.0, 18.0, 30.0]",
            "environment.deck.wire_positions_m",
        ),
    ] {
        let file = scenario_with(&dir, "bad.toml", &[(key, value)]);
        let output = deckland(["scenario", "--check", file.to_str().unwrap()]);
        assert_refused(&output, 1, &[field, "line "]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 8): `approach.airspeed_mps = 40`, the documented minimum, passed
/// `--check` but could not be trimmed, and the error was printed twice; `sink
/// --conditions adverse` always diverged at t = 0. `--check` sets the run up, the error
/// is printed once, and the sink test flies.
#[test]
fn regression_check_means_flyable() {
    let dir = scratch("class-8");
    // On the 3-DOF behind a stationary ship the regression was found on (behind the
    // steaming ship of the 3-D default the trim names the angle of attack it would need
    // instead of not converging).
    let file = scenario_with(
        &dir,
        "slow.toml",
        &[
            ("airspeed_mps", "40.0"),
            ("model", "\"3dof\""),
            ("forward_speed_mps", "0.0"),
        ],
    );
    let check = deckland(["scenario", "--check", file.to_str().unwrap()]);
    assert_refused(&check, 1, &["cannot be flown", "trim"]);
    let stderr = String::from_utf8_lossy(&check.stderr);
    assert_eq!(stderr.lines().count(), 1, "{stderr}");
    assert_eq!(stderr.matches("did not converge").count(), 1, "{stderr}");
    let (out, run) = run_into_out(&dir, &file);
    assert_refused(&run, 1, &["trim"]);
    assert_eq!(
        String::from_utf8_lossy(&run.stderr)
            .matches("trim did")
            .count(),
        1
    );
    assert!(!out.exists());
    // What --check accepts flies.
    let good = scenario_with(&dir, "good.toml", &[("airspeed_mps", "60.0")]);
    let check = deckland(["scenario", "--check", good.to_str().unwrap()]);
    assert!(check.status.success(), "{check:?}");
    let run = deckland([
        "run",
        good.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(run.status.success(), "{run:?}");
    // A mission `run` does not fly is named, not silently flown as an approach.
    let step_file = dir.join("step.toml");
    fs::write(
        &step_file,
        "[mission]\nkind = \"pitch_step\"\nstep_deg = 2.0\nstep_time_s = 1.0\nduration_s = 3.0\n\
         start_distance_aft_m = 1000.0\naltitude_m = 150.0\n",
    )
    .unwrap();
    let check = deckland(["scenario", "--check", step_file.to_str().unwrap()]);
    assert!(check.status.success(), "{check:?}");
    assert!(String::from_utf8_lossy(&check.stdout).contains("pitch step"));
    let run = deckland(["run", step_file.to_str().unwrap()]);
    assert_refused(&run, 1, &["mission.kind"]);

    for controller in ["opd", "pid"] {
        let sink = deckland([
            "sink",
            "--conditions",
            "adverse",
            "--controller",
            controller,
            "--seconds",
            "6",
            "--out",
            out.to_str().unwrap(),
            "--force",
            "--json",
        ]);
        assert!(sink.status.success(), "{sink:?}");
        let v: Value = serde_json::from_slice(&sink.stdout).unwrap();
        assert_eq!(v["outcome"], "completed", "{controller}: {}", v["reason"]);
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 9): the recording interval counted steps, so `time_step_s = 1e-5`
/// recorded every 0.1 ms (a 1.45 GB CSV). It is 10 ms of simulated time whatever the
/// step.
#[test]
fn regression_the_recording_interval_is_in_seconds() {
    let dir = scratch("class-9");
    let file = scenario_with(
        &dir,
        "fine.toml",
        &[("time_step_s", "0.0001"), ("start_range_m", "200.0")],
    );
    let (out, run) = run_into_out(&dir, &file);
    assert!(run.status.success(), "{run:?}");
    let csv = fs::read_to_string(out.join("approach.csv")).unwrap();
    let times: Vec<f64> = csv
        .lines()
        .skip(1)
        .map(|l| l.split(',').next().unwrap().parse().unwrap())
        .collect();
    // Rows every 10 ms (the last row is the end of the run, in between).
    for pair in times[..times.len() - 1].windows(2) {
        assert!((pair[1] - pair[0] - 0.01).abs() < 1e-9, "{pair:?}");
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 10): SIGKILL and SIGTERM left `.partial-*` temporary files (one of
/// 96 MB). SIGTERM is handled like Ctrl-C, and the next run removes what a SIGKILL left.
#[cfg(unix)]
#[test]
fn regression_kills_leave_no_temporary_files() {
    let dir = scratch("class-10");
    fs::create_dir_all(&dir).unwrap();
    // SIGTERM stops a campaign like Ctrl-C: partial results, status 130, no temporaries.
    let file = scenario_with(&dir, "s.toml", &[]);
    let out = dir.join("campaign");
    let child = endless_campaign(file.to_str().unwrap(), &out)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let output = signal_after(child, "TERM", 1500);
    assert_eq!(output.status.code(), Some(130), "{output:?}");
    let summary = summary_json(&out);
    assert_eq!(summary["partial"], true);
    assert!(temporary_files(&out).is_empty());

    // What a killed run left (its process gone) is removed by the next run, in an
    // --out folder and in the default runs/ folders: a temporary file named as ours, for
    // a file on the folder's list (issue 28: nothing else is ever removed).
    // 4194305 is above Linux's largest process id.
    let stale = ".partial-4194305-0123456789abcdef.deckland-runs.csv";
    fs::write(out.join(stale), b"half").unwrap();
    let again = deckland([
        "environment",
        "--seconds",
        "0.1",
        "--out",
        out.to_str().unwrap(),
        "--force",
    ]);
    assert!(again.status.success(), "{again:?}");
    assert!(temporary_files(&out).is_empty());
    let old_run = dir.join("runs").join("land-20250101T000000Z");
    fs::create_dir_all(&old_run).unwrap();
    fs::write(
        old_run.join(".deckland-outputs"),
        "deckland land\nruns.csv\n",
    )
    .unwrap();
    fs::write(old_run.join(stale), b"half").unwrap();
    let default = deckland_in(&dir, ["environment", "--seconds", "0.1"]);
    assert!(default.status.success(), "{default:?}");
    assert!(temporary_files(&old_run).is_empty());
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 11): `--out /dev --force` as root wrote 15 files into /dev, and
/// `--force` left another command's outputs mixed with the new ones.
#[test]
fn regression_output_folders_are_the_users_own_and_force_replaces_only_results() {
    let dir = scratch("class-11");
    #[cfg(unix)]
    {
        let before = fs::read_dir("/dev").unwrap().count();
        let output = deckland([
            "environment",
            "--seconds",
            "0.1",
            "--out",
            "/dev",
            "--force",
        ]);
        assert_refused(&output, 1, &["--out /dev"]);
        assert_eq!(fs::read_dir("/dev").unwrap().count(), before);
    }
    let file = dir.join("a-file");
    fs::create_dir_all(&dir).unwrap();
    fs::write(&file, b"x").unwrap();
    let output = deckland(["environment", "--out", file.to_str().unwrap()]);
    assert_refused(&output, 1, &["not a folder"]);

    let out = dir.join("out");
    let out_text = out.to_str().unwrap();
    let first = deckland(["environment", "--seconds", "0.1", "--out", out_text]);
    assert!(first.status.success(), "{first:?}");
    fs::write(out.join("my-notes.txt"), b"keep me").unwrap();
    let refused = deckland(["step", "--seconds", "2", "--out", out_text]);
    assert_refused(&refused, 1, &["--force", "deckland environment"]);
    let forced = deckland(["step", "--seconds", "2", "--out", out_text, "--force"]);
    assert!(forced.status.success(), "{forced:?}");
    let mut names: Vec<String> = fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            ".deckland-outputs",
            "my-notes.txt",
            "step.csv",
            "step_elevator.png",
            "step_elevator.svg",
            "step_pitch.png",
            "step_pitch.svg",
        ]
    );
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (class 12): `land --json`, `run --json` and `summary.json` carried the key
/// `outcome` twice. Every JSON document of every command has unique keys.
#[test]
fn regression_every_json_document_has_unique_keys() {
    let dir = scratch("class-12");
    let file = scenario_with(&dir, "s.toml", &[("start_range_m", "300.0")]);
    let file = file.to_str().unwrap();
    let out = dir.join("out");
    let out_text = out.to_str().unwrap();
    let commands: Vec<Vec<&str>> = vec![
        vec!["land", "--json"],
        vec!["run", file, "--json"],
        vec!["campaign", file, "--runs", "2", "--json"],
        vec!["step", "--seconds", "2", "--json"],
        vec!["sink", "--seconds", "6", "--json"],
    ];
    for command in commands {
        let mut args = command.clone();
        args.extend(["--out", out_text, "--force"]);
        let output = deckland(&args);
        assert!(output.status.success(), "{command:?}: {output:?}");
        assert_no_panic(&output);
        assert_unique_keys(&String::from_utf8(output.stdout).unwrap());
        if let Ok(summary) = fs::read_to_string(out.join("summary.json")) {
            assert_unique_keys(&summary);
        }
    }
    for command in [["trim", "--json"], ["linearize", "--json"]] {
        let output = deckland(command);
        assert!(output.status.success());
        assert_unique_keys(&String::from_utf8(output.stdout).unwrap());
    }
    let _ = fs::remove_dir_all(&dir);
}

/// `deckland scenario --check FILE`.
fn check(file: &Path) -> std::process::Output {
    deckland(["scenario", "--check", file.to_str().unwrap()])
}

/// Regression (issue 45, R4): `wind_over_deck_mps` ≤ 2.2·10⁻³⁰⁸ passed `--check`; the
/// periodic wake divides by it and the run ended "diverged: non-finite `airspeed_mps`".
#[test]
fn r4_a_wind_over_deck_the_wake_cannot_divide_by_is_refused_at_check() {
    let dir = scratch("issue-45-r4");
    for value in ["2.2e-308", "5e-324", "1e-310", "0.001"] {
        let file = scenario_with(&dir, "calm.toml", &[("wind_over_deck_mps", value)]);
        assert_refused(
            &check(&file),
            1,
            &[
                "environment.wind.wind_over_deck_mps",
                "0.01",
                "divides by it",
            ],
        );
    }
    for value in ["0.0", "0.01", "40.0"] {
        let file = scenario_with(&dir, "calm.toml", &[("wind_over_deck_mps", value)]);
        assert!(check(&file).status.success(), "{value} is flyable");
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R10): a product of inertia accepted near its bound
/// (|I_xz| < √(I_x·I_z)) diverged in the first 1-ms step (x = −2.9·10¹⁴ m at 0.001 s).
#[test]
fn r10_near_singular_inertia_is_refused_at_check() {
    let dir = scratch("issue-45-r10");
    let bound = (31_184.0_f64 * 230_415.0).sqrt();
    for fraction in [0.999_999, 0.9999, 0.99] {
        let value = format!("{:.1}", -fraction * bound);
        let file = scenario_with(&dir, "ixz.toml", &[("product_of_inertia_xz_kg_m2", &value)]);
        assert_refused(
            &check(&file),
            1,
            &[
                "aircraft.lateral.product_of_inertia_xz_kg_m2",
                "principal moment",
            ],
        );
    }
    // Well inside the bound the aircraft flies as before.
    let value = format!("{:.1}", -0.9 * bound);
    let file = scenario_with(&dir, "ixz.toml", &[("product_of_inertia_xz_kg_m2", &value)]);
    assert!(check(&file).status.success());
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R6): `step --axis roll --scenario F` with `model = "3dof"`
/// silently flew the 6-DOF aircraft.
#[test]
fn r6_a_lateral_step_refuses_a_three_dof_scenario_naming_the_key() {
    let dir = scratch("issue-45-r6");
    fs::create_dir_all(&dir).unwrap();
    let file = dir.join("longitudinal.toml");
    fs::write(&file, "[aircraft]\nmodel = \"3dof\"\n").unwrap();
    for axis in ["roll", "yaw"] {
        let output = deckland([
            "step",
            "--axis",
            axis,
            "--scenario",
            file.to_str().unwrap(),
            "--out",
            dir.join("out").to_str().unwrap(),
        ]);
        assert_refused(&output, 1, &["aircraft.model", "3dof", axis]);
        assert!(!dir.join("out").exists());
    }
    let _ = fs::remove_dir_all(&dir);
}

/// Regression (issue 45, R11): the lateral step's refusal named design parameters that
/// are not scenario keys (`command_jerk`, `command_rate_fraction`,
/// `aircraft.aileron_actuator.min_deflection_deg`), and a step of 5·10⁻³²⁴° was accepted
/// (and printed as 324 digits).
#[test]
fn r11_lateral_step_refusals_name_scenario_keys_and_tiny_steps_are_refused() {
    let dir = scratch("issue-45-r11");
    fs::create_dir_all(&dir).unwrap();
    let out = dir.join("out");
    for step in ["5e-324", "1e-300", "0.001", "1e308", "-31"] {
        let output = deckland([
            "step",
            "--axis",
            "roll",
            "--step-deg",
            step,
            "--out",
            out.to_str().unwrap(),
        ]);
        assert_refused(&output, 1, &["--step-deg", "0.01", step]);
        assert!(
            String::from_utf8_lossy(&output.stderr).len() < 400,
            "readable"
        );
    }
    let file = dir.join("slow.toml");
    fs::write(
        &file,
        "[aircraft.aileron_actuator]\nnatural_frequency_rad_s = 30.74\ndamping_ratio = 0.509\n\
         travel_deg = 60\nrate_limit_degps = 0.001\n",
    )
    .unwrap();
    let output = deckland([
        "step",
        "--axis",
        "roll",
        "--scenario",
        file.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ]);
    assert_refused(
        &output,
        1,
        &[
            "aircraft.aileron_actuator.rate_limit_degps",
            "aircraft.aileron_actuator.travel_deg",
        ],
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    for design_only in [
        "command_rate_fraction",
        "command_travel_fraction",
        "min_deflection",
    ] {
        assert!(!stderr.contains(design_only), "{stderr}");
    }
    assert!(!out.exists());
    let _ = fs::remove_dir_all(&dir);
}
