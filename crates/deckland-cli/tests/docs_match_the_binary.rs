//! The README names what the binary writes, key for key (issue 14, class 12: it named
//! the trim residuals `_m_s2`, `_rad_s`, `_rad_s2` where the binary writes `_mps2`,
//! `_radps`, `_radps2`, and listed three of the five examples).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, scratch};
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
    std::fs::write(&scenario, "[approach]\nstart_range_m = 300.0\n").unwrap();
    let scenario = scenario.to_str().unwrap();
    let trim = json_keys(&stdout_of(&["trim", "--json"]));
    let mut linearize = json_keys(&stdout_of(&["linearize", "--json"]));
    // `trim` holds the trim document, documented with `deckland trim`.
    linearize.retain(|k| !trim.contains(k) || k == "trim");
    let cases = [
        ("it prints one JSON document with", trim.clone()),
        ("`--json` adds to the trim document (under", linearize),
        (
            "`--json` prints the summary:",
            // Seed 3 touches down (seed 1 flies over the last wire: no `touchdown` keys).
            json_keys(&stdout_of(&[
                "land", "--seed", "3", "--json", "--out", out, "--force",
            ])),
        ),
        (
            "`--json` prints one JSON document instead of the table:",
            json_keys(&stdout_of(&[
                "step",
                "--seconds",
                "2",
                "--json",
                "--out",
                out,
                "--force",
            ])),
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
