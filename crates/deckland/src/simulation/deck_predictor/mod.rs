//! Deck predictors: where the glide path expects the landing point to be
//! (docs/model.md §5.7, deck-motion compensation; see [`crate::control::FlightPathGenerator`]).
//!
//! Every predictor implements [`DeckPredictor`]; the scenario's three
//! ([`crate::control::DeckPredictorKind`]) are one module each:
//!
//! - [`estimator`] (default): the ship's sensed motion (docs/model.md §3.5) feeds a Kalman
//!   filter ([`crate::estimation::DeckMotionEstimator`]); the landing point and the ramp
//!   are forecast from its estimate at the hook's touchdown and ramp-crossing times, the
//!   data link's latency added to the horizon. The anchor passes through a critically
//!   damped filter so that each 50-Hz update moves the path smoothly.
//! - [`oracle`]: the same forecast and the same anchor from the ship model's *true* state
//!   (studies only: the two differ only in what they know); or, in the paper's set, the
//!   prediction itself.
//! - [`filter_lead`]: a low-pass filter on the landing point's height with a lead.
//!
//! With `ramp_aware` the forecast anchor is raised, where needed, so that the path crosses
//! the predicted ramp `ramp_clearance_margin_m` above it.
//!
//! A user's own predictor is one type implementing [`DeckPredictor`], flown with
//! `Simulation::builder(&scenario).deck_predictor(..)` (see
//! `tests/custom_deck_predictor.rs`). The loop calls the scenario's through
//! [`BuiltDeckPredictor`], an enum without dynamic dispatch.

pub mod estimator;
pub mod filter_lead;
pub mod oracle;
mod raise;
mod roll;
mod uncertainty;

pub(crate) use raise::{
    anchor_free_response, capped_raise_share, closed_loop_ramp_clearance_sigma_m,
    landing_point_following_ramp_clearance_sigma_m, ramp_aware_anchor,
};
pub use roll::SensedRoll;
pub(crate) use uncertainty::UncertaintyHold;

use std::fmt::Debug;

use super::anchor_shaping::AnchorShaping;
use crate::aircraft::six_dof::series_sin_cos;
use crate::control::{
    DeckForecast, DeckMotionFilter, DeckPredictorKind, DeckReference, FlightPathGenerator,
    LiftLoop, RampStrikeModel,
};
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, ShipMotion, ShipMotionEstimate, ShipMotionForecast,
    ShipMotionParameters, ShipMotionPropagator, ShipMotionState, ShipPose, ShipPoseRate,
};
use crate::estimation::DeckMotionEstimator;
use crate::parameters::ParameterError;
use crate::random::{stream_names, RandomStreams};
use crate::scenario::{Mission, Scenario};
use crate::sensors::{EstimatorStart, ShipMotionSensor};

/// The ship's motion at one instant, as a predictor reads it.
#[derive(Debug, Clone, Copy)]
pub struct DeckView<'a> {
    /// The ship-motion model (the shaping filters).
    pub ship_model: &'a ShipMotion,
    /// The model's true state (an oracle's knowledge; a real predictor reads the sensed
    /// motion instead).
    pub ship_state: &'a ShipMotionState,
    /// The deck's geometry.
    pub deck: &'a DeckGeometry,
    /// The ship's pose now.
    pub pose: &'a ShipPose,
    /// Its rate.
    pub rate: &'a ShipPoseRate,
    /// In the 3-D approach, the ship's latest sensed roll: the landing point and the ramp
    /// lie off the roll axis, so they rise and fall with it, which the heave-and-pitch
    /// forecast does not see (`None` in the 3-DOF approach).
    pub roll: Option<SensedRoll>,
}

/// Where the hook is, for the predictor.
#[derive(Debug, Clone, Copy)]
pub struct HookTrack {
    /// Now (s).
    pub time_s: f64,
    /// The hook's earth x (m).
    pub x_m: f64,
    /// Its rate (m/s).
    pub x_rate_mps: f64,
    /// The integration step (s): a smoothed anchor moves once per step.
    pub dt: f64,
}

