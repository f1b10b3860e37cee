//! The command part of the design: the jerk-limited design step the hardware allows, or
//! the refusal naming the hardware limit.

use super::command_shaping::JerkLimitedStep;
use super::request::{AxisHardware, DesignError, DesignRequest};

/// Travel from the trim surface position to the nearer stop (rad).
pub fn nearer_stop_travel_rad(hardware: &AxisHardware) -> f64 {
    let actuator = &hardware.actuator;
    (hardware.surface_trim_rad - actuator.min_deflection_deg.to_radians())
        .min(actuator.max_deflection_deg.to_radians() - hardware.surface_trim_rad)
}

/// The shaped command's bounds for this hardware: (jerk J in rad/s³, acceleration A in
/// rad/s², the stop that bounds A), from η and κ as in the module docs.
pub fn command_bounds(
    hardware: &AxisHardware,
    rate_fraction: f64,
    travel_fraction: f64,
) -> (f64, f64, &'static str) {
    let actuator = &hardware.actuator;
    let (mq, md) = (
        hardware.plant.rate_damping_per_s.abs(),
        hardware.plant.control_power_per_s2.abs(),
    );
    let up = hardware.surface_trim_rad - actuator.min_deflection_deg.to_radians();
    let down = actuator.max_deflection_deg.to_radians() - hardware.surface_trim_rad;
    let (travel, stop) = if up <= down {
        (up, hardware.actuator_keys.min_deflection)
    } else {
        (down, hardware.actuator_keys.max_deflection)
    };
    let acceleration = travel_fraction * md * travel;
    let rate = actuator
        .rate_limit_degps
        .map_or(f64::INFINITY, f64::to_radians);
    let jerk = rate_fraction * rate * md - mq * acceleration;
    (jerk, acceleration, stop)
}

/// The command part of the design: the shaped design step and its settling time, or the
/// refusal naming the hardware limit (see the module docs' criterion).
pub fn design_command(
    hardware: &AxisHardware,
    request: &DesignRequest,
) -> Result<(JerkLimitedStep, f64), DesignError> {
    let (jerk, acceleration, stop) = command_bounds(
        hardware,
        request.command_rate_fraction,
        request.command_travel_fraction,
    );
    let actuator = &hardware.actuator;
    if jerk.is_nan() || jerk <= 0.0 {
        return Err(DesignError::CommandCannotBeShaped {
            rate_limit_key: hardware.actuator_keys.rate_limit,
            rate_limit_degps: actuator.rate_limit_degps.unwrap_or(f64::INFINITY),
            travel_key: stop,
            travel_deg: if stop.ends_with("min_deflection_deg") {
                actuator.min_deflection_deg
            } else {
                actuator.max_deflection_deg
            },
            jerk_radps3: jerk,
        });
    }
    let step = request.design_step_deg.to_radians();
    let lag_s = 2.0 * actuator.damping_ratio / actuator.natural_frequency_rad_s;
    let fastest = JerkLimitedStep::new(step, jerk, acceleration);
    let minimum_s = fastest.duration_s() + lag_s;
    let Some(requested_s) = request.command_settling_time_s else {
        return Ok((fastest, minimum_s));
    };
    if requested_s < minimum_s {
        let acceleration_bound = fastest.peak_acceleration_radps2() >= acceleration * (1.0 - 1e-9);
        let (limiting, limit_value) = if acceleration_bound {
            let stop_deg = if stop.ends_with("min_deflection_deg") {
                actuator.min_deflection_deg
            } else {
                actuator.max_deflection_deg
            };
            (stop, stop_deg)
        } else {
            (
                hardware.actuator_keys.rate_limit,
                actuator.rate_limit_degps.unwrap_or(f64::INFINITY),
            )
        };
        return Err(DesignError::SettlingTimeTooShort {
            step_deg: request.design_step_deg,
            requested_s,
            minimum_s,
            limiting,
            limit_value,
            rate_fraction: request.command_rate_fraction,
            travel_fraction: request.command_travel_fraction,
        });
    }
    // Slower than the fastest: lower the jerk until the trajectory takes the time asked
    // (bisection on J; the duration falls monotonically as J grows).
    let target_s = requested_s - lag_s;
    let (mut low, mut high) = (1e-9, jerk);
    for _ in 0..100 {
        let middle = 0.5 * (low + high);
        if JerkLimitedStep::new(step, middle, acceleration).duration_s() > target_s {
            low = middle;
        } else {
            high = middle;
        }
    }
    Ok((JerkLimitedStep::new(step, high, acceleration), requested_s))
}
