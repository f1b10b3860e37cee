//! The description of a configuration: the spaces, the observation's table, the trim.

use deckland::metrics::lso_grade::Grade;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use super::config::EnvConfig;
use super::reward::OUTCOMES;
use crate::scenario::Scenario;

/// The description of a configuration, shared by both classes' getters.
pub(super) fn describe<'py>(py: Python<'py>, config: &EnvConfig) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let scaling = config.entry_scaling();
    let bounds = config.bounds();
    let table = PyList::empty(py);
    for (i, o) in config.observation_specs().enumerate() {
        let row = PyDict::new(py);
        row.set_item("name", o.name)?;
        row.set_item("unit", o.unit)?;
        row.set_item("source", o.source)?;
        row.set_item("offset", scaling[i].0)?;
        row.set_item("scale", scaling[i].1)?;
        row.set_item("low", bounds[i].0)?;
        row.set_item("high", bounds[i].1)?;
        table.append(row)?;
    }
    dict.set_item("observations", table)?;
    dict.set_item("actions", config.action_names.clone())?;
    dict.set_item("built_in_loops", config.built_in_loops.clone())?;
    dict.set_item("outcomes", OUTCOMES.to_vec())?;
    // The LSO's grades by code (the vector environment's grade codes) and their points.
    dict.set_item("lso_grades", Grade::ALL.map(Grade::name).to_vec())?;
    dict.set_item("lso_points", Grade::ALL.map(Grade::points).to_vec())?;
    dict.set_item("control_interval_s", config.interval_s)?;
    dict.set_item("max_time_s", config.scenario.max_time_s)?;
    let trim = PyDict::new(py);
    trim.set_item("theta_rad", config.theta_trim_rad)?;
    trim.set_item("elevator_rad", config.elevator_trim_rad)?;
    trim.set_item("thrust_n", config.thrust_trim_n)?;
    trim.set_item("alpha_rad", config.alpha_trim_rad)?;
    trim.set_item("climb_rate_mps", config.climb_rate_trim_mps)?;
    trim.set_item("max_thrust_n", config.max_thrust_n)?;
    trim.set_item("max_direct_lift", config.max_direct_lift)?;
    let spans = PyDict::new(py);
    spans.set_item("pitch_command_span_rad", config.pitch_span_rad)?;
    spans.set_item("thrust_span_n", config.thrust_span_n)?;
    spans.set_item("elevator_span_rad", config.elevator_span_rad)?;
    spans.set_item("climb_rate_span_mps", config.climb_rate_span_mps)?;
    for (key, value) in &config.lateral.spans {
        spans.set_item(key, value)?;
    }
    for (key, value) in &config.lateral.trim {
        trim.set_item(key, value)?;
    }
    dict.set_item("trim", trim)?;
    dict.set_item("spans", spans)?;
    dict.set_item(
        "scenario",
        Scenario {
            scenario: config.scenario,
            name: config.name.clone(),
        },
    )?;
    Ok(dict)
}
