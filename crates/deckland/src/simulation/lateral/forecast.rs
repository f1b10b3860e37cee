//! The lateral deck-motion forecast (docs/model.md §10.3; shared model §10.5, §10.7):
//! where the landing point will be, across the final bearing, at touchdown, from the
//! ship's sensed roll, yaw and sway ([`crate::sensors::LateralShipMotionSensor`]).
//!
//! Each channel is forecast from its latest measurement (value and rate, `latency_s`
//! old) by the free response of a damped oscillator over the horizon τ (the time to
//! touchdown plus the measurement's age), the best forecast of a stationary
//! second-order process without further input:
//! x(τ) = e^(−ζωτ)·[x₀·cos ω_d τ + (ẋ₀ + ζωx₀)/ω_d·sin ω_d τ], ω_d = ω√(1 − ζ²).
//! Roll's filter is that oscillator (ω = 0.314 rad/s, ζ = 0.1), so its forecast is
//! exact; yaw and sway use the heave form 1/D(s), whose measured value and rate leave
//! its fast double pole at s = −1 unobserved: they are forecast on its dominant mode,
//! s² + 0.08s + 0.16 (ω = 0.4 rad/s, ζ = 0.1), an approximation whose error is the fast
//! pole's transient, gone within about 3 s. The forecast roll, yaw and sway then place
//! the aim point with the deck's geometry ([`DeckGeometry::point_on_landing_centreline`]);
//! its displacement across the bearing from the mean aim point is the forecast.

use crate::environment::{
    DeckGeometry, ShipPose, ROLL_FILTER_DAMPING_RATIO, ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
};
use crate::sensors::LateralShipMotionMeasurement;

/// Natural frequency of the dominant mode of 1/D(s), s² + 0.08s + 0.16 (rad/s).
pub const DOMINANT_MODE_FREQUENCY_RADPS: f64 = 0.4;
/// Damping ratio of that mode (–): 0.08/(2·0.4).
pub const DOMINANT_MODE_DAMPING_RATIO: f64 = 0.1;

/// The free response of a damped oscillator (ω, ζ < 1) from (x₀, ẋ₀) after τ.
pub fn oscillator_forecast(x0: f64, rate0: f64, omega: f64, zeta: f64, tau: f64) -> f64 {
    let damped = omega * (1.0 - zeta * zeta).sqrt();
    let (sin, cos) = (damped * tau).sin_cos();
    (-zeta * omega * tau).exp() * (x0 * cos + (rate0 + zeta * omega * x0) / damped * sin)
}

/// The forecast of the landing point's displacement across the bearing (m, right) at
/// `time_s` + `time_to_go_s` from `measurement`, for the deck `deck`.
pub fn lateral_landing_point_forecast_m(
    deck: &DeckGeometry,
    measurement: &LateralShipMotionMeasurement,
    time_s: f64,
    time_to_go_s: f64,
) -> f64 {
    let tau = (time_s - measurement.time_s).max(0.0) + time_to_go_s.max(0.0);
    let roll = oscillator_forecast(
        measurement.roll_rad,
        measurement.roll_rate_radps,
        ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
        ROLL_FILTER_DAMPING_RATIO,
        tau,
    );
    let dominant = |x0, rate0| {
        oscillator_forecast(
            x0,
            rate0,
            DOMINANT_MODE_FREQUENCY_RADPS,
            DOMINANT_MODE_DAMPING_RATIO,
            tau,
        )
    };
    let yaw = dominant(measurement.yaw_rad, measurement.yaw_rate_radps);
    let sway = dominant(measurement.sway_m, measurement.sway_rate_mps);
    aim_point_displacement_m(deck, roll, yaw, sway)
}

/// The aim point's displacement across the bearing (m, right) for ship roll, yaw (rad)
/// and sway (m) from the mean pose.
pub fn aim_point_displacement_m(deck: &DeckGeometry, roll: f64, yaw: f64, sway: f64) -> f64 {
    let heading = deck.ship_mean_heading_rad();
    let moved = ShipPose {
        pitch_centre_x_m: -sway * heading.sin(),
        pitch_centre_y_m: sway * heading.cos(),
        roll_rad: roll,
        yaw_rad: yaw,
        ..ShipPose::default()
    };
    deck.aim_point_3d(&moved).y_m - deck.aim_point_3d(&ShipPose::default()).y_m
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_oscillator_forecast_solves_its_equation() {
        // ẍ + 2ζωẋ + ω²x = 0 checked by finite differences of the forecast.
        let (omega, zeta) = (0.314, 0.1);
        let x = |t: f64| oscillator_forecast(0.02, -0.003, omega, zeta, t);
        let h = 1e-3;
        for t in [0.5, 3.0, 11.0] {
            let acceleration = (x(t + h) - 2.0 * x(t) + x(t - h)) / (h * h);
            let rate = (x(t + h) - x(t - h)) / (2.0 * h);
            let residual = acceleration + 2.0 * zeta * omega * rate + omega * omega * x(t);
            assert!(residual.abs() < 1e-8, "{residual}");
        }
        assert!((x(0.0) - 0.02).abs() < 1e-15);
    }

    #[test]
    fn roll_moves_the_aim_point_to_starboard_by_the_deck_height_over_the_roll_axis() {
        // §10.5: roll moves a deck point to starboard by 19 m·sin φ_s; the landing
        // area's centreline is 9° off the ship's, so earth y takes cos 9° of it.
        let deck = DeckGeometry::default();
        let roll = 0.01;
        let moved = aim_point_displacement_m(&deck, roll, 0.0, 0.0);
        let expected = 19.0 * roll.sin() * 9.0_f64.to_radians().cos();
        assert!((moved - expected).abs() < 2e-3, "{moved} vs {expected}");
        // Sway moves it by its own amount along the ship's y axis.
        let swayed = aim_point_displacement_m(&deck, 0.0, 0.0, 1.0);
        assert!((swayed - 9.0_f64.to_radians().cos()).abs() < 1e-12);
    }
}
