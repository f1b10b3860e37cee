//! The deck-motion predictor block: where the glide path expects the landing point to be
//! (docs/model.md §5.7, deck-motion compensation; see [`crate::control::FlightPathGenerator`]).
//!
//! - `estimator` (default): the ship's sensed motion (docs/model.md §3.5) feeds a Kalman
//!   filter ([`DeckMotionEstimator`]); the landing point and the ramp are forecast from
//!   its estimate at the hook's touchdown and ramp-crossing times, the data link's
//!   latency added to the horizon. The anchor passes through a critically damped filter
//!   so that each 50-Hz update moves the path smoothly.
//! - `oracle`: the same forecast and the same anchor from the ship model's *true* state
//!   (studies only: the two differ only in what they know).
//! - `filter_lead`: a low-pass filter on the landing point's height with a lead.
//!
//! With `ramp_aware` the predicted anchor is raised, where needed, so that the path
//! crosses the predicted ramp `ramp_clearance_margin_m` above it.

use super::anchor_shaping::AnchorShaping;
use crate::control::{
    DeckForecast, DeckMotionFilter, DeckReference, FlightPathGenerator, FlightPathParameters,
};
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, ShipMotion, ShipMotionEstimate, ShipMotionForecast,
    ShipMotionPredictor, ShipMotionState, ShipPose, ShipPoseRate,
};
use crate::estimation::DeckMotionEstimator;
use crate::sensors::ShipMotionSensor;

/// Names of the `filter_lead` predictor's states.
const FILTER_STATE_NAMES: &[&str] = &["landing_point_height_m", "landing_point_climb_rate_mps"];

/// The `estimator` predictor's parts: the ship's sensing, the Kalman filter, the
/// forecast and the smoothing of the anchor (all discrete: updated once per step).
#[derive(Debug, Clone)]
pub struct EstimatorPredictor {
    sensor: ShipMotionSensor,
    estimator: DeckMotionEstimator,
    predictor: ShipMotionPredictor,
    estimate: ShipMotionEstimate,
    shaping: AnchorShaping,
}

impl EstimatorPredictor {
    /// The predictor with this sensing and filter, its anchor smoothed at
    /// `anchor_frequency_radps`.
    pub fn new(
        sensor: ShipMotionSensor,
        estimator: DeckMotionEstimator,
        predictor: ShipMotionPredictor,
        anchor_frequency_radps: f64,
    ) -> Self {
        let estimate = estimator.estimate();
        Self {
            sensor,
            estimator,
            predictor,
            estimate,
            shaping: AnchorShaping::new(anchor_frequency_radps),
        }
    }

    /// The Kalman filter.
    pub fn estimator(&self) -> &DeckMotionEstimator {
        &self.estimator
    }
}

/// How the landing point is predicted for the glide path, with the predictor's own state.
#[derive(Debug, Clone)]
pub enum DeckPredictor {
    /// The Kalman estimate of the sensed ship motion, forecast to touchdown.
    Estimator(Box<EstimatorPredictor>),
    /// The minimum-variance prediction at the estimated touchdown time from the ship
    /// model's *true* state: an oracle. With `shaping` it also forecasts the ramp and the
    /// deck's rate (for ramp-aware guidance and the wave-off decision) and shapes the
    /// anchor as the estimator does; without, it is the paper's (the prediction itself,
    /// with rate zero).
    Oracle {
        /// The tabulated transitions.
        predictor: ShipMotionPredictor,
        /// The estimator's anchor shaping, or `None` for the paper's oracle.
        shaping: Option<AnchorShaping>,
    },
    /// A critically damped low-pass filter on the landing point's height (two states)
    /// with a linear lead.
    FilterLead(DeckMotionFilter),
}

/// The ship's motion at one instant, as the predictor reads it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct DeckView<'a> {
    pub ship_model: &'a ShipMotion,
    pub ship_state: &'a ShipMotionState,
    pub deck: &'a DeckGeometry,
    pub pose: &'a ShipPose,
    pub rate: &'a ShipPoseRate,
}

/// Where the hook is, for the predictor.
#[derive(Debug, Clone, Copy)]
pub(crate) struct HookTrack {
    pub time_s: f64,
    pub x_m: f64,
    pub x_rate_mps: f64,
    /// The integration step (s): the smoothed anchor moves once per step.
    pub dt: f64,
}

