//! Flight-path generator: the glide path the hook follows down to the deck (paper §2.1,
//! §4.1; docs/model.md §5).
//!
//! The glide path is a straight line at `glide_slope_deg` through an anchor on the deck:
//! h_ref = h_anchor + (x_anchor − x_hook)·tan(glide slope), with climb rate
//! ḣ_ref = ḣ_anchor + (ẋ_anchor − ẋ_hook)·tan(glide slope).
//!
//! Until the last `compensation_window_s` seconds before touchdown the anchor is the
//! *mean* landing point (ship level, no heave). Then, with deck-motion compensation on,
//! it moves over `compensation_blend_s` seconds to the *predicted* landing point (for
//! `filter_lead`, the filtered one extrapolated `deck_motion_lead_s` ahead, ĥ_L + τ·ĥ̇_L,
//! the lead of the AN/SPN-42 deck-motion compensation, paper §2.1). The blend avoids a
//! step in the reference. The rate fed forward is ĥ̇_L (the prediction's own
//! acceleration term is left out).
//!
//! Three predictors of the landing point are offered ([`DeckPredictorKind`]; the
//! blocks are in `simulation::deck_prediction`):
//!
//! - `estimator` (default): the minimum-variance prediction of the landing point's height
//!   at the estimated touchdown time from a Kalman filter's estimate of the ship-motion
//!   state, fed by the ship's sensed motion ([`crate::estimation::DeckMotionEstimator`]);
//!   raised, when `ramp_aware`, so that the path clears the predicted ramp by
//!   `ramp_clearance_margin_m`, and smoothed by a critically damped filter whose rate is
//!   fed forward. The lead is not used.
//! - `oracle`: the same prediction from the ship model's *true* state (the paper's set;
//!   studies only); its expected rate of change is zero, so nothing is fed forward.
//! - `filter_lead`: the filtered landing point extrapolated by the lead, below.
//!
//! The blend's weight rises linearly (`linear`, the paper's set) or as 3s² − 2s³
//! (`smooth`), which leaves no step in the reference's rate. The path may aim
//! `touchdown_correction_m` from the aim point.
//!
//! For `filter_lead`, ĥ_L and ĥ̇_L are not the raw deck signals but the states of a critically damped
//! second-order low-pass filter ([`super::DeckMotionFilter`]) on the landing point's height. The
//! raw rate contains 81 m × the ship's pitch rate, the output of the shaping filter's
//! white-noise-driven state: continuous but rough. Fed forward unfiltered it reaches the
//! pitch command as noise and drove the cascade into saturation and divergence.

use crate::control::smooth_step;
use crate::environment::{EarthPoint, EarthVelocity};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// How the landing point is predicted for deck-motion compensation (docs/model.md §5.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum DeckPredictorKind {
    /// Minimum-variance prediction at the touchdown time from a Kalman filter's estimate
    /// of the ship-motion state, fed by the sensed ship motion (docs/model.md §3.5): what
    /// an aircraft can fly with. The default.
    #[default]
    Estimator,
    /// Minimum-variance prediction at the touchdown time from the ship model's *true*
    /// state: an upper bound for studies, which no aircraft can fly with. `model` is its
    /// former name, still read.
    #[serde(alias = "model")]
    Oracle,
    /// Low-pass filtered landing point plus a linear lead of `deck_motion_lead_s`.
    FilterLead,
}

impl DeckPredictorKind {
    /// Whether this predictor forecasts the deck from the ship-motion model (and so gives
    /// the ramp and the deck's rate at a future time, with their error σ).
    pub fn forecasts(self) -> bool {
        matches!(self, Self::Estimator | Self::Oracle)
    }
}

/// How the compensation weight w rises from 0 to 1 over the blend (docs/model.md §5.7).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum CompensationBlend {
    /// w = 3s² − 2s³ of the blend's progress s: no step in the reference's rate either
    /// where the blend starts or where it ends. The default.
    #[default]
    Smooth,
    /// w = s, as the paper's hardware set flies: the reference's rate steps by
    /// offset/T_blend where the blend starts and ends.
    Linear,
}

