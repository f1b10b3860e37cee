//! Environments of one configuration stepped in one call ([`Lanes`]): the Python class
//! `_VecEnv`, and, as one lane stepped on the calling thread, `_Env` ([`super::single`]).

use std::sync::{Arc, Mutex, PoisonError};

use deckland::metrics::lso_grade::Grade;
use numpy::ndarray::Array2;
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3};
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyMemoryError;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::config::{Config, EnvConfig};
use super::describe::describe;
use super::episode::{frame_array, seed_value, EnvCore};
use super::parallel::{for_each_item, helpers};
use crate::errors::{argument_error, strict_integer, value_error};
use crate::render::{draw_side_view, FRAME_HEIGHT, FRAME_WIDTH};

/// Many environments of one configuration, stepped in one call over threads.
#[pyclass(name = "_VecEnv", module = "deckland._deckland")]
pub struct VecEnv {
    lanes: Lanes,
    /// The environments whose episode ended at the last step: the next starts them again.
    restart: Vec<bool>,
    /// Whether every environment has started (`reset`). Kept here rather than read from
    /// the episodes: reading 64 of them would fetch the data the helper threads keep in
    /// their cores' caches.
    started: bool,
}

/// What `_VecEnv.reset` returns.
type VecReset<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f32>>,
);

/// What `_VecEnv.step` returns.
type VecStep<'py> = (
    Bound<'py, PyArray2<f32>>,
    Bound<'py, PyArray1<f64>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray1<bool>>,
    Bound<'py, PyArray2<f64>>,
    Bound<'py, PyArray2<f32>>,
    Option<Bound<'py, PyArray1<i8>>>,
    Option<Bound<'py, PyArray1<i8>>>,
    Option<Bound<'py, PyArray1<i8>>>,
    Option<Bound<'py, PyArray1<i8>>>,
);

/// Every environment's results of a step, one array each, environment by environment.
pub(super) struct Outputs {
    pub(super) observations: Vec<f32>,
    pub(super) raw: Vec<f64>,
    pub(super) pilot: Vec<f32>,
    pub(super) rewards: Vec<f64>,
    pub(super) terminated: Vec<bool>,
    pub(super) truncated: Vec<bool>,
}

/// One environment in a step: its episode and where its results go.
struct Slot<'a> {
    core: &'a mut Option<EnvCore>,
    observation: &'a mut [f32],
    raw: &'a mut [f64],
    pilot: &'a mut [f32],
    reward: &'a mut f64,
    terminated: &'a mut bool,
    truncated: &'a mut bool,
    outcome: &'a mut (i8, i8, i8, i8),
}

#[pymethods]
impl VecEnv {
    /// `num_envs` environments of `config`.
    #[new]
    fn new(num_envs: &Bound<'_, PyAny>, config: &Config) -> PyResult<Self> {
        let num_envs = environment_count(strict_integer("num_envs", num_envs)?)?;
        let lanes = Lanes::new(num_envs, Arc::clone(&config.0), true)?;
        let mut restart = Vec::new();
        restart
            .try_reserve_exact(num_envs)
            .map_err(|_| environments_do_not_fit(num_envs, None))?;
        restart.resize(num_envs, false);
        Ok(Self {
            lanes,
            restart,
            started: false,
        })
    }

