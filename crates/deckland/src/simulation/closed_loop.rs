//! The closed loop as a composition of blocks: plant, ship motion, wind, pitch sensor,
//! deck-motion predictor, pitch law, speed loop and outer loops (docs/model.md §5–6).
//!
//! Each block with continuous dynamics owns a named slot of the state vector
//! ([`LoopLayout`]); the loop evaluates the blocks in the order the signals flow and
//! writes each block's rate into its slot. Random samples and sampled signals are drawn
//! once per step by [`ClosedLoop::hold`] and passed to [`ClosedLoop::evaluate`]
//! explicitly ([`HeldInputs`]), which is a pure function of time, state and held inputs.

use super::deck_prediction::DeckPredictor;
use super::flight_computer::{FlightComputer, HeldCommands};
pub use super::layout::LoopLayout;
use super::outer_loops::{OuterLoopInputs, OuterLoops};
use super::signals::Signals;
use super::taps::Taps;
use crate::aircraft::{Aircraft, AircraftCommands, AircraftState, HookGeometry, TrimPoint};
use crate::control::pitch::{AxisLaw, BuiltPitchLaw, ElevatorSaturation, PitchLawInputs};
use crate::control::{
    DeckReference, DirectLiftParameters, SpeedController, WaveOffDecision, WaveOffParameters,
};
use crate::environment::{
    steady_wake, DeckGeometry, ShipMotion, ShipMotionState, ShipNoise, ShipPose, ShipPoseRate,
    Wind, WindModel,
};
use crate::integration::VectorSystem;
use crate::random::NoiseStream;
use crate::sensors::PitchSensor;

/// Tolerance of "the elevator sits on a position limit" for the pitch laws (rad).
const SATURATION_TOLERANCE_RAD: f64 = 1e-9;

/// Inputs drawn or sampled once per step and held over its four RK4 stages.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeldInputs {
    /// White-noise inputs of the ship's shaping filters.
    pub ship_noise: ShipNoise,
    /// Pitch-measurement error (rad): white noise plus the sinusoid, sampled at the start
    /// of the step (the sensor is read once per control step).
    pub pitch_noise_rad: f64,
    /// The wind at the aircraft (mean, turbulence, steady and periodic wake), sampled at
    /// the start of the step, like the turbulence it contains.
    pub wind: Wind,
    /// The deck reference of the glide-path generator, computed at the start of the step
    /// (the guidance computer updates once per step); `None` outside an approach.
    pub deck: Option<DeckReference>,
    /// With a flight-control computer running in frames, the commands of the current
    /// frame, which the actuators hold; `None` updates them continuously.
    pub commands: Option<HeldCommands>,
    /// With a flight-control computer, the pitch attitude it read at the frame's start
    /// (rad) and the time that reading stands for (s); the pitch law uses it in place of
    /// θ + `pitch_noise_rad`.
    pub theta_read: Option<(f64, f64)>,
    /// Whether a frame of the flight-control computer starts at this step: then
    /// [`ClosedLoop::compute_frame`] computes the frame's commands (`commands` holds the
    /// last frame's until it does).
    pub frame_starts: bool,
    /// Whether the aircraft is waving off (docs/model.md §9): full thrust and a climb.
    pub wave_off: bool,
}

/// The random streams the loop draws from step by step.
#[derive(Debug, Clone)]
pub struct StepStreams {
    /// White noise of the heave shaping filter.
    pub ship_heave: NoiseStream,
    /// White noise of the pitch shaping filter.
    pub ship_pitch: NoiseStream,
}

