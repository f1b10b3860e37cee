//! `deckland.fly`: one approach, recorded as `deckland land` and `deckland run` record it.

use std::path::PathBuf;

use deckland::experiments::{fly_approach, ApproachRun, APPROACH_RECORD_INTERVAL_S};
use deckland::recording::acmi::{write_acmi, AcmiReference};
use deckland::recording::TimeSeriesRecorder;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::errors::value_error;
use crate::folders::Destination;
use crate::outputs::{events_list, summary_dict, time_series};
use crate::scenario::{flown_scenario, scenario_or_default, Scenario};
use crate::stepping::{python_law_label, Stepper};

/// What `fly` returns to the Python package: the summary, the time series, the events,
/// the ACMI replay if asked for and the folder written, if any.
type Flown<'py> = (
    Py<PyAny>,
    Bound<'py, PyDict>,
    Bound<'py, PyList>,
    Option<String>,
    Option<String>,
);

/// Flies one approach; returns `(summary, time_series, events, acmi, folder)` with the
/// time series as a dict of numpy arrays (the Python package makes the DataFrame), with
/// `acmi` the approach as a Tacview ACMI 2.2 text (`deckland land --acmi`'s file), and
/// with `out` the folder written there as `deckland run --out` writes it (`plots`,
/// `figures`: a `deckland.Figures`, `force`).
#[pyfunction]
#[pyo3(signature = (scenario = None, seed = None, disperse = false, pitch_law = None, control_interval_s = 0.02, acmi = false, out = None, force = false, plots = true, figures = None))]
#[allow(clippy::too_many_arguments)]
pub fn fly<'py>(
    py: Python<'py>,
    scenario: Option<PyRef<'_, Scenario>>,
    seed: Option<i128>,
    disperse: bool,
    pitch_law: Option<Bound<'py, PyAny>>,
    control_interval_s: f64,
    acmi: bool,
    out: Option<PathBuf>,
    force: bool,
    plots: bool,
    figures: Option<Bound<'py, PyAny>>,
) -> PyResult<Flown<'py>> {
    let destination = Destination::of(out, force, figures.as_ref())?;
    let base = scenario_or_default(scenario);
    let flown = flown_scenario(&base.scenario, seed, disperse)?;
    let (run, controller) = match pitch_law {
        None => {
            let run = py
                .detach(|| fly_approach(&flown))
                .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
            (run, flown.control.pitch.label().to_owned())
        }
        Some(law) => {
            let label = python_law_label(&law)?;
            let mut stepper = Stepper::new(&flown, control_interval_s)?;
            let mut recorder = TimeSeriesRecorder::every(APPROACH_RECORD_INTERVAL_S);
            let lateral_columns = stepper.simulation().lateral_columns();
            while !stepper.ended() {
                let overrides = stepper.law_overrides(&law, None)?;
                stepper.advance(&mut recorder, &overrides);
            }
            let summary = recorder
                .summary
                .take()
                .ok_or_else(|| value_error("the approach ended without a summary"))?;
            let run = ApproachRun {
                samples: recorder.samples,
                events: recorder.events,
                summary,
                lateral_columns,
            };
            (run, label)
        }
    };
    let replay = acmi.then(|| {
        let reference = AcmiReference {
            deck_angle_deg: flown.environment.deck.deck_angle_deg,
            ..AcmiReference::default()
        };
        let title = format!("{controller}, seed {}", flown.seed);
        write_acmi(&reference, &title, &run.samples, &run.events, &run.summary)
    });
    let summary_dict = summary_dict(py, &run.summary, &controller, &base.name, flown.seed)?;
    let (time_series, events_list) = (time_series(py, &run)?, events_list(py, &run.events)?);
    let folder = match destination {
        None => None,
        Some(destination) => Some(destination.write(py, |request| {
            deckland_cli::folders::write_approach(
                request,
                &run,
                &flown,
                &controller,
                &base.name,
                plots,
                acmi,
            )
        })?),
    };
    Ok((summary_dict, time_series, events_list, replay, folder))
}
