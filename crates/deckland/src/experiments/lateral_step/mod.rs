//! A bank-angle or sideslip step of the 6-DOF aircraft from the approach trim (issue 26,
//! docs/lateral-control.md): the roll law flies the bank channel, the yaw law the sideslip
//! channel, the 80 Hz flight computer holds both.
//!
//! - **Plant**: `aircraft::six_dof` at the approach trim (69.1 m/s, level, landing
//!   configuration, 150 m), RK4 at 1 ms, the actuators' limits applied after each step.
//!   The longitudinal axis is left at trim: elevator and thrust commands held at their
//!   trim values (no pitch law; a 10° bank asks 1.5 % more lift, which the run's few
//!   seconds leave as a slow sink).
//! - **Flight computer**: every 12.5 ms (80 Hz; frames of 12 or 13 steps of 1 ms) it samples
//!   the measurements, and the surface commands it computes from them act one frame later
//!   and are held for a frame (sample-and-hold plus one frame of computing: the 18.75 ms
//!   the design assumes). The laws' states are integrated with the plant on the held
//!   inputs, the measurement's age growing from the sample.
//! - **Command**: the step at [`LATERAL_STEP_TIME_S`], shaped as the design code shapes a
//!   step for the channel's surface (`control::design::design_command`: 60 % of the rate
//!   limit, 80 % of the travel), with its feed-forward; the other channel is commanded
//!   to zero (β = 0: coordination; φ = 0).
//! - **Adverse**: lateral turbulence (a first-order Dryden v-gust, σ_v = σ_u = 0.540 m/s,
//!   L = 30.48 m, the project's free-air turbulence form, docs/model.md §3.2, §10.6; the
//!   loop has no lateral turbulence of its own yet, so it is written here), bank noise of
//!   the pitch sensor's form (white σ 0.001 rad per sample plus 0.001 rad at 7 rad/s,
//!   docs/model.md §3.3, an assumption for the bank channel) and air-data sideslip noise
//!   (white σ 0.2°, docs/model.md §10.7, an assumption). No law reads the heading, so a
//!   heading sensor's noise does not enter this experiment.
//! - **Gust**: optionally a 1 − cos crosswind gust (earth y) to test coordination.

use crate::aircraft::six_dof::{
    linearize_six_dof, SixDofAircraft, SixDofCommands, SixDofState, SixDofTrimPoint,
};
use crate::control::design::command_shaping::JerkLimitedStep;
use crate::control::design::{design_command, DesignRequest};
use crate::control::lateral::design::channel_hardware;
use crate::control::lateral::{
    ChannelInputs, LateralChannel, RollLaw, RollLawInputs, SideslipBlend, YawLaw, YawLawInputs,
};
use crate::control::pitch::ElevatorSaturation;
use crate::environment::Wind;
use crate::parameters::readable_number;
use crate::random::{NoiseStream, RandomStreams};
use response::measure;

mod response;
mod setup;
mod spec;

pub use response::{LateralStepReport, LateralStepResponse, LateralStepRun};
pub use setup::{LateralLaws, LateralSetup};
pub use spec::{CrosswindGust, LateralAxis, LateralSample, LateralStep, LateralStepError};

/// Time of the step after the start (s).
pub const LATERAL_STEP_TIME_S: f64 = 1.0;
/// Half-width of the settling band as a fraction of the step (issue 26: ±5 %).
pub const LATERAL_SETTLING_BAND_FRACTION: f64 = 0.05;
/// Integration step (s).
const DT_S: f64 = 0.001;
/// The flight computer's frame (s): 80 Hz.
const FRAME_S: f64 = 1.0 / 80.0;
/// Altitude of the run (m).
const ALTITUDE_M: f64 = 150.0;
/// The lateral turbulence: σ_v (m/s) and scale (m), the project's free-air values.
const TURBULENCE_SIGMA_V_MPS: f64 = 0.540;
const TURBULENCE_SCALE_M: f64 = 30.48;
/// Bank sensor: white σ per sample, sinusoid amplitude (rad) and frequency (rad/s).
const BANK_WHITE_SIGMA_RAD: f64 = 0.001;
const BANK_SINUSOID_RAD: f64 = 0.001;
const BANK_SINUSOID_RADPS: f64 = 7.0;
/// Air-data sideslip: white σ per sample (rad), 0.2°.
const SIDESLIP_WHITE_SIGMA_RAD: f64 = 0.2 * std::f64::consts::PI / 180.0;
/// Largest bank or sideslip step (deg).
pub const MAX_LATERAL_STEP_DEG: f64 = 30.0;
/// Smallest nonzero bank or sideslip step (deg): a sixth of the bank sensor's noise
/// (0.057° σ); below it the step's metrics, which are shares of the step (overshoot,
/// the 5 % settling band), would measure the trim's numerical residue, not the response.
pub const MIN_LATERAL_STEP_DEG: f64 = 0.01;
/// Tolerance of "on the rate limit" (deg/s).
const RATE_LIMIT_TOLERANCE_DEGPS: f64 = 1e-6;

