//! The angled deck in three dimensions on a ship that steams, heaves, pitches, rolls,
//! yaws and sways (docs/model.md §3.8; shared model §10.5).
//!
//! Ship axes: x forward along the ship's centreline, y to starboard, z down, with their
//! origin, the ship's rotation centre, on the roll axis `deck_height_above_roll_axis_m`
//! (19 m) below the pitch centre of §2.7. The landing area's centreline passes through
//! the aim point, 81 m aft of the pitch centre and `aim_point_port_of_centreline_m`
//! (10 m) to port, and is angled `deck_angle_deg` (9°) to port of the ship's centreline,
//! so that going aft along it leads to starboard. A deck point s metres forward of the
//! aim point along it (ramp s = −60 m, wires at their `wire_positions_m`) is at
//! (−81 + s·cos δ, −a − s·sin δ, −d) in ship axes.
//!
//! Earth axes are those of §1 and §10.1: x along the final bearing, which is the landing
//! area's centreline at the ship's mean heading, y to the right, h up. The ship's mean
//! heading is therefore δ to starboard of earth x, and the ship steams along it at its
//! forward speed V: its pitch centre moves at V·(cos δ, sin δ), so the landing area's
//! centreline drifts to the right at V·sin δ (1.2 m/s at 7.7 m/s and 9°).
//!
//! Attitude: the ship-to-earth rotation is R = R_z(ψ₀ + ψ_s)·R_y(θ_s)·R_x(φ_s) (yaw,
//! pitch, roll; ψ₀ = δ), all about the rotation centre, which is at earth
//! (x_G, y_G, h_deck − d + z_G): heave z_G and sway move it, and the pose's pitch-centre
//! x, y are its horizontal position. With δ = 0, a = 0, d = 0 and no roll, yaw or sway,
//! every point equals [`DeckGeometry::point_along_deck`] exactly (same operations).
//! Roll φ_s moves a deck point at lateral position y down by y·sin φ_s and to starboard
//! by d·sin φ_s (to first order), as §10.5 states.

use super::deck::{DeckGeometry, EarthPoint, EarthVelocity, ShipPose, ShipPoseRate};
use super::ship::{ShipMotion, ShipMotionState};

/// A unit direction in earth axes: x forward, y right, h up (–).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EarthDirection {
    /// Component along earth x.
    pub x: f64,
    /// Component along earth y (right).
    pub y: f64,
    /// Component up.
    pub h: f64,
}

/// The landing area's centreline at one instant: a point on it (the aim point) and its
/// forward direction, both in earth axes.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DeckCentreline {
    /// The aim point (m).
    pub point: EarthPoint,
    /// The unit direction forward along the landing area.
    pub direction: EarthDirection,
}

/// The ship's attitude at one instant, evaluated once: the ship-to-earth rotation R, the
/// angular velocity in earth axes and the deck angle's sine and cosine, so that several
/// points and velocities of one pose share one evaluation of their sines and cosines
/// (the results are those of the single-point methods, to the bit).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipAttitude {
    rotation: [[f64; 3]; 3],
    angular_velocity: [f64; 3],
    deck_angle_sin_cos: (f64, f64),
}

/// sin, cos of the heading ψ₀ + ψ_s, of the pitch θ_s and of the roll φ_s.
pub(crate) type AttitudeSinCos = [(f64, f64); 3];

fn attitude_sin_cos(pose: &ShipPose, mean_heading_rad: f64) -> AttitudeSinCos {
    [
        (mean_heading_rad + pose.yaw_rad).sin_cos(),
        sin_cos(pose.pitch_rad),
        sin_cos(pose.roll_rad),
    ]
}

/// sin, cos of `angle` (rad); of ±0 without evaluating them (sin ±0 = ±0, cos ±0 = 1:
/// the same values), as for a pose without pitch or roll.
#[inline]
fn sin_cos(angle: f64) -> (f64, f64) {
    if angle == 0.0 {
        (angle, 1.0)
    } else {
        angle.sin_cos()
    }
}