/// A deck predictor: observes the ship once per step and gives the glide path its deck
/// reference; it may have continuous states (a filter), which the loop integrates.
pub trait DeckPredictor: Debug + Send + Sync {
    /// Names of its continuous states (none by default).
    fn state_names(&self) -> &'static [&'static str] {
        &[]
    }

    /// Its continuous state at the start (zero by default).
    fn initial_state(&self, view: &DeckView<'_>, state: &mut [f64]) {
        let _ = view;
        state.fill(0.0);
    }

    /// Once per step, at its start: what the aircraft learns of the ship (nothing by
    /// default).
    fn observe(&mut self, time_s: f64, view: &DeckView<'_>) {
        let _ = (time_s, view);
    }

    /// The deck reference for the flight-path generator this step, with `state` its
    /// continuous state (called once per step).
    fn deck_reference(&mut self, query: &DeckQuery<'_>, state: &[f64]) -> DeckReference;

    /// The rate of its continuous state, given the landing point's true height (m)
    /// (nothing by default).
    fn derivative(&self, state: &[f64], aim_height_m: f64, rate: &mut [f64]) {
        let _ = (state, aim_height_m);
        rate.fill(0.0);
    }

    /// Its Kalman filter, if it has one (for analyses).
    fn estimator(&self) -> Option<&DeckMotionEstimator> {
        None
    }

    /// A copy of it, as it is now (a simulation is cloned to look ahead).
    fn clone_box(&self) -> Box<dyn DeckPredictor>;

    /// Re-keys its random streams with `key` ([`crate::random::Reseed`]), for a flight
    /// continued with fresh noise. A predictor that draws noise must re-key it here; by
    /// default it draws none.
    fn reseed(&mut self, key: u64) {
        let _ = key;
    }
}

impl Clone for Box<dyn DeckPredictor> {
    fn clone(&self) -> Self {
        self.clone_box()
    }
}

/// The predictor of a run: the scenario's, called without dynamic dispatch, or a user's.
// One per simulation, read every step: the oracle stays inline (no indirection).
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub enum BuiltDeckPredictor {
    /// The Kalman estimate of the sensed ship motion, forecast to touchdown.
    Estimator(Box<estimator::Estimator>),
    /// The forecast from the ship model's true state.
    Oracle(oracle::Oracle),
    /// The filtered landing point with a lead.
    FilterLead(filter_lead::FilterLead),
    /// A user's own.
    Custom(Box<dyn DeckPredictor>),
}

/// Calls `$call` on the predictor inside, whichever it is.
macro_rules! each {
    ($self:expr, $p:ident => $call:expr) => {
        match $self {
            BuiltDeckPredictor::Estimator($p) => $call,
            BuiltDeckPredictor::Oracle($p) => $call,
            BuiltDeckPredictor::FilterLead($p) => $call,
            BuiltDeckPredictor::Custom($p) => $call,
        }
    };
}

