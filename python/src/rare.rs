//! `deckland.rare`: the probability per approach of a catastrophe by splitting, as
//! `deckland rare` (docs/rare-events.md); and its Dask form's two halves: one repetition
//! flown on a worker (`rare_repetition`), and the estimate driven from batches of them
//! (`rare_batched`).

use deckland::monte_carlo::{MAX_CAMPAIGN_SEED, MAX_THREADS};
use deckland::rare::{
    estimate_rate, estimate_rate_batched, fly_repetition, AmsError, Branch, EventParticle, Outcome,
    PartialReason, RareEvent, RareRequest, Run,
};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt};

use crate::campaign::whole;
use crate::convert::to_python;
use crate::errors::{strict_integer, value_error};
use crate::folders::Destination;
use crate::scenario::Scenario;

/// A real number argument: a float or an int, not a bool or anything else (`TypeError`
/// naming it, as for the whole-number arguments).
fn real(name: &str, value: &Bound<'_, PyAny>) -> PyResult<f64> {
    let is_number = value.is_instance_of::<PyFloat>()
        || (value.is_instance_of::<PyInt>() && !value.is_instance_of::<PyBool>());
    if !is_number {
        return Err(PyTypeError::new_err(format!(
            "`{name}` = {} is not allowed: expected a real number (a float or an int, not a \
             bool or string)",
            value
                .repr()
                .map_or_else(|_| "?".to_owned(), |r| r.to_string())
        )));
    }
    value.extract::<f64>()
}

/// The request of the arguments that `deckland.rare` shares with its Dask form, and the
/// thread count: each checked and defaulted as `deckland rare` does.
#[allow(clippy::too_many_arguments)]
fn request_of(
    scenario: &Scenario,
    event: &str,
    threshold: Option<&Bound<'_, PyAny>>,
    target_rel_error: Option<&Bound<'_, PyAny>>,
    max_runs: Option<&Bound<'_, PyAny>>,
    particles: Option<&Bound<'_, PyAny>>,
    seed: Option<&Bound<'_, PyAny>>,
    threads: Option<&Bound<'_, PyAny>>,
    calibrate_score: Option<&Bound<'_, PyAny>>,
) -> PyResult<(RareRequest, usize)> {
    let event = RareEvent::from_name(event).map_err(value_error)?;
    let defaults = RareRequest::new(event, scenario.scenario.seed);
    let integer = |name: &str, value: Option<&Bound<'_, PyAny>>, min, max, default| match value {
        Some(v) => whole(name, strict_integer(name, v)?, min, max),
        None => Ok(default),
    };
    let request = RareRequest {
        threshold: threshold.map(|t| real("threshold", t)).transpose()?,
        target_rel_error: target_rel_error
            .map(|t| real("target_rel_error", t))
            .transpose()?
            .unwrap_or(defaults.target_rel_error),
        max_runs: integer("max_runs", max_runs, 1, 1_000_000_000, defaults.max_runs)?,
        particles: integer(
            "particles",
            particles,
            4,
            100_000,
            defaults.particles as u64,
        )? as usize,
        seed: integer("seed", seed, 0, MAX_CAMPAIGN_SEED, defaults.seed)?,
        calibration_runs: integer("calibrate_score", calibrate_score, 0, 100_000, 0)?,
        ..defaults
    };
    let default_threads =
        std::thread::available_parallelism().map_or(1, |n| n.get().min(MAX_THREADS as usize));
    let threads = integer("threads", threads, 1, MAX_THREADS, default_threads as u64)? as usize;
    Ok((request, threads))
}

