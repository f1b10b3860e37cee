//! Every signal of the closed loop at one instant: what recorders receive and what the
//! run loop looks at to find events.
//!
//! A signal that does not apply to the mission flown (the glide path outside an
//! approach, the climb-rate command in a pitch step) is `None`, never NaN or ∞: every
//! number in a [`Signals`] of a running simulation is finite and within
//! [`SIGNAL_MAGNITUDE_LIMIT`], which the run loop checks at every step
//! ([`Signals::first_out_of_range`]); a run whose signals leave it ends as diverged,
//! naming the signal.

use crate::environment::{EarthPoint, ShipPose, ShipPoseRate, Wind};

/// The largest magnitude any signal may reach before the run is declared diverged. No
/// signal of the model comes near it (positions are kilometres, thrust about 10⁵ N); a
/// larger value means the simulation has left the model, and unit conversions or sums
/// of it could overflow to ∞ in a file.
pub const SIGNAL_MAGNITUDE_LIMIT: f64 = 1e12;

/// Every signal of interest at one instant, for recorders and event detection.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Signals {
    /// Time (s).
    pub time_s: f64,
    /// CG earth x (m).
    pub x_m: f64,
    /// CG altitude (m).
    pub h_m: f64,
    /// Hook earth x (m).
    pub hook_x_m: f64,
    /// Hook height (m).
    pub hook_h_m: f64,
    /// Hook climb rate (m/s).
    pub hook_climb_rate_mps: f64,
    /// Hook earth x rate (m/s).
    pub hook_x_rate_mps: f64,
    /// Reference height of the hook from the flight-path generator (m); `None` outside
    /// an approach (no glide path).
    pub path_height_m: Option<f64>,
    /// Glide-path error h_ref − h_hook (m), positive when below the path.
    pub glide_path_error_m: f64,
    /// Time to touchdown estimated by the generator (s); `None` outside an approach.
    pub time_to_go_s: Option<f64>,
    /// Weight of the moving deck in the glide-path anchor (0–1).
    pub compensation_weight: f64,
    /// True airspeed (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack (rad).
    pub alpha_rad: f64,
    /// Pitch angle (rad).
    pub theta_rad: f64,
    /// Measured pitch angle (rad).
    pub theta_measured_rad: f64,
    /// Pitch command from the sink-rate loop or the step (rad).
    pub theta_ref_rad: f64,
    /// Pitch rate (rad/s).
    pub q_radps: f64,
    /// CG climb rate ḣ (m/s).
    pub climb_rate_mps: f64,
    /// Climb-rate command (m/s); `None` when no loop commands one (pitch step).
    pub climb_rate_command_mps: Option<f64>,
    /// Elevator position (rad).
    pub elevator_rad: f64,
    /// Elevator rate (rad/s).
    pub elevator_rate_radps: f64,
    /// Elevator command (rad).
    pub elevator_command_rad: f64,
    /// Total actual thrust (N).
    pub thrust_n: f64,
    /// Total thrust command (N).
    pub thrust_command_n: f64,
    /// Wind at the aircraft (earth axes).
    pub wind: Wind,
    /// Distance of the CG aft of the ship's pitch centre (m).
    pub distance_aft_m: f64,
    /// The ship's pose.
    pub ship: ShipPose,
    /// The rate of the ship's pose.
    pub ship_rate: ShipPoseRate,
    /// The moving landing point.
    pub aim_point: EarthPoint,
    /// The pitch law's disturbance estimate (rad/s²), if it has one (the O-PD does).
    pub disturbance_estimate_radps2: Option<f64>,
    /// Direct lift control's lift-coefficient increment ΔC_L (–); `None` without it.
    pub direct_lift_coefficient: Option<f64>,
    /// Direct lift control's command (–); `None` without it.
    pub direct_lift_command: Option<f64>,
}