impl BuiltDeckPredictor {
    /// The scenario's predictor (`control.flight_path.deck_motion_predictor`), for the
    /// ship model `ship` starting at `ship_state`.
    pub(crate) fn for_scenario(
        scenario: &Scenario,
        ship: &ShipMotion,
        ship_state: &ShipMotionState,
        streams: &RandomStreams,
    ) -> Result<Self, ParameterError> {
        let flight_path = &scenario.control.flight_path;
        // The forecasts reach the compensation window and the blend, plus the data link's
        // latency for the estimator.
        let horizon_s = flight_path.compensation_window_s + flight_path.compensation_blend_s;
        // The forecast's σ is worked out only where the guidance or the wave-off uses it.
        let wave_off = &scenario.control.wave_off;
        let uncertainty = flight_path.ramp_strike_probability_limit > 0.0
            || (wave_off.enabled
                && (wave_off.max_ramp_strike_probability > 0.0
                    || wave_off.max_hard_landing_probability > 0.0));
        // The σ is worked out once per frame of the flight computer and held over it.
        let frames_hz = scenario.control.flight_computer_rate_hz;
        // The path's response to the ramp's later updates only where the wave-off reads
        // it (its closed-loop ramp-strike model, with a ramp-aware anchor, which can ride
        // the ramp): from its window's opening, two frames early so that the value held
        // over the frame is fresh by then.
        // The anchor model also carries the landing point's updates (off the floor).
        let closed_loop = wave_off.ramp_strike_model.is_closed_loop();
        let follows_landing_point = wave_off.ramp_strike_model.follows_landing_point();
        let lift = lift_loop(scenario, ship.parameters());
        let followed_within_s =
            (uncertainty && wave_off.enabled && closed_loop && flight_path.ramp_aware).then(|| {
                let frame_s = frames_hz.map_or(0.0, |rate_hz| 1.0 / rate_hz);
                wave_off.window_start_time_to_go_s + FOLLOWED_VARIANCE_LEAD_FRAMES * frame_s
            });
        Ok(match flight_path.deck_motion_predictor {
            DeckPredictorKind::Oracle => Self::Oracle(
                oracle::Oracle::new(
                    ShipMotionPropagator::new(ship, horizon_s),
                    (flight_path.ramp_aware || scenario.control.wave_off.enabled).then(|| {
                        AnchorShaping::new(flight_path.anchor_filter_frequency_radps)
                            .with_uncertainty(uncertainty)
                            .with_followed_variance(followed_within_s, follows_landing_point, lift)
                    }),
                )
                .with_uncertainty_frames(frames_hz),
            ),
            DeckPredictorKind::Estimator => {
                let sensing = scenario.environment.ship_sensing;
                Self::Estimator(Box::new(
                    estimator::Estimator::new(
                        ShipMotionSensor::new(sensing, streams)?,
                        match sensing.estimator_start {
                            EstimatorStart::Converged => DeckMotionEstimator::converged(
                                ship,
                                &sensing,
                                ship_state,
                                &mut streams.stream(stream_names::SHIP_ESTIMATE_START),
                            ),
                            EstimatorStart::Cold => DeckMotionEstimator::new(ship, &sensing),
                        },
                        ShipMotionPropagator::new(ship, horizon_s + sensing.latency_s + 1.0),
                        flight_path.anchor_filter_frequency_radps,
                    )
                    .with_uncertainty(uncertainty)
                    .with_followed_variance(followed_within_s, follows_landing_point, lift)
                    .with_uncertainty_frames(frames_hz),
                ))
            }
            DeckPredictorKind::FilterLead => Self::FilterLead(filter_lead::FilterLead::new(
                DeckMotionFilter::new(flight_path.deck_filter_frequency_radps),
            )),
        })
    }

    /// Re-keys its random streams ([`DeckPredictor::reseed`]).
    pub(crate) fn reseed(&mut self, key: u64) {
        each!(self, p => p.reseed(key))
    }

    /// Names of the predictor's continuous states.
    pub fn state_names(&self) -> &'static [&'static str] {
        each!(self, p => p.state_names())
    }

    /// The Kalman filter, for the `estimator`.
    pub fn estimator(&self) -> Option<&DeckMotionEstimator> {
        each!(self, p => p.estimator())
    }

    /// The state at the start.
    pub(crate) fn initial_state(&self, view: &DeckView<'_>, state: &mut [f64]) {
        each!(self, p => p.initial_state(view, state))
    }

    /// Once per step, at its start: the predictor observes the ship.
    pub(crate) fn observe(&mut self, time_s: f64, view: &DeckView<'_>) {
        each!(self, p => p.observe(time_s, view))
    }

    /// The predictor's state rate, given the landing point's true height (m), which is
    /// worked out (`aim_height_m` called) only for a predictor that reads it.
    #[inline(always)]
    pub(crate) fn derivative(
        &self,
        state: &[f64],
        aim_height_m: impl FnOnce() -> f64,
        rate: &mut [f64],
    ) {
        if let Self::FilterLead(filter) = self {
            filter.derivative(state, aim_height_m(), rate);
        } else if let Self::Custom(custom) = self {
            custom.derivative(state, aim_height_m(), rate);
        }
    }

    /// The deck reference for the flight-path generator: the mean landing point and the
    /// predicted one (see each predictor), and the forecast of the ramp and the deck's
    /// rate where the predictor gives one. Called once per step.
    #[inline]
    pub(crate) fn deck_reference(
        &mut self,
        view: &DeckView<'_>,
        state: &[f64],
        flight_path: &FlightPathGenerator,
        hook: &HookTrack,
    ) -> DeckReference {
        let (pose, rate, deck) = (view.pose, view.rate, view.deck);
        // Ship level and at its mean height: the aim point sits 81 m aft of the pitch
        // centre at deck height (no trigonometry needed).
        let mean_aim = EarthPoint {
            x_m: pose.pitch_centre_x_m - deck.landing_point_aft_of_pitch_centre_m,
            y_m: pose.pitch_centre_y_m,
            h_m: deck.deck_height_m,
        };
        let mean_aim_velocity = EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps,
            y_mps: rate.pitch_centre_y_rate_mps,
            h_mps: 0.0,
        };
        let aim_x_m = mean_aim.x_m + flight_path.parameters().touchdown_correction_m;
        let time_to_go_s =
            flight_path.time_to_go_s(hook.x_m, hook.x_rate_mps, aim_x_m, mean_aim_velocity.x_mps);
        let query = DeckQuery {
            view,
            flight_path,
            hook,
            time_to_go_s,
            aim_x_m,
            mean_aim,
            mean_aim_velocity,
        };
        each!(self, p => p.deck_reference(&query, state))
    }
}

