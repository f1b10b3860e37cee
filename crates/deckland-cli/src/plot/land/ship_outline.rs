//! The carrier's flight deck drawn to scale in the plan view (issue 44): a simplified
//! outline of the Nimitz class's flight deck, 332.8 m long and 76.8 m wide (public
//! figures, as docs/model.md §12's hull), placed by the deck geometry of the scenario:
//! the ramp on its stern edge, the aim point `aim_point_port_of_centreline_m` to port of
//! the ship's centreline, the landing area angled `deck_angle_deg` to port of it.

use deckland::environment::DeckGeometry;

/// The flight deck's outline in ship axes: metres forward of the stern (the ramp's edge)
/// and to starboard of the ship's centreline, starting at the stern's port corner and
/// running round to starboard, closed. Simplified: the stern 40 m wide, the island side
/// 30 m to starboard at most, the angled deck 46.8 m to port at its forward corner, the
/// bow a point; the overall length and width are the class's.
pub(crate) const FLIGHT_DECK_OUTLINE: [(f64, f64); 14] = [
    (0.0, -20.0),
    (0.0, 20.0),
    (60.0, 24.0),
    (150.0, 30.0),
    (230.0, 30.0),
    (270.0, 22.0),
    (320.0, 8.0),
    (332.8, 0.0),
    (320.0, -8.0),
    (250.0, -22.0),
    (215.0, -44.0),
    (195.0, -46.8),
    (100.0, -32.0),
    (0.0, -20.0),
];

/// The ship's axes in the horizontal earth plane at one instant: the stern's point on the
/// ship's centreline (earth x, y; m) and the unit vectors forward and to starboard.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ShipAxes {
    pub stern: (f64, f64),
    pub forward: (f64, f64),
    pub starboard: (f64, f64),
}

impl ShipAxes {
    /// The axes of the ship whose landing area's centreline passes through `aim` (earth x,
    /// y; m) with heading `landing_heading_rad` (from the final bearing, positive right),
    /// on `deck`: the ship's centreline is `deck_angle_deg` to starboard of the landing
    /// area's, `aim_point_port_of_centreline_m` to starboard of the aim point, and its stern
    /// passes through the ramp, `ramp_aft_of_aim_point_m` aft of the aim point along the
    /// landing area's centreline.
    pub(crate) fn new(aim: (f64, f64), landing_heading_rad: f64, deck: &DeckGeometry) -> Self {
        let heading = landing_heading_rad + deck.deck_angle_deg.to_radians();
        let (sin, cos) = heading.sin_cos();
        let (forward, starboard) = ((cos, sin), (-sin, cos));
        let (sin_l, cos_l) = landing_heading_rad.sin_cos();
        let ramp = (
            aim.0 - deck.ramp_aft_of_aim_point_m * cos_l,
            aim.1 - deck.ramp_aft_of_aim_point_m * sin_l,
        );
        let dot = |a: (f64, f64), b: (f64, f64)| a.0 * b.0 + a.1 * b.1;
        // Along the ship: the ramp's station; across it: the centreline, to starboard of
        // the aim point.
        let along = dot((ramp.0 - aim.0, ramp.1 - aim.1), forward);
        let across = deck.aim_point_port_of_centreline_m;
        Self {
            stern: (
                aim.0 + along * forward.0 + across * starboard.0,
                aim.1 + along * forward.1 + across * starboard.1,
            ),
            forward,
            starboard,
        }
    }

    /// The earth point of ship-axes point (`x` forward of the stern, `y` to starboard).
    pub(crate) fn earth(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            self.stern.0 + x * self.forward.0 + y * self.starboard.0,
            self.stern.1 + x * self.forward.1 + y * self.starboard.1,
        )
    }

    /// The flight deck's outline in earth axes.
    pub(crate) fn outline(&self) -> Vec<(f64, f64)> {
        FLIGHT_DECK_OUTLINE.iter().map(|&p| self.earth(p)).collect()
    }

    /// The ship-axes point of an earth point (the inverse of [`ShipAxes::earth`]).
    #[cfg(test)]
    pub(crate) fn ship(&self, (x, y): (f64, f64)) -> (f64, f64) {
        let d = (x - self.stern.0, y - self.stern.1);
        (
            d.0 * self.forward.0 + d.1 * self.forward.1,
            d.0 * self.starboard.0 + d.1 * self.starboard.1,
        )
    }
}

/// Whether ship-axes point `p` is inside the outline (even-odd rule).
#[cfg(test)]
pub(crate) fn inside_outline(p: (f64, f64)) -> bool {
    inside_polygon(p, &FLIGHT_DECK_OUTLINE)
}

/// Whether `p` is inside the closed polygon `polygon` (even-odd rule; the first point
/// repeated last).
#[cfg(test)]
pub(crate) fn inside_polygon(p: (f64, f64), polygon: &[(f64, f64)]) -> bool {
    let mut inside = false;
    for pair in polygon.windows(2) {
        let ((x0, y0), (x1, y1)) = (pair[0], pair[1]);
        if (y0 > p.1) != (y1 > p.1) && p.0 < x0 + (p.1 - y0) * (x1 - x0) / (y1 - y0) {
            inside = !inside;
        }
    }
    inside
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The outline is the class's 332.8 m by 76.8 m (public figures).
    #[test]
    fn the_outline_is_the_nimitz_flight_decks_size() {
        let xs = FLIGHT_DECK_OUTLINE.iter().map(|p| p.0);
        let ys = FLIGHT_DECK_OUTLINE.iter().map(|p| p.1);
        let span = |v: &mut dyn Iterator<Item = f64>| {
            let (lo, hi) = v.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
            hi - lo
        };
        assert!((span(&mut xs.clone()) - 332.8).abs() < 1e-9);
        assert!((span(&mut ys.clone()) - 76.8).abs() < 1e-9);
    }

    /// Placed by the default deck, whatever the heading: the ramp is on the stern edge's
    /// centre-port part, the aim point 10 m to port of the centreline and 60·cos 9° m
    /// forward of the stern, every wire and the landing area's centreline inside the deck.
    #[test]
    fn the_ramp_is_on_the_stern_and_the_wires_on_the_deck() {
        let deck = DeckGeometry::default();
        for heading_deg in [-3.0_f64, 0.0, 2.5] {
            let heading = heading_deg.to_radians();
            let aim = (1234.0, -5.0);
            let axes = ShipAxes::new(aim, heading, &deck);
            let (sin, cos) = heading.sin_cos();
            let along = |s: f64| (aim.0 + s * cos, aim.1 + s * sin);
            let ramp = axes.ship(along(-deck.ramp_aft_of_aim_point_m));
            assert!(ramp.0.abs() < 1e-9, "{ramp:?}");
            assert!((-20.0..20.0).contains(&ramp.1), "{ramp:?}");
            let aim_ship = axes.ship(aim);
            assert!((aim_ship.1 + 10.0).abs() < 1e-9, "{aim_ship:?}");
            assert!((aim_ship.0 - 60.0 * 9_f64.to_radians().cos()).abs() < 1e-9);
            for s in deck.wire_positions_m {
                assert!(inside_outline(axes.ship(along(s))), "wire at {s} m");
            }
            for s in (0..=20).map(|k| -59.0 + 10.0 * f64::from(k)) {
                assert!(inside_outline(axes.ship(along(s))), "centreline at {s} m");
            }
            // Round trip.
            let p = (37.0, -12.5);
            let back = axes.ship(axes.earth(p));
            assert!((back.0 - p.0).abs() < 1e-9 && (back.1 - p.1).abs() < 1e-9);
        }
    }
}