/// The sensors and turbulence of an adverse run, each on its own stream.
struct Disturbances {
    turbulence_v_mps: f64,
    turbulence: NoiseStream,
    bank_noise: NoiseStream,
    sideslip_noise: NoiseStream,
}

impl Disturbances {
    /// The streams of `streams`, the turbulence drawn from its stationary distribution
    /// in an `adverse` run (else calm).
    fn new(streams: &RandomStreams, adverse: bool) -> Self {
        let mut disturbances = Self {
            turbulence_v_mps: 0.0,
            turbulence: streams.stream("lateral_turbulence_v"),
            bank_noise: streams.stream("bank_noise"),
            sideslip_noise: streams.stream("sideslip_noise"),
        };
        if adverse {
            disturbances.turbulence_v_mps =
                TURBULENCE_SIGMA_V_MPS * disturbances.turbulence.standard_normal();
        }
        disturbances
    }

    /// The bank and air-data sideslip sensors' noise (rad) of a frame sampled at `t`
    /// (s); none outside an `adverse` run.
    fn sensor_noise(&mut self, adverse: bool, t: f64) -> (f64, f64) {
        if adverse {
            (
                BANK_WHITE_SIGMA_RAD * self.bank_noise.standard_normal()
                    + BANK_SINUSOID_RAD * (BANK_SINUSOID_RADPS * t).sin(),
                SIDESLIP_WHITE_SIGMA_RAD * self.sideslip_noise.standard_normal(),
            )
        } else {
            (0.0, 0.0)
        }
    }

    /// The turbulence one step of `DT_S` on, flown through at `speed_mps` (m/s): the
    /// first-order Dryden form (module docs).
    fn advance_turbulence(&mut self, speed_mps: f64) {
        let decay = (-DT_S * speed_mps / TURBULENCE_SCALE_M).exp();
        self.turbulence_v_mps = decay * self.turbulence_v_mps
            + TURBULENCE_SIGMA_V_MPS
                * (1.0 - decay * decay).sqrt()
                * self.turbulence.standard_normal();
    }
}

/// The lateral signals of a plant state: (φ, β, p, −r) and the air data's sideslip.
fn sideslip_rad(aircraft: &SixDofAircraft, state: &SixDofState, wind: &Wind) -> f64 {
    let air = aircraft.air_velocity(
        [state.u_mps, state.v_mps, state.w_mps],
        [state.phi_rad, state.theta_rad, state.psi_rad],
        wind,
    );
    aircraft.air_data(air).beta_rad
}

const PLANT: usize = SixDofState::DIMENSION;
const LAW: usize = 3;
const N: usize = PLANT + 2 * LAW;

