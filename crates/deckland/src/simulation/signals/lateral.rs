//! The 3-D approach's signals on the bus (docs/model.md §10.1–10.4): `None` outside it
//! (a 3-DOF run, or a 6-DOF run with `approach.three_dimensional = false`).

/// The lateral signals of the 3-D approach at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralSignals {
    /// The hook's offset from the moving landing area's centreline, square to it (m,
    /// positive to the right).
    pub cross_track_m: Option<f64>,
    /// The rate of that offset relative to the deck (m/s, positive to the right).
    pub cross_track_rate_mps: Option<f64>,
    /// Earth y of the moving aim point, where the landing centreline passes (m).
    pub aim_point_y_m: Option<f64>,
    /// Heading of the landing centreline from the final bearing (rad, to the right).
    pub centreline_heading_rad: Option<f64>,
    /// The lineup guidance's error: the hook's offset from its reference line (the
    /// mean centreline, moved by the forecast deck motion in close) (m, right).
    pub lineup_error_m: Option<f64>,
    /// The forecast lateral displacement of the landing point at touchdown from its
    /// mean position (m, right), before the compensation weight.
    pub lateral_forecast_m: Option<f64>,
    /// Bank command of the lineup guidance (rad, right wing down).
    pub bank_command_rad: Option<f64>,
    /// Ship roll φ_s (rad, starboard side down).
    pub ship_roll_rad: Option<f64>,
    /// Ship yaw ψ_s from its mean heading (rad, bow to starboard).
    pub ship_yaw_rad: Option<f64>,
    /// Ship sway y_s along its own y axis (m, to starboard).
    pub ship_sway_m: Option<f64>,
    /// Wind at the aircraft, y (m/s, positive to the right).
    pub wind_y_mps: Option<f64>,
}
