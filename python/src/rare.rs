//! `deckland.rare`: the probability per approach of a catastrophe by splitting, as
//! `deckland rare` (docs/rare-events.md).

use deckland::monte_carlo::{MAX_CAMPAIGN_SEED, MAX_THREADS};
use deckland::rare::{estimate_rate, RareEvent, RareRequest};
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt};

use crate::campaign::whole;
use crate::convert::to_python;
use crate::errors::{strict_integer, value_error};
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

/// Estimates the probability per approach of `event` in `scenario` by adaptive
/// multilevel splitting; returns the result as `deckland rare` writes `summary.json`.
#[pyfunction]
#[pyo3(signature = (scenario, event, threshold = None, target_rel_error = None, max_runs = None, particles = None, seed = None, threads = None))]
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
) -> PyResult<Py<PyAny>> {
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
        ..defaults
    };
    let default_threads =
        std::thread::available_parallelism().map_or(1, |n| n.get().min(MAX_THREADS as usize));
    let threads = integer("threads", threads, 1, MAX_THREADS, default_threads as u64)? as usize;
    let flown = scenario.scenario;
    let result = py.detach(|| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .map_err(|e| e.to_string())?;
        pool.install(|| estimate_rate(&flown, &request, |_, _| {}))
            .map_err(|e| e.to_string())
    });
    let result = result.map_err(|e| value_error(format!("cannot estimate the rate: {e}")))?;
    to_python(py, &result)
}
