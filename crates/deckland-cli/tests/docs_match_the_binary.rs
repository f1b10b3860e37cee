//! The README names what the binary writes, key for key (issue 14, class 12: it named
//! the trim residuals `_m_s2`, `_rad_s`, `_rad_s2` where the binary writes `_mps2`,
//! `_radps`, `_radps2`, and listed three of the five examples).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, scratch, ROLL_STEP};
use serde_json::Value;
use std::collections::BTreeSet;
use std::path::PathBuf;

fn readme() -> String {
    std::fs::read_to_string(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../README.md"))
        .unwrap()
}

/// The identifiers in backticks in the README's paragraph (or list item) that holds
/// `anchor`, from `anchor` on: `` `{a, b}` `` gives `a` and `b`.
fn documented_keys(anchor: &str) -> BTreeSet<String> {
    let text = readme();
    let start = text
        .find(anchor)
        .unwrap_or_else(|| panic!("the README has no `{anchor}`"));
    let rest = &text[start + anchor.len()..];
    let end = ["\n\n", "\n- "]
        .iter()
        .filter_map(|e| rest.find(e))
        .min()
        .unwrap_or(rest.len());
    rest[..end]
        .split('`')
        .skip(1)
        .step_by(2)
        .flat_map(|code| {
            code.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .filter(|w| !w.is_empty() && w != &"null")
                .map(str::to_owned)
                .collect::<Vec<_>>()
        })
        .collect()
}

/// Every object key of a JSON document, at any depth.
fn json_keys(text: &str) -> BTreeSet<String> {
    fn walk(value: &Value, keys: &mut BTreeSet<String>) {
        match value {
            Value::Object(map) => {
                for (key, inner) in map {
                    keys.insert(key.clone());
                    walk(inner, keys);
                }
            }
            Value::Array(items) => items.iter().for_each(|v| walk(v, keys)),
            _ => {}
        }
    }
    let mut keys = BTreeSet::new();
    walk(&serde_json::from_str(text).unwrap(), &mut keys);
    keys
}

fn stdout_of(args: &[&str]) -> String {
    let output = deckland(args);
    assert!(output.status.success(), "{args:?}: {output:?}");
    String::from_utf8(output.stdout).unwrap()
}

#[test]
fn every_json_document_is_documented_key_for_key() {
    let dir = scratch("docs");
    let out = dir.join("out");
    let out = out.to_str().unwrap();
    let scenario = dir.join("short.toml");
    std::fs::create_dir_all(&dir).unwrap();
    // A short 3-DOF approach: the campaign's `summary.json` bullet documents a 3-DOF
    // campaign (a 3-D campaign's additions are the bullet after it).
    std::fs::write(
        &scenario,
        "[aircraft]\nmodel = \"3dof\"\n[approach]\nstart_range_m = 300.0\n",
    )
    .unwrap();
    let scenario = scenario.to_str().unwrap();
    let trim = json_keys(&stdout_of(&["trim", "--json"]));
    let mut linearize = json_keys(&stdout_of(&["linearize", "--json"]));
    // `trim` holds the trim document, documented with `deckland trim`.
    linearize.retain(|k| !trim.contains(k) || k == "trim");
    // The pitch step and the bank step, each two seconds long.
    let short_step_json = ["--seconds", "2", "--json", "--out", out, "--force"];
    let six_dof_trim = json_keys(&stdout_of(&["trim", "--model", "6dof", "--json"]));
    let mut six_dof_linearize = json_keys(&stdout_of(&["linearize", "--model", "6dof", "--json"]));
    six_dof_linearize.retain(|k| !six_dof_trim.contains(k) || k == "trim");
    let cases = [
        ("it prints one JSON document with", trim.clone()),
        (
            "`trim --model 6dof --json` prints one JSON document with",
            six_dof_trim,
        ),
        (
            "`linearize --model 6dof --json` adds to the trim document (under",
            six_dof_linearize,
        ),
        ("`--json` adds to the trim document (under", linearize),
        (
            "`--json` prints the summary:",
            // Seed 5 touches down with a deviation called (seeds 1–4 are called none: no
            // `deviations` keys).
            json_keys(&stdout_of(&[
                "land", "--seed", "5", "--json", "--out", out, "--force",
            ])),
        ),
        (
            "`--json` prints one JSON document instead of the table:",
            json_keys(&stdout_of(&[&["step"][..], &short_step_json].concat())),
        ),
        (
            "With `--axis roll` or `yaw`, `--json` prints",
            json_keys(&stdout_of(&[&ROLL_STEP[..], &short_step_json].concat())),
        ),
        (
            "`summary.json` (and `--json`)\nholds",
            json_keys(&stdout_of(&[
                "sink",
                "--seconds",
                "6",
                "--json",
                "--out",
                out,
                "--force",
            ])),
        ),
        (
            "- `summary.json` —",
            json_keys(&stdout_of(&[
                "campaign", scenario, "--runs", "2", "--json", "--out", out, "--force",
            ])),
        ),
    ];
    for (anchor, keys) in cases {
        let documented = documented_keys(anchor);
        let undocumented: Vec<_> = keys.difference(&documented).collect();
        let absent: Vec<_> = documented.difference(&keys).collect();
        assert!(
            undocumented.is_empty() && absent.is_empty(),
            "README at `{anchor}`: keys written but not documented {undocumented:?}, \
             documented but not written {absent:?}"
        );
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_readme_lists_every_example() {
    let folder = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../deckland/examples");
    let examples: BTreeSet<String> = std::fs::read_dir(folder)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter_map(|n| n.strip_suffix(".rs").map(str::to_owned))
        .collect();
    let text = readme();
    let line = text
        .lines()
        .find(|l| l.contains("(examples: "))
        .expect("the layout lists the examples");
    let listed: BTreeSet<String> = line
        .split("(examples: ")
        .nth(1)
        .unwrap()
        .trim_end_matches(')')
        .split(", ")
        .map(str::to_owned)
        .collect();
    assert_eq!(listed, examples);
}

/// A line of a campaign's table with its timing masked: the threads, the seconds and the
/// rate of "…, seed 1, 2 threads, 6.8 s (147 runs/s)" change from run to run.
fn masked(line: &str) -> String {
    match (line.find(" threads, "), line.rfind(" runs/s)")) {
        (Some(threads), Some(rate)) if threads < rate => {
            let start = line[..threads].rfind(", ").map_or(0, |i| i + 2);
            format!(
                "{}<threads, time and rate>{}",
                &line[..start],
                &line[rate + " runs/s)".len()..]
            )
        }
        _ => line.trim_end().to_owned(),
    }
}

/// The README's example outputs: each ```text block right after a line
/// `<!-- the output of: deckland ARGS -->`, with ARGS.
fn readme_examples() -> Vec<(String, Vec<String>)> {
    let text = readme();
    let marker = "<!-- the output of: deckland ";
    let mut examples = Vec::new();
    for (start, _) in text.match_indices(marker) {
        let rest = &text[start + marker.len()..];
        let args = rest[..rest.find(" -->").expect("a closed marker")].to_owned();
        let block = rest
            .split_once("```text\n")
            .and_then(|(between, block)| {
                (between.lines().count() <= 1).then(|| block.split_once("\n```").unwrap().0)
            })
            .unwrap_or_else(|| panic!("no ```text block right after the marker of `{args}`"));
        examples.push((args, block.lines().map(masked).collect()));
    }
    examples
}

/// Every example output in the README is what the binary prints for its command, line
/// for line (an excerpt keeps its lines in order), for the default hardware: the step,
/// land, sink, trim, linearize and campaign tables (issue 29: the step table was the
/// paper hardware's, the sink example did not settle).
#[test]
fn every_example_output_in_the_readme_is_what_the_binary_prints() {
    let examples = readme_examples();
    let commands: BTreeSet<&str> = examples
        .iter()
        .filter_map(|(args, _)| args.split_whitespace().next())
        .collect();
    for command in ["step", "land", "sink", "campaign", "trim", "linearize"] {
        assert!(
            commands.contains(command),
            "the README shows no example output of `{command}`"
        );
    }
    let dir = scratch("docs-examples");
    for (index, (args, block)) in examples.iter().enumerate() {
        let mut argv: Vec<String> = args.split_whitespace().map(str::to_owned).collect();
        if ["land", "step", "sink", "campaign"].contains(&argv[0].as_str()) {
            let out = dir.join(index.to_string());
            argv.extend(["--out".to_owned(), out.display().to_string()]);
        }
        // From the repository's root, as the README runs it (scenario paths).
        let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
        let output = common::deckland_in(&root, &argv);
        assert!(output.status.success(), "{argv:?}: {output:?}");
        let printed: Vec<String> = String::from_utf8(output.stdout)
            .unwrap()
            .lines()
            .map(masked)
            .collect();
        let mut from = 0;
        for line in block {
            match printed[from..].iter().position(|p| p == line) {
                Some(at) => from += at + 1,
                None => panic!(
                    "README example of `deckland {args}`: the binary does not print, in \
                     this order,\n  {line}\nIt prints:\n{}",
                    printed.join("\n")
                ),
            }
        }
    }
    let _ = std::fs::remove_dir_all(&dir);
}

/// The long options of `deckland COMMAND --help`.
fn options_of(command: &str) -> BTreeSet<String> {
    stdout_of(&[command, "--help"])
        .lines()
        .filter(|line| line.trim_start().starts_with('-'))
        .flat_map(|line| line.split(|c: char| c.is_whitespace() || c == ','))
        .filter(|w| w.starts_with("--") && w.len() > 2)
        .map(|w| w.split(['=', '<']).next().unwrap().to_owned())
        .filter(|w| w != "--help" && w != "--version")
        .collect()
}

/// Every synopsis in the README (the ```sh synopsis block line `cargo run --release -- COMMAND
/// [--option …]` and its continuation lines) names exactly the options of the command's
/// `--help` (issue 29: the step synopsis left out `--hardware`).
#[test]
fn every_synopsis_names_exactly_the_options_of_help() {
    let text = readme();
    let mut checked = BTreeSet::new();
    let lines: Vec<&str> = text.lines().collect();
    for (index, line) in lines.iter().enumerate() {
        let Some(rest) = line.trim_start().strip_prefix("cargo run --release -- ") else {
            continue;
        };
        let command = rest.split_whitespace().next().unwrap().to_owned();
        // A synopsis lists options in brackets; other lines are examples.
        if !rest.contains("[--") {
            continue;
        }
        let mut synopsis = rest.trim_end_matches('\\').to_owned();
        for next in &lines[index + 1..] {
            let next = next.trim();
            if next.starts_with('[') {
                synopsis.push(' ');
                synopsis.push_str(next.trim_end_matches('\\'));
            } else {
                break;
            }
        }
        let named: BTreeSet<String> = synopsis
            .split(|c: char| c.is_whitespace() || c == '[' || c == ']' || c == '|')
            .filter(|w| w.starts_with("--") && w.len() > 2)
            .map(str::to_owned)
            .collect();
        let help = options_of(&command);
        let missing: Vec<_> = help.difference(&named).collect();
        let unknown: Vec<_> = named.difference(&help).collect();
        assert!(
            missing.is_empty() && unknown.is_empty(),
            "README synopsis of `{command}`: options of --help missing {missing:?}, \
             options --help does not have {unknown:?}"
        );
        checked.insert(command);
    }
    for command in ["land", "step", "sink", "campaign", "trim", "environment"] {
        assert!(
            checked.contains(command),
            "no synopsis of `{command}`: {checked:?}"
        );
    }
}
