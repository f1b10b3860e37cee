//! The closed loop as one system of ODEs: plant, ship filters, pitch controller (with its
//! observer) and the integrators of the speed, sink-rate and guidance loops advance
//! together in one RK4 step (MODEL.md §6).

use crate::aircraft::{Aircraft, AircraftCommands, AircraftState, HookGeometry};
use crate::analysis::TrimPoint;
use crate::control::pitch::{ElevatorSaturation, PitchControlInputs, PitchController};
use crate::control::{
    DeckMotionFilter, DeckMotionPredictor, DeckReference, FlightPathGenerator, LoopController,
    SpeedController,
};
use crate::environment::{
    DeckGeometry, EarthPoint, EarthVelocity, ShipMotion, ShipMotionPredictor, ShipMotionState,
    ShipNoise, ShipPose, ShipPoseRate, Wind, WindModel,
};
use crate::integration::OdeSystem;
use crate::sensors::PitchSensor;

/// Number of scalar states of the closed loop.
pub const LOOP_DIMENSION: usize = AircraftState::DIMENSION + ShipMotionState::DIMENSION + 3 + 3 + 2;

/// The closed loop's state, as named parts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LoopState {
    /// The aircraft plant.
    pub aircraft: AircraftState,
    /// The ship's heave and pitch shaping filters.
    pub ship: ShipMotionState,
    /// The pitch controller's state (observer x1, x2, x3, or the PID integral).
    pub pitch_controller: [f64; 3],
    /// ∫ airspeed error dt (m).
    pub speed_integral_m: f64,
    /// ∫ climb-rate error dt (m).
    pub sink_rate_integral_m: f64,
    /// ∫ hook height error dt (m·s).
    pub guidance_integral_m_s: f64,
    /// Filtered landing-point height ĥ_L (m) and rate ĥ̇_L (m/s).
    pub deck_estimate: [f64; 2],
}

impl LoopState {
    /// The state as an integrator array.
    #[inline]
    pub fn to_array(&self) -> [f64; LOOP_DIMENSION] {
        let a = self.aircraft.to_array();
        let h = &self.ship.heave_filter;
        let p = &self.ship.pitch_filter;
        let c = &self.pitch_controller;
        [
            a[0],
            a[1],
            a[2],
            a[3],
            a[4],
            a[5],
            a[6],
            a[7],
            a[8],
            a[9], //
            h[0],
            h[1],
            h[2],
            h[3],
            p[0],
            p[1],
            p[2],
            p[3], //
            c[0],
            c[1],
            c[2], //
            self.speed_integral_m,
            self.sink_rate_integral_m,
            self.guidance_integral_m_s,
            self.deck_estimate[0],
            self.deck_estimate[1],
        ]
    }

    /// The state from an integrator array.
    #[inline]
    pub fn from_array(x: &[f64; LOOP_DIMENSION]) -> Self {
        Self {
            aircraft: AircraftState::from_array(&[
                x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8], x[9],
            ]),
            ship: ShipMotionState {
                heave_filter: [x[10], x[11], x[12], x[13]],
                pitch_filter: [x[14], x[15], x[16], x[17]],
            },
            pitch_controller: [x[18], x[19], x[20]],
            speed_integral_m: x[21],
            sink_rate_integral_m: x[22],
            guidance_integral_m_s: x[23],
            deck_estimate: [x[24], x[25]],
        }
    }
}

/// Random inputs drawn once per step and held over its four RK4 stages.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct HeldInputs {
    /// White-noise inputs of the ship's shaping filters.
    pub ship_noise: ShipNoise,
    /// Pitch-measurement error (rad): white noise plus the sinusoid, sampled at the start
    /// of the step (the sensor is read once per control step).
    pub pitch_noise_rad: f64,
    /// The wind at the aircraft (mean, turbulence, steady and periodic wake), sampled at
    /// the start of the step and held over it, like the turbulence it contains;
    /// `None` evaluates it at every stage.
    pub wind: Option<Wind>,
    /// The deck reference of the glide-path generator (mean and predicted landing point),
    /// computed at the start of the step and held over it (the guidance computer updates
    /// once per step); `None` outside the approach.
    pub deck: Option<DeckReference>,
}

