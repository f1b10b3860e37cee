//! Automatic wave-off: the decision not to land (docs/model.md §9).
//!
//! A landing signal officer, and an automatic carrier landing system, abort an approach
//! that is not going to end well. The decision is taken on named criteria, evaluated once
//! per step while the hook is between `window_start_time_to_go_s` and
//! `decision_time_to_go_s` from touchdown (after that the aircraft is committed: a
//! wave-off could no longer stop the hook reaching the deck):
//!
//! 1. **ramp clearance**: the hook's predicted height over the predicted ramp when it
//!    crosses it, assuming it keeps its present offset from the glide path, below
//!    `min_ramp_clearance_m` (1.5 m; the guidance itself keeps the landing signal
//!    officer's margin, [`crate::control::FlightPathParameters::ramp_clearance_margin_m`]);
//! 2. **touchdown sink rate**: the hook's sink rate plus the predicted climb rate of the
//!    landing point at touchdown above `max_touchdown_sink_rate_mps`;
//! 3. **glide-path error**: the hook more than `max_glide_path_error_m` off the path,
//!    or moving away from it faster than `max_glide_path_error_rate_mps`;
//! 4. **deck motion**: the predicted ship pitch at touchdown beyond `max_deck_pitch_deg`,
//!    or the predicted landing point more than `max_landing_point_displacement_m` from
//!    its mean height.
//!
//! The wave-off is flown by the outer loops: full thrust of both engines, and a climb
//! rate of `climb_rate_mps` commanded to the sink-rate loop, whose pitch authority
//! limits the rotation (pitching up swings the hook, 7 m aft of the CG, down); the pitch
//! command is kept at or above the air-relative flight path plus `min_alpha_deg`, and
//! past the ramp at or above the approach attitude (the simulation's `WaveOffFlight`).
//! The climb command and the floors take over over `climb_blend_s`, without a step.

use serde::{Deserialize, Serialize};

use crate::control::DeckForecast;
use crate::parameters::{check_ranges, Bounds, ParameterError};