/// The closed-loop system integrated by the simulation.
#[derive(Debug, Clone)]
pub struct ClosedLoop {
    pub(crate) layout: LoopLayout,
    pub(crate) aircraft: Aircraft,
    pub(crate) hook: HookGeometry,
    pub(crate) ship: ShipMotion,
    pub(crate) deck: DeckGeometry,
    pub(crate) ship_initial_x_m: f64,
    pub(crate) wind: WindModel,
    pub(crate) sensor: PitchSensor,
    pub(crate) deck_predictor: DeckPredictor,
    pub(crate) pitch: BuiltPitchLaw,
    pub(crate) speed: SpeedController,
    pub(crate) outer: OuterLoops,
    pub(crate) trim: TrimPoint,
    pub(crate) airspeed_reference_mps: f64,
    pub(crate) computer: Option<FlightComputer>,
    pub(crate) wave_off: WaveOffParameters,
    /// The steady air wake fed forward into the pitch command, with this lead (s);
    /// `None` when it is not.
    pub(crate) wake_feedforward_lead_s: Option<f64>,
    /// Direct lift control, in an approach that flies it (docs/model.md §5.9).
    pub(crate) direct_lift: Option<DirectLiftParameters>,
    /// The wave-off decision, once taken: its time (s) and why.
    pub(crate) waved_off: Option<(f64, WaveOffDecision)>,
    /// A decision taken while holding the inputs of a step, not yet reported as an event.
    pub(crate) unreported_wave_off: Option<(f64, WaveOffDecision)>,
}

impl ClosedLoop {
    /// The slots of the blocks in the state vector.
    pub fn layout(&self) -> &LoopLayout {
        &self.layout
    }

    /// The trim point the controllers were designed at.
    pub fn trim(&self) -> &TrimPoint {
        &self.trim
    }

    /// The pitch law that flies.
    pub fn pitch_law(&self) -> &BuiltPitchLaw {
        &self.pitch
    }

    /// The outer loops.
    pub fn outer_loops(&self) -> &OuterLoops {
        &self.outer
    }

    /// The deck geometry.
    pub fn deck(&self) -> &DeckGeometry {
        &self.deck
    }

    /// The aircraft model.
    pub fn aircraft(&self) -> &Aircraft {
        &self.aircraft
    }

    /// The aircraft's state in `x`.
    #[inline]
    pub fn aircraft_state(&self, x: &[f64]) -> AircraftState {
        AircraftState::from_array(&self.layout.aircraft.array(x))
    }

    /// The ship's state in `x`.
    #[inline]
    fn ship_state(&self, x: &[f64]) -> ShipMotionState {
        ShipMotionState::from_array(&self.layout.ship.array(x))
    }

    /// The ship's pose and its rate at time `t` for the ship state in `x`.
    #[inline]
    pub fn ship_pose(&self, x: &[f64], t: f64) -> (ShipPose, ShipPoseRate) {
        let ship = self.ship_state(x);
        (
            self.ship.pose(&ship, self.ship_initial_x_m, t),
            self.ship.pose_rate(&ship),
        )
    }

    /// Draws and samples the inputs held over the step from `t`: the ship filters' white
    /// noise and the pitch sensor's error (each from its own stream, docs/model.md §3.4), the
    /// wind at the aircraft and, in an approach, the deck reference and whether the
    /// aircraft waves off (the guidance computer's step).
    pub fn hold(&mut self, t: f64, x: &[f64], streams: &mut StepStreams, dt: f64) -> HeldInputs {
        let ship_state = self.ship_state(x);
        let aircraft = self.aircraft_state(x);
        let (pose, _) = self.ship_pose(x, t);
        let wind = self
            .wind
            .wind(t, pose.distance_aft_of_pitch_centre_m(aircraft.x_m));
        let deck = self.guidance_computer_step(t, x, &aircraft, &ship_state, dt);
        let wave_off = self.waved_off.is_some();
        let ship_noise = self
            .ship
            .draw_noise(&mut streams.ship_heave, &mut streams.ship_pitch, dt);
        let Some(mut computer) = self.computer.take() else {
            return HeldInputs {
                ship_noise,
                pitch_noise_rad: self.sensor.draw_white_noise() + self.sensor.sinusoid(t),
                wind,
                deck,
                commands: None,
                theta_read: None,
                frame_starts: false,
                wave_off,
            };
        };
        // A frame of the flight-control computer: read the sensor (the mean of its samples
        // since the last frame); `compute_frame` computes the commands at its start, and
        // both are held until the next.
        let pitch_noise_rad = self.sensor.draw_white_noise() + self.sensor.sinusoid(t);
        let frame_starts = computer.starts_frame(t);
        computer.sample(t, aircraft.theta_rad + pitch_noise_rad, frame_starts);
        let held = HeldInputs {
            ship_noise,
            pitch_noise_rad,
            wind,
            deck,
            commands: Some(computer.commands),
            theta_read: Some((computer.theta_read_rad, computer.theta_read_time_s)),
            frame_starts,
            wave_off,
        };
        self.computer = Some(computer);
        held
    }

