//! Why shards cannot be merged: every error names the shard (its source or its
//! `runs.csv`) and the field, row or line at fault.

use super::row::RowError;
use super::shard::Shard;

/// Why shards cannot be merged into one campaign.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum MergeError {
    /// Nothing to merge.
    #[error("no shard to merge")]
    NoShards,
    /// Two shards flew different scenarios.
    #[error(
        "{other} flew another scenario than {first}: `{field}` is {other_value} there and \
         {first_value} in {first}"
    )]
    DifferentScenario {
        /// The first shard's source.
        first: String,
        /// The other shard's source.
        other: String,
        /// The first line that differs (a key of the scenario, or the line's text).
        field: String,
        /// That line in the first shard.
        first_value: String,
        /// That line in the other shard.
        other_value: String,
    },
    /// A field that must agree between shards does not.
    #[error("{other} is not a shard of the same campaign as {first}: `{field}` is {other_value} there and {first_value} in {first}")]
    Different {
        /// The field (`campaign_seed`, `requested_runs`, `controllers`, shard count).
        field: &'static str,
        /// The first shard's source.
        first: String,
        /// Its value there.
        first_value: String,
        /// The other shard's source.
        other: String,
        /// Its value there.
        other_value: String,
    },
    /// A shard was stopped before its runs finished.
    #[error("{location} is shard {shard} stopped before every run finished (`partial`: true); fly it again to merge it")]
    Partial {
        /// Where the shard comes from.
        location: String,
        /// The shard.
        shard: Shard,
    },
    /// Two shards are the same one.
    #[error("{first} and {other} are both shard {shard}: a shard can be merged once")]
    Overlapping {
        /// The shard.
        shard: Shard,
        /// The first source.
        first: String,
        /// The other source.
        other: String,
    },
    /// Shards of the campaign are not there.
    #[error("missing shard{} {}: a merge needs every shard", if *total == 1 { "" } else { "s" }, listed_missing(missing, *total, *count))]
    MissingShards {
        /// The first shards missing (K of K/M, from 0), at most ten.
        missing: Vec<u64>,
        /// How many are missing.
        total: u64,
        /// M.
        count: u64,
    },
    /// A row that is not one of the shard's runs, or whose seed is not its run's.
    #[error("{location} (shard {shard}): run {run_index} ({controller}) {problem}")]
    ForeignRow {
        /// Where the shard comes from.
        location: String,
        /// The shard.
        shard: Shard,
        /// The row's run index.
        run_index: u64,
        /// The row's controller.
        controller: String,
        /// What is wrong with it.
        problem: String,
    },
    /// A shard's identity is beyond the campaign's limits or not one a campaign writes.
    #[error("{location}: `{field}` is {value}: {problem}")]
    BadIdentity {
        /// Where the shard comes from.
        location: String,
        /// The field at fault (`requested_runs`, `controllers`, `shard`).
        field: &'static str,
        /// Its value.
        value: String,
        /// What is allowed.
        problem: String,
    },
    /// A row no campaign can write (see [`RunRow::check`](super::RunRow::check)).
    #[error("{location}: row {row} (run {run_index}, {controller}): {error}")]
    BadRow {
        /// Where the shard comes from (its `runs.csv`).
        location: String,
        /// The row, from 1 (line `row + 1` of `runs.csv`, after its header).
        row: u64,
        /// The row's run index.
        run_index: u64,
        /// The row's controller.
        controller: String,
        /// The column at fault and why.
        error: Box<RowError>,
    },
    /// `runs.csv` text that is not a campaign's table.
    #[error("{location} line {line}: {problem}")]
    RunsCsv {
        /// Where the text comes from.
        location: String,
        /// The line at fault (the header is line 1).
        line: u64,
        /// What is wrong.
        problem: String,
    },
    /// A shard lacks runs it should hold.
    #[error("{location} (shard {shard}) holds {found} of its {expected} rows; the first missing is run {first_missing} ({controller}): is its runs.csv truncated?")]
    MissingRuns {
        /// Where the shard comes from.
        location: String,
        /// The shard.
        shard: Shard,
        /// Rows expected (runs × controllers).
        expected: u64,
        /// Rows found.
        found: u64,
        /// The first run missing.
        first_missing: u64,
        /// Its controller.
        controller: String,
    },
}

/// The missing shards in words: the first ten, and how many more.
fn listed_missing(missing: &[u64], total: u64, count: u64) -> String {
    let mut text = missing
        .iter()
        .map(|k| format!("{k}/{count}"))
        .collect::<Vec<_>>()
        .join(", ");
    let more = total.saturating_sub(missing.len() as u64);
    if more > 0 {
        text.push_str(&format!(" and {more} more"));
    }
    text
}
