//! The ship's pose in the 3-D approach and what the blocks read of it (docs/model.md
//! §10.1): the full 3-D pose (steaming, heave, pitch, roll, yaw, sway), the 3-D aim
//! point and centreline, and the equivalent longitudinal pose the longitudinal blocks
//! see — the 3-D pose with its pitch centre's x and its heave shifted so that the
//! longitudinal deck geometry ([`DeckGeometry::aim_point`], the deck plane, the ramp)
//! puts the aim point where the 3-D geometry does, and its y at the 3-D aim point's.

use super::LateralLoop;
use crate::environment::{
    DeckGeometry, EarthDirection, EarthPoint, EarthVelocity, LateralShipMotionState, ShipAttitude,
    ShipMotion, ShipMotionState, ShipPose, ShipPoseRate,
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
        let (view, direction) = self.deck_view_parts(ship, deck, ship_state, lateral_state, time_s);
        DeckView3d {
            centreline_heading_rad: direction.y.atan2(direction.x),
            ..view
        }
    }

    /// The equivalent longitudinal pose and its rate of [`LateralLoop::deck_view`] alone
    /// (what the longitudinal blocks' per-step samples read), without the centreline's
    /// heading.
    pub fn longitudinal_pose(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        ship_state: &ShipMotionState,
        lateral_state: &LateralShipMotionState,
        time_s: f64,
    ) -> (ShipPose, ShipPoseRate) {
        let (view, _) = self.deck_view_parts(ship, deck, ship_state, lateral_state, time_s);
        (view.longitudinal, view.longitudinal_rate)
    }

    /// The ship's pose and its rate at `time_s`: [`DeckGeometry::steaming_pose`]
    /// completed by [`crate::environment::LateralShipMotion::complete_pose`] (and their
    /// rates), with the same operations, the mean heading's sine and cosine taken from
    /// [`LateralLoop::mean_heading_sin_cos`] instead of evaluated four times.
    fn pose_and_rate(
        &self,
        ship: &ShipMotion,
        ship_state: &ShipMotionState,
        lateral_state: &LateralShipMotionState,
        time_s: f64,
    ) -> (ShipPose, ShipPoseRate) {
        let (sin, cos) = self.mean_heading_sin_cos;
        let speed = ship.parameters().forward_speed_mps;
        let (x0, y0) = self.initial_pitch_centre_m;
        let outputs = ship.outputs(ship_state);
        let lateral = self.ship.outputs(lateral_state);
        let pose = ShipPose {
            pitch_centre_x_m: (x0 + speed * cos * time_s) - lateral.sway_m * sin,
            pitch_centre_y_m: (y0 + speed * sin * time_s) + lateral.sway_m * cos,
            heave_m: outputs.heave_m,
            pitch_rad: outputs.pitch_rad,
            roll_rad: lateral.roll_rad,
            yaw_rad: lateral.yaw_rad,
        };
        let rate = ShipPoseRate {
            pitch_centre_x_rate_mps: speed * cos - lateral.sway_rate_mps * sin,
            pitch_centre_y_rate_mps: speed * sin + lateral.sway_rate_mps * cos,
            heave_rate_mps: outputs.heave_rate_mps,
            pitch_rate_radps: outputs.pitch_rate_radps,
            roll_rate_radps: lateral.roll_rate_radps,
            yaw_rate_radps: lateral.yaw_rate_radps,
        };
        (pose, rate)
    }

    /// [`LateralLoop::deck_view`] without the centreline's heading (left 0), and the
    /// centreline's direction it comes from.
    fn deck_view_parts(
        &self,
        ship: &ShipMotion,
        deck: &DeckGeometry,
        ship_state: &ShipMotionState,
        lateral_state: &LateralShipMotionState,
        time_s: f64,
    ) -> (DeckView3d, EarthDirection) {
        let (pose, rate) = self.pose_and_rate(ship, ship_state, lateral_state, time_s);
        let attitude = deck.ship_attitude(&pose, &rate);
        let line = deck.landing_centreline_at(&attitude, &pose);
        let aim = line.point;
        let aim_velocity = deck.velocity_on_landing_centreline_at(&attitude, &rate, 0.0);
        let flat_aim = deck.aim_point(&pose);
        let flat_velocity = deck.velocity_along_deck(&pose, &rate, 0.0);
        let view = DeckView3d {
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
            centreline_heading_rad: 0.0,
        };
        (view, line.direction)
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
        // The pose with the cached mean heading is the composition of the environment's
        // steaming pose and lateral completion, to the bit.
        let heading = deck.ship_mean_heading_rad();
        let composed = lateral.ship.complete_pose(
            &lateral_state,
            deck.steaming_pose(&ship, &ship_state, lateral.initial_pitch_centre_m, 10.0),
            heading,
        );
        let composed_rate = lateral.ship.complete_pose_rate(
            &lateral_state,
            deck.steaming_pose_rate(&ship, &ship_state),
            heading,
        );
        assert_eq!((view.pose, view.rate), (composed, composed_rate));
        let line = deck.landing_centreline(&composed);
        assert_eq!(view.aim, line.point);
        assert_eq!(
            view.centreline_heading_rad,
            line.direction.y.atan2(line.direction.x)
        );
        assert_eq!(
            view.aim_velocity,
            deck.velocity_on_landing_centreline(&composed, &composed_rate, 0.0)
        );
        let longitudinal =
            lateral.longitudinal_pose(&ship, &deck, &ship_state, &lateral_state, 10.0);
        assert_eq!(longitudinal, (view.longitudinal, view.longitudinal_rate));
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
