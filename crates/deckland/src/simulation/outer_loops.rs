//! The loops above the pitch law, one variant per kind of run (docs/model.md §5): a pitch
//! step, a climb-rate program through the sink-rate loop, or the full approach cascade
//! flight path → guidance → sink rate.

use super::taps::{LoopBreak, Taps};
use crate::control::pitch::command_shaping::JerkLimitedStep;
use crate::control::{
    CommandRamp, DeckReference, FlightPathGenerator, LoopController, PathReference,
};
use crate::environment::Wind;

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
        /// How a wave-off is flown; `None` without wave-offs.
        wave_off: Option<WaveOffFlight>,
        /// Guidance: height error → climb-rate command.
        guidance: LoopController,
        /// The sink-rate loop: climb-rate error → pitch command.
        sink_rate: LoopController,
    },
}

/// How the outer loops fly a wave-off (docs/model.md §9): a commanded climb through the
/// sink-rate loop, with two floors under its pitch command.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WaveOffFlight {
    /// The climb rate commanded (m/s, up).
    pub climb_rate_mps: f64,
    /// The smallest angle of attack flown (rad): the pitch command is at least the
    /// air-relative flight-path angle plus this.
    pub min_alpha_rad: f64,
    /// The ramp's distance aft of the landing point (m): once the hook is past it, the
    /// pitch command is at least the approach attitude.
    pub ramp_aft_of_aim_point_m: f64,
}

impl WaveOffFlight {
    /// The pitch command `theta_rad` of the sink-rate loop with the wave-off's floors,
    /// and whether a floor raised it. At full thrust the climb overshoots its command,
    /// and the sink-rate loop pushes over: in the heavy sea's wake that took α below the
    /// aerodynamic model's −5°. The attitude floor waits for the ramp (pitching up
    /// before it swings the hook down towards it); the α floor does not, as losing the
    /// wing is worse.
    #[inline(always)]
    fn floored_pitch(
        &self,
        theta_rad: f64,
        inputs: &OuterLoopInputs,
        deck: &DeckReference,
    ) -> (f64, bool) {
        let mut floor = inputs.air_path_angle_rad + self.min_alpha_rad;
        if inputs.hook_x_m > deck.mean_aim.x_m - self.ramp_aft_of_aim_point_m {
            floor = floor.max(inputs.theta_trim_rad);
        }
        if theta_rad < floor {
            (floor, true)
        } else {
            (theta_rad, false)
        }
    }
}

/// The hook's kinematics and the aircraft's climb rate, as the outer loops read them.
#[derive(Debug, Clone, Copy)]
pub(crate) struct OuterLoopInputs {
    pub time_s: f64,
    pub theta_trim_rad: f64,
    pub climb_rate_mps: f64,
    /// The air-relative flight-path angle θ − α (rad).
    pub air_path_angle_rad: f64,
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
    /// Whether a wave-off's floor raised the pitch command (the sink-rate integrator
    /// then holds).
    pub pitch_floored: bool,
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
        let mut pitch_floored = false;
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
                    wave_off: flight,
                } => {
                    let deck = deck.expect("an approach always holds a deck reference");
                    let path = flight_path.reference(inputs.hook_x_m, inputs.hook_x_rate_mps, deck);
                    let height_error = path.height_m - inputs.hook_h_m;
                    let height_error_rate = path.climb_rate_mps - inputs.hook_climb_rate_mps;
                    // A wave-off commands its climb; the guidance no longer flies the path.
                    let flight = flight.filter(|_| wave_off);
                    let command = taps.tap(
                        LoopBreak::ClimbRateCommand,
                        match flight {
                            Some(flight) => flight.climb_rate_mps,
                            None => {
                                path.climb_rate_mps
                                    + guidance.output(
                                        height_error,
                                        inputs.guidance_integral_m_s,
                                        height_error_rate,
                                    )
                            }
                        },
                    );
                    let error = command - inputs.climb_rate_mps;
                    let theta = trim_theta
                        + sink_rate.output(error, inputs.sink_rate_integral_m, 0.0)
                        + inputs.wake_pitch_feedforward_rad;
                    let theta = match flight {
                        Some(flight) => {
                            let (theta, floored) = flight.floored_pitch(theta, inputs, deck);
                            pitch_floored = floored;
                            theta
                        }
                        None => theta,
                    };
                    (theta, command, Some(path), height_error, error)
                }
            };
        OuterLoopOutputs {
            theta_ref_rad: taps.tap(LoopBreak::PitchCommand, theta_ref_rad),
            theta_ref_rate_radps: reference_rate,
            theta_ref_acceleration_radps2: reference_acceleration,
            climb_rate_command_mps,
            path,
            height_error_m,
            climb_rate_error_mps,
            pitch_floored,
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
                // While a wave-off's floor holds the pitch command up, the sink-rate
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
