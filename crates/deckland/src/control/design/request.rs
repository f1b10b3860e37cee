//! What a design is given and asked: the axis's hardware, the sensor's noise, the
//! request's targets, the law in its linear limit, and the errors that name a field.

use serde::{Deserialize, Serialize};
use thiserror::Error;

use super::plant::{ActuatorKeys, AngleOfAttackCoupling, AxisPlantDerivatives};
use crate::aircraft::ElevatorActuatorParameters;
use crate::control::LinearLaw;
use crate::estimation::ObserverParameters;
use crate::sensors::PitchNoiseParameters;

/// The hardware an axis's loop flies: the surface actuator (with its rate limit and
/// stops) and its scenario keys, the trim surface position and the plant derivatives at
/// trim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AxisHardware {
    /// The surface actuator: dynamics, stops and rate limit (docs/model.md §2.6; the
    /// elevator's parameter type serves every second-order surface actuator).
    pub actuator: ElevatorActuatorParameters,
    /// The scenario keys of the actuator's limits, named by refusals.
    pub actuator_keys: ActuatorKeys,
    /// Trim surface position δ* (rad).
    pub surface_trim_rad: f64,
    /// Rate damping and control power at trim.
    pub plant: AxisPlantDerivatives,
    /// The pitch axis's angle-of-attack coupling at trim, which the observer must
    /// estimate as a disturbance; `None` assesses the loop on the observer's own model
    /// (and is the roll and yaw axes' value).
    pub coupling: Option<AngleOfAttackCoupling>,
    /// Equivalent delay of a sampled flight-control computer (s): half a frame for the
    /// zero-order hold plus the computing delay (one 12.5-ms frame at 80 Hz gives
    /// 18.75 ms); 0 for the continuous controller of the simulation.
    pub control_delay_s: f64,
}

/// The angle-measurement error the loop must live with (docs/model.md §3.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorNoise {
    /// Standard deviation of the white part, drawn every sample (rad).
    pub white_sigma_rad: f64,
    /// Interval at which the white part is drawn (s): the control step.
    pub sample_interval_s: f64,
    /// Amplitude of the sinusoidal part (rad).
    pub sinusoid_amplitude_rad: f64,
    /// Frequency of the sinusoidal part (rad/s).
    pub sinusoid_frequency_radps: f64,
}

impl SensorNoise {
    /// The noise of a scenario's pitch sensor read every `control_interval_s` seconds
    /// (zero when the noise is switched off).
    pub fn from_parameters(noise: &PitchNoiseParameters, control_interval_s: f64) -> Self {
        let on = if noise.enabled { 1.0 } else { 0.0 };
        Self {
            white_sigma_rad: on * noise.white_noise_sigma_rad,
            sample_interval_s: control_interval_s,
            sinusoid_amplitude_rad: on * noise.sinusoid_amplitude_rad,
            sinusoid_frequency_radps: noise.sinusoid_frequency_radps,
        }
    }
}

/// What the design must achieve; [`Default`] gives the targets of issue 11.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct DesignRequest {
    /// Largest step of the angle the loop must fly without saturating (deg); default 5.
    pub design_step_deg: f64,
    /// Requested settling time of the design step (s); `None`: the fastest allowed.
    pub command_settling_time_s: Option<f64>,
    /// Share η of the rate limit the shaped command may use (–); default 0.6. The rest
    /// (16 °/s of the 40) is left to the feedback: in adverse conditions the sensor's
    /// errors and the gusts alone drive the elevator at about 15 °/s RMS. With 0.75 the
    /// adverse 5° step spent 24 % of its time on the rate limit and overshot 15 %; with
    /// 0.6, 8 % and 2 % (docs/pitch-step.md).
    pub command_rate_fraction: f64,
    /// Share κ of the travel to the nearer stop the shaped command may use (–); 0.8.
    pub command_travel_fraction: f64,
    /// Smallest phase margin at the surface command (deg); default 45.
    pub min_phase_margin_deg: f64,
    /// Smallest gain margin at the surface command (dB); default 6.
    pub min_gain_margin_db: f64,
    /// Largest noise-driven surface-rate RMS as a share of the rate limit (–); 0.25.
    pub max_noise_rate_fraction: f64,
    /// Smallest surface-command amplitude of a rate-limit limit cycle predicted by the
    /// describing function, as a multiple of the travel to the nearer stop (–); default 3.
    pub min_limit_cycle_travel_ratio: f64,
    /// Crossover of the loop around this loop (for pitch: the sink rate), rad/s; default
    /// 1.2.
    pub outer_loop_crossover_radps: f64,
    /// Largest phase lag of the angle behind its command at that frequency (deg);
    /// default 60 (the sink-rate
    /// loop then keeps about 30° of phase margin, docs/stabilator-design.md).
    pub max_outer_loop_lag_deg: f64,
    /// Observer gains k1, k2, k3 and exponent α1 (ε is designed); docs/model.md §4 defaults.
    pub observer: ObserverParameters,
}

impl Default for DesignRequest {
    fn default() -> Self {
        Self {
            design_step_deg: 5.0,
            command_settling_time_s: None,
            command_rate_fraction: 0.6,
            command_travel_fraction: 0.8,
            min_phase_margin_deg: 45.0,
            min_gain_margin_db: 6.0,
            max_noise_rate_fraction: 0.25,
            min_limit_cycle_travel_ratio: 3.0,
            outer_loop_crossover_radps: 1.2,
            max_outer_loop_lag_deg: 60.0,
            observer: ObserverParameters::default(),
        }
    }
}

