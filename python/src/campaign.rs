//! `deckland.campaign`: N approaches in parallel, as `deckland campaign` flies them.
//!
//! The same [`CampaignSpec`] and [`run_campaign`] as the CLI, so the runs (their seeds,
//! dispersions and results) and the runs table of `runs.csv` ([`RunsTable`]) are the
//! CLI's, bit for bit, for any number of threads. Ctrl-C stops the workers before their
//! next run and raises `KeyboardInterrupt`.
//!
//! `campaign_shard` flies one shard K/M (the runs i with i mod M = K) and returns it as
//! text that any process can carry (JSON, its rows as `runs.csv`, whose numbers read
//! back exactly); `merge_shards` checks and merges such shards with the library's
//! `merge_shards` into the campaign flown whole. `deckland.dask` maps shards over a
//! Dask cluster with them.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

use deckland::monte_carlo::{
    merge_shards, parse_runs_csv, run_campaign, runs_csv_text, CampaignResult, CampaignSpec,
    CampaignSummary, LateralStatistics, RunRecord, RunsSchema, RunsTable, Shard, ShardIdentity,
    ShardRows, TrapSheetStatistics, DEFAULT_TARGET_RATE, MAX_CAMPAIGN_SEED, MAX_THREADS,
    SHARD_SCHEME,
};
use deckland::scenario::load_scenario_in as load_scenario;
use deckland_cli::folders::CampaignReport;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::{Deserialize, Serialize};

use crate::columns::Columns;
use crate::convert::to_python;
use crate::errors::{argument_error, strict_integer, value_error};
use crate::folders::Destination;
use crate::scenario::Scenario;

/// The runs table as columns, in its schema's order (the columns of `runs.csv`, as the
/// CLI writes them), and the statistics of its lateral group's columns for the summary
/// (`None` when its schema has none).
#[allow(clippy::type_complexity)]
fn table_of(
    table: &RunsTable<'_>,
) -> PyResult<(
    Columns,
    Option<LateralStatistics>,
    Option<TrapSheetStatistics>,
)> {
    let columns = table.columns().map_err(value_error)?;
    let (statistics, trap_sheet) = table.lateral_statistics();
    Ok((columns, statistics, trap_sheet))
}

/// The most approaches of one campaign (per controller), and so the most shards: the
/// limit of `deckland campaign --runs` (a record of each run is kept, about 0.3 kB; 100 000
/// runs already give a rate to ±0.3 points).
pub(crate) const MAX_RUNS: u64 = deckland::monte_carlo::MAX_RUNS;

/// A whole number argument in [`min`, `max`], else `ValueError` naming it and the range.
pub(crate) fn whole(name: &str, value: i128, min: i128, max: u64) -> PyResult<u64> {
    match u64::try_from(value) {
        Ok(v) if value >= min && v <= max => Ok(v),
        _ => Err(argument_error(
            name,
            value,
            format_args!("a whole number in [{min}, {max}]"),
        )),
    }
}

/// What `campaign` and `merge_shards_text` return: the rows of `runs.csv` as a dict of
/// numpy arrays, the summary as `summary.json`, and the folder written, if any.
type Flown<'py> = (Bound<'py, PyDict>, Py<PyAny>, Option<String>);