/// The wave-off decision's limits and how it is flown (docs/model.md §9).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct WaveOffParameters {
    /// Whether the aircraft decides to wave off at all; on in the realistic set, off in
    /// the paper's (the paper has no wave-off).
    pub enabled: bool,
    /// Time to go (s) at which the decision window opens; 4 s (a project choice: earlier
    /// decisions rest on forecasts too uncertain to act on, docs/deck-prediction.md).
    pub window_start_time_to_go_s: f64,
    /// Time to go (s) after which the aircraft is committed; 2.5 s, about 1.4 s before
    /// the hook crosses the ramp (a project choice: engines spool with a 0.625-s lag, and
    /// pitching up first swings the hook, 7 m aft of the CG, down, so a wave-off begun
    /// within a second of the ramp brings the hook closer to it, so later decisions end
    /// on the ramp more often than they save; docs/no-oracle-results.md).
    pub decision_time_to_go_s: f64,
    /// Smallest predicted hook-to-ramp clearance (m); 0 (off) by default, where the
    /// ramp-strike probability decides (docs/no-oracle-results.md). The landing signal
    /// officer's 10-ft (3.05-m) minimum is the guidance's margin
    /// (`control.flight_path.ramp_clearance_margin_m`); on this deck's geometry (3.7 m
    /// nominal clearance) waving off every pass predicted below 3.05 m waves off half the
    /// approaches in a moderate sea (docs/model.md §9).
    pub min_ramp_clearance_m: f64,
    /// Largest probability of a ramp strike under the forecast (–); the module docs' first
    /// criterion; 0 turns it off; 0.2 (decided 1.5–2.5 s before the ramp, where the
    /// path still corrects, docs/no-oracle-results.md); [0, 1).
    pub max_ramp_strike_probability: f64,
    /// Which clearance the ramp-strike probability is taken on: `closed_loop` (the
    /// default: the path the guidance flies until the crossing, docs/model.md §9) or
    /// `forecast` (the path held as it is now: the probability as it first came, and of
    /// a file that names none); [`RampStrikeModel`].
    #[serde(default = "RampStrikeModel::named_by_none")]
    pub ramp_strike_model: RampStrikeModel,
    /// Largest probability of a hard landing under the forecast (–); 0 turns it off, the
    /// default: the deck makes hard landings after the decision point, where the
    /// forecast cannot see them, so a limit waves off many approaches for few hard
    /// landings avoided (docs/no-oracle-results.md); [0, 1).
    pub max_hard_landing_probability: f64,
    /// The touchdown sink rate relative to the deck that the hard-landing probability
    /// counts as hard (m/s); 7.6 m/s, the outcome's limit (docs/model.md §7); (0, 20].
    pub hard_landing_sink_rate_mps: f64,
    /// σ_sink, the scatter of the hook's own sink rate at touchdown about the one the
    /// hard-landing probability predicts (m/s); 0.6 m/s, measured about the closed-loop
    /// sink in the paper's sea (docs/no-oracle-results.md); 1.0 m/s, the assumption it
    /// replaced, in a file that names none; [0, 5].
    #[serde(default = "WaveOffParameters::touchdown_sink_rate_sigma_named_by_none")]
    pub touchdown_sink_rate_sigma_mps: f64,
    /// Which touchdown sink rate the hard-landing probability is taken on: `closed_loop`
    /// (the default: the hook's sink as the guidance flies it to touchdown,
    /// docs/model.md §9) or `forecast` (the hook's sink now: the probability as it first
    /// came, and of a file that names none); [`HardLandingModel`].
    #[serde(default = "HardLandingModel::named_by_none")]
    pub hard_landing_model: HardLandingModel,
    /// Largest predicted touchdown sink rate relative to the deck (m/s); 7.0 m/s, below
    /// the 7.6-m/s hard-landing limit (docs/model.md §7).
    pub max_touchdown_sink_rate_mps: f64,
    /// Largest height error of the hook to the glide path (m); 3 m.
    pub max_glide_path_error_m: f64,
    /// Largest rate at which the hook drifts from the glide path (m/s); 4 m/s.
    pub max_glide_path_error_rate_mps: f64,
    /// Largest predicted ship pitch at touchdown (deg); 3.5°.
    pub max_deck_pitch_deg: f64,
    /// Largest predicted displacement of the landing point from its mean height (m);
    /// 5.35 m, half of the 35-ft (10.7-m) total deck motion at which recovery stops
    /// (docs/model.md §3.6; what it costs and saves: docs/no-oracle-results.md).
    pub max_landing_point_displacement_m: f64,
    /// Climb rate commanded in the wave-off (m/s, up); 5 m/s.
    pub climb_rate_mps: f64,
    /// The time over which the wave-off takes over the pitch command (s): the climb-rate
    /// command cross-fades from the guidance's to `climb_rate_mps`, and the α floor
    /// fades in, along 3x² − 2x³ from the decision; the attitude floor fades in alike as
    /// the hook passes the ramp, so the pitch command never steps (docs/model.md §9).
    /// 0.4 s, about the pitch attitude's own response (short period and actuator,
    /// 0.3–0.5 s; docs/landing-design.md). 0 is the step; [0, 2].
    pub climb_blend_s: f64,
    /// The late abort's ramp criterion (docs/landing-design.md): from the commit point
    /// (`decision_time_to_go_s`) until the hook crosses the ramp, while the probability
    /// of a ramp strike under the forecast (the first criterion's) is above this, the
    /// late abort is engaged: direct lift blended to full up and, with
    /// `late_abort_full_thrust`, full thrust; released when it falls below or the hook
    /// passes the ramp, the landing going on (–). 0.2, the wave-off's own limit before
    /// the commit point (docs/landing-design.md); 0 turns it off (the paper's set, where
    /// the wave-off is off too); [0, 1).
    pub late_abort_ramp_strike_probability: f64,
    /// The late abort's sink criterion: from the commit point to touchdown, while the
    /// predicted touchdown sink rate relative to the deck (the second criterion's) is
    /// above this, the late abort is engaged (m/s); 0 turns it off, the default: a limit
    /// high enough to engage seldom catches no hard landing, one low enough to catch
    /// them engages on most approaches (docs/landing-design.md); [0, 20].
    pub late_abort_touchdown_sink_rate_mps: f64,
    /// Whether the late abort also blends the thrust command to full thrust of both
    /// engines; on: direct lift is usually at full authority already when the forecast
    /// ramp rises (the law flies the raised anchor), so the thrust's extra airspeed is
    /// what the late abort adds (docs/landing-design.md).
    pub late_abort_full_thrust: bool,
    /// The rate at which the late abort's share of the command rises from 0 to 1 when it
    /// engages, and falls back when it is released (1/s): the direct-lift command moves
    /// from the law's to full up along a ramp, never by a step; 5 per second (full in
    /// 0.2 s, about the surfaces' own time to full authority, 0.15 s at 1/s); (0, 100].
    pub late_abort_rate_per_s: f64,
    /// Smallest angle of attack the wave-off flies (deg); 4°. At full thrust the climb
    /// overshoots its command and the sink-rate loop pushes the nose over, which the heavy
    /// sea's wake took below the aerodynamic model's −5°. The pitch command is kept at or
    /// above the air-relative flight-path angle plus this, an α limiter as fly-by-wire
    /// laws have (the approach flies α ≈ 7°); a 40 °/s stabilator needs 0.9 s to reverse
    /// a push-over, in which α falls by 7° (docs/landing-design.md).
    pub min_alpha_deg: f64,
    /// The wave-off's ramp-strike limit in a heavy sea (–, `wave_off/heavy_sea.rs`); 0.005; 0 off.
    pub heavy_sea_ramp_strike_probability: f64,
    /// The late abort's limit in a heavy sea (–) alike; 0.005; 0 off; [0, 1).
    pub heavy_sea_late_abort_ramp_strike_probability: f64,
    /// The ramp σ (m) up to which the ordinary limits hold; 4.3 m; [0, 50].
    pub heavy_sea_ramp_sigma_start_m: f64,
    /// The σ (m) from which the heavy-sea limits hold in full; 4.5 m; start to 50.
    pub heavy_sea_ramp_sigma_full_m: f64,
    /// The commit gate (`wave_off/heavy_sea.rs`): at the commit point an approach whose
    /// ramp-strike probability (the first criterion's) is above this waves off, where
    /// the sea is at least `commit_gate_ramp_sigma_full_m` (–). 7·10⁻⁴: in the paper's
    /// sea the committed approaches then carry less than the guidance's bound of 10⁻⁴
    /// per approach flown (docs/landing-design.md); [0, 1); 0 off (the paper's set and
    /// a file that names none).
    #[serde(default)]
    pub max_commit_ramp_strike_probability: f64,
    /// The sea's stationary ramp σ (m) up to which there is no commit gate: 3.2 m, where
    /// the capped path stops holding its bound with no recovery credited; [0, 50].
    #[serde(default = "WaveOffParameters::commit_gate_start_m")]
    pub commit_gate_ramp_sigma_start_m: f64,
    /// The σ (m) from which the gate's limit holds in full; 3.35 m, where that path's
    /// probability is twice the bound; start to 50. Between, the limit is
    /// p_gate^w (w from 0 to 1 linearly in σ: 1, no gate, to p_gate).
    #[serde(default = "WaveOffParameters::commit_gate_full_m")]
    pub commit_gate_ramp_sigma_full_m: f64,
    /// The lead τ of the wave-off's α floor (s): it holds α + τ·q, the angle of attack
    /// predicted τ ahead, as the approach's α protection does; 0.3 s, the pitch loop's
    /// lag (docs/landing-design.md); 0 holds α itself (the paper's set); [0, 2].
    pub alpha_lead_s: f64,
    /// The wave-off's airspeed limit, as a margin over the approach airspeed (m/s): the
    /// wave-off flies full thrust of both engines until the airspeed passes the approach
    /// airspeed plus this; above it the thrust comes off by m/τ_e per m/s over (τ_e
    /// the engines' time constant: the fastest they follow, which damps the speed at
    /// about 0.5; the aircraft overshoots the limit by about its acceleration times τ_e,
    /// some 7 m/s). 10 m/s (about 20 kn, a project choice
    /// far below the flaps' 250-kn limit): a wave-off at full thrust from 10 s out
    /// reached 109 m/s, where the α floor could no longer hold the pitch loop and α fell
    /// below the aerodynamic model's −5° (docs/seaway-results.md). 0 is no limit (full
    /// thrust throughout, the paper's set and a file whose `[control.wave_off]` names
    /// none); [0, 50].
    #[serde(default = "WaveOffParameters::no_airspeed_limit")]
    pub climb_out_airspeed_margin_mps: f64,
    /// The limits in which a carrier recovers aircraft and the early "foul deck:
    /// motion" wave-off against them (`wave_off/recovery.rs`); a file with no
    /// `[control.wave_off.recovery]` section flies without the early check.
    #[serde(default = "RecoveryLimits::named_by_none")]
    pub recovery: RecoveryLimits,
}

