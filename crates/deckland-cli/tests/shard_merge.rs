//! `deckland campaign --shard K/M` and `deckland merge`: three shards merged are the
//! campaign flown whole, byte for byte; shards that do not belong together, partial or
//! unfinished shards and malformed shard specs are refused by name; `runs.parquet` holds
//! the rows of `runs.csv`.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{
    assert_success, deckland, scratch, short_dispersed_scenario, signal_after, succeeded_json,
    summary_json,
};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

fn stderr(output: &Output) -> String {
    String::from_utf8_lossy(&output.stderr).into_owned()
}

/// Fails the test unless the command's standard error contains `expected`.
fn assert_in_stderr(output: &Output, expected: &str) {
    assert!(
        stderr(output).contains(expected),
        "expected {expected:?} in: {}",
        stderr(output)
    );
}

/// Flies `deckland campaign FILE --runs RUNS --seed SEED --compare [--shard S] --out OUT`.
fn campaign(file: &str, runs: &str, seed: &str, shard: Option<&str>, out: &Path) -> Output {
    let mut args = vec![
        "campaign",
        file,
        "--runs",
        runs,
        "--seed",
        seed,
        "--compare",
        "--threads",
        if shard.is_some() { "1" } else { "2" },
        "--json",
        "--out",
        out.to_str().unwrap(),
    ];
    if let Some(shard) = shard {
        args.extend(["--shard", shard]);
    }
    deckland(args)
}

/// The statistics of a `summary.json`: the text from `"campaign_seed"` up to the first
/// key that describes how the campaign was flown (`"threads"`).
fn statistics_text(folder: &Path) -> String {
    let text = std::fs::read_to_string(folder.join("summary.json")).unwrap();
    let start = text.find("\"campaign_seed\"").unwrap();
    let end = text.find("\"threads\"").unwrap();
    text[start..end].to_owned()
}

fn merge(folders: &[&PathBuf], out: &Path) -> Output {
    let mut args: Vec<&str> = vec!["merge"];
    args.extend(folders.iter().map(|f| f.to_str().unwrap()));
    args.extend(["--json", "--force", "--out", out.to_str().unwrap()]);
    deckland(args)
}

