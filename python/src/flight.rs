//! `deckland.fly`: one approach, recorded as `deckland land` and `deckland run` record it.

use deckland::experiments::{fly_approach, ApproachRow, APPROACH_RECORD_INTERVAL_S};
use deckland::random::RandomStreams;
use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::{Mission, Scenario as RustScenario};
use deckland::simulation::{Event, RunSummary, Signals};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use serde::Serialize;

use crate::approach::{python_law_label, Stepper};
use crate::columns::Columns;
use crate::convert::to_python;
use crate::errors::value_error;
use crate::scenario::{scenario_or_default, with_seed, Scenario};

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

/// The recorded signals as the columns of `approach.csv`.
pub(crate) fn time_series<'py>(
    py: Python<'py>,
    samples: &[Signals],
) -> PyResult<Bound<'py, PyDict>> {
    let mut table = Columns::with_capacity(samples.len());
    for sample in samples {
        table
            .push(&ApproachRow::from(sample))
            .map_err(value_error)?;
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

/// The scenario a flight flies: the seed given (else the scenario's), the dispersions
/// drawn from that seed as a campaign run draws them when `disperse`, as an approach.
pub(crate) fn flight_scenario(
    scenario: &RustScenario,
    seed: Option<i128>,
    disperse: bool,
) -> PyResult<RustScenario> {
    let mut scenario = with_seed(*scenario, seed)?;
    if disperse {
        let draw = scenario
            .dispersion
            .sample(&RandomStreams::new(scenario.seed));
        scenario = draw.apply(&scenario);
    }
    Ok(RustScenario {
        mission: Mission::Approach,
        ..scenario
    })
}

/// Flies one approach; returns `(summary, time_series, events)` with the time series
/// as a dict of numpy arrays (the Python package makes the DataFrame).
#[pyfunction]
#[pyo3(signature = (scenario = None, seed = None, disperse = false, pitch_law = None, control_interval_s = 0.02))]
pub fn fly<'py>(
    py: Python<'py>,
    scenario: Option<PyRef<'_, Scenario>>,
    seed: Option<i128>,
    disperse: bool,
    pitch_law: Option<Bound<'py, PyAny>>,
    control_interval_s: f64,
) -> PyResult<(Py<PyAny>, Bound<'py, PyDict>, Bound<'py, PyList>)> {
    let base = scenario_or_default(scenario);
    let flown = flight_scenario(&base.scenario, seed, disperse)?;
    let (summary, samples, events, controller) = match pitch_law {
        None => {
            let run = py
                .detach(|| fly_approach(&flown))
                .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
            let label = flown.control.pitch.label().to_owned();
            (run.summary, run.samples, run.events, label)
        }
        Some(law) => {
            let label = python_law_label(&law)?;
            let mut stepper = Stepper::new(&flown, control_interval_s)?;
            let mut recorder = TimeSeriesRecorder::every(APPROACH_RECORD_INTERVAL_S);
            while !stepper.ended() {
                let overrides = stepper.law_overrides(&law, None)?;
                stepper.advance(&mut recorder, &overrides);
            }
            let summary = recorder
                .summary
                .take()
                .ok_or_else(|| value_error("the approach ended without a summary"))?;
            (summary, recorder.samples, recorder.events, label)
        }
    };
    Ok((
        summary_dict(py, &summary, &controller, &base.name, flown.seed)?,
        time_series(py, &samples)?,
        events_list(py, &events)?,
    ))
}
