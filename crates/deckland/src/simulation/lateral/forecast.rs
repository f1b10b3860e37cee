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
//!
//! The lineup compensation (docs/model.md §10.3) forecasts, the same way, another point
//! of the landing centreline: the station `aft_m` aft of the aim point (by default the
//! ramp, where the landing signal officer grades lineup), at the time the hook crosses
//! it; once the hook has passed the station, the point abreast of the hook now
//! ([`compensation_station`]). The two meet at the crossing, so the forecast has no step.

use crate::environment::{
    DeckGeometry, ShipPose, ShipPoseRate, ROLL_FILTER_DAMPING_RATIO,
    ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
};
use crate::sensors::LateralShipMotionMeasurement;

pub use super::free_response::FreeResponse;

/// Natural frequency of the dominant mode of 1/D(s), s² + 0.08s + 0.16 (rad/s).
pub const DOMINANT_MODE_FREQUENCY_RADPS: f64 = 0.4;
/// Damping ratio of that mode (–): 0.08/(2·0.4).
pub const DOMINANT_MODE_DAMPING_RATIO: f64 = 0.1;

/// The free response of a damped oscillator (ω, ζ < 1) from (x₀, ẋ₀) after τ.
pub fn oscillator_forecast(x0: f64, rate0: f64, omega: f64, zeta: f64, tau: f64) -> f64 {
    FreeResponse::new(omega, zeta, tau).value(x0, rate0)
}

/// The rate of [`oscillator_forecast`] after τ: its derivative in τ,
/// e^(−ζωτ)·[ẋ₀·cos ω_d τ − (ζω·(ẋ₀ + ζωx₀)/ω_d + ω_d·x₀)·sin ω_d τ].
pub fn oscillator_forecast_rate(x0: f64, rate0: f64, omega: f64, zeta: f64, tau: f64) -> f64 {
    FreeResponse::new(omega, zeta, tau).rate(x0, rate0)
}

/// The forecast roll and roll rate (rad, rad/s) of the ship `tau` s after `measurement`
/// was taken, by the roll filter's free response (exact for its second-order form).
pub fn roll_forecast(measurement: &LateralShipMotionMeasurement, tau: f64) -> (f64, f64) {
    let (omega, zeta) = (
        ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
        ROLL_FILTER_DAMPING_RATIO,
    );
    let (x0, rate0) = (
        measurement.motion.roll_rad,
        measurement.motion.roll_rate_radps,
    );
    let response = FreeResponse::new(omega, zeta, tau);
    (response.value(x0, rate0), response.rate(x0, rate0))
}

/// How far the point `s_m` along the landing centreline (m, forward of the aim point)
/// rises per unit sin φ_s of ship roll (m): minus its distance to starboard of the roll
/// axis (docs/model.md §10.5), from the deck's geometry by a central difference, which
/// cancels the deck height's (1 − cos φ_s) term.
pub fn roll_rise_per_sine_m(deck: &DeckGeometry, s_m: f64) -> f64 {
    let roll = 1e-3_f64;
    let height = |roll_rad: f64| {
        deck.point_on_landing_centreline(
            &ShipPose {
                roll_rad,
                ..ShipPose::default()
            },
            s_m,
        )
        .h_m
    };
    (height(roll) - height(-roll)) / (2.0 * roll.sin())
}

/// The forecast of the landing point's displacement across the bearing (m, right) at
/// `time_s` + `time_to_go_s` from `measurement`, for the deck `deck`.
pub fn lateral_landing_point_forecast_m(
    deck: &DeckGeometry,
    measurement: &LateralShipMotionMeasurement,
    time_s: f64,
    time_to_go_s: f64,
) -> f64 {
    CentrelineForecaster::new(deck).forecast_m(deck, measurement, time_s, time_to_go_s, 0.0)
}

/// Where the lineup compensation looks for a hook `range_m` before the mean aim point
/// (along the final bearing) closing at `closure_mps`, aiming at the station
/// `station_aft_m` aft of the aim point: the time until the hook crosses the station
/// (s; 0 once past it) and the point's distance aft of the aim point (m; the station
/// until the crossing, then the point abreast of the hook, down to the aim point).
pub fn compensation_station(range_m: f64, closure_mps: f64, station_aft_m: f64) -> (f64, f64) {
    let horizon_s = (range_m - station_aft_m).max(0.0) / closure_mps;
    (horizon_s, range_m.clamp(0.0, station_aft_m))
}