    /// The spaces, the observation's table, the loops still flying, the trim.
    fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.lanes.describe(py)
    }

    /// Starts every environment's episode, environment i with `seeds[i]`: (observations,
    /// raw observations, autopilot actions).
    fn reset<'py>(&mut self, py: Python<'py>, seeds: Vec<i128>) -> PyResult<VecReset<'py>> {
        let n = self.lanes.len();
        if seeds.len() != n {
            return Err(argument_error(
                "seeds",
                format_args!("{} seeds", seeds.len()),
                format_args!("one per environment, {n}"),
            ));
        }
        let seeds = seeds
            .into_iter()
            .map(|s| seed_value(s).map(Some))
            .collect::<PyResult<Vec<_>>>()?;
        self.started = false;
        let out = self.lanes.run(py, &[], &seeds)?;
        self.started = true;
        self.restart.iter_mut().for_each(|r| *r = false);
        let config = &self.lanes.config;
        let (k, width) = (config.observation_len(), config.action_len());
        Ok((
            matrix(py, out.observations, k)?,
            matrix(py, out.raw, k)?,
            matrix(py, out.pilot, width)?,
        ))
    }

    /// Steps every environment with its row of `actions`, except those whose episode
    /// ended at the previous step: they start again with their entry of `seeds` (needed
    /// then, one per environment, the others' ignored), their action ignored, reward 0.
    /// Returns (observations, rewards, terminated, truncated, raw observations, autopilot
    /// actions, outcome codes, wires, off-centre flags, LSO grades), the last four only
    /// when an episode ended (else None; −1: running, or truncated by the step limit; no
    /// wire; no 3-D touchdown; the flag 1 for a touchdown off centre, 0 within the limit).
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        actions: &Bound<'py, PyAny>,
        seeds: Option<Vec<i128>>,
    ) -> PyResult<VecStep<'py>> {
        let n = self.lanes.len();
        let config = Arc::clone(&self.lanes.config);
        let width = config.action_len();
        let actions = action_rows(actions, n, width)?;
        if !self.started {
            return Err(pyo3::exceptions::PyRuntimeError::new_err(
                "the environments have not been reset: call reset() first",
            ));
        }
        let mut plan = vec![None; n];
        if self.restart.iter().any(|&r| r) {
            let Some(seeds) = seeds.filter(|s| s.len() == n) else {
                return Err(argument_error(
                    "seeds",
                    "missing",
                    format_args!(
                        "{n} seeds, one per environment, when episodes ended at the previous step"
                    ),
                ));
            };
            for (i, seed) in seeds.into_iter().enumerate() {
                if self.restart[i] {
                    plan[i] = Some(seed_value(seed)?);
                }
            }
        }
        for (i, row) in actions.chunks(width).enumerate() {
            if plan[i].is_none() && !config.action_allowed(row) {
                config.check_action(row, &format!("actions[{i}]"))?;
            }
        }
        let out = self.lanes.run(py, &actions, &plan)?;
        let mut ended = false;
        for (restart, (terminated, truncated)) in self
            .restart
            .iter_mut()
            .zip(out.terminated.iter().zip(&out.truncated))
        {
            *restart = *terminated || *truncated;
            ended |= *restart;
        }
        let (codes, wires, off_centre, grades) = if ended {
            let column = |f: fn(&(i8, i8, i8, i8)) -> i8| {
                Some(self.lanes.outcome_column(f).into_pyarray(py))
            };
            (
                column(|o| o.0),
                column(|o| o.1),
                column(|o| o.2),
                column(|o| o.3),
            )
        } else {
            (None, None, None, None)
        };
        let k = config.observation_len();
        Ok((
            matrix(py, out.observations, k)?,
            out.rewards.into_pyarray(py),
            out.terminated.into_pyarray(py),
            out.truncated.into_pyarray(py),
            matrix(py, out.raw, k)?,
            matrix(py, out.pilot, width)?,
            codes,
            wires,
            off_centre,
            grades,
        ))
    }

    /// The side view of environment `index` now.
    fn render<'py>(&mut self, py: Python<'py>, index: usize) -> PyResult<Bound<'py, PyArray3<u8>>> {
        self.lanes.render(py, index)
    }
}

/// Environments of one configuration, each a lane, stepped in one call: the single
/// environment is one lane of it, the vectorised one many.
pub(super) struct Lanes {
    pub(super) config: Arc<EnvConfig>,
    cores: Vec<Option<EnvCore>>,
    /// Each environment's outcome code, wire, off-centre flag and LSO grade at the last
    /// step (−1: none; the flag 1 or 0 after a 3-D touchdown).
    outcomes: Vec<(i8, i8, i8, i8)>,
    /// Whether a step spreads the lanes over the helper threads ([`helpers`]), the
    /// interpreter released (the vectorised environment), or steps them on the calling
    /// thread, the interpreter held (the single one).
    threads: bool,
}

