//! Flight-deck geometry on the moving ship (paper Eq. 17–18; docs/model.md §2.7, §3.1).
//!
//! Signs: the ship sails in +x (earth axes), the aircraft approaches from astern flying
//! +x, so "aft" is −x. Heights h are positive up. Ship pitch θ_s is positive bow-up, so a
//! bow-up pitch lowers every point aft of the pitch centre. Positions along the deck, s,
//! are measured from the aim point, positive forward: the ramp is at s = −60 m, the wires
//! at s = −18, −6, +6, +18 m.
//!
//! The deck is the straight line through the point `deck_height_m` above the pitch
//! centre, inclined at θ_s. A point a lever arm r = 81 − s aft of the pitch centre is at
//! x = x_G − r·cos θ_s, h = h_deck + z_G − r·sin θ_s, which for s = 0 is Eq. 17–18 with
//! the deck height added. Choice where the paper is silent: the pitch centre is taken at
//! flight-deck level, as Eq. 17–18 imply; a pitch axis 20 m lower (near the waterline)
//! would shift deck points forward by h_deck·sin θ_s (0.5 m at 1.5°), ignored here.

use serde::{Deserialize, Serialize};

use crate::parameters::{check_ranges, Bounds, ParameterError};

/// Where the ship is, in earth axes, at one instant: the inputs of Eq. 17–18 (x_G, z_G,
/// θ_s) and the lateral components of docs/model.md §10.5 (sway, roll, yaw). The 3-DOF
/// approach uses the x–h part; the lateral components are zero there.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipPose {
    /// Earth x of the ship's pitch centre, x_G (m); x_G(t) = x_G0 + V_ship·t.
    pub pitch_centre_x_m: f64,
    /// Earth y of the ship's pitch centre (m, positive right of the final bearing): the
    /// ship's sway and its drift across the bearing.
    pub pitch_centre_y_m: f64,
    /// Heave of the pitch centre z_G (m, positive up, zero mean).
    pub heave_m: f64,
    /// Ship pitch θ_s (rad, positive bow-up).
    pub pitch_rad: f64,
    /// Ship roll φ_s (rad, positive starboard side down).
    pub roll_rad: f64,
    /// Ship yaw ψ_s from its mean heading (rad, positive bow to starboard).
    pub yaw_rad: f64,
}

impl ShipPose {
    /// Distance X of earth position `x_m` aft of the pitch centre (m, positive aft):
    /// X = x_G − x, the argument of the wake model (paper Eq. 21–25).
    pub fn distance_aft_of_pitch_centre_m(&self, x_m: f64) -> f64 {
        self.pitch_centre_x_m - x_m
    }
}

/// Rates of a [`ShipPose`].
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipPoseRate {
    /// ẋ_G, the ship's forward speed (m/s).
    pub pitch_centre_x_rate_mps: f64,
    /// ẏ_G (m/s, positive right).
    pub pitch_centre_y_rate_mps: f64,
    /// ż_G (m/s, positive up).
    pub heave_rate_mps: f64,
    /// θ̇_s (rad/s, positive bow-up).
    pub pitch_rate_radps: f64,
    /// φ̇_s (rad/s, positive starboard side down).
    pub roll_rate_radps: f64,
    /// ψ̇_s (rad/s, positive bow to starboard).
    pub yaw_rate_radps: f64,
}

/// A point in earth axes (docs/model.md §1, §10.1): x positive forward along the final
/// bearing (m), y positive to the right of it (m), h height above mean sea level (m, up;
/// h = −z). The 3-DOF model flies in the x–h plane, y = 0.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EarthPoint {
    /// Earth x (m, positive in the direction of flight).
    pub x_m: f64,
    /// Earth y (m, positive to the right of the final bearing).
    pub y_m: f64,
    /// Height above mean sea level (m, positive up).
    pub h_m: f64,
}

/// A velocity in earth axes (m/s): x positive forward, y positive right, h positive up.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct EarthVelocity {
    /// ẋ (m/s, positive forward).
    pub x_mps: f64,
    /// ẏ (m/s, positive right).
    pub y_mps: f64,
    /// ḣ (m/s, positive up).
    pub h_mps: f64,
}

