//! Assessing any law, given in its linear limit, on the reduced linear loop of an axis: margins
//! with the actuator and the computer's delay, the θ/θ_ref lag seen by the outer loop, the
//! sensor noise at the surface, and the rate limit's limit cycle.

use nalgebra::Complex;
use serde::Serialize;

use super::loop_model::{log_grid, margins_of, AxisLoopModel, LoopInput, LoopOutput, Margins};
use super::plant::LinearActuator;
use super::rate_limit::rate_limit_cycles;
use super::request::{AxisHardware, DesignRequest, SensorNoise};
use crate::control::LinearLaw;

/// How the sensor noise reaches the surface and the attitude (reduced linear loop).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct NoiseBudget {
    /// Surface-rate RMS from the white part (rad/s).
    pub white_surface_rate_rms_radps: f64,
    /// Surface-rate RMS from the sinusoid (rad/s): amplitude·|H(jω)|·ω/√2.
    pub sinusoid_surface_rate_rms_radps: f64,
    /// Both together (rad/s).
    pub surface_rate_rms_radps: f64,
    /// Gain from the sensor error to the surface at the sinusoid's frequency (rad/rad).
    pub sinusoid_to_surface_gain: f64,
    /// Amplitude of the true attitude's answer to the sinusoid (rad).
    pub angle_sinusoid_amplitude_rad: f64,
    /// RMS of the true attitude's answer to the white part (rad).
    pub angle_white_rms_rad: f64,
}

/// What a law achieves on the reduced linear loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopAssessment {
    /// Margins at the surface command.
    pub margins: Margins,
    /// Phase lag of θ/θ_ref at the outer loop's crossover (deg, positive lagging).
    pub outer_loop_lag_deg: f64,
    /// Noise at the surface and the attitude.
    pub noise: NoiseBudget,
    /// Largest real part of the closed loop's eigenvalues (1/s).
    pub closed_loop_max_real_part: f64,
    /// Smallest surface-command amplitude (rad) of a limit cycle the rate limit can
    /// sustain ([`rate_limit_cycles`]); infinite when none is predicted or there is no
    /// rate limit.
    pub limit_cycle_amplitude_rad: f64,
}

/// Assesses `law` on the reduced linear loop of `hardware` with the sensor `noise`, the
/// outer loop crossing over at `outer_loop_crossover_radps` (see the module docs).
pub fn assess_loop(
    hardware: &AxisHardware,
    noise: &SensorNoise,
    law: &LinearLaw,
    outer_loop_crossover_radps: f64,
) -> LoopAssessment {
    let actuator = LinearActuator {
        natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
        damping_ratio: hardware.actuator.damping_ratio,
    };
    let model = AxisLoopModel::new(hardware.plant, hardware.coupling, actuator, law);
    let delayed =
        |w: f64| model.loop_gain(w) * Complex::from_polar(1.0, -w * hardware.control_delay_s);
    let omegas = log_grid(0.01, 300.0, 800);
    let response: Vec<Complex<f64>> = omegas.iter().map(|&w| delayed(w)).collect();
    let margins = margins_of(&omegas, &response);
    let limit_cycle_amplitude_rad = match hardware.actuator.rate_limit_degps {
        Some(rate) => rate_limit_cycles(delayed, rate.to_radians(), &log_grid(0.05, 50.0, 600))
            .first()
            .map_or(f64::INFINITY, |c| c.amplitude),
        None => f64::INFINITY,
    };
    let lag = -model
        .closed_loop(
            LoopInput::Command,
            LoopOutput::Angle,
            outer_loop_crossover_radps,
        )
        .arg()
        .to_degrees();
    let omega = noise.sinusoid_frequency_radps;
    let to_surface = model
        .closed_loop(LoopInput::SensorNoise, LoopOutput::Surface, omega)
        .norm();
    // The RMS of `output` under the sensor's white noise (0 without it).
    let white_rms = |output| {
        if noise.white_sigma_rad > 0.0 {
            model.white_noise_rms(output, noise.white_sigma_rad, noise.sample_interval_s)
        } else {
            0.0
        }
    };
    let white_rate = white_rms(LoopOutput::SurfaceRate);
    let sinusoid_rate = noise.sinusoid_amplitude_rad * to_surface * omega / 2f64.sqrt();
    let white_angle = white_rms(LoopOutput::Angle);
    let angle_sinusoid = noise.sinusoid_amplitude_rad
        * model
            .closed_loop(LoopInput::SensorNoise, LoopOutput::Angle, omega)
            .norm();
    LoopAssessment {
        margins,
        outer_loop_lag_deg: lag,
        noise: NoiseBudget {
            white_surface_rate_rms_radps: white_rate,
            sinusoid_surface_rate_rms_radps: sinusoid_rate,
            surface_rate_rms_radps: white_rate.hypot(sinusoid_rate),
            sinusoid_to_surface_gain: to_surface,
            angle_sinusoid_amplitude_rad: angle_sinusoid,
            angle_white_rms_rad: white_angle,
        },
        closed_loop_max_real_part: model.closed_loop_max_real_part(),
        limit_cycle_amplitude_rad,
    }
}

/// How far an assessed law is from meeting each requirement of `request`, for a rate
/// limit (rad/s) and a travel to the nearer stop (rad): (field, achieved, required,
/// shortfall ≥ 0 as a fraction of the requirement).
pub fn shortfalls(
    candidate: &LoopAssessment,
    request: &DesignRequest,
    rate_limit_radps: f64,
    travel_rad: f64,
) -> [(&'static str, f64, f64, f64); 5] {
    let cycle_ratio = candidate.limit_cycle_amplitude_rad / travel_rad;
    let pm = candidate
        .margins
        .phase_margin_deg
        .unwrap_or(f64::NEG_INFINITY);
    let gm = candidate.margins.gain_margin_db.unwrap_or(f64::INFINITY);
    let noise_fraction = candidate.noise.surface_rate_rms_radps / rate_limit_radps;
    // (field, achieved, required, whether larger is better)
    [
        (
            "min_phase_margin_deg",
            pm,
            request.min_phase_margin_deg,
            true,
        ),
        ("min_gain_margin_db", gm, request.min_gain_margin_db, true),
        (
            "max_outer_loop_lag_deg",
            candidate.outer_loop_lag_deg,
            request.max_outer_loop_lag_deg,
            false,
        ),
        (
            "max_noise_rate_fraction",
            noise_fraction,
            request.max_noise_rate_fraction,
            false,
        ),
        (
            "min_limit_cycle_travel_ratio",
            cycle_ratio,
            request.min_limit_cycle_travel_ratio,
            true,
        ),
    ]
    .map(|(field, achieved, required, larger_is_better)| {
        let gap = if larger_is_better {
            required - achieved
        } else {
            achieved - required
        };
        (
            field,
            achieved,
            required,
            (gap / required.abs().max(1e-9)).max(0.0),
        )
    })
}