/// Flies `step` from the approach trim of `setup` with the roll law `roll` and the yaw
/// law `yaw` (module docs), and measures the stepped channel.
pub fn fly_lateral_step(
    setup: &LateralSetup,
    step: &LateralStep,
    roll: &dyn RollLaw,
    yaw: &dyn YawLaw,
) -> Result<LateralStepRun, LateralStepError> {
    check_step(step, roll, yaw)?;
    let (aircraft, trim) = (&setup.aircraft, &setup.trim);
    let channel = match step.axis {
        LateralAxis::Roll => LateralChannel::Roll,
        LateralAxis::Yaw => LateralChannel::Yaw,
    };
    let shaped = shaped_command(aircraft, trim, step, channel)?;
    let mut disturbances = Disturbances::new(&RandomStreams::new(step.seed), step.adverse);
    let mut x = [0.0; N];
    x[..PLANT].copy_from_slice(&trim.state(0.0, 0.0, ALTITUDE_M).to_array());
    let mut computer = FlightComputer::new(trim, step)?;
    let mut samples = Vec::new();
    let steps = (step.seconds / DT_S).round() as usize;
    let record_every = ((step.record_interval_s / DT_S).round() as usize).max(1);
    let mut diverged = false;
    for k in 0..=steps {
        let t = k as f64 * DT_S;
        let plant = SixDofState::from_array(x[..PLANT].try_into().expect("plant slice"));
        let wind = Wind {
            x_mps: 0.0,
            y_mps: disturbances.turbulence_v_mps + step.gust.map_or(0.0, |g| g.wind_mps(t)),
            z_mps: 0.0,
        };
        let beta = sideslip_rad(aircraft, &plant, &wind);
        let reference = StepReference::at(&shaped, step.axis, trim, t);
        // The flight computer's frame: sample, compute, and act one frame later.
        if computer.starts_frame(t) {
            let (bank_noise, beta_noise) = disturbances.sensor_noise(step.adverse, t);
            let measured = (
                plant.phi_rad + bank_noise,
                computer.measure_sideslip(beta + beta_noise, aircraft, &plant, &wind),
            );
            let inputs = law_inputs(aircraft, trim, &plant, &reference, step.axis, measured);
            computer.compute(k == 0, inputs, (roll, yaw), &mut x);
        }
        if k % record_every == 0 {
            samples.push(lateral_sample(t, &plant, &reference, beta, &wind));
        }
        if k == steps {
            break;
        }
        let plant = rk4_step(
            &mut x,
            t,
            &computer.frame,
            &wind,
            step.gust,
            aircraft,
            (roll, yaw),
        );
        if step.adverse {
            disturbances.advance_turbulence(trim.speed_mps);
        }
        if !x.iter().all(|v| v.is_finite()) || plant.phi_rad.abs() > 1.5 {
            diverged = true;
            break;
        }
    }
    let mut response = measure(step, channel, &samples, &shaped, aircraft, diverged)?;
    response.controller = match channel {
        LateralChannel::Roll => roll.label(),
        LateralChannel::Yaw => yaw.label(),
    }
    .to_owned();
    Ok(LateralStepRun { samples, response })
}

/// Refuses a step out of its ranges (a bank or sideslip step within ±30°, 2–600 s) and
/// laws with more states than the run holds.
fn check_step(
    step: &LateralStep,
    roll: &dyn RollLaw,
    yaw: &dyn YawLaw,
) -> Result<(), LateralStepError> {
    let bad = |field: &str, value: f64, expected: &str| {
        Err(LateralStepError::Setup(format!(
            "lateral step `{field}` = {} is out of range: expected {expected}",
            readable_number(value)
        )))
    };
    let magnitude = step.step_deg.abs();
    if !(step.step_deg.is_finite()
        && magnitude <= MAX_LATERAL_STEP_DEG
        && (magnitude == 0.0 || magnitude >= MIN_LATERAL_STEP_DEG))
    {
        return bad(
            "step_deg",
            step.step_deg,
            "0 (no step) or a bank or sideslip step of 0.01° to 30° either way",
        );
    }
    if !(step.seconds.is_finite() && step.seconds >= 2.0 && step.seconds <= 600.0) {
        return bad("seconds", step.seconds, "in [2, 600]");
    }
    if roll.state_names().len() > LAW || yaw.state_names().len() > LAW {
        return Err(LateralStepError::Setup(format!(
            "a lateral law has at most {LAW} states"
        )));
    }
    Ok(())
}

/// The step's command, shaped as the design code shapes a step for `channel`'s surface
/// (module docs); a flat one for a zero step.
fn shaped_command(
    aircraft: &SixDofAircraft,
    trim: &SixDofTrimPoint,
    step: &LateralStep,
    channel: LateralChannel,
) -> Result<JerkLimitedStep, LateralStepError> {
    let model = linearize_six_dof(aircraft, trim);
    let hardware = channel_hardware(aircraft, &model, channel);
    if step.step_deg == 0.0 {
        return Ok(JerkLimitedStep::new(0.0, 1.0, 1.0));
    }
    let request = DesignRequest {
        design_step_deg: step.step_deg.abs(),
        ..DesignRequest::default()
    };
    let (fastest, _) =
        design_command(&hardware, &request).map_err(|e| LateralStepError::Setup(e.to_string()))?;
    Ok(JerkLimitedStep::new(
        step.step_deg.to_radians(),
        fastest.jerk_radps3,
        fastest.acceleration_radps2,
    ))
}

