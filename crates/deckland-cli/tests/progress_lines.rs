//! Long work is never silent (issue 46): with stderr a pipe, as here, `campaign` writes a
//! progress line at each tenth of its runs, also with `--json`, whose JSON names the
//! output folder; `summary.json` keeps its own fields.
#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, scratch, summary_json};

#[test]
fn a_piped_json_campaign_reports_each_tenth_and_names_its_folder() {
    let out = scratch("progress-lines");
    let scenario = concat!(env!("CARGO_MANIFEST_DIR"), "/../../scenarios/calm.toml");
    let output = deckland([
        "campaign",
        scenario,
        "--runs",
        "20",
        "--seed",
        "1",
        "--threads",
        "2",
        "--json",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(output.status.success(), "{output:?}");
    let stderr = String::from_utf8(output.stderr).unwrap();
    let done: Vec<u64> = stderr
        .lines()
        .filter_map(|l| l.strip_prefix("campaign: "))
        .map(|l| l.split('/').next().unwrap().parse().unwrap())
        .collect();
    assert_eq!(done.len(), 10, "{stderr}");
    assert!(done.windows(2).all(|w| w[0] < w[1]), "{stderr}");
    assert!(stderr.contains("20/20 runs (100 %)"), "{stderr}");
    let json: serde_json::Value = serde_json::from_slice(&output.stdout).unwrap();
    assert_eq!(json["output_folder"], out.display().to_string());
    assert_eq!(json["finished_runs"], 20);
    let summary = summary_json(&out);
    assert!(summary.get("output_folder").is_none(), "{summary}");
    assert_eq!(summary["finished_runs"], 20);
    let _ = std::fs::remove_dir_all(&out);
}
