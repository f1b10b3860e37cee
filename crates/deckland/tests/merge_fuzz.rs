//! Property (fuzz) test of `merge` (issue 28, item 6): tampered and mismatched shards.
//!
//! Each case starts from the three shards of one small campaign flown under two
//! controllers (`shard_fixture`), carried as a merge gets them — an identity and the
//! text of `runs.csv` — and applies one to four tamperings: a field of a row set to a
//! hostile value (an unknown outcome, a wire out of 1–4, ±∞, NaN, 1.8e308, huge or
//! negative integers, an empty field, quotes, commas, line breaks), a line removed,
//! repeated or swapped, the text cut at a random byte or a random byte inserted, and the
//! identity changed (run count 0 to 2⁶⁴ − 1, campaign seed, controllers emptied,
//! repeated or renamed, shard K/M up to 2⁶⁴ − 1, `partial`, the scenario text), a shard
//! dropped or given twice. The properties:
//!
//! - nothing panics, aborts, hangs or allocates by a shard's word (a case is bounded);
//! - a refusal says where (a shard's source or its `runs.csv`);
//! - an accepted merge is a campaign: every row passes the row schema, every run of
//!   every controller is there once with its run's seed, and when no tampering changed
//!   what the shards say, it is the untampered merge.
//!
//! `DECKLAND_FUZZ_CASES` sets the number of cases (default 2000, about a second).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod shard_fixture;

use deckland::monte_carlo::{
    merge_shards, parse_runs_csv, run_seed, LateralRow, MergeError, RunsSchema, Shard,
    ShardIdentity, ShardRows,
};
use proptest::prelude::*;
use proptest::test_runner::{Config, TestRunner};
use shard_fixture::{flown_shards, rows_csv, RUNS, SHARDS};

/// A shard as it travels: what it says it is, and its `runs.csv` text.
#[derive(Clone)]
struct Carried {
    identity: ShardIdentity,
    text: String,
}

/// Hostile field values.
const VALUES: [&str; 22] = [
    "crash",
    "completed",
    "",
    "9",
    "0",
    "-1",
    "300",
    "NaN",
    "inf",
    "-inf",
    "1.7976931348623157e308",
    "-1.7976931348623157e308",
    "1e-320",
    "18446744073709551616",
    "9223372036854775807",
    "\"",
    "a,b",
    "line\nbreak",
    "trap",
    "O-PD",
    "PID",
    "3",
];

/// One tampering: a kind and three random numbers that choose where and what.
type Tampering = (u8, u64, u64, u64);