/// What the glide path asks a deck predictor at one step: where the hook is on its
/// approach to the deck, the deck's mean position, and the estimated time to touchdown.
#[derive(Debug, Clone, Copy)]
pub struct DeckQuery<'a> {
    /// The ship's motion now.
    pub view: &'a DeckView<'a>,
    /// The glide-path generator.
    pub flight_path: &'a FlightPathGenerator,
    /// Where the hook is.
    pub hook: &'a HookTrack,
    /// The estimated time to touchdown (s).
    pub time_to_go_s: f64,
    /// The aim point's x with the touchdown correction (m).
    pub aim_x_m: f64,
    /// The landing point with the ship level at its mean height.
    pub mean_aim: EarthPoint,
    /// Its velocity (the ship's forward speed; no vertical motion).
    pub mean_aim_velocity: EarthVelocity,
}

impl DeckQuery<'_> {
    /// A reference that anchors the path on `aim` moving at `aim_velocity`, with no
    /// forecast (so no ramp-aware raise and no wave-off), as the paper's predictors.
    pub fn unshaped(&self, aim: EarthPoint, aim_velocity: EarthVelocity) -> DeckReference {
        DeckReference {
            mean_aim: self.mean_aim,
            mean_aim_velocity: self.mean_aim_velocity,
            aim,
            aim_velocity,
            forecast: None,
            unfiltered_aim_h_m: None,
            aim_acceleration_mps2: 0.0,
        }
    }

    /// The reference from a forecast of `estimate` (`age_s` old) by `predictor`, the
    /// anchor ramp-aware and shaped by `shaping`, the forecast's σ held over each guidance
    /// frame by `hold`: the `estimator`'s design, and the
    /// `oracle`'s with the true state for the estimate. Inlined into the step as the code
    /// it replaced was: called, it cost 0.8 % more instructions per simulated second
    /// (callgrind, BENCHMARKS.md).
    #[inline(always)]
    pub(crate) fn shaped_reference(
        &self,
        predictor: &ShipMotionPropagator,
        estimate: &ShipMotionEstimate,
        age_s: f64,
        shaping: &mut AnchorShaping,
        hold: &mut UncertaintyHold,
    ) -> DeckReference {
        let (deck, hook) = (self.view.deck, self.hook);
        let parameters = self.flight_path.parameters();
        let closure = hook.x_rate_mps - self.mean_aim_velocity.x_mps;
        let forecast = forecast_deck(
            predictor,
            self.view.ship_model,
            estimate,
            age_s,
            self.time_to_go_s,
            closure,
            deck,
            shaping.uncertainty.then_some(Uncertainty {
                min_horizon_s: parameters.ramp_sigma_min_horizon_s,
                anchor_frequency_radps: parameters.anchor_filter_frequency_radps,
                followed_within_s: shaping.followed_within_s,
                follows_landing_point: shaping.follows_landing_point,
                lift: shaping.lift,
                now_s: hook.time_s,
                hold,
            }),
            self.view.roll.is_some(),
        );
        let forecast = match self.view.roll {
            Some(roll) => roll.add_to(
                forecast,
                hook.time_s,
                self.time_to_go_s,
                deck.ramp_aft_of_aim_point_m,
                closure,
            ),
            None => forecast,
        };
        let target = ramp_aware_anchor(parameters, self.flight_path, deck, &forecast);
        let descent = (parameters.ramp_aware && parameters.descend_after_ramp).then(|| {
            capped_raise_share(
                parameters,
                deck,
                self.aim_x_m - hook.x_m,
                closure,
                shaping.raise_m(),
            )
        });
        let shaped = shaping.step(target, forecast.landing_point_height_m, descent, hook.dt);
        DeckReference {
            mean_aim: self.mean_aim,
            mean_aim_velocity: self.mean_aim_velocity,
            aim: EarthPoint {
                x_m: self.mean_aim.x_m,
                y_m: self.mean_aim.y_m,
                h_m: shaped.height_m,
            },
            aim_velocity: EarthVelocity {
                x_mps: self.mean_aim_velocity.x_mps,
                y_mps: self.mean_aim_velocity.y_mps,
                h_mps: shaped.rate_mps,
            },
            forecast: Some(forecast),
            unfiltered_aim_h_m: Some(shaped.unfiltered_m),
            aim_acceleration_mps2: shaped.acceleration_mps2,
        }
    }
}