impl Default for WaveOffParameters {
    fn default() -> Self {
        Self {
            enabled: true,
            window_start_time_to_go_s: 4.0,
            decision_time_to_go_s: 2.5,
            min_ramp_clearance_m: 0.0,
            max_ramp_strike_probability: 0.2,
            ramp_strike_model: RampStrikeModel::ClosedLoopLift,
            max_hard_landing_probability: 0.0,
            hard_landing_sink_rate_mps: 7.6,
            touchdown_sink_rate_sigma_mps: 0.6,
            hard_landing_model: HardLandingModel::ClosedLoop,
            max_touchdown_sink_rate_mps: 7.0,
            max_glide_path_error_m: 3.0,
            max_glide_path_error_rate_mps: 4.0,
            max_deck_pitch_deg: 3.5,
            max_landing_point_displacement_m: 5.35,
            climb_rate_mps: 5.0,
            climb_blend_s: 0.4,
            late_abort_ramp_strike_probability: 0.2,
            late_abort_touchdown_sink_rate_mps: 0.0,
            late_abort_full_thrust: true,
            late_abort_rate_per_s: 5.0,
            min_alpha_deg: 4.0,
            heavy_sea_ramp_strike_probability: 0.005,
            heavy_sea_late_abort_ramp_strike_probability: 0.005,
            heavy_sea_ramp_sigma_start_m: 4.3,
            heavy_sea_ramp_sigma_full_m: 4.5,
            max_commit_ramp_strike_probability: 7e-4,
            commit_gate_ramp_sigma_start_m: Self::commit_gate_start_m(),
            commit_gate_ramp_sigma_full_m: Self::commit_gate_full_m(),
            alpha_lead_s: 0.3,
            climb_out_airspeed_margin_mps: 10.0,
            recovery: RecoveryLimits::default(),
        }
    }
}

