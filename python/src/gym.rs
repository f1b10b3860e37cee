//! The core of the Gymnasium environment `deckland/CarrierLanding-v1`, in Rust: the
//! control modes and the authority each gives the agent ([`Control`], [`AgentTaps`]),
//! the normalised observation ([`OBSERVATIONS`]), the reward and the outcome, for one
//! environment (`_Env`) and for many stepped in one call over threads (`_VecEnv`).
//!
//! One step is one control interval of [`Stepper`]; the agent's commands replace the
//! built-in loops' through [`deckland::simulation::Taps`] and are held over the interval.
//! The automatic wave-off is off in every mode: the wave-off is the agent's action, and
//! the outcome is the physics' (ramp crossing, touchdown, the wires).

use std::sync::Arc;

use deckland::control::DeckReference;
use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{EndReason, LoopBreak, Recorder, Signals, Taps};
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArray3, PyArrayMethods};
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;

use crate::errors::{argument_error, value_error};
use crate::render::{draw_side_view, FRAME_HEIGHT, FRAME_WIDTH};
use crate::scenario::{flown_scenario, scenario_or_default, with_seed, Scenario};
use crate::stepping::{Look, Stepper};

/// Who flies what: the control mode of the environment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Control {
    /// The agent commands the stabilator, the thrust and direct lift; no built-in loop
    /// reaches a surface or the engines.
    Surfaces,
    /// The agent commands the pitch attitude and the thrust; the built-in pitch law flies
    /// the stabilator.
    Attitude,
    /// The agent commands the climb rate; the sink-rate loop, the pitch law and the
    /// speed loop fly the rest.
    Guidance,
}

/// The modes by name, in the order of the documentation.
const CONTROLS: [(&str, Control); 3] = [
    ("surfaces", Control::Surfaces),
    ("attitude", Control::Attitude),
    ("guidance", Control::Guidance),
];

impl Control {
    fn parse(name: &str) -> PyResult<Self> {
        CONTROLS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, c)| *c)
            .ok_or_else(|| {
                argument_error(
                    "control",
                    format_args!("{name:?}"),
                    "\"surfaces\", \"attitude\" or \"guidance\"",
                )
            })
    }

    /// The action's entries, in order (each in [−1, 1]; the last is the wave-off).
    fn action_names(self) -> &'static [&'static str] {
        match self {
            Control::Surfaces => &["elevator", "thrust", "direct_lift", "wave_off"],
            Control::Attitude => &["pitch_command", "thrust", "wave_off"],
            Control::Guidance => &["climb_rate_command", "wave_off"],
        }
    }

    /// The built-in loops whose commands reach the aircraft in this mode.
    fn built_in_loops(self) -> &'static [&'static str] {
        match self {
            Control::Surfaces => &[],
            Control::Attitude => &["pitch_law: pitch command -> stabilator command"],
            Control::Guidance => &[
                "sink_rate: climb-rate command -> pitch command",
                "wake_feedforward: pitch fed forward against the carrier's air wake",
                "pitch_law: pitch command -> stabilator command",
                "speed: airspeed -> thrust command (full thrust once the agent waves off)",
            ],
        }
    }
}

/// The agent's commands for one interval, replacing the loops' at their taps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AgentTaps {
    control: Control,
    /// Surfaces: elevator (rad); attitude: pitch command (rad); guidance: climb-rate
    /// command (m/s).
    first: f64,
    /// Surfaces and attitude: total thrust command (N).
    thrust_n: f64,
    /// Surfaces: direct lift's lift-coefficient command (–).
    direct_lift: f64,
    /// Guidance: the agent has waved off (full thrust).
    full_thrust_n: Option<f64>,
}

impl Taps for AgentTaps {
    #[inline]
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        use Control::{Attitude, Guidance, Surfaces};
        match (self.control, at) {
            (Surfaces, LoopBreak::ElevatorCommand) | (Attitude, LoopBreak::PitchCommand) => {
                self.first
            }
            (Guidance, LoopBreak::ClimbRateCommand) => self.first,
            (Surfaces | Attitude, LoopBreak::ThrustCommand) => self.thrust_n,
            (Guidance, LoopBreak::ThrustCommand) => self.full_thrust_n.unwrap_or(computed),
            (Surfaces, LoopBreak::DirectLiftCommand) => self.direct_lift,
            (Attitude | Guidance, LoopBreak::DirectLiftCommand) => 0.0,
            _ => computed,
        }
    }
}

