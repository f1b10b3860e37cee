//! The loops above the pitch law, one variant per kind of run (docs/model.md §5): a pitch
//! step, a climb-rate program through the sink-rate loop, or the full approach cascade
//! flight path → guidance → sink rate.

use super::taps::Taps;
use crate::control::pitch::command_shaping::JerkLimitedStep;
use crate::control::{
    CommandRamp, DeckReference, FlightPathGenerator, LoopController, PathReference,
};

/// What produces the pitch command θ_ref.
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
        /// The climb rate commanded in a wave-off (m/s); `None` without wave-offs.
        wave_off_climb_rate_mps: Option<f64>,
        /// The ramp's distance aft of the landing point (m): once the hook is past it, a
        /// wave-off holds at least the approach attitude.
        ramp_aft_of_aim_point_m: f64,
        /// Guidance: height error → climb-rate command.
        guidance: LoopController,
        /// The sink-rate loop: climb-rate error → pitch command.
        sink_rate: LoopController,
    },
}

/// The hook's kinematics and the aircraft's climb rate, as the outer loops read them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OuterLoopInputs {
    pub time_s: f64,
    pub theta_trim_rad: f64,
    pub climb_rate_mps: f64,
    pub hook_x_m: f64,
    pub hook_h_m: f64,
    pub hook_x_rate_mps: f64,
    pub hook_climb_rate_mps: f64,
    /// ∫ climb-rate error dt (m).
    pub sink_rate_integral_m: f64,
    /// ∫ hook height error dt (m·s).
    pub guidance_integral_m_s: f64,
    /// Pitch fed forward against the steady air wake's vertical wind (rad).
    pub wake_pitch_feedforward_rad: f64,
}

/// The outer loops' outputs at one instant.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OuterLoopOutputs {
    /// The pitch command, after the taps (rad).
    pub theta_ref_rad: f64,
    /// Its rate (rad/s) when it is a shaped trajectory, else 0.
    pub theta_ref_rate_radps: f64,
    /// Its acceleration (rad/s²) when it is a shaped trajectory, else 0.
    pub theta_ref_acceleration_radps2: f64,
    /// The climb-rate command (m/s); NaN when no loop commands one.
    pub climb_rate_command_mps: f64,
    /// The glide path, in an approach.
    pub path: Option<PathReference>,
    /// Height error of the hook to the path h_ref − h (m), 0 outside an approach.
    pub height_error_m: f64,
    /// Climb-rate error (m/s), 0 without a sink-rate loop.
    pub climb_rate_error_mps: f64,
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
        let (mut reference_rate, mut reference_acceleration) = (0.0, 0.0);
        let (theta_ref_rad, climb_rate_command_mps, path, height_error_m, climb_rate_error_mps) =
            match self {
                Self::PitchStep {
                    step_rad,
                    step_time_s,
                    shaped: None,
                } => {
                    let step = if inputs.time_s >= *step_time_s {
                        *step_rad
                    } else {
                        0.0
                    };
                    (trim_theta + step, f64::NAN, None, 0.0, 0.0)
                }
                Self::PitchStep {
                    step_time_s,
                    shaped: Some(trajectory),
                    ..
                } => {
                    let reference = trajectory.reference(inputs.time_s - step_time_s);
                    reference_rate = reference.rate_radps;
                    reference_acceleration = reference.acceleration_radps2;
                    (trim_theta + reference.theta_rad, f64::NAN, None, 0.0, 0.0)
                }
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
                    (theta, command, None, 0.0, error)
                }
                Self::Approach {
                    flight_path,
                    guidance,
                    sink_rate,
                    wave_off_climb_rate_mps,
                    ramp_aft_of_aim_point_m,
                } => {
                    let deck = deck.expect("an approach always holds a deck reference");
                    let path = flight_path.reference(inputs.hook_x_m, inputs.hook_x_rate_mps, deck);
                    let height_error = path.height_m - inputs.hook_h_m;
                    let height_error_rate = path.climb_rate_mps - inputs.hook_climb_rate_mps;
                    // A wave-off commands its climb; the guidance no longer flies the path.
                    let command = taps.climb_rate_command(match wave_off_climb_rate_mps {
                        Some(climb) if wave_off => *climb,
                        _ => {
                            path.climb_rate_mps
                                + guidance.output(
                                    height_error,
                                    inputs.guidance_integral_m_s,
                                    height_error_rate,
                                )
                        }
                    });
                    let error = command - inputs.climb_rate_mps;
                    let theta = trim_theta
                        + sink_rate.output(error, inputs.sink_rate_integral_m, 0.0)
                        + inputs.wake_pitch_feedforward_rad;
                    // Past the ramp a wave-off holds at least the approach attitude
                    // (docs/model.md §9): at full thrust the climb overshoots its command,
                    // and pushing over took α below −5° in the heavy sea's wake. Before
                    // the ramp the law is left alone: pitching up there swings the hook
                    // down towards the ramp.
                    let theta = if wave_off
                        && inputs.hook_x_m > deck.mean_aim.x_m - ramp_aft_of_aim_point_m
                    {
                        theta.max(trim_theta)
                    } else {
                        theta
                    };
                    (theta, command, Some(path), height_error, error)
                }
            };
        OuterLoopOutputs {
            theta_ref_rad: taps.pitch_command(theta_ref_rad),
            theta_ref_rate_radps: reference_rate,
            theta_ref_acceleration_radps2: reference_acceleration,
            climb_rate_command_mps,
            path,
            height_error_m,
            climb_rate_error_mps,
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
                sink_rate.integral_rate(
                    outputs.climb_rate_error_mps,
                    inputs.sink_rate_integral_m,
                    0.0,
                ),
                // The guidance integrator holds in a wave-off.
                if wave_off {
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

    /// Whether these loops fly an approach to the deck.
    pub fn is_approach(&self) -> bool {
        matches!(self, Self::Approach { .. })
    }
}