/// Ship-to-earth rotation R = R_z(ψ)·R_y(θ)·R_x(φ), in (x forward, y right, z down).
fn rotation(angles: &AttitudeSinCos) -> [[f64; 3]; 3] {
    let [(s_psi, c_psi), (s_theta, c_theta), (s_phi, c_phi)] = *angles;
    [
        [
            c_psi * c_theta,
            c_psi * s_theta * s_phi - s_psi * c_phi,
            c_psi * s_theta * c_phi + s_psi * s_phi,
        ],
        [
            s_psi * c_theta,
            s_psi * s_theta * s_phi + c_psi * c_phi,
            s_psi * s_theta * c_phi - c_psi * s_phi,
        ],
        [-s_theta, c_theta * s_phi, c_theta * c_phi],
    ]
}

/// R·v for a ship-axes vector v (x forward, y starboard, z down).
fn rotate(r: &[[f64; 3]; 3], v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|i| r[i][0] * v[0] + r[i][1] * v[1] + r[i][2] * v[2])
}

/// The ship's angular velocity in earth axes (x, y, z down) from the Euler rates.
fn angular_velocity(angles: &AttitudeSinCos, rate: &ShipPoseRate) -> [f64; 3] {
    let [(s_psi, c_psi), (s_theta, c_theta), _] = *angles;
    let (psi_dot, theta_dot, phi_dot) = (
        rate.yaw_rate_radps,
        rate.pitch_rate_radps,
        rate.roll_rate_radps,
    );
    [
        -theta_dot * s_psi + phi_dot * c_psi * c_theta,
        theta_dot * c_psi + phi_dot * s_psi * c_theta,
        psi_dot - phi_dot * s_theta,
    ]
}

impl ShipAttitude {
    /// The rate of the heading atan2(d_y, d_x) of the earth direction `direction` of a
    /// line fixed in the ship (rad/s, positive to the right): with ḋ = ω × d (earth
    /// axes, z down), (d_x·ḋ_y − d_y·ḋ_x)/(d_x² + d_y²).
    pub fn heading_rate_radps(&self, direction: &EarthDirection) -> f64 {
        let [wx, wy, wz] = self.angular_velocity;
        let (dx, dy, dz) = (direction.x, direction.y, -direction.h);
        let dx_rate = wy * dz - wz * dy;
        let dy_rate = wz * dx - wx * dz;
        (dx * dy_rate - dy * dx_rate) / (dx * dx + dy * dy)
    }
}

impl DeckGeometry {
    /// The ship's mean heading ψ₀ from earth x (rad, positive to starboard): the deck
    /// angle, since the final bearing runs along the landing area's centreline.
    pub fn ship_mean_heading_rad(&self) -> f64 {
        self.deck_angle_deg.to_radians()
    }

    /// The ship's pose at time `time_s` (s) on its mean track, with the heave and pitch
    /// of `state`: its pitch centre, at earth (x₀, y₀) = `initial_pitch_centre_m` at
    /// t = 0, steams along the mean heading at the ship's forward speed V,
    /// (x, y) = (x₀ + V·cos ψ₀·t, y₀ + V·sin ψ₀·t). Complete it with
    /// [`super::LateralShipMotion::complete_pose`] for roll, yaw and sway.
    pub fn steaming_pose(
        &self,
        ship: &ShipMotion,
        state: &ShipMotionState,
        initial_pitch_centre_m: (f64, f64),
        time_s: f64,
    ) -> ShipPose {
        let speed = ship.parameters().forward_speed_mps;
        let (sin, cos) = self.ship_mean_heading_rad().sin_cos();
        let outputs = ship.outputs(state);
        ShipPose {
            pitch_centre_x_m: initial_pitch_centre_m.0 + speed * cos * time_s,
            pitch_centre_y_m: initial_pitch_centre_m.1 + speed * sin * time_s,
            heave_m: outputs.heave_m,
            pitch_rad: outputs.pitch_rad,
            ..ShipPose::default()
        }
    }

    /// Rates of [`DeckGeometry::steaming_pose`]: V·(cos ψ₀, sin ψ₀), heave and pitch rate.
    pub fn steaming_pose_rate(&self, ship: &ShipMotion, state: &ShipMotionState) -> ShipPoseRate {
        let speed = ship.parameters().forward_speed_mps;
        let (sin, cos) = self.ship_mean_heading_rad().sin_cos();
        let outputs = ship.outputs(state);
        ShipPoseRate {
            pitch_centre_x_rate_mps: speed * cos,
            pitch_centre_y_rate_mps: speed * sin,
            heave_rate_mps: outputs.heave_rate_mps,
            pitch_rate_radps: outputs.pitch_rate_radps,
            ..ShipPoseRate::default()
        }
    }

