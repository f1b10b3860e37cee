//! One environment's episode: its start, its steps, its reward and outcome.

use deckland::metrics::lso_grade::Grade;
use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{EndReason, Recorder};
use numpy::{IntoPyArray, PyArray3, PyArrayMethods};
use pyo3::prelude::*;

use super::config::EnvConfig;
use super::reward::OUTCOMES;
use crate::render::{FRAME_HEIGHT, FRAME_WIDTH};
use crate::scenario::with_seed;
use crate::stepping::Stepper;

/// Sees nothing: the environment reads the simulation itself.
struct Quiet;

impl Recorder for Quiet {}

/// One environment's episode.
pub(crate) struct EnvCore {
    pub(super) stepper: Stepper,
    pub(super) seed: u64,
    pub(super) waved_off: bool,
    pub(super) steps: u64,
    /// The outcome's code in [`OUTCOMES`] and the wire, once ended.
    pub(super) outcome: Option<(usize, Option<u8>)>,
    pub(super) reason: Option<String>,
    /// A 3-D approach's touchdown off the centreline (`None`: no lateral touchdown).
    pub(super) off_centre: Option<bool>,
    /// The LSO's grade of the pass and its comment, once ended (an agent's own wave-off
    /// is graded `own_wave_off`).
    pub(super) lso: Option<(Grade, String)>,
}

/// What a step gives besides the observation.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StepResult {
    pub(super) reward: f64,
    pub(super) terminated: bool,
    pub(super) truncated: bool,
}

impl EnvCore {
    pub(super) fn new(config: &EnvConfig, seed: u64) -> PyResult<Self> {
        let scenario = RustScenario {
            seed,
            ..config.scenario
        };
        Ok(Self {
            stepper: Stepper::new(&scenario, config.interval_s)?,
            seed,
            waved_off: false,
            steps: 0,
            outcome: None,
            reason: None,
            off_centre: None,
            lso: None,
        })
    }

    /// Writes the observation (raw, normalised) and the autopilot's action.
    pub(super) fn observe(
        &mut self,
        config: &EnvConfig,
        obs: &mut [f32],
        raw: &mut [f64],
        pilot: &mut [f32],
    ) {
        let look = self.stepper.look();
        config.raw(&look, self.waved_off, raw);
        config.normalise(raw, obs);
        config.autopilot_action(&look.signals, pilot);
    }

    /// One interval with `action` (checked by the caller).
    pub(super) fn step(&mut self, config: &EnvConfig, action: &[f64]) -> StepResult {
        if config.action_len() == action.len() && action[action.len() - 1] > 0.0 {
            self.waved_off = true;
        }
        let taps = config.taps(action, self.waved_off);
        self.stepper.advance(&mut Quiet, &taps);
        self.steps += 1;
        // The squared distance of the hook to the glide path (in 3-D, to its line).
        let squared_error = {
            let look = self.stepper.look();
            config.tracking.iter().fold(0.0, |sum, &id| {
                let error = look.signals.get(id).unwrap_or(f64::NAN);
                sum + error * error
            })
        };
        let mut result = StepResult {
            reward: -config.rewards.error_weight
                * squared_error.min(config.rewards.error_cap_m2)
                * config.interval_s,
            ..StepResult::default()
        };
        if result.reward.is_nan() {
            result.reward =
                -config.rewards.error_weight * config.rewards.error_cap_m2 * config.interval_s;
        }
        if let Some(reason) = self.stepper.end_reason() {
            let name = match reason {
                EndReason::FlewOverLastWire { .. } if self.waved_off => "wave_off",
                reason => reason.outcome().name(),
            };
            let code = OUTCOMES.iter().position(|o| *o == name).unwrap_or(5);
            let wire = reason.wire();
            result.reward += config.rewards.end[code];
            if let Some(w) = wire.filter(|w| (1..=4).contains(w)) {
                result.reward += config.rewards.wire_bonus[usize::from(w) - 1];
            }
            self.outcome = Some((code, wire));
            self.off_centre = self
                .stepper
                .simulation()
                .summary()
                .and_then(|s| s.lateral_touchdown())
                .map(|l| l.off_centre);
            if self.off_centre == Some(true) {
                result.reward += config.rewards.off_centre;
            }
            self.lso = self
                .stepper
                .simulation()
                .summary()
                .and_then(|s| s.lso_grade.clone())
                .map(|graded| {
                    let grade = if name == "wave_off" {
                        Grade::OwnWaveOff
                    } else {
                        graded.grade
                    };
                    (grade, graded.comment)
                });
            self.reason = if name == "wave_off" {
                Some("the agent waved off and flew over the last wire".to_owned())
            } else {
                reason.description()
            };
            if name == "timeout" {
                result.truncated = true;
            } else {
                result.terminated = true;
            }
        } else if config.max_episode_steps.is_some_and(|m| self.steps >= m) {
            result.truncated = true;
        }
        result
    }
}

/// The seed as the library takes it (checked).
pub(super) fn seed_value(seed: i128) -> PyResult<u64> {
    with_seed(RustScenario::default(), Some(seed)).map(|s| s.seed)
}

/// A frame as a (height, width, 3) array.
pub(super) fn frame_array(py: Python<'_>, frame: Vec<u8>) -> PyResult<Bound<'_, PyArray3<u8>>> {
    frame
        .into_pyarray(py)
        .reshape([FRAME_HEIGHT, FRAME_WIDTH, 3])
}
