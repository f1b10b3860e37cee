//! Every signal of the closed loop at one instant: what recorders receive and what the
//! run loop looks at to find events.

use crate::environment::{EarthPoint, ShipPose, ShipPoseRate, Wind};

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
    /// Reference height of the hook from the flight-path generator (m).
    pub path_height_m: f64,
    /// Glide-path error h_ref − h_hook (m), positive when below the path.
    pub glide_path_error_m: f64,
    /// Time to touchdown estimated by the generator (s).
    pub time_to_go_s: f64,
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
    /// Climb-rate command (m/s).
    pub climb_rate_command_mps: f64,
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
}
