//! The limits in which a carrier recovers aircraft, and the early "foul deck: motion"
//! wave-off (docs/model.md §9, §12): far from the ramp, before the wave-off window opens,
//! the aircraft waves off when the deck forecast for touchdown is outside them, as the
//! landing signal officer fouls the deck when it moves too much.

use serde::{Deserialize, Serialize};

use super::{WaveOffCriterion, WaveOffDecision, WaveOffInputs, WaveOffParameters};
use crate::parameters::{Bounds, ParameterError};

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
    /// Total deck motion at which recovery stops (m): 35 ft, 10.67 m, peak to peak; the
    /// check doubles the landing point's predicted excursion from its mean height.
    pub total_deck_motion_m: f64,
    /// The lens's stabilisation limit in ship pitch (deg): ±1.62°.
    pub lens_pitch_limit_deg: f64,
    /// The lens's stabilisation limit in ship roll (deg): ±8.19°. Named for the record;
    /// the early check does not read it yet (the longitudinal forecast has no roll).
    pub lens_roll_limit_deg: f64,
    /// Deck motion in `deck_motion_window_s` beyond which recovery stops (m): 8 ft,
    /// 2.44 m; the check takes the landing point's predicted vertical velocity at
    /// touchdown over the window (a linear estimate).
    pub deck_motion_in_window_m: f64,
    /// The window of that motion (s): 4 s.
    pub deck_motion_window_s: f64,
}

impl Default for RecoveryLimits {
    fn default() -> Self {
        Self {
            foul_deck_time_to_go_s: 0.0,
            total_deck_motion_m: 10.668, // 35 ft of 0.3048 m
            lens_pitch_limit_deg: 1.62,
            lens_roll_limit_deg: 8.19,
            deck_motion_in_window_m: 2.4384, // 8 ft
            deck_motion_window_s: 4.0,
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
            ..Self::default()
        }
    }

    /// Checks every value: the check's time to go 0–60 s, every limit positive and
    /// finite (total motion (0, 100] m, pitch (0, 30]°, roll (0, 45]°, motion in the
    /// window (0, 50] m over (0, 30] s).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.wave_off.recovery";
        Bounds::closed(0.0, 60.0).check(
            SECTION,
            "foul_deck_time_to_go_s",
            self.foul_deck_time_to_go_s,
        )?;
        Bounds::positive_up_to(100.0).check(
            SECTION,
            "total_deck_motion_m",
            self.total_deck_motion_m,
        )?;
        Bounds::positive_up_to(30.0).check(
            SECTION,
            "lens_pitch_limit_deg",
            self.lens_pitch_limit_deg,
        )?;
        Bounds::positive_up_to(45.0).check(
            SECTION,
            "lens_roll_limit_deg",
            self.lens_roll_limit_deg,
        )?;
        Bounds::positive_up_to(50.0).check(
            SECTION,
            "deck_motion_in_window_m",
            self.deck_motion_in_window_m,
        )?;
        Bounds::positive_up_to(30.0).check(
            SECTION,
            "deck_motion_window_s",
            self.deck_motion_window_s,
        )
    }

    /// The largest share (%) of a limit that the deck forecast for touchdown reaches:
    /// pitch against the lens's, twice the landing point's excursion from its mean
    /// against the total motion, and its vertical velocity times the window against the
    /// motion in the window.
    pub fn largest_share_pct(&self, inputs: &WaveOffInputs) -> f64 {
        let forecast = &inputs.forecast;
        let pitch = forecast.pitch_rad.to_degrees().abs() / self.lens_pitch_limit_deg;
        let excursion = 2.0
            * (forecast.landing_point_height_m - inputs.mean_landing_point_height_m).abs()
            / self.total_deck_motion_m;
        let window = forecast.landing_point_climb_rate_mps.abs() * self.deck_motion_window_s
            / self.deck_motion_in_window_m;
        100.0 * pitch.max(excursion).max(window)
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