impl Lanes {
    /// `count` lanes of `config`, none started (a `MemoryError` if they do not fit).
    pub(super) fn new(count: usize, config: Arc<EnvConfig>, threads: bool) -> PyResult<Self> {
        let refused = |_| environments_do_not_fit(count, None);
        let mut cores = Vec::new();
        cores.try_reserve_exact(count).map_err(refused)?;
        cores.resize_with(count, || None);
        let mut outcomes = Vec::new();
        outcomes.try_reserve_exact(count).map_err(refused)?;
        outcomes.resize(count, (-1, -1, -1, -1));
        Ok(Self {
            config,
            cores,
            outcomes,
            threads,
        })
    }

    /// The number of lanes.
    pub(super) fn len(&self) -> usize {
        self.cores.len()
    }

    /// Lane `index`'s episode (None before its first start).
    pub(super) fn core(&self, index: usize) -> Option<&EnvCore> {
        self.cores.get(index).and_then(Option::as_ref)
    }

    /// The spaces, the observation's table, the loops still flying, the trim.
    pub(super) fn describe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        describe(py, &self.config)
    }

    /// Steps every lane: those with a seed in `plan` start again with it, the others
    /// take their row of `actions` (checked by the caller).
    pub(super) fn run(
        &mut self,
        py: Python<'_>,
        actions: &[f64],
        plan: &[Option<u64>],
    ) -> PyResult<Outputs> {
        let config = &*self.config;
        let (n, k, width) = (
            self.cores.len(),
            config.observation_len(),
            config.action_len(),
        );
        let mut out = Outputs {
            observations: vec![0.0; n * k],
            raw: vec![0.0; n * k],
            pilot: vec![0.0; n * width],
            rewards: vec![0.0; n],
            terminated: vec![false; n],
            truncated: vec![false; n],
        };
        let mut slots: Vec<Slot<'_>> = self
            .cores
            .iter_mut()
            .zip(out.observations.chunks_mut(k))
            .zip(out.raw.chunks_mut(k))
            .zip(out.pilot.chunks_mut(width))
            .zip(out.rewards.iter_mut())
            .zip(out.terminated.iter_mut().zip(out.truncated.iter_mut()))
            .zip(self.outcomes.iter_mut())
            .map(
                |(
                    (((((core, observation), raw), pilot), reward), (terminated, truncated)),
                    outcome,
                )| {
                    Slot {
                        core,
                        observation,
                        raw,
                        pilot,
                        reward,
                        terminated,
                        truncated,
                        outcome,
                    }
                },
            )
            .collect();
        // The first error of an environment's start, if any (none after the configuration's
        // own start succeeded, short of memory).
        let error: Mutex<Option<PyErr>> = Mutex::new(None);
        let work = |i: usize, slot: &mut Slot<'_>| {
            *slot.outcome = (-1, -1, -1, -1);
            if let Some(seed) = plan[i] {
                match EnvCore::new(config, seed) {
                    Ok(core) => *slot.core = Some(core),
                    Err(e) => {
                        error
                            .lock()
                            .unwrap_or_else(PoisonError::into_inner)
                            .get_or_insert(e);
                        return;
                    }
                }
            }
            let Some(core) = slot.core.as_mut() else {
                return;
            };
            if plan[i].is_none() {
                let result = core.step(config, &actions[i * width..(i + 1) * width]);
                *slot.reward = result.reward;
                *slot.terminated = result.terminated;
                *slot.truncated = result.truncated;
                if let Some((code, wire)) = core.outcome {
                    *slot.outcome = (
                        code as i8,
                        wire.map_or(-1, |w| w as i8),
                        core.off_centre.map_or(-1, i8::from),
                        core.lso.as_ref().map_or(-1, |(grade, _)| {
                            Grade::ALL
                                .iter()
                                .position(|g| g == grade)
                                .map_or(-1, |i| i as i8)
                        }),
                    );
                }
            }
            core.observe(config, slot.observation, slot.raw, slot.pilot);
        };
        if self.threads {
            py.detach(|| for_each_item(helpers(), &mut slots, work));
        } else {
            for_each_item(None, &mut slots, work);
        }
        drop(slots);
        if let Some(error) = error.into_inner().unwrap_or_else(PoisonError::into_inner) {
            return Err(error);
        }
        Ok(out)
    }

    /// The side view of lane `index` now (white before its first start).
    pub(super) fn render<'py>(
        &mut self,
        py: Python<'py>,
        index: usize,
    ) -> PyResult<Bound<'py, PyArray3<u8>>> {
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

    /// One column of the lanes' outcomes at the last step.
    fn outcome_column(&self, field: fn(&(i8, i8, i8, i8)) -> i8) -> Vec<i8> {
        self.outcomes.iter().map(field).collect()
    }
}

