//! The loops above the pitch law, one variant per kind of run (docs/model.md §5): a pitch
//! step, a climb-rate program through the sink-rate loop, or the full approach cascade
//! flight path → guidance → sink rate.

use super::alpha_floor::AlphaFloor;
use super::outcome::decision_words;
use super::outer_loop_signals::{OuterLoopInputs, OuterLoopOutputs};
use super::taps::{LoopBreak, Taps};
pub use super::wave_off_flight::WaveOffFlight;
use crate::control::pitch::command_shaping::JerkLimitedStep;
use crate::control::{
    CommandRamp, DeckReference, FlightPathGenerator, LoopController, PathReference, WaveOffDecision,
};
use crate::environment::Wind;

/// What produces the pitch command θ_ref.
// One per simulation, read every step: the approach's loops stay inline (no indirection).
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone, PartialEq)]
pub enum OuterLoops {
    /// θ_ref steps by `step_rad` at `step_time_s` from trim, or follows `shaped` from
    /// then, with its rate and acceleration fed forward; no outer loop.
    PitchStep {
        /// Step size (rad).
        step_rad: f64,
        /// Time of the step (s).
        step_time_s: f64,
        /// The jerk-limited trajectory flown instead of the step, if any.
        shaped: Option<JerkLimitedStep>,
    },
    /// A climb-rate command ramped in by `ramp` to `climb_rate_mps`, followed by the
    /// sink-rate loop, with the pitch feed-forward moving from trim to
    /// `theta_feedforward_rad` alike; no guidance.
    ClimbRate {
        /// Commanded climb rate after the ramp (m/s, negative descending).
        climb_rate_mps: f64,
        /// How the command comes in.
        ramp: CommandRamp,
        /// Trim pitch of the commanded descent (rad).
        theta_feedforward_rad: f64,
        /// The sink-rate loop.
        sink_rate: LoopController,
    },
    /// The glide path, guidance and the sink-rate loop down to the deck.
    Approach {
        /// The glide-path generator.
        flight_path: FlightPathGenerator,
        /// How a wave-off is flown; `None` without wave-offs.
        wave_off: Option<WaveOffFlight>,
        /// The late abort after the commit point (docs/landing-design.md), updated by the
        /// guidance computer once per step.
        late_abort: LateAbort,
        /// Guidance: height error → climb-rate command.
        guidance: LoopController,
        /// The sink-rate loop: climb-rate error → pitch command.
        sink_rate: LoopController,
        /// The angle-of-attack protection on the pitch command; `None` without it.
        alpha_floor: Option<AlphaFloor>,
    },
}

/// A pitch step's command from trim: the step `step_rad` (rad) from `step_time_s` (s),
/// or the `shaped` trajectory from then, its rate and acceleration fed forward.
#[inline(always)]
fn pitch_step_outputs(
    step_rad: f64,
    step_time_s: f64,
    shaped: Option<&JerkLimitedStep>,
    inputs: &OuterLoopInputs,
) -> OuterLoopOutputs {
    let trim_theta = inputs.theta_trim_rad;
    match shaped {
        None => {
            let step = if inputs.time_s >= step_time_s {
                step_rad
            } else {
                0.0
            };
            OuterLoopOutputs::pitch_only(trim_theta + step, 0.0, 0.0)
        }
        Some(trajectory) => {
            let reference = trajectory.reference(inputs.time_s - step_time_s);
            OuterLoopOutputs::pitch_only(
                trim_theta + reference.theta_rad,
                reference.rate_radps,
                reference.acceleration_radps2,
            )
        }
    }
}