impl WaveOffParameters {
    /// The paper's set: no wave-off.
    pub fn paper() -> Self {
        Self {
            enabled: false,
            min_ramp_clearance_m: 1.5,
            late_abort_ramp_strike_probability: 0.0,
            late_abort_full_thrust: false,
            heavy_sea_ramp_strike_probability: 0.0,
            heavy_sea_late_abort_ramp_strike_probability: 0.0,
            max_commit_ramp_strike_probability: 0.0,
            alpha_lead_s: 0.0,
            min_alpha_deg: 2.0,
            // No airspeed limit, no early check, the probabilities as they first came.
            ..Self::named_by_none()
        }
    }

    /// The wave-off of a file whose `[control]` or `[control.wave_off]` section names
    /// none of the keys the seaway's recovery brought: no airspeed limit and no early
    /// check, as every file written before them flies.
    pub fn named_by_none() -> Self {
        Self {
            climb_out_airspeed_margin_mps: Self::no_airspeed_limit(),
            recovery: RecoveryLimits::named_by_none(),
            ramp_strike_model: RampStrikeModel::named_by_none(),
            hard_landing_model: HardLandingModel::named_by_none(),
            touchdown_sink_rate_sigma_mps: Self::touchdown_sink_rate_sigma_named_by_none(),
            max_commit_ramp_strike_probability: 0.0,
            ..Self::default()
        }
    }

    /// The commit gate's start (m): 3.2 m (`commit_gate_ramp_sigma_start_m`).
    pub fn commit_gate_start_m() -> f64 {
        3.2
    }

    /// The commit gate's full σ (m): 3.35 m (`commit_gate_ramp_sigma_full_m`).
    pub fn commit_gate_full_m() -> f64 {
        3.35
    }

    /// σ_sink of a file that names none (m/s): the assumption the hard-landing
    /// probability first came with.
    pub fn touchdown_sink_rate_sigma_named_by_none() -> f64 {
        1.0
    }

    /// No airspeed limit in the wave-off (full thrust throughout).
    pub fn no_airspeed_limit() -> f64 {
        0.0
    }

    /// Checks every limit: window 0–30 s, decision point 0–30 s and not after the window
    /// opens, clearance 0–20 m, the probabilities [0, 1), the hard-landing sink rate
    /// (0, 20] m/s and its σ [0, 5] m/s, sink rate (0, 20] m/s, glide-path error (0, 50] m and
    /// (0, 50] m/s, deck pitch (0, 30]°, displacement (0, 50] m, climb rate (0, 30] m/s
    /// and its blend 0–2 s, the late abort's probability [0, 1), sink rate 0–20 m/s and
    /// rate (0, 100] per second, smallest α −5°–15° (the aerodynamic model's lower end to
    /// the stall's side of the approach).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.wave_off";
        check_ranges!(SECTION, self, {
            window_start_time_to_go_s: Bounds::closed(0.0, 30.0),
            decision_time_to_go_s: Bounds::closed(0.0, self.window_start_time_to_go_s),
        });
        let probability = Bounds::closed(0.0, 1.0).exclusive_max();
        self.validate_criteria(SECTION, probability)?;
        check_ranges!(SECTION, self, {
            climb_rate_mps: Bounds::positive_up_to(30.0),
            climb_blend_s: Bounds::closed(0.0, 2.0),
        });
        probability.check(
            SECTION,
            "late_abort_ramp_strike_probability",
            self.late_abort_ramp_strike_probability,
        )?;
        check_ranges!(SECTION, self, {
            late_abort_touchdown_sink_rate_mps: Bounds::closed(0.0, 20.0),
            late_abort_rate_per_s: Bounds::positive_up_to(100.0),
            min_alpha_deg: Bounds::closed(-5.0, 15.0),
        });
        self.validate_heavy_sea(SECTION, probability)?;
        check_ranges!(SECTION, self, {
            alpha_lead_s: Bounds::closed(0.0, 2.0),
            climb_out_airspeed_margin_mps: Bounds::closed(0.0, 50.0),
        });
        self.recovery.validate()
    }

    /// Checks the limits of the decision's criteria: clearance, the probabilities, the
    /// sink rates, the glide-path error and its rate, deck pitch and displacement.
    fn validate_criteria(&self, section: &str, probability: Bounds) -> Result<(), ParameterError> {
        let (up_to_20, up_to_50) = (Bounds::positive_up_to(20.0), Bounds::positive_up_to(50.0));
        // One limit a line, as a table.
        #[rustfmt::skip]
        let limits = [
            (Bounds::closed(0.0, 20.0), "min_ramp_clearance_m", self.min_ramp_clearance_m),
            (probability, "max_ramp_strike_probability", self.max_ramp_strike_probability),
            (probability, "max_hard_landing_probability", self.max_hard_landing_probability),
            (up_to_20, "hard_landing_sink_rate_mps", self.hard_landing_sink_rate_mps),
            (Bounds::closed(0.0, 5.0), "touchdown_sink_rate_sigma_mps", self.touchdown_sink_rate_sigma_mps),
            (up_to_20, "max_touchdown_sink_rate_mps", self.max_touchdown_sink_rate_mps),
            (up_to_50, "max_glide_path_error_m", self.max_glide_path_error_m),
            (up_to_50, "max_glide_path_error_rate_mps", self.max_glide_path_error_rate_mps),
            (Bounds::positive_up_to(30.0), "max_deck_pitch_deg", self.max_deck_pitch_deg),
            (up_to_50, "max_landing_point_displacement_m", self.max_landing_point_displacement_m),
        ];
        limits
            .into_iter()
            .try_for_each(|(bounds, key, value)| bounds.check(section, key, value))
    }
}

