//! `deckland campaign`: N approaches of a scenario file in parallel (Monte Carlo).
//!
//! Run `i` flies seed SplitMix64(S, i) (`deckland::monte_carlo::run_seed`) with the
//! scenario's dispersions drawn from that seed, on a pool of `--threads` workers; the
//! results are sorted by run index, so every file except the timing in `summary.json` is
//! identical for any thread count. Writes into the output folder:
//!
//! - `scenario.toml`: the nominal scenario flown;
//! - `runs.csv`: one row per run and controller (outcome, wire, touchdown, ramp
//!   clearance, glide-path error, the dispersions drawn, the failure reason), and the
//!   same rows as `runs.parquet`;
//! - `summary.json`: outcome rates with 95 % Wilson score intervals and exact 95 % upper
//!   bounds, the runs needed to show a target rate, touchdown distance and sink-rate
//!   mean, standard deviation and percentiles, and the calibration of the forecast's
//!   probabilities at the commit point (`calibration`), per controller;
//! - plots: `touchdown_dispersion` (touchdown point along the deck against sink rate,
//!   with the wires and the ramp), `touchdown_histograms`, `outcomes`.
//!
//! The runs table's column schema (`monte_carlo::RunsSchema`) is decided once from the
//! scenario. A 3-D approach campaign's has the lateral group: each run's lateral
//! touchdown and trap sheet (`monte_carlo::LateralRow`) in `runs.csv` and
//! `runs.parquet`, and their statistics (`lateral`, `trap_sheet`) in `summary.json`, the
//! terminal and `report.html`, and the `touchdown_plan` plot.
//!
//! `--shard K/M` flies only the runs i with i mod M = K (round robin: every shard is a
//! sample of the whole campaign and the shards differ by one run at most); the folder
//! says which shard it is, and `deckland merge` puts the M folders together into the
//! campaign flown whole ([`merge`](super::merge)).
//!
//! Ctrl-C or SIGTERM stops the workers before their next run; the finished runs are
//! written, marked `"partial": true`, and the command exits with status 130.
//!
//! `--runs` is at most [`MAX_RUNS`] and `--threads` at most [`MAX_THREADS`]: the records
//! of every run are kept in memory, and threads beyond the cores buy nothing.

pub mod calibration;
pub mod folder;
pub mod greenie;
pub mod paired;
pub mod report;
pub mod trap_sheet;

use super::common::{check_set_up, load_scenario_file, seed_parser, OutputArgs};
use crate::output::OutputDir;
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::monte_carlo::{
    run_campaign, CampaignSpec, CampaignSummary, RunRecord, RunsSchema, RunsTable, Shard,
    DEFAULT_TARGET_RATE, SHARD_SCHEME,
};
use deckland::scenario::Mission;
use folder::{CampaignFolder, CampaignReport};
use std::path::PathBuf;
use std::time::Instant;

/// Options of `deckland campaign`.
#[derive(Debug, Clone, Args)]
pub struct CampaignArgs {
    /// Scenario file (TOML); its `[dispersion]` section sets the per-run dispersions.
    pub scenario: PathBuf,
    /// Number of approaches (per controller with `--compare`), 1 to 100 000.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_RUNS), allow_negative_numbers = true)]
    pub runs: u64,
    /// Campaign seed S, 0 to 2⁶³ − 1; run i flies seed SplitMix64(S, i) (default: the
    /// scenario's seed).
    #[arg(long, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: Option<u64>,
    /// Worker threads, 1 to 256 (default: the number of CPUs). The results do not depend
    /// on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=MAX_THREADS), allow_negative_numbers = true)]
    pub threads: Option<u16>,
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub figures: crate::plot::FigureArgs,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
    /// Fly the same seeds and dispersions under O-PD and PID and report them side by side.
    #[arg(long)]
    pub compare: bool,
    /// Fly only shard K/M of the campaign: the runs i with i mod M = K. Shards are
    /// numbered from 0, like the runs: K from 0 to M − 1, so three shards are 0/3, 1/3
    /// and 2/3 (3/3 is refused). `deckland merge` puts the M shard folders together.
    #[arg(long, value_parser = clap::builder::ValueParser::new(parse_shard), allow_hyphen_values = true)]
    pub shard: Option<Shard>,
}

/// `K/M`, refused with the library's reason.
fn parse_shard(text: &str) -> Result<Shard, String> {
    text.parse::<Shard>().map_err(|e| e.to_string())
}