/// Which loops run and what they track.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LoopMode {
    /// Pitch attitude steps by `step_rad` at `step_time_s`; outer loops off.
    PitchStep {
        /// Step size (rad).
        step_rad: f64,
        /// Time of the step (s).
        step_time_s: f64,
    },
    /// Climb rate ramps to `climb_rate_mps` over `ramp_s` from `step_time_s`, with the
    /// pitch feed-forward moving to `theta_feedforward_rad` alike; guidance off.
    ClimbRate {
        /// Commanded climb rate after the ramp (m/s, negative descending).
        climb_rate_mps: f64,
        /// Start of the command (s).
        step_time_s: f64,
        /// Ramp time (s); 0 is a step.
        ramp_s: f64,
        /// Trim pitch of the commanded descent (rad).
        theta_feedforward_rad: f64,
    },
    /// The full cascade following the glide path to the deck.
    Approach,
}

/// A point where a loop of the cascade can be cut for analysis: downstream of it the loop
/// uses an injected value, and the value the loop computes there is reported in
/// [`Signals::loop_break_output`] (MODEL.md §5: margins on the linearised cascade).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopBreak {
    /// The elevator command (rad): the pitch loop.
    ElevatorCommand,
    /// The pitch command θ_ref (rad): the sink-rate loop.
    PitchCommand,
    /// The climb-rate command (m/s): the guidance loop.
    ClimbRateCommand,
    /// The thrust command (N): the speed loop.
    ThrustCommand,
}

/// Every signal of interest at one instant, for recorders and event detection.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Signals {
    /// Time (s).
    pub time_s: f64,
    /// CG earth x (m).
    pub x_m: f64,
    /// CG altitude (m).
    pub h_m: f64,
    /// Hook earth x (m).
    pub hook_x_m: f64,
    /// Hook height (m).
    pub hook_h_m: f64,
    /// Hook climb rate (m/s).
    pub hook_climb_rate_mps: f64,
    /// Hook earth x rate (m/s).
    pub hook_x_rate_mps: f64,
    /// Reference height of the hook from the flight-path generator (m).
    pub path_height_m: f64,
    /// Glide-path error h_ref − h_hook (m), positive when below the path.
    pub glide_path_error_m: f64,
    /// Time to touchdown estimated by the generator (s).
    pub time_to_go_s: f64,
    /// Weight of the moving deck in the glide-path anchor (0–1).
    pub compensation_weight: f64,
    /// True airspeed (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack (rad).
    pub alpha_rad: f64,
    /// Pitch angle (rad).
    pub theta_rad: f64,
    /// Measured pitch angle (rad).
    pub theta_measured_rad: f64,
    /// Pitch command from the sink-rate loop or the step (rad).
    pub theta_ref_rad: f64,
    /// Pitch rate (rad/s).
    pub q_radps: f64,
    /// CG climb rate ḣ (m/s).
    pub climb_rate_mps: f64,
    /// Climb-rate command (m/s).
    pub climb_rate_command_mps: f64,
    /// Elevator position (rad).
    pub elevator_rad: f64,
    /// Elevator command (rad).
    pub elevator_command_rad: f64,
    /// Total actual thrust (N).
    pub thrust_n: f64,
    /// Total thrust command (N).
    pub thrust_command_n: f64,
    /// Wind at the aircraft (earth axes).
    pub wind: Wind,
    /// Distance of the CG aft of the ship's pitch centre (m).
    pub distance_aft_m: f64,
    /// The ship's pose.
    pub ship: ShipPose,
    /// The rate of the ship's pose.
    pub ship_rate: ShipPoseRate,
    /// The moving landing point.
    pub aim_point: EarthPoint,
    /// The pitch controller's disturbance estimate (rad/s², O-PD only).
    pub disturbance_estimate_radps2: Option<f64>,
    /// With a loop break set, the value the loop computed at the break (else NaN).
    pub loop_break_output: f64,
}

