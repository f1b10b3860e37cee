//! The ship's pose in the 3-D approach and what the blocks read of it (docs/model.md
//! §10.1): the full 3-D pose (steaming, heave, pitch, roll, yaw, sway), the 3-D aim
//! point and centreline, and the equivalent longitudinal pose the longitudinal blocks
//! see — the 3-D pose with its pitch centre's x and its heave shifted so that the
//! longitudinal deck geometry ([`DeckGeometry::aim_point`], the deck plane, the ramp)
//! puts the aim point where the 3-D geometry does, and its y at the 3-D aim point's.

use super::LateralLoop;
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, LateralShipMotionState, ShipAttitude, ShipMotion,
    ShipMotionState, ShipPose, ShipPoseRate,
};

/// The ship as the 3-D approach sees it at one instant.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct DeckView3d {
    /// The full 3-D pose and its rate.
    pub pose: ShipPose,
    pub rate: ShipPoseRate,
    /// The pose's rotation and angular velocity, evaluated once for every deck point.
    pub attitude: ShipAttitude,
    /// The equivalent longitudinal pose and its rate (module docs).
    pub longitudinal: ShipPose,
    pub longitudinal_rate: ShipPoseRate,
    /// The 3-D aim point and its velocity.
    pub aim: EarthPoint,
    pub aim_velocity: EarthVelocity,
    /// Heading of the landing centreline from the final bearing (rad, right).
    pub centreline_heading_rad: f64,
}

impl LateralLoop {
    /// The ship's 3-D view at `time_s` for the heave-and-pitch state `ship_state` and the
    /// lateral filters' state `lateral_state`.
    pub fn deck_view(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        ship_state: &ShipMotionState,
        lateral_state: &LateralShipMotionState,
        time_s: f64,
    ) -> DeckView3d {
        let heading = deck.ship_mean_heading_rad();
        let pose = deck.steaming_pose(ship, ship_state, self.initial_pitch_centre_m, time_s);
        let pose = self.ship.complete_pose(lateral_state, pose, heading);
        let rate = deck.steaming_pose_rate(ship, ship_state);
        let rate = self.ship.complete_pose_rate(lateral_state, rate, heading);
        let attitude = deck.ship_attitude(&pose, &rate);
        let line = deck.landing_centreline_at(&attitude, &pose);
        let aim = line.point;
        let aim_velocity = deck.velocity_on_landing_centreline_at(&attitude, &rate, 0.0);
        let flat_aim = deck.aim_point(&pose);
        let flat_velocity = deck.velocity_along_deck(&pose, &rate, 0.0);
        DeckView3d {
            pose,
            rate,
            attitude,
            longitudinal: ShipPose {
                pitch_centre_x_m: pose.pitch_centre_x_m + (aim.x_m - flat_aim.x_m),
                pitch_centre_y_m: aim.y_m,
                heave_m: pose.heave_m + (aim.h_m - flat_aim.h_m),
                ..pose
            },
            longitudinal_rate: ShipPoseRate {
                pitch_centre_x_rate_mps: rate.pitch_centre_x_rate_mps
                    + (aim_velocity.x_mps - flat_velocity.x_mps),
                pitch_centre_y_rate_mps: aim_velocity.y_mps,
                heave_rate_mps: rate.heave_rate_mps + (aim_velocity.h_mps - flat_velocity.h_mps),
                ..rate
            },
            aim,
            aim_velocity,
            centreline_heading_rad: line.direction.y.atan2(line.direction.x),
        }
    }
}

impl DeckView3d {
    /// The hook's offset to the right of the moving landing centreline (m) and its rate
    /// relative to the deck (m/s): the hook's velocity less that of the centreline's
    /// point abreast of it, square to the centreline.
    pub fn cross_track(
        &self,
        deck: &DeckGeometry,
        hook: &EarthPoint,
        hook_velocity: &EarthVelocity,
    ) -> (f64, f64) {
        let (sin, cos) = self.centreline_heading_rad.sin_cos();
        let (dx, dy) = (hook.x_m - self.aim.x_m, hook.y_m - self.aim.y_m);
        let offset = cos * dy - sin * dx;
        let along = cos * dx + sin * dy;
        let line_velocity =
            deck.velocity_on_landing_centreline_at(&self.attitude, &self.rate, along);
        let rate = cos * (hook_velocity.y_mps - line_velocity.y_mps)
            - sin * (hook_velocity.x_mps - line_velocity.x_mps);
        (offset, rate)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::ShipMotionParameters;

    #[test]
    fn the_equivalent_longitudinal_pose_puts_the_aim_point_where_the_3d_geometry_does() {
        let deck = DeckGeometry::default();
        let ship = ShipMotion::new(ShipMotionParameters {
            forward_speed_mps: 7.7,
            ..ShipMotionParameters::default()
        })
        .expect("valid");
        let lateral = super::super::build::test_loop(&deck, &ship);
        let ship_state = ShipMotionState::from_array(&[0.3, 0.1, -0.05, 0.01, 0.2, 0.0, 0.03, 0.0]);
        let lateral_state = LateralShipMotionState::from_array(&[
            0.01, 0.002, 0.003, 0.001, 0.0, 0.0, 0.4, 0.05, 0.0, 0.0,
        ]);
        let view = lateral.deck_view(&ship, &deck, &ship_state, &lateral_state, 10.0);
        let flat = deck.aim_point(&view.longitudinal);
        assert!((flat.x_m - view.aim.x_m).abs() < 1e-9);
        assert!((flat.h_m - view.aim.h_m).abs() < 1e-9);
        // The mean aim point starts at the origin and drifts right at V·sin δ.
        let still = LateralShipMotionState::default();
        let mean = lateral.deck_view(&ship, &deck, &ShipMotionState::default(), &still, 10.0);
        let drift = 7.7 * 9.0_f64.to_radians().sin() * 10.0;
        assert!((mean.aim.y_m - drift).abs() < 1e-9, "{}", mean.aim.y_m);
        assert!(mean.centreline_heading_rad.abs() < 1e-12);
        // A hook 2 m right of the line, moving with it: offset 2 m, no rate.
        let hook = EarthPoint {
            x_m: mean.aim.x_m - 500.0,
            y_m: mean.aim.y_m + 2.0,
            h_m: 50.0,
        };
        let (offset, rate) = mean.cross_track(&deck, &hook, &mean.aim_velocity);
        assert!(
            (offset - 2.0).abs() < 1e-9 && rate.abs() < 1e-9,
            "{offset} {rate}"
        );
    }
}
