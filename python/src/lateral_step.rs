//! `deckland.lateral_step`: a bank-angle or sideslip step of the 6-DOF aircraft with the
//! lateral laws (`deckland step --axis roll|yaw`): the report its `--json` prints and the
//! columns of its `step.csv`, as a Python dictionary and numpy arrays.

use deckland::experiments::{
    fly_lateral_step, LateralAxis, LateralSample, LateralSetup, LateralStep, LateralStepReport,
};
use deckland::scenario::{HardwareSet, MAX_SEED};
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::to_python;
use crate::errors::{argument_error, value_error};
use crate::scenario::{scenario_or_default, Scenario};

/// The controllers `controller` names, as (law name, column prefix).
fn controllers(controller: &str) -> PyResult<Vec<(&'static str, &'static str)>> {
    const OPD: (&str, &str) = ("observer_pd", "opd");
    const PID: (&str, &str) = ("pid", "pid");
    match controller {
        "opd" => Ok(vec![OPD]),
        "pid" => Ok(vec![PID]),
        "both" => Ok(vec![OPD, PID]),
        other => Err(argument_error(
            "controller",
            format_args!("{other:?}"),
            "\"opd\", \"pid\" or \"both\"",
        )),
    }
}

/// Flies a 10° bank step (or `step_deg` of bank or sideslip on `axis`, `roll` or `yaw`)
/// for `seconds` in `conditions` (`ideal` or `adverse`, seeded by `seed`) with the
/// `controller` (`opd`, `pid` or `both`) on both channels, on `scenario`'s 6-DOF aircraft
/// and its `[control.roll]`/`[control.yaw]` laws (the default scenario when `None`).
/// Returns `(report, columns)`: the dictionary `deckland step --axis AXIS --json` prints
/// (without `output_folder`) and the columns of its `step.csv` as numpy arrays.
#[pyfunction]
#[pyo3(signature = (axis = "roll", step_deg = 10.0, seconds = 8.0, conditions = "ideal", seed = 1, controller = "both", scenario = None))]
#[allow(clippy::too_many_arguments)]
pub fn lateral_step<'py>(
    py: Python<'py>,
    axis: &str,
    step_deg: f64,
    seconds: f64,
    conditions: &str,
    seed: i128,
    controller: &str,
    scenario: Option<PyRef<'_, Scenario>>,
) -> PyResult<(Py<PyAny>, Bound<'py, PyDict>)> {
    let axis = match axis {
        "roll" => LateralAxis::Roll,
        "yaw" => LateralAxis::Yaw,
        other => {
            return Err(argument_error(
                "axis",
                format_args!("{other:?}"),
                "\"roll\" or \"yaw\"",
            ))
        }
    };
    let adverse = match conditions {
        "ideal" => false,
        "adverse" => true,
        other => {
            return Err(argument_error(
                "conditions",
                format_args!("{other:?}"),
                "\"ideal\" or \"adverse\"",
            ))
        }
    };
    let seed = u64::try_from(seed)
        .ok()
        .filter(|s| *s <= MAX_SEED)
        .ok_or_else(|| {
            argument_error(
                "seed",
                seed,
                format_args!("an integer in [0, {MAX_SEED}] (2⁶³ − 1)"),
            )
        })?;
    if !(step_deg.is_finite() && step_deg != 0.0 && step_deg.abs() <= 30.0) {
        return Err(argument_error(
            "step_deg",
            step_deg,
            "a nonzero bank or sideslip step (deg) with |step_deg| <= 30",
        ));
    }
    let names = controllers(controller)?;
    let scenario = scenario_or_default(scenario).scenario;
    if scenario.hardware == HardwareSet::Paper {
        return Err(value_error(
            "a scenario with `hardware = \"paper\"` has no lateral axes: the paper's set \
             flies the 3-DOF model",
        ));
    }
    let step = LateralStep {
        adverse,
        seed,
        ..LateralStep::new(axis, step_deg, seconds)
    };
    let (setup, runs) = py
        .detach(|| -> Result<_, String> {
            let setup = LateralSetup::from_scenario(&scenario).map_err(|e| e.to_string())?;
            let runs = names
                .iter()
                .map(|(name, _)| {
                    let (roll, yaw) = setup
                        .scenario_laws(&scenario, name)
                        .map_err(|e| e.to_string())?;
                    fly_lateral_step(&setup, &step, roll.as_ref(), yaw.as_ref())
                        .map_err(|e| e.to_string())
                })
                .collect::<Result<Vec<_>, String>>()?;
            Ok((setup, runs))
        })
        .map_err(value_error)?;
    let rows = runs.iter().map(|r| r.samples.len()).max().unwrap_or(0);
    let columns = PyDict::new(py);
    let longest = runs.iter().find(|r| r.samples.len() == rows);
    let time: Vec<f64> = (0..rows)
        .map(|i| longest.map_or(f64::NAN, |r| r.samples[i].time_s))
        .collect();
    columns.set_item("time_s", PyArray1::from_vec(py, time))?;
    for (run, (_, prefix)) in runs.iter().zip(&names) {
        for (index, column) in LateralSample::COLUMNS.iter().enumerate() {
            let values: Vec<f64> = (0..rows)
                .map(|i| run.samples.get(i).map_or(f64::NAN, |s| s.values()[index]))
                .collect();
            columns.set_item(format!("{prefix}_{column}"), PyArray1::from_vec(py, values))?;
        }
    }
    let report = LateralStepReport::new(
        &setup,
        &step,
        runs.into_iter().map(|r| r.response).collect(),
    );
    Ok((to_python(py, &report)?, columns))
}
