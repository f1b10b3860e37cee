//! The guidance computer's step and the wave-off decision in the loop (docs/model.md
//! §5.7, §9): once per step the ship's sensed motion updates the deck-motion predictor,
//! which gives the deck reference; the decision logic of
//! [`crate::control::WaveOffParameters`] then reads the hook, the glide path and the deck
//! forecast. Once decided, [`super::wave_off_flight::WaveOffFlight`] says how the outer
//! loops fly the wave-off.

use super::closed_loop::ClosedLoop;
use super::commit::CommitPoint;
use super::deck_predictor::{DeckView, HookTrack};
use super::lateral::build::BuiltLateral;
use super::outer_loops::OuterLoops;
use crate::aircraft::AircraftState;
use crate::control::{
    DeckForecast, DeckReference, FlightPathGenerator, HardLandingModel, LateAbortInputs, LiftLoop,
    PathReference, WaveOffDecision, WaveOffInputs, WaveOffParameters,
};
use crate::environment::{DeckGeometry, ShipMotionState, ShipPose, ShipPoseRate};

impl ClosedLoop {
    /// The guidance computer at the start of a step from `t` (state `x`): the deck
    /// predictor observes the ship, and in an approach gives the deck reference held over
    /// the step, on which the wave-off supervisor decides (unless `waving_off` already):
    /// the reference and the decision, if one is taken now. The ship is its motion state,
    /// pose and pose rate at `t` and `x` ([`ClosedLoop::ship_pose`]).
    #[inline(always)]
    pub(crate) fn guidance_computer_step(
        &mut self,
        t: f64,
        x: &[f64],
        aircraft: &AircraftState,
        (ship_state, pose, rate): (&ShipMotionState, &ShipPose, &ShipPoseRate),
        dt: f64,
        waving_off: bool,
    ) -> (Option<DeckReference>, Option<WaveOffDecision>) {
        let view = DeckView {
            ship_model: &self.ship,
            ship_state,
            deck: &self.deck,
            pose,
            rate,
            roll: self.sensed_roll(),
        };
        self.deck_predictor.observe(t, &view);
        let OuterLoops::Approach { flight_path, .. } = &self.outer else {
            return (None, None);
        };
        let flight_path = *flight_path;
        let (sin_t, cos_t) = aircraft.theta_rad.sin_cos();
        let (hook_x_m, hook_h_m) = self.hook.position_trig(aircraft, sin_t, cos_t);
        let (hook_x_rate_mps, hook_climb_rate_mps) =
            self.hook.velocity_trig(aircraft, sin_t, cos_t);
        let track = HookTrack {
            time_s: t,
            x_m: hook_x_m,
            x_rate_mps: hook_x_rate_mps,
            dt,
        };
        let reference = self.deck_predictor.deck_reference(
            &view,
            self.layout.deck_predictor.of(x),
            &flight_path,
            &track,
        );
        if waving_off {
            note_wave_off(&mut self.outer, t);
            return (Some(reference), None);
        }
        let hook = HookKinematics {
            x_m: hook_x_m,
            h_m: hook_h_m,
            x_rate_mps: hook_x_rate_mps,
            climb_rate_mps: hook_climb_rate_mps,
        };
        // The ramp-strike limits of this sea (the ordinary ones but in a heavy sea).
        let wave_off = &self.wave_off_in_sea;
        let supervisor = (wave_off, self.ramp_strike_lift);
        let inputs = wave_off_inputs(supervisor, &flight_path, &self.deck, &reference, &hook);
        let mut decision = inputs.and_then(|inputs| {
            wave_off
                .decide_foul_deck(&inputs)
                .or_else(|| wave_off.decide(&inputs))
        });
        if decision.is_none() {
            let (commit, lateral) = (&mut self.commit, &self.lateral);
            decision = inputs.and_then(|inputs| commit_point(wave_off, commit, lateral, &inputs));
        }
        if decision.is_some() {
            note_wave_off(&mut self.outer, t);
        }
        if decision.is_none() && wave_off.late_abort_enabled() {
            let ramp_x_m = reference.mean_aim.x_m - self.deck.ramp_aft_of_aim_point_m;
            let before_ramp = hook_x_m < ramp_x_m;
            let late = inputs
                .and_then(|inputs| wave_off.late_abort(&late_abort_inputs(&inputs, before_ramp)));
            if let OuterLoops::Approach { late_abort, .. } = &mut self.outer {
                late_abort.step(t, dt, late);
            }
        }
        (Some(reference), decision)
    }
}

