//! What a flown approach gives back, as Python objects: its summary (`summary.json`),
//! its time series (the columns of `approach.csv`) and its events.

use deckland::experiments::ApproachRun;
use deckland::simulation::{Event, RunSummary};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde::Serialize;

use crate::columns::Columns;
use crate::convert::to_python;
use crate::errors::value_error;

/// What `summary.json` holds (as `deckland land` and `run` write it): the run's summary
/// with what was flown.
#[derive(Debug, Serialize)]
pub(crate) struct LandingReport<'a> {
    /// Pitch controller label.
    pub controller: &'a str,
    /// The scenario's name: `adverse` for the default, the file name for a file.
    pub conditions: &'a str,
    /// Seed of the random streams.
    pub seed: u64,
    /// Outcome name.
    pub outcome: &'static str,
    /// The run's summary.
    #[serde(flatten)]
    pub summary: &'a RunSummary,
}

/// The summary dict of a run (`summary.json`).
pub(crate) fn summary_dict(
    py: Python<'_>,
    summary: &RunSummary,
    controller: &str,
    conditions: &str,
    seed: u64,
) -> PyResult<Py<PyAny>> {
    to_python(
        py,
        &LandingReport {
            controller,
            conditions,
            seed,
            outcome: summary.outcome.name(),
            summary,
        },
    )
}

/// The recorded signals of `run` as the columns of `approach.csv`.
pub(crate) fn time_series<'py>(py: Python<'py>, run: &ApproachRun) -> PyResult<Bound<'py, PyDict>> {
    let mut table = Columns::with_capacity(run.samples.len());
    for row in run.rows() {
        table.push(&row).map_err(value_error)?;
    }
    crate::columns::into_dict(table, py)
}

/// The events as a list of dicts (`{"event": "touchdown", "time_s": …, …}`).
pub(crate) fn events_list<'py>(py: Python<'py>, events: &[Event]) -> PyResult<Bound<'py, PyList>> {
    let list = PyList::empty(py);
    for event in events {
        list.append(to_python(py, event)?)?;
    }
    Ok(list)
}