/// Why a request cannot be met by the hardware.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum DesignError {
    /// A request or hardware value is NaN or out of its range.
    #[error("design parameter `{field}` = {} is out of range: expected {expected}", crate::parameters::readable_number(*value))]
    InvalidParameter {
        /// The parameter's name.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
    /// The surface's rate limit cannot move it against the airframe's rate damping over
    /// the travel the command may use: no jerk-limited command exists.
    #[error(
        "no command can be shaped for this surface: its rate limit `{rate_limit_key}` = \
         {rate_limit_degps} deg/s cannot drive it over the travel `{travel_key}` = \
         {travel_deg}° against the airframe's rate damping (command jerk \
         η·R·|M_δ| − |M_q|·A = {jerk_radps3:.3e} rad/s³, must be > 0); raise \
         `{rate_limit_key}` or lower `{travel_key}`"
    )]
    CommandCannotBeShaped {
        /// The scenario key of the rate limit.
        rate_limit_key: &'static str,
        /// Its value (deg/s).
        rate_limit_degps: f64,
        /// The scenario key of the stop the command moves towards.
        travel_key: &'static str,
        /// Its value (deg).
        travel_deg: f64,
        /// The command's jerk bound, not positive (rad/s³).
        jerk_radps3: f64,
    },
    /// The requested settling time is shorter than the hardware allows.
    #[error(
        "a {step_deg}° step cannot settle in {requested_s:.3} s: `{limiting}` = \
         {limit_value} allows no less than {minimum_s:.3} s (jerk-limited trajectory with \
         {rate_fraction} of the rate limit and {travel_fraction} of the travel for the \
         command, plus the actuator's lag)"
    )]
    SettlingTimeTooShort {
        /// The design step (deg).
        step_deg: f64,
        /// The requested settling time (s).
        requested_s: f64,
        /// The shortest the hardware allows (s).
        minimum_s: f64,
        /// The hardware parameter that sets the minimum: the rate limit, or the stop.
        limiting: &'static str,
        /// Its value (deg/s or deg).
        limit_value: f64,
        /// Share of the rate limit given to the command.
        rate_fraction: f64,
        /// Share of the travel given to the command.
        travel_fraction: f64,
    },
    /// No feedback on the search grid meets every requirement.
    #[error(
        "no O-PD feedback meets `{limiting}`: the best candidate reaches {best:.3}, the \
         request asks for {required:.3}"
    )]
    NoFeasibleFeedback {
        /// The request field that failed (for the candidate closest to success).
        limiting: &'static str,
        /// What that candidate achieves, in the field's unit.
        best: f64,
        /// What the request asks for.
        required: f64,
    },
}

/// A law in its linear limit, with the scenario parameter that sets its speed (for the
/// message with which setup refuses a tuning the hardware cannot fly,
/// `control.rate_limit_check`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearisedLaw {
    /// The law on the reduced loop.
    pub law: LinearLaw,
    /// The key in the law's section (`control.pitch`) of the parameter that sets the loop's speed.
    pub speed_key: &'static str,
    /// Its value.
    pub speed_value: f64,
    /// What would slow the loop, in words (`a longer settling_time_s`).
    pub speed_advice: &'static str,
}

/// `Ok` when `value` is finite and `ok`; otherwise the error naming `field`.
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    expected: &'static str,
) -> Result<(), DesignError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(DesignError::InvalidParameter {
            field,
            value,
            expected,
        })
    }
}

/// Checks the hardware's plant and every field of `request` that a design reads, naming
/// the first one out of its range.
pub fn check_request(hardware: &AxisHardware, request: &DesignRequest) -> Result<(), DesignError> {
    hardware
        .plant
        .validate()
        .map_err(|_| DesignError::InvalidParameter {
            field: "control_power_per_s2",
            value: hardware.plant.control_power_per_s2,
            expected: "finite and nonzero (and a finite rate_damping_per_s)",
        })?;
    check(
        "design_step_deg",
        request.design_step_deg,
        request.design_step_deg > 0.0 && request.design_step_deg <= 20.0,
        "in (0, 20]",
    )?;
    check(
        "command_rate_fraction",
        request.command_rate_fraction,
        request.command_rate_fraction > 0.0 && request.command_rate_fraction <= 1.0,
        "in (0, 1]",
    )?;
    check(
        "command_travel_fraction",
        request.command_travel_fraction,
        request.command_travel_fraction > 0.0 && request.command_travel_fraction <= 1.0,
        "in (0, 1]",
    )?;
    check(
        "max_noise_rate_fraction",
        request.max_noise_rate_fraction,
        request.max_noise_rate_fraction > 0.0,
        "> 0",
    )?;
    check(
        "outer_loop_crossover_radps",
        request.outer_loop_crossover_radps,
        request.outer_loop_crossover_radps > 0.0,
        "> 0",
    )?;
    if let Some(t) = request.command_settling_time_s {
        check("command_settling_time_s", t, t > 0.0, "> 0")?;
    }
    Ok(())
}
