//! The wave-off's ramp-strike limits in a heavy sea (docs/landing-design.md,
//! "Catastrophes first in a heavy sea"): the sea state the estimator's ship model is built
//! for, and the limits that move with it. The defaults: both limits 0.5 %
//! (docs/landing-design.md), moving in between a stationary ramp σ
//! of 4.3 m, the sea in which the guidance's clearance, capped at 4 m, stops holding its
//! own ramp-strike bound of 10⁻⁴, and 4.5 m, where the capped path's strike probability
//! is twice the bound (`analysis::deck_floor`'s floor of the ramp over the 1.4 s from the
//! commit point; the paper's sea is at 4.20 m, the heavy sea at 6.84 m); the paper's set
//! has none.
//!
//! And the commit gate (docs/landing-design.md, "The commit gate"): at the commit point,
//! an approach whose ramp-strike probability is above 7·10⁻⁴ waves off, in a sea from a
//! stationary ramp σ of 3.2 m, where the capped path stops holding the bound with no
//! recovery credited (the ordinary late abort, at 20 %, does not fly it), in full from
//! 3.35 m, where that path's probability is twice the bound.

use super::WaveOffParameters;
use crate::environment::{DeckGeometry, ShipMotionParameters};
use crate::parameters::{Bounds, ParameterError};

/// The stationary σ of the ramp's height (m) in the sea of `ship` on `deck`:
/// √(σ_H² + (r_R·σ_θ)²), heave and pitch independent, the ramp r_R = landing point aft of
/// the pitch centre + ramp aft of the landing point (141 m) aft of the pitch centre,
/// pitch small (docs/model.md §3.1): 2.10 m in the moderate sea (1.0 m, 0.75°), 4.20 m
/// in the paper's (2.0 m, 1.5°), 6.84 m in the heavy sea (3.0 m, 2.5°); 0 with the ship
/// steady. The sea state the estimator's ship model is built for.
pub fn stationary_ramp_height_sigma_m(ship: &ShipMotionParameters, deck: &DeckGeometry) -> f64 {
    if !ship.enabled {
        return 0.0;
    }
    ship.deck_point_height_rms_m(
        deck.landing_point_aft_of_pitch_centre_m + deck.ramp_aft_of_aim_point_m,
    )
}

impl WaveOffParameters {
    /// Checks the heavy-sea keys and the commit gate's of `section`: the three limits
    /// with `probability`'s bounds, each band's start σ in [0, 50] m and its full σ from
    /// the start to 50 m.
    pub(super) fn validate_heavy_sea(
        &self,
        section: &str,
        probability: Bounds,
    ) -> Result<(), ParameterError> {
        for (key, value) in [
            (
                "heavy_sea_ramp_strike_probability",
                self.heavy_sea_ramp_strike_probability,
            ),
            (
                "heavy_sea_late_abort_ramp_strike_probability",
                self.heavy_sea_late_abort_ramp_strike_probability,
            ),
            (
                "max_commit_ramp_strike_probability",
                self.max_commit_ramp_strike_probability,
            ),
        ] {
            probability.check(section, key, value)?;
        }
        for [(start_key, start), (full_key, full)] in [
            [
                (
                    "heavy_sea_ramp_sigma_start_m",
                    self.heavy_sea_ramp_sigma_start_m,
                ),
                (
                    "heavy_sea_ramp_sigma_full_m",
                    self.heavy_sea_ramp_sigma_full_m,
                ),
            ],
            [
                (
                    "commit_gate_ramp_sigma_start_m",
                    self.commit_gate_ramp_sigma_start_m,
                ),
                (
                    "commit_gate_ramp_sigma_full_m",
                    self.commit_gate_ramp_sigma_full_m,
                ),
            ],
        ] {
            Bounds::closed(0.0, 50.0).check(section, start_key, start)?;
            Bounds::closed(start, 50.0).check(section, full_key, full)?;
        }
        Ok(())
    }