/// Applies `tampering` to `shards`.
fn tamper(shards: &mut Vec<Carried>, &(kind, a, b, c): &Tampering) {
    if shards.is_empty() {
        return;
    }
    let which = (a % shards.len() as u64) as usize;
    let shard = &mut shards[which];
    let lines: Vec<String> = shard.text.lines().map(|l| format!("{l}\n")).collect();
    let line = |n: u64| (n % lines.len().max(1) as u64) as usize;
    match kind {
        0..=4 => {
            // A field of a row (or of the header) set to a hostile value.
            let mut fields: Vec<String> = lines
                .get(line(b))
                .map(|l| l.trim_end().split(',').map(str::to_owned).collect())
                .unwrap_or_default();
            if !fields.is_empty() {
                let field = (c % fields.len() as u64) as usize;
                fields[field] = VALUES[(c / 31 % VALUES.len() as u64) as usize].to_owned();
                let mut edited = lines.clone();
                edited[line(b)] = fields.join(",") + "\n";
                shard.text = edited.concat();
            }
        }
        5 => {
            let mut edited = lines.clone();
            if !edited.is_empty() {
                edited.remove(line(b));
            }
            shard.text = edited.concat();
        }
        6 => {
            let mut edited = lines.clone();
            if !edited.is_empty() {
                let copy = edited[line(b)].clone();
                edited.insert(line(c), copy);
            }
            shard.text = edited.concat();
        }
        7 => {
            let mut edited = lines.clone();
            if !edited.is_empty() {
                let (i, j) = (line(b), line(c));
                edited.swap(i, j);
            }
            shard.text = edited.concat();
        }
        8 => {
            let cut = (b % (shard.text.len() as u64 + 1)) as usize;
            let cut = (0..=cut)
                .rev()
                .find(|&i| shard.text.is_char_boundary(i))
                .unwrap();
            shard.text.truncate(cut);
        }
        9 => {
            let at = (b % (shard.text.len() as u64 + 1)) as usize;
            let at = (0..=at)
                .rev()
                .find(|&i| shard.text.is_char_boundary(i))
                .unwrap();
            let byte = [b',', b'"', b'\n', b'\r', b'x', b'-', b'9', b'.'][(c % 8) as usize];
            shard.text.insert(at, byte as char);
        }
        10 => {
            shard.identity.requested_runs =
                [0, 1, RUNS - 1, RUNS + 1, 100_000, 100_001, u64::MAX][(b % 7) as usize];
        }
        11 => shard.identity.campaign_seed ^= 1 << (b % 64),
        12 if shard.identity.controllers.is_empty() => {}
        12 => match b % 4 {
            0 => shard.identity.controllers.clear(),
            1 => {
                let first = shard.identity.controllers[0].clone();
                shard.identity.controllers.push(first);
            }
            2 => shard.identity.controllers[0] = VALUES[(c % VALUES.len() as u64) as usize].into(),
            _ => shard.identity.controllers.reverse(),
        },
        13 => {
            let count =
                [1, 2, SHARDS + 1, RUNS, RUNS + 1, 100_000, 100_001, u64::MAX][(b % 8) as usize];
            if let Ok(new) = Shard::new(c % count.max(1), count) {
                shard.identity.shard = new;
            }
        }
        14 => {
            shard.identity.partial = !shard.identity.partial;
        }
        15 => shard.identity.scenario_toml.push_str("# edited\n"),
        16 => {
            shards.remove(which);
        }
        _ => {
            let copy = shards[which].clone();
            shards.push(copy);
        }
    }
}

/// Reads and merges `shards` as a front end does.
fn merge(shards: &[Carried]) -> Result<deckland::monte_carlo::MergedCampaign, MergeError> {
    let mut parts = Vec::new();
    for shard in shards {
        let table = parse_runs_csv(&format!("{}/runs.csv", shard.identity.source), &shard.text)?;
        parts.push(ShardRows {
            identity: shard.identity.clone(),
            table,
        });
    }
    merge_shards(parts)
}

