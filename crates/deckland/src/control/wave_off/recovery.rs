//! The limits in which a carrier recovers aircraft, and the early "foul deck: motion"
//! wave-off (docs/model.md §9, §12): far from the ramp, before the wave-off window opens,
//! the aircraft waves off when the deck forecast for touchdown is outside them, as the
//! landing signal officer fouls the deck when it moves too much.

use serde::{Deserialize, Serialize};

use super::{WaveOffCriterion, WaveOffDecision, WaveOffInputs, WaveOffParameters};
use crate::environment::{DeckGeometry, ShipMotion};
use crate::parameters::{check_ranges, Bounds, ParameterError};

/// How the early check reads the deck forecast against the limits
/// (`foul_deck_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum FoulDeckModel {
    /// Pitch against the lens, twice the excursion against the total motion, and the
    /// landing point's vertical velocity times the window against the motion in it; no
    /// roll. The check as it first came, and of a file that names no model.
    Linear,
    /// As `linear`, with the forecast roll against the lens's roll limit, and the motion
    /// in the window as the stationary sea's best estimate from the vertical velocity,
    /// β·ḣ (docs/model.md §12): the velocity times the window overstates a sea's motion
    /// over 4 s, by about a third at a 9-s encounter period. The default.
    Stationary,
}

impl FoulDeckModel {
    /// The model of a file that names none: the check as it first came.
    pub fn named_by_none() -> Self {
        Self::Linear
    }
}

/// The recovery limits (the LSO NATOPS manual as summarised in public sources; each an
/// assumption of that summary, docs/model.md §12) and the early check against them.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct RecoveryLimits {
    /// Time to go (s) from which the forecast deck at touchdown is checked against the
    /// limits, until the wave-off window opens (`window_start_time_to_go_s`); 0, off,
    /// by default: from 10 s (about 700 m from the ramp) it waves off 82 % of the paper's
    /// sea's approaches (that sea is beyond the limits) and 13.7 % in sea state 6 (none in
    /// sea state 5), but 4 % and 0.4 % of all approaches then diverge, α below −5° about
    /// 7.5 s after the wave-off (docs/seaway-results.md): the wave-off's flight is
    /// designed for decisions in the last 4 s.
    #[serde(default = "RecoveryLimits::off")]
    pub foul_deck_time_to_go_s: f64,
    /// How the early check reads the forecast against the limits: `stationary` (the
    /// default) or `linear` (the check as it first came, and of a file that names
    /// none); [`FoulDeckModel`].
    #[serde(default = "FoulDeckModel::named_by_none")]
    pub foul_deck_model: FoulDeckModel,
    /// Total deck motion at which recovery stops (m): 35 ft, 10.67 m, peak to peak; the
    /// check doubles the landing point's predicted excursion from its mean height.
    pub total_deck_motion_m: f64,
    /// The lens's stabilisation limit in ship pitch (deg): ±1.62°.
    pub lens_pitch_limit_deg: f64,
    /// The lens's stabilisation limit in ship roll (deg): ±8.19°; checked by the
    /// `stationary` model against the forecast roll (the 3-D approach's; the
    /// longitudinal approach forecasts none).
    pub lens_roll_limit_deg: f64,
    /// Deck motion in `deck_motion_window_s` beyond which recovery stops (m): 8 ft,
    /// 2.44 m; the check takes the landing point's predicted vertical velocity at
    /// touchdown over the window (a linear estimate).
    pub deck_motion_in_window_m: f64,
    /// The window of that motion (s): 4 s.
    pub deck_motion_window_s: f64,
    /// β, the motion in the window per m/s of the landing point's vertical velocity
    /// (s), of the ship flown: set when the loop is built
    /// ([`RecoveryLimits::for_ship`]); `None`, the window itself.
    #[serde(skip)]
    pub window_motion_per_rate_s: Option<f64>,
}

impl Default for RecoveryLimits {
    fn default() -> Self {
        Self {
            foul_deck_time_to_go_s: 10.0,
            foul_deck_model: FoulDeckModel::Stationary,
            total_deck_motion_m: 10.668, // 35 ft of 0.3048 m
            lens_pitch_limit_deg: 1.62,
            lens_roll_limit_deg: 8.19,
            deck_motion_in_window_m: 2.4384, // 8 ft
            deck_motion_window_s: 4.0,
            window_motion_per_rate_s: None,
        }
    }
}