/// What [`forecast_deck`] needs to work out the forecast's uncertainty.
pub(crate) struct Uncertainty<'a> {
    /// h_min, the shortest horizon of the ramp's σ (s).
    pub min_horizon_s: f64,
    /// ω of the glide path's anchor filter (rad/s), for the variance the path follows.
    pub anchor_frequency_radps: f64,
    /// The time to go (s) from which the variance the path follows is worked out;
    /// `None`: never (0).
    pub followed_within_s: Option<f64>,
    /// Whether that includes the landing point's part, for a path off the ramp's floor
    /// (`ramp_strike_model = "closed_loop_anchor"`).
    pub follows_landing_point: bool,
    /// The direct-lift loop the hook follows the updates with, instead of the anchor
    /// filter (`ramp_strike_model = "closed_loop_lift"`).
    pub lift: Option<LiftLoop>,
    /// The time of the step (s).
    pub now_s: f64,
    /// The σ held over the guidance frame.
    pub hold: &'a mut UncertaintyHold,
}

/// The forecast of the deck for a hook `time_to_go_s` from touchdown closing at
/// `closure_mps`, from `estimate` whose time lies `age_s` in the past: the landing point
/// at touchdown, the ramp when the hook crosses it (`ramp_aft_of_aim_point_m` / closure
/// earlier); with `uncertainty`, also the σ of the ramp's height at the crossing (or
/// h_min ahead, if the crossing is nearer), of the landing point's climb rate at
/// touchdown and the path's response to the ramp's later updates
/// ([`ramp_update_response_m2`]), worked out when the step from `now` (s) starts a new
/// frame of `hold` and held otherwise (without, 0). With `series_trig` (the 3-D approach)
/// the ship's predicted pitch has its sine and cosine by [`series_sin_cos`] (within an
/// ulp of the library's, about a third of its cost); without, the library's.
#[allow(clippy::too_many_arguments)]
pub(crate) fn forecast_deck(
    predictor: &ShipMotionPropagator,
    ship: &ShipMotion,
    estimate: &ShipMotionEstimate,
    age_s: f64,
    time_to_go_s: f64,
    closure_mps: f64,
    deck: &DeckGeometry,
    uncertainty: Option<Uncertainty<'_>>,
    series_trig: bool,
) -> DeckForecast {
    let landing_arm_m = deck.landing_point_aft_of_pitch_centre_m;
    let ramp_arm_m = landing_arm_m + deck.ramp_aft_of_aim_point_m;
    let ramp_time_s = if closure_mps > 0.0 {
        (time_to_go_s - deck.ramp_aft_of_aim_point_m / closure_mps).max(0.0)
    } else {
        time_to_go_s
    };
    let (touchdown_lead_s, ramp_lead_s) = (age_s + time_to_go_s.max(0.0), age_s + ramp_time_s);
    let at_touchdown: ShipMotionForecast =
        predictor.forecast_mean(ship, estimate, touchdown_lead_s);
    let at_ramp = predictor.forecast_mean(ship, estimate, ramp_lead_s);
    let (
        ramp_height_sigma_m,
        landing_point_climb_rate_sigma_mps,
        ramp_update_response_m2,
        landing_point_update_response_m2,
    ) = match uncertainty {
        Some(uncertainty) => forecast_uncertainty(
            predictor,
            ship,
            estimate,
            uncertainty,
            (age_s, ramp_time_s, touchdown_lead_s),
            (ramp_arm_m, at_ramp.pitch_rad),
            (landing_arm_m, at_touchdown.pitch_rad),
        ),
        None => (0.0, 0.0, [0.0; 2], [0.0; 2]),
    };
    let trig = |pitch_rad: f64| {
        if series_trig {
            series_sin_cos(pitch_rad)
        } else {
            (pitch_rad.sin(), pitch_rad.cos())
        }
    };
    let (sin_ramp, cos_ramp) = trig(at_ramp.pitch_rad);
    let (sin_touchdown, cos_touchdown) = trig(at_touchdown.pitch_rad);
    DeckForecast {
        ramp_height_m: deck.deck_height_m
            + at_ramp.deck_point_height_at_sine_m(ramp_arm_m, sin_ramp),
        landing_point_climb_rate_mps: at_touchdown
            .deck_point_climb_rate_at_cosine_mps(landing_arm_m, cos_touchdown),
        landing_point_height_m: deck.deck_height_m
            + at_touchdown.deck_point_height_at_sine_m(landing_arm_m, sin_touchdown),
        pitch_rad: at_touchdown.pitch_rad,
        ramp_climb_rate_mps: at_ramp.deck_point_climb_rate_at_cosine_mps(ramp_arm_m, cos_ramp),
        ramp_height_sigma_m,
        landing_point_climb_rate_sigma_mps,
        ramp_update_response_m2,
        landing_point_update_response_m2,
        roll_rad: 0.0,
    }
}