/// At the commit point (the first step with the time to go at or below
/// `decision_time_to_go_s`, no wave-off decided): the commit gate's decision on what the
/// forecast gives now, or, to commit, that forecast recorded in `commit`
/// (`simulation/commit.rs`; a 3-D approach's `lateral` part adds its off-centre
/// probability later). `None` elsewhere.
fn commit_point(
    wave_off: &WaveOffParameters,
    commit: &mut CommitPoint,
    lateral: &BuiltLateral,
    inputs: &WaveOffInputs,
) -> Option<WaveOffDecision> {
    if commit.reached() || inputs.time_to_go_s > wave_off.decision_time_to_go_s {
        return None;
    }
    let forecast = wave_off.commit_forecast(inputs);
    let decision = wave_off.decide_commit(&forecast);
    if decision.is_none() {
        let three_d = matches!(lateral, BuiltLateral::ThreeDimensional(_));
        commit.record(forecast, three_d);
    }
    decision
}

/// Notes in the wave-off's flight that it was decided at `t` (s), unless noted
/// already: its take-over blends from then (`WaveOffFlight::share`).
fn note_wave_off(outer: &mut OuterLoops, t: f64) {
    if let OuterLoops::Approach {
        wave_off: Some(flight),
        ..
    } = outer
    {
        flight.decided_at_s.get_or_insert(t);
    }
}

/// The late abort's inputs from the wave-off's: the same closed-loop predicted clearance,
/// its σ and the same predicted touchdown sink rate relative to the deck.
fn late_abort_inputs(inputs: &WaveOffInputs, before_ramp: bool) -> LateAbortInputs {
    let forecast = &inputs.forecast;
    LateAbortInputs {
        time_to_go_s: inputs.time_to_go_s,
        before_ramp,
        predicted_ramp_clearance_m: inputs.closed_loop_ramp_clearance_m(),
        ramp_clearance_sigma_m: inputs.ramp_clearance_sigma_m,
        predicted_touchdown_sink_rate_mps: -inputs.hook_climb_rate_mps
            + forecast.landing_point_climb_rate_mps,
    }
}

/// The hook's position and velocity (earth axes).
#[derive(Debug, Clone, Copy)]
pub(crate) struct HookKinematics {
    pub x_m: f64,
    pub h_m: f64,
    pub x_rate_mps: f64,
    pub climb_rate_mps: f64,
}

/// What the wave-off decision looks at for a hook at `hook` on the path of
/// `flight_path` over the deck `reference`; `None` without a wave-off or a forecast
/// (predictors without one never wave off). Inlined into the step, once a step, as it
/// was before the closed loop's terms made it too large for the compiler's own choice.
#[inline(always)]
fn wave_off_inputs(
    (wave_off, lift): (&WaveOffParameters, Option<LiftLoop>),
    flight_path: &FlightPathGenerator,
    deck: &DeckGeometry,
    reference: &DeckReference,
    hook: &HookKinematics,
) -> Option<WaveOffInputs> {
    if !wave_off.enabled {
        return None;
    }
    let forecast = reference.forecast?;
    let path = flight_path.reference(hook.x_m, hook.x_rate_mps, reference);
    // The path is a straight line: at the ramp (mean position) it stands
    // (ramp x − hook x)·tan Γ below its height over the hook.
    let ramp_x_m = reference.mean_aim.x_m - deck.ramp_aft_of_aim_point_m;
    // From the window's opening on (and past the commit point, where it is recorded).
    let in_window = path.time_to_go_s <= wave_off.window_start_time_to_go_s;
    let (gain_m, ramp_clearance_sigma_m) = closed_loop_ramp_terms(
        (wave_off, lift),
        flight_path,
        deck,
        reference,
        hook,
        (&path, &forecast, in_window),
    );
    let closed_loop_hook_sink_rate_mps =
        match (wave_off.hard_landing_model, reference.unfiltered_aim_h_m) {
            (HardLandingModel::ClosedLoop, Some(target_m)) if in_window => {
                closed_loop_hook_sink_rate_mps(flight_path, reference, hook, &path, target_m)
            }
            _ => 0.0,
        };
    Some(WaveOffInputs {
        time_to_go_s: path.time_to_go_s,
        glide_path_error_m: path.height_m - hook.h_m,
        glide_path_error_rate_mps: path.climb_rate_mps - hook.climb_rate_mps,
        path_height_at_ramp_m: path.height_m - (ramp_x_m - hook.x_m) * flight_path.tan_slope(),
        hook_climb_rate_mps: hook.climb_rate_mps,
        mean_landing_point_height_m: reference.mean_aim.h_m,
        ramp_clearance_sigma_m,
        ramp_clearance_gain_m: gain_m,
        closed_loop_hook_sink_rate_mps,
        forecast,
    })
}