/// Sees nothing: the environment reads the simulation itself.
struct Quiet;

impl Recorder for Quiet {}

/// One entry of the observation: its name, unit, where it comes from, and its scale
/// and realistic range (the normalised value is (raw − offset)/scale, clipped to the
/// range's image).
#[derive(Debug, Clone, Copy)]
pub(crate) struct ObservationSpec {
    pub name: &'static str,
    pub unit: &'static str,
    pub source: &'static str,
    pub scale: f64,
    pub low: f64,
    pub high: f64,
}

const DEG: f64 = std::f64::consts::PI / 180.0;

/// The observation's entries, in order (the offsets are [`EnvConfig::offsets`]). The
/// last five only with `forecast=True`.
pub(crate) const OBSERVATIONS: [ObservationSpec; 18] = [
    ObservationSpec { name: "glide_path_error_m", unit: "m", source: "hook's height error to the glide path, positive below (signal glide_path_error_m)", scale: 5.0, low: -100.0, high: 100.0 },
    ObservationSpec { name: "sink_rate_mps", unit: "m/s", source: "CG sink rate, positive down (signal climb_rate_mps negated); offset: the glide slope's, V·sin Γ", scale: 5.0, low: -30.0, high: 30.0 },
    ObservationSpec { name: "theta_measured_rad", unit: "rad", source: "pitch attitude as the pitch sensor gives it to the flight computer, with its noise (signal theta_measured_rad); offset: the trim's", scale: 10.0 * DEG, low: -90.0 * DEG, high: 90.0 * DEG },
    ObservationSpec { name: "q_radps", unit: "rad/s", source: "pitch rate (signal q_radps, as the pitch law reads it)", scale: 10.0 * DEG, low: -3.0, high: 3.0 },
    ObservationSpec { name: "alpha_rad", unit: "rad", source: "angle of attack (signal alpha_rad); offset: the trim's; range: the model's validity, −5° to 40°", scale: 10.0 * DEG, low: -5.0 * DEG, high: 40.0 * DEG },
    ObservationSpec { name: "airspeed_mps", unit: "m/s", source: "true airspeed (signal airspeed_mps); offset: the approach speed", scale: 10.0, low: 0.0, high: 150.0 },
    ObservationSpec { name: "elevator_rad", unit: "rad", source: "stabilator position (signal elevator_rad); offset: the trim's; range: its travel", scale: 10.0 * DEG, low: -60.0 * DEG, high: 30.0 * DEG },
    ObservationSpec { name: "thrust_fraction", unit: "-", source: "thrust of both engines over their maximum (signal thrust_n); offset 0.5", scale: 0.5, low: 0.0, high: 1.0 },
    ObservationSpec { name: "direct_lift_coefficient", unit: "-", source: "direct lift's lift-coefficient increment (signal direct_lift_coefficient, 0 without direct lift); scale: its largest", scale: 1.0, low: -1.0, high: 1.0 },
    ObservationSpec { name: "range_to_go_m", unit: "m", source: "range of the hook to the landing point (signal range_to_go_m)", scale: 1000.0, low: -500.0, high: 10_000.0 },
    ObservationSpec { name: "time_to_go_s", unit: "s", source: "time to touchdown as the flight-path generator estimates it (signal time_to_go_s; 120 when not closing)", scale: 10.0, low: -10.0, high: 120.0 },
    ObservationSpec { name: "deck_offset_m", unit: "m", source: "landing point's height above its mean as the deck-motion estimator sees it (signal aim_point.h_m minus environment.deck.deck_height_m)", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "waved_off", unit: "-", source: "1 once the agent has waved off, else 0", scale: 1.0, low: 0.0, high: 1.0 },
    ObservationSpec { name: "forecast_landing_point_height_m", unit: "m", source: "deck forecast: landing point's height at touchdown above its mean (the estimator's DeckForecast)", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_landing_point_climb_rate_mps", unit: "m/s", source: "deck forecast: landing point's climb rate at touchdown", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_ramp_height_m", unit: "m", source: "deck forecast: ramp's height above the mean deck when the hook crosses it", scale: 3.0, low: -15.0, high: 15.0 },
    ObservationSpec { name: "forecast_deck_pitch_rad", unit: "rad", source: "deck forecast: ship pitch at touchdown, bow up", scale: 2.0 * DEG, low: -0.2, high: 0.2 },
    ObservationSpec { name: "forecast_available", unit: "-", source: "1 when the deck predictor gives a forecast (the default estimator does; the others none: 0, and the forecast entries 0)", scale: 1.0, low: 0.0, high: 1.0 },
];

/// Entries without the forecast.
const BASE_OBSERVATIONS: usize = 13;
/// The time to go shown when the generator gives none (not closing on the deck).
const NO_TIME_TO_GO_S: f64 = 120.0;

/// The outcomes, in the order of their codes (`_VecEnv.step`'s `outcome` column).
pub(crate) const OUTCOMES: [&str; 7] = [
    "trap",
    "bolter",
    "hard_landing",
    "ramp_strike",
    "wave_off",
    "diverged",
    "timeout",
];

/// The rewards (see the module's doc in `deckland/env.py`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Rewards {
    /// At the end, in the order of [`OUTCOMES`].
    end: [f64; 7],
    /// A trap's bonus per wire 1–4.
    wire_bonus: [f64; 4],
    /// Weight of the squared glide-path error per second (1/m²/s); 0 in the sparse
    /// reward.
    error_weight: f64,
    /// Cap of the squared error (m²).
    error_cap_m2: f64,
}

