//! Merging shards into the campaign they are part of.
//!
//! Each shard says what it belongs to ([`ShardIdentity`]: the scenario flown, the
//! campaign seed, the run count, the controllers, which shard it is and whether it was
//! stopped early) and carries its rows. [`merge_shards`] checks that the shards belong to
//! one campaign and cover it exactly once — every error names the shard and the field at
//! fault — and returns the campaign's rows in run order: those of the campaign flown
//! whole on one machine.
//!
//! Nothing a shard says is trusted before it is checked: its identity against the
//! campaign's limits ([`super::limits`]) before anything is allocated by it, and every row
//! against the row schema ([`RunRow::check`]). [`super::parse_runs_csv`] reads a shard's
//! `runs.csv` text with the same checks (the exact columns, a last line that ends, every
//! row), naming the line and the column at fault, so that every front end (the CLI's
//! `merge`, Python, Dask) refuses the same inputs with the same words.

use super::limits::{
    check_runs, MAX_CONTROLLERS, MAX_CONTROLLER_LABEL_BYTES, MAX_RUNS, MAX_SHARDS,
};
use super::merge_error::MergeError;
use super::row::RunRow;
use super::runs_table::{RunsSchema, RunsTable};
use super::seeds::run_seed;
use super::shard::Shard;
use crate::scenario::load_scenario;

/// Most missing shards a message lists one by one.
const LISTED_MISSING: usize = 10;

/// What a shard says it is part of.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShardIdentity {
    /// Where the shard comes from, for messages (a folder, a task).
    pub source: String,
    /// The scenario flown, as its canonical TOML text (`scenario.toml` of the shard).
    pub scenario_toml: String,
    /// The campaign seed S.
    pub campaign_seed: u64,
    /// Approaches per controller in the whole campaign.
    pub requested_runs: u64,
    /// The controllers' labels, in order.
    pub controllers: Vec<String>,
    /// Which shard.
    pub shard: Shard,
    /// Whether the shard was stopped before every run finished.
    pub partial: bool,
}

/// One shard: what it is and its runs table.
#[derive(Debug, Clone, PartialEq)]
pub struct ShardRows {
    /// What the shard is part of.
    pub identity: ShardIdentity,
    /// Its runs table (`runs.csv`), the rows in any order.
    pub table: RunsTable<'static>,
}

/// The campaign put together from its shards.
#[derive(Debug, Clone, PartialEq)]
pub struct MergedCampaign {
    /// The scenario flown (TOML text, the same for every shard).
    pub scenario_toml: String,
    /// The campaign seed.
    pub campaign_seed: u64,
    /// Approaches per controller.
    pub requested_runs: u64,
    /// The controllers' labels, in order.
    pub controllers: Vec<String>,
    /// Every run's rows, sorted by run index and controller, in the schema of the
    /// scenario flown.
    pub table: RunsTable<'static>,
    /// The shards' sources, by shard index (the first is shard 0).
    pub sources: Vec<String>,
}

/// Checks a shard's identity against the campaign's limits, before anything is allocated
/// by it: its run count, its controllers, and a shard count no larger than its runs.
fn check_identity(identity: &ShardIdentity) -> Result<(), MergeError> {
    let bad = |field: &'static str, value: String, problem: String| MergeError::BadIdentity {
        location: identity.source.clone(),
        field,
        value,
        problem,
    };
    let runs = identity.requested_runs;
    if let Err(error) = check_runs(runs) {
        return Err(bad(
            "requested_runs",
            runs.to_string(),
            format!("a campaign flies 1 to {MAX_RUNS} runs ({error})"),
        ));
    }
    let count = identity.shard.count();
    if count > runs.min(MAX_SHARDS) {
        return Err(bad(
            "shard",
            identity.shard.to_string(),
            format!("a campaign of {runs} runs has at most {runs} shards (one run each)"),
        ));
    }
    let controllers = &identity.controllers;
    let listed = || format!("[{}]", controllers.join(", "));
    if controllers.is_empty() || controllers.len() > MAX_CONTROLLERS {
        return Err(bad(
            "controllers",
            listed(),
            format!("a campaign flies 1 to {MAX_CONTROLLERS} controllers"),
        ));
    }
    for (position, label) in controllers.iter().enumerate() {
        if label.is_empty()
            || label.len() > MAX_CONTROLLER_LABEL_BYTES
            || label.chars().any(char::is_control)
        {
            return Err(bad(
                "controllers",
                format!("{label:?}"),
                format!(
                    "a controller's label is 1 to {MAX_CONTROLLER_LABEL_BYTES} bytes of \
                     printable text"
                ),
            ));
        }
        if controllers[..position].contains(label) {
            return Err(bad(
                "controllers",
                listed(),
                format!("`{label}` is listed twice"),
            ));
        }
    }
    Ok(())
}