#[test]
fn tampered_and_mismatched_shards_are_refused_or_merge_into_a_campaign() {
    let cases: u32 = std::env::var("DECKLAND_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(2000);
    let original: Vec<Carried> = flown_shards()
        .into_iter()
        .map(|s| Carried {
            text: rows_csv(&s.table.rows),
            identity: s.identity,
        })
        .collect();
    let untampered = merge(&original).unwrap();
    let refused = std::cell::Cell::new(0_u32);
    let mut runner = TestRunner::new(Config {
        cases,
        max_shrink_iters: 200,
        failure_persistence: None,
        ..Config::default()
    });
    let plan = prop::collection::vec((0_u8..18, any::<u64>(), any::<u64>(), any::<u64>()), 1..5);
    let result = runner.run(&plan, |plan| {
        let mut shards = original.clone();
        for tampering in &plan {
            tamper(&mut shards, tampering);
        }
        match merge(&shards) {
            Err(error) => {
                let message = error.to_string();
                prop_assert!(
                    ["s0", "s1", "s2"].iter().any(|s| message.contains(s))
                        || matches!(
                            error,
                            MergeError::NoShards | MergeError::MissingShards { .. }
                        ),
                    "says not where: {message}"
                );
                refused.set(refused.get() + 1);
            }
            Ok(merged) => {
                let variants = merged.controllers.len() as u64;
                prop_assert_eq!(
                    merged.table.rows.len() as u64,
                    merged.requested_runs * variants
                );
                for (position, row) in merged.table.rows.iter().enumerate() {
                    prop_assert!(row.check().is_ok(), "{row:?}");
                    prop_assert_eq!(row.run_index, position as u64 / variants);
                    prop_assert_eq!(
                        row.controller.as_ref(),
                        merged.controllers[position % variants as usize].as_str()
                    );
                    prop_assert_eq!(row.seed, run_seed(merged.campaign_seed, row.run_index));
                }
                let same_words = shards.len() == original.len()
                    && shards
                        .iter()
                        .zip(&original)
                        .all(|(s, o)| s.identity == o.identity && s.text == o.text);
                if same_words {
                    prop_assert_eq!(&merged, &untampered);
                }
            }
        }
        Ok(())
    });
    if let Err(failure) = result {
        panic!("{failure}");
    }
    // Most tamperings are caught; a few change nothing (a line swapped with itself).
    let refused = refused.get();
    assert!(refused > cases / 2, "only {refused} of {cases} refused");
}

/// Regression (issue 45, R3): merge decided "3-D" from the `runs.csv` header alone. It
/// accepted 3-D shards with their lateral columns stripped, lateral columns under a
/// `scenario.toml` saying `model = "3dof"`, touched-down rows with blank lateral values
/// and an empty `scenario.toml`. The columns are now checked against each shard's own
/// scenario, and each row's lateral values against its touchdown.
#[test]
fn r3_merge_checks_lateral_columns_against_the_scenario_and_each_row() {
    let original = flown_shards();
    let refused = |shards: Vec<ShardRows>, words: &[&str]| {
        let message = merge_shards(shards).unwrap_err().to_string();
        for word in words {
            assert!(message.contains(word), "no `{word}` in: {message}");
        }
    };
    let mut three_d = shard_fixture::wide_scenario();
    three_d.aircraft.model = deckland::aircraft::PlantModel::SixDof;
    let three_d_toml = toml::to_string(&three_d).unwrap();
    let blank = LateralRow {
        touchdown: (None, None, None, None, None, None),
        trap_sheet: [None; 24],
    };
    // A 3-D scenario's shards with the lateral columns stripped.
    let mut stripped = original.clone();
    for shard in &mut stripped {
        shard.identity.scenario_toml = three_d_toml.clone();
    }
    refused(
        stripped.clone(),
        &["s0", "runs.csv columns", "no lateral columns", "6dof"],
    );
    // Lateral columns appended under a scenario that says 3dof.
    let mut appended = original.clone();
    for shard in &mut appended {
        shard.table.schema = RunsSchema::WITH_LATERAL;
        shard.table.lateral_rows = vec![blank; shard.table.rows.len()];
    }
    refused(
        appended,
        &["s0", "runs.csv columns", "`aircraft.model` = \"3dof\""],
    );
    // Touched-down rows of a 3-D shard with blank lateral values.
    let mut blanks = stripped;
    for shard in &mut blanks {
        shard.table.schema = RunsSchema::WITH_LATERAL;
        shard.table.lateral_rows = vec![blank; shard.table.rows.len()];
    }
    assert!(original
        .iter()
        .flat_map(|s| &s.table.rows)
        .any(|r| r.touchdown_distance_m.is_some()));
    refused(blanks, &["touchdown_lateral_offset_m", "touched down"]);
    // An empty (or blank) scenario.toml, and one that is not a scenario.
    for text in ["", " \n", "not = [toml"] {
        let mut empty = original.clone();
        for shard in &mut empty {
            shard.identity.scenario_toml = text.to_owned();
        }
        refused(empty, &["s0", "scenario.toml"]);
    }
}