/// [`forecast_deck`]'s uncertainty, worked out when the step from `now` starts a new
/// frame of the hold and held otherwise: the σ of the ramp's height at the crossing
/// (`ramp_time_s` ahead, or h_min if nearer), of the landing point's climb rate at
/// touchdown (`touchdown_lead_s`) and the path's response to the ramp's later updates
/// ([`ramp_update_response_m2`]; from the time to go `followed_within_s` on, else 0),
/// from `estimate` `age_s` old; the ramp and the landing point are (lever arm aft of the
/// pitch centre (m), predicted pitch (rad)).
#[inline]
fn forecast_uncertainty(
    predictor: &ShipMotionPropagator,
    ship: &ShipMotion,
    estimate: &ShipMotionEstimate,
    uncertainty: Uncertainty<'_>,
    (age_s, ramp_time_s, touchdown_lead_s): (f64, f64, f64),
    ramp: (f64, f64),
    landing_point: (f64, f64),
) -> (f64, f64, [f64; 2], [f64; 2]) {
    let Uncertainty {
        min_horizon_s,
        anchor_frequency_radps,
        followed_within_s,
        follows_landing_point,
        lift,
        now_s,
        hold,
    } = uncertainty;
    if hold.due(now_s) {
        // The time to go: the touchdown's lead less the estimate's age.
        let followed =
            followed_within_s.is_some_and(|within_s| touchdown_lead_s - age_s <= within_s);
        let ramp_sigma = |lead_s: f64| predictor.deck_point_sigma(ship, estimate, lead_s, ramp, 0);
        hold.sigmas = (
            ramp_sigma(age_s + ramp_time_s.max(min_horizon_s)),
            predictor.deck_point_sigma(ship, estimate, touchdown_lead_s, landing_point, 1),
            if followed {
                ramp_update_response_m2(
                    |tau_s| ramp_sigma(age_s + tau_s).powi(2),
                    ramp_time_s,
                    following_share(anchor_frequency_radps, lift),
                )
            } else {
                [0.0; 2]
            },
            if followed && follows_landing_point {
                // Forecast τ before the crossing, the touchdown is that much further off.
                let touchdown_after_s = touchdown_lead_s - age_s - ramp_time_s;
                landing_point_update_response_m2(
                    |tau_s| {
                        let (ramp_lead_s, landing_lead_s) =
                            (age_s + tau_s, age_s + tau_s + touchdown_after_s);
                        let landing_sigma = predictor.deck_point_sigma(
                            ship,
                            estimate,
                            landing_lead_s,
                            landing_point,
                            0,
                        );
                        [
                            predictor.deck_points_height_covariance(
                                ship,
                                estimate,
                                (ramp_lead_s, ramp),
                                (landing_lead_s, landing_point),
                            ),
                            landing_sigma * landing_sigma,
                        ]
                    },
                    ramp_time_s,
                    following_share(anchor_frequency_radps, lift),
                )
            } else {
                [0.0; 2]
            },
        );
    }
    hold.sigmas
}