/// What the flight computer holds over a frame: the commands acting, the laws' inputs
/// sampled at its start, and when (s).
struct Frame {
    commands: SixDofCommands,
    roll_inputs: RollLawInputs,
    yaw_inputs: YawLawInputs,
    sample_time_s: f64,
}

/// The commands of both laws at one instant: the bank and sideslip commands (rad), and
/// the stepped channel's rate (rad/s) and acceleration (rad/s²) fed forward.
struct StepReference {
    bank_rad: f64,
    sideslip_rad: f64,
    rate_radps: f64,
    acceleration_radps2: f64,
}

impl StepReference {
    /// The commands at `t` (s): trim until [`LATERAL_STEP_TIME_S`], then the `shaped`
    /// step added to the stepped `axis`'s trim.
    fn at(shaped: &JerkLimitedStep, axis: LateralAxis, trim: &SixDofTrimPoint, t: f64) -> Self {
        let (angle_ref, rate_radps, acceleration_radps2) = if t < LATERAL_STEP_TIME_S {
            (0.0, 0.0, 0.0)
        } else {
            let r = shaped.reference(t - LATERAL_STEP_TIME_S);
            (r.theta_rad, r.rate_radps, r.acceleration_radps2)
        };
        let (bank_rad, sideslip_rad) = match axis {
            LateralAxis::Roll => (trim.phi_rad + angle_ref, trim.sideslip_rad),
            LateralAxis::Yaw => (trim.phi_rad, trim.sideslip_rad + angle_ref),
        };
        Self {
            bank_rad,
            sideslip_rad,
            rate_radps,
            acceleration_radps2,
        }
    }

    /// The rate and acceleration fed forward to the channel: the reference's when it is
    /// the stepped one, else none.
    fn feed(&self, stepped: bool) -> (f64, f64) {
        if stepped {
            (self.rate_radps, self.acceleration_radps2)
        } else {
            (0.0, 0.0)
        }
    }
}

/// The flight computer of the run: at each frame's start it acts on the commands it
/// computed in the last, samples the sensors and computes the next (module docs).
struct FlightComputer {
    /// What acts over the frame.
    frame: Frame,
    /// The commands computed this frame, acting from the next.
    pending: SixDofCommands,
    /// The trim commands: elevator and thrust stay at trim.
    commands_trim: SixDofCommands,
    /// The frame now, −1 before the first.
    frame_index: i64,
    /// Time since the last sample at the frame's start (s).
    frame_elapsed_s: f64,
    /// With a blend, the sideslip the yaw law reads is blended with the inertial
    /// sideslip rate; this is the last frame's rate (rad/s).
    blend: Option<SideslipBlend>,
    last_inertial_rate_radps: f64,
}

impl FlightComputer {
    /// A computer holding `trim`'s commands, before its first frame, with the sideslip
    /// blend `step` asks for.
    fn new(trim: &SixDofTrimPoint, step: &LateralStep) -> Result<Self, LateralStepError> {
        let commands_trim = SixDofCommands {
            elevator_rad: trim.elevator_rad,
            thrust_n: trim.thrust_n,
            aileron_rad: trim.aileron_rad,
            rudder_rad: trim.rudder_rad,
        };
        Ok(Self {
            frame: Frame {
                commands: commands_trim,
                roll_inputs: RollLawInputs::default(),
                yaw_inputs: YawLawInputs::default(),
                sample_time_s: 0.0,
            },
            pending: commands_trim,
            commands_trim,
            frame_index: -1,
            frame_elapsed_s: 0.0,
            blend: (step.sideslip_blend_crossover_radps.map(SideslipBlend::new)).transpose()?,
            last_inertial_rate_radps: 0.0,
        })
    }