impl Rewards {
    fn from_dict(rewards: &Bound<'_, PyDict>, shaped: bool) -> PyResult<Self> {
        let number = |key: &str| -> PyResult<f64> {
            let value = rewards
                .get_item(key)?
                .ok_or_else(|| value_error(format!("`rewards` has no `{key}`")))?;
            let v: f64 = value.extract().map_err(|_| {
                argument_error(&format!("rewards[{key:?}]"), value.to_string(), "a number")
            })?;
            if v.is_finite() {
                Ok(v)
            } else {
                Err(argument_error(
                    &format!("rewards[{key:?}]"),
                    v,
                    "a finite number",
                ))
            }
        };
        let mut end = [0.0; 7];
        for (slot, name) in end.iter_mut().zip(OUTCOMES) {
            *slot = number(name)?;
        }
        let bonus = rewards
            .get_item("wire_bonus")?
            .ok_or_else(|| value_error("`rewards` has no `wire_bonus`"))?;
        let mut wire_bonus = [0.0; 4];
        for (i, slot) in wire_bonus.iter_mut().enumerate() {
            let value = bonus.get_item(i + 1).map_err(|_| {
                value_error(format!("`rewards[\"wire_bonus\"]` has no wire {}", i + 1))
            })?;
            *slot = value.extract().map_err(|_| {
                argument_error(
                    &format!("rewards[\"wire_bonus\"][{}]", i + 1),
                    value.to_string(),
                    "a number",
                )
            })?;
        }
        let error_weight = if shaped { number("error_weight")? } else { 0.0 };
        let error_cap_m2 = number("error_cap_m2")?;
        Ok(Self {
            end,
            wire_bonus,
            error_weight,
            error_cap_m2,
        })
    }
}

/// What every environment of one configuration shares.
#[derive(Debug, Clone)]
pub(crate) struct EnvConfig {
    scenario: RustScenario,
    name: String,
    control: Control,
    interval_s: f64,
    /// Action spans: elevator (rad), thrust (N), pitch (rad), climb rate (m/s).
    elevator_span_rad: f64,
    thrust_span_n: f64,
    pitch_span_rad: f64,
    climb_rate_span_mps: f64,
    /// Trim: θ, δe, T, α; the glide slope's climb rate (m/s, negative).
    theta_trim_rad: f64,
    elevator_trim_rad: f64,
    thrust_trim_n: f64,
    alpha_trim_rad: f64,
    climb_rate_trim_mps: f64,
    max_thrust_n: f64,
    elevator_range_rad: (f64, f64),
    /// Direct lift's largest increment (0 without direct lift).
    max_direct_lift: f64,
    rewards: Rewards,
    forecast: bool,
    max_episode_steps: Option<u64>,
}

impl EnvConfig {
    /// The number of observation entries.
    fn observation_len(&self) -> usize {
        if self.forecast {
            OBSERVATIONS.len()
        } else {
            BASE_OBSERVATIONS
        }
    }

    fn action_len(&self) -> usize {
        self.control.action_names().len()
    }

