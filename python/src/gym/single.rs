//! One environment: the Python class `_Env`, one lane of [`Lanes`] stepped on the
//! calling thread.

use std::sync::Arc;

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::action::action_values;
use super::config::Config;
use super::episode::{seed_value, EnvCore};
use super::reward::{EndInfo, OUTCOMES};
use super::vector::Lanes;

/// One environment (the Python class `deckland.env.CarrierLandingEnv` wraps it).
#[pyclass(name = "_Env", module = "deckland._deckland")]
pub struct Env {
    /// One lane.
    lanes: Lanes,
    /// The episode's actions, one row after another (to copy the episode by replaying).
    actions: Vec<f64>,
}

#[pymethods]
impl Env {
    /// The environment of `config`.
    #[new]
    fn new(config: &Config) -> PyResult<Self> {
        Ok(Self {
            lanes: Lanes::new(1, Arc::clone(&config.0), false)?,
            actions: Vec::new(),
        })
    }

    /// The spaces, the observation's table, the loops still flying, the trim.
    fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.lanes.describe(py)
    }

    /// Starts an episode with `seed`: (observation, raw observation, autopilot action).
    #[allow(clippy::type_complexity)]
    fn reset<'py>(
        &mut self,
        py: Python<'py>,
        seed: i128,
    ) -> PyResult<(
        Bound<'py, PyArray1<f32>>,
        Bound<'py, PyArray1<f64>>,
        Bound<'py, PyArray1<f32>>,
    )> {
        let seed = seed_value(seed)?;
        let out = self.lanes.run(py, &[], &[Some(seed)])?;
        self.actions.clear();
        Ok((
            out.observations.into_pyarray(py),
            out.raw.into_pyarray(py),
            out.pilot.into_pyarray(py),
        ))
    }

    /// One step: (observation, reward, terminated, truncated, info).
    #[allow(clippy::type_complexity)]
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        action: &Bound<'py, PyAny>,
    ) -> PyResult<(
        Bound<'py, PyArray1<f32>>,
        f64,
        bool,
        bool,
        Bound<'py, PyDict>,
    )> {
        let action = action_values(action)?;
        self.lanes.config.check_action(&action, "action")?;
        match self.lanes.core(0) {
            None => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "the environment has not been reset: call reset() first",
                ))
            }
            Some(core) if core.outcome.is_some() => {
                return Err(pyo3::exceptions::PyRuntimeError::new_err(
                    "the episode has ended: call reset() first",
                ))
            }
            Some(_) => {}
        }
        let out = self.lanes.run(py, &action, &[None])?;
        self.actions.extend_from_slice(&action);
        let info = PyDict::new(py);
        info.set_item(pyo3::intern!(py, "raw"), out.raw.into_pyarray(py))?;
        info.set_item(
            pyo3::intern!(py, "autopilot_action"),
            out.pilot.into_pyarray(py),
        )?;
        if let Some(core) = self.lanes.core(0) {
            if let Some((code, wire)) = core.outcome {
                for entry in &self.lanes.config.end_info {
                    end_info(&info, *entry, core, code, wire)?;
                }
                if let Some((grade, comment)) = &core.lso {
                    info.set_item("lso_grade", grade.name())?;
                    info.set_item("lso_points", grade.points())?;
                    info.set_item("lso_comment", comment)?;
                }
            }
        }
        Ok((
            out.observations.into_pyarray(py),
            out.rewards[0],
            out.terminated[0],
            out.truncated[0],
            info,
        ))
    }

    /// The side view of the approach now, (height, width, 3) uint8.
    fn render<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<u8>>> {
        self.lanes.render(py, 0)
    }

    /// The actions of the episode so far, (steps, action entries) float64.
    fn actions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let width = self.lanes.config.action_len();
        self.actions
            .clone()
            .into_pyarray(py)
            .reshape([self.actions.len() / width, width])
    }

    /// The seed of the episode (None before the first reset).
    #[getter]
    fn seed(&self) -> Option<u64> {
        self.lanes.core(0).map(|c| c.seed)
    }

    /// The simulated time (s).
    #[getter]
    fn time_s(&self) -> f64 {
        self.lanes
            .core(0)
            .map_or(0.0, |c| c.stepper.simulation().time_s())
    }
}

/// Sets `entry` of the `info` of a step that ended `core`'s episode with the outcome
/// `code` and `wire`.
fn end_info(
    info: &Bound<'_, PyDict>,
    entry: EndInfo,
    core: &EnvCore,
    code: usize,
    wire: Option<u8>,
) -> PyResult<()> {
    match entry {
        EndInfo::Outcome => info.set_item("outcome", OUTCOMES[code]),
        EndInfo::Wire => info.set_item("wire", wire),
        EndInfo::Reason => info.set_item("reason", core.reason.clone()),
        EndInfo::TimeS => info.set_item("time_s", core.stepper.simulation().time_s()),
        EndInfo::OffCentre => info.set_item("off_centre", core.off_centre),
    }
}