    /// At the start of a flight-computer frame (`held.frame_starts`), computes the frame's
    /// elevator and thrust commands from the reading held, each passed through `taps` (so
    /// that a command given from outside reaches the computer), and holds them in `held`
    /// and in the computer for the rest of the frame. Without a computer, or within a
    /// frame, does nothing. Computing again with other taps replaces the commands.
    pub fn compute_frame<T: Taps>(&mut self, t: f64, x: &[f64], held: &mut HeldInputs, taps: &T) {
        if !held.frame_starts {
            return;
        }
        let Some(mut computer) = self.computer.take() else {
            return;
        };
        held.commands = None;
        let signals = self.evaluate(t, x, held, taps, &mut computer.scratch);
        computer.commands = HeldCommands {
            elevator_rad: signals.elevator_command_rad,
            thrust_n: signals.thrust_command_n,
            direct_lift: signals.direct_lift_command.unwrap_or(0.0),
        };
        held.commands = Some(computer.commands);
        self.computer = Some(computer);
    }

    /// Advances the loop's discrete-time parts by `dt` after a step: the free-air
    /// turbulence, by its exact Gauss–Markov update at the aircraft's airspeed.
    pub fn advance_discrete(&mut self, dt: f64, airspeed_mps: f64) {
        self.wind.advance(dt, airspeed_mps);
    }