/// Flies `runs` approaches of `scenario` (with its dispersions) in parallel; returns
/// `(runs, summary, folder)`: the rows of `runs.csv` as a dict of numpy arrays, the
/// summary as `summary.json`, and with `out` the folder written there as `deckland
/// campaign --out` writes it (`figures`: a `deckland.Figures`; `force`). `progress`, a
/// callable, is called as `progress(done, total)` with the runs flown at most every
/// 0.25 s and at the end.
#[pyfunction]
#[pyo3(signature = (scenario, runs, seed = None, threads = None, compare = false, progress = None, out = None, force = false, figures = None))]
#[allow(clippy::too_many_arguments)]
pub fn campaign<'py>(
    py: Python<'py>,
    scenario: PyRef<'_, Scenario>,
    runs: &Bound<'_, PyAny>,
    seed: Option<&Bound<'_, PyAny>>,
    threads: Option<&Bound<'_, PyAny>>,
    compare: bool,
    progress: Option<&Bound<'_, PyAny>>,
    out: Option<PathBuf>,
    force: bool,
    figures: Option<&Bound<'_, PyAny>>,
) -> PyResult<Flown<'py>> {
    let destination = Destination::of(out, force, figures)?;
    if let Some(progress) = progress.filter(|p| !p.is_callable()) {
        return Err(pyo3::exceptions::PyTypeError::new_err(format!(
            "`progress` = {progress}: expected a callable progress(done, total) or None"
        )));
    }
    let runs = whole("runs", strict_integer("runs", runs)?, 1, MAX_RUNS)?;
    let seed = seed.map(|s| strict_integer("seed", s)).transpose()?;
    let threads = threads.map(|t| strict_integer("threads", t)).transpose()?;
    let seed = match seed {
        Some(seed) => whole("seed", seed, 0, MAX_CAMPAIGN_SEED)?,
        None => scenario.scenario.seed,
    };
    let threads = match threads {
        Some(threads) => whole("threads", threads, 1, MAX_THREADS)? as usize,
        None => {
            std::thread::available_parallelism().map_or(1, |n| n.get().min(MAX_THREADS as usize))
        }
    };
    let mut spec = CampaignSpec::new(scenario.scenario, runs, seed);
    if compare {
        spec = spec.comparing_pitch_controllers();
    }
    let started = Instant::now();
    let result = fly(py, &spec, threads, progress)?;
    let elapsed_s = started.elapsed().as_secs_f64();

    let table = RunsTable::of_result(RunsSchema::of(&spec.scenario), &result);
    let (columns, lateral, trap_sheet) = table_of(&table)?;
    let summary = CampaignSummary::of_result(&result, seed, DEFAULT_TARGET_RATE);
    let report = CampaignReport {
        scenario_file: scenario.name.clone(),
        summary: &summary,
        threads: Some(threads),
        elapsed_s,
        runs_per_s: Some(result.records.len() as f64 / elapsed_s.max(1e-9)),
        shard: Shard::WHOLE.to_string(),
        shard_scheme: SHARD_SCHEME,
        merged_from: Vec::new(),
        lateral,
        trap_sheet,
    };
    let folder = match destination {
        None => None,
        Some(destination) => {
            let scenario_toml = toml::to_string(&spec.scenario).map_err(value_error)?;
            let contents = (&spec.scenario, scenario_toml.as_str());
            write_folder(py, destination, contents, &report, &table)?
        }
    };
    Ok((
        crate::columns::into_dict(columns, py)?,
        to_python(py, &report)?,
        folder,
    ))
}

/// Writes the campaign's folder at `destination` (the command line's files) from the
/// scenario and its TOML text; returns its path.
fn write_folder(
    py: Python<'_>,
    destination: Destination,
    (scenario, scenario_toml): (&deckland::scenario::Scenario, &str),
    report: &CampaignReport,
    table: &RunsTable,
) -> PyResult<Option<String>> {
    let written = destination.write(py, |request| {
        deckland_cli::folders::write_campaign(request, scenario, scenario_toml, report, table)
    })?;
    Ok(Some(written))
}

/// How often a campaign calls its `progress` callback at most.
const PROGRESS_INTERVAL: Duration = Duration::from_millis(250);