impl Signals {
    /// Every numeric signal with its name, `None` for those that do not apply.
    pub fn named_values(&self) -> [(&'static str, Option<f64>); 37] {
        [
            ("time_s", Some(self.time_s)),
            ("x_m", Some(self.x_m)),
            ("h_m", Some(self.h_m)),
            ("hook_x_m", Some(self.hook_x_m)),
            ("hook_h_m", Some(self.hook_h_m)),
            ("hook_climb_rate_mps", Some(self.hook_climb_rate_mps)),
            ("hook_x_rate_mps", Some(self.hook_x_rate_mps)),
            ("path_height_m", self.path_height_m),
            ("glide_path_error_m", Some(self.glide_path_error_m)),
            ("time_to_go_s", self.time_to_go_s),
            ("compensation_weight", Some(self.compensation_weight)),
            ("airspeed_mps", Some(self.airspeed_mps)),
            ("alpha_rad", Some(self.alpha_rad)),
            ("theta_rad", Some(self.theta_rad)),
            ("theta_measured_rad", Some(self.theta_measured_rad)),
            ("theta_ref_rad", Some(self.theta_ref_rad)),
            ("q_radps", Some(self.q_radps)),
            ("climb_rate_mps", Some(self.climb_rate_mps)),
            ("climb_rate_command_mps", self.climb_rate_command_mps),
            ("elevator_rad", Some(self.elevator_rad)),
            ("elevator_command_rad", Some(self.elevator_command_rad)),
            ("thrust_n", Some(self.thrust_n)),
            ("thrust_command_n", Some(self.thrust_command_n)),
            ("wind.x_mps", Some(self.wind.x_mps)),
            ("wind.z_mps", Some(self.wind.z_mps)),
            ("distance_aft_m", Some(self.distance_aft_m)),
            ("ship.pitch_centre_x_m", Some(self.ship.pitch_centre_x_m)),
            ("ship.heave_m", Some(self.ship.heave_m)),
            ("ship.pitch_rad", Some(self.ship.pitch_rad)),
            (
                "ship_rate.pitch_centre_x_rate_mps",
                Some(self.ship_rate.pitch_centre_x_rate_mps),
            ),
            (
                "ship_rate.heave_rate_mps",
                Some(self.ship_rate.heave_rate_mps),
            ),
            (
                "ship_rate.pitch_rate_radps",
                Some(self.ship_rate.pitch_rate_radps),
            ),
            ("aim_point.x_m", Some(self.aim_point.x_m)),
            ("aim_point.h_m", Some(self.aim_point.h_m)),
            (
                "disturbance_estimate_radps2",
                self.disturbance_estimate_radps2,
            ),
            ("direct_lift_coefficient", self.direct_lift_coefficient),
            ("direct_lift_command", self.direct_lift_command),
        ]
    }

    /// The first signal that is NaN, infinite or beyond ±[`SIGNAL_MAGNITUDE_LIMIT`], with
    /// its value; `None` when every signal is in range.
    pub fn first_out_of_range(&self) -> Option<(&'static str, f64)> {
        let in_range = |v: f64| v.abs() <= SIGNAL_MAGNITUDE_LIMIT; // false for NaN
        let values = self.named_values();
        // Checked every step: one pass without early exits (which the compiler can keep
        // branch-free), then the search for the name only when something is wrong.
        let all_in_range = values
            .iter()
            .fold(true, |ok, (_, value)| ok & value.is_none_or(in_range));
        if all_in_range {
            return None;
        }
        values
            .into_iter()
            .find_map(|(name, value)| value.filter(|v| !in_range(*v)).map(|v| (name, v)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn signals_out_of_range_are_named_with_their_value() {
        let mut signals = Signals {
            airspeed_mps: 69.1,
            ..Signals::default()
        };
        assert_eq!(signals.first_out_of_range(), None);
        signals.elevator_command_rad = f64::NEG_INFINITY;
        assert_eq!(
            signals.first_out_of_range(),
            Some(("elevator_command_rad", f64::NEG_INFINITY))
        );
        signals.elevator_command_rad = 0.0;
        signals.aim_point.x_m = 2e12;
        assert_eq!(signals.first_out_of_range(), Some(("aim_point.x_m", 2e12)));
        signals.aim_point.x_m = 0.0;
        signals.climb_rate_command_mps = Some(f64::NAN);
        let (name, value) = signals.first_out_of_range().expect("NaN is out of range");
        assert_eq!(name, "climb_rate_command_mps");
        assert!(value.is_nan());
        // A signal that does not apply is not a divergence.
        signals.climb_rate_command_mps = None;
        signals.path_height_m = None;
        assert_eq!(signals.first_out_of_range(), None);
    }
}
