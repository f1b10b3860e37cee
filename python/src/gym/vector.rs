//! Many environments of one configuration stepped in one call: the Python class `_VecEnv`.

use std::sync::Arc;

use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods};
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use rayon::prelude::*;

use super::config::{config, EnvConfig};
use super::describe::describe;
use super::episode::{frame_array, seed_value, EnvCore, StepResult};
use crate::errors::{argument_error, value_error};
use crate::render::{draw_side_view, FRAME_HEIGHT, FRAME_WIDTH};
use crate::scenario::Scenario;

/// Many environments of one configuration, stepped in one call over threads.
#[pyclass(name = "_VecEnv", module = "deckland._deckland")]
pub struct VecEnv {
    config: Arc<EnvConfig>,
    cores: Vec<Option<EnvCore>>,
}

/// What `_VecEnv.step` returns.
type VecStep<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<i8>>,
    Bound<'py, PyArray1<i8>>,
);

#[pymethods]
impl VecEnv {
    #[new]
    #[pyo3(signature = (num_envs, scenario, control, control_interval_s, pitch_command_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps, rewards, reward, forecast, max_episode_steps))]
    #[allow(clippy::too_many_arguments)]
    fn new(
        num_envs: usize,
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
        max_episode_steps: Option<u64>,
    ) -> PyResult<Self> {
        if !(1..=100_000).contains(&num_envs) {
            return Err(argument_error(
                "num_envs",
                num_envs,
                "an integer in [1, 100000]",
            ));
        }
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
            max_episode_steps,
        )?;
        Ok(Self {
            config: Arc::new(config),
            cores: (0..num_envs).map(|_| None).collect(),
        })
    }

    /// The spaces, the observation's table, the loops still flying, the trim.
    fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        describe(py, &self.config)
    }

    /// Steps every environment: those with `reset[i]` start again with `seeds[i]` (their
    /// action is ignored, reward 0), the others take their row of `actions`. Returns
    /// (observations, rewards, terminated, truncated, raw observations, autopilot actions,
    /// outcome codes (−1: running), wires (−1: none)).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        actions: &Bound<'py, PyAny>,
        reset: Vec<bool>,
        seeds: Vec<i128>,
    ) -> PyResult<VecStep<'py>> {
        let n = self.cores.len();
        let config = Arc::clone(&self.config);
        let width = config.action_len();
        let actions: Vec<f64> = if let Ok(a) = actions.extract::<PyReadonlyArray2<'_, f32>>() {
            if a.shape() != [n, width] {
                return Err(shape_error(a.shape(), n, width));
            }
            a.as_array().iter().map(|&v| f64::from(v)).collect()
        } else {
            let a = actions
                .extract::<PyReadonlyArray2<'_, f64>>()
                .map_err(|_| {
                    argument_error(
                        "actions",
                        "not a 2-d float array",
                        format_args!("an array of shape ({n}, {width})"),
                    )
                })?;
            if a.shape() != [n, width] {
                return Err(shape_error(a.shape(), n, width));
            }
            a.as_array().iter().copied().collect()
        };
        if reset.len() != n || seeds.len() != n {
            return Err(value_error(
                "`reset` and `seeds` must have one entry per environment",
            ));
        }
        let mut plan = Vec::with_capacity(n);
        for i in 0..n {
            let restart = reset[i] || self.cores[i].is_none();
            if restart {
                plan.push(Some(seed_value(seeds[i])?));
            } else {
                config.check_action(
                    &actions[i * width..(i + 1) * width],
                    &format!("actions[{i}]"),
                )?;
                if self.cores[i].as_ref().is_some_and(|c| c.outcome.is_some()) {
                    return Err(value_error(format!(
                        "environment {i} has ended: it must be reset (`reset[{i}]`)"
                    )));
                }
                plan.push(None);
            }
        }
        let k = config.observation_len();
        let mut obs = vec![0.0f32; n * k];
        let mut raw = vec![0.0f64; n * k];
        let mut pilot = vec![0.0f32; n * width];
        let mut results = vec![(StepResult::default(), -1i8, -1i8); n];
        let outcome = py.detach(|| {
            self.cores
                .par_iter_mut()
                .zip(plan.par_iter())
                .zip(obs.par_chunks_mut(k))
                .zip(raw.par_chunks_mut(k))
                .zip(pilot.par_chunks_mut(width))
                .zip(results.par_iter_mut())
                .enumerate()
                .try_for_each(|(i, (((((core, plan), obs), raw), pilot), result))| {
                    if let Some(seed) = plan {
                        *core = Some(EnvCore::new(&config, *seed).map_err(|e| e.to_string())?);
                    }
                    let Some(core) = core.as_mut() else {
                        return Ok(());
                    };
                    if plan.is_none() {
                        result.0 = core.step(&config, &actions[i * width..(i + 1) * width]);
                        if let Some((code, wire)) = core.outcome {
                            result.1 = code as i8;
                            result.2 = wire.map_or(-1, |w| w as i8);
                        }
                    }
                    core.observe(&config, obs, raw, pilot);
                    Ok::<(), String>(())
                })
        });
        outcome.map_err(value_error)?;
        let rewards: Vec<f64> = results.iter().map(|r| r.0.reward).collect();
        let terminated: Vec<bool> = results.iter().map(|r| r.0.terminated).collect();
        let truncated: Vec<bool> = results.iter().map(|r| r.0.truncated).collect();
        let codes: Vec<i8> = results.iter().map(|r| r.1).collect();
        let wires: Vec<i8> = results.iter().map(|r| r.2).collect();
        Ok((
            obs.into_pyarray(py).reshape([n, k])?,
            rewards.into_pyarray(py),
            terminated.into_pyarray(py),
            truncated.into_pyarray(py),
            raw.into_pyarray(py).reshape([n, k])?,
            pilot.into_pyarray(py).reshape([n, width])?,
            codes.into_pyarray(py),
            wires.into_pyarray(py),
        ))
    }

    /// The side view of environment `index` now.
    fn render<'py>(&mut self, py: Python<'py>, index: usize) -> PyResult<Bound<'py, PyArray3<u8>>> {
        let config = Arc::clone(&self.config);
        let core = self
            .cores
            .get_mut(index)
            .ok_or_else(|| argument_error("index", index, "an environment's index"))?;
        let frame = match core.as_mut() {
            Some(core) => {
                let look = core.stepper.look();
                draw_side_view(&config.scenario, &look.signals, core.waved_off)
            }
            None => vec![255; FRAME_HEIGHT * FRAME_WIDTH * 3],
        };
        frame_array(py, frame)
    }
}

fn shape_error(shape: &[usize], n: usize, width: usize) -> PyErr {
    argument_error(
        "actions",
        format_args!("an array of shape {shape:?}"),
        format_args!("an array of shape ({n}, {width}): one action per environment"),
    )
}
