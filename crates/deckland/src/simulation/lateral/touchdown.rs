//! The 3-D approach's outcomes (shared model §10.8; docs/model.md §10.4): at touchdown
//! the hook's offset from the landing area's centreline, its drift across it relative
//! to the deck, the bank and the heading to the centreline; at the ramp the lineup error
//! in degrees as the landing signal officer grades it (the angle off the centreline seen
//! from the aim point); and whether the touchdown is off centre.

use serde::Serialize;

pub use crate::control::wave_off_lateral::MAX_OFF_CENTRE_M;
/// Bank limit at touchdown reported as a safety statistic (deg): 5, an assumption.
pub const MAX_TOUCHDOWN_BANK_DEG: f64 = 5.0;
/// Drift limit at touchdown reported as a safety statistic (m/s): 1.5, an assumption.
pub const MAX_TOUCHDOWN_DRIFT_MPS: f64 = 1.5;

/// The lateral outcome of a 3-D approach.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LateralTouchdown {
    /// The hook's offset right of the centreline at touchdown (m).
    pub offset_m: f64,
    /// Its rate across the centreline relative to the deck (m/s, right).
    pub drift_rate_mps: f64,
    /// Bank angle at touchdown (deg, right wing down).
    pub bank_deg: f64,
    /// Heading relative to the centreline at touchdown (deg, nose right).
    pub heading_to_centreline_deg: f64,
    /// Lineup error at the ramp: the angle of the hook off the centreline seen from the
    /// aim point (deg, right); `None` if the hook did not cross the ramp.
    pub ramp_lineup_error_deg: Option<f64>,
    /// Whether the touchdown is more than [`MAX_OFF_CENTRE_M`] off the centreline.
    pub off_centre: bool,
}

/// The lineup error at the ramp (deg): the hook `offset_m` right of the centreline
/// `ramp_aft_of_aim_point_m` aft of the aim point, seen from the aim point.
pub fn ramp_lineup_error_deg(offset_m: f64, ramp_aft_of_aim_point_m: f64) -> f64 {
    offset_m.atan2(ramp_aft_of_aim_point_m).to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn half_a_degree_at_the_ramp_is_about_half_a_metre() {
        // 60 m·tan 0.5° = 0.524 m.
        assert!((ramp_lineup_error_deg(0.524, 60.0) - 0.5).abs() < 1e-3);
        assert!(ramp_lineup_error_deg(-1.0, 60.0) < 0.0);
    }
}
