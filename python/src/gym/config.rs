//! What every environment of one configuration shares, built from the Python arguments.

use deckland::scenario::Scenario as RustScenario;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use super::control::Control;
use super::lateral::LateralConfig;
use super::reward::Rewards;
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
    /// The 3-D environment's lateral half (`None`: the 2-D environment).
    pub(super) lateral: Option<LateralConfig>,
    /// Each observation entry's normalisation (from the fields above, computed once:
    /// `normalisation_table` in the observation's module).
    pub(super) normalisation: Vec<Normalisation>,
}

/// Builds the configuration from the Python arguments.
#[allow(clippy::too_many_arguments)]
pub(super) fn config(
    scenario: Option<PyRef<'_, Scenario>>,
    control: &str,
    control_interval_s: f64,
    spans: (f64, Option<f64>, f64, f64),
    rewards: &Bound<'_, PyDict>,
    reward: &str,
    forecast: bool,
    max_episode_steps: Option<u64>,
    lateral_spans: Option<(f64, f64, f64, f64)>,
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
    let lateral = match lateral_spans {
        Some(spans) => Some(LateralConfig::new(&flown, spans)?),
        None => None,
    };
    let slope_rad = flown.control.flight_path.glide_slope_deg.to_radians();
    let direct_lift = flown.control.direct_lift;
    let mut config = EnvConfig {
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
        lateral,
        normalisation: Vec::new(),
    };
    config.normalisation = config.normalisation_table();
    Ok(config)
}
