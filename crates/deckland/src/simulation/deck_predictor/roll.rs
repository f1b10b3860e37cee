//! The ship's roll in the longitudinal deck forecast of the 3-D approach
//! (docs/model.md §10.3): the landing point and the ramp lie off the roll axis, so they
//! rise and fall with it, which the heave-and-pitch forecast does not see.

use crate::aircraft::six_dof::series_sin_cos;
use crate::control::DeckForecast;

/// The ship's latest sensed roll, and how much the landing point and the ramp rise per
/// unit sin φ_s of it (docs/model.md §10.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensedRoll {
    /// The measurement (its roll and roll rate, and when it was taken).
    pub measurement: crate::sensors::LateralShipMotionMeasurement,
    /// The landing point's rise per unit sin φ_s (m): its distance to port of the roll
    /// axis.
    pub landing_point_rise_m: f64,
    /// The ramp's (m).
    pub ramp_rise_m: f64,
}

impl SensedRoll {
    /// The ship's latest sensed roll, `measurement` (`None` before the first one
    /// arrives), with the landing point's and the ramp's rise per unit sin φ_s
    /// `rise_m` (m).
    pub fn latest(
        measurement: Option<crate::sensors::LateralShipMotionMeasurement>,
        rise_m: (f64, f64),
    ) -> Option<Self> {
        measurement.map(|measurement| Self {
            measurement,
            landing_point_rise_m: rise_m.0,
            ramp_rise_m: rise_m.1,
        })
    }

    /// `forecast` with the landing point's and the ramp's heights and climb rates moved
    /// by the roll forecast at the touchdown and the ramp crossing, `now_s` + the
    /// horizons (`time_to_go_s`, and the ramp `ramp_aft_m` earlier at `closure_mps`).
    pub fn add_to(
        &self,
        forecast: DeckForecast,
        now_s: f64,
        time_to_go_s: f64,
        ramp_aft_m: f64,
        closure_mps: f64,
    ) -> DeckForecast {
        use crate::simulation::lateral::forecast::roll_forecast;
        let age_s = (now_s - self.measurement.time_s).max(0.0);
        let ramp_time_s = if closure_mps > 0.0 {
            (time_to_go_s - ramp_aft_m / closure_mps).max(0.0)
        } else {
            time_to_go_s
        };
        let (roll, roll_rate) = roll_forecast(&self.measurement, age_s + time_to_go_s.max(0.0));
        let (ramp_roll, ramp_roll_rate) = roll_forecast(&self.measurement, age_s + ramp_time_s);
        // The ship's roll is small: its sine and cosine by series, within an ulp.
        let (sin_roll, cos_roll) = series_sin_cos(roll);
        let (sin_ramp_roll, cos_ramp_roll) = series_sin_cos(ramp_roll);
        DeckForecast {
            landing_point_height_m: forecast.landing_point_height_m
                + self.landing_point_rise_m * sin_roll,
            landing_point_climb_rate_mps: forecast.landing_point_climb_rate_mps
                + self.landing_point_rise_m * cos_roll * roll_rate,
            ramp_height_m: forecast.ramp_height_m + self.ramp_rise_m * sin_ramp_roll,
            ramp_climb_rate_mps: forecast.ramp_climb_rate_mps
                + self.ramp_rise_m * cos_ramp_roll * ramp_roll_rate,
            roll_rad: roll,
            ..forecast
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::LateralShipMotionOutputs;
    use crate::sensors::LateralShipMotionMeasurement;
    use crate::simulation::lateral::forecast::roll_forecast;

    #[test]
    fn the_sensed_roll_moves_the_longitudinal_forecast_by_the_points_rise() {
        let forecast = DeckForecast {
            ramp_height_m: 1.0,
            landing_point_climb_rate_mps: 0.2,
            landing_point_height_m: 2.0,
            pitch_rad: 0.01,
            ramp_climb_rate_mps: -0.1,
            ramp_height_sigma_m: 0.3,
            landing_point_climb_rate_sigma_mps: 0.4,
            ramp_update_response_m2: [0.0; 2],
            landing_point_update_response_m2: [0.0; 2],
            roll_rad: 0.0,
        };
        let roll = SensedRoll {
            measurement: LateralShipMotionMeasurement {
                time_s: 10.0,
                motion: LateralShipMotionOutputs {
                    roll_rad: 0.02,
                    roll_rate_radps: 0.005,
                    yaw_rad: 0.0,
                    yaw_rate_radps: 0.0,
                    sway_m: 0.0,
                    sway_rate_mps: 0.0,
                },
            },
            landing_point_rise_m: 10.0,
            ramp_rise_m: 0.6,
        };
        // Touchdown 3 s after a measurement 0.5 s old; the ramp, 60 m aft at 60 m/s, 1 s
        // before it. The roll at each horizon is the oscillator's, checked above.
        let moved = roll.add_to(forecast, 10.5, 2.5, 60.0, 60.0);
        let (at_touchdown, rate_at_touchdown) = roll_forecast(&roll.measurement, 3.0);
        let (at_ramp, rate_at_ramp) = roll_forecast(&roll.measurement, 2.0);
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(
            moved.landing_point_height_m,
            2.0 + 10.0 * at_touchdown.sin()
        ));
        assert!(close(
            moved.landing_point_climb_rate_mps,
            0.2 + 10.0 * at_touchdown.cos() * rate_at_touchdown
        ));
        assert!(close(moved.ramp_height_m, 1.0 + 0.6 * at_ramp.sin()));
        assert!(close(
            moved.ramp_climb_rate_mps,
            -0.1 + 0.6 * at_ramp.cos() * rate_at_ramp
        ));
        // The σ and the pitch are the heave-and-pitch forecast's.
        assert_eq!(
            (
                moved.pitch_rad,
                moved.ramp_height_sigma_m,
                moved.landing_point_climb_rate_sigma_mps
            ),
            (0.01, 0.3, 0.4)
        );
        // A level ship at rest moves nothing.
        let level = SensedRoll {
            measurement: LateralShipMotionMeasurement {
                motion: LateralShipMotionOutputs {
                    roll_rad: 0.0,
                    roll_rate_radps: 0.0,
                    ..roll.measurement.motion
                },
                ..roll.measurement
            },
            ..roll
        };
        assert_eq!(level.add_to(forecast, 10.5, 2.5, 60.0, 60.0), forecast);
    }
}