/// The probability per approach of a catastrophe, by splitting, as ``deckland rare``.
///
/// ``event`` is ``"ramp_strike"``, ``"hard_landing"``, ``"off_centre"`` (3-D approach),
/// ``"divergence"`` or ``"lost"`` (any of them); ``threshold`` moves it (a ramp clearance
/// below it in m, a touchdown sink rate or offset above it). Splitting stops at
/// ``target_rel_error`` (default 0.1, checked from 32 repetitions on) or once
/// ``max_runs`` approaches' worth is spent (default 100 000). Returns the dict that
/// ``deckland rare`` writes as ``summary.json`` (without the folder and the time): the
/// estimate under ``estimate`` (``probability``, ``interval``,
/// ``relative_standard_error``, ``stop``), each repetition's ``levels``, the approaches
/// spent and those a plain campaign would need. The result does not depend on
/// ``threads``; a bad argument or a budget too small raises ``ValueError``.
///
/// With ``out``, the folder ``deckland rare --out`` writes is written there (the summary,
/// ``levels.csv``, the levels' plot, ``save_flights`` flights that reached the event
/// with their plots, default 3, at most 20, and ``report.html``), and the dict's
/// ``folder`` names it; ``force`` and ``figures`` as for :func:`fly`.
///
/// ``calibrate_score`` (``ramp_strike`` and ``lost`` only; default 0, the plain score):
/// flights that calibrate the ramp's score first, as ``--calibrate-score``.
#[pyfunction]
#[pyo3(signature = (scenario, event, threshold = None, target_rel_error = None, max_runs = None, particles = None, seed = None, threads = None, *, calibrate_score = None, out = None, force = false, save_flights = None, figures = None))]
#[allow(clippy::too_many_arguments)]
pub fn rare(
    py: Python<'_>,
    scenario: PyRef<'_, Scenario>,
    event: &str,
    threshold: Option<&Bound<'_, PyAny>>,
    target_rel_error: Option<&Bound<'_, PyAny>>,
    max_runs: Option<&Bound<'_, PyAny>>,
    particles: Option<&Bound<'_, PyAny>>,
    seed: Option<&Bound<'_, PyAny>>,
    threads: Option<&Bound<'_, PyAny>>,
    calibrate_score: Option<&Bound<'_, PyAny>>,
    out: Option<std::path::PathBuf>,
    force: bool,
    save_flights: Option<&Bound<'_, PyAny>>,
    figures: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let destination = Destination::of(out, force, figures)?;
    let save_flights = match save_flights {
        Some(count) => whole(
            "save_flights",
            strict_integer("save_flights", count)?,
            0,
            MAX_SAVED_FLIGHTS,
        )? as usize,
        None => 3,
    };
    let (request, threads) = request_of(
        &scenario,
        event,
        threshold,
        target_rel_error,
        max_runs,
        particles,
        seed,
        threads,
        calibrate_score,
    )?;
    let flown = scenario.scenario;
    let started = std::time::Instant::now();
    let result = py.detach(|| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| e.to_string())?;
        pool.install(|| estimate_rate(&flown, &request, |_, _| {}))
            .map_err(|e| e.to_string())
    });
    let result = result.map_err(|e| value_error(format!("cannot estimate the rate: {e}")))?;
    let elapsed_s = started.elapsed().as_secs_f64();
    let folder = destination
        .map(|destination| {
            destination.write(py, |request| {
                deckland_cli::folders::write_rare(request, &flown, &result, save_flights, elapsed_s)
            })
        })
        .transpose()?;
    let dict = to_python(py, &result)?;
    if let Some(folder) = folder {
        dict.bind(py).set_item("folder", folder)?;
    }
    Ok(dict)
}

/// The most flights that reached the event a folder saves (`deckland rare
/// --save-flights` keeps at most this many).
const MAX_SAVED_FLIGHTS: u64 = 20;

/// Repetition `repetition` of `deckland.rare(scenario, event, ...)` flown here on at most
/// `share` steps and `threads` threads: a Dask task. Returns the run as plain Python
/// values (`run_from_python` reads it back, every number exact).
#[pyfunction]
#[pyo3(signature = (scenario, event, repetition, share, threshold = None, particles = None, seed = None, threads = None, calibrate_score = None))]
#[allow(clippy::too_many_arguments)]
pub fn rare_repetition(
    py: Python<'_>,
    scenario: PyRef<'_, Scenario>,
    event: &str,
    repetition: u64,
    share: u64,
    threshold: Option<&Bound<'_, PyAny>>,
    particles: Option<&Bound<'_, PyAny>>,
    seed: Option<&Bound<'_, PyAny>>,
    threads: Option<&Bound<'_, PyAny>>,
    calibrate_score: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    let (request, threads) = request_of(
        &scenario,
        event,
        threshold,
        None,
        None,
        particles,
        seed,
        threads,
        calibrate_score,
    )?;
    let flown = scenario.scenario;
    let run = py.detach(|| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| e.to_string())?;
        pool.install(|| fly_repetition(&flown, &request, repetition, share))
            .map_err(|e| e.to_string())
    });
    let run = run.map_err(|e| value_error(format!("cannot fly the repetition: {e}")))?;
    run_to_python(py, &run)
}

