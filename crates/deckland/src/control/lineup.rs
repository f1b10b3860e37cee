//! Lineup guidance (docs/model.md §10.2; shared model §10.7): the hook's lateral offset
//! from the landing area's centreline, and its rate, to a bank command for the roll law.
//!
//! With the roll law much faster than the lineup (its 2 % settling time is 1 s), the
//! hook's lateral motion relative to the centreline is a double integrator of bank,
//! ÿ ≈ g·φ (a coordinated turn, β = 0, turns the heading at ψ̇ = g·tan φ/V and the track
//! with it). A PD on the offset y_e and its rate ẏ_e,
//! φ_c = −(ω²/g)·y_e − (2ζω/g)·ẏ_e, places the lineup's poles at natural frequency ω and
//! damping ζ. A steady crosswind needs no integral: the heading, the integral of bank,
//! settles into the crab that holds the track. The command is limited to ±20° far out
//! and ±10° in the last 12 s (shared model §10.7), the limit passing from one to the
//! other smoothly over [`LineupParameters::limit_blend_s`] (w = 3s² − 2s³), so that no
//! mode change steps the command.
//!
//! In close the loop is tightened: its natural frequency passes from ω far out to
//! [`LineupParameters::close_natural_frequency_radps`] with the deck-motion
//! compensation's weight (docs/model.md §10.2), the weight that also moves its
//! reference line onto the forecast centreline, so that the hook follows the deck's
//! lateral motion forecast in the last seconds. The weight is smooth, so the gains
//! change without a step.

use crate::parameters::{check_ranges, Bounds, ParameterError};

/// Where the lineup guidance's parameters are named in errors.
pub const LINEUP_SECTION: &str = "control.lineup";

/// Tuning and limits of the lineup guidance (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LineupParameters {
    /// Natural frequency ω of the lineup (rad/s), (0, 2]: 0.4, a correction of a few
    /// metres settles in about 15 s, a quarter of the roll loop's bandwidth or less
    /// (an assumption, docs/three-d-approach.md).
    pub natural_frequency_radps: f64,
    /// Damping ratio ζ of the lineup (–), [0.3, 3]: 0.9.
    pub damping_ratio: f64,
    /// Natural frequency in close (rad/s), (0, 2]: 0.8, blended in from
    /// [`LineupParameters::natural_frequency_radps`] with the compensation weight
    /// (`approach.lineup_close_frequency_radps`; docs/three-d-approach.md).
    pub close_natural_frequency_radps: f64,
    /// The station of the landing centreline the compensation aims the hook at, aft of
    /// the aim point (m), [0, 200]: 60, the ramp (`approach.lineup_station_aft_m`;
    /// `simulation::lateral::forecast::compensation_station`).
    pub compensation_station_aft_m: f64,
    /// Largest bank command far out (deg), (0, 45]: 20 (shared model §10.7).
    pub max_bank_far_deg: f64,
    /// Largest bank command in close (deg), (0, 45]: 10 (shared model §10.7).
    pub max_bank_close_deg: f64,
    /// Time to go below which the close limit holds (s), [0, 60]: 12 (shared model §10.7).
    pub close_time_to_go_s: f64,
    /// Time over which the limit passes from far to close (s), (0, 30]: 2.
    pub limit_blend_s: f64,
    /// Gravitational acceleration the gains are scaled by (m/s²).
    pub gravity_mps2: f64,
}

impl Default for LineupParameters {
    fn default() -> Self {
        Self {
            natural_frequency_radps: 0.4,
            damping_ratio: 0.9,
            close_natural_frequency_radps: 0.8,
            compensation_station_aft_m: 60.0,
            max_bank_far_deg: 20.0,
            max_bank_close_deg: 10.0,
            close_time_to_go_s: 12.0,
            limit_blend_s: 2.0,
            gravity_mps2: 9.75,
        }
    }
}

impl LineupParameters {
    /// Checks every field against its range, naming `control.lineup.<key>`.
    pub fn validate(&self) -> Result<(), ParameterError> {
        let s = LINEUP_SECTION;
        check_ranges!(s, self, {
            natural_frequency_radps: Bounds::closed(0.0, 2.0).exclusive_min(),
            damping_ratio: Bounds::closed(0.3, 3.0),
            close_natural_frequency_radps: Bounds::closed(0.0, 2.0).exclusive_min(),
            compensation_station_aft_m: Bounds::closed(0.0, 200.0),
            max_bank_far_deg: Bounds::closed(0.0, 45.0).exclusive_min(),
            max_bank_close_deg: Bounds::closed(0.0, 45.0).exclusive_min(),
            close_time_to_go_s: Bounds::closed(0.0, 60.0),
            limit_blend_s: Bounds::closed(0.0, 30.0) .exclusive_min(),
            gravity_mps2: Bounds::closed(0.0, 30.0) .exclusive_min(),
        });
        Ok(())
    }

