//! The 3-D approach's outcomes (shared model §10.8; docs/model.md §10.4): at touchdown
//! the hook's offset from the landing area's centreline, its drift across it relative
//! to the deck, the bank and the heading to the centreline; at the ramp the lineup error
//! in degrees as the landing signal officer grades it (the angle off the centreline seen
//! from the aim point); and whether the touchdown is off centre.

pub use crate::control::wave_off_lateral::MAX_OFF_CENTRE_M;
pub use crate::simulation::outcome::LateralTouchdown;
/// Bank limit at touchdown reported as a safety statistic (deg): 5, an assumption.
pub const MAX_TOUCHDOWN_BANK_DEG: f64 = 5.0;
/// Drift limit at touchdown reported as a safety statistic (m/s): 1.5, an assumption.
pub const MAX_TOUCHDOWN_DRIFT_MPS: f64 = 1.5;

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