    /// The ship's attitude for the 3-D `pose` and its `rate` ([`ShipAttitude`]).
    pub fn ship_attitude(&self, pose: &ShipPose, rate: &ShipPoseRate) -> ShipAttitude {
        let mean_heading_rad = self.ship_mean_heading_rad();
        let angles = attitude_sin_cos(pose, mean_heading_rad);
        // The deck angle is the mean heading: without yaw, its sine and cosine are the
        // heading's.
        let deck_angle_sin_cos = if (mean_heading_rad + pose.yaw_rad).to_bits()
            == self.deck_angle_deg.to_radians().to_bits()
        {
            angles[0]
        } else {
            self.deck_angle_deg.to_radians().sin_cos()
        };
        Self::ship_attitude_of(&angles, rate, deck_angle_sin_cos)
    }

    /// The sines and cosines of the heading ψ₀ + ψ_s, of the pitch θ_s and of the roll
    /// φ_s of the 3-D `pose`.
    pub(crate) fn attitude_sin_cos(&self, pose: &ShipPose) -> AttitudeSinCos {
        attitude_sin_cos(pose, self.ship_mean_heading_rad())
    }

    /// [`DeckGeometry::ship_attitude`] from the attitude's sines and cosines `angles`
    /// ([`DeckGeometry::attitude_sin_cos`]) and the deck angle's `deck_angle_sin_cos`, evaluated once
    /// by the caller.
    pub(crate) fn ship_attitude_of(
        angles: &AttitudeSinCos,
        rate: &ShipPoseRate,
        deck_angle_sin_cos: (f64, f64),
    ) -> ShipAttitude {
        ShipAttitude {
            rotation: rotation(angles),
            angular_velocity: angular_velocity(angles, rate),
            deck_angle_sin_cos,
        }
    }

    /// [`DeckGeometry::aim_point`] and [`DeckGeometry::velocity_along_deck`] at the aim
    /// point (the longitudinal deck geometry, Eq. 17–18) with the pitch's (sin θ_s,
    /// cos θ_s) evaluated once by the caller: the same operations, the same results.
    pub(crate) fn aim_point_along_deck_of(
        &self,
        pose: &ShipPose,
        rate: &ShipPoseRate,
        (sin, cos): (f64, f64),
    ) -> (EarthPoint, EarthVelocity) {
        let r = self.landing_point_aft_of_pitch_centre_m - 0.0;
        (
            EarthPoint {
                x_m: pose.pitch_centre_x_m - r * cos,
                y_m: pose.pitch_centre_y_m,
                h_m: self.deck_height_m + pose.heave_m - r * sin,
            },
            EarthVelocity {
                x_mps: rate.pitch_centre_x_rate_mps + r * sin * rate.pitch_rate_radps,
                y_mps: rate.pitch_centre_y_rate_mps,
                h_mps: rate.heave_rate_mps - r * cos * rate.pitch_rate_radps,
            },
        )
    }

    /// Ship-axes position (x forward, y starboard, z down; m) of the deck point `s_m`
    /// metres forward of the aim point along the landing area's centreline, from the
    /// rotation centre, with the deck angle's (sin, cos).
    fn ship_axes_point_at(&self, (sin, cos): (f64, f64), s_m: f64) -> [f64; 3] {
        [
            -self.landing_point_aft_of_pitch_centre_m + s_m * cos,
            -self.aim_point_port_of_centreline_m - s_m * sin,
            -self.deck_height_above_roll_axis_m,
        ]
    }

    /// [`DeckGeometry::ship_axes_point_at`] at this deck's angle.
    #[cfg(test)]
    fn ship_axes_point(&self, s_m: f64) -> [f64; 3] {
        self.ship_axes_point_at(self.deck_angle_deg.to_radians().sin_cos(), s_m)
    }

    /// Earth position of the deck point `s_m` metres forward of the aim point along the
    /// landing area's centreline (module docs), for the full 3-D `pose`.
    pub fn point_on_landing_centreline(&self, pose: &ShipPose, s_m: f64) -> EarthPoint {
        let attitude = self.ship_attitude(pose, &ShipPoseRate::default());
        self.point_on_landing_centreline_at(&attitude, pose, s_m)
    }