/// Parameters of the glide path and of deck-motion compensation.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct FlightPathParameters {
    /// Glide slope (deg, positive descending); 3.5° by default.
    pub glide_slope_deg: f64,
    /// Follow the moving landing point in the last seconds (paper §2.1); on by default.
    pub deck_motion_compensation: bool,
    /// How the landing point is predicted; `model` by default.
    pub deck_motion_predictor: DeckPredictorKind,
    /// How long before touchdown compensation starts (s); 12 s (paper §2.1).
    pub compensation_window_s: f64,
    /// How long the anchor takes to move from the mean to the moving deck (s); 2 s.
    pub compensation_blend_s: f64,
    /// Prediction horizon of the `filter_lead` deck-motion lead (s); 1 s.
    pub deck_motion_lead_s: f64,
    /// Natural frequency of the critically damped deck-motion filter (rad/s); 1.0.
    pub deck_filter_frequency_radps: f64,
    /// Shape of the blend-in of compensation; `smooth` (realistic), `linear` (paper).
    pub compensation_blend: CompensationBlend,
    /// Natural frequency (rad/s) of the critically damped filter through which the
    /// `estimator`'s predicted anchor passes (and the realistic set's `oracle`'s, which
    /// flies the same design), so that each 50-Hz update of the estimate moves the glide
    /// path smoothly; 1 rad/s (docs/model.md §5.7: against 4 rad/s it
    /// halves the hard landings in the paper's sea and keeps the stabilator off its rate
    /// limit, 0.1 % of the approach against 7 %, docs/no-oracle-results.md).
    pub anchor_filter_frequency_radps: f64,
    /// Keep the path above the ramp: the anchor is raised so that the path crosses the
    /// predicted ramp at least `ramp_clearance_margin_m` above it (docs/model.md §5.7);
    /// on in the realistic set, off in the paper's.
    pub ramp_aware: bool,
    /// Smallest hook-over-ramp clearance the path keeps above the predicted ramp (m);
    /// 2.0 m, raised by the risk-aware clearance (`ramp_strike_probability_limit`); 2.5 m,
    /// fixed, in the paper's set (the LSO's 3.05 m lifts the path too often on this deck,
    /// docs/model.md §5.7).
    pub ramp_clearance_margin_m: f64,
    /// With `ramp_aware`, shed the anchor's raise between the ramp and the aim point: the
    /// path crosses the predicted ramp with the margin, then descends on a steeper last
    /// segment to the predicted landing point instead of landing raise/tan Γ long
    /// (docs/model.md §5.7); on in the realistic set.
    pub descend_after_ramp: bool,
    /// Risk-aware clearance over the ramp (docs/model.md §5.7): the path crosses the
    /// predicted ramp at least z·σ_c above it, z = Φ⁻¹(1 − p) for this p, σ_c² = σ_r² +
    /// σ_h² + (ṙ·σ_t)² with σ_r the forecast's σ of the ramp height at the crossing, ṙ the
    /// ramp's predicted climb rate then, σ_h = `hook_height_sigma_m` and
    /// σ_t = `ramp_crossing_time_sigma_s`, so that under the Gaussian forecast the hook
    /// passes below the ramp with probability at most p; never less than
    /// `ramp_clearance_margin_m`. 0 turns it off (the fixed margin alone, the paper's
    /// set); 10⁻⁴ (the clearance z·σ_c less `ramp_recovery_m`, capped at
    /// `max_ramp_clearance_m`, which binds in the paper's sea; docs/model.md §5.7,
    /// docs/no-oracle-results.md); [0, 0.5).
    pub ramp_strike_probability_limit: f64,
    /// The most clearance over the predicted ramp the risk-aware clearance may ask for
    /// (m): far out the forecast's σ is the sea's own, and an uncapped z·σ would move the
    /// path by metres (in the heavy sea the aircraft then dives below α = −5° when the
    /// forecast tightens); 4.0 m, [`ramp_clearance_margin_m`, 20].
    pub max_ramp_clearance_m: f64,
    /// σ_h, the hook's height scatter about the path where it crosses the ramp (m), for
    /// the risk-aware clearance and the wave-off's ramp-strike probability; an assumption
    /// near the glide-path error RMS of the default approach (0.2–0.4 m,
    /// docs/no-oracle-results.md); 0.3 m, [0, 5].
    pub hook_height_sigma_m: f64,
    /// The shortest horizon at which the risk-aware clearance and the wave-off take the
    /// ramp forecast's σ (s): the ramp's σ is that of the forecast at the crossing, or
    /// this long ahead if the crossing is nearer, since the flight path cannot follow a
    /// correction faster than it answers (about 2 s behind pitch, docs/model.md §5.5,
    /// less with direct lift); 1.5 s; [0, 10].
    pub ramp_sigma_min_horizon_s: f64,
    /// σ_t, the uncertainty of the time at which the hook crosses the ramp (s), which a
    /// moving ramp turns into height (ṙ·σ_t); an assumption; 0.1 s, [0, 2].
    pub ramp_crossing_time_sigma_s: f64,
    /// With `descend_after_ramp`, the time over which the descent's extra sink rate
    /// blends in after the hook crosses the ramp and out before the aim point (s), as
    /// 3x² − 2x³: the climb-rate command and its rate have no step there (a linear shed,
    /// 0 here, stepped the command by 1.5 m/s over the ramp and drove the stabilator onto
    /// its rate limit, docs/model.md §5.7); 0.25 s; [0, 2] s (at most half the
    /// ramp-to-aim-point segment is used).
    pub descent_blend_s: f64,
    /// The most sink the descent after the ramp adds (m/s): a larger raise is shed in part
    /// and the hook lands long, no dive at the deck; 1.5, (0, 20] (docs/model.md §5.7).
    pub max_descent_after_ramp_sink_mps: f64,
    /// Touchdown-point correction (m along the deck, positive forward): the path aims
    /// this far from the aim point (docs/model.md §5.7); 0.
    pub touchdown_correction_m: f64,
    /// Feed the steady air wake's vertical wind forward into the pitch command,
    /// Δθ = W_z/V (docs/model.md §5.7), from the MIL-F-8785C steady-wake model at the
    /// aircraft's distance aft of the ship; on in the realistic set, off in the paper's.
    pub wake_feedforward: bool,
    /// Lead τ of the wake feed-forward (s): Δθ = (W_z + τ·dW_z/dt)/V, the wind's change
    /// along the path fed τ ahead to make up for the flight path's lag behind pitch
    /// (about 2 s, docs/model.md §5.5); 3 s in the realistic set, which also takes out
    /// part of the periodic wake's float (docs/landing-design.md, "Touchdown scatter in a
    /// moderate sea"), 0 (none) in the paper's.
    pub wake_feedforward_lead_s: f64,
    /// r, the height the aircraft can still gain over the ramp after the wave-off's commit
    /// point, credited against the risk-aware clearance: the path crosses the predicted
    /// ramp max(`ramp_clearance_margin_m`, z·σ_c − r) above it (docs/model.md §5.7). Direct
    /// lift's ±0.15 of C_L (about 1.18 m/s² at 69 m/s) held over the 1.4 s from the commit
    /// point to the ramp gives ½·1.18·1.4² = 1.16 m (docs/deck-prediction.md); 0 m, [0, 5].
    pub ramp_recovery_m: f64,
}