    /// The offset of each observation entry (raw units).
    fn offsets(&self) -> [f64; 18] {
        let mut offsets = [0.0; 18];
        offsets[1] = -self.climb_rate_trim_mps;
        offsets[2] = self.theta_trim_rad;
        offsets[4] = self.alpha_trim_rad;
        offsets[5] = self.scenario.approach.airspeed_mps;
        offsets[6] = self.elevator_trim_rad;
        offsets[7] = 0.5;
        offsets
    }

    /// The scale of each entry (the direct lift's is its largest increment).
    fn scales(&self) -> [f64; 18] {
        let mut scales = OBSERVATIONS.map(|o| o.scale);
        if self.max_direct_lift > 0.0 {
            scales[8] = self.max_direct_lift;
        }
        scales
    }

    /// The raw range of each entry (the direct lift's: ± its largest increment).
    fn ranges(&self) -> [(f64, f64); 18] {
        let mut ranges = OBSERVATIONS.map(|o| (o.low, o.high));
        ranges[6] = self.elevator_range_rad;
        ranges[8] = (-self.max_direct_lift, self.max_direct_lift);
        ranges
    }

    /// The raw observation at `look` (NaN where a signal diverged).
    fn raw(&self, look: &Look, waved_off: bool, raw: &mut [f64]) {
        let s: &Signals = &look.signals;
        let deck_mean_m = self.scenario.environment.deck.deck_height_m;
        let values = [
            s.glide_path_error_m,
            -s.climb_rate_mps,
            s.theta_measured_rad,
            s.q_radps,
            s.alpha_rad,
            s.airspeed_mps,
            s.elevator_rad,
            s.thrust_n / self.max_thrust_n,
            s.direct_lift_coefficient.unwrap_or(0.0),
            s.range_to_go_m,
            s.time_to_go_s
                .filter(|t| t.is_finite())
                .unwrap_or(NO_TIME_TO_GO_S),
            s.aim_point.h_m - deck_mean_m,
            f64::from(u8::from(waved_off)),
        ];
        raw[..BASE_OBSERVATIONS].copy_from_slice(&values);
        if self.forecast {
            let forecast = look.deck.as_ref().and_then(|d: &DeckReference| d.forecast);
            let extra = match forecast {
                Some(f) => [
                    f.landing_point_height_m - deck_mean_m,
                    f.landing_point_climb_rate_mps,
                    f.ramp_height_m - deck_mean_m,
                    f.pitch_rad,
                    1.0,
                ],
                None => [0.0; 5],
            };
            raw[BASE_OBSERVATIONS..].copy_from_slice(&extra);
        }
    }

    /// The normalised observation of `raw`.
    fn normalise(&self, raw: &[f64], observation: &mut [f32]) {
        let offsets = self.offsets();
        let scales = self.scales();
        let ranges = self.ranges();
        for (i, (value, out)) in raw.iter().zip(observation.iter_mut()).enumerate() {
            let low = (ranges[i].0 - offsets[i]) / scales[i];
            let high = (ranges[i].1 - offsets[i]) / scales[i];
            let normalised = (value - offsets[i]) / scales[i];
            let normalised = if normalised.is_nan() { 0.0 } else { normalised };
            *out = normalised.clamp(low, high) as f32;
        }
    }

    /// The bounds of the normalised observation.
    fn bounds(&self) -> Vec<(f64, f64)> {
        let offsets = self.offsets();
        let scales = self.scales();
        let ranges = self.ranges();
        (0..self.observation_len())
            .map(|i| {
                let low = ((ranges[i].0 - offsets[i]) / scales[i]) as f32;
                let high = ((ranges[i].1 - offsets[i]) / scales[i]) as f32;
                (f64::from(low), f64::from(high))
            })
            .collect()
    }

    /// The taps of `action` (checked: every entry in [−1, 1]).
    fn taps(&self, action: &[f64], waved_off: bool) -> AgentTaps {
        let thrust =
            |a: f64| (self.thrust_trim_n + a * self.thrust_span_n).clamp(0.0, self.max_thrust_n);
        let (low, high) = self.elevator_range_rad;
        match self.control {
            Control::Surfaces => AgentTaps {
                control: self.control,
                first: (self.elevator_trim_rad + action[0] * self.elevator_span_rad)
                    .clamp(low, high),
                thrust_n: thrust(action[1]),
                direct_lift: action[2] * self.max_direct_lift,
                full_thrust_n: None,
            },
            Control::Attitude => AgentTaps {
                control: self.control,
                first: self.theta_trim_rad + action[0] * self.pitch_span_rad,
                thrust_n: thrust(action[1]),
                direct_lift: 0.0,
                full_thrust_n: None,
            },
            Control::Guidance => AgentTaps {
                control: self.control,
                first: self.climb_rate_trim_mps + action[0] * self.climb_rate_span_mps,
                thrust_n: 0.0,
                direct_lift: 0.0,
                full_thrust_n: waved_off.then_some(self.max_thrust_n),
            },
        }
    }