/// Flies `spec` on `threads` workers with the GIL released; Ctrl-C, or an exception
/// raised by `progress`, stops the workers and raises it. `progress(done, total)` is
/// called with the runs flown and the runs to fly at most every 0.25 s and once at the
/// end.
fn fly(
    py: Python<'_>,
    spec: &CampaignSpec,
    threads: usize,
    progress: Option<&Bound<'_, PyAny>>,
) -> PyResult<CampaignResult> {
    let stop = AtomicBool::new(false);
    let done = AtomicU64::new(0);
    let total = spec
        .shard
        .runs_of(spec.runs)
        .saturating_mul(spec.controllers.len() as u64);
    let progress = progress.map(|p| p.clone().unbind());
    let count = |_: &RunRecord| {
        done.fetch_add(1, Ordering::Relaxed);
    };
    let mut interrupted: Option<PyErr> = None;
    let result = py.detach(|| {
        std::thread::scope(|scope| {
            let worker = scope.spawn(|| run_campaign(spec, threads, &count, &stop));
            let mut reported = (Instant::now(), u64::MAX);
            loop {
                let finished = worker.is_finished();
                if interrupted.is_none() {
                    let now = done.load(Ordering::Relaxed);
                    let due = finished || reported.0.elapsed() >= PROGRESS_INTERVAL;
                    let call = progress.as_ref().filter(|_| due && now != reported.1);
                    let checked = Python::attach(|py| {
                        py.check_signals()?;
                        if let Some(callback) = call {
                            callback.call1(py, (now, total))?;
                        }
                        Ok::<(), PyErr>(())
                    });
                    if call.is_some() {
                        reported = (Instant::now(), now);
                    }
                    if let Err(error) = checked {
                        stop.store(true, Ordering::Relaxed);
                        interrupted = Some(error);
                    }
                }
                if finished {
                    break;
                }
                std::thread::sleep(Duration::from_millis(20));
            }
            worker.join()
        })
    });
    if let Some(error) = interrupted {
        return Err(error);
    }
    result
        .map_err(|_| value_error("the campaign's worker thread panicked"))?
        .map_err(|error| value_error(format!("cannot run the campaign: {error}")))
}

/// One shard as it travels between processes: what it is part of, and its rows as the
/// text of `runs.csv` (shortest round-trip numbers: they read back bit for bit).
#[derive(Debug, Serialize, Deserialize)]
struct ShardPayload {
    scenario_name: String,
    scenario_toml: String,
    campaign_seed: u64,
    requested_runs: u64,
    controllers: Vec<String>,
    shard: String,
    partial: bool,
    elapsed_s: f64,
    runs_csv: String,
}

/// Flies shard `index`/`count` of the campaign of `runs` approaches of `scenario` (the
/// runs i with i mod count = index); returns it as JSON text for `merge_shards`.
#[pyfunction]
#[pyo3(signature = (scenario, runs, index, count, seed = None, threads = None, compare = false))]
#[allow(clippy::too_many_arguments)]
pub fn campaign_shard(
    py: Python<'_>,
    scenario: PyRef<'_, Scenario>,
    runs: &Bound<'_, PyAny>,
    index: &Bound<'_, PyAny>,
    count: &Bound<'_, PyAny>,
    seed: Option<&Bound<'_, PyAny>>,
    threads: Option<&Bound<'_, PyAny>>,
    compare: bool,
) -> PyResult<String> {
    let runs = whole("runs", strict_integer("runs", runs)?, 1, MAX_RUNS)?;
    let (index, count) = (
        strict_integer("index", index)?,
        strict_integer("count", count)?,
    );
    let seed = seed.map(|s| strict_integer("seed", s)).transpose()?;
    let threads = threads
        .map(|t| strict_integer("threads", t))
        .transpose()?
        .unwrap_or(1);
    let count = whole("count", count, 1, MAX_RUNS)?;
    let index = whole("index", index, 0, count - 1)?;
    let shard = Shard::new(index, count)
        .and_then(|shard| shard.of_runs(runs))
        .map_err(value_error)?;
    let seed = match seed {
        Some(seed) => whole("seed", seed, 0, MAX_CAMPAIGN_SEED)?,
        None => scenario.scenario.seed,
    };
    let threads = whole("threads", threads, 1, MAX_THREADS)? as usize;
    let mut spec = CampaignSpec::new(scenario.scenario, runs, seed);
    if compare {
        spec = spec.comparing_pitch_controllers();
    }
    spec = spec.sharded(shard);
    let started = Instant::now();
    let result = fly(py, &spec, threads, None)?;
    let elapsed_s = started.elapsed().as_secs_f64();
    let table = RunsTable::of_result(RunsSchema::of(&spec.scenario), &result);
    let runs_csv = runs_csv_text(&table).map_err(value_error)?;
    let payload = ShardPayload {
        scenario_name: scenario.name.clone(),
        scenario_toml: toml::to_string(&spec.scenario).map_err(value_error)?,
        campaign_seed: seed,
        requested_runs: runs,
        controllers: result.controller_labels.clone(),
        shard: shard.to_string(),
        partial: result.partial,
        elapsed_s,
        runs_csv,
    };
    serde_json::to_string(&payload).map_err(value_error)
}