#[test]
fn three_shards_merged_are_the_campaign_flown_whole_byte_for_byte() {
    let dir = scratch("shards-merge");
    let file = short_dispersed_scenario(&dir);
    let whole = dir.join("whole");
    assert_success(&campaign(&file, "23", "7", None, &whole));
    let shards: Vec<PathBuf> = (0..3).map(|k| dir.join(format!("shard-{k}"))).collect();
    for (k, folder) in shards.iter().enumerate() {
        let output = campaign(&file, "23", "7", Some(&format!("{k}/3")), folder);
        let summary = succeeded_json(&output);
        assert_eq!(summary["shard"], format!("{k}/3"));
        assert_eq!(summary["requested_runs"], 23);
        // Round robin: shard k holds the runs i with i mod 3 = k, under both controllers.
        let expected_runs = (0..23).filter(|i| i % 3 == k).count();
        assert_eq!(summary["finished_runs"], 2 * expected_runs);
        let csv = std::fs::read_to_string(folder.join("runs.csv")).unwrap();
        for line in csv.lines().skip(1) {
            let run: usize = line.split(',').next().unwrap().parse().unwrap();
            assert_eq!(run % 3, k, "{line}");
        }
    }
    let merged = dir.join("merged");
    // In any order.
    let output = merge(&[&shards[2], &shards[0], &shards[1]], &merged);
    assert_success(&output);
    assert_eq!(
        std::fs::read(whole.join("runs.csv")).unwrap(),
        std::fs::read(merged.join("runs.csv")).unwrap(),
        "runs.csv of the merge differs from the campaign flown whole"
    );
    assert_eq!(
        statistics_text(&whole),
        statistics_text(&merged),
        "the statistics of summary.json differ"
    );
    assert_eq!(
        std::fs::read(whole.join("scenario.toml")).unwrap(),
        std::fs::read(merged.join("scenario.toml")).unwrap()
    );
    let summary: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(summary["merged_from"].as_array().unwrap().len(), 3);
    assert_eq!(summary["partial"], false);
    for file in ["outcomes.png", "touchdown_dispersion.svg", "report.html"] {
        assert!(merged.join(file).exists(), "{file}");
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// A 3-D approach campaign's shards merged are the campaign flown whole too: `runs.csv`
/// (with its lateral and trap-sheet columns) byte for byte, and every statistic of
/// `summary.json`, the lateral and trap-sheet statistics included.
#[test]
fn three_d_shards_merged_are_the_campaign_flown_whole() {
    let dir = scratch("shards-merge-3d");
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/crosswind.toml");
    let file = file.to_str().unwrap();
    let whole = dir.join("whole");
    assert_success(&campaign(file, "5", "11", None, &whole));
    let shards: Vec<PathBuf> = (0..2).map(|k| dir.join(format!("shard-{k}"))).collect();
    for (k, folder) in shards.iter().enumerate() {
        assert_success(&campaign(file, "5", "11", Some(&format!("{k}/2")), folder));
    }
    let merged = dir.join("merged");
    let output = merge(&[&shards[1], &shards[0]], &merged);
    assert_success(&output);
    let csv = std::fs::read(whole.join("runs.csv")).unwrap();
    assert!(String::from_utf8_lossy(&csv).contains("trap_ar_lineup_peak_deg"));
    assert_eq!(
        csv,
        std::fs::read(merged.join("runs.csv")).unwrap(),
        "runs.csv of the 3-D merge differs from the campaign flown whole"
    );
    assert_eq!(statistics_text(&whole), statistics_text(&merged));
    let read = |folder: &Path| -> serde_json::Value {
        serde_json::from_slice(&std::fs::read(folder.join("summary.json")).unwrap()).unwrap()
    };
    let (whole_json, merged_json) = (read(&whole), read(&merged));
    for key in ["lateral", "trap_sheet"] {
        assert!(whole_json[key].is_object(), "{key}");
        assert_eq!(whole_json[key], merged_json[key], "{key}");
    }
    assert_parquet_holds_runs_csv(&merged);
    assert!(merged.join("touchdown_plan.svg").exists());
    // A 3-D shard with a 3-DOF campaign's shard: refused, naming the aircraft model.
    let flat = dir.join("flat");
    let dispersed = short_dispersed_scenario(&dir);
    assert_success(&campaign(&dispersed, "5", "11", Some("1/2"), &flat));
    let output = merge(&[&shards[0], &flat], &dir.join("mixed"));
    assert!(!output.status.success());
    assert_in_stderr(&output, "aircraft.model");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_merge_refuses_shards_of_other_campaigns_missing_overlapping_or_unfinished() {
    let dir = scratch("shards-refuse");
    let file = short_dispersed_scenario(&dir);
    let shard = |name: &str, runs: &str, seed: &str, spec: &str| {
        let folder = dir.join(name);
        assert_success(&campaign(&file, runs, seed, Some(spec), &folder));
        folder
    };
    let zero = shard("s0", "6", "7", "0/2");
    let one = shard("s1", "6", "7", "1/2");
    let out = dir.join("out");
    assert_success(&merge(&[&zero, &one], &out));

    let refused = |folders: &[&PathBuf], expected: &str| {
        let output = merge(folders, &out);
        assert_eq!(output.status.code(), Some(1), "{}", stderr(&output));
        assert_in_stderr(&output, expected);
    };
    refused(&[&zero], "missing shard 1/2: a merge needs every shard");
    refused(&[&zero, &one, &one], "are both shard 1/2");
    let other_seed = shard("seed8", "6", "8", "1/2");
    refused(
        &[&zero, &other_seed],
        "is not a shard of the same campaign as",
    );
    refused(&[&zero, &other_seed], "`campaign_seed` is 8 there and 7 in");
    let other_runs = shard("runs7", "7", "7", "1/2");
    refused(
        &[&zero, &other_runs],
        "`requested_runs` is 7 there and 6 in",
    );
    let other_count = shard("of3", "6", "7", "1/3");
    refused(
        &[&zero, &other_count],
        "`shard count M` is 1/3 there and 0/2",
    );

    // Another scenario: the same file with another start range.
    let other_file = dir.join("other.toml");
    std::fs::write(
        &other_file,
        std::fs::read_to_string(&file)
            .unwrap()
            .replace("500.0", "520.0"),
    )
    .unwrap();
    let other_scenario = dir.join("other-scenario");
    assert_success(&campaign(
        other_file.to_str().unwrap(),
        "6",
        "7",
        Some("1/2"),
        &other_scenario,
    ));
    refused(&[&zero, &other_scenario], "flew another scenario than");
    refused(&[&zero, &other_scenario], "`approach.start_range_m` is 520");

    // A shard killed before it wrote its results: no summary.json.
    let unfinished = dir.join("unfinished");
    std::fs::create_dir_all(&unfinished).unwrap();
    std::fs::copy(one.join("runs.csv"), unfinished.join("runs.csv")).unwrap();
    refused(&[&zero, &unfinished], "has no summary.json");

    // A truncated runs.csv: its last row lost.
    let truncated = dir.join("truncated");
    std::fs::create_dir_all(&truncated).unwrap();
    for name in ["summary.json", "scenario.toml"] {
        std::fs::copy(one.join(name), truncated.join(name)).unwrap();
    }
    let csv = std::fs::read_to_string(one.join("runs.csv")).unwrap();
    let kept: Vec<&str> = csv.lines().collect();
    std::fs::write(
        truncated.join("runs.csv"),
        kept[..kept.len() - 1].join("\n") + "\n",
    )
    .unwrap();
    refused(&[&zero, &truncated], "holds 5 of its 6 rows");

    // A number edited into NaN: refused, not carried into the merged files.
    let edited = dir.join("edited");
    std::fs::create_dir_all(&edited).unwrap();
    for name in ["summary.json", "scenario.toml"] {
        std::fs::copy(one.join(name), edited.join(name)).unwrap();
    }
    let mut reader = csv::Reader::from_path(one.join("runs.csv")).unwrap();
    let header = reader.headers().unwrap().clone();
    let column = header.iter().position(|h| h == "end_time_s").unwrap();
    let mut writer = csv::Writer::from_path(edited.join("runs.csv")).unwrap();
    writer.write_record(&header).unwrap();
    for (index, record) in reader.records().enumerate() {
        let mut fields: Vec<String> = record.unwrap().iter().map(str::to_owned).collect();
        if index == 0 {
            fields[column] = "NaN".to_owned();
        }
        writer.write_record(&fields).unwrap();
    }
    writer.flush().unwrap();
    refused(
        &[&zero, &edited],
        "`end_time_s` is NaN: not a finite number",
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// A shard stopped by SIGTERM (as by Ctrl-C) is marked partial and refused by a merge.
#[cfg(unix)]
#[test]
fn an_interrupted_shard_is_partial_and_refused() {
    let dir = scratch("shards-partial");
    let file = short_dispersed_scenario(&dir);
    let complete = dir.join("complete");
    assert_success(&campaign(&file, "4", "7", Some("0/2"), &complete));
    let interrupted = dir.join("interrupted");
    let child = Command::new(env!("CARGO_BIN_EXE_deckland"))
        .args([
            "campaign",
            &file,
            "--runs",
            "100000",
            "--seed",
            "7",
            "--compare",
            "--shard",
            "1/2",
            "--threads",
            "1",
            "--json",
            "--out",
            interrupted.to_str().unwrap(),
        ])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let status = signal_after(child, "TERM", 1500).status;
    assert_eq!(status.code(), Some(130));
    let summary = summary_json(&interrupted);
    assert_eq!(summary["partial"], true);
    assert_eq!(summary["shard"], "1/2");
    // The shard of a 100 000-run campaign does not match the 4-run one: make it match
    // but for `partial`, so the merge is refused for that reason alone.
    let mut text = std::fs::read_to_string(interrupted.join("summary.json")).unwrap();
    text = text.replace("\"requested_runs\": 100000", "\"requested_runs\": 4");
    std::fs::write(interrupted.join("summary.json"), text).unwrap();
    let output = merge(&[&complete, &interrupted], &dir.join("out"));
    assert_eq!(output.status.code(), Some(1));
    assert_in_stderr(&output, "is shard 1/2 stopped before every run finished");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn malformed_shards_are_refused_by_name() {
    let dir = scratch("shards-malformed");
    let file = short_dispersed_scenario(&dir);
    for (spec, expected) in [
        ("3/3", "shard `3/3`: K must be 0 to M − 1 = 2"),
        (
            "0/0",
            "shard `0/0`: the number of shards M must be at least 1",
        ),
        ("a/b", "`a/b` is not a shard: expected K/M"),
        ("1", "`1` is not a shard"),
        ("-1/3", "`-1/3` is not a shard"),
    ] {
        let output = campaign(&file, "4", "1", Some(spec), &dir.join("out"));
        assert_eq!(output.status.code(), Some(2), "{spec}: {}", stderr(&output));
        assert!(
            stderr(&output).contains(expected),
            "{spec}: {}",
            stderr(&output)
        );
        assert!(stderr(&output).contains("--shard"), "{spec}");
    }
    // More shards than runs, so that a shard would hold no run: named, not an empty
    // folder (issue 45, R7: merge refuses such a set, so campaign does too).
    let output = campaign(&file, "2", "1", Some("2/3"), &dir.join("empty"));
    assert_eq!(output.status.code(), Some(1));
    assert_in_stderr(
        &output,
        "the number of shards M must be at most the number of runs (2), so that every \
         shard flies a run",
    );
    assert!(!dir.join("empty").exists());
    let _ = std::fs::remove_dir_all(&dir);
}

/// `runs.parquet` in `out` holds the rows of its `runs.csv`: the same columns in order,
/// every value the CSV's (a double bit for bit).
fn assert_parquet_holds_runs_csv(out: &Path) {
    use parquet::file::reader::{FileReader, SerializedFileReader};
    use parquet::record::Field;

    let mut csv = csv::Reader::from_path(out.join("runs.csv")).unwrap();
    let header: Vec<String> = csv.headers().unwrap().iter().map(str::to_owned).collect();
    let rows: Vec<Vec<String>> = csv
        .records()
        .map(|r| r.unwrap().iter().map(str::to_owned).collect())
        .collect();
    let reader =
        SerializedFileReader::new(std::fs::File::open(out.join("runs.parquet")).unwrap()).unwrap();
    let columns: Vec<String> = reader
        .metadata()
        .file_metadata()
        .schema_descr()
        .columns()
        .iter()
        .map(|c| c.name().to_owned())
        .collect();
    assert_eq!(
        columns, header,
        "the Parquet columns are the CSV's, in order"
    );
    let records: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(Result::unwrap)
        .collect();
    assert_eq!(records.len(), rows.len());
    for (record, row) in records.iter().zip(&rows) {
        for ((name, field), text) in record.get_column_iter().zip(row) {
            match field {
                Field::Null => assert_eq!(*text, "", "{name}"),
                Field::Long(v) => assert_eq!(v.to_string(), *text, "{name}"),
                // The CSV text read as a double is the same double, bit for bit.
                Field::Double(v) => assert_eq!(
                    v.to_bits(),
                    text.parse::<f64>().unwrap().to_bits(),
                    "{name}"
                ),
                Field::Str(v) => assert_eq!(v, text, "{name}"),
                Field::Bool(v) => assert_eq!(v.to_string(), *text, "{name}"),
                other => panic!("{name}: unexpected {other:?}"),
            }
        }
    }
}

#[test]
fn runs_parquet_holds_the_rows_of_runs_csv() {
    let dir = scratch("shards-parquet");
    let file = short_dispersed_scenario(&dir);
    let out = dir.join("out");
    assert_success(&campaign(&file, "9", "3", None, &out));
    assert_parquet_holds_runs_csv(&out);
    // A 3-D campaign's lateral columns too (`off_centre` a boolean).
    let crosswind =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/crosswind.toml");
    let out_3d = dir.join("out-3d");
    assert_success(&campaign(
        crosswind.to_str().unwrap(),
        "2",
        "3",
        None,
        &out_3d,
    ));
    let header = std::fs::read_to_string(out_3d.join("runs.csv")).unwrap();
    let header = header.lines().next().unwrap();
    assert!(
        header.contains(",off_centre,trap_x_glide_slope_mean_m,"),
        "{header}"
    );
    // The LSO's grade, the wave-off's criterion, the deck's share within the recovery
    // limits and the commit point's probabilities last, after the lateral and trap-sheet
    // columns.
    assert!(
        header.ends_with(
            ",trap_ar_lineup_peak_deg,lso_grade,lso_points,lso_comment,wave_off_criterion,\
             deck_within_limits_pct,commit_ramp_strike_probability,\
             commit_hard_landing_probability,commit_off_centre_probability,\
             commit_ramp_clearance_m,commit_ramp_clearance_sigma_m"
        ),
        "{header}"
    );
    assert_parquet_holds_runs_csv(&out_3d);
    let _ = std::fs::remove_dir_all(&dir);
}

/// `runs.csv` of `folder` with each line's fields kept by `keep` (position, field).
fn edit_runs_csv(folder: &Path, keep: impl Fn(usize, &str, bool) -> Option<String>) {
    let path = folder.join("runs.csv");
    let text = std::fs::read_to_string(&path).unwrap();
    let header: Vec<&str> = text.lines().next().unwrap().split(',').collect();
    let touchdown = header
        .iter()
        .position(|c| *c == "touchdown_distance_m")
        .unwrap();
    let mut edited = String::new();
    for (number, line) in text.lines().enumerate() {
        let fields: Vec<&str> = line.split(',').collect();
        let touched_down = number > 0 && !fields[touchdown].is_empty();
        let kept: Vec<String> = fields
            .iter()
            .enumerate()
            .filter_map(|(k, f)| keep(k, f, touched_down))
            .collect();
        edited.push_str(&kept.join(","));
        edited.push('\n');
    }
    std::fs::write(&path, edited).unwrap();
}

/// Regression (issue 45, R3): merge decided "3-D" from the `runs.csv` header alone and
/// accepted, with status 0, 3-D shards with their lateral columns stripped, 3-D rows
/// under a `scenario.toml` saying `model = "3dof"`, touched-down rows with blank lateral
/// values and an empty `scenario.toml` (merged into a 0-byte one).
#[test]
fn r3_merge_checks_lateral_columns_against_the_scenario_and_each_row() {
    let dir = scratch("issue-45-r3");
    let file = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/crosswind.toml");
    let file = file.to_str().unwrap();
    let shards: Vec<PathBuf> = (0..2).map(|k| dir.join(format!("shard-{k}"))).collect();
    for (k, folder) in shards.iter().enumerate() {
        assert_success(&campaign(file, "4", "11", Some(&format!("{k}/2")), folder));
    }
    assert_success(&merge(&[&shards[0], &shards[1]], &dir.join("merged")));
    let copy = |name: &str| -> Vec<PathBuf> {
        shards
            .iter()
            .map(|from| {
                let to = dir.join(name).join(from.file_name().unwrap());
                std::fs::create_dir_all(&to).unwrap();
                for entry in std::fs::read_dir(from).unwrap() {
                    let entry = entry.unwrap();
                    std::fs::copy(entry.path(), to.join(entry.file_name())).unwrap();
                }
                to
            })
            .collect()
    };
    let refused = |copies: &[PathBuf], words: &[&str]| {
        let output = merge(&[&copies[0], &copies[1]], &dir.join("out"));
        let text = stderr(&output);
        assert_eq!(output.status.code(), Some(1), "{text}");
        for word in words {
            assert!(text.contains(word), "no `{word}` in: {text}");
        }
    };
    let base_columns = 23; // RUN_COLUMNS: every campaign's columns
                           // The lateral columns stripped.
    let stripped = copy("stripped");
    for folder in &stripped {
        // The LSO's three columns, the last, kept.
        let lso_columns_from = base_columns + 6 + 24;
        edit_runs_csv(folder, |k, f, _| {
            (k < base_columns || k >= lso_columns_from).then(|| f.to_owned())
        });
    }
    refused(&stripped, &["runs.csv columns", "6dof"]);
    // The scenario says 3dof under 3-D rows.
    let flat = copy("flat");
    for folder in &flat {
        let path = folder.join("scenario.toml");
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains("model = \"6dof\""), "{text}");
        std::fs::write(
            &path,
            text.replacen("model = \"6dof\"", "model = \"3dof\"", 1),
        )
        .unwrap();
    }
    refused(&flat, &["runs.csv columns", "3dof"]);
    // Touched-down rows with blank lateral values.
    let blank = copy("blank");
    for folder in &blank {
        edit_runs_csv(folder, |k, f, touched_down| {
            Some(
                if touched_down && (base_columns..base_columns + 6).contains(&k) {
                    String::new()
                } else {
                    f.to_owned()
                },
            )
        });
    }
    refused(&blank, &["touchdown_lateral_offset_m", "touched down"]);
    // An empty scenario.toml.
    let empty = copy("empty");
    for folder in &empty {
        std::fs::write(folder.join("scenario.toml"), "").unwrap();
    }
    refused(&empty, &["scenario.toml", "empty"]);
    let _ = std::fs::remove_dir_all(&dir);
}