/// The values the wave-off's criteria look at, worked out from its inputs.
struct WaveOffMeasures {
    /// Predicted ramp clearance (m).
    clearance: f64,
    /// Predicted touchdown sink rate relative to the deck (m/s).
    sink: f64,
    /// Forecast deck pitch (deg).
    pitch_deg: f64,
    /// Forecast landing point's displacement from its mean height (m).
    displacement: f64,
    /// The glide-path error's rate when the error grows, else 0 (m/s).
    drift: f64,
    /// Ramp-strike probability (–), 0 with its criterion off.
    ramp_strike: f64,
    /// Hard-landing probability (–), 0 with its criterion off.
    hard_landing: f64,
}

/// Which criterion called the wave-off.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum WaveOffCriterion {
    /// Probability of a ramp strike above the limit.
    RampStrikeProbability,
    /// Probability of a hard landing above the limit.
    HardLandingProbability,
    /// Predicted hook-to-ramp clearance below the minimum.
    RampClearance,
    /// Predicted touchdown sink rate relative to the deck above the limit.
    TouchdownSinkRate,
    /// Hook too far off the glide path.
    GlidePathError,
    /// Hook drifting off the glide path too fast.
    GlidePathErrorRate,
    /// Predicted ship pitch at touchdown beyond the limit.
    DeckPitch,
    /// Predicted landing point too far from its mean height.
    LandingPointDisplacement,
    /// 3-D approach: probability of an off-centre touchdown above the limit
    /// (`control::wave_off_lateral`).
    OffCentreProbability,
    /// 3-D approach: drifting across the centreline too fast.
    LineupDriftRate,
    /// Far from the ramp: the deck forecast for touchdown beyond a recovery limit ("foul
    /// deck: motion", `wave_off/recovery.rs`).
    FoulDeckMotion,
}

impl WaveOffCriterion {
    /// Every criterion, in the order of the decision's checks.
    pub const ALL: [WaveOffCriterion; 11] = [
        Self::FoulDeckMotion,
        Self::RampStrikeProbability,
        Self::HardLandingProbability,
        Self::RampClearance,
        Self::TouchdownSinkRate,
        Self::GlidePathError,
        Self::GlidePathErrorRate,
        Self::DeckPitch,
        Self::LandingPointDisplacement,
        Self::OffCentreProbability,
        Self::LineupDriftRate,
    ];

    /// The criterion's name, as written to files.
    pub fn name(self) -> &'static str {
        match self {
            Self::RampStrikeProbability => "ramp_strike_probability",
            Self::HardLandingProbability => "hard_landing_probability",
            Self::RampClearance => "ramp_clearance",
            Self::TouchdownSinkRate => "touchdown_sink_rate",
            Self::GlidePathError => "glide_path_error",
            Self::GlidePathErrorRate => "glide_path_error_rate",
            Self::DeckPitch => "deck_pitch",
            Self::LandingPointDisplacement => "landing_point_displacement",
            Self::OffCentreProbability => "off_centre_probability",
            Self::LineupDriftRate => "lineup_drift_rate",
            Self::FoulDeckMotion => "foul_deck_motion",
        }
    }

    /// The criterion's quantity and unit, in words.
    pub fn quantity(self) -> &'static str {
        match self {
            Self::RampStrikeProbability => "probability of a ramp strike (%)",
            Self::HardLandingProbability => "probability of a hard landing (%)",
            Self::RampClearance => "predicted ramp clearance (m)",
            Self::TouchdownSinkRate => "predicted touchdown sink rate (m/s)",
            Self::GlidePathError => "glide-path error (m)",
            Self::GlidePathErrorRate => "glide-path error rate (m/s)",
            Self::DeckPitch => "predicted deck pitch (deg)",
            Self::LandingPointDisplacement => "predicted landing-point displacement (m)",
            Self::OffCentreProbability => "probability of an off-centre touchdown (%)",
            Self::LineupDriftRate => "drift rate across the centreline (m/s)",
            Self::FoulDeckMotion => {
                "foul deck: predicted deck motion at touchdown, largest share of a recovery limit (%)"
            }
        }
    }
}

/// A wave-off decision: which criterion, its value and its limit.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct WaveOffDecision {
    /// The criterion that called it.
    pub criterion: WaveOffCriterion,
    /// The criterion's value (unit of [`WaveOffCriterion::quantity`]).
    pub value: f64,
    /// Its limit.
    pub limit: f64,
    /// The predicted hook-to-ramp clearance at the decision (m).
    pub predicted_ramp_clearance_m: f64,
}

