//! The angled deck in three dimensions (docs/model.md §3.8; shared model §10.5): the
//! reduction to the 3-DOF deck, velocities against finite differences, the centreline's
//! drift, and roll's effect on a deck point as §10.5 states it.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::environment::{
    DeckGeometry, LateralShipMotion, LateralShipMotionState, ShipMotion, ShipMotionParameters,
    ShipMotionState, ShipPose, ShipPoseRate,
};

/// Deck positions along the landing area's centreline: the ramp, the wires, the aim
/// point and points fore and aft.
const POSITIONS_M: [f64; 8] = [-60.0, -18.0, -6.0, 0.0, 6.0, 18.0, 40.0, -300.0];

#[test]
fn with_no_angle_offset_roll_axis_or_lateral_motion_the_3d_points_are_the_3dof_points() {
    let deck = DeckGeometry {
        deck_angle_deg: 0.0,
        aim_point_port_of_centreline_m: 0.0,
        deck_height_above_roll_axis_m: 0.0,
        ..DeckGeometry::default()
    };
    for (pitch_deg, heave_m, x_m) in [(0.0, 0.0, 0.0), (1.7, -1.3, 1234.5), (-2.9, 2.2, -77.7)] {
        let pose = ShipPose {
            pitch_centre_x_m: x_m,
            pitch_centre_y_m: 3.25,
            heave_m,
            pitch_rad: f64::to_radians(pitch_deg),
            ..ShipPose::default()
        };
        for s in POSITIONS_M {
            assert_eq!(
                deck.point_on_landing_centreline(&pose, s),
                deck.point_along_deck(&pose, s),
                "pitch {pitch_deg}°, s = {s}"
            );
        }
        assert_eq!(deck.ramp_3d(&pose), deck.ramp(&pose));
        assert_eq!(deck.wires_3d(&pose), deck.wires(&pose));
        assert_eq!(deck.aim_point_3d(&pose), deck.aim_point(&pose));
        // The aim point's offset to port moves only y.
        let offset = DeckGeometry {
            aim_point_port_of_centreline_m: 10.0,
            ..deck
        };
        let (a, b) = (offset.aim_point_3d(&pose), deck.aim_point(&pose));
        assert_eq!((a.x_m, a.h_m), (b.x_m, b.h_m));
        assert_eq!(a.y_m, b.y_m - 10.0);
    }
}

/// A pose with every component away from zero, and its rates.
fn moving_ship() -> (ShipPose, ShipPoseRate) {
    (
        ShipPose {
            pitch_centre_x_m: 500.0,
            pitch_centre_y_m: -4.0,
            heave_m: 1.1,
            pitch_rad: 0.03,
            roll_rad: -0.02,
            yaw_rad: 0.006,
        },
        ShipPoseRate {
            pitch_centre_x_rate_mps: 7.6,
            pitch_centre_y_rate_mps: 1.3,
            heave_rate_mps: -0.8,
            pitch_rate_radps: 0.012,
            roll_rate_radps: 0.02,
            yaw_rate_radps: -0.004,
        },
    )
}

/// `pose` advanced by `dt` seconds at constant `rate`.
fn advanced(pose: &ShipPose, rate: &ShipPoseRate, dt: f64) -> ShipPose {
    ShipPose {
        pitch_centre_x_m: pose.pitch_centre_x_m + rate.pitch_centre_x_rate_mps * dt,
        pitch_centre_y_m: pose.pitch_centre_y_m + rate.pitch_centre_y_rate_mps * dt,
        heave_m: pose.heave_m + rate.heave_rate_mps * dt,
        pitch_rad: pose.pitch_rad + rate.pitch_rate_radps * dt,
        roll_rad: pose.roll_rad + rate.roll_rate_radps * dt,
        yaw_rad: pose.yaw_rad + rate.yaw_rate_radps * dt,
    }
}

#[test]
fn velocities_agree_with_a_central_finite_difference_of_positions() {
    let deck = DeckGeometry::default();
    let (pose, rate) = moving_ship();
    let h = 1e-4;
    for s in POSITIONS_M {
        let ahead = deck.point_on_landing_centreline(&advanced(&pose, &rate, h), s);
        let behind = deck.point_on_landing_centreline(&advanced(&pose, &rate, -h), s);
        let v = deck.velocity_on_landing_centreline(&pose, &rate, s);
        // Central-difference truncation: h²/6 times the third derivative, below 1e-8 here.
        for (difference, velocity, axis) in [
            ((ahead.x_m - behind.x_m) / (2.0 * h), v.x_mps, "x"),
            ((ahead.y_m - behind.y_m) / (2.0 * h), v.y_mps, "y"),
            ((ahead.h_m - behind.h_m) / (2.0 * h), v.h_mps, "h"),
        ] {
            assert!(
                (difference - velocity).abs() < 1e-6,
                "s = {s}, {axis}: finite difference {difference}, velocity {velocity}"
            );
        }
    }
}