    /// Whether a frame starts at `t` (s); if one does, the last frame's commands act
    /// from now and the sensors are sampled now.
    fn starts_frame(&mut self, t: f64) -> bool {
        let frame_now = (t / FRAME_S + 1e-9).floor() as i64;
        if frame_now == self.frame_index {
            return false;
        }
        self.frame_index = frame_now;
        self.frame.commands = self.pending;
        self.frame_elapsed_s = t - self.frame.sample_time_s;
        self.frame.sample_time_s = t;
        true
    }

    /// The sideslip measured at the frame's start (rad) from the air data's
    /// `air_data_beta` (rad) and, with a blend, the inertial rate β̇ ≈ v̇/V over the
    /// time since the last sample (trapezoid), with the frame's commands.
    fn measure_sideslip(
        &mut self,
        air_data_beta: f64,
        aircraft: &SixDofAircraft,
        plant: &SixDofState,
        wind: &Wind,
    ) -> f64 {
        match self.blend.as_mut() {
            None => air_data_beta,
            Some(blend) => {
                let airspeed = norm(aircraft.air_velocity(
                    [plant.u_mps, plant.v_mps, plant.w_mps],
                    [plant.phi_rad, plant.theta_rad, plant.psi_rad],
                    wind,
                ));
                let rate = aircraft.derivative(plant, &self.frame.commands, wind).v_mps / airspeed;
                let mean_rate = 0.5 * (rate + self.last_inertial_rate_radps);
                self.last_inertial_rate_radps = rate;
                blend.update(air_data_beta, mean_rate, self.frame_elapsed_s)
            }
        }
    }

    /// Computes the next frame's commands from the laws' `inputs` and their states in
    /// `x`; on the `first` frame the laws' states start from the inputs and the commands
    /// act at once.
    fn compute(
        &mut self,
        first: bool,
        inputs: (RollLawInputs, YawLawInputs),
        (roll, yaw): (&dyn RollLaw, &dyn YawLaw),
        x: &mut [f64; N],
    ) {
        let frame = &mut self.frame;
        (frame.roll_inputs, frame.yaw_inputs) = inputs;
        if first {
            roll.initial_state(&frame.roll_inputs, &mut x[PLANT..PLANT + LAW]);
            yaw.initial_state(&frame.yaw_inputs, &mut x[PLANT + LAW..]);
        }
        self.pending = SixDofCommands {
            aileron_rad: roll.surface_command_rad(&x[PLANT..PLANT + LAW], &frame.roll_inputs),
            rudder_rad: yaw.surface_command_rad(&x[PLANT + LAW..], &frame.yaw_inputs),
            ..self.commands_trim
        };
        if first {
            frame.commands = self.pending;
        }
    }
}

/// The roll and yaw laws' inputs at a frame's start: the `reference`'s commands (the
/// stepped `axis` fed forward), the `measured` bank and sideslip (rad), the plant's rates
/// and surfaces, and the trim.
fn law_inputs(
    aircraft: &SixDofAircraft,
    trim: &SixDofTrimPoint,
    plant: &SixDofState,
    reference: &StepReference,
    axis: LateralAxis,
    (bank_measured_rad, sideslip_measured_rad): (f64, f64),
) -> (RollLawInputs, YawLawInputs) {
    let (roll_rate_ref, roll_acc_ref) = reference.feed(axis == LateralAxis::Roll);
    let (yaw_rate_ref, yaw_acc_ref) = reference.feed(axis == LateralAxis::Yaw);
    let roll = RollLawInputs(ChannelInputs {
        command_rad: reference.bank_rad,
        command_rate_radps: roll_rate_ref,
        command_acceleration_radps2: roll_acc_ref,
        measured_rad: bank_measured_rad,
        measurement_age_s: 0.0,
        rate_measured_radps: plant.p_radps,
        surface_actual_rad: plant.aileron_rad,
        trim_angle_rad: trim.phi_rad,
        surface_trim_rad: trim.aileron_rad,
        surface_saturation: saturation(aircraft.aileron(), plant.aileron_rad),
    });
    let yaw = YawLawInputs(ChannelInputs {
        command_rad: reference.sideslip_rad,
        command_rate_radps: yaw_rate_ref,
        command_acceleration_radps2: yaw_acc_ref,
        measured_rad: sideslip_measured_rad,
        measurement_age_s: 0.0,
        rate_measured_radps: -plant.r_radps,
        surface_actual_rad: plant.rudder_rad,
        trim_angle_rad: trim.sideslip_rad,
        surface_trim_rad: trim.rudder_rad,
        surface_saturation: saturation(aircraft.rudder(), plant.rudder_rad),
    });
    (roll, yaw)
}