impl RecoveryLimits {
    /// The early check off (the default, and the value of a file that names none).
    pub fn off() -> f64 {
        0.0
    }

    /// The limits of a file with no `[control.wave_off.recovery]` section: the check off.
    pub fn named_by_none() -> Self {
        Self {
            foul_deck_time_to_go_s: 0.0,
            foul_deck_model: FoulDeckModel::named_by_none(),
            ..Self::default()
        }
    }

    /// These limits for the ship `ship` and deck `deck` flown: with the `stationary`
    /// model and the check on, β of the landing point over the window
    /// ([`ShipMotion::deck_point_window_motion_per_rate_s`]).
    pub fn for_ship(self, ship: &ShipMotion, deck: &DeckGeometry) -> Self {
        let on = self.foul_deck_time_to_go_s > 0.0;
        let window_motion_per_rate_s = (on && self.foul_deck_model == FoulDeckModel::Stationary)
            .then(|| {
                ship.deck_point_window_motion_per_rate_s(
                    deck.landing_point_aft_of_pitch_centre_m,
                    self.deck_motion_window_s,
                )
            });
        Self {
            window_motion_per_rate_s,
            ..self
        }
    }

    /// Checks every value: the check's time to go 0–60 s, every limit positive and
    /// finite (total motion (0, 100] m, pitch (0, 30]°, roll (0, 45]°, motion in the
    /// window (0, 50] m over (0, 30] s).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.wave_off.recovery";
        check_ranges!(SECTION, self, {
            foul_deck_time_to_go_s: Bounds::closed(0.0, 60.0),
            total_deck_motion_m: Bounds::positive_up_to(100.0),
            lens_pitch_limit_deg: Bounds::positive_up_to(30.0),
            lens_roll_limit_deg: Bounds::positive_up_to(45.0),
            deck_motion_in_window_m: Bounds::positive_up_to(50.0),
            deck_motion_window_s: Bounds::positive_up_to(30.0),
        });
        Ok(())
    }

    /// The largest share (%) of a limit that the deck forecast for touchdown reaches:
    /// pitch against the lens's, twice the landing point's excursion from its mean
    /// against the total motion, and its vertical velocity times the window (`linear`)
    /// or β (`stationary`) against the motion in the window; with `stationary`, roll
    /// against the lens's too.
    pub fn largest_share_pct(&self, inputs: &WaveOffInputs) -> f64 {
        let forecast = &inputs.forecast;
        let pitch = forecast.pitch_rad.to_degrees().abs() / self.lens_pitch_limit_deg;
        let excursion = 2.0
            * (forecast.landing_point_height_m - inputs.mean_landing_point_height_m).abs()
            / self.total_deck_motion_m;
        let window_motion_s = self
            .window_motion_per_rate_s
            .unwrap_or(self.deck_motion_window_s);
        let window = forecast.landing_point_climb_rate_mps.abs() * window_motion_s
            / self.deck_motion_in_window_m;
        let roll = match self.foul_deck_model {
            FoulDeckModel::Linear => 0.0,
            FoulDeckModel::Stationary => {
                forecast.roll_rad.to_degrees().abs() / self.lens_roll_limit_deg
            }
        };
        100.0 * pitch.max(excursion).max(window).max(roll)
    }
}

impl WaveOffParameters {
    /// The early "foul deck: motion" decision: with the wave-off on, between
    /// `recovery.foul_deck_time_to_go_s` and the window's start, a wave-off when the deck
    /// forecast for touchdown is beyond a recovery limit; `None` otherwise.
    pub fn decide_foul_deck(&self, inputs: &WaveOffInputs) -> Option<WaveOffDecision> {
        let limits = &self.recovery;
        let early = inputs.time_to_go_s > self.window_start_time_to_go_s
            && inputs.time_to_go_s <= limits.foul_deck_time_to_go_s;
        if !self.enabled || !early {
            return None;
        }
        let share = limits.largest_share_pct(inputs);
        (share > 100.0).then_some(WaveOffDecision {
            criterion: WaveOffCriterion::FoulDeckMotion,
            value: share,
            limit: 100.0,
            predicted_ramp_clearance_m: inputs.predicted_ramp_clearance_m(),
        })
    }
}
