//! What every environment of one configuration shares, built from the Python arguments.

use std::sync::Arc;

use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::SignalId;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::control::Control;
use super::lateral::{LateralConfig, LateralHalf};
use super::reward::{EndInfo, Rewards, END_INFO};
use crate::errors::argument_error;
use crate::scenario::{flown_scenario, scenario_or_default, Scenario};
use crate::stepping::Stepper;

/// How an entry is normalised: (raw − offset)/scale, clipped to [low, high].
#[derive(Debug, Clone, Copy)]
pub(crate) struct Normalisation {
    pub offset: f64,
    pub scale: f64,
    pub low: f64,
    pub high: f64,
}

/// What every environment of one configuration shares.
#[derive(Debug, Clone)]
pub(crate) struct EnvConfig {
    pub(super) scenario: RustScenario,
    pub(super) name: String,
    pub(super) control: Control,
    pub(super) interval_s: f64,
    /// Action spans: elevator (rad), thrust (N), pitch (rad), climb rate (m/s).
    pub(super) elevator_span_rad: f64,
    pub(super) thrust_span_n: f64,
    pub(super) pitch_span_rad: f64,
    pub(super) climb_rate_span_mps: f64,
    /// Trim: θ, δe, T, α; the glide slope's climb rate (m/s, negative).
    pub(super) theta_trim_rad: f64,
    pub(super) elevator_trim_rad: f64,
    pub(super) thrust_trim_n: f64,
    pub(super) alpha_trim_rad: f64,
    pub(super) climb_rate_trim_mps: f64,
    pub(super) max_thrust_n: f64,
    pub(super) elevator_range_rad: (f64, f64),
    /// Direct lift's largest increment (0 without direct lift).
    pub(super) max_direct_lift: f64,
    pub(super) rewards: Rewards,
    pub(super) forecast: bool,
    pub(super) max_episode_steps: Option<u64>,
    /// The action's entries, in order: the control mode's longitudinal ones, the
    /// lateral commands, the wave-off last.
    pub(super) action_names: Vec<&'static str>,
    /// The built-in loops whose commands reach the aircraft.
    pub(super) built_in_loops: Vec<&'static str>,
    /// The 3-D environment's lateral half (its lists empty in the 2-D environment).
    pub(super) lateral: LateralHalf,
    /// The signals whose squares add up to the tracking error: the glide path error and,
    /// in the 3-D environment, the cross-track error.
    pub(super) tracking: Vec<SignalId>,
    /// What a step's `info` tells at an episode's end, in order.
    pub(super) end_info: Vec<EndInfo>,
    /// Each observation entry's normalisation (from the fields above, computed once:
    /// `normalisation_table` in the observation's module).
    pub(super) normalisation: Vec<Normalisation>,
}

/// The configuration as the Python class `_EnvConfig`: built once from the arguments of
/// the environments (`deckland.env`), then handed to `_Env` or `_VecEnv`.
#[pyclass(name = "_EnvConfig", module = "deckland._deckland", frozen)]
pub struct Config(pub(super) Arc<EnvConfig>);

#[pymethods]
impl Config {
    /// Builds the configuration from the Python arguments.
    #[new]
    #[pyo3(signature = (scenario, control, control_interval_s, pitch_command_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps, rewards, reward, forecast, max_episode_steps=None, lateral_spans=None))]
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
        max_episode_steps: Option<u64>,
        lateral_spans: Option<(f64, f64, f64, f64)>,
    ) -> PyResult<Self> {
        let control = Control::parse(control)?;
        let shaped = is_shaped(reward)?;
        let base = scenario_or_default(scenario);
        let mut flown = flown_scenario(&base.scenario, None, false)?;
        // The wave-off is the agent's decision.
        flown.control.wave_off.enabled = false;
        let probe = Stepper::new(&flown, control_interval_s)?;
        let system = probe.simulation().system();
        let trim = *system.trim();
        let max_thrust_n = system.aircraft().engines().max_total_thrust_n();
        let actuator = system.aircraft().actuator();
        let thrust_span_n = thrust_span_n.unwrap_or(0.25 * max_thrust_n);
        check_spans(
            (
                pitch_command_span_rad,
                thrust_span_n,
                elevator_span_rad,
                climb_rate_span_mps,
            ),
            trim.theta_rad,
        )?;
        let lateral = lateral_half(&flown, control, lateral_spans)?;
        let slope_rad = flown.control.flight_path.glide_slope_deg.to_radians();
        let direct_lift = flown.control.direct_lift;
        let mut config = EnvConfig {
            scenario: flown,
            name: base.name,
            control,
            interval_s: probe.interval_s(),
            elevator_span_rad,
            thrust_span_n,
            pitch_span_rad: pitch_command_span_rad,
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
            action_names: action_names(control, &lateral),
            built_in_loops: [control.built_in_loops(), lateral.loops].concat(),
            tracking: [&[SignalId::GlidePathError][..], lateral.tracking].concat(),
            end_info: [&END_INFO[..], lateral.end_info].concat(),
            lateral,
            normalisation: Vec::new(),
        };
        config.normalisation = config.normalisation_table();
        Ok(Self(Arc::new(config)))
    }
}

/// Whether the reward `reward` is the shaped one (`"shaped"`) or the sparse one
/// (`"sparse"`; anything else is refused).
fn is_shaped(reward: &str) -> PyResult<bool> {
    match reward {
        "shaped" => Ok(true),
        "sparse" => Ok(false),
        other => Err(argument_error(
            "reward",
            format_args!("{other:?}"),
            "\"shaped\" or \"sparse\"",
        )),
    }
}

/// The action spans (pitch command, thrust, elevator, climb rate) checked: positive, and
/// the trim pitch `theta_trim_rad` ± the pitch command's within ±π/2.
fn check_spans(spans: (f64, f64, f64, f64), theta_trim_rad: f64) -> PyResult<()> {
    let (pitch_span_rad, thrust_span_n, elevator_span_rad, climb_rate_span_mps) = spans;
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
    let reach = (theta_trim_rad + std::f64::consts::FRAC_PI_2)
        .min(std::f64::consts::FRAC_PI_2 - theta_trim_rad);
    if pitch_span_rad > reach {
        return Err(argument_error(
            "pitch_command_span_rad",
            format_args!("{pitch_span_rad:?}"),
            format_args!(
                "at most {reach:?} rad, so that the trim pitch ± the span stays within ±π/2"
            ),
        ));
    }
    Ok(())
}

/// The environment's lateral half: the 3-D environment's with `lateral_spans` (checked,
/// and `flown` checked to be a 3-D approach), else the 2-D environment's, empty. The
/// one place that chooses between the two; the rest maps over the half's lists.
fn lateral_half(
    flown: &RustScenario,
    control: Control,
    lateral_spans: Option<(f64, f64, f64, f64)>,
) -> PyResult<LateralHalf> {
    match lateral_spans {
        Some(spans) => Ok(LateralHalf::new(
            &LateralConfig::new(flown, spans)?,
            control,
        )),
        None => Ok(LateralHalf::default()),
    }
}

/// The action's entries: the longitudinal ones of `control`, the lateral commands, the
/// wave-off last.
fn action_names(control: Control, lateral: &LateralHalf) -> Vec<&'static str> {
    let names = control.action_names();
    let (longitudinal, wave_off) = names.split_at(names.len() - 1);
    let commands = lateral.commands.iter().map(|c| c.name);
    longitudinal
        .iter()
        .copied()
        .chain(commands)
        .chain(wave_off.iter().copied())
        .collect()
}