/// The closed-loop system integrated by the simulation.
#[derive(Debug, Clone)]
pub struct ClosedLoop {
    pub(crate) aircraft: Aircraft,
    pub(crate) hook: HookGeometry,
    pub(crate) ship: ShipMotion,
    pub(crate) deck: DeckGeometry,
    pub(crate) ship_initial_x_m: f64,
    pub(crate) wind: WindModel,
    pub(crate) sensor: PitchSensor,
    pub(crate) pitch: PitchController,
    pub(crate) speed: SpeedController,
    pub(crate) sink_rate: LoopController,
    pub(crate) guidance: LoopController,
    pub(crate) flight_path: FlightPathGenerator,
    pub(crate) deck_filter: DeckMotionFilter,
    pub(crate) predictor: ShipMotionPredictor,
    pub(crate) trim: TrimPoint,
    pub(crate) airspeed_reference_mps: f64,
    pub(crate) mode: LoopMode,
    pub(crate) held: HeldInputs,
    /// Analysis only: the loop cut and the value injected there.
    pub(crate) loop_break: Option<(LoopBreak, f64)>,
}

impl ClosedLoop {
    /// The ship's pose and its rate at time `t`.
    #[inline]
    pub fn ship_pose(&self, ship: &ShipMotionState, t: f64) -> (ShipPose, ShipPoseRate) {
        (
            self.ship.pose(ship, self.ship_initial_x_m, t),
            self.ship.pose_rate(ship),
        )
    }

    /// The wind at the aircraft and (in an approach) the deck reference at (t, x): what
    /// the runner samples at the start of a step and holds over it.
    pub fn step_samples(&self, t: f64, x: &[f64; LOOP_DIMENSION]) -> (Wind, Option<DeckReference>) {
        let s = LoopState::from_array(x);
        let (pose, pose_rate) = self.ship_pose(&s.ship, t);
        let wind = self
            .wind
            .wind(t, pose.distance_aft_of_pitch_centre_m(s.aircraft.x_m));
        let deck = matches!(self.mode, LoopMode::Approach).then(|| {
            let (sin_t, cos_t) = s.aircraft.theta_rad.sin_cos();
            let (hook_x_m, _) = self.hook.position_trig(&s.aircraft, sin_t, cos_t);
            let (hook_x_rate_mps, _) = self.hook.velocity_trig(&s.aircraft, sin_t, cos_t);
            self.deck_reference(&s, &pose, &pose_rate, hook_x_m, hook_x_rate_mps)
        });
        (wind, deck)
    }

    /// The deck reference for the flight-path generator: the mean landing point and the
    /// predicted moving one, by the configured [`DeckMotionPredictor`]: the model's
    /// prediction at the touchdown time (rate zero), or the filtered estimate
    /// `deck_estimate` (ĥ_L, ĥ̇_L).
    #[inline]
    pub fn deck_reference(
        &self,
        state: &LoopState,
        pose: &ShipPose,
        rate: &ShipPoseRate,
        hook_x_m: f64,
        hook_x_rate_mps: f64,
    ) -> DeckReference {
        // Ship level and at its mean height: the aim point sits 81 m aft of the pitch
        // centre at deck height (no trigonometry needed).
        let mean_aim = EarthPoint {
            x_m: pose.pitch_centre_x_m - self.deck.landing_point_aft_of_pitch_centre_m,
            h_m: self.deck.deck_height_m,
        };
        let mean_aim_velocity = EarthVelocity {
            x_mps: rate.pitch_centre_x_rate_mps,
            h_mps: 0.0,
        };
        let (aim, aim_velocity) = match self.flight_path.parameters().deck_motion_predictor {
            DeckMotionPredictor::Model => {
                let horizon_s = self.flight_path.time_to_go_s(
                    hook_x_m,
                    hook_x_rate_mps,
                    mean_aim.x_m,
                    mean_aim_velocity.x_mps,
                );
                let predicted = self.predictor.predict(&self.ship, &state.ship, horizon_s);
                let predicted_pose = ShipPose {
                    heave_m: predicted.heave_m,
                    pitch_rad: predicted.pitch_rad,
                    ..*pose
                };
                (self.deck.aim_point(&predicted_pose), mean_aim_velocity)
            }
            DeckMotionPredictor::FilterLead => {
                let aim = self.deck.aim_point(pose);
                (
                    EarthPoint {
                        x_m: aim.x_m,
                        h_m: state.deck_estimate[0],
                    },
                    EarthVelocity {
                        x_mps: self.deck.velocity_along_deck(pose, rate, 0.0).x_mps,
                        h_mps: state.deck_estimate[1],
                    },
                )
            }
        };
        DeckReference {
            mean_aim,
            mean_aim_velocity,
            aim,
            aim_velocity,
        }
    }