/// The approach's climb-rate command (m/s) at the hook's `height_error` (m) to `path`:
/// the path's climb rate plus the guidance's output, or, while a wave-off is flown,
/// `flight`'s climb blended in over it; through the taps.
#[inline(always)]
fn approach_climb_rate_command<T: Taps>(
    path: &PathReference,
    height_error: f64,
    guidance: &LoopController,
    flight: Option<WaveOffFlight>,
    inputs: &OuterLoopInputs,
    taps: &T,
) -> f64 {
    let height_error_rate = path.climb_rate_mps - inputs.hook_climb_rate_mps;
    let approach = || {
        path.climb_rate_mps
            + guidance.output(
                height_error,
                inputs.guidance_integral_m_s,
                height_error_rate,
            )
    };
    taps.tap(
        LoopBreak::ClimbRateCommand,
        match flight {
            Some(flight) => flight.climb_rate_command(inputs.time_s, approach),
            None => approach(),
        },
    )
}

/// The approach's pitch command `theta` (rad) raised by the floor of a wave-off flown
/// (`flight`) and by the angle-of-attack floor, and whether either raised it.
#[inline(always)]
fn floored_pitch(
    theta: f64,
    flight: Option<WaveOffFlight>,
    alpha_floor: &Option<AlphaFloor>,
    inputs: &OuterLoopInputs,
    deck: &DeckReference,
) -> (f64, bool) {
    let (theta, wave_off_floored) = match flight {
        Some(flight) => flight.floored_pitch(theta, inputs, deck),
        None => (theta, false),
    };
    match alpha_floor {
        Some(alpha_floor) => {
            let (theta, floored) = alpha_floor.floored_pitch(theta, inputs);
            (theta, wave_off_floored | floored)
        }
        None => (theta, wave_off_floored),
    }
}

/// The late abort (a staged decision after the wave-off's commit point,
/// docs/landing-design.md): its share of the direct-lift (and thrust) command, moved
/// towards 1 while engaged and back to 0 when released at `rate_per_s`, once per step,
/// so that the command never steps; and the first decision that engaged it.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateAbort {
    /// The share of full up direct lift in the command (–), 0 to 1.
    pub share: f64,
    /// Whether a criterion holds it engaged now.
    pub engaged: bool,
    /// Whether it blends the thrust command to full thrust too.
    pub full_thrust: bool,
    /// The rate at which the share moves (1/s).
    pub rate_per_s: f64,
    /// When it first engaged (s), and why.
    pub first: Option<(f64, WaveOffDecision)>,
}

impl LateAbort {
    /// A late abort that moves its share at `rate_per_s` (1/s), with full thrust if
    /// `full_thrust`.
    pub fn new(rate_per_s: f64, full_thrust: bool) -> Self {
        Self {
            rate_per_s,
            full_thrust,
            ..Self::default()
        }
    }

    /// One step of `dt` (s) at `time_s`: engaged while a criterion calls it, by
    /// `decision` (the first one is kept), released when none does (holding it to the
    /// ramp once engaged gave back more boardings for the same ramp strikes,
    /// docs/landing-design.md); the share moves towards its target by at most
    /// `rate_per_s`·dt.
    pub fn step(&mut self, time_s: f64, dt: f64, decision: Option<WaveOffDecision>) {
        self.engaged = decision.is_some();
        if let (None, Some(decision)) = (self.first, decision) {
            self.first = Some((time_s, decision));
        }
        let target = if self.engaged { 1.0 } else { 0.0 };
        let most = self.rate_per_s * dt;
        self.share += (target - self.share).clamp(-most, most);
    }

    /// Its share of full thrust (–): the share when it blends the thrust in, else 0.
    #[inline]
    pub fn thrust_share(&self) -> f64 {
        if self.full_thrust {
            self.share
        } else {
            0.0
        }
    }

    /// The first decision in words, as a run's reason gives a wave-off's: "late abort at
    /// t = 23.10 s on ramp_strike_probability: probability of a ramp strike (%) 7.52
    /// against the limit 5.00"; `None` if it never engaged.
    pub fn description(&self) -> Option<String> {
        self.first
            .map(|(time_s, decision)| decision_words("late abort", time_s, &decision))
    }
}