/// The forecast of points of the landing centreline ([`CentrelineForecaster::forecast_m`])
/// for one deck, step after step, with what does not
/// change evaluated once: the ship's mean heading's sine and cosine (which are also the
/// deck angle's), the free response of yaw and sway (one mode, one horizon) once for
/// both, and the mean centreline's point at the last station asked for (the station
/// stays at the ramp until the hook crosses it). The operations are those of
/// [`centreline_displacement_m`], so the results are the same to the bit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentrelineForecaster {
    /// sin, cos of the ship's mean heading ψ₀ (= the deck angle δ).
    heading_sin_cos: (f64, f64),
    /// The last station's distance aft of the aim point (m) and its point's y on the
    /// mean pose (m).
    mean_station: Option<(f64, f64)>,
}

impl CentrelineForecaster {
    /// The forecaster for `deck`.
    pub fn new(deck: &DeckGeometry) -> Self {
        let heading = deck.ship_mean_heading_rad();
        Self {
            heading_sin_cos: (heading.sin(), heading.cos()),
            mean_station: None,
        }
    }

    /// The forecast displacement across the bearing (m, right) of the landing
    /// centreline's point `aft_m` aft of the aim point, at `time_s` + `horizon_s`, from
    /// `measurement`: each channel's free response over the horizon plus the
    /// measurement's age, placed by the deck geometry (module docs). `aft_m` = 0 is the
    /// aim point. `deck` is the deck this was built for.
    pub fn forecast_m(
        &mut self,
        deck: &DeckGeometry,
        measurement: &LateralShipMotionMeasurement,
        time_s: f64,
        horizon_s: f64,
        aft_m: f64,
    ) -> f64 {
        let tau = (time_s - measurement.time_s).max(0.0) + horizon_s.max(0.0);
        let roll = FreeResponse::new(
            ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
            ROLL_FILTER_DAMPING_RATIO,
            tau,
        )
        .value(
            measurement.motion.roll_rad,
            measurement.motion.roll_rate_radps,
        );
        let dominant = FreeResponse::new(
            DOMINANT_MODE_FREQUENCY_RADPS,
            DOMINANT_MODE_DAMPING_RATIO,
            tau,
        );
        let yaw = dominant.value(
            measurement.motion.yaw_rad,
            measurement.motion.yaw_rate_radps,
        );
        let sway = dominant.value(measurement.motion.sway_m, measurement.motion.sway_rate_mps);
        let (sin, cos) = self.heading_sin_cos;
        let moved = ShipPose {
            pitch_centre_x_m: -sway * sin,
            pitch_centre_y_m: sway * cos,
            roll_rad: roll,
            yaw_rad: yaw,
            ..ShipPose::default()
        };
        // [`DeckGeometry::point_on_landing_centreline`] with the deck angle's sine and
        // cosine, which are the mean heading's.
        let attitude = DeckGeometry::ship_attitude_of(
            &deck.attitude_sin_cos(&moved),
            &ShipPoseRate::default(),
            self.heading_sin_cos,
        );
        let moved_y = deck
            .point_on_landing_centreline_at(&attitude, &moved, -aft_m)
            .y_m;
        let mean_y = match self.mean_station {
            Some((station, y)) if station.to_bits() == aft_m.to_bits() => y,
            _ => {
                let y = deck
                    .point_on_landing_centreline(&ShipPose::default(), -aft_m)
                    .y_m;
                self.mean_station = Some((aft_m, y));
                y
            }
        };
        moved_y - mean_y
    }
}

/// The aim point's displacement across the bearing (m, right) for ship roll, yaw (rad)
/// and sway (m) from the mean pose.
pub fn aim_point_displacement_m(deck: &DeckGeometry, roll: f64, yaw: f64, sway: f64) -> f64 {
    centreline_displacement_m(deck, roll, yaw, sway, 0.0)
}