/// The closed-loop ramp-strike probability's terms (docs/model.md §9): how much the
/// clearance gains before the crossing over the path held (m) and σ_c′ (m). The path the
/// guidance flies until the crossing: its anchor filter goes on towards the anchor it is
/// given now, and, while that anchor rides the forecast ramp, it follows the ramp's
/// forecast as it firms up; off the ramp's floor, in the anchor models, the landing
/// point's. With `lift` (`closed_loop_lift`) the hook flies to the path on the unfiltered
/// anchor by direct lift, which leaves the error its loop's free response gives at the
/// crossing, and follows the updates by that loop's step response (the forecast's
/// moments carry it). Only the ramp-strike probability reads them, from the window's
/// opening on (`in_window`), and only in the closed-loop models (`ramp_strike_model`;
/// with `forecast`, c and σ_c as they are).
#[inline(always)]
fn closed_loop_ramp_terms(
    (wave_off, lift): (&WaveOffParameters, Option<LiftLoop>),
    flight_path: &FlightPathGenerator,
    deck: &DeckGeometry,
    reference: &DeckReference,
    hook: &HookKinematics,
    (path, forecast, in_window): (&PathReference, &DeckForecast, bool),
) -> (f64, f64) {
    let parameters = flight_path.parameters();
    let closed_loop = wave_off.ramp_strike_model.is_closed_loop();
    let base_sigma = |weight| {
        super::deck_predictor::closed_loop_ramp_clearance_sigma_m(parameters, forecast, weight)
    };
    let Some(target_m) = reference
        .unfiltered_aim_h_m
        .filter(|_| closed_loop && in_window)
    else {
        return (0.0, base_sigma(0.0));
    };
    let closure_mps = hook.x_rate_mps - reference.mean_aim_velocity.x_mps;
    let ramp_time_s = if closure_mps > 0.0 {
        (path.time_to_go_s - deck.ramp_aft_of_aim_point_m / closure_mps).max(0.0)
    } else {
        path.time_to_go_s
    };
    let weight = path.compensation_weight;
    let gain_m = match lift {
        Some(lift) => {
            // The hook's error to the path on the unfiltered anchor, and its rate.
            let error_m = path.height_m - hook.h_m + weight * (target_m - reference.aim.h_m);
            let rate_mps = path.climb_rate_mps - hook.climb_rate_mps;
            let left_m = lift.free_response(error_m, rate_mps, ramp_time_s);
            error_m - left_m
        }
        None => {
            let (moved_m, _) = super::deck_predictor::anchor_free_response(
                reference.aim.h_m,
                reference.aim_velocity.h_mps,
                target_m,
                parameters.anchor_filter_frequency_radps,
                ramp_time_s,
            );
            weight * moved_m
        }
    };
    let sigma_m = if target_m > forecast.landing_point_height_m {
        base_sigma(weight)
    } else if wave_off.ramp_strike_model.follows_landing_point() {
        super::deck_predictor::landing_point_following_ramp_clearance_sigma_m(
            parameters, forecast, weight,
        )
    } else {
        base_sigma(0.0)
    };
    (gain_m, sigma_m)
}

/// The hook's sink rate at touchdown as the guidance flies it (m/s, down;
/// docs/model.md §9): the path descends at the closure times tan Γ and moves with
/// w of its anchor, whose critically damped filter goes on towards the anchor it is
/// given now (`target_m`); at touchdown, `path.time_to_go_s` ahead, the hook sinks at
/// closure·tan Γ − w·ȧ(T).
#[inline(always)]
fn closed_loop_hook_sink_rate_mps(
    flight_path: &FlightPathGenerator,
    reference: &DeckReference,
    hook: &HookKinematics,
    path: &crate::control::PathReference,
    target_m: f64,
) -> f64 {
    let closure_mps = hook.x_rate_mps - reference.mean_aim_velocity.x_mps;
    let (_, anchor_rate_mps) = super::deck_predictor::anchor_free_response(
        reference.aim.h_m,
        reference.aim_velocity.h_mps,
        target_m,
        flight_path.parameters().anchor_filter_frequency_radps,
        path.time_to_go_s,
    );
    closure_mps * flight_path.tan_slope() - path.compensation_weight * anchor_rate_mps
}