impl OuterLoops {
    /// The pitch command and what led to it; `deck` is the held deck reference of an
    /// approach.
    #[inline(always)]
    pub(crate) fn outputs<T: Taps>(
        &self,
        inputs: &OuterLoopInputs,
        deck: Option<&DeckReference>,
        wave_off: bool,
        taps: &T,
    ) -> OuterLoopOutputs {
        let trim_theta = inputs.theta_trim_rad;
        let outputs = match self {
            Self::PitchStep {
                step_rad,
                step_time_s,
                shaped,
            } => pitch_step_outputs(*step_rad, *step_time_s, shaped.as_ref(), inputs),
            Self::ClimbRate {
                climb_rate_mps,
                ramp,
                theta_feedforward_rad,
                sink_rate,
            } => {
                let fraction = ramp.fraction(inputs.time_s);
                let command = fraction * climb_rate_mps;
                let base = trim_theta + fraction * (theta_feedforward_rad - trim_theta);
                let error = command - inputs.climb_rate_mps;
                let theta = base + sink_rate.output(error, inputs.sink_rate_integral_m, 0.0);
                OuterLoopOutputs {
                    climb_rate_command_mps: command,
                    climb_rate_error_mps: error,
                    ..OuterLoopOutputs::pitch_only(theta, 0.0, 0.0)
                }
            }
            Self::Approach {
                flight_path,
                guidance,
                sink_rate,
                wave_off: flight,
                late_abort,
                alpha_floor,
            } => {
                let deck = deck.expect("an approach always holds a deck reference");
                let path = flight_path.reference(inputs.hook_x_m, inputs.hook_x_rate_mps, deck);
                let height_error = path.height_m - inputs.hook_h_m;
                // A wave-off takes over from the guidance's climb-rate command (its blend).
                let flight = flight.filter(|_| wave_off);
                let command = approach_climb_rate_command(
                    &path,
                    height_error,
                    guidance,
                    flight,
                    inputs,
                    taps,
                );
                let error = command - inputs.climb_rate_mps;
                let theta = trim_theta
                    + sink_rate.output(error, inputs.sink_rate_integral_m, 0.0)
                    + inputs.wake_pitch_feedforward_rad;
                let (theta, pitch_floored) =
                    floored_pitch(theta, flight, alpha_floor, inputs, deck);
                OuterLoopOutputs {
                    climb_rate_command_mps: command,
                    path: Some(path),
                    height_error_m: height_error,
                    climb_rate_error_mps: error,
                    pitch_floored,
                    late_abort_lift_share: late_abort.share,
                    late_abort_thrust_share: late_abort.thrust_share(),
                    ..OuterLoopOutputs::pitch_only(theta, 0.0, 0.0)
                }
            }
        };
        OuterLoopOutputs {
            theta_ref_rad: taps.tap(LoopBreak::PitchCommand, outputs.theta_ref_rad),
            ..outputs
        }
    }

    /// The rates of the sink-rate and guidance integrators (zero where a loop is off).
    #[inline(always)]
    pub(crate) fn integral_rates(
        &self,
        inputs: &OuterLoopInputs,
        outputs: &OuterLoopOutputs,
        wave_off: bool,
    ) -> (f64, f64) {
        match self {
            Self::PitchStep { .. } => (0.0, 0.0),
            Self::ClimbRate { sink_rate, .. } => (
                sink_rate.integral_rate(
                    outputs.climb_rate_error_mps,
                    inputs.sink_rate_integral_m,
                    0.0,
                ),
                0.0,
            ),
            Self::Approach {
                guidance,
                sink_rate,
                ..
            } => (
                // While a floor (the wave-off's or the α protection's) holds the pitch command up, the sink-rate
                // integrator does not wind the loop's own command further down (the
                // conditional integration of LoopController, with the floor as the limit).
                if outputs.pitch_floored
                    && outputs.climb_rate_error_mps * sink_rate.gains.integral < 0.0
                {
                    0.0
                } else {
                    sink_rate.integral_rate(
                        outputs.climb_rate_error_mps,
                        inputs.sink_rate_integral_m,
                        0.0,
                    )
                },
                // The guidance integrator holds in a wave-off, and while a floor holds the
                // pitch command up against a path below the hook.
                if wave_off
                    || (outputs.pitch_floored
                        && outputs.height_error_m * guidance.gains.integral < 0.0)
                {
                    0.0
                } else {
                    guidance.integral_rate(
                        outputs.height_error_m,
                        inputs.guidance_integral_m_s,
                        0.0,
                    )
                },
            ),
        }
    }