    /// The bank limit (rad) at `time_to_go_s` (s; `None`: far out): the far limit above
    /// the close time plus the blend, the close limit below the close time, a smooth
    /// blend between.
    pub fn bank_limit_rad(&self, time_to_go_s: Option<f64>) -> f64 {
        let far = self.max_bank_far_deg.to_radians();
        let close = self.max_bank_close_deg.to_radians();
        let Some(time_to_go_s) = time_to_go_s else {
            return far;
        };
        let s = ((time_to_go_s - self.close_time_to_go_s) / self.limit_blend_s).clamp(0.0, 1.0);
        close + (far - close) * s * s * (3.0 - 2.0 * s)
    }

    /// The natural frequency (rad/s) at the compensation weight `close_weight` (0 far
    /// out, 1 in close): ω far out + w·(ω in close − ω far out).
    pub fn natural_frequency_at(&self, close_weight: f64) -> f64 {
        let far = self.natural_frequency_radps;
        far + close_weight * (self.close_natural_frequency_radps - far)
    }

    /// The bank command (rad, right wing down positive) for the lateral error `error_m`
    /// (m, positive right of the reference line) and its rate `error_rate_mps` (m/s), at
    /// `time_to_go_s` and the compensation weight `close_weight`; limited as
    /// [`LineupParameters::bank_limit_rad`].
    pub fn bank_command_rad(
        &self,
        error_m: f64,
        error_rate_mps: f64,
        time_to_go_s: Option<f64>,
        close_weight: f64,
    ) -> f64 {
        let omega = self.natural_frequency_at(close_weight);
        let command = -(omega * omega * error_m
            + 2.0 * self.damping_ratio * omega * error_rate_mps)
            / self.gravity_mps2;
        let limit = self.bank_limit_rad(time_to_go_s);
        command.clamp(-limit, limit)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn right_of_the_line_banks_left_and_the_gains_place_the_poles() {
        let p = LineupParameters::default();
        // ÿ = g·φ with φ = −(ω²/g)·y − (2ζω/g)·ẏ: ÿ + 2ζω·ẏ + ω²·y = 0.
        let phi = p.bank_command_rad(1.0, 0.0, None, 0.0);
        assert!((phi * p.gravity_mps2 + 0.16).abs() < 1e-12, "{phi}");
        let phi_rate = p.bank_command_rad(0.0, 1.0, None, 0.0);
        assert!((phi_rate * p.gravity_mps2 + 0.72).abs() < 1e-12);
    }

    #[test]
    fn in_close_the_poles_move_to_the_close_frequency_without_a_step() {
        let p = LineupParameters::default();
        // Fully in close, ω = 0.8: ω² = 0.64 per metre, 2ζω = 1.44 per m/s (6.1°,
        // inside the close limit).
        let phi = p.bank_command_rad(0.5, 0.5, Some(5.0), 1.0);
        assert!(
            (phi * p.gravity_mps2 + 0.5 * (0.64 + 1.44)).abs() < 1e-12,
            "{phi}"
        );
        assert_eq!(p.natural_frequency_at(0.0), 0.4);
        assert!((p.natural_frequency_at(0.5) - 0.6).abs() < 1e-12);
        // A weight that moves by 1e-3 moves the command by a small amount only.
        let mut last = p.bank_command_rad(0.5, 0.1, Some(5.0), 0.0);
        for k in 1..=1000 {
            let now = p.bank_command_rad(0.5, 0.1, Some(5.0), f64::from(k) * 1e-3);
            assert!((now - last).abs() < 1e-4);
            last = now;
        }
    }

    #[test]
    fn the_limit_is_twenty_degrees_far_out_ten_in_close_and_continuous() {
        let p = LineupParameters::default();
        let deg = |t: Option<f64>| p.bank_limit_rad(t).to_degrees();
        assert!((deg(None) - 20.0).abs() < 1e-12);
        assert!((deg(Some(30.0)) - 20.0).abs() < 1e-12);
        assert!((deg(Some(12.0)) - 10.0).abs() < 1e-12);
        assert!((deg(Some(5.0)) - 10.0).abs() < 1e-12);
        assert!((deg(Some(13.0)) - 15.0).abs() < 1e-12);
        // No step anywhere: 1-ms steps change the limit by far less than a degree.
        let mut last = deg(Some(20.0));
        for k in 0..20_000 {
            let now = deg(Some(20.0 - f64::from(k) * 0.001));
            assert!((now - last).abs() < 0.01);
            last = now;
        }
        assert!(
            (p.bank_command_rad(-100.0, 0.0, Some(1.0), 1.0).to_degrees() - 10.0).abs() < 1e-12
        );
    }

    #[test]
    fn a_bad_parameter_is_named() {
        let p = LineupParameters {
            damping_ratio: 0.0,
            ..LineupParameters::default()
        };
        let error = p.validate().expect_err("out of range").to_string();
        assert!(
            error.contains("control.lineup") && error.contains("damping_ratio"),
            "{error}"
        );
    }
}