impl Default for FlightPathParameters {
    fn default() -> Self {
        Self {
            glide_slope_deg: 3.5,
            deck_motion_compensation: true,
            deck_motion_predictor: DeckPredictorKind::Estimator,
            compensation_window_s: 12.0,
            compensation_blend_s: 2.0,
            deck_motion_lead_s: 1.0,
            deck_filter_frequency_radps: 1.0,
            compensation_blend: CompensationBlend::Smooth,
            anchor_filter_frequency_radps: 1.0,
            ramp_aware: true,
            ramp_clearance_margin_m: 2.0,
            descend_after_ramp: true,
            descent_blend_s: 0.25,
            max_descent_after_ramp_sink_mps: 1.5,
            ramp_strike_probability_limit: 0.0001,
            max_ramp_clearance_m: 4.0,
            hook_height_sigma_m: 0.3,
            ramp_sigma_min_horizon_s: 1.5,
            ramp_crossing_time_sigma_s: 0.1,
            touchdown_correction_m: 0.0,
            wake_feedforward: true,
            wake_feedforward_lead_s: 3.0,
            ramp_recovery_m: 1.16,
        }
    }
}

impl FlightPathParameters {
    /// The paper's glide path: the `oracle` predictor, a linear blend, no ramp awareness
    /// and no touchdown correction (what the paper's hardware set flies, docs/model.md
    /// §2.6).
    pub fn paper() -> Self {
        Self {
            deck_motion_predictor: DeckPredictorKind::Oracle,
            compensation_blend: CompensationBlend::Linear,
            ramp_aware: false,
            ramp_clearance_margin_m: 2.5,
            descend_after_ramp: false,
            ramp_strike_probability_limit: 0.0,
            ramp_recovery_m: 0.0,
            touchdown_correction_m: 0.0,
            wake_feedforward: false,
            wake_feedforward_lead_s: 0.0,
            ..Self::default()
        }
    }