    /// A run's `reason` with the late abort's decision after it, if it engaged (a run
    /// without a reason, a trap, keeps none: campaign files hold no reason for a trap).
    pub(crate) fn with_late_abort(&self, reason: Option<String>) -> Option<String> {
        let Self::Approach { late_abort, .. } = self else {
            return reason;
        };
        match (reason, late_abort.description()) {
            (Some(reason), Some(late)) => Some(format!("{reason}; {late}")),
            (reason, _) => reason,
        }
    }

    /// Whether these loops fly an approach to the deck.
    pub fn is_approach(&self) -> bool {
        matches!(self, Self::Approach { .. })
    }
}

/// The air-relative flight-path angle that gives an inertial glide slope `slope_rad`
/// relative to a deck moving at `ship_speed_mps` in a steady wind: the closure speed is
/// V cos γ_a + W_x − V_ship and the required sink is closure·tan(slope) − W_z (air
/// sinking with W_z > 0 carries the aircraft down). Solved by fixed-point iteration.
pub fn approach_flight_path_angle(
    airspeed_mps: f64,
    slope_rad: f64,
    wind: &Wind,
    ship_speed_mps: f64,
) -> f64 {
    let mut gamma: f64 = -slope_rad;
    for _ in 0..20 {
        let closure = airspeed_mps * gamma.cos() + wind.x_mps - ship_speed_mps;
        let air_sink = closure * slope_rad.tan() - wind.z_mps;
        gamma = -(air_sink / airspeed_mps).clamp(-1.0, 1.0).asin();
    }
    gamma
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::control::WaveOffCriterion;

    fn decision() -> WaveOffDecision {
        WaveOffDecision {
            criterion: WaveOffCriterion::RampStrikeProbability,
            value: 7.5,
            limit: 5.0,
            predicted_ramp_clearance_m: 1.4,
        }
    }

    /// At 5 per second on 1-ms steps the share rises by 0.005 a step: 0.5 after 100
    /// steps, 1 (and no more) after 200; released, it falls at the same rate. The first
    /// decision is kept and named.
    #[test]
    fn the_late_abort_blends_in_and_out_at_its_rate() {
        let mut abort = LateAbort::new(5.0, false);
        let mut largest_change = 0.0_f64;
        let mut last = 0.0;
        let mut at = |abort: &LateAbort, last: &mut f64| {
            largest_change = largest_change.max((abort.share - *last).abs());
            *last = abort.share;
        };
        for k in 0..100 {
            abort.step(23.0 + f64::from(k) * 0.001, 0.001, Some(decision()));
            at(&abort, &mut last);
        }
        assert!((abort.share - 0.5).abs() < 1e-12, "{}", abort.share);
        for k in 100..300 {
            abort.step(23.0 + f64::from(k) * 0.001, 0.001, Some(decision()));
            at(&abort, &mut last);
        }
        assert_eq!(abort.share, 1.0);
        for _ in 0..40 {
            abort.step(24.0, 0.001, None);
            at(&abort, &mut last);
        }
        assert!((abort.share - 0.8).abs() < 1e-12, "{}", abort.share);
        assert!(largest_change <= 0.005 + 1e-12, "{largest_change}");
        assert_eq!(abort.first.map(|(t, _)| t), Some(23.0));
        assert_eq!(
            abort.description().as_deref(),
            Some(
                "late abort at t = 23.00 s on ramp_strike_probability: probability of a \
                 ramp strike (%) 7.50 against the limit 5.00"
            )
        );
        assert_eq!(LateAbort::new(5.0, false).description(), None);
    }
}