impl DeckPredictor {
    /// Names of the predictor's continuous states.
    pub fn state_names(&self) -> &'static [&'static str] {
        match self {
            Self::Estimator(_) | Self::Oracle { .. } => &[],
            Self::FilterLead(_) => FILTER_STATE_NAMES,
        }
    }

    /// The Kalman filter, for the `estimator`.
    pub fn estimator(&self) -> Option<&DeckMotionEstimator> {
        match self {
            Self::Estimator(block) => Some(block.estimator()),
            _ => None,
        }
    }

    /// The state at the start: the filter on the current landing point.
    pub(crate) fn initial_state(&self, view: &DeckView<'_>, state: &mut [f64]) {
        if let Self::FilterLead(_) = self {
            state[0] = view.deck.aim_point(view.pose).h_m;
            state[1] = view
                .deck
                .velocity_along_deck(view.pose, view.rate, 0.0)
                .h_mps;
        }
    }

    /// Once per step, at its start: the ship's inertial navigation samples the true
    /// motion and the measurements that have arrived over the data link update the
    /// Kalman filter (`estimator` only).
    pub(crate) fn observe(&mut self, time_s: f64, view: &DeckView<'_>) {
        if let Self::Estimator(block) = self {
            let truth = view.ship_model.outputs(view.ship_state);
            block.sensor.sample(time_s, &truth);
            let mut updated = false;
            while let Some(measurement) = block.sensor.receive(time_s) {
                block.estimator.update(&measurement);
                updated = true;
            }
            if updated {
                block.estimate = block.estimator.estimate();
            }
        }
    }

    /// The predictor's state rate, given the landing point's true height (m).
    #[inline(always)]
    pub(crate) fn derivative(&self, state: &[f64], aim_height_m: f64, rate: &mut [f64]) {
        if let Self::FilterLead(filter) = self {
            let d = filter.derivative([state[0], state[1]], aim_height_m);
            rate[0] = d[0];
            rate[1] = d[1];
        }
    }

    /// The deck reference for the flight-path generator: the mean landing point and the
    /// predicted moving one (the forecast at the touchdown time, raised above the ramp
    /// when ramp-aware and shaped by [`AnchorShaping`] for the estimator and the realistic
    /// oracle; the paper's oracle's prediction with rate zero; or the filtered height and
    /// rate), and the forecast of the ramp and the deck's rate. Called once per step (the
    /// shaped anchor moves by `hook.dt`).
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
            h_m: deck.deck_height_m,
        };
        let mean_aim_velocity = EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps,
            h_mps: 0.0,
        };
        let aim_x_m = mean_aim.x_m + flight_path.parameters().touchdown_correction_m;
        let time_to_go_s =
            flight_path.time_to_go_s(hook.x_m, hook.x_rate_mps, aim_x_m, mean_aim_velocity.x_mps);
        let unshaped = |aim, aim_velocity| DeckReference {
            mean_aim,
            mean_aim_velocity,
            aim,
            aim_velocity,
            forecast: None,
            unfiltered_aim_h_m: None,
            aim_acceleration_mps2: 0.0,
        };
        let approach = ApproachGeometry {
            view,
            flight_path,
            hook,
            time_to_go_s,
            aim_x_m,
            mean_aim,
            mean_aim_velocity,
        };
        match self {
            Self::Oracle {
                predictor,
                shaping: None,
            } => {
                let predicted = predictor.predict(view.ship_model, view.ship_state, time_to_go_s);
                let predicted_pose = ShipPose {
                    heave_m: predicted.heave_m,
                    pitch_rad: predicted.pitch_rad,
                    ..*pose
                };
                unshaped(deck.aim_point(&predicted_pose), mean_aim_velocity)
            }
            Self::Oracle {
                predictor,
                shaping: Some(shaping),
            } => {
                let truth = ShipMotionEstimate {
                    mean: *view.ship_state,
                    ..ShipMotionEstimate::default()
                };
                approach.shaped_reference(predictor, &truth, 0.0, shaping)
            }
            Self::Estimator(block) => {
                let age_s = hook.time_s - block.estimator.time_s();
                approach.shaped_reference(
                    &block.predictor,
                    &block.estimate,
                    age_s,
                    &mut block.shaping,
                )
            }
            Self::FilterLead(_) => unshaped(
                EarthPoint {
                    x_m: deck.aim_point(pose).x_m,
                    h_m: state[0],
                },
                EarthVelocity {
                    x_mps: deck.velocity_along_deck(pose, rate, 0.0).x_mps,
                    h_mps: state[1],
                },
            ),
        }
    }
}

/// Where the hook is on its approach to the deck, for one step's reference.
struct ApproachGeometry<'a> {
    view: &'a DeckView<'a>,
    flight_path: &'a FlightPathGenerator,
    hook: &'a HookTrack,
    time_to_go_s: f64,
    /// The aim point's x with the touchdown correction (m).
    aim_x_m: f64,
    mean_aim: EarthPoint,
    mean_aim_velocity: EarthVelocity,
}