#[test]
fn the_landing_centreline_drifts_right_at_ship_speed_times_the_sine_of_the_deck_angle() {
    let deck = DeckGeometry::default();
    let parameters = ShipMotionParameters {
        enabled: false,
        forward_speed_mps: 7.7,
        ..ShipMotionParameters::default()
    };
    let ship = ShipMotion::new(parameters).unwrap();
    let state = ShipMotionState::default();
    let expected = 7.7 * 9.0_f64.to_radians().sin(); // 1.2045 m/s
    assert!((expected - 1.2045).abs() < 1e-4);
    let rate = deck.steaming_pose_rate(&ship, &state);
    for s in POSITIONS_M {
        let pose = |t: f64| deck.steaming_pose(&ship, &state, (100.0, 0.0), t);
        let v = deck.velocity_on_landing_centreline(&pose(0.0), &rate, s);
        assert!((v.y_mps - expected).abs() < 1e-12, "s = {s}: {}", v.y_mps);
        let drift = deck.point_on_landing_centreline(&pose(10.0), s).y_m
            - deck.point_on_landing_centreline(&pose(0.0), s).y_m;
        assert!((drift - 10.0 * expected).abs() < 1e-9, "s = {s}: {drift}");
        // The centreline stays parallel to the final bearing (earth x) as it drifts.
        let line = deck.landing_centreline(&pose(10.0));
        assert!((line.direction.x - 1.0).abs() < 1e-12 && line.direction.y.abs() < 1e-12);
    }
    // A point that stays put sees the centreline move from its left to its right.
    let point = deck.aim_point_3d(&deck.steaming_pose(&ship, &state, (100.0, 0.0), 0.0));
    let later = deck.steaming_pose(&ship, &state, (100.0, 0.0), 4.0);
    let offset = deck.offset_right_of_landing_centreline(&later, &point);
    assert!((offset + 4.0 * expected).abs() < 1e-9, "{offset}");
}

#[test]
fn roll_moves_a_deck_point_down_by_y_sin_roll_and_to_starboard_by_19_m_sin_roll() {
    let deck = DeckGeometry::default();
    let heading = deck.ship_mean_heading_rad();
    // The ship's own starboard axis in earth x, y.
    let (starboard_x, starboard_y) = (-heading.sin(), heading.cos());
    let level = ShipPose::default();
    for roll_deg in [2.0, -3.0] {
        let roll = f64::to_radians(roll_deg);
        let rolled = ShipPose {
            roll_rad: roll,
            ..level
        };
        for s in [0.0, -60.0, 18.0] {
            // Lateral position of the point from the roll axis, in ship axes (starboard).
            let y = -10.0 - s * deck.deck_angle_deg.to_radians().sin();
            let (a, b) = (
                deck.point_on_landing_centreline(&level, s),
                deck.point_on_landing_centreline(&rolled, s),
            );
            let down = a.h_m - b.h_m;
            let starboard = (b.x_m - a.x_m) * starboard_x + (b.y_m - a.y_m) * starboard_y;
            // Second-order terms: (|y| + 19 m)(1 − cos φ).
            let second_order = (y.abs() + 19.0) * (1.0 - roll.cos()) + 1e-12;
            assert!(
                (down - y * roll.sin()).abs() <= second_order,
                "s = {s}: down {down}"
            );
            assert!(
                (starboard - 19.0 * roll.sin()).abs() <= second_order,
                "s = {s}: starboard {starboard}"
            );
        }
    }
}

#[test]
fn a_complete_pose_puts_sway_roll_and_yaw_on_the_steaming_ship() {
    let deck = DeckGeometry::default();
    let parameters = ShipMotionParameters {
        forward_speed_mps: 7.7,
        ..ShipMotionParameters::default()
    };
    let ship = ShipMotion::new(parameters).unwrap();
    let lateral = LateralShipMotion::new(&parameters).unwrap();
    let state = LateralShipMotionState {
        roll_filter: [0.01, 0.002],
        yaw_filter: [-0.003, 0.0, 0.0, 0.0],
        sway_filter: [0.4, 0.1, 0.0, 0.0],
    };
    let heading = deck.ship_mean_heading_rad();
    let base = deck.steaming_pose(&ship, &ShipMotionState::default(), (0.0, 0.0), 2.0);
    let pose = lateral.complete_pose(&state, base, heading);
    assert_eq!((pose.roll_rad, pose.yaw_rad), (0.01, -0.003));
    let sway_earth_y = pose.pitch_centre_y_m - base.pitch_centre_y_m;
    assert!((sway_earth_y - 0.4 * heading.cos()).abs() < 1e-12);
    let rate = lateral.complete_pose_rate(
        &state,
        deck.steaming_pose_rate(&ship, &ShipMotionState::default()),
        heading,
    );
    assert!(
        (rate.pitch_centre_y_rate_mps - (7.7 * heading.sin() + 0.1 * heading.cos())).abs() < 1e-12
    );
    assert_eq!(rate.roll_rate_radps, 0.002);
}

#[test]
fn deck_keys_out_of_range_are_refused_by_name() {
    for (text, key) in [
        (
            "[environment.deck]\ndeck_angle_deg = 20.0\n",
            "deck_angle_deg",
        ),
        (
            "[environment.deck]\naim_point_port_of_centreline_m = 31.0\n",
            "aim_point_port_of_centreline_m",
        ),
        (
            "[environment.deck]\ndeck_height_above_roll_axis_m = -1.0\n",
            "deck_height_above_roll_axis_m",
        ),
    ] {
        let error = deckland::scenario::load_scenario(text, "deck.toml").unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains(&format!("environment.deck.{key}")),
            "{message}"
        );
    }
}
