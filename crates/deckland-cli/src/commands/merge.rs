//! `deckland merge`: the shard folders of a campaign (`deckland campaign --shard K/M`)
//! put together into the campaign folder of the campaign flown whole.
//!
//! Each shard folder says what it is part of: `scenario.toml` (the scenario flown, as
//! canonical TOML), and in `summary.json` the campaign seed, the run count, the
//! controllers, the shard `K/M` and whether it was stopped early (`partial`). Its rows
//! are read back from `runs.csv` (numbers are written in their shortest round-trip form,
//! so they read back exactly), with a 3-D campaign's lateral and trap-sheet columns. The library's `merge_shards` checks that the shards belong
//! to one campaign, cover it once and are complete, and sorts the rows; the rates,
//! intervals, upper bounds, percentiles and plots are then computed from the rows by the
//! same code as `deckland campaign`'s, so `runs.csv` and the statistics of
//! `summary.json` are those of the campaign flown whole, byte for byte.
//!
//! A folder without `summary.json` is a shard that never finished (killed before writing
//! its results): refused, as a partial shard is.
//!
//! Nothing in a shard folder is trusted: its files are read as regular files only and
//! with a size limit, its identity is checked against the campaign's limits (runs,
//! shards, controllers) and every row of `runs.csv` against the row schema of the library
//! (`parse_runs_csv`): an edited or damaged shard is refused, naming the file, the line
//! and the column, before any statistic or plot is computed.

use super::campaign::folder::{self, CampaignFolder, CampaignReport};
use super::campaign::report;
use super::common::{load_scenario_file, OutputArgs};
use crate::output::OutputDir;
use anyhow::{anyhow, bail, Context, Result};
use clap::Args;
use deckland::monte_carlo::{
    merge_shards, parse_runs_csv, CampaignSummary, Shard, ShardIdentity, ShardRows,
    DEFAULT_TARGET_RATE, MAX_RUNS_CSV_BYTES, MAX_SUMMARY_JSON_BYTES,
};
use deckland::scenario::{read_text_file, MAX_SCENARIO_FILE_BYTES};
use serde_json::Value;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Options of `deckland merge`.
#[derive(Debug, Clone, Args)]
pub struct MergeArgs {
    /// The shard folders (`deckland campaign --shard K/M --out DIR`), every K of one M, in
    /// any order.
    #[arg(required = true)]
    pub shards: Vec<PathBuf>,
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub figures: crate::plot::FigureArgs,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// One field of a shard's `summary.json`, or an error naming the file and the field.
fn field<'a>(summary: &'a Value, file: &Path, name: &str) -> Result<&'a Value> {
    summary
        .get(name)
        .ok_or_else(|| anyhow!("{}: no `{name}`", file.display()))
}

/// A whole-number field of a shard's `summary.json`.
fn whole(summary: &Value, file: &Path, name: &str) -> Result<u64> {
    let value = field(summary, file, name)?;
    value.as_u64().ok_or_else(|| {
        anyhow!(
            "{}: `{name}` is {value}, not a whole number",
            file.display()
        )
    })
}

/// A shard folder: what it is part of, its rows, its scenario file and the scenario.
struct ShardFolder {
    rows: ShardRows,
    scenario_file: String,
}

/// Reads the shard folder `folder`.
fn read_shard(folder: &Path) -> Result<ShardFolder> {
    let source = folder.display().to_string();
    if !folder.is_dir() {
        bail!("{source} is not a folder");
    }
    let summary_path = folder.join("summary.json");
    if !summary_path.is_file() {
        bail!(
            "{source} has no summary.json: not a campaign folder, or a shard that never \
             finished (stopped before writing its results); fly it again to merge it"
        );
    }
    let text = read_text_file(
        &summary_path,
        MAX_SUMMARY_JSON_BYTES,
        "shard's summary.json",
    )?;
    let summary: Value = serde_json::from_str(&text)
        .with_context(|| format!("{} is not JSON", summary_path.display()))?;
    let file = summary_path.as_path();
    let shard_text = field(&summary, file, "shard")?;
    let shard: Shard = shard_text
        .as_str()
        .ok_or_else(|| anyhow!("{}: `shard` is {shard_text}, not K/M", file.display()))?
        .parse()
        .with_context(|| format!("{}: `shard`", file.display()))?;
    let partial = field(&summary, file, "partial")?;
    let partial = partial.as_bool().ok_or_else(|| {
        anyhow!(
            "{}: `partial` is {partial}, not true or false",
            file.display()
        )
    })?;
    let controllers = field(&summary, file, "controllers")?
        .as_array()
        .ok_or_else(|| anyhow!("{}: `controllers` is not a list", file.display()))?
        .iter()
        .map(|c| {
            c.get("controller")
                .and_then(Value::as_str)
                .map(str::to_owned)
                .ok_or_else(|| anyhow!("{}: a controller has no name", file.display()))
        })
        .collect::<Result<Vec<_>>>()?;
    let scenario_file = field(&summary, file, "scenario_file")?
        .as_str()
        .unwrap_or_default()
        .to_owned();
    let scenario_path = folder.join("scenario.toml");
    let scenario_toml = read_text_file(&scenario_path, MAX_SCENARIO_FILE_BYTES, "scenario file")?;
    let runs_path = folder.join("runs.csv");
    let runs_text = read_text_file(&runs_path, MAX_RUNS_CSV_BYTES, "shard's runs.csv")?;
    let table = parse_runs_csv(&runs_path.display().to_string(), &runs_text)?;
    Ok(ShardFolder {
        rows: ShardRows {
            identity: ShardIdentity {
                source,
                scenario_toml,
                campaign_seed: whole(&summary, file, "campaign_seed")?,
                requested_runs: whole(&summary, file, "requested_runs")?,
                controllers,
                shard,
                partial,
            },
            table,
        },
        scenario_file,
    })
}

/// Runs `deckland merge`.
pub fn run(args: &MergeArgs) -> Result<()> {
    let started = Instant::now();
    let folders = args
        .shards
        .iter()
        .map(|folder| read_shard(folder))
        .collect::<Result<Vec<_>>>()?;
    // The scenario file named by shard 0 (they may differ in path between machines).
    let scenario_file = folders
        .iter()
        .find(|f| f.rows.identity.shard.index() == 0)
        .map(|f| f.scenario_file.clone())
        .unwrap_or_default();
    let merged = merge_shards(folders.into_iter().map(|f| f.rows).collect())
        .context("cannot merge the shards")?;
    let first_folder = merged
        .sources
        .first()
        .map(PathBuf::from)
        .ok_or_else(|| anyhow!("no shard to merge"))?;
    let scenario = load_scenario_file(&first_folder.join("scenario.toml"))?;
    let summary = CampaignSummary::of_merged(&merged, DEFAULT_TARGET_RATE);
    let output = OutputDir::prepare("merge", args.output.out.as_deref(), args.output.force)?;
    let (lateral, trap_sheet) = merged.table.lateral_statistics();
    let report = CampaignReport::merged(
        scenario_file.clone(),
        &summary,
        started.elapsed().as_secs_f64(),
        merged.sources.clone(),
        lateral,
        trap_sheet,
    );
    let folder = CampaignFolder {
        scenario: &scenario,
        scenario_toml: &merged.scenario_toml,
        table: &merged.table,
        report: &report,
        title: folder::title(Path::new(&scenario_file), &report),
    };
    report::write_folder(&folder, &output)?;
    if args.output.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        report::print_table(&report, &output)?;
    }
    Ok(())
}
