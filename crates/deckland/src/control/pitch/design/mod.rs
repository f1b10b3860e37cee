//! The design code of a pitch loop, which works for any law that describes itself in its
//! linear limit ([`LinearLaw`]) and never names a concrete law (docs/stabilator-design.md;
//! docs/model.md §2.6, §3.3, §4–5):
//!
//! - [`loop_model`]: the reduced linear loop — plant, actuator, sensor noise and the law's
//!   [`LinearLaw`] — with its loop gain at the elevator command and its closed-loop
//!   transfer functions;
//! - [`assess_loop`]: a law's margins with the actuator and the computer's delay, the
//!   θ/θ_ref lag seen by the outer loop, the sensor noise at the elevator and the rate
//!   limit's limit cycle ([`rate_limit`], describing function), and [`shortfalls`], how far
//!   that is from a [`PitchDesignRequest`];
//! - [`design_command`]: the jerk-limited command the elevator's rate and travel allow
//!   ([`JerkLimitedStep`] with the feed-forward of
//!   [`super::command_shaping::reference_equivalent_control`]). The feed-forward elevator
//!   δ_ff = (q̇_r − M_q·q_r)/M_δ may use a fraction η of the rate limit R and a fraction κ
//!   of the travel to the nearer stop:
//!   A = κ·|M_δ|·min(δe* − δ_min, δ_max − δe*),  J = η·R·|M_δ| − |M_q|·A.
//!   **Criterion** (the one a request can fail): the command settling time of a design
//!   step Δθ is the trajectory's duration plus the actuator's lag 2ζ_a/ω_a; a requested
//!   settling time below it is refused, naming the rate limit (when the jerk bound sets
//!   the duration) or the stop (when the acceleration bound does);
//! - [`check_pitch_tuning`]: setup's refusal of a tuning the hardware cannot fly.
//!
//! A law's own design procedure sits beside the law and calls these: the O-PD's search
//! over its settling time, ε and fed-back attitude is
//! `observer_pd::design_observer_pd`. The plant, the actuator and the sensor are
//! named for the pitch axis; a roll or yaw loop has the same structure (angle, rate,
//! surface) with its own derivatives.

use serde::{Deserialize, Serialize};
use thiserror::Error;

#[cfg(doc)]
use super::command_shaping::JerkLimitedStep;
use crate::aircraft::ElevatorActuatorParameters;
pub use crate::control::LinearLaw;
use crate::estimation::ObserverParameters;
use crate::sensors::PitchNoiseParameters;

mod assessment;
mod command;
pub mod loop_model;
mod plant;
pub mod rate_limit;
#[cfg(test)]
pub(crate) mod tests;

pub use assessment::{assess_loop, shortfalls, LoopAssessment, NoiseBudget};
pub use command::{command_bounds, design_command, nearer_stop_travel_rad};
use loop_model::log_grid;
pub use plant::{AngleOfAttackCoupling, LinearActuator, PitchPlantDerivatives};

/// The hardware the pitch loop flies: elevator actuator (with its rate limit and stops),
/// trim elevator and the pitch-plant derivatives at trim.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchHardware {
    /// The elevator actuator: dynamics, stops and rate limit (docs/model.md §2.6).
    pub actuator: ElevatorActuatorParameters,
    /// Trim elevator δe* (rad).
    pub elevator_trim_rad: f64,
    /// ∂q̇/∂q and ∂q̇/∂δe at trim.
    pub plant: PitchPlantDerivatives,
    /// The angle-of-attack coupling at trim, which the observer must estimate as a
    /// disturbance; `None` assesses the loop on the observer's own model.
    pub coupling: Option<AngleOfAttackCoupling>,
    /// Equivalent delay of a sampled flight-control computer (s): half a frame for the
    /// zero-order hold plus the computing delay (one 12.5-ms frame at 80 Hz gives
    /// 18.75 ms); 0 for the continuous controller of the simulation.
    pub control_delay_s: f64,
}