/// The displacement across the bearing (m, right) of the landing centreline's point
/// `aft_m` aft of the aim point for ship roll, yaw (rad) and sway (m) from the mean pose.
pub fn centreline_displacement_m(
    deck: &DeckGeometry,
    roll: f64,
    yaw: f64,
    sway: f64,
    aft_m: f64,
) -> f64 {
    let heading = deck.ship_mean_heading_rad();
    let moved = ShipPose {
        pitch_centre_x_m: -sway * heading.sin(),
        pitch_centre_y_m: sway * heading.cos(),
        roll_rad: roll,
        yaw_rad: yaw,
        ..ShipPose::default()
    };
    deck.point_on_landing_centreline(&moved, -aft_m).y_m
        - deck
            .point_on_landing_centreline(&ShipPose::default(), -aft_m)
            .y_m
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::LateralShipMotionOutputs;

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
    fn the_forecaster_is_the_displacement_of_the_forecast_channels_to_the_bit() {
        // The forecaster shares the mean heading's trig, the yaw and sway response and
        // the mean station's point; the result must be that of each channel's
        // oscillator forecast placed by `centreline_displacement_m`, the station moving
        // from the ramp to the aim point and back (its memo invalidated each time).
        let deck = DeckGeometry::default();
        let measurement = LateralShipMotionMeasurement {
            time_s: 10.0,
            motion: LateralShipMotionOutputs {
                roll_rad: 0.012,
                roll_rate_radps: -0.003,
                yaw_rad: -0.004,
                yaw_rate_radps: 0.0015,
                sway_m: 0.35,
                sway_rate_mps: -0.12,
            },
        };
        let mut forecaster = CentrelineForecaster::new(&deck);
        for (k, aft) in [60.0, 60.0, 42.5, 0.0, 60.0, 60.0, 13.0]
            .into_iter()
            .enumerate()
        {
            let (t, horizon) = (10.02 + 0.001 * k as f64, 3.0 - 0.3 * k as f64);
            let tau = (t - measurement.time_s) + horizon;
            let channel = |x0, rate0, omega, zeta| oscillator_forecast(x0, rate0, omega, zeta, tau);
            let expected = centreline_displacement_m(
                &deck,
                channel(
                    measurement.motion.roll_rad,
                    measurement.motion.roll_rate_radps,
                    ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
                    ROLL_FILTER_DAMPING_RATIO,
                ),
                channel(
                    measurement.motion.yaw_rad,
                    measurement.motion.yaw_rate_radps,
                    0.4,
                    0.1,
                ),
                channel(
                    measurement.motion.sway_m,
                    measurement.motion.sway_rate_mps,
                    0.4,
                    0.1,
                ),
                aft,
            );
            let forecast = forecaster.forecast_m(&deck, &measurement, t, horizon, aft);
            assert_eq!(
                forecast.to_bits(),
                expected.to_bits(),
                "{aft} m: {forecast} vs {expected}"
            );
            assert!(forecast.abs() > 1e-3, "the deck moves: {forecast}");
        }
    }

    #[test]
    fn the_oscillator_forecast_rate_is_its_derivative() {
        let (omega, zeta) = (0.314, 0.1);
        let h = 1e-4;
        for t in [0.0, 0.7, 4.0, 13.0] {
            let numeric = (oscillator_forecast(0.02, -0.003, omega, zeta, t + h)
                - oscillator_forecast(0.02, -0.003, omega, zeta, t - h))
                / (2.0 * h);
            let rate = oscillator_forecast_rate(0.02, -0.003, omega, zeta, t);
            assert!((rate - numeric).abs() < 1e-9, "{rate} vs {numeric}");
        }
        assert!((oscillator_forecast_rate(0.02, -0.003, omega, zeta, 0.0) + 0.003).abs() < 1e-15);
    }

    #[test]
    fn roll_raises_the_aim_point_by_its_distance_to_port_of_the_roll_axis() {
        // §10.5: the aim point lies 10 m to port of the ship's centreline, so a roll φ_s
        // (starboard side down) raises it by 10 m·sin φ_s. The ramp, 60 m aft along a
        // centreline angled 9° to port, lies 60·sin 9° = 9.39 m further to starboard:
        // 0.61 m to port, so it rises by 0.61 m·sin φ_s.
        let deck = DeckGeometry::default();
        let aim = roll_rise_per_sine_m(&deck, 0.0);
        assert!((aim - 10.0).abs() < 1e-6, "{aim}");
        let ramp = roll_rise_per_sine_m(&deck, -60.0);
        let expected = 10.0 - 60.0 * 9.0_f64.to_radians().sin();
        assert!((ramp - expected).abs() < 0.02, "{ramp} vs {expected}");
    }

    #[test]
    fn a_still_deck_forecasts_no_displacement_at_any_station_or_horizon() {
        let deck = DeckGeometry::default();
        let still = LateralShipMotionMeasurement {
            time_s: 3.0,
            ..LateralShipMotionMeasurement::default()
        };
        let mut forecaster = CentrelineForecaster::new(&deck);
        for horizon in [0.0, 0.5, 4.0, 12.0] {
            for aft in [0.0, 30.0, 60.0, 150.0] {
                let forecast = forecaster.forecast_m(&deck, &still, 3.1, horizon, aft);
                assert!(forecast.abs() < 1e-12, "{horizon} s, {aft} m: {forecast}");
            }
        }
    }

    #[test]
    fn yaw_moves_the_ramp_by_its_lever_from_the_rotation_centre() {
        // §10.5 geometry: the ramp, 60 m aft of the aim point along the landing
        // centreline (9° to port), is at ship x = −81 − 60·cos 9°, y = −10 + 60·sin 9°
        // from the rotation centre; the ship's mean heading is 9° right of the bearing.
        // Yawing by ψ moves it across the bearing by
        // [sin(δ + ψ) − sin δ]·x + [cos(δ + ψ) − cos δ]·y.
        let deck = DeckGeometry::default();
        let delta = 9.0_f64.to_radians();
        let (x, y) = (-81.0 - 60.0 * delta.cos(), -10.0 + 60.0 * delta.sin());
        let yaw = 0.003;
        let expected =
            ((delta + yaw).sin() - delta.sin()) * x + ((delta + yaw).cos() - delta.cos()) * y;
        let moved = centreline_displacement_m(&deck, 0.0, yaw, 0.0, 60.0);
        assert!((moved - expected).abs() < 1e-9, "{moved} vs {expected}");
        // About 0.42 m to port: the stern swings left as the bow yaws right.
        assert!((moved + 0.416).abs() < 0.005, "{moved}");
        // The aim point, nearer the rotation centre, moves less.
        assert!(aim_point_displacement_m(&deck, 0.0, yaw, 0.0).abs() < 0.6 * moved.abs());
    }

    #[test]
    fn the_station_passes_from_the_ramp_to_the_point_abreast_without_a_step() {
        // 600 m out at 60 m/s: 9 s to the ramp, aiming at the ramp.
        assert_eq!(compensation_station(600.0, 60.0, 60.0), (9.0, 60.0));
        assert_eq!(compensation_station(60.0, 60.0, 60.0), (0.0, 60.0));
        // Past the ramp: the point abreast of the hook, now; at and past the aim point,
        // the aim point.
        assert_eq!(compensation_station(25.0, 60.0, 60.0), (0.0, 25.0));
        assert_eq!(compensation_station(-3.0, 60.0, 60.0), (0.0, 0.0));
        // A station of 0: the aim point at touchdown.
        assert_eq!(compensation_station(600.0, 60.0, 0.0), (10.0, 0.0));
        // The forecast of a moving deck is continuous as the hook crosses the station.
        let deck = DeckGeometry::default();
        let moving = LateralShipMotionMeasurement {
            time_s: 10.0,
            motion: LateralShipMotionOutputs {
                roll_rad: 0.01,
                roll_rate_radps: -0.002,
                yaw_rad: -0.003,
                yaw_rate_radps: 0.001,
                sway_m: 0.3,
                sway_rate_mps: -0.1,
            },
        };
        let at = |range_m: f64| {
            let (horizon, aft) = compensation_station(range_m, 60.0, 60.0);
            CentrelineForecaster::new(&deck).forecast_m(&deck, &moving, 10.05, horizon, aft)
        };
        let step = (at(60.0 + 1e-6) - at(60.0 - 1e-6)).abs();
        assert!(step < 1e-6, "{step}");
        assert!(at(60.0).abs() > 0.5, "the deck moves: {}", at(60.0));
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