/// The first line where two scenario texts differ: (key or line, first value, other).
fn first_difference(first: &str, other: &str) -> (String, String, String) {
    let mut section = String::new();
    let mut a = first.lines();
    let mut b = other.lines();
    loop {
        match (a.next(), b.next()) {
            (Some(x), Some(y)) if x == y => {
                if x.starts_with('[') {
                    section = x.trim_matches(|c| c == '[' || c == ']').to_owned();
                }
            }
            (x, y) => {
                let line = x.or(y).unwrap_or_default();
                let field = match line.split_once('=') {
                    Some((key, _)) if !section.is_empty() => format!("{section}.{}", key.trim()),
                    Some((key, _)) => key.trim().to_owned(),
                    None => line.trim().to_owned(),
                };
                let value = |l: Option<&str>| match l {
                    Some(l) => l
                        .split_once('=')
                        .map_or(l.trim(), |(_, v)| v.trim())
                        .to_owned(),
                    None => "absent".to_owned(),
                };
                return (field, value(x), value(y));
            }
        }
    }
}

/// Checks that `shards` are the M shards of one campaign, each complete and holding
/// exactly its own runs, and returns the campaign's rows sorted by run index and
/// controller: the rows of the campaign flown whole.
pub fn merge_shards(mut shards: Vec<ShardRows>) -> Result<MergedCampaign, MergeError> {
    let first = shards.first().ok_or(MergeError::NoShards)?.identity.clone();
    for shard in &shards {
        check_identity(&shard.identity)?;
        check_columns_against_scenario(shard)?;
    }
    for shard in &shards {
        check_same_campaign(&first, shard)?;
    }
    let by_index = index_shards(&shards, first.shard.count())?;
    if let Some(partial) = shards.iter().find(|s| s.identity.partial) {
        return Err(MergeError::Partial {
            location: partial.identity.source.clone(),
            shard: partial.identity.shard,
        });
    }
    let position_of = |label: &str| first.controllers.iter().position(|c| c == label);
    for shard in &mut shards {
        check_rows(
            shard,
            first.campaign_seed,
            first.requested_runs,
            &position_of,
        )?;
    }
    let sources = by_index
        .iter()
        .flatten()
        .map(|&p| shards[p].identity.source.clone())
        .collect();
    let mut table = RunsTable::empty(shards[0].table.schema);
    for shard in shards {
        table.append(shard.table);
    }
    table.sort_by_key(|r| (r.run_index, position_of(&r.controller)));
    Ok(MergedCampaign {
        scenario_toml: first.scenario_toml,
        campaign_seed: first.campaign_seed,
        requested_runs: first.requested_runs,
        controllers: first.controllers,
        table,
        sources,
    })
}