/// `values`, `columns` a row, as a 2-d array (without a copy).
fn matrix<T: numpy::Element>(
    py: Python<'_>,
    values: Vec<T>,
    columns: usize,
) -> PyResult<Bound<'_, PyArray2<T>>> {
    let rows = values.len() / columns;
    let array = Array2::from_shape_vec((rows, columns), values)
        .map_err(|e| value_error(format!("an array of {rows} rows of {columns}: {e}")))?;
    Ok(array.into_pyarray(py))
}

/// Most environments of one vector environment, whatever the memory.
const MAX_ENVIRONMENTS: i128 = 100_000;

/// Memory one environment holds once its episode has started (bytes): its simulation,
/// estimator and buffers. Measured on the 3-D environment (the larger) as the growth of
/// the resident set over 500 environments: 150 kB after 10 steps, 165 kB after 1500
/// (100 000 of them took about 14 GB in issue 45); rounded up to 192 kB.
const ENVIRONMENT_BYTES: u64 = 192 * 1024;

/// Share of the memory available at construction that the environments may take.
const MEMORY_SHARE: u64 = 2; // one half

/// `num_envs` checked: 1 to [`MAX_ENVIRONMENTS`], and no more than half the memory
/// available now holds ([`ENVIRONMENT_BYTES`] each), so that a count the machine cannot
/// hold raises `MemoryError` here instead of the allocator aborting the interpreter
/// later (issue 45, R5).
fn environment_count(num_envs: i128) -> PyResult<usize> {
    if !(1..=MAX_ENVIRONMENTS).contains(&num_envs) {
        return Err(argument_error(
            "num_envs",
            num_envs,
            format_args!("an integer in [1, {MAX_ENVIRONMENTS}]"),
        ));
    }
    let count = num_envs as u64; // 1 to 100 000
    if let Some(available) = available_memory_bytes() {
        if count.saturating_mul(ENVIRONMENT_BYTES) > available / MEMORY_SHARE {
            return Err(environments_do_not_fit(count as usize, Some(available)));
        }
    }
    Ok(count as usize)
}

/// The `MemoryError` for `num_envs` environments that do not fit in memory.
fn environments_do_not_fit(num_envs: usize, available: Option<u64>) -> PyErr {
    let most = available.map_or_else(String::new, |bytes| {
        format!(
            ": {} MB are available and each environment needs about {} kB, so at most {} \
             fit in half of it",
            bytes / 1_000_000,
            ENVIRONMENT_BYTES / 1024,
            bytes / MEMORY_SHARE / ENVIRONMENT_BYTES
        )
    });
    PyMemoryError::new_err(format!(
        "`num_envs` = {num_envs} is not allowed: the environments do not fit in memory{most}"
    ))
}

/// The memory available to new allocations (bytes): `MemAvailable` of `/proc/meminfo`
/// on Linux; `None` elsewhere or when it cannot be read (then only the count's limit
/// applies).
fn available_memory_bytes() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kilobytes: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    kilobytes.checked_mul(1024)
}

/// The actions, one row of `width` per environment, from a 2-d float32 or float64 array.
fn action_rows(actions: &Bound<'_, PyAny>, n: usize, width: usize) -> PyResult<Vec<f64>> {
    if let Ok(a) = actions.extract::<PyReadonlyArray2<'_, f32>>() {
        if a.shape() != [n, width] {
            return Err(shape_error(a.shape(), n, width));
        }
        return Ok(a.as_array().iter().map(|&v| f64::from(v)).collect());
    }
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
    Ok(a.as_array().iter().copied().collect())
}

fn shape_error(shape: &[usize], n: usize, width: usize) -> PyErr {
    argument_error(
        "actions",
        format_args!("an array of shape {shape:?}"),
        format_args!("an array of shape ({n}, {width}): one action per environment"),
    )
}
