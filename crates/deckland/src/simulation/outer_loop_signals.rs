//! What the outer loops read and give at one instant (docs/model.md §5): the signals
//! that pass between them and the blocks around them, which both sides import.

use crate::control::PathReference;

/// The hook's kinematics and the aircraft's climb rate, as the outer loops read them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OuterLoopInputs {
    pub time_s: f64,
    pub theta_trim_rad: f64,
    pub climb_rate_mps: f64,
    /// The air-relative flight-path angle θ − α (rad).
    pub air_path_angle_rad: f64,
    /// The pitch attitude θ (rad).
    pub theta_rad: f64,
    /// The angle of attack α (rad).
    pub alpha_rad: f64,
    /// The pitch rate q (rad/s).
    pub pitch_rate_radps: f64,
    pub hook_x_m: f64,
    pub hook_h_m: f64,
    pub hook_x_rate_mps: f64,
    pub hook_climb_rate_mps: f64,
    /// ∫ climb-rate error dt (m).
    pub sink_rate_integral_m: f64,
    /// ∫ hook height error dt (m·s).
    pub guidance_integral_m_s: f64,
    /// Pitch fed forward against the steady air wake's vertical wind (rad).
    pub wake_pitch_feedforward_rad: f64,
}

/// The outer loops' outputs at one instant.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OuterLoopOutputs {
    /// The pitch command, after the taps (rad).
    pub theta_ref_rad: f64,
    /// Its rate (rad/s) when it is a shaped trajectory, else 0.
    pub theta_ref_rate_radps: f64,
    /// Its acceleration (rad/s²) when it is a shaped trajectory, else 0.
    pub theta_ref_acceleration_radps2: f64,
    /// The climb-rate command (m/s); NaN when no loop commands one.
    pub climb_rate_command_mps: f64,
    /// The glide path, in an approach.
    pub path: Option<PathReference>,
    /// Height error of the hook to the path h_ref − h (m), 0 outside an approach.
    pub height_error_m: f64,
    /// Climb-rate error (m/s), 0 without a sink-rate loop.
    pub climb_rate_error_mps: f64,
    /// Whether a wave-off's floor raised the pitch command (the sink-rate integrator
    /// then holds).
    pub pitch_floored: bool,
    /// The late abort's share of full up direct lift (–), 0 outside it.
    pub late_abort_lift_share: f64,
    /// The late abort's share of full thrust (–), 0 outside it or without its thrust.
    pub late_abort_thrust_share: f64,
}

impl OuterLoopOutputs {
    /// The outputs of a pitch command `theta_ref_rad` (rad), with its rate (rad/s) and
    /// acceleration (rad/s²), that no climb-rate loop or approach led to.
    #[inline(always)]
    pub(super) fn pitch_only(
        theta_ref_rad: f64,
        theta_ref_rate_radps: f64,
        theta_ref_acceleration_radps2: f64,
    ) -> Self {
        Self {
            theta_ref_rad,
            theta_ref_rate_radps,
            theta_ref_acceleration_radps2,
            climb_rate_command_mps: f64::NAN,
            path: None,
            height_error_m: 0.0,
            climb_rate_error_mps: 0.0,
            pitch_floored: false,
            late_abort_lift_share: 0.0,
            late_abort_thrust_share: 0.0,
        }
    }
}