/// What the decision looks at, once per step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveOffInputs {
    /// Estimated time to touchdown (s).
    pub time_to_go_s: f64,
    /// Height error of the hook to the path, h_ref − h_hook (m).
    pub glide_path_error_m: f64,
    /// Its rate (m/s).
    pub glide_path_error_rate_mps: f64,
    /// The glide path's height where it crosses the ramp (m).
    pub path_height_at_ramp_m: f64,
    /// The hook's climb rate (m/s, up).
    pub hook_climb_rate_mps: f64,
    /// Mean height of the landing point (m).
    pub mean_landing_point_height_m: f64,
    /// σ_c of the closed-loop predicted ramp clearance (m), for the ramp-strike
    /// probability: the forecast's σ of the ramp less what the path follows of it
    /// before the crossing, with the hook's and the crossing time's (docs/model.md §9).
    pub ramp_clearance_sigma_m: f64,
    /// How much the glide path at the ramp still rises before the hook crosses it (m):
    /// w times its anchor filter's own response towards the anchor it is given now, over
    /// the time to the crossing (docs/model.md §9); 0 without a filtered anchor (the
    /// `filter_lead` predictor) or before the decision window opens (where nothing reads
    /// it).
    pub ramp_clearance_gain_m: f64,
    /// The hook's sink rate at touchdown as the guidance flies it (m/s, down): the
    /// path's descent at the closure, less the rate its anchor filter is left with at
    /// touchdown (docs/model.md §9); 0 where nothing reads it (the `forecast`
    /// hard-landing model, or before the decision window opens).
    pub closed_loop_hook_sink_rate_mps: f64,
    /// The deck forecast.
    pub forecast: DeckForecast,
}

impl WaveOffInputs {
    /// The predicted hook-to-ramp clearance (m): the path's height at the ramp less the
    /// hook's error to it, above the forecast ramp.
    #[inline]
    pub fn predicted_ramp_clearance_m(&self) -> f64 {
        self.path_height_at_ramp_m - self.glide_path_error_m - self.forecast.ramp_height_m
    }

    /// The closed-loop predicted clearance (m), the ramp-strike probability's mean: the
    /// predicted clearance plus the path's rise before the crossing
    /// (`ramp_clearance_gain_m`).
    #[inline]
    pub fn closed_loop_ramp_clearance_m(&self) -> f64 {
        self.predicted_ramp_clearance_m() + self.ramp_clearance_gain_m
    }

    /// The probability of a ramp strike under the forecast and the path the guidance
    /// flies until the crossing: Φ(−c/σ_c) of the closed-loop clearance c and its σ_c.
    #[inline]
    pub fn ramp_strike_probability(&self) -> f64 {
        ramp_strike_probability(
            self.closed_loop_ramp_clearance_m(),
            self.ramp_clearance_sigma_m,
        )
    }
}

impl WaveOffParameters {
    /// Whether the hook is in the decision window.
    pub fn in_window(&self, time_to_go_s: f64) -> bool {
        self.enabled
            && time_to_go_s <= self.window_start_time_to_go_s
            && time_to_go_s >= self.decision_time_to_go_s
    }

    /// The decision on these inputs: the first criterion (in the order of the module
    /// docs) that is out of limits, or `None` to go on. Outside the window, `None`.
    pub fn decide(&self, inputs: &WaveOffInputs) -> Option<WaveOffDecision> {
        if !self.in_window(inputs.time_to_go_s) {
            return None;
        }
        let m = self.measures(inputs);
        let percent = |x: f64| 100.0 * x;
        use WaveOffCriterion::*;
        let (ramp, hard) = (
            self.max_ramp_strike_probability,
            self.max_hard_landing_probability,
        );
        let (error, pitch, moved) = (inputs.glide_path_error_m, m.pitch_deg, m.displacement);
        // One criterion a line, as a table: its value, its limit, whether it is out.
        #[rustfmt::skip]
        let checks = [
            (RampStrikeProbability, percent(m.ramp_strike), percent(ramp), ramp > 0.0 && m.ramp_strike > ramp),
            (HardLandingProbability, percent(m.hard_landing), percent(hard), hard > 0.0 && m.hard_landing > hard),
            (RampClearance, m.clearance, self.min_ramp_clearance_m, m.clearance < self.min_ramp_clearance_m),
            (TouchdownSinkRate, m.sink, self.max_touchdown_sink_rate_mps, m.sink > self.max_touchdown_sink_rate_mps),
            (GlidePathError, error, self.max_glide_path_error_m, error.abs() > self.max_glide_path_error_m),
            (GlidePathErrorRate, m.drift, self.max_glide_path_error_rate_mps, m.drift > self.max_glide_path_error_rate_mps),
            (DeckPitch, pitch, self.max_deck_pitch_deg, pitch.abs() > self.max_deck_pitch_deg),
            (LandingPointDisplacement, moved, self.max_landing_point_displacement_m, moved.abs() > self.max_landing_point_displacement_m),
        ];
        first_out_of_limits(checks, m.clearance)
    }