/// Reads an array of exactly four numbers. serde's `[f64; 4]` reads the first four
/// elements and lets the TOML reader drop any further ones unread (issue 14, class 7:
/// extra elements, even a string or a table, were silently ignored).
fn exactly_four_numbers<'de, D: serde::Deserializer<'de>>(
    deserializer: D,
) -> Result<[f64; 4], D::Error> {
    let values = Vec::<f64>::deserialize(deserializer)?;
    <[f64; 4]>::try_from(values.as_slice()).map_err(|_| {
        serde::de::Error::invalid_length(values.len(), &"an array of exactly 4 numbers")
    })
}

/// Deck geometry (docs/model.md §2.7; paper Eq. 17–18 for the 81 m).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct DeckGeometry {
    /// Distance of the landing (aim) point aft of the ship's pitch centre (m); paper
    /// Eq. 17–18: 81.
    pub landing_point_aft_of_pitch_centre_m: f64,
    /// Arresting wires along the deck from the aim point, positive forward (m); docs/model.md
    /// §2.7: −18, −6, +6, +18.
    #[serde(deserialize_with = "exactly_four_numbers")]
    pub wire_positions_m: [f64; 4],
    /// Distance of the ramp (aft edge of the deck) aft of the aim point (m); docs/model.md
    /// §2.7: 60.
    pub ramp_aft_of_aim_point_m: f64,
    /// Height of the flight deck above mean sea level at zero heave and pitch (m); the
    /// paper gives none: 20, a typical carrier's flight-deck height above the waterline.
    pub deck_height_m: f64,
    /// Angle of the landing area's centreline to port of the ship's centreline (deg);
    /// docs/model.md §3.8: 9 (Nimitz class about 9.0–9.1°). The 3-DOF approach ignores it.
    pub deck_angle_deg: f64,
    /// Distance of the aim point to port of the ship's centreline (m); docs/model.md
    /// §3.8: 10 (an assumption). The 3-DOF approach ignores it.
    pub aim_point_port_of_centreline_m: f64,
    /// Height of the flight deck above the ship's roll axis (m); docs/model.md §3.8: 19
    /// (an assumption). The 3-DOF approach ignores it.
    pub deck_height_above_roll_axis_m: f64,
}

impl Default for DeckGeometry {
    fn default() -> Self {
        Self {
            landing_point_aft_of_pitch_centre_m: 81.0,
            wire_positions_m: [-18.0, -6.0, 6.0, 18.0],
            ramp_aft_of_aim_point_m: 60.0,
            deck_height_m: 20.0,
            deck_angle_deg: 9.0,
            aim_point_port_of_centreline_m: 10.0,
            deck_height_above_roll_axis_m: 19.0,
        }
    }
}

