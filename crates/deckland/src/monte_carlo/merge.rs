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
//! against the row schema ([`RunRow::check`]). [`parse_runs_csv`] reads a shard's
//! `runs.csv` text with the same checks (the exact columns, a last line that ends, every
//! row), naming the line and the column at fault, so that every front end (the CLI's
//! `merge`, Python, Dask) refuses the same inputs with the same words.

use super::limits::{
    check_runs, MAX_CONTROLLERS, MAX_CONTROLLER_LABEL_BYTES, MAX_RUNS, MAX_SHARDS,
};
use super::row::{RowError, RunRow, RUN_COLUMNS};
use super::seeds::run_seed;
use super::shard::Shard;

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

/// One shard: what it is and its rows.
#[derive(Debug, Clone, PartialEq)]
pub struct ShardRows {
    /// What the shard is part of.
    pub identity: ShardIdentity,
    /// Its rows (`runs.csv`), in any order.
    pub rows: Vec<RunRow<'static>>,
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
    /// Every run's rows, sorted by run index and controller.
    pub rows: Vec<RunRow<'static>>,
    /// The shards' sources, by shard index (the first is shard 0).
    pub sources: Vec<String>,
}

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
    /// A row no campaign can write (see [`RunRow::check`]).
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

/// Reads the rows of a shard's `runs.csv` text (`location` names it in messages):
/// exactly the columns of [`RUN_COLUMNS`] in order, a last line that ends (a file cut
/// short is refused, even inside a row's text), and every row one a campaign can write
/// ([`RunRow::check`]). Every error names the line and the column at fault.
pub fn parse_runs_csv(location: &str, text: &str) -> Result<Vec<RunRow<'static>>, MergeError> {
    let at = |line: u64, problem: String| MergeError::RunsCsv {
        location: location.to_owned(),
        line,
        problem,
    };
    let header = text
        .lines()
        .next()
        .unwrap_or_default()
        .trim_end_matches('\r');
    let columns: Vec<&str> = header.split(',').collect();
    if columns != RUN_COLUMNS {
        let position = RUN_COLUMNS
            .iter()
            .zip(&columns)
            .position(|(a, b)| a != b)
            .unwrap_or(columns.len().min(RUN_COLUMNS.len()));
        let problem = match (RUN_COLUMNS.get(position), columns.get(position)) {
            (Some(expected), Some(found)) => {
                format!(
                    "column {} is `{found}` where a campaign writes `{expected}`",
                    position + 1
                )
            }
            (Some(expected), None) => format!("the column `{expected}` is missing"),
            (None, Some(found)) => format!("`{found}` is not a column of a campaign"),
            (None, None) => "no header".to_owned(),
        };
        return Err(at(
            1,
            format!("{problem} (the header is `{}`)", RUN_COLUMNS.join(",")),
        ));
    }
    if !text.ends_with('\n') {
        let lines = text.lines().count() as u64;
        return Err(at(
            lines,
            "the last line does not end: the file is cut short (truncated?)".to_owned(),
        ));
    }
    let most_rows = MAX_RUNS * MAX_CONTROLLERS as u64;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(text.as_bytes());
    let mut rows = Vec::new();
    for (position, row) in reader.deserialize::<RunRow<'static>>().enumerate() {
        let number = position as u64 + 1;
        if number > most_rows {
            return Err(at(
                number + 1,
                format!("more than {most_rows} rows: more than a campaign has"),
            ));
        }
        let row = row.map_err(|error| {
            let line = error.position().map_or(number + 1, |p| p.line());
            let column = match error.kind() {
                csv::ErrorKind::Deserialize { err, .. } => err
                    .field()
                    .and_then(|f| RUN_COLUMNS.get(f as usize))
                    .map(|c| format!("`{c}`: "))
                    .unwrap_or_default(),
                _ => String::new(),
            };
            let message = match error.kind() {
                csv::ErrorKind::Deserialize { err, .. } => err.kind().to_string(),
                csv::ErrorKind::UnequalLengths { len, .. } => format!(
                    "{len} fields where a campaign writes {}: is the row cut short?",
                    RUN_COLUMNS.len()
                ),
                _ => error.to_string(),
            };
            at(line, format!("{column}{message}"))
        })?;
        if let Err(error) = row.check() {
            return Err(MergeError::BadRow {
                location: location.to_owned(),
                row: number,
                run_index: row.run_index,
                controller: row.controller.to_string(),
                error: Box::new(error),
            });
        }
        rows.push(row);
    }
    Ok(rows)
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
    }
    for shard in &shards {
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
    }
    let count = first.shard.count();
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
    if let Some(partial) = shards.iter().find(|s| s.identity.partial) {
        return Err(MergeError::Partial {
            location: partial.identity.source.clone(),
            shard: partial.identity.shard,
        });
    }
    let variants = first.controllers.len() as u64;
    let position_of = |label: &str| first.controllers.iter().position(|c| c == label);
    for shard in &mut shards {
        check_rows(
            shard,
            first.campaign_seed,
            first.requested_runs,
            variants,
            &position_of,
        )?;
    }
    let sources = by_index
        .iter()
        .flatten()
        .map(|&p| shards[p].identity.source.clone())
        .collect();
    let mut rows: Vec<RunRow<'static>> = shards.into_iter().flat_map(|s| s.rows).collect();
    rows.sort_by_key(|r| (r.run_index, position_of(&r.controller)));
    Ok(MergedCampaign {
        scenario_toml: first.scenario_toml,
        campaign_seed: first.campaign_seed,
        requested_runs: first.requested_runs,
        controllers: first.controllers,
        rows,
        sources,
    })
}