/// The pitch-measurement error the loop must live with (docs/model.md §3.3).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchSensorNoise {
    /// Standard deviation of the white part, drawn every sample (rad).
    pub white_sigma_rad: f64,
    /// Interval at which the white part is drawn (s): the control step.
    pub sample_interval_s: f64,
    /// Amplitude of the sinusoidal part (rad).
    pub sinusoid_amplitude_rad: f64,
    /// Frequency of the sinusoidal part (rad/s).
    pub sinusoid_frequency_radps: f64,
}

impl PitchSensorNoise {
    /// The noise of a scenario's sensor read every `control_interval_s` seconds (zero
    /// when the noise is switched off).
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
pub struct PitchDesignRequest {
    /// Largest pitch step the loop must fly without saturating (deg); default 5.
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
    /// Smallest phase margin at the elevator command (deg); default 45.
    pub min_phase_margin_deg: f64,
    /// Smallest gain margin at the elevator command (dB); default 6.
    pub min_gain_margin_db: f64,
    /// Largest noise-driven elevator-rate RMS as a share of the rate limit (–); 0.25.
    pub max_noise_rate_fraction: f64,
    /// Smallest elevator-command amplitude of a rate-limit limit cycle predicted by the
    /// describing function, as a multiple of the travel to the nearer stop (–); default 3.
    pub min_limit_cycle_travel_ratio: f64,
    /// Crossover of the loop around the pitch loop (sink rate), rad/s; default 1.2.
    pub outer_loop_crossover_radps: f64,
    /// Largest phase lag of θ/θ_ref at that frequency (deg); default 60 (the sink-rate
    /// loop then keeps about 30° of phase margin, docs/stabilator-design.md).
    pub max_outer_loop_lag_deg: f64,
    /// Observer gains k1, k2, k3 and exponent α1 (ε is designed); docs/model.md §4 defaults.
    pub observer: ObserverParameters,
}

impl Default for PitchDesignRequest {
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
pub enum PitchDesignError {
    /// A request or hardware value is NaN or out of its range.
    #[error("pitch design parameter `{field}` = {value} is out of range: expected {expected}")]
    InvalidParameter {
        /// The parameter's name.
        field: &'static str,
        /// The rejected value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
    /// The requested settling time is shorter than the hardware allows.
    #[error(
        "a {step_deg}° pitch step cannot settle in {requested_s:.3} s: `{limiting}` = \
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

/// A pitch law in its linear limit, with the scenario parameter that sets its speed (for
/// the message with which setup refuses a tuning the hardware cannot fly,
/// `control.rate_limit_check`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearisedLaw {
    /// The law on the reduced pitch loop.
    pub law: LinearLaw,
    /// The key in `control.pitch` of the parameter that sets the loop's speed.
    pub speed_key: &'static str,
    /// Its value.
    pub speed_value: f64,
    /// What would slow the loop, in words (`a longer settling_time_s`).
    pub speed_advice: &'static str,
}

/// Why the hardware cannot fly a pitch tuning ([`check_pitch_tuning`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PitchTuningProblem {
    /// The linear loop with the actuator and the computer's delay is unstable.
    Unstable {
        /// Phase margin at the elevator command (deg), ≤ 0; `None` when the delay-free
        /// loop itself has an unstable eigenvalue.
        phase_margin_deg: Option<f64>,
        /// Its crossover (rad/s).
        crossover_radps: Option<f64>,
    },
    /// The describing function predicts a rate-limit oscillation from too small an
    /// elevator-command amplitude.
    RateLimitOscillation {
        /// Smallest elevator-command amplitude of a limit cycle the rate limit sustains
        /// (rad).
        amplitude_rad: f64,
        /// Travel from trim to the nearer stop (rad).
        travel_rad: f64,
    },
}

/// Frequencies of [`check_pitch_tuning`] (rad/s): 240 points, log-spaced from 0.05 to 100.
fn check_grid() -> &'static [f64] {
    static GRID: std::sync::OnceLock<Vec<f64>> = std::sync::OnceLock::new();
    GRID.get_or_init(|| log_grid(0.05, 100.0, 240))
}

/// The setup's check that the hardware can fly `law`: on the reduced linear loop with the
/// actuator and the computer's delay ([`PitchHardware::control_delay_s`]) the loop must be
/// stable (a positive phase margin at the elevator command), and the smallest limit cycle
/// that the rate limit can sustain (describing function, [`rate_limit`]) must need an
/// elevator-command amplitude of at least `min_travel_ratio` times the travel to the
/// nearer stop — the design procedure's criterion
/// ([`PitchDesignRequest::min_limit_cycle_travel_ratio`], 3 by default), which separates
/// the tunings whose adverse approaches diverged at 40 °/s from those that did not
/// (docs/pitch-step.md).
///
/// Pure in its inputs; the last result is kept per thread, so that the runs of a campaign
/// with the same trim pay for it once (about 0.3 ms otherwise).
pub fn check_pitch_tuning(
    hardware: &PitchHardware,
    law: &LinearLaw,
    min_travel_ratio: f64,
) -> Result<(), PitchTuningProblem> {
    type Key = (PitchHardware, LinearLaw, f64);
    type Answer = Result<(), PitchTuningProblem>;
    thread_local! {
        static LAST: std::cell::Cell<Option<(Key, Answer)>> = const { std::cell::Cell::new(None) };
    }
    let key = (*hardware, *law, min_travel_ratio);
    if let Some((last, answer)) = LAST.get() {
        if last == key {
            return answer;
        }
    }
    let actuator = LinearActuator {
        natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
        damping_ratio: hardware.actuator.damping_ratio,
    };
    let model = loop_model::PitchLoopModel::new(hardware.plant, hardware.coupling, actuator, law);
    let delayed = |w: f64| {
        model.loop_gain(w) * nalgebra::Complex::from_polar(1.0, -w * hardware.control_delay_s)
    };
    let omegas = check_grid();
    let response: Vec<_> = omegas.iter().map(|&w| delayed(w)).collect();
    let margins = loop_model::margins_of(omegas, &response);
    let answer = if model.closed_loop_max_real_part() >= 0.0 {
        Err(PitchTuningProblem::Unstable {
            phase_margin_deg: None,
            crossover_radps: None,
        })
    } else if let Some(pm) = margins.phase_margin_deg.filter(|pm| *pm <= 0.0) {
        Err(PitchTuningProblem::Unstable {
            phase_margin_deg: Some(pm),
            crossover_radps: margins.crossover_radps,
        })
    } else {
        let travel_rad = nearer_stop_travel_rad(hardware);
        let amplitude_rad = match hardware.actuator.rate_limit_degps {
            Some(rate) => {
                rate_limit::rate_limit_cycles_sampled(omegas, &response, rate.to_radians())
                    .first()
                    .map_or(f64::INFINITY, |c| c.amplitude)
            }
            None => f64::INFINITY,
        };
        if amplitude_rad >= min_travel_ratio * travel_rad {
            Ok(())
        } else {
            Err(PitchTuningProblem::RateLimitOscillation {
                amplitude_rad,
                travel_rad,
            })
        }
    };
    LAST.set(Some((key, answer)));
    answer
}

/// `Ok` when `value` is finite and `ok`; otherwise the error naming `field`.
pub(crate) fn check(
    field: &'static str,
    value: f64,
    ok: bool,
    expected: &'static str,
) -> Result<(), PitchDesignError> {
    if value.is_finite() && ok {
        Ok(())
    } else {
        Err(PitchDesignError::InvalidParameter {
            field,
            value,
            expected,
        })
    }
}

/// Checks the hardware's plant and every field of `request` that a design reads, naming
/// the first one out of its range.
pub fn check_request(
    hardware: &PitchHardware,
    request: &PitchDesignRequest,
) -> Result<(), PitchDesignError> {
    hardware
        .plant
        .validate()
        .map_err(|_| PitchDesignError::InvalidParameter {
            field: "dqdot_delevator_per_s2",
            value: hardware.plant.dqdot_delevator_per_s2,
            expected: "finite and nonzero (and a finite dqdot_dq_per_s)",
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
