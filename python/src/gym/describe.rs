//! The description of a configuration: the spaces, the observation's table, the trim.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use super::config::EnvConfig;
use super::observation::OBSERVATIONS;
use super::reward::OUTCOMES;
use crate::scenario::Scenario;

/// The description of a configuration, shared by both classes' getters.
pub(super) fn describe<'py>(py: Python<'py>, config: &EnvConfig) -> PyResult<Bound<'py, PyDict>> {
    let dict = PyDict::new(py);
    let offsets = config.offsets();
    let scales = config.scales();
    let bounds = config.bounds();
    let table = PyList::empty(py);
    for i in 0..config.observation_len() {
        let o = OBSERVATIONS[i];
        let row = PyDict::new(py);
        row.set_item("name", o.name)?;
        row.set_item("unit", o.unit)?;
        row.set_item("source", o.source)?;
        row.set_item("offset", offsets[i])?;
        row.set_item("scale", scales[i])?;
        row.set_item("low", bounds[i].0)?;
        row.set_item("high", bounds[i].1)?;
        table.append(row)?;
    }
    dict.set_item("observations", table)?;
    dict.set_item("actions", config.control.action_names().to_vec())?;
    dict.set_item("built_in_loops", config.control.built_in_loops().to_vec())?;
    dict.set_item("outcomes", OUTCOMES.to_vec())?;
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
    dict.set_item("trim", trim)?;
    let spans = PyDict::new(py);
    spans.set_item("pitch_command_span_rad", config.pitch_span_rad)?;
    spans.set_item("thrust_span_n", config.thrust_span_n)?;
    spans.set_item("elevator_span_rad", config.elevator_span_rad)?;
    spans.set_item("climb_rate_span_mps", config.climb_rate_span_mps)?;
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
