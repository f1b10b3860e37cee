//! Building the closed loop from a scenario: models, trim, linearisation, controllers and
//! the initial state.

use super::closed_loop::{ClosedLoop, HeldInputs, LoopMode, LoopState};
use crate::aircraft::{Aircraft, AircraftError, AircraftState};
use crate::analysis::{linearize, trim, TrimError, TrimPoint, TrimRequest};
use crate::control::pitch::{PitchController, PitchPlantDerivatives};
use crate::control::{ControlError, DeckMotionFilter, FlightPathGenerator, SpeedController};
use crate::environment::{
    mean_wind, EnvironmentError, ShipMotion, ShipMotionPredictor, Wind, WindModel,
};
use crate::random::{stream_names, NoiseStream, RandomStreams};
use crate::scenario::{Mission, Scenario};
use crate::sensors::PitchSensor;

/// Why a simulation could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SimulationError {
    /// An aircraft parameter is invalid.
    #[error("aircraft: {0}")]
    Aircraft(#[from] AircraftError),
    /// An environment parameter is invalid.
    #[error("environment: {0}")]
    Environment(#[from] EnvironmentError),
    /// A controller parameter is invalid.
    #[error("control: {0}")]
    Control(#[from] ControlError),
    /// The start condition cannot be trimmed.
    #[error("cannot trim the start condition: {0}")]
    Trim(#[from] TrimError),
    /// A scenario value outside its allowed range.
    #[error("scenario field `{field}` = {value} is out of range: expected {expected}")]
    OutOfRange {
        /// The field's path in the scenario.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
}

fn check_range(
    field: &'static str,
    value: f64,
    min: f64,
    max: f64,
    expected: &'static str,
) -> Result<(), SimulationError> {
    if value.is_finite() && value >= min && value <= max {
        Ok(())
    } else {
        Err(SimulationError::OutOfRange {
            field,
            value,
            expected,
        })
    }
}

/// The checks shared by the fixed-length missions (pitch step, sink rate).
fn check_timed_mission(
    step_time_s: f64,
    duration_s: f64,
    altitude_m: f64,
) -> Result<(), SimulationError> {
    check_range(
        "mission.duration_s",
        duration_s,
        0.1,
        3600.0,
        "a duration between 0.1 and 3600 s",
    )?;
    check_range(
        "mission.step_time_s",
        step_time_s,
        0.0,
        duration_s,
        "a time within the run",
    )?;
    check_range(
        "mission.altitude_m",
        altitude_m,
        30.0,
        10_000.0,
        "an altitude between 30 and 10000 m",
    )
}

impl Scenario {
    /// Checks every field; the error names the first bad one.
    pub fn validate(&self) -> Result<(), SimulationError> {
        check_range(
            "time_step_s",
            self.time_step_s,
            1e-5,
            0.01,
            "a step between 0.00001 and 0.01 s",
        )?;
        check_range(
            "max_time_s",
            self.max_time_s,
            1.0,
            3600.0,
            "a limit between 1 and 3600 s",
        )?;
        check_range(
            "approach.start_range_m",
            self.approach.start_range_m,
            200.0,
            10_000.0,
            "a range between 200 and 10000 m",
        )?;
        check_range(
            "approach.airspeed_mps",
            self.approach.airspeed_mps,
            40.0,
            150.0,
            "an airspeed between 40 and 150 m/s",
        )?;
        check_range(
            "approach.start_height_offset_m",
            self.approach.start_height_offset_m,
            -50.0,
            50.0,
            "an offset between -50 and 50 m",
        )?;
        check_range(
            "outcome.hard_landing_sink_rate_mps",
            self.outcome.hard_landing_sink_rate_mps,
            0.0,
            50.0,
            "a sink rate between 0 and 50 m/s",
        )?;
        check_range(
            "outcome.min_airspeed_mps",
            self.outcome.min_airspeed_mps,
            0.0,
            100.0,
            "an airspeed between 0 and 100 m/s",
        )?;
        match self.mission {
            Mission::Approach => {}
            Mission::PitchStep {
                step_deg,
                step_time_s,
                duration_s,
                start_distance_aft_m,
                altitude_m,
            } => {
                check_range(
                    "mission.step_deg",
                    step_deg,
                    -20.0,
                    20.0,
                    "a step between -20 and 20 deg",
                )?;
                check_range(
                    "mission.start_distance_aft_m",
                    start_distance_aft_m,
                    -10_000.0,
                    20_000.0,
                    "a distance between -10000 and 20000 m",
                )?;
                check_timed_mission(step_time_s, duration_s, altitude_m)?;
            }
            Mission::SinkRate {
                sink_rate_mps,
                step_time_s,
                ramp_s,
                duration_s,
                altitude_m,
            } => {
                check_range(
                    "mission.sink_rate_mps",
                    sink_rate_mps,
                    -20.0,
                    20.0,
                    "a sink rate between -20 and 20 m/s",
                )?;
                check_range(
                    "mission.ramp_s",
                    ramp_s,
                    0.0,
                    duration_s,
                    "a ramp time within the run",
                )?;
                check_timed_mission(step_time_s, duration_s, altitude_m)?;
            }
        }
        self.aircraft.hook.validate()?;
        self.environment.validate()?;
        let control = &self.control;
        control.speed.validate()?;
        control.sink_rate.validate()?;
        control.guidance.validate()?;
        control.flight_path.validate()?;
        Ok(())
    }
}

/// The random streams a run draws from step by step.
#[derive(Debug, Clone)]
pub(crate) struct StepStreams {
    pub ship_heave: NoiseStream,
    pub ship_pitch: NoiseStream,
}

/// Everything [`super::Simulation`] needs to start.
pub(crate) struct Setup {
    pub system: ClosedLoop,
    pub initial: LoopState,
    pub streams: StepStreams,
    pub end_time_s: f64,
    pub initial_airspeed_mps: f64,
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

pub(crate) fn build(scenario: &Scenario) -> Result<Setup, SimulationError> {
    scenario.validate()?;
    let section = &scenario.aircraft;
    let aircraft = Aircraft::new(
        section.parameters,
        section.aerodynamics(),
        section.engines,
        section.elevator_actuator,
    )?;
    let env = &scenario.environment;
    let streams = RandomStreams::new(scenario.seed);
    let ship = ShipMotion::new(env.ship)?;
    let mut ship_heave = streams.stream(stream_names::SHIP_HEAVE);
    let mut ship_pitch = streams.stream(stream_names::SHIP_PITCH);
    let ship_state = ship.stationary_initial_state(&mut ship_heave, &mut ship_pitch);
    let wind = WindModel::new(env.wind, env.ship.forward_speed_mps, &streams)?;
    let sensor = PitchSensor::new(env.pitch_noise, &streams)?;
    let steady_wind = if env.wind.mean_wind {
        mean_wind(env.wind.wind_over_deck_mps, env.ship.forward_speed_mps)
    } else {
        Wind::default()
    };
    let airspeed = scenario.approach.airspeed_mps;
    let deck = env.deck;
    let ship_initial_x_m = deck.landing_point_aft_of_pitch_centre_m;
    let flight_path = FlightPathGenerator::new(scenario.control.flight_path)?;
    let slope = scenario.control.flight_path.glide_slope_deg.to_radians();

    let (gamma, mode, end_time_s) = match scenario.mission {
        Mission::Approach => (
            approach_flight_path_angle(airspeed, slope, &steady_wind, env.ship.forward_speed_mps),
            LoopMode::Approach,
            scenario.max_time_s,
        ),
        Mission::PitchStep {
            step_deg,
            step_time_s,
            duration_s,
            ..
        } => (
            0.0,
            LoopMode::PitchStep {
                step_rad: step_deg.to_radians(),
                step_time_s,
            },
            duration_s,
        ),
        Mission::SinkRate {
            sink_rate_mps,
            step_time_s,
            ramp_s,
            duration_s,
            ..
        } => {
            let descent = trim(
                &aircraft,
                &TrimRequest {
                    speed_mps: airspeed,
                    flight_path_angle_rad: -(sink_rate_mps / airspeed).clamp(-1.0, 1.0).asin(),
                },
            )?;
            (
                0.0,
                LoopMode::ClimbRate {
                    climb_rate_mps: -sink_rate_mps,
                    step_time_s,
                    ramp_s,
                    theta_feedforward_rad: descent.theta_rad,
                },
                duration_s,
            )
        }
    };
    let trim_point: TrimPoint = trim(
        &aircraft,
        &TrimRequest {
            speed_mps: airspeed,
            flight_path_angle_rad: gamma,
        },
    )?;
    let model = linearize(&aircraft, &trim_point);
    let plant = PitchPlantDerivatives {
        dqdot_dq_per_s: model.pitch_damping_per_s(),
        dqdot_delevator_per_s2: model.elevator_effectiveness_per_s2(),
    };
    let pitch = PitchController::new(&scenario.control.pitch, plant)?;
    let speed = SpeedController::new(
        &scenario.control.speed,
        aircraft.parameters().mass_kg,
        trim_point.thrust_n,
        aircraft.engines().max_total_thrust_n(),
    );

    // Initial position.
    let hook = section.hook;
    let placeholder = trim_point.state(0.0, 0.0, &steady_wind);
    let (hook_dx, hook_dh) = hook.position(&placeholder);
    let (x_m, h_m) = match scenario.mission {
        Mission::Approach => {
            let range = scenario.approach.start_range_m;
            let hook_x = -range;
            let hook_h =
                deck.deck_height_m + range * slope.tan() + scenario.approach.start_height_offset_m;
            (hook_x - hook_dx, hook_h - hook_dh)
        }
        Mission::PitchStep {
            start_distance_aft_m,
            altitude_m,
            ..
        } => (ship_initial_x_m - start_distance_aft_m, altitude_m),
        Mission::SinkRate { altitude_m, .. } => (ship_initial_x_m - 20_000.0, altitude_m),
    };
    let aircraft_state: AircraftState = trim_point.state(x_m, h_m, &steady_wind);
    let pitch_state = pitch.initial_state(trim_point.theta_rad, trim_point.theta_rad);
    let (pose, pose_rate) = (
        ship.pose(&ship_state, ship_initial_x_m, 0.0),
        ship.pose_rate(&ship_state),
    );
    let initial = LoopState {
        aircraft: aircraft_state,
        ship: ship_state,
        pitch_controller: pitch_state.to_array(),
        deck_estimate: [
            deck.aim_point(&pose).h_m,
            deck.velocity_along_deck(&pose, &pose_rate, 0.0).h_mps,
        ],
        ..Default::default()
    };
    let system = ClosedLoop {
        aircraft,
        hook,
        ship,
        deck,
        ship_initial_x_m,
        wind,
        sensor,
        pitch,
        speed,
        sink_rate: scenario.control.sink_rate.controller(),
        guidance: scenario.control.guidance.controller(),
        flight_path,
        deck_filter: DeckMotionFilter::new(
            scenario.control.flight_path.deck_filter_frequency_radps,
        ),
        predictor: ShipMotionPredictor::new(
            scenario.control.flight_path.compensation_window_s
                + scenario.control.flight_path.compensation_blend_s,
        ),
        trim: trim_point,
        airspeed_reference_mps: airspeed,
        mode,
        held: HeldInputs::default(),
        loop_break: None,
    };
    Ok(Setup {
        system,
        initial,
        streams: StepStreams {
            ship_heave,
            ship_pitch,
        },
        end_time_s,
        initial_airspeed_mps: airspeed,
    })
}
