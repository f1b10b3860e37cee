//! One environment: the Python class `_Env`.

use std::sync::Arc;

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::action::action_values;
use super::config::{config, EnvConfig};
use super::describe::describe;
use super::episode::{frame_array, seed_value, EnvCore};
use super::reward::OUTCOMES;
use crate::render::{draw_side_view, FRAME_HEIGHT, FRAME_WIDTH};
use crate::scenario::Scenario;

/// One environment (the Python class `deckland.env.CarrierLandingEnv` wraps it).
#[pyclass(name = "_Env", module = "deckland._deckland")]
pub struct Env {
    config: Arc<EnvConfig>,
    core: Option<EnvCore>,
    /// The episode's actions, one row after another (to copy the episode by replaying).
    actions: Vec<f64>,
}

#[pymethods]
impl Env {
    #[new]
    #[pyo3(signature = (scenario, control, control_interval_s, pitch_command_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps, rewards, reward, forecast, lateral_spans=None))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        scenario: Option<PyRef<'_, Scenario>>,
        control: &str,
        control_interval_s: f64,
        pitch_command_span_rad: f64,
        thrust_span_n: Option<f64>,
        elevator_span_rad: f64,
        climb_rate_span_mps: f64,
        rewards: &Bound<'_, PyDict>,
        reward: &str,
        forecast: bool,
        lateral_spans: Option<(f64, f64, f64, f64)>,
    ) -> PyResult<Self> {
        let config = config(
            scenario,
            control,
            control_interval_s,
            (
                pitch_command_span_rad,
                thrust_span_n,
                elevator_span_rad,
                climb_rate_span_mps,
            ),
            rewards,
            reward,
            forecast,
            None,
            lateral_spans,
        )?;
        Ok(Self {
            config: Arc::new(config),
            core: None,
            actions: Vec::new(),
        })
    }

    /// The spaces, the observation's table, the loops still flying, the trim.
    fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        describe(py, &self.config)
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
        let config = &self.config;
        let mut core = EnvCore::new(config, seed)?;
        let mut obs = vec![0.0f32; config.observation_len()];
        let mut raw = vec![0.0f64; config.observation_len()];
        let mut pilot = vec![0.0f32; config.action_len()];
        core.observe(config, &mut obs, &mut raw, &mut pilot);
        self.core = Some(core);
        self.actions.clear();
        Ok((
            obs.into_pyarray(py),
            raw.into_pyarray(py),
            pilot.into_pyarray(py),
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
        let config = &self.config;
        config.check_action(&action, "action")?;
        let Some(core) = self.core.as_mut() else {
            return Err(pyo3::exceptions::PyRuntimeError::new_err(
                "the environment has not been reset: call reset() first",
            ));
        };
        if core.outcome.is_some() {
            return Err(pyo3::exceptions::PyRuntimeError::new_err(
                "the episode has ended: call reset() first",
            ));
        }
        let result = core.step(config, &action);
        self.actions.extend_from_slice(&action);
        let mut obs = vec![0.0f32; config.observation_len()];
        let mut raw = vec![0.0f64; config.observation_len()];
        let mut pilot = vec![0.0f32; config.action_len()];
        core.observe(config, &mut obs, &mut raw, &mut pilot);
        let info = PyDict::new(py);
        info.set_item(pyo3::intern!(py, "raw"), raw.into_pyarray(py))?;
        info.set_item(
            pyo3::intern!(py, "autopilot_action"),
            pilot.into_pyarray(py),
        )?;
        if let Some((code, wire)) = core.outcome {
            info.set_item("outcome", OUTCOMES[code])?;
            info.set_item("wire", wire)?;
            info.set_item("reason", core.reason.clone())?;
            info.set_item("time_s", core.stepper.simulation().time_s())?;
            if config.lateral.is_some() {
                info.set_item("off_centre", core.off_centre)?;
            }
            if let Some((grade, comment)) = &core.lso {
                info.set_item("lso_grade", grade.name())?;
                info.set_item("lso_points", grade.points())?;
                info.set_item("lso_comment", comment)?;
            }
        }
        Ok((
            obs.into_pyarray(py),
            result.reward,
            result.terminated,
            result.truncated,
            info,
        ))
    }

    /// The side view of the approach now, (height, width, 3) uint8.
    fn render<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let config = &self.config;
        let frame = match self.core.as_mut() {
            Some(core) => {
                let look = core.stepper.look();
                draw_side_view(&config.scenario, &look.signals, core.waved_off)
            }
            None => vec![255; FRAME_HEIGHT * FRAME_WIDTH * 3],
        };
        frame_array(py, frame)
    }

    /// The actions of the episode so far, (steps, action entries) float64.
    fn actions<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let width = self.config.action_len();
        self.actions
            .clone()
            .into_pyarray(py)
            .reshape([self.actions.len() / width, width])
    }

    /// The seed of the episode (None before the first reset).
    #[getter]
    fn seed(&self) -> Option<u64> {
        self.core.as_ref().map(|c| c.seed)
    }

    /// The simulated time (s).
    #[getter]
    fn time_s(&self) -> f64 {
        self.core
            .as_ref()
            .map_or(0.0, |c| c.stepper.simulation().time_s())
    }
}
