//! `deckland.campaign`: N approaches in parallel, as `deckland campaign` flies them.
//!
//! The same [`CampaignSpec`] and [`run_campaign`] as the CLI, so the runs (their seeds,
//! dispersions and results) and the rows of `runs.csv` ([`RunRow`]) are the CLI's, bit
//! for bit, for any number of threads. Ctrl-C stops the workers before their next run
//! and raises `KeyboardInterrupt`.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use deckland::monte_carlo::{run_campaign, CampaignSpec, RunRecord, RunRow};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use serde::Serialize;

use crate::columns::Columns;
use crate::convert::to_python;
use crate::errors::{argument_error, value_error};
use crate::scenario::Scenario;

/// What the summary holds: the keys of the CLI's `summary.json`.
#[derive(Debug, Serialize)]
struct CampaignReport<'a> {
    scenario_file: &'a str,
    campaign_seed: u64,
    seed_derivation: &'static str,
    requested_runs: u64,
    finished_runs: u64,
    partial: bool,
    partial_note: Option<String>,
    threads: usize,
    elapsed_s: f64,
    runs_per_s: f64,
    confidence_interval: &'static str,
    percentiles: &'static str,
    controllers: &'a [deckland::monte_carlo::CampaignStatistics],
}

/// A whole number argument ≥ `min`, else `ValueError` naming it.
fn whole(name: &str, value: i128, min: i128, max: u64) -> PyResult<u64> {
    match u64::try_from(value) {
        Ok(v) if value >= min && v <= max => Ok(v),
        _ => Err(argument_error(
            name,
            value,
            format_args!("a whole number in [{min}, {max}]"),
        )),
    }
}

/// Flies `runs` approaches of `scenario` (with its dispersions) in parallel; returns
/// `(runs, summary)`: the rows of `runs.csv` as a dict of numpy arrays, and the summary
/// as `summary.json`.
#[pyfunction]
#[pyo3(signature = (scenario, runs, seed = None, threads = None, compare = false))]
pub fn campaign<'py>(
    py: Python<'py>,
    scenario: PyRef<'_, Scenario>,
    runs: i128,
    seed: Option<i128>,
    threads: Option<i128>,
    compare: bool,
) -> PyResult<(Bound<'py, PyDict>, Py<PyAny>)> {
    let runs = whole("runs", runs, 1, u64::MAX)?;
    let seed = match seed {
        Some(seed) => whole("seed", seed, 0, u64::MAX)?,
        None => scenario.scenario.seed,
    };
    let threads = match threads {
        Some(threads) => whole("threads", threads, 1, 1024)? as usize,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let mut spec = CampaignSpec::new(scenario.scenario, runs, seed);
    if compare {
        spec = spec.comparing_pitch_controllers();
    }
    let stop = AtomicBool::new(false);
    let started = Instant::now();
    let mut interrupted: Option<PyErr> = None;
    let result = py.detach(|| {
        std::thread::scope(|scope| {
            let worker = scope.spawn(|| run_campaign(&spec, threads, &|_: &RunRecord| {}, &stop));
            while !worker.is_finished() {
                std::thread::sleep(Duration::from_millis(20));
                if interrupted.is_none() {
                    if let Err(error) = Python::attach(|py| py.check_signals()) {
                        stop.store(true, Ordering::Relaxed);
                        interrupted = Some(error);
                    }
                }
            }
            worker.join()
        })
    });
    if let Some(error) = interrupted {
        return Err(error);
    }
    let result = result
        .map_err(|_| value_error("the campaign's worker thread panicked"))?
        .map_err(|error| value_error(format!("cannot run the campaign: {error}")))?;
    let elapsed_s = started.elapsed().as_secs_f64();

    let mut table = Columns::with_capacity(result.records.len());
    for record in &result.records {
        table
            .push(&RunRow::new(record, &result.controller_labels))
            .map_err(value_error)?;
    }
    let statistics = result.statistics();
    let finished_runs = result.records.len() as u64;
    let report = CampaignReport {
        scenario_file: &scenario.name,
        campaign_seed: seed,
        seed_derivation: "run i (from 0) flies seed SplitMix64 output i of the campaign seed, \
                          shifted right by one bit (mix(S + (i + 1)·0x9e3779b97f4a7c15) >> 1); \
                          its dispersions come from that seed's \"dispersion\" stream; \
                          `deckland run FILE --seed SEED --disperse` flies it again",
        requested_runs: runs,
        finished_runs,
        partial: result.partial,
        partial_note: None,
        threads,
        elapsed_s,
        runs_per_s: finished_runs as f64 / elapsed_s.max(1e-9),
        confidence_interval: "95 % Wilson score interval of each rate",
        percentiles: "linear interpolation between closest ranks (Hyndman & Fan type 7)",
        controllers: &statistics,
    };
    Ok((crate::columns::into_dict(table, py)?, to_python(py, &report)?))
}