/// `deckland.rare`'s estimate with each batch of repetitions flown by
/// `run_batch(first, size, share)`, which returns the runs of repetitions `first` …
/// `first + size − 1` as `rare_repetition` gives them, in order: the same result to the
/// bit. An exception of `run_batch` ends the estimate with it.
#[pyfunction]
#[pyo3(signature = (scenario, event, run_batch, threshold = None, target_rel_error = None, max_runs = None, particles = None, seed = None, calibrate_score = None))]
#[allow(clippy::too_many_arguments)]
pub fn rare_batched(
    py: Python<'_>,
    scenario: PyRef<'_, Scenario>,
    event: &str,
    run_batch: &Bound<'_, PyAny>,
    threshold: Option<&Bound<'_, PyAny>>,
    target_rel_error: Option<&Bound<'_, PyAny>>,
    max_runs: Option<&Bound<'_, PyAny>>,
    particles: Option<&Bound<'_, PyAny>>,
    seed: Option<&Bound<'_, PyAny>>,
    calibrate_score: Option<&Bound<'_, PyAny>>,
) -> PyResult<Py<PyAny>> {
    if !run_batch.is_callable() {
        return Err(PyTypeError::new_err(format!(
            "`run_batch` = {run_batch}: expected a callable run_batch(first, size, share)"
        )));
    }
    let (request, _) = request_of(
        &scenario,
        event,
        threshold,
        target_rel_error,
        max_runs,
        particles,
        seed,
        None,
        calibrate_score,
    )?;
    let mut failure: Option<PyErr> = None;
    let batch = |repetitions: std::ops::Range<u64>, share: u64| {
        let size = repetitions.end - repetitions.start;
        let runs = run_batch
            .call1((repetitions.start, size, share))
            .and_then(|list| {
                list.try_iter()?
                    .map(|item| run_from_python(&item?))
                    .collect::<PyResult<Vec<Run>>>()
            });
        match runs {
            Ok(runs) => runs.into_iter().map(Ok).collect(),
            Err(error) => {
                let message = error.to_string();
                failure.get_or_insert(error);
                repetitions
                    .map(|_| Err(AmsError::Batch(message.clone())))
                    .collect()
            }
        }
    };
    let result = estimate_rate_batched(&scenario.scenario, &request, batch, |_, _| {});
    if let Some(error) = failure {
        return Err(error);
    }
    let result = result.map_err(|e| value_error(format!("cannot estimate the rate: {e}")))?;
    to_python(py, &result)
}

/// A run as plain Python values, every number exact (a float for each f64, infinities
/// included): `(estimate, (outcome, level, limit), iterations, levels, killed, steps,
/// trajectories, reached, events)`, an event `(index, max, [(step, key), ...])`.
fn run_to_python(py: Python<'_>, run: &Run) -> PyResult<Py<PyAny>> {
    let outcome = match run.outcome {
        Outcome::Converged => ("converged", 0.0, 0u64),
        Outcome::Extinct { level } => ("extinct", level, 0),
        Outcome::Partial(PartialReason::StepBudget { budget }) => ("step_budget", 0.0, budget),
        Outcome::Partial(PartialReason::MaxIterations { limit }) => ("max_iterations", 0.0, limit),
    };
    let events: Vec<EventValues> = run
        .events
        .iter()
        .map(|e| {
            let lineage = e.lineage.iter().map(|b| (b.step, b.key)).collect();
            (e.index, e.max, lineage)
        })
        .collect();
    let value = (
        run.estimate,
        outcome,
        run.iterations,
        run.levels.clone(),
        run.killed.clone(),
        run.steps,
        run.trajectories,
        run.reached,
        events,
    );
    Ok(value.into_pyobject(py)?.into_any().unbind())
}

/// A final particle as plain values: its index, maximum and lineage of (step, key).
type EventValues = (usize, f64, Vec<(usize, u64)>);

/// A run as plain values ([`run_to_python`]).
type RunValues = (
    Option<f64>,
    (String, f64, u64),
    u64,
    Vec<f64>,
    Vec<usize>,
    u64,
    u64,
    usize,
    Vec<EventValues>,
);

/// The run that [`run_to_python`] wrote (`ValueError` for anything else).
fn run_from_python(value: &Bound<'_, PyAny>) -> PyResult<Run> {
    let (
        estimate,
        (outcome, level, limit),
        iterations,
        levels,
        killed,
        steps,
        trajectories,
        reached,
        events,
    ): RunValues = value.extract().map_err(|e| {
        value_error(format!(
            "a repetition came back as something other than a run: {e}"
        ))
    })?;
    let outcome = match outcome.as_str() {
        "converged" => Outcome::Converged,
        "extinct" => Outcome::Extinct { level },
        "step_budget" => Outcome::Partial(PartialReason::StepBudget { budget: limit }),
        "max_iterations" => Outcome::Partial(PartialReason::MaxIterations { limit }),
        other => {
            return Err(value_error(format!(
                "a repetition came back with outcome {other:?}"
            )))
        }
    };
    let events = events
        .into_iter()
        .map(|(index, max, lineage)| EventParticle {
            index,
            max,
            lineage: lineage
                .into_iter()
                .map(|(step, key)| Branch { step, key })
                .collect(),
        })
        .collect();
    Ok(Run {
        estimate,
        outcome,
        iterations,
        levels,
        killed,
        steps,
        trajectories,
        reached,
        events,
    })
}