    /// The commit gate's decision at the commit point on what the forecast gives there:
    /// a wave-off on the ramp-strike probability if it is above
    /// `max_commit_ramp_strike_probability` (the limit in this sea,
    /// [`Self::in_sea`]); `None` to commit, and always with the gate off (0).
    pub fn decide_commit(&self, forecast: &CommitForecast) -> Option<WaveOffDecision> {
        let (p, limit) = (
            forecast.ramp_strike_probability,
            self.max_commit_ramp_strike_probability,
        );
        let out = self.enabled && limit > 0.0 && p > limit;
        #[rustfmt::skip]
        let checks = [(WaveOffCriterion::RampStrikeProbability, 100.0 * p, 100.0 * limit, out)];
        first_out_of_limits(checks, forecast.ramp_clearance_m)
    }

    /// What the criteria of [`Self::decide`] compare with their limits, on `inputs`.
    fn measures(&self, inputs: &WaveOffInputs) -> WaveOffMeasures {
        let forecast = &inputs.forecast;
        let clearance = inputs.predicted_ramp_clearance_m();
        let sink = -inputs.hook_climb_rate_mps + forecast.landing_point_climb_rate_mps;
        let pitch_deg = forecast.pitch_rad.to_degrees();
        let displacement = forecast.landing_point_height_m - inputs.mean_landing_point_height_m;
        // The error grows when it and its rate have the same sign.
        let drift = if inputs.glide_path_error_m * inputs.glide_path_error_rate_mps > 0.0 {
            inputs.glide_path_error_rate_mps.abs()
        } else {
            0.0
        };
        let ramp_strike = if self.max_ramp_strike_probability > 0.0 {
            inputs.ramp_strike_probability()
        } else {
            0.0
        };
        let hard_landing = if self.max_hard_landing_probability > 0.0 {
            self.hard_landing_probability(self.hard_landing_sink_rate_mps_of(inputs), forecast)
        } else {
            0.0
        };
        WaveOffMeasures {
            clearance,
            sink,
            pitch_deg,
            displacement,
            drift,
            ramp_strike,
            hard_landing,
        }
    }

    /// The probability of a hard landing under the forecast for a predicted touchdown
    /// sink rate relative to the deck `sink` (m/s): Φ((sink − limit)/σ), σ the hypot of
    /// the forecast's σ of the landing point's climb rate (0 when nothing asked the deck
    /// predictor for it) and the hook's own `touchdown_sink_rate_sigma_mps`.
    fn hard_landing_probability(&self, sink: f64, forecast: &DeckForecast) -> f64 {
        let sigma = forecast
            .landing_point_climb_rate_sigma_mps
            .hypot(self.touchdown_sink_rate_sigma_mps);
        super::risk::normal_cdf((sink - self.hard_landing_sink_rate_mps) / sigma.max(1e-9))
    }

    /// The predicted touchdown sink rate relative to the deck (m/s) that the
    /// hard-landing probability is taken on (`hard_landing_model`): the hook's sink now,
    /// or as the guidance flies it to touchdown, less the landing point's forecast climb
    /// rate at touchdown.
    fn hard_landing_sink_rate_mps_of(&self, inputs: &WaveOffInputs) -> f64 {
        let hook_sink_mps = match self.hard_landing_model {
            HardLandingModel::Forecast => -inputs.hook_climb_rate_mps,
            HardLandingModel::ClosedLoop => inputs.closed_loop_hook_sink_rate_mps,
        };
        hook_sink_mps + inputs.forecast.landing_point_climb_rate_mps
    }

    /// The probabilities the forecast gives on `inputs` for the wave-off's probabilistic
    /// criteria, with the criteria's formulas whether they are on or off: what the
    /// approach is committed on at the commit point ([`CommitForecast`]; the off-centre
    /// probability of a 3-D approach is the lateral criterion's, added by the caller).
    pub fn commit_forecast(&self, inputs: &WaveOffInputs) -> CommitForecast {
        let sink = self.hard_landing_sink_rate_mps_of(inputs);
        CommitForecast {
            ramp_strike_probability: inputs.ramp_strike_probability(),
            hard_landing_probability: self.hard_landing_probability(sink, &inputs.forecast),
            off_centre_probability: None,
            ramp_clearance_m: inputs.closed_loop_ramp_clearance_m(),
            ramp_clearance_sigma_m: inputs.ramp_clearance_sigma_m,
        }
    }
}