/// Checks that `shard` holds exactly its runs under every controller, each with its
/// run's seed; sorts its rows by run index and controller.
fn check_rows(
    shard: &mut ShardRows,
    campaign_seed: u64,
    runs: u64,
    variants: u64,
    position_of: &dyn Fn(&str) -> Option<usize>,
) -> Result<(), MergeError> {
    let identity = &shard.identity;
    let foreign = |row: &RunRow, problem: String| MergeError::ForeignRow {
        location: identity.source.clone(),
        shard: identity.shard,
        run_index: row.run_index,
        controller: row.controller.to_string(),
        problem,
    };
    for (position, row) in shard.rows.iter().enumerate() {
        if let Err(error) = row.check() {
            return Err(MergeError::BadRow {
                location: identity.source.clone(),
                row: position as u64 + 1,
                run_index: row.run_index,
                controller: row.controller.to_string(),
                error: Box::new(error),
            });
        }
        if row.run_index >= runs {
            return Err(foreign(
                row,
                format!("is beyond the campaign's {runs} runs"),
            ));
        }
        if !identity.shard.contains(row.run_index) {
            return Err(foreign(
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
                row,
                "flies a controller the shard does not list".to_owned(),
            ));
        }
        let seed = run_seed(campaign_seed, row.run_index);
        if row.seed != seed {
            return Err(foreign(
                row,
                format!(
                    "has seed {} where campaign seed {campaign_seed} gives {seed}",
                    row.seed
                ),
            ));
        }
    }
    shard
        .rows
        .sort_by_key(|r| (r.run_index, position_of(&r.controller)));
    let expected = identity.shard.runs_of(runs) * variants;
    let mut expected_keys = (0..identity.shard.runs_of(runs))
        .flat_map(|p| (0..variants).map(move |v| (identity.shard.run_index(p), v as usize)));
    let mut previous: Option<(u64, Option<usize>)> = None;
    for row in &shard.rows {
        let key = (row.run_index, position_of(&row.controller));
        if previous == Some(key) {
            return Err(foreign(row, "appears twice".to_owned()));
        }
        previous = Some(key);
        let Some((run_index, variant)) = expected_keys.next() else {
            break;
        };
        if (run_index, Some(variant)) != key {
            let controller = shard
                .identity
                .controllers
                .get(variant)
                .cloned()
                .unwrap_or_default();
            return Err(MergeError::MissingRuns {
                location: identity.source.clone(),
                shard: identity.shard,
                expected,
                found: shard.rows.len() as u64,
                first_missing: run_index,
                controller,
            });
        }
    }
    if let Some((run_index, variant)) = expected_keys.next() {
        return Err(MergeError::MissingRuns {
            location: identity.source.clone(),
            shard: identity.shard,
            expected,
            found: shard.rows.len() as u64,
            first_missing: run_index,
            controller: identity
                .controllers
                .get(variant)
                .cloned()
                .unwrap_or_default(),
        });
    }
    Ok(())
}