    /// The action that commands what the built-in loops compute now (the autopilot as a
    /// policy; it never waves off), clipped to the action space.
    fn autopilot_action(&self, s: &Signals, action: &mut [f32]) {
        let values: [f64; 4] = match self.control {
            Control::Surfaces => [
                (s.elevator_command_rad - self.elevator_trim_rad) / self.elevator_span_rad,
                (s.thrust_command_n - self.thrust_trim_n) / self.thrust_span_n,
                if self.max_direct_lift > 0.0 {
                    s.direct_lift_command.unwrap_or(0.0) / self.max_direct_lift
                } else {
                    0.0
                },
                -1.0,
            ],
            Control::Attitude => [
                (s.theta_ref_rad - self.theta_trim_rad) / self.pitch_span_rad,
                (s.thrust_command_n - self.thrust_trim_n) / self.thrust_span_n,
                -1.0,
                0.0,
            ],
            Control::Guidance => [
                (s.climb_rate_command_mps.unwrap_or(self.climb_rate_trim_mps)
                    - self.climb_rate_trim_mps)
                    / self.climb_rate_span_mps,
                -1.0,
                0.0,
                0.0,
            ],
        };
        for (out, value) in action.iter_mut().zip(values) {
            let value = if value.is_nan() { 0.0 } else { value };
            *out = value.clamp(-1.0, 1.0) as f32;
        }
    }

    /// `action` checked: `len` finite numbers in [−1, 1], else `ValueError` naming it.
    fn check_action(&self, action: &[f64], which: &str) -> PyResult<()> {
        let len = self.action_len();
        if action.len() == len && action.iter().all(|a| (-1.0..=1.0).contains(a)) {
            return Ok(());
        }
        Err(argument_error(
            which,
            format_args!("{action:?}"),
            format_args!(
                "{len} numbers in [-1, 1] (the action space: {})",
                self.control.action_names().join(", ")
            ),
        ))
    }
}

/// One environment's episode.
pub(crate) struct EnvCore {
    stepper: Stepper,
    seed: u64,
    waved_off: bool,
    steps: u64,
    /// The outcome's code in [`OUTCOMES`] and the wire, once ended.
    outcome: Option<(usize, Option<u8>)>,
    reason: Option<String>,
}

/// What a step gives besides the observation.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct StepResult {
    reward: f64,
    terminated: bool,
    truncated: bool,
}