    /// The derivative of the closed loop and the signals at (t, x). Always inlined, so
    /// that in [`OdeSystem::derivative`], which drops the signals, the work done only for
    /// them is optimised away.
    #[inline(always)]
    pub fn evaluate(&self, t: f64, x: &[f64; LOOP_DIMENSION]) -> ([f64; LOOP_DIMENSION], Signals) {
        let s = LoopState::from_array(x);
        let a = &s.aircraft;
        let (pose, pose_rate) = self.ship_pose(&s.ship, t);
        let distance_aft_m = pose.distance_aft_of_pitch_centre_m(a.x_m);
        let wind = match self.held.wind {
            Some(wind) => wind,
            None => self.wind.wind(t, distance_aft_m),
        };
        let (sin_t, cos_t) = a.theta_rad.sin_cos();
        let air = self
            .aircraft
            .air_data_trig(a.u_mps, a.w_mps, sin_t, cos_t, &wind);
        let (hook_x_m, hook_h_m) = self.hook.position_trig(a, sin_t, cos_t);
        let (hook_x_rate_mps, hook_climb_rate_mps) = self.hook.velocity_trig(a, sin_t, cos_t);
        let (_, climb_rate_mps) = a.earth_velocity_trig(sin_t, cos_t);
        let trim = &self.trim;

        // References: flight path → guidance → sink rate → pitch (MODEL.md §5).
        let mut path_height_m = f64::NAN;
        let mut time_to_go_s = f64::INFINITY;
        let mut compensation_weight = 0.0;
        let mut height_error = 0.0;
        let mut climb_rate_command_mps = f64::NAN;
        let mut sink_error = 0.0;
        let mut loop_break_output = f64::NAN;
        let mut theta_ref_rad = match self.mode {
            LoopMode::PitchStep {
                step_rad,
                step_time_s,
            } => trim.theta_rad + if t >= step_time_s { step_rad } else { 0.0 },
            LoopMode::ClimbRate {
                climb_rate_mps: command,
                step_time_s,
                ramp_s,
                theta_feedforward_rad,
            } => {
                let fraction = if t < step_time_s {
                    0.0
                } else if ramp_s > 0.0 {
                    ((t - step_time_s) / ramp_s).min(1.0)
                } else {
                    1.0
                };
                let command = fraction * command;
                let base = trim.theta_rad + fraction * (theta_feedforward_rad - trim.theta_rad);
                climb_rate_command_mps = command;
                sink_error = command - climb_rate_mps;
                base + self
                    .sink_rate
                    .output(sink_error, s.sink_rate_integral_m, 0.0)
            }
            LoopMode::Approach => {
                let deck = match self.held.deck {
                    Some(deck) => deck,
                    None => self.deck_reference(&s, &pose, &pose_rate, hook_x_m, hook_x_rate_mps),
                };
                let path = self.flight_path.reference(hook_x_m, hook_x_rate_mps, &deck);
                path_height_m = path.height_m;
                time_to_go_s = path.time_to_go_s;
                compensation_weight = path.compensation_weight;
                height_error = path.height_m - hook_h_m;
                let height_error_rate = path.climb_rate_mps - hook_climb_rate_mps;
                climb_rate_command_mps = path.climb_rate_mps
                    + self.guidance.output(
                        height_error,
                        s.guidance_integral_m_s,
                        height_error_rate,
                    );
                if let Some((LoopBreak::ClimbRateCommand, injected)) = self.loop_break {
                    loop_break_output = climb_rate_command_mps;
                    climb_rate_command_mps = injected;
                }
                sink_error = climb_rate_command_mps - climb_rate_mps;
                trim.theta_rad
                    + self
                        .sink_rate
                        .output(sink_error, s.sink_rate_integral_m, 0.0)
            }
        };

        if let Some((LoopBreak::PitchCommand, injected)) = self.loop_break {
            loop_break_output = theta_ref_rad;
            theta_ref_rad = injected;
        }

        // Pitch controller on the measured attitude (MODEL.md §3.3, §4).
        let theta_measured_rad = a.theta_rad + self.held.pitch_noise_rad;
        let actuator = self.aircraft.actuator();
        let pitch_inputs = PitchControlInputs {
            theta_ref_rad,
            theta_measured_rad,
            pitch_rate_measured_radps: a.q_radps,
            elevator_actual_rad: a.elevator_rad,
            theta_trim_rad: trim.theta_rad,
            elevator_trim_rad: trim.elevator_rad,
            elevator_saturation: ElevatorSaturation::from_position(
                a.elevator_rad,
                actuator.min_rad(),
                actuator.max_rad(),
                1e-9,
            ),
        };
        let pitch_state = self.pitch.state_from_array(&s.pitch_controller);
        let mut elevator_command_rad = self.pitch.elevator_command_rad(&pitch_state, &pitch_inputs);
        if let Some((LoopBreak::ElevatorCommand, injected)) = self.loop_break {
            loop_break_output = elevator_command_rad;
            elevator_command_rad = injected;
        }

        // Speed loop (MODEL.md §5).
        let speed_error = self.airspeed_reference_mps - air.airspeed_mps;
        let mut thrust_command_n = self.speed.thrust_command_n(speed_error, s.speed_integral_m);
        if let Some((LoopBreak::ThrustCommand, injected)) = self.loop_break {
            loop_break_output = thrust_command_n;
            thrust_command_n = injected;
        }

        let commands = AircraftCommands {
            elevator_rad: elevator_command_rad,
            thrust_n: thrust_command_n,
        };
        let aircraft_rate = self
            .aircraft
            .derivative_from(a, &commands, &air, sin_t, cos_t);
        let ship_rate = self.ship.derivative(&s.ship, self.held.ship_noise);
        let aim_point = self.deck.aim_point(&pose);
        let pitch_rate = self
            .pitch
            .derivative_array(&s.pitch_controller, &pitch_inputs);
        let (sink_integral_rate, guidance_integral_rate) = match self.mode {
            LoopMode::PitchStep { .. } => (0.0, 0.0),
            LoopMode::ClimbRate { .. } => (
                self.sink_rate
                    .integral_rate(sink_error, s.sink_rate_integral_m, 0.0),
                0.0,
            ),
            LoopMode::Approach => (
                self.sink_rate
                    .integral_rate(sink_error, s.sink_rate_integral_m, 0.0),
                self.guidance
                    .integral_rate(height_error, s.guidance_integral_m_s, 0.0),
            ),
        };
        let derivative = LoopState {
            aircraft: aircraft_rate,
            ship: ship_rate,
            pitch_controller: pitch_rate,
            speed_integral_m: self.speed.integral_rate(speed_error, s.speed_integral_m),
            sink_rate_integral_m: sink_integral_rate,
            guidance_integral_m_s: guidance_integral_rate,
            deck_estimate: self.deck_filter.derivative(s.deck_estimate, aim_point.h_m),
        }
        .to_array();
        let signals = Signals {
            time_s: t,
            x_m: a.x_m,
            h_m: a.h_m,
            hook_x_m,
            hook_h_m,
            hook_climb_rate_mps,
            hook_x_rate_mps,
            path_height_m,
            glide_path_error_m: height_error,
            time_to_go_s,
            compensation_weight,
            airspeed_mps: air.airspeed_mps,
            alpha_rad: air.alpha_rad,
            theta_rad: a.theta_rad,
            theta_measured_rad,
            theta_ref_rad,
            q_radps: a.q_radps,
            climb_rate_mps,
            climb_rate_command_mps,
            elevator_rad: a.elevator_rad,
            elevator_command_rad,
            thrust_n: a.total_thrust_n(),
            thrust_command_n,
            wind,
            distance_aft_m,
            ship: pose,
            ship_rate: pose_rate,
            aim_point,
            disturbance_estimate_radps2: pitch_state.disturbance_estimate_radps2(),
            loop_break_output,
        };
        (derivative, signals)
    }
}

impl OdeSystem<LOOP_DIMENSION> for ClosedLoop {
    #[inline]
    fn derivative(&self, t: f64, x: &[f64; LOOP_DIMENSION]) -> [f64; LOOP_DIMENSION] {
        self.evaluate(t, x).0
    }

    fn constrain(&self, x: &mut [f64; LOOP_DIMENSION]) {
        let mut elevator = x[8];
        let mut rate = x[9];
        self.aircraft.actuator().constrain(&mut elevator, &mut rate);
        x[8] = elevator;
        x[9] = rate;
    }
}