/// Checks that `shard`'s column schema is the one its own `scenario.toml` flies
/// ([`RunsSchema::of`]: the lateral columns exactly when it flies the 3-D approach,
/// `[aircraft] model = "6dof"` with `approach.three_dimensional`), with each group's
/// values one per row ([`RunsTable::check_shape`]). The header of `runs.csv` alone
/// decides nothing: columns stripped from a 3-D shard, or appended to a 3-DOF one, are
/// refused, as is a `scenario.toml` that is empty or not a scenario.
fn check_columns_against_scenario(shard: &ShardRows) -> Result<(), MergeError> {
    let identity = &shard.identity;
    let bad = |field: &'static str, value: String, problem: String| MergeError::BadIdentity {
        location: identity.source.clone(),
        field,
        value,
        problem,
    };
    if identity.scenario_toml.trim().is_empty() {
        return Err(bad(
            "scenario.toml",
            "empty".to_owned(),
            "a shard's scenario.toml holds the whole scenario its campaign flew".to_owned(),
        ));
    }
    let scenario = load_scenario(&identity.scenario_toml, "scenario.toml").map_err(|error| {
        bad(
            "scenario.toml",
            "not a scenario".to_owned(),
            error.to_string(),
        )
    })?;
    let schema = RunsSchema::of(&scenario);
    if shard.table.schema != schema {
        return Err(bad(
            "runs.csv columns",
            shard.table.schema.holds().to_owned(),
            format!(
                "its scenario.toml (`aircraft.model` = \"{}\", \
                 `approach.three_dimensional` = {}) flies {}",
                scenario.aircraft.model.name(),
                scenario.approach.three_dimensional,
                schema.flown_by()
            ),
        ));
    }
    shard
        .table
        .check_shape()
        .map_err(|error| bad(error.field, error.value, error.problem))
}

/// Checks that `shard` says it is part of the campaign of `first`: the same scenario,
/// seed, run count, controllers and shard count.
fn check_same_campaign(first: &ShardIdentity, shard: &ShardRows) -> Result<(), MergeError> {
    let identity = &shard.identity;
    if identity.scenario_toml != first.scenario_toml {
        let (field, first_value, other_value) =
            first_difference(&first.scenario_toml, &identity.scenario_toml);
        return Err(MergeError::DifferentScenario {
            first: first.source.clone(),
            other: identity.source.clone(),
            field,
            first_value,
            other_value,
        });
    }
    let different =
        |field: &'static str, first_value: String, other_value: String| MergeError::Different {
            field,
            first: first.source.clone(),
            first_value,
            other: identity.source.clone(),
            other_value,
        };
    if identity.campaign_seed != first.campaign_seed {
        return Err(different(
            "campaign_seed",
            first.campaign_seed.to_string(),
            identity.campaign_seed.to_string(),
        ));
    }
    if identity.requested_runs != first.requested_runs {
        return Err(different(
            "requested_runs",
            first.requested_runs.to_string(),
            identity.requested_runs.to_string(),
        ));
    }
    if identity.controllers != first.controllers {
        return Err(different(
            "controllers",
            first.controllers.join(", "),
            identity.controllers.join(", "),
        ));
    }
    if identity.shard.count() != first.shard.count() {
        return Err(different(
            "shard count M",
            first.shard.to_string(),
            identity.shard.to_string(),
        ));
    }
    Ok(())
}

/// The position in `shards` of each shard 0 … `count` − 1; refuses a shard given twice
/// and names the shards missing.
fn index_shards(shards: &[ShardRows], count: u64) -> Result<Vec<Option<usize>>, MergeError> {
    let mut by_index: Vec<Option<usize>> = vec![None; usize::try_from(count).unwrap_or(0)];
    for (position, shard) in shards.iter().enumerate() {
        let identity = &shard.identity;
        let slot = usize::try_from(identity.shard.index())
            .ok()
            .and_then(|i| by_index.get_mut(i));
        let Some(slot) = slot else {
            continue; // a valid shard's index is within its count
        };
        if let Some(earlier) = *slot {
            return Err(MergeError::Overlapping {
                shard: identity.shard,
                first: shards[earlier].identity.source.clone(),
                other: identity.source.clone(),
            });
        }
        *slot = Some(position);
    }
    let missing = (0..count).filter(|&k| by_index.get(k as usize).is_none_or(Option::is_none));
    let total = missing.clone().count() as u64;
    if total > 0 {
        return Err(MergeError::MissingShards {
            missing: missing.take(LISTED_MISSING).collect(),
            total,
            count,
        });
    }
    Ok(by_index)
}