    /// Checks every value against its range (each field's doc), naming the key.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.flight_path";
        check_ranges!(SECTION, self, {
            glide_slope_deg: Bounds::positive_up_to(10.0),
            compensation_window_s: Bounds::closed(0.0, 60.0),
            compensation_blend_s: Bounds::positive_up_to(30.0),
            deck_motion_lead_s: Bounds::closed(0.0, 10.0),
            deck_filter_frequency_radps: Bounds::positive_up_to(100.0),
            anchor_filter_frequency_radps: Bounds::positive_up_to(100.0),
            ramp_clearance_margin_m: Bounds::closed(0.0, 20.0),
            descent_blend_s: Bounds::closed(0.0, 2.0),
            max_descent_after_ramp_sink_mps: Bounds::positive_up_to(20.0),
            ramp_strike_probability_limit: Bounds::closed(0.0, 0.5).exclusive_max(),
            max_ramp_clearance_m: Bounds::closed(self.ramp_clearance_margin_m.max(0.0), 20.0),
            hook_height_sigma_m: Bounds::closed(0.0, 5.0),
            ramp_sigma_min_horizon_s: Bounds::closed(0.0, 10.0),
            ramp_crossing_time_sigma_s: Bounds::closed(0.0, 2.0),
            touchdown_correction_m: Bounds::closed(-50.0, 50.0),
            wake_feedforward_lead_s: Bounds::closed(0.0, 10.0),
            ramp_recovery_m: Bounds::closed(0.0, 5.0),
        });
        Ok(())
    }
}

/// Where the deck is, for the generator: the mean and the (filtered) landing point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckReference {
    /// The landing point with the ship level and at its mean height.
    pub mean_aim: EarthPoint,
    /// Velocity of the mean landing point (the ship's speed).
    pub mean_aim_velocity: EarthVelocity,
    /// The moving landing point (its filtered estimate in the simulation).
    pub aim: EarthPoint,
    /// Its velocity (filtered estimate).
    pub aim_velocity: EarthVelocity,
    /// The deck forecast at the hook's ramp crossing and touchdown, from predictors that
    /// forecast the ship's motion ([`DeckPredictorKind::forecasts`]); for the wave-off
    /// decision.
    pub forecast: Option<DeckForecast>,
    /// The estimator's anchor height before its anchor filter (m), which direct lift
    /// control flies to (docs/model.md §5.9); `None` for the other predictors.
    pub unfiltered_aim_h_m: Option<f64>,
    /// The estimator's filtered anchor's vertical acceleration (m/s², up), for direct
    /// lift's feed-forward (docs/model.md §5.9); 0 for the other predictors.
    pub aim_acceleration_mps2: f64,
}