impl DeckGeometry {
    /// Checks every field: lengths in [0, 400] m (ramp distance > 0), deck height in
    /// [0, 100] m, wires finite, strictly increasing and forward of the ramp; deck angle
    /// in [0, 15]°, aim point −30 to 30 m to port, deck height above the roll axis in
    /// [0, 40] m.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "environment.deck";
        check_ranges!(SECTION, self, {
            landing_point_aft_of_pitch_centre_m: Bounds::closed(0.0, 400.0),
        });
        let ramp_bounds = Bounds::positive_up_to(400.0);
        ramp_bounds.check(
            SECTION,
            "ramp_aft_of_aim_point_m",
            self.ramp_aft_of_aim_point_m,
        )?;
        check_ranges!(SECTION, self, {
            deck_height_m: Bounds::closed(0.0, 100.0),
            deck_angle_deg: Bounds::closed(0.0, 15.0),
            aim_point_port_of_centreline_m: Bounds::closed(-30.0, 30.0),
            deck_height_above_roll_axis_m: Bounds::closed(0.0, 40.0),
        });
        for &position in &self.wire_positions_m {
            Bounds::closed(-400.0, 400.0).check(SECTION, "wire_positions_m", position)?;
        }
        let ramp_m = -self.ramp_aft_of_aim_point_m;
        let ordered = self.wire_positions_m.windows(2).all(|w| w[0] < w[1]);
        if !ordered || self.wire_positions_m[0] <= ramp_m {
            return Err(ParameterError::new(
                SECTION,
                "wire_positions_m",
                self.wire_positions_m,
                format_args!(
                    "positions increasing strictly from aft to forward, every wire forward \
                     of the ramp at {ramp_m} m"
                ),
            ));
        }
        Ok(())
    }

    /// Lever arm r of deck position `s_m` aft of the pitch centre (m): r = 81 − s.
    fn lever_arm_m(&self, s_m: f64) -> f64 {
        self.landing_point_aft_of_pitch_centre_m - s_m
    }

    /// Earth position of the deck point `s_m` metres forward of the aim point
    /// (x = x_G − r cos θ_s, h = h_deck + z_G − r sin θ_s, r = 81 − s; Eq. 17–18).
    pub fn point_along_deck(&self, pose: &ShipPose, s_m: f64) -> EarthPoint {
        let r = self.lever_arm_m(s_m);
        let (sin, cos) = pose.pitch_rad.sin_cos();
        EarthPoint {
            x_m: pose.pitch_centre_x_m - r * cos,
            y_m: pose.pitch_centre_y_m,
            h_m: self.deck_height_m + pose.heave_m - r * sin,
        }
    }

    /// Earth velocity of the deck point `s_m` metres forward of the aim point
    /// (time derivative of [`DeckGeometry::point_along_deck`]).
    pub fn velocity_along_deck(
        &self,
        pose: &ShipPose,
        rate: &ShipPoseRate,
        s_m: f64,
    ) -> EarthVelocity {
        let r = self.lever_arm_m(s_m);
        let (sin, cos) = pose.pitch_rad.sin_cos();
        EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps + r * sin * rate.pitch_rate_radps,
            y_mps: rate.pitch_centre_y_rate_mps,
            h_mps: rate.heave_rate_mps - r * cos * rate.pitch_rate_radps,
        }
    }

    /// The landing (aim) point x_L, h_L (paper Eq. 17–18 plus the deck height).
    pub fn aim_point(&self, pose: &ShipPose) -> EarthPoint {
        self.point_along_deck(pose, 0.0)
    }

    /// The ramp, the aft edge of the deck.
    pub fn ramp(&self, pose: &ShipPose) -> EarthPoint {
        self.point_along_deck(pose, -self.ramp_aft_of_aim_point_m)
    }

    /// The four arresting wires, from aft (wire 1) to forward (wire 4).
    pub fn wires(&self, pose: &ShipPose) -> [EarthPoint; 4] {
        self.wire_positions_m
            .map(|s_m| self.point_along_deck(pose, s_m))
    }

    /// Height of the deck plane (m, above mean sea level) at earth position `x_m`,
    /// extended aft past the ramp: h_deck + z_G − (x_G − x)·tan θ_s.
    pub fn deck_plane_height(&self, pose: &ShipPose, x_m: f64) -> f64 {
        let distance_aft = pose.distance_aft_of_pitch_centre_m(x_m);
        self.deck_height_m + pose.heave_m - distance_aft * pose.pitch_rad.tan()
    }

    /// Height of the deck (m, above mean sea level) below earth position `x_m`:
    /// [`DeckGeometry::deck_plane_height`], or `None` aft of the ramp (over the water).
    /// The deck is taken to run on forward without end (the paper gives no bow).
    pub fn deck_height_below(&self, pose: &ShipPose, x_m: f64) -> Option<f64> {
        if x_m < self.ramp(pose).x_m {
            return None;
        }
        Some(self.deck_plane_height(pose, x_m))
    }

    /// Distance along the deck from the aim point (m, positive forward) of the deck point
    /// at earth position `x_m`: s = 81 − (x_G − x)/cos θ_s (inverse of
    /// [`DeckGeometry::point_along_deck`]'s x).
    pub fn distance_along_deck(&self, pose: &ShipPose, x_m: f64) -> f64 {
        self.landing_point_aft_of_pitch_centre_m
            - pose.distance_aft_of_pitch_centre_m(x_m) / pose.pitch_rad.cos()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pose(pitch_deg: f64) -> ShipPose {
        ShipPose {
            pitch_centre_x_m: 1000.0,
            heave_m: 1.5,
            pitch_rad: pitch_deg.to_radians(),
            ..Default::default()
        }
    }

    #[test]
    fn level_deck_puts_points_at_their_nominal_positions() {
        let deck = DeckGeometry::default();
        let level = ShipPose {
            pitch_centre_x_m: 1000.0,
            ..ShipPose::default()
        };
        for (point, x_m) in [(deck.aim_point(&level), 919.0), (deck.ramp(&level), 859.0)] {
            assert_eq!(
                point,
                EarthPoint {
                    x_m,
                    h_m: 20.0,
                    ..Default::default()
                }
            );
        }
        let wires = deck.wires(&level);
        assert_eq!(wires.map(|p| p.x_m), [901.0, 913.0, 925.0, 937.0]);
    }

    #[test]
    fn aim_point_follows_eq_17_18() {
        // Hand-computed: θ = 2°, x_L = 1000 − 81·cos 2° = 919.04934, h_L = 20 + 1.5 − 81·sin 2°
        // = 18.67314.
        let deck = DeckGeometry::default();
        let aim = deck.aim_point(&pose(2.0));
        assert!((aim.x_m - 919.049_34).abs() < 1e-5, "{aim:?}");
        assert!((aim.h_m - 18.673_14).abs() < 1e-5, "{aim:?}");
    }

    #[test]
    fn bow_up_pitch_lowers_the_ramp_more_than_the_aim_point() {
        let deck = DeckGeometry::default();
        let p = pose(2.0);
        assert!(deck.ramp(&p).h_m < deck.aim_point(&p).h_m);
        assert!(deck.aim_point(&p).h_m < deck.wires(&p)[3].h_m);
    }

    #[test]
    fn deck_height_below_agrees_with_deck_points_and_is_none_over_water() {
        let deck = DeckGeometry::default();
        let p = pose(-1.7);
        for s in [-60.0, -18.0, 0.0, 18.0, 70.0] {
            let point = deck.point_along_deck(&p, s);
            let height = deck.deck_height_below(&p, point.x_m).expect("on deck");
            assert!((height - point.h_m).abs() < 1e-9, "s = {s}");
        }
        let ramp = deck.ramp(&p);
        assert_eq!(deck.deck_height_below(&p, ramp.x_m - 0.01), None);
    }

    #[test]
    fn deck_point_velocity_matches_finite_difference() {
        let deck = DeckGeometry::default();
        let rate = ShipPoseRate {
            pitch_centre_x_rate_mps: 5.0,
            heave_rate_mps: 0.7,
            pitch_rate_radps: 0.02,
            ..Default::default()
        };
        let p0 = pose(1.0);
        let h = 1e-6;
        let p1 = ShipPose {
            pitch_centre_x_m: p0.pitch_centre_x_m + rate.pitch_centre_x_rate_mps * h,
            heave_m: p0.heave_m + rate.heave_rate_mps * h,
            pitch_rad: p0.pitch_rad + rate.pitch_rate_radps * h,
            ..Default::default()
        };
        let s = -30.0;
        let (a, b) = (deck.point_along_deck(&p0, s), deck.point_along_deck(&p1, s));
        let v = deck.velocity_along_deck(&p0, &rate, s);
        assert!(((b.x_m - a.x_m) / h - v.x_mps).abs() < 1e-5);
        assert!(((b.h_m - a.h_m) / h - v.h_mps).abs() < 1e-5);
    }

    #[test]
    fn validate_rejects_wires_out_of_order_or_aft_of_the_ramp() {
        let mut deck = DeckGeometry::default();
        assert!(deck.validate().is_ok());
        deck.wire_positions_m = [-18.0, 6.0, -6.0, 18.0];
        assert!(matches!(
            deck.validate(),
            Err(ParameterError { ref path, .. }) if path == "environment.deck.wire_positions_m"
        ));
        deck.wire_positions_m = [-61.0, -6.0, 6.0, 18.0];
        assert!(matches!(
            deck.validate(),
            Err(ParameterError { ref path, .. }) if path == "environment.deck.wire_positions_m"
        ));
    }
}