    /// Writes the derivative of the loop at (t, x) with the held inputs into `rate` and
    /// returns every signal. Always inlined, so that in the RK4 stages, which drop the
    /// signals, the work done only for them is optimised away.
    #[inline(always)]
    pub fn evaluate<T: Taps>(
        &self,
        t: f64,
        x: &[f64],
        held: &HeldInputs,
        taps: &T,
        rate: &mut [f64],
    ) -> Signals {
        let layout = &self.layout;
        let a = &self.aircraft_state(x);
        let ship_state = self.ship_state(x);
        let pose = self.ship.pose(&ship_state, self.ship_initial_x_m, t);
        let pose_rate = self.ship.pose_rate(&ship_state);
        let distance_aft_m = pose.distance_aft_of_pitch_centre_m(a.x_m);
        let wind = held.wind;

        // Plant kinematics and air data.
        let (sin_t, cos_t) = a.theta_rad.sin_cos();
        let air = self
            .aircraft
            .air_data_trig(a.u_mps, a.w_mps, sin_t, cos_t, &wind);
        let (hook_x_m, hook_h_m) = self.hook.position_trig(a, sin_t, cos_t);
        let (hook_x_rate_mps, hook_climb_rate_mps) = self.hook.velocity_trig(a, sin_t, cos_t);
        let (x_rate_mps, climb_rate_mps) = a.earth_velocity_trig(sin_t, cos_t);

        // Outer loops: flight path → guidance → sink rate → θ_ref (docs/model.md §5).
        let outer_inputs = OuterLoopInputs {
            time_s: t,
            theta_trim_rad: self.trim.theta_rad,
            climb_rate_mps,
            air_path_angle_rad: a.theta_rad - air.alpha_rad,
            hook_x_m,
            hook_h_m,
            hook_x_rate_mps,
            hook_climb_rate_mps,
            sink_rate_integral_m: layout.sink_rate.scalar(x),
            guidance_integral_m_s: layout.guidance.scalar(x),
            wake_pitch_feedforward_rad: self.wake_feedforward_lead_s.map_or(0.0, |lead_s| {
                // Δθ = (W_z + τ·dW_z/dt)/V: air sinking (W_z > 0) is climbed against, led
                // by the path's lag behind pitch (docs/model.md §5.7).
                let wake_z = |d: f64| steady_wake(d).z_mps * self.wind.parameters().wake_weight(d);
                let mut feedforward = wake_z(distance_aft_m);
                if lead_s > 0.0 {
                    let distance_rate_mps = pose_rate.pitch_centre_x_rate_mps - x_rate_mps;
                    let slope = wake_z(distance_aft_m + 0.5) - wake_z(distance_aft_m - 0.5);
                    feedforward += lead_s * slope * distance_rate_mps;
                }
                feedforward / air.airspeed_mps
            }),
        };
        let outer = self
            .outer
            .outputs(&outer_inputs, held.deck.as_ref(), held.wave_off, taps);

        // Pitch law on the measured attitude (docs/model.md §3.3, §4).
        let (theta_measured_rad, measurement_age_s) = match held.theta_read {
            Some((read, read_time)) => (read, t - read_time),
            None => (a.theta_rad + held.pitch_noise_rad, 0.0),
        };
        let actuator = self.aircraft.actuator();
        let pitch_inputs = PitchLawInputs {
            theta_ref_rad: outer.theta_ref_rad,
            theta_ref_rate_radps: outer.theta_ref_rate_radps,
            theta_ref_acceleration_radps2: outer.theta_ref_acceleration_radps2,
            theta_measured_rad,
            measurement_age_s,
            pitch_rate_measured_radps: a.q_radps,
            elevator_actual_rad: a.elevator_rad,
            theta_trim_rad: self.trim.theta_rad,
            elevator_trim_rad: self.trim.elevator_rad,
            elevator_saturation: ElevatorSaturation::from_position(
                a.elevator_rad,
                actuator.min_rad(),
                actuator.max_rad(),
                SATURATION_TOLERANCE_RAD,
            ),
        };
        let pitch_state = layout.pitch_law.of(x);
        let elevator_command_rad = taps.elevator_command(match held.commands {
            Some(commands) => commands.elevator_rad,
            None => self.pitch.surface_command_rad(pitch_state, &pitch_inputs),
        });

        // Speed loop (docs/model.md §5).
        let speed_state = layout.speed.of(x);
        let speed_error = self.airspeed_reference_mps
            - self
                .speed
                .feedback_airspeed_mps(speed_state, air.airspeed_mps);
        let thrust_command_n = taps.thrust_command(match held.commands {
            Some(commands) => commands.thrust_n,
            // A wave-off: full thrust of both engines (docs/model.md §9).
            None if held.wave_off => self.aircraft.engines().max_total_thrust_n(),
            None => self.speed.thrust_command_n(speed_error, speed_state[0]),
        });

        // Rates, block by block.
        let commands = AircraftCommands {
            elevator_rad: elevator_command_rad,
            thrust_n: thrust_command_n,
        };
        // Direct lift control on the hook's height error to the path (docs/model.md §5.9).
        let direct_lift = self.direct_lift.map(|law| {
            let increment = layout.direct_lift.scalar(x);
            let command = taps.direct_lift_command(match held.commands {
                Some(commands) => commands.direct_lift,
                None => {
                    let error_rate = outer
                        .path
                        .map_or(0.0, |p| p.climb_rate_mps - hook_climb_rate_mps);
                    match (outer.path, held.deck) {
                        (Some(path), Some(deck)) => {
                            // The path moves with its anchor by the compensation weight
                            // (FlightPathGenerator): on the unfiltered anchor it is this
                            // much higher, and it accelerates with the filtered one.
                            let error_m = outer.height_error_m
                                + deck
                                    .unfiltered_aim_h_m
                                    .map_or(0.0, |h| path.compensation_weight * (h - deck.aim.h_m));
                            let p = self.aircraft.parameters();
                            let feedforward = law.feedforward(
                                path.compensation_weight * deck.aim_acceleration_mps2,
                                p.mass_kg,
                                air.dynamic_pressure_pa,
                                p.wing_area_m2,
                            );
                            let command =
                                law.command(error_m, error_rate, feedforward, held.wave_off);
                            // The flare on the deck forecast: the landing point's predicted
                            // climb rate at touchdown less the hook's.
                            deck.forecast.map_or(command, |forecast| {
                                law.flare(
                                    command,
                                    path.time_to_go_s,
                                    forecast.landing_point_climb_rate_mps - hook_climb_rate_mps,
                                )
                            })
                        }
                        _ => law.command(outer.height_error_m, error_rate, 0.0, held.wave_off),
                    }
                }
            });
            rate[layout.direct_lift.offset] = law.increment_rate(increment, command);
            (increment, command)
        });
        let aircraft_rate = self.aircraft.derivative_with_direct_lift(
            a,
            &commands,
            &air,
            sin_t,
            cos_t,
            direct_lift.map_or(0.0, |(increment, _)| increment),
        );
        layout.aircraft.write_array(rate, &aircraft_rate.to_array());
        let ship_rate = self.ship.derivative(&ship_state, held.ship_noise);
        layout.ship.write_array(rate, &ship_rate.to_array());
        self.pitch
            .derivative(pitch_state, &pitch_inputs, layout.pitch_law.of_mut(rate));
        self.speed.derivative(
            speed_state,
            speed_error,
            air.airspeed_mps,
            layout.speed.of_mut(rate),
        );
        let (sink_integral_rate, guidance_integral_rate) =
            self.outer
                .integral_rates(&outer_inputs, &outer, held.wave_off);
        rate[layout.sink_rate.offset] = sink_integral_rate;
        rate[layout.guidance.offset] = guidance_integral_rate;
        let aim_point = self.deck.aim_point(&pose);
        self.deck_predictor.derivative(
            layout.deck_predictor.of(x),
            aim_point.h_m,
            layout.deck_predictor.of_mut(rate),
        );

        let path = outer.path;
        Signals {
            time_s: t,
            x_m: a.x_m,
            h_m: a.h_m,
            hook_x_m,
            hook_h_m,
            hook_climb_rate_mps,
            hook_x_rate_mps,
            path_height_m: path.map(|p| p.height_m),
            glide_path_error_m: outer.height_error_m,
            time_to_go_s: path.map(|p| p.time_to_go_s),
            compensation_weight: path.map_or(0.0, |p| p.compensation_weight),
            airspeed_mps: air.airspeed_mps,
            alpha_rad: air.alpha_rad,
            theta_rad: a.theta_rad,
            theta_measured_rad,
            theta_ref_rad: outer.theta_ref_rad,
            q_radps: a.q_radps,
            climb_rate_mps,
            // A pitch step has no climb-rate loop: not applicable, rather than NaN.
            climb_rate_command_mps: (!matches!(self.outer, OuterLoops::PitchStep { .. }))
                .then_some(outer.climb_rate_command_mps),
            elevator_rad: a.elevator_rad,
            elevator_rate_radps: a.elevator_rate_radps,
            elevator_command_rad,
            thrust_n: a.total_thrust_n(),
            thrust_command_n,
            wind,
            distance_aft_m,
            ship: pose,
            ship_rate: pose_rate,
            aim_point,
            disturbance_estimate_radps2: self.pitch.disturbance_estimate_radps2(pitch_state),
            direct_lift_coefficient: direct_lift.map(|(increment, _)| increment),
            direct_lift_command: direct_lift.map(|(_, command)| command),
        }
    }