impl EnvCore {
    fn new(config: &EnvConfig, seed: u64) -> PyResult<Self> {
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
        })
    }

    /// Writes the observation (raw, normalised) and the autopilot's action.
    fn observe(&mut self, config: &EnvConfig, obs: &mut [f32], raw: &mut [f64], pilot: &mut [f32]) {
        let look = self.stepper.look();
        config.raw(&look, self.waved_off, raw);
        config.normalise(raw, obs);
        config.autopilot_action(&look.signals, pilot);
    }

    /// One interval with `action` (checked by the caller).
    fn step(&mut self, config: &EnvConfig, action: &[f64]) -> StepResult {
        if config.control.action_names().len() == action.len() && action[action.len() - 1] > 0.0 {
            self.waved_off = true;
        }
        let taps = config.taps(action, self.waved_off);
        self.stepper.advance(&mut Quiet, &taps);
        self.steps += 1;
        let error = {
            let look = self.stepper.look();
            look.signals.glide_path_error_m
        };
        let mut result = StepResult {
            reward: -config.rewards.error_weight
                * (error * error).min(config.rewards.error_cap_m2)
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

/// Reads an action (a 1-d array of float32 or float64, or a sequence of numbers).
fn action_values(action: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(a) = action.cast::<PyArray1<f32>>() {
        if let Ok(values) = a.to_vec() {
            return Ok(values.into_iter().map(f64::from).collect());
        }
    }
    if let Ok(a) = action.cast::<PyArray1<f64>>() {
        if let Ok(values) = a.to_vec() {
            return Ok(values);
        }
    }
    action.extract::<Vec<f64>>().map_err(|_| {
        argument_error(
            "action",
            action
                .repr()
                .map_or_else(|_| "?".to_owned(), |r| r.to_string()),
            "an array of numbers in [-1, 1]",
        )
    })
}

/// Builds the configuration from the Python arguments.
#[allow(clippy::too_many_arguments)]
fn config(
    scenario: Option<PyRef<'_, Scenario>>,
    control: &str,
    control_interval_s: f64,
    spans: (f64, Option<f64>, f64, f64),
    rewards: &Bound<'_, PyDict>,
    reward: &str,
    forecast: bool,
    max_episode_steps: Option<u64>,
) -> PyResult<EnvConfig> {
    let control = Control::parse(control)?;
    let shaped = match reward {
        "shaped" => true,
        "sparse" => false,
        other => {
            return Err(argument_error(
                "reward",
                format_args!("{other:?}"),
                "\"shaped\" or \"sparse\"",
            ))
        }
    };
    let base = scenario_or_default(scenario);
    let mut flown = flown_scenario(&base.scenario, None, false)?;
    // The wave-off is the agent's decision.
    flown.control.wave_off.enabled = false;
    let probe = Stepper::new(&flown, control_interval_s)?;
    let system = probe.simulation().system();
    let trim = *system.trim();
    let max_thrust_n = system.aircraft().engines().max_total_thrust_n();
    let actuator = system.aircraft().actuator();
    let (pitch_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps) = spans;
    let thrust_span_n = thrust_span_n.unwrap_or(0.25 * max_thrust_n);
    for (name, value) in [
        ("pitch_command_span_rad", pitch_span_rad),
        ("thrust_span_n", thrust_span_n),
        ("elevator_span_rad", elevator_span_rad),
        ("climb_rate_span_mps", climb_rate_span_mps),
    ] {
        if !(value.is_finite() && value > 0.0) {
            return Err(argument_error(
                name,
                format_args!("{value:?}"),
                "a positive number",
            ));
        }
    }
    let reach = (trim.theta_rad + std::f64::consts::FRAC_PI_2)
        .min(std::f64::consts::FRAC_PI_2 - trim.theta_rad);
    if pitch_span_rad > reach {
        return Err(argument_error(
            "pitch_command_span_rad",
            format_args!("{pitch_span_rad:?}"),
            format_args!(
                "at most {reach:?} rad, so that the trim pitch ± the span stays within ±π/2"
            ),
        ));
    }
    let slope_rad = flown.control.flight_path.glide_slope_deg.to_radians();
    let direct_lift = flown.control.direct_lift;
    Ok(EnvConfig {
        scenario: flown,
        name: base.name,
        control,
        interval_s: probe.interval_s(),
        elevator_span_rad,
        thrust_span_n,
        pitch_span_rad,
        climb_rate_span_mps,
        theta_trim_rad: trim.theta_rad,
        elevator_trim_rad: trim.elevator_rad,
        thrust_trim_n: trim.thrust_n,
        alpha_trim_rad: trim.alpha_rad,
        climb_rate_trim_mps: -flown.approach.airspeed_mps * slope_rad.sin(),
        max_thrust_n,
        elevator_range_rad: (actuator.min_rad(), actuator.max_rad()),
        max_direct_lift: if direct_lift.enabled {
            direct_lift.max_lift_coefficient_increment
        } else {
            0.0
        },
        rewards: Rewards::from_dict(rewards, shaped)?,
        forecast,
        max_episode_steps,
    })
}

/// The description of a configuration, shared by both classes' getters.
fn describe<'py>(py: Python<'py>, config: &EnvConfig) -> PyResult<Bound<'py, PyDict>> {
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

/// The seed as the library takes it (checked).
fn seed_value(seed: i128) -> PyResult<u64> {
    with_seed(RustScenario::default(), Some(seed)).map(|s| s.seed)
}

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
    #[pyo3(signature = (scenario, control, control_interval_s, pitch_command_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps, rewards, reward, forecast))]
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

/// A frame as a (height, width, 3) array.
fn frame_array(py: Python<'_>, frame: Vec<u8>) -> PyResult<Bound<'_, PyArray3<u8>>> {
    frame
        .into_pyarray(py)
        .reshape([FRAME_HEIGHT, FRAME_WIDTH, 3])
}

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