/// The direct-lift loop the ramp-strike probability follows the hook with
/// (`ramp_strike_model = "closed_loop_lift"` in an approach flown with direct lift): the
/// law's, its close-in gain scheduled on the sea as the loop flies it, for the lift a
/// unit of C_L gives at the approach speed, q̄S/m with q̄ = ½ρV² (m/s²), in the sea of
/// `ship`; `None` otherwise.
pub(crate) fn lift_loop(scenario: &Scenario, ship: &ShipMotionParameters) -> Option<LiftLoop> {
    let law = &scenario.control.direct_lift;
    let lift_model = scenario.control.wave_off.ramp_strike_model == RampStrikeModel::ClosedLoopLift;
    if !lift_model || scenario.mission != Mission::Approach || !law.enabled {
        return None;
    }
    let landing_arm_m = scenario
        .environment
        .deck
        .landing_point_aft_of_pitch_centre_m;
    let aircraft = &scenario.aircraft.parameters;
    let dynamic_pressure_pa =
        0.5 * aircraft.air_density_kg_m3 * scenario.approach.airspeed_mps.powi(2);
    law.for_sea(ship.deck_point_height_rms_m(landing_arm_m))
        .lift_loop(dynamic_pressure_pa * aircraft.wing_area_m2 / aircraft.mass_kg)
}

/// How many guidance frames before the wave-off's window opens the forecast starts to
/// carry the path's response to the ramp's later updates, so that the value held over
/// the frame in which the window opens is that frame's (the time to go falls by about a
/// frame per frame).
const FOLLOWED_VARIANCE_LEAD_FRAMES: f64 = 2.0;

/// The number of intervals of [`ramp_update_response_m2`]'s quadrature.
const FOLLOWED_VARIANCE_INTERVALS: u32 = 8;

/// How a glide path anchored on the forecast ramp follows the forecast's updates still to
/// come before a crossing `ramp_time_s` ahead (m²; docs/model.md §9): [∫₀ᵀ g dσ²,
/// ∫₀ᵀ g² dσ²], `variance(τ)` the forecast's variance of the ramp's height at the
/// crossing when made τ before it (m²). The forecast's error is the sum of its updates
/// still to come, independent (a minimum-variance forecast's innovations), the one made
/// τ before the crossing of variance dσ²(τ); the anchor's critically damped filter at
/// `anchor_frequency_radps` ω has moved by g(τ) = 1 − (1 + ωτ)·e^(−ωτ) of it by the
/// crossing, and a path moving by w of its anchor by w·g, so the hook's clearance keeps
/// (1 − w·g)² of its variance: the path takes F = 2w·∫g dσ² − w²·∫g² dσ² out. By the
/// midpoint rule in g over [`FOLLOWED_VARIANCE_INTERVALS`] equal intervals of τ, σ²
/// taken at their ends (exact for a g constant over each); a variance that falls over an
/// interval adds nothing (no update has negative variance); zeros for a crossing now or
/// past.
pub(crate) fn ramp_update_response_m2(
    variance: impl Fn(f64) -> f64,
    ramp_time_s: f64,
    share: impl Fn(f64) -> f64,
) -> [f64; 2] {
    update_response(
        |tau_s| {
            let v = variance(tau_s);
            [v, v]
        },
        ramp_time_s,
        share,
        true,
    )
}