impl ApproachGeometry<'_> {
    /// The reference from a forecast of `estimate` (`age_s` old) by `predictor`, the
    /// anchor ramp-aware and shaped by `shaping`: the `estimator`'s design, and the
    /// `oracle`'s with the true state for the estimate. Inlined into the step as the code
    /// it replaced was: called, it cost 0.8 % more instructions per simulated second
    /// (callgrind, BENCHMARKS.md).
    #[inline(always)]
    fn shaped_reference(
        &self,
        predictor: &ShipMotionPredictor,
        estimate: &ShipMotionEstimate,
        age_s: f64,
        shaping: &mut AnchorShaping,
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
        );
        let target = ramp_aware_anchor(parameters, self.flight_path, deck, &forecast);
        let descent = (parameters.ramp_aware && parameters.descend_after_ramp)
            .then(|| raise_share(parameters, deck, self.aim_x_m - hook.x_m, closure));
        let shaped = shaping.step(target, forecast.landing_point_height_m, descent, hook.dt);
        DeckReference {
            mean_aim: self.mean_aim,
            mean_aim_velocity: self.mean_aim_velocity,
            aim: EarthPoint {
                x_m: self.mean_aim.x_m,
                h_m: shaped.height_m,
            },
            aim_velocity: EarthVelocity {
                x_mps: self.mean_aim_velocity.x_mps,
                h_mps: shaped.rate_mps,
            },
            forecast: Some(forecast),
            unfiltered_aim_h_m: Some(shaped.unfiltered_m),
            aim_acceleration_mps2: shaped.acceleration_mps2,
        }
    }
}

/// The forecast of the deck for a hook `time_to_go_s` from touchdown closing at
/// `closure_mps`, from `estimate` whose time lies `age_s` in the past: the landing point
/// at touchdown, the ramp when the hook crosses it (`ramp_aft_of_aim_point_m` / closure
/// earlier).
fn forecast_deck(
    predictor: &ShipMotionPredictor,
    ship: &ShipMotion,
    estimate: &ShipMotionEstimate,
    age_s: f64,
    time_to_go_s: f64,
    closure_mps: f64,
    deck: &DeckGeometry,
) -> DeckForecast {
    let landing_arm_m = deck.landing_point_aft_of_pitch_centre_m;
    let ramp_arm_m = landing_arm_m + deck.ramp_aft_of_aim_point_m;
    let ramp_time_s = if closure_mps > 0.0 {
        (time_to_go_s - deck.ramp_aft_of_aim_point_m / closure_mps).max(0.0)
    } else {
        time_to_go_s
    };
    let at_touchdown: ShipMotionForecast =
        predictor.forecast_mean(ship, estimate, age_s + time_to_go_s.max(0.0));
    let at_ramp = predictor.forecast_mean(ship, estimate, age_s + ramp_time_s);
    DeckForecast {
        ramp_height_m: deck.deck_height_m + at_ramp.deck_point_height_m(ramp_arm_m),
        landing_point_climb_rate_mps: at_touchdown.deck_point_climb_rate_mps(landing_arm_m),
        landing_point_height_m: deck.deck_height_m
            + at_touchdown.deck_point_height_m(landing_arm_m),
        pitch_rad: at_touchdown.pitch_rad,
    }
}

/// The anchor height: the forecast landing point, raised where the ramp-aware path needs
/// it so that the path crosses the predicted ramp `ramp_clearance_margin_m` above it.
/// The path passes the ramp (ramp_aft_of_aim_point + touchdown correction)·tan Γ above
/// its anchor.
fn ramp_aware_anchor(
    parameters: &FlightPathParameters,
    flight_path: &FlightPathGenerator,
    deck: &DeckGeometry,
    forecast: &DeckForecast,
) -> f64 {
    if !parameters.ramp_aware {
        return forecast.landing_point_height_m;
    }
    let rise_to_ramp_m = (deck.ramp_aft_of_aim_point_m + parameters.touchdown_correction_m)
        * flight_path.tan_slope();
    let floor_m = forecast.ramp_height_m + parameters.ramp_clearance_margin_m - rise_to_ramp_m;
    forecast.landing_point_height_m.max(floor_m)
}

/// The share of the ramp-aware raise the path keeps for a hook `range_m` before the
/// aim point, closing at `closure_mps`, and its rate (1/s). With `descend_after_ramp`
/// the path keeps all of it up to the ramp and sheds it linearly from the ramp to the
/// aim point: it crosses the ramp with the margin and still reaches the predicted landing
/// point, on a steeper last segment, instead of landing raise/tan Γ long. Without, it
/// keeps all of it.
fn raise_share(
    parameters: &FlightPathParameters,
    deck: &DeckGeometry,
    range_m: f64,
    closure_mps: f64,
) -> (f64, f64) {
    let ramp_range_m = deck.ramp_aft_of_aim_point_m + parameters.touchdown_correction_m;
    if !parameters.descend_after_ramp || range_m >= ramp_range_m || ramp_range_m <= 0.0 {
        (1.0, 0.0)
    } else if range_m <= 0.0 {
        (0.0, 0.0)
    } else {
        (range_m / ramp_range_m, -closure_mps / ramp_range_m)
    }
}

#[cfg(test)]
#[path = "deck_prediction_tests.rs"]
mod tests;