/// Most approaches of one campaign (per controller): the library's limit, the same for
/// every front end.
pub const MAX_RUNS: u64 = deckland::monte_carlo::MAX_RUNS;

/// Most worker threads: the library's limit, the same for every front end.
pub const MAX_THREADS: i64 = deckland::monte_carlo::MAX_THREADS as i64;

/// `--threads`, else the number of CPUs (at most [`MAX_THREADS`]).
pub fn threads_or_cpus(threads: Option<u16>) -> usize {
    threads.map_or_else(
        || {
            std::thread::available_parallelism()
                .map(|n| n.get())
                .unwrap_or(1)
                .min(MAX_THREADS as usize)
        },
        usize::from,
    )
}

/// Runs `deckland campaign`.
pub fn run(args: &CampaignArgs) -> Result<()> {
    let scenario = load_scenario_file(&args.scenario)?;
    if !matches!(scenario.mission, Mission::Approach) {
        bail!(
            "{}: `mission.kind` is not \"approach\": a campaign flies approaches",
            args.scenario.display()
        );
    }
    // The nominal scenario must fly; a dispersed run that cannot is a row of the result.
    check_set_up(&scenario)?;
    let seed = args.seed.unwrap_or(scenario.seed);
    let mut spec = CampaignSpec::new(scenario, args.runs, seed);
    if args.compare {
        spec = spec.comparing_pitch_controllers();
    }
    let threads = threads_or_cpus(args.threads);
    let shard = args.shard.unwrap_or(Shard::WHOLE).of_runs(args.runs)?;
    spec = spec.sharded(shard);
    let output = OutputDir::prepare("campaign", args.output.out.as_deref(), args.output.force)?;
    let total = shard
        .runs_of(args.runs)
        .saturating_mul(spec.controllers.len() as u64);
    let bar = crate::progress::Progress::counted("campaign", total, "runs");
    let stop = crate::interrupt::graceful_stop();
    let started = Instant::now();
    let result = run_campaign(&spec, threads, &|_: &RunRecord| bar.inc(1), stop)
        .context("cannot run the campaign")?;
    let elapsed_s = started.elapsed().as_secs_f64();
    bar.finish_and_clear();

    let summary = CampaignSummary::of_result(&result, seed, DEFAULT_TARGET_RATE);
    let finished_runs = result.records.len() as u64;
    let table = RunsTable::of_result(RunsSchema::of(&spec.scenario), &result);
    let (lateral, trap_sheet) = table.lateral_statistics();
    let report = CampaignReport {
        lateral,
        trap_sheet,
        scenario_file: args.scenario.display().to_string(),
        summary: &summary,
        threads: Some(threads),
        elapsed_s,
        runs_per_s: Some(finished_runs as f64 / elapsed_s.max(1e-9)),
        shard: shard.to_string(),
        shard_scheme: SHARD_SCHEME,
        merged_from: Vec::new(),
    };
    let scenario_toml =
        toml::to_string(&spec.scenario).context("cannot write the scenario as TOML")?;
    let folder = CampaignFolder {
        scenario: &spec.scenario,
        scenario_toml: &scenario_toml,
        table: &table,
        report: &report,
        title: folder::title(&args.scenario, &report),
    };
    report::write_folder(&folder, &output)?;
    if args.output.json {
        outln!("{}", json_naming_the_folder(&report, &output)?)?;
    } else {
        report::print_statistics(&report)?;
        let controllers: Vec<&str> = summary
            .controllers
            .iter()
            .map(|s| s.controller.as_str())
            .collect();
        if let Some(paired) = paired::PairedComparison::of(&table.rows, &controllers) {
            report::print_paired(&paired)?;
        }
        outln!("  results in {}", output.path().display())?;
    }
    if result.partial {
        warnln!(
            "campaign stopped by Ctrl-C or SIGTERM: partial results ({finished_runs} of {total} runs) in {}",
            output.path().display()
        );
        std::process::exit(crate::interrupt::INTERRUPTED_STATUS);
    }
    Ok(())
}

/// `report` as the JSON `--json` prints: `summary.json`'s fields and `output_folder`,
/// where the files went.
fn json_naming_the_folder(report: &CampaignReport, output: &OutputDir) -> Result<String> {
    let mut json = serde_json::to_value(report)?;
    if let serde_json::Value::Object(fields) = &mut json {
        fields.insert(
            "output_folder".to_owned(),
            serde_json::Value::String(output.path().display().to_string()),
        );
    }
    Ok(serde_json::to_string_pretty(&json)?)
}