/// The recorded sample at `t` (s) of `plant` flying `reference`, with the air data's
/// sideslip `beta` (rad) in `wind`.
fn lateral_sample(
    t: f64,
    plant: &SixDofState,
    reference: &StepReference,
    beta: f64,
    wind: &Wind,
) -> LateralSample {
    LateralSample {
        time_s: t,
        bank_command_deg: reference.bank_rad.to_degrees(),
        bank_deg: plant.phi_rad.to_degrees(),
        sideslip_command_deg: reference.sideslip_rad.to_degrees(),
        sideslip_deg: beta.to_degrees(),
        heading_deg: plant.psi_rad.to_degrees(),
        roll_rate_degps: plant.p_radps.to_degrees(),
        yaw_rate_degps: plant.r_radps.to_degrees(),
        aileron_deg: plant.aileron_rad.to_degrees(),
        aileron_rate_degps: plant.aileron_rate_radps.to_degrees(),
        rudder_deg: plant.rudder_rad.to_degrees(),
        rudder_rate_degps: plant.rudder_rate_radps.to_degrees(),
        wind_y_mps: wind.y_mps,
        altitude_m: plant.h_m,
    }
}

/// One RK4 step of `DT_S` from `t` (s) over the plant and both laws' states in `x`, on
/// the `frame`'s held commands and inputs (the measurement's age growing from its
/// sample) and the wind at `t`, its `gust` moving with time; the actuators' limits
/// applied after. Returns the plant's new state.
fn rk4_step(
    x: &mut [f64; N],
    t: f64,
    frame: &Frame,
    wind: &Wind,
    gust: Option<CrosswindGust>,
    aircraft: &SixDofAircraft,
    (roll, yaw): (&dyn RollLaw, &dyn YawLaw),
) -> SixDofState {
    let age0 = t - frame.sample_time_s;
    let derivative = |at: f64, state: &[f64; N]| -> [f64; N] {
        let plant = SixDofState::from_array(state[..PLANT].try_into().expect("plant"));
        let mut rate = [0.0; N];
        let wind_at = Wind {
            y_mps: wind.y_mps - gust.map_or(0.0, |g| g.wind_mps(t))
                + gust.map_or(0.0, |g| g.wind_mps(at)),
            ..*wind
        };
        rate[..PLANT].copy_from_slice(
            &aircraft
                .derivative(&plant, &frame.commands, &wind_at)
                .to_array(),
        );
        let age = age0 + (at - t);
        let mut roll_now = frame.roll_inputs;
        roll_now.0.measurement_age_s = age;
        let mut yaw_now = frame.yaw_inputs;
        yaw_now.0.measurement_age_s = age;
        let (roll_rate, yaw_rate) = rate[PLANT..].split_at_mut(LAW);
        roll.derivative(&state[PLANT..PLANT + LAW], &roll_now, roll_rate);
        yaw.derivative(&state[PLANT + LAW..], &yaw_now, yaw_rate);
        rate
    };
    let k1 = derivative(t, x);
    let k2 = derivative(t + 0.5 * DT_S, &add(x, &k1, 0.5 * DT_S));
    let k3 = derivative(t + 0.5 * DT_S, &add(x, &k2, 0.5 * DT_S));
    let k4 = derivative(t + DT_S, &add(x, &k3, DT_S));
    for i in 0..N {
        x[i] += DT_S / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
    }
    let mut plant = SixDofState::from_array(x[..PLANT].try_into().expect("plant"));
    aircraft.constrain(&mut plant);
    x[..PLANT].copy_from_slice(&plant.to_array());
    plant
}

fn norm(v: [f64; 3]) -> f64 {
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

fn add(x: &[f64; N], k: &[f64; N], h: f64) -> [f64; N] {
    let mut out = *x;
    for i in 0..N {
        out[i] += h * k[i];
    }
    out
}

fn saturation(
    actuator: &crate::aircraft::ElevatorActuator,
    position_rad: f64,
) -> ElevatorSaturation {
    ElevatorSaturation::from_position(position_rad, actuator.min_rad(), actuator.max_rad(), 1e-8)
}