    /// The heavy-sea limits' share w (0 to 1) in a sea whose stationary σ of the ramp
    /// height is `ramp_sigma_m`: 0 at and below `heavy_sea_ramp_sigma_start_m`, 1 at and
    /// above `heavy_sea_ramp_sigma_full_m`, linear between.
    pub fn heavy_sea_share(&self, ramp_sigma_m: f64) -> f64 {
        band_share(
            ramp_sigma_m,
            self.heavy_sea_ramp_sigma_start_m,
            self.heavy_sea_ramp_sigma_full_m,
        )
    }

    /// The commit gate's limit in a sea whose stationary σ of the ramp height is
    /// `ramp_sigma_m`: 0 (no gate) where `max_commit_ramp_strike_probability` is 0 or the
    /// sea is at or below `commit_gate_ramp_sigma_start_m`; p_gate^w above, w the share
    /// of the way to `commit_gate_ramp_sigma_full_m` (from 1, which no probability
    /// exceeds, to p_gate in full).
    pub fn commit_gate_in_sea(&self, ramp_sigma_m: f64) -> f64 {
        let limit = self.max_commit_ramp_strike_probability;
        let share = band_share(
            ramp_sigma_m,
            self.commit_gate_ramp_sigma_start_m,
            self.commit_gate_ramp_sigma_full_m,
        );
        if limit <= 0.0 || share <= 0.0 {
            0.0
        } else {
            limit.powf(share)
        }
    }

    /// These parameters in a sea whose stationary σ of the ramp height is `ramp_sigma_m`:
    /// the ramp-strike limits of [`WaveOffParameters::for_sea`] and the commit gate of
    /// [`WaveOffParameters::commit_gate_in_sea`] in `max_commit_ramp_strike_probability`.
    pub fn in_sea(&self, ramp_sigma_m: f64) -> Self {
        Self {
            max_commit_ramp_strike_probability: self.commit_gate_in_sea(ramp_sigma_m),
            ..self.for_sea(ramp_sigma_m)
        }
    }

    /// These parameters in a sea whose stationary σ of the ramp height is `ramp_sigma_m`
    /// (`stationary_ramp_height_sigma_m`): each ramp-strike limit that is on and has a
    /// heavy-sea limit moves to it by the share [`WaveOffParameters::heavy_sea_share`],
    /// p = p₀ + w·(p_heavy − p₀); the same parameters where w = 0 or no heavy-sea limit
    /// is set.
    pub fn for_sea(&self, ramp_sigma_m: f64) -> Self {
        let heavy = self.heavy_sea_ramp_strike_probability > 0.0
            || self.heavy_sea_late_abort_ramp_strike_probability > 0.0;
        let share = if heavy {
            self.heavy_sea_share(ramp_sigma_m)
        } else {
            0.0
        };
        if share <= 0.0 {
            return *self;
        }
        let blend = |ordinary: f64, heavy: f64| {
            if ordinary <= 0.0 || heavy <= 0.0 {
                ordinary
            } else if share >= 1.0 {
                heavy
            } else {
                ordinary + share * (heavy - ordinary)
            }
        };
        Self {
            max_ramp_strike_probability: blend(
                self.max_ramp_strike_probability,
                self.heavy_sea_ramp_strike_probability,
            ),
            late_abort_ramp_strike_probability: blend(
                self.late_abort_ramp_strike_probability,
                self.heavy_sea_late_abort_ramp_strike_probability,
            ),
            ..*self
        }
    }

    /// [`WaveOffParameters::in_sea`] in the sea of `ship` on `deck`.
    pub fn for_ship(&self, ship: &ShipMotionParameters, deck: &DeckGeometry) -> Self {
        if self.heavy_sea_ramp_strike_probability <= 0.0
            && self.heavy_sea_late_abort_ramp_strike_probability <= 0.0
            && self.max_commit_ramp_strike_probability <= 0.0
        {
            return *self;
        }
        self.in_sea(stationary_ramp_height_sigma_m(ship, deck))
    }
}

/// The share w (0 to 1) of a band from `start` to `full` at `sigma`: 0 at and below the
/// start, 1 at and above the full σ, linear between.
fn band_share(sigma: f64, start: f64, full: f64) -> f64 {
    if sigma <= start {
        0.0
    } else if sigma >= full {
        1.0
    } else {
        (sigma - start) / (full - start)
    }
}