    /// [`DeckGeometry::point_on_landing_centreline`] with the pose's `attitude`.
    pub fn point_on_landing_centreline_at(
        &self,
        attitude: &ShipAttitude,
        pose: &ShipPose,
        s_m: f64,
    ) -> EarthPoint {
        let point = self.ship_axes_point_at(attitude.deck_angle_sin_cos, s_m);
        let offset = rotate(&attitude.rotation, point);
        let centre_h = self.deck_height_m - self.deck_height_above_roll_axis_m + pose.heave_m;
        EarthPoint {
            x_m: pose.pitch_centre_x_m + offset[0],
            y_m: pose.pitch_centre_y_m + offset[1],
            h_m: centre_h - offset[2],
        }
    }

    /// Earth velocity of [`DeckGeometry::point_on_landing_centreline`]: the rotation
    /// centre's velocity plus ω × (R·p).
    pub fn velocity_on_landing_centreline(
        &self,
        pose: &ShipPose,
        rate: &ShipPoseRate,
        s_m: f64,
    ) -> EarthVelocity {
        self.velocity_on_landing_centreline_at(&self.ship_attitude(pose, rate), rate, s_m)
    }

    /// [`DeckGeometry::velocity_on_landing_centreline`] with the pose's `attitude`.
    pub fn velocity_on_landing_centreline_at(
        &self,
        attitude: &ShipAttitude,
        rate: &ShipPoseRate,
        s_m: f64,
    ) -> EarthVelocity {
        let point = self.ship_axes_point_at(attitude.deck_angle_sin_cos, s_m);
        let offset = rotate(&attitude.rotation, point);
        let omega = attitude.angular_velocity;
        let cross = [
            omega[1] * offset[2] - omega[2] * offset[1],
            omega[2] * offset[0] - omega[0] * offset[2],
            omega[0] * offset[1] - omega[1] * offset[0],
        ];
        EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps + cross[0],
            y_mps: rate.pitch_centre_y_rate_mps + cross[1],
            h_mps: rate.heave_rate_mps - cross[2],
        }
    }

    /// The aim point in three dimensions.
    pub fn aim_point_3d(&self, pose: &ShipPose) -> EarthPoint {
        self.point_on_landing_centreline(pose, 0.0)
    }

    /// The ramp in three dimensions, on the landing area's centreline.
    pub fn ramp_3d(&self, pose: &ShipPose) -> EarthPoint {
        self.point_on_landing_centreline(pose, -self.ramp_aft_of_aim_point_m)
    }

    /// The four wires' crossings of the landing area's centreline, aft (wire 1) to
    /// forward (wire 4).
    pub fn wires_3d(&self, pose: &ShipPose) -> [EarthPoint; 4] {
        self.wire_positions_m
            .map(|s_m| self.point_on_landing_centreline(pose, s_m))
    }

    /// The landing area's centreline: the aim point and the forward direction.
    pub fn landing_centreline(&self, pose: &ShipPose) -> DeckCentreline {
        let attitude = self.ship_attitude(pose, &ShipPoseRate::default());
        self.landing_centreline_at(&attitude, pose)
    }

    /// [`DeckGeometry::landing_centreline`] with the pose's `attitude`.
    pub fn landing_centreline_at(
        &self,
        attitude: &ShipAttitude,
        pose: &ShipPose,
    ) -> DeckCentreline {
        let (sin, cos) = attitude.deck_angle_sin_cos;
        let direction = rotate(&attitude.rotation, [cos, -sin, 0.0]);
        DeckCentreline {
            point: self.point_on_landing_centreline_at(attitude, pose, 0.0),
            direction: EarthDirection {
                x: direction[0],
                y: direction[1],
                h: -direction[2],
            },
        }
    }

    /// Horizontal distance of earth point `point` to the right of the landing area's
    /// centreline (m; negative to the left), measured square to the centreline's
    /// horizontal direction: the lineup offset of a point such as the hook.
    pub fn offset_right_of_landing_centreline(&self, pose: &ShipPose, point: &EarthPoint) -> f64 {
        let line = self.landing_centreline(pose);
        let norm = line.direction.x.hypot(line.direction.y);
        let (dx, dy) = (point.x_m - line.point.x_m, point.y_m - line.point.y_m);
        (line.direction.x * dy - line.direction.y * dx) / norm
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn at_the_mean_heading_the_landing_centreline_is_the_final_bearing() {
        let deck = DeckGeometry::default();
        let line = deck.landing_centreline(&ShipPose::default());
        assert!((line.direction.x - 1.0).abs() < 1e-15);
        assert!(line.direction.y.abs() < 1e-15 && line.direction.h.abs() < 1e-15);
        // The ramp lies on it, 60 m aft of the aim point.
        let (aim, ramp) = (line.point, deck.ramp_3d(&ShipPose::default()));
        assert!((aim.x_m - ramp.x_m - 60.0).abs() < 1e-12);
        assert!((aim.y_m - ramp.y_m).abs() < 1e-12);
    }

    #[test]
    fn the_ramp_is_about_9_4_m_to_starboard_of_the_aim_point_in_ship_axes() {
        // §10.5: 60·sin 9° = 9.386 m.
        let deck = DeckGeometry::default();
        let (aim, ramp) = (deck.ship_axes_point(0.0), deck.ship_axes_point(-60.0));
        assert!((ramp[1] - aim[1] - 9.386).abs() < 1e-3);
    }

    #[test]
    fn the_attitude_and_aim_point_from_sines_and_cosines_are_those_of_the_pose() {
        let deck = DeckGeometry::default();
        let pose = ShipPose {
            pitch_centre_x_m: 12.5,
            pitch_centre_y_m: -3.0,
            heave_m: 0.7,
            pitch_rad: 0.021,
            roll_rad: -0.013,
            yaw_rad: 0.004,
        };
        let rate = ShipPoseRate {
            pitch_centre_x_rate_mps: 7.6,
            pitch_centre_y_rate_mps: 1.2,
            heave_rate_mps: -0.4,
            pitch_rate_radps: 0.01,
            roll_rate_radps: 0.02,
            yaw_rate_radps: -0.003,
        };
        let angles = deck.attitude_sin_cos(&pose);
        let deck_angle = deck.deck_angle_deg.to_radians().sin_cos();
        assert_eq!(
            DeckGeometry::ship_attitude_of(&angles, &rate, deck_angle),
            deck.ship_attitude(&pose, &rate)
        );
        let (aim, velocity) = deck.aim_point_along_deck_of(&pose, &rate, angles[1]);
        assert_eq!(aim, deck.aim_point(&pose));
        assert_eq!(velocity, deck.velocity_along_deck(&pose, &rate, 0.0));
    }

    #[test]
    fn the_centreline_heading_rate_is_the_derivative_of_its_heading() {
        // The pose moved along its rate by ±h: the heading's central difference.
        let deck = DeckGeometry::default();
        let pose = ShipPose {
            pitch_rad: 0.02,
            roll_rad: -0.015,
            yaw_rad: 0.004,
            ..ShipPose::default()
        };
        let rate = ShipPoseRate {
            pitch_rate_radps: 0.012,
            roll_rate_radps: 0.02,
            yaw_rate_radps: -0.003,
            ..ShipPoseRate::default()
        };
        let heading = |h: f64| {
            let moved = ShipPose {
                pitch_rad: pose.pitch_rad + h * rate.pitch_rate_radps,
                roll_rad: pose.roll_rad + h * rate.roll_rate_radps,
                yaw_rad: pose.yaw_rad + h * rate.yaw_rate_radps,
                ..pose
            };
            let d = deck.landing_centreline(&moved).direction;
            d.y.atan2(d.x)
        };
        let h = 1e-3;
        let numerical = (heading(h) - heading(-h)) / (2.0 * h);
        let attitude = deck.ship_attitude(&pose, &rate);
        let analytical = attitude.heading_rate_radps(&deck.landing_centreline(&pose).direction);
        assert!(
            (analytical - numerical).abs() < 1e-9,
            "{analytical} vs {numerical}"
        );
        assert!((analytical - rate.yaw_rate_radps).abs() < 1e-3);
    }

    #[test]
    fn offset_right_of_the_centreline_is_signed() {
        let deck = DeckGeometry::default();
        let pose = ShipPose::default();
        let mut point = deck.point_on_landing_centreline(&pose, -300.0);
        assert!(deck.offset_right_of_landing_centreline(&pose, &point).abs() < 1e-9);
        point.y_m += 2.0;
        let offset = deck.offset_right_of_landing_centreline(&pose, &point);
        assert!((offset - 2.0).abs() < 1e-9, "{offset}");
    }
}