    /// The wave-off decision, once taken: its time (s) and why.
    pub fn wave_off_decision(&self) -> Option<(f64, WaveOffDecision)> {
        self.waved_off
    }

    /// The wave-off decision taken since the last call, if any (for the run loop to
    /// report it as an event once).
    pub(crate) fn take_unreported_wave_off(&mut self) -> Option<(f64, WaveOffDecision)> {
        self.unreported_wave_off.take()
    }

    /// Holds the elevator actuator at its stops after a step.
    pub fn constrain(&self, x: &mut [f64]) {
        let slot = self.layout.aircraft.of_mut(x);
        let (mut position, mut rate) = (
            slot[AircraftState::ELEVATOR_INDEX],
            slot[AircraftState::ELEVATOR_RATE_INDEX],
        );
        self.aircraft.actuator().constrain(&mut position, &mut rate);
        slot[AircraftState::ELEVATOR_INDEX] = position;
        slot[AircraftState::ELEVATOR_RATE_INDEX] = rate;
    }
}

/// The loop with its held inputs and taps fixed over a step: the system the RK4 stages
/// see.
pub(crate) struct HeldLoop<'a, T: Taps> {
    pub system: &'a ClosedLoop,
    pub held: &'a HeldInputs,
    pub taps: &'a T,
}

impl<T: Taps> VectorSystem for HeldLoop<'_, T> {
    #[inline]
    fn derivative_into(&self, t: f64, x: &[f64], rate: &mut [f64]) {
        self.system.evaluate(t, x, self.held, self.taps, rate);
    }

    fn constrain(&self, x: &mut [f64]) {
        self.system.constrain(x);
    }
}