/// Checks that `shard` holds exactly its runs under every controller, each with its
/// run's seed; sorts its rows by run index and controller.
fn check_rows(
    shard: &mut ShardRows,
    campaign_seed: u64,
    runs: u64,
    position_of: &dyn Fn(&str) -> Option<usize>,
) -> Result<(), MergeError> {
    for (position, row) in shard.table.rows.iter().enumerate() {
        check_row(&shard.identity, position, &shard.table)?;
        check_row_belongs(&shard.identity, row, campaign_seed, runs, position_of)?;
    }
    shard
        .table
        .sort_by_key(|r| (r.run_index, position_of(&r.controller)));
    check_every_run_once(shard, runs, position_of)
}

/// The error for `row` of the shard `identity` that is not one of its runs.
fn foreign(identity: &ShardIdentity, row: &RunRow, problem: String) -> MergeError {
    MergeError::ForeignRow {
        location: identity.source.clone(),
        shard: identity.shard,
        run_index: row.run_index,
        controller: row.controller.to_string(),
        problem,
    }
}

/// Checks the values of the `position`-th row (from 0) of `table` against the row
/// schema, and those of its schema's other groups ([`RunsTable::check_row`]).
fn check_row(
    identity: &ShardIdentity,
    position: usize,
    table: &RunsTable,
) -> Result<(), MergeError> {
    let row = &table.rows[position];
    table
        .check_row(position)
        .map_err(|error| MergeError::BadRow {
            location: identity.source.clone(),
            row: position as u64 + 1,
            run_index: row.run_index,
            controller: row.controller.to_string(),
            error: Box::new(error),
        })
}

/// Checks that `row` is a run of the shard `identity`: within the campaign's `runs`,
/// of this shard, under a listed controller and with its run's seed.
fn check_row_belongs(
    identity: &ShardIdentity,
    row: &RunRow,
    campaign_seed: u64,
    runs: u64,
    position_of: &dyn Fn(&str) -> Option<usize>,
) -> Result<(), MergeError> {
    if row.run_index >= runs {
        return Err(foreign(
            identity,
            row,
            format!("is beyond the campaign's {runs} runs"),
        ));
    }
    if !identity.shard.contains(row.run_index) {
        return Err(foreign(
            identity,
            row,
            format!(
                "belongs to shard {}/{}",
                row.run_index % identity.shard.count(),
                identity.shard.count()
            ),
        ));
    }
    if position_of(&row.controller).is_none() {
        return Err(foreign(
            identity,
            row,
            "flies a controller the shard does not list".to_owned(),
        ));
    }
    let seed = run_seed(campaign_seed, row.run_index);
    if row.seed != seed {
        return Err(foreign(
            identity,
            row,
            format!(
                "has seed {} where campaign seed {campaign_seed} gives {seed}",
                row.seed
            ),
        ));
    }
    Ok(())
}

/// Checks that the sorted rows of `shard` are each of its runs under each controller,
/// once: none twice, none missing.
fn check_every_run_once(
    shard: &ShardRows,
    runs: u64,
    position_of: &dyn Fn(&str) -> Option<usize>,
) -> Result<(), MergeError> {
    let identity = &shard.identity;
    let variants = identity.controllers.len() as u64;
    let expected = identity.shard.runs_of(runs) * variants;
    let mut expected_keys = (0..identity.shard.runs_of(runs))
        .flat_map(|p| (0..variants).map(move |v| (identity.shard.run_index(p), v as usize)));
    let missing = |run_index: u64, variant: usize| MergeError::MissingRuns {
        location: identity.source.clone(),
        shard: identity.shard,
        expected,
        found: shard.table.rows.len() as u64,
        first_missing: run_index,
        controller: identity
            .controllers
            .get(variant)
            .cloned()
            .unwrap_or_default(),
    };
    let mut previous: Option<(u64, Option<usize>)> = None;
    for row in &shard.table.rows {
        let key = (row.run_index, position_of(&row.controller));
        if previous == Some(key) {
            return Err(foreign(identity, row, "appears twice".to_owned()));
        }
        previous = Some(key);
        let Some((run_index, variant)) = expected_keys.next() else {
            break;
        };
        if (run_index, Some(variant)) != key {
            return Err(missing(run_index, variant));
        }
    }
    match expected_keys.next() {
        Some((run_index, variant)) => Err(missing(run_index, variant)),
        None => Ok(()),
    }
}