/// What a model-based predictor expects the deck to do while the hook closes on it (the
/// means: the loop does not need the error variances every step;
/// [`crate::environment::ShipMotionPropagator::forecast`] gives them).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckForecast {
    /// Predicted ramp height when the hook crosses it (m).
    pub ramp_height_m: f64,
    /// Predicted climb rate of the landing point at touchdown (m/s, up).
    pub landing_point_climb_rate_mps: f64,
    /// Predicted landing-point height at touchdown (m).
    pub landing_point_height_m: f64,
    /// Predicted ship pitch at touchdown (rad, bow up).
    pub pitch_rad: f64,
    /// Predicted climb rate of the ramp when the hook crosses it (m/s, up).
    pub ramp_climb_rate_mps: f64,
    /// σ of the ramp-height prediction at the crossing (m), from the estimator's
    /// covariance carried to that horizon and the sea still to come
    /// ([`crate::environment::ShipMotionPropagator::deck_point_uncertainty`]); 0 when
    /// neither the guidance nor the wave-off asks for it.
    pub ramp_height_sigma_m: f64,
    /// σ of the landing point's predicted climb rate at touchdown (m/s); 0 likewise.
    pub landing_point_climb_rate_sigma_mps: f64,
    /// How the glide path's anchor, riding the ramp, follows the ramp height's forecast
    /// updates still to come before the crossing (m²; docs/model.md §9):
    /// [∫₀ᵀ g dσ², ∫₀ᵀ g² dσ²], σ²(τ) the ramp's forecast variance τ before the crossing,
    /// T the time to it and g(τ) = 1 − (1 + ωτ)·e^(−ωτ) the critically damped anchor
    /// filter's step response at `anchor_filter_frequency_radps` ω. A path that moves by
    /// w of its anchor takes F = 2w·∫g dσ² − w²·∫g² dσ² out of the ramp's variance.
    /// Zeros when nothing asked for the σ, without a wave-off or a ramp-aware anchor, or
    /// more than two guidance frames before the wave-off's window opens.
    pub ramp_update_response_m2: [f64; 2],
    /// How the glide path's anchor, off the ramp's floor (the forecast landing point),
    /// follows the landing point's forecast updates still to come before the crossing, as
    /// they bear on the ramp's (m²; docs/model.md §9): [∫₀ᵀ g dC, ∫₀ᵀ g² dσ_L²], C(τ) the
    /// covariance of the ramp's height at the crossing and the landing point's at
    /// touchdown forecast τ before the crossing, σ_L² the landing point's variance. A path
    /// that moves by w of its anchor takes F = 2w·∫g dC − w²·∫g² dσ_L² out of the ramp's
    /// variance. Zeros unless `ramp_strike_model = "closed_loop_anchor"`, and as
    /// `ramp_update_response_m2` otherwise.
    pub landing_point_update_response_m2: [f64; 2],
    /// Predicted ship roll at touchdown (rad, starboard down); 0 without a roll forecast
    /// (the longitudinal approach).
    pub roll_rad: f64,
}

#[cfg(test)]
impl DeckForecast {
    /// A still deck's forecast: the landing point and the ramp at these heights (m),
    /// nothing moving and nothing uncertain (the tests' fixture).
    pub(crate) fn still(landing_point_height_m: f64, ramp_height_m: f64) -> Self {
        Self {
            ramp_height_m,
            landing_point_climb_rate_mps: 0.0,
            landing_point_height_m,
            pitch_rad: 0.0,
            ramp_climb_rate_mps: 0.0,
            ramp_height_sigma_m: 0.0,
            landing_point_climb_rate_sigma_mps: 0.0,
            ramp_update_response_m2: [0.0; 2],
            landing_point_update_response_m2: [0.0; 2],
            roll_rad: 0.0,
        }
    }
}

/// The generator's output for the hook.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PathReference {
    /// Reference height of the hook (m).
    pub height_m: f64,
    /// Reference climb rate of the hook (m/s, positive up).
    pub climb_rate_mps: f64,
    /// Estimated time to touchdown (s); infinite when not closing on the deck.
    pub time_to_go_s: f64,
    /// Weight of the moving landing point in the anchor, 0 (mean deck) to 1.
    pub compensation_weight: f64,
}

/// The glide-path generator.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlightPathGenerator {
    parameters: FlightPathParameters,
    tan_slope: f64,
    ramp_clearance_z: f64,
}

