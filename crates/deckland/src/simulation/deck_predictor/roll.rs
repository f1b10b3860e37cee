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