/// g(τ) = 1 − (1 + ωτ)·e^(−ωτ), the share of a step in its target that the anchor's
/// critically damped filter at `frequency_radps` ω has followed τ after it.
#[inline]
pub(crate) fn anchor_filter_share(frequency_radps: f64) -> impl Fn(f64) -> f64 {
    move |tau_s| {
        let x = frequency_radps * tau_s;
        1.0 - (1.0 + x) * (-x).exp()
    }
}

/// The share g(τ) of a step in its anchor that the hook has followed τ after it: the
/// anchor filter's (at `anchor_frequency_radps`), or with `lift` the direct-lift loop's,
/// which flies the unfiltered anchor (`ramp_strike_model = "closed_loop_lift"`).
#[inline]
fn following_share(anchor_frequency_radps: f64, lift: Option<LiftLoop>) -> impl Fn(f64) -> f64 {
    let filter = anchor_filter_share(anchor_frequency_radps);
    move |tau_s| match lift {
        Some(lift) => lift.step_share(tau_s),
        None => filter(tau_s),
    }
}

/// How a glide path anchored on the forecast landing point (off the ramp's floor) follows
/// the forecast's updates still to come before a crossing `ramp_time_s` ahead (m²;
/// docs/model.md §9): [∫₀ᵀ g dC, ∫₀ᵀ g² dσ_L²], C(τ) the covariance of the ramp's height
/// at the crossing and the landing point's at touchdown when both are forecast τ before
/// the crossing, σ_L²(τ) the landing point's variance then, g as in
/// [`ramp_update_response_m2`]. An update moves the path by w·g of the landing point's
/// part, so the clearance's variance changes by −(2w·g·dC − w²g²·dσ_L²): a path that
/// moves by w of its anchor takes F = 2w·∫g dC − w²·∫g² dσ_L² out of the ramp's variance,
/// which is negative (variance added) when the two are little correlated. The same
/// quadrature; a covariance may fall over an interval, a variance adds nothing there.
pub(crate) fn landing_point_update_response_m2(
    covariance_and_variance: impl Fn(f64) -> [f64; 2],
    ramp_time_s: f64,
    share: impl Fn(f64) -> f64,
) -> [f64; 2] {
    update_response(covariance_and_variance, ramp_time_s, share, false)
}

/// The quadrature of [`ramp_update_response_m2`]: [Σ g·Δa, Σ g²·Δb] over the intervals,
/// (a, b) = `values(τ)`, Δb at least 0, and Δa too when `a_is_variance`.
#[inline]
fn update_response(
    values: impl Fn(f64) -> [f64; 2],
    ramp_time_s: f64,
    share: impl Fn(f64) -> f64,
    a_is_variance: bool,
) -> [f64; 2] {
    if ramp_time_s <= 0.0 {
        return [0.0; 2];
    }
    let step_s = ramp_time_s / f64::from(FOLLOWED_VARIANCE_INTERVALS);
    let mut before = values(0.0);
    let mut moments = [0.0; 2];
    for j in 1..=FOLLOWED_VARIANCE_INTERVALS {
        let tau_s = f64::from(j) * step_s;
        let after = values(tau_s);
        let g = share(tau_s - 0.5 * step_s);
        let second = (after[1] - before[1]).max(0.0);
        let first = if a_is_variance {
            (after[0] - before[0]).max(0.0)
        } else {
            after[0] - before[0]
        };
        moments[0] += g * first;
        moments[1] += g * g * second;
        before = after;
    }
    moments
}

#[cfg(test)]
mod tests;