/// Merges shards made by `campaign_shard` (every shard of one campaign, in any order)
/// into the campaign flown whole; returns `(runs, summary, folder)` as `campaign` does,
/// with `out` writing the folder `deckland merge` writes. A shard
/// that is not one (its text, its run or shard count beyond the campaign's limits), of
/// another campaign, a missing, repeated or partial shard raises `ValueError` naming it.
#[pyfunction]
#[pyo3(signature = (shards, out = None, force = false, figures = None))]
pub fn merge_shards_text<'py>(
    py: Python<'py>,
    shards: Vec<String>,
    out: Option<PathBuf>,
    force: bool,
    figures: Option<&Bound<'_, PyAny>>,
) -> PyResult<Flown<'py>> {
    let destination = Destination::of(out, force, figures)?;
    let started = Instant::now();
    let mut parts = Vec::with_capacity(shards.len());
    let mut scenario_name = String::new();
    for (position, text) in shards.iter().enumerate() {
        let payload: ShardPayload = serde_json::from_str(text)
            .map_err(|e| value_error(format!("shard {position} is not a shard: {e}")))?;
        let shard: Shard = payload
            .shard
            .parse()
            .map_err(|e| value_error(format!("shard {position} is not a shard: {e}")))?;
        // Within the limits a campaign can be flown with: a forged count or run count
        // would size the merge's tables (10¹⁴ shards ask for petabytes).
        let within = |name: &str, value: u64| {
            whole(name, value.into(), 1, MAX_RUNS)
                .map_err(|e| value_error(format!("shard {position} ({shard}): {e}")))
        };
        within("shard count M", shard.count())?;
        within("requested_runs", payload.requested_runs)?;
        if shard.index() == 0 {
            scenario_name = payload.scenario_name.clone();
        }
        // The library's row schema: the columns, each field's type and range.
        let table = parse_runs_csv(&format!("shard {shard}"), &payload.runs_csv)
            .map_err(|e| value_error(e.to_string()))?;
        parts.push(ShardRows {
            identity: ShardIdentity {
                source: format!("shard {shard}"),
                scenario_toml: payload.scenario_toml,
                campaign_seed: payload.campaign_seed,
                requested_runs: payload.requested_runs,
                controllers: payload.controllers,
                shard,
                partial: payload.partial,
            },
            table,
        });
    }
    // Whatever a tampered shard does inside the library, it is a ValueError here, never
    // a PanicException.
    let (merged, summary) = catch_unwind(AssertUnwindSafe(|| {
        merge_shards(parts).map(|merged| {
            let summary = CampaignSummary::of_merged(&merged, DEFAULT_TARGET_RATE);
            (merged, summary)
        })
    }))
    .map_err(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown".to_owned());
        value_error(format!(
            "cannot merge: the shards are not a campaign ({message})"
        ))
    })?
    .map_err(|e| value_error(format!("cannot merge: {e}")))?;
    let (columns, lateral, trap_sheet) = table_of(&merged.table)?;
    let report = CampaignReport::merged(
        scenario_name.clone(),
        &summary,
        started.elapsed().as_secs_f64(),
        merged.sources.clone(),
        lateral,
        trap_sheet,
    );
    let folder = match destination {
        None => None,
        Some(destination) => {
            let scenario = load_scenario(
                &merged.scenario_toml,
                "the shards' scenario.toml",
                std::path::Path::new(""),
            )
            .map_err(|e| value_error(format!("cannot merge: {e}")))?;
            let contents = (&scenario, merged.scenario_toml.as_str());
            write_folder(py, destination, contents, &report, &merged.table)?
        }
    };
    Ok((
        crate::columns::into_dict(columns, py)?,
        to_python(py, &report)?,
        folder,
    ))
}