/// Which clearance the ramp-strike probability is taken on (`ramp_strike_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum RampStrikeModel {
    /// The path held as it is now: c the predicted clearance, σ_c the forecast's σ of
    /// the ramp at the crossing with the hook's and the crossing time's. The probability
    /// as it first came, and of a file that names none; pessimistic by about 5× in the
    /// paper's sea (docs/no-oracle-results.md).
    Forecast,
    /// The path the guidance flies until the crossing (docs/model.md §9): c′ adds the
    /// anchor filter's rise before the crossing, σ_c′ takes out the forecast's later
    /// updates that the path follows while its anchor rides the ramp. The default of
    /// the files written before `closed_loop_anchor`.
    ClosedLoop,
    /// As `closed_loop`, and off the ramp's floor, where the anchor is the forecast
    /// landing point, σ_c′ also takes out what the path follows of the landing point's
    /// later updates as they bear on the ramp's (their covariance), and adds what it
    /// follows of them that does not (docs/model.md §9).
    ClosedLoopAnchor,
    /// As `closed_loop_anchor`, with the hook flown by direct lift (docs/model.md §9):
    /// c′ is the path on the unfiltered anchor less the hook's error to it as the
    /// direct-lift loop leaves it at the crossing, and the later updates are followed
    /// by that loop's step response, not the anchor filter's. Without direct lift, as
    /// `closed_loop_anchor`. The default.
    ClosedLoopLift,
}

impl RampStrikeModel {
    /// Whether the probability is taken on the path the guidance flies (`closed_loop`,
    /// `closed_loop_anchor`).
    pub fn is_closed_loop(self) -> bool {
        matches!(
            self,
            Self::ClosedLoop | Self::ClosedLoopAnchor | Self::ClosedLoopLift
        )
    }

    /// Whether off the ramp's floor the path's following of the landing point is
    /// credited (`closed_loop_anchor`, `closed_loop_lift`).
    pub fn follows_landing_point(self) -> bool {
        matches!(self, Self::ClosedLoopAnchor | Self::ClosedLoopLift)
    }

    /// The model of a file that names none: the probability as it first came.
    pub fn named_by_none() -> Self {
        Self::Forecast
    }
}

/// Which touchdown sink rate the hard-landing probability is taken on
/// (`hard_landing_model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HardLandingModel {
    /// The hook's sink rate now, held to touchdown: the probability as it first came,
    /// and of a file that names none; pessimistic by about 2.7× in the paper's sea
    /// (docs/no-oracle-results.md).
    Forecast,
    /// The hook's sink rate at touchdown as the guidance flies it (docs/model.md §9):
    /// the path's descent at the closure, less the rate its anchor filter is left with
    /// at touchdown. The default.
    ClosedLoop,
}

impl HardLandingModel {
    /// The model of a file that names none: the probability as it first came.
    pub fn named_by_none() -> Self {
        Self::Forecast
    }
}

/// The probability of a ramp strike under the forecast: Φ(−c/σ_c) for the closed-loop
/// predicted hook-to-ramp clearance `clearance_m` (m) and its σ `sigma_m` (m).
fn ramp_strike_probability(clearance_m: f64, sigma_m: f64) -> f64 {
    super::risk::normal_cdf(-clearance_m / sigma_m.max(1e-9))
}

/// What the forecast gave at the commit point of an approach (the first step with the
/// time to go at or below `decision_time_to_go_s`, the approach not waving off by then):
/// the probabilities of the wave-off's probabilistic criteria, computed whether the
/// criteria are on or off, to be held against what the flight did (docs/no-oracle-results.md,
/// "Calibration at the commit point").
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct CommitForecast {
    /// Probability of a ramp strike, Φ(−c/σ_c) of the closed-loop clearance (–).
    pub ramp_strike_probability: f64,
    /// Probability of a hard landing, Φ((sink − limit)/σ) (–).
    pub hard_landing_probability: f64,
    /// 3-D approach: probability of an off-centre touchdown, the lateral criterion's
    /// (`control::wave_off_lateral`), at the lateral guidance's first frame from the
    /// commit point (–); `None` for a longitudinal approach.
    pub off_centre_probability: Option<f64>,
    /// c, the predicted hook-to-ramp clearance the ramp-strike probability is taken on
    /// (m): the closed-loop one, or the one of the path held with `ramp_strike_model =
    /// "forecast"` ([`WaveOffInputs::closed_loop_ramp_clearance_m`]).
    pub ramp_clearance_m: f64,
    /// σ_c, its σ (m) ([`WaveOffInputs::ramp_clearance_sigma_m`]).
    pub ramp_clearance_sigma_m: f64,
}

/// The decision of the first of `checks` — each a criterion, its value, its limit and
/// whether the value is out of the limit — that is out of its limit, carrying
/// `predicted_ramp_clearance_m`; `None` if every check is within its limit.
pub(in crate::control) fn first_out_of_limits<const N: usize>(
    checks: [(WaveOffCriterion, f64, f64, bool); N],
    predicted_ramp_clearance_m: f64,
) -> Option<WaveOffDecision> {
    checks
        .into_iter()
        .find(|check| check.3)
        .map(|(criterion, value, limit, _)| WaveOffDecision {
            criterion,
            value,
            limit,
            predicted_ramp_clearance_m,
        })
}

mod heavy_sea;
mod recovery;

pub use recovery::{FoulDeckModel, RecoveryLimits};

#[cfg(test)]
pub(in crate::control) mod tests;