impl FlightPathGenerator {
    /// Builds the generator after validating its parameters.
    pub fn new(parameters: FlightPathParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        let p = parameters.ramp_strike_probability_limit;
        Ok(Self {
            parameters,
            tan_slope: parameters.glide_slope_deg.to_radians().tan(),
            ramp_clearance_z: if p > 0.0 {
                super::risk::normal_upper_quantile(p)
            } else {
                0.0
            },
        })
    }

    /// The parameters.
    pub fn parameters(&self) -> &FlightPathParameters {
        &self.parameters
    }

    /// z = Φ⁻¹(1 − p) of the ramp-strike probability limit p (–); 0 when it is off.
    pub fn ramp_clearance_z(&self) -> f64 {
        self.ramp_clearance_z
    }

    /// tan of the glide slope (–).
    pub fn tan_slope(&self) -> f64 {
        self.tan_slope
    }

    /// Estimated time to touchdown (s) of a hook at `hook_x_m` moving at `hook_x_rate_mps`
    /// towards the mean landing point `mean_aim_x_m` moving at `mean_aim_x_rate_mps`:
    /// range over closure speed; infinite when not closing.
    #[inline]
    pub fn time_to_go_s(
        &self,
        hook_x_m: f64,
        hook_x_rate_mps: f64,
        mean_aim_x_m: f64,
        mean_aim_x_rate_mps: f64,
    ) -> f64 {
        let closure = hook_x_rate_mps - mean_aim_x_rate_mps;
        if closure > 0.0 {
            (mean_aim_x_m - hook_x_m) / closure
        } else {
            f64::INFINITY
        }
    }

    /// The reference for a hook at earth x `hook_x_m` moving at `hook_x_rate_mps`, given
    /// the (predicted) landing point in `deck`.
    #[inline]
    pub fn reference(
        &self,
        hook_x_m: f64,
        hook_x_rate_mps: f64,
        deck: &DeckReference,
    ) -> PathReference {
        let p = &self.parameters;
        // The path aims `touchdown_correction_m` from the mean aim point (0 adds nothing).
        let aim_x_m = deck.mean_aim.x_m + p.touchdown_correction_m;
        let range = aim_x_m - hook_x_m;
        let time_to_go_s = self.time_to_go_s(
            hook_x_m,
            hook_x_rate_mps,
            aim_x_m,
            deck.mean_aim_velocity.x_mps,
        );
        let (weight, weight_rate) = if p.deck_motion_compensation {
            let w = (p.compensation_window_s - time_to_go_s) / p.compensation_blend_s;
            if w <= 0.0 {
                (0.0, 0.0)
            } else if w >= 1.0 {
                (1.0, 0.0)
            } else {
                // d(time to go)/dt = −1 at constant closure.
                match p.compensation_blend {
                    CompensationBlend::Linear => (w, 1.0 / p.compensation_blend_s),
                    CompensationBlend::Smooth => {
                        (smooth_step(w), 6.0 * w * (1.0 - w) / p.compensation_blend_s)
                    }
                }
            }
        } else {
            (0.0, 0.0)
        };
        let lead_s = match p.deck_motion_predictor {
            DeckPredictorKind::Estimator | DeckPredictorKind::Oracle => 0.0,
            DeckPredictorKind::FilterLead => p.deck_motion_lead_s,
        };
        let predicted = deck.aim.h_m + lead_s * deck.aim_velocity.h_mps;
        let offset = predicted - deck.mean_aim.h_m;
        let anchor_h = deck.mean_aim.h_m + weight * offset;
        let anchor_h_rate = deck.mean_aim_velocity.h_mps
            + weight * (deck.aim_velocity.h_mps - deck.mean_aim_velocity.h_mps)
            + weight_rate * offset;
        PathReference {
            height_m: anchor_h + range * self.tan_slope,
            climb_rate_mps: anchor_h_rate
                + (deck.mean_aim_velocity.x_mps - hook_x_rate_mps) * self.tan_slope,
            time_to_go_s,
            compensation_weight: weight,
        }
    }
}

#[cfg(test)]
mod tests;
