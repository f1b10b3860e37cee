//! Building the closed loop from a scenario: models, trim, linearisation, controllers and
//! the initial state.

use std::sync::Arc;

use super::alpha_floor::AlphaFloor;
use super::blocks::arrival_timing::ArrivalTimingBlock;
use super::blocks::plant::BuiltPlant;
use super::blocks::{check_placement, Block, BlockPlacementError, BlockPosition, PlacedBlock};
use super::closed_loop::{ClosedLoop, LoopLayout, StepStreams};
use super::commit::CommitPoint;
use super::deck_predictor::{BuiltDeckPredictor, DeckPredictor, DeckView};
use super::flight_computer::FlightComputer;
use super::outer_loops::{approach_flight_path_angle, LateAbort, OuterLoops, WaveOffFlight};
use super::pitch_setup::{refuse_infeasible_pitch_tuning, shape_pitch_step};
use crate::aircraft::six_dof::SixDofAircraft;
use crate::aircraft::{linearize, trim, Aircraft, PlantModel, TrimError, TrimPoint, TrimRequest};
use crate::control::pitch::{
    AxisLaw, AxisPlantDerivatives, BuiltPitchLaw, PitchDesignContext, PitchLaw, PitchLawInputs,
};
use crate::control::{
    CommandRamp, DirectLiftParameters, FlightPathGenerator, SpeedController, WaveOffParameters,
};
use crate::environment::{mean_wind, DeckGeometry, ShipMotion, ShipMotionState, Wind, WindModel};
use crate::parameters::ParameterError;
use crate::random::{stream_names, NoiseStream, RandomStreams};
use crate::scenario::{Mission, Scenario};
use crate::sensors::PitchSensor;

/// Builds a user's own pitch law for the plant and hardware of a run (called once per
/// run, after trim, so that a campaign can fly it over dispersed scenarios).
pub type PitchLawFactory =
    dyn Fn(&PitchDesignContext) -> Result<Box<dyn PitchLaw>, ParameterError> + Send + Sync;

/// Why a simulation could not be set up.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SetupError {
    /// A scenario value is outside its allowed range, or a controller cannot be built.
    #[error("{0}")]
    Parameter(#[from] ParameterError),
    /// The start condition cannot be trimmed.
    #[error("cannot trim the start condition: {0}")]
    Trim(#[from] TrimError),
    /// A user's block reads a signal no block before it writes.
    #[error("{0}")]
    Block(#[from] BlockPlacementError),
}

/// Everything `Simulation` needs to start.
pub(crate) struct Setup {
    pub system: ClosedLoop,
    pub initial: Vec<f64>,
    pub streams: StepStreams,
    pub end_time_s: f64,
}

/// The outer loops of the scenario's mission, the flight-path angle to trim for and the
/// run's length (s).
fn outer_loops(
    scenario: &Scenario,
    aircraft: &Aircraft,
    steady_wind: &Wind,
) -> Result<(OuterLoops, f64, f64), SetupError> {
    let control = &scenario.control;
    let airspeed = scenario.approach.airspeed_mps;
    Ok(match scenario.mission {
        Mission::Approach => {
            let slope = control.flight_path.glide_slope_deg.to_radians();
            let gamma = approach_flight_path_angle(
                airspeed,
                slope,
                steady_wind,
                scenario.environment.ship.forward_speed_mps,
            );
            let loops = OuterLoops::Approach {
                flight_path: FlightPathGenerator::new(control.flight_path)?,
                wave_off: control.wave_off.enabled.then_some(WaveOffFlight {
                    climb_rate_mps: control.wave_off.climb_rate_mps,
                    min_alpha_rad: control.wave_off.min_alpha_deg.to_radians(),
                    ramp_aft_of_aim_point_m: scenario.environment.deck.ramp_aft_of_aim_point_m,
                    climb_blend_s: control.wave_off.climb_blend_s,
                    decided_at_s: None,
                    alpha_lead_s: control.wave_off.alpha_lead_s,
                }),
                late_abort: LateAbort::new(
                    control.wave_off.late_abort_rate_per_s,
                    control.wave_off.late_abort_full_thrust,
                ),
                guidance: control.guidance.controller(),
                sink_rate: control.sink_rate.controller(),
                alpha_floor: control.sink_rate.alpha_protection.then_some(AlphaFloor {
                    min_alpha_rad: control.sink_rate.min_alpha_deg.to_radians(),
                    lead_s: control.sink_rate.alpha_lead_s,
                }),
            };
            (loops, gamma, scenario.max_time_s)
        }
        Mission::PitchStep {
            step_deg,
            step_time_s,
            duration_s,
            ..
        } => {
            // The trajectory is shaped once the trim is known (`shape_pitch_step`).
            let loops = OuterLoops::PitchStep {
                step_rad: step_deg.to_radians(),
                step_time_s,
                shaped: None,
            };
            (loops, 0.0, duration_s)
        }
        Mission::SinkRate {
            sink_rate_mps,
            step_time_s,
            ramp_s,
            duration_s,
            ..
        } => {
            let descent = trim(
                aircraft,
                &TrimRequest {
                    speed_mps: airspeed,
                    flight_path_angle_rad: -(sink_rate_mps / airspeed).clamp(-1.0, 1.0).asin(),
                },
            )?;
            let loops = OuterLoops::ClimbRate {
                climb_rate_mps: -sink_rate_mps,
                ramp: CommandRamp {
                    start_s: step_time_s,
                    ramp_s,
                },
                theta_feedforward_rad: descent.theta_rad,
                sink_rate: control.sink_rate.controller(),
            };
            (loops, 0.0, duration_s)
        }
    })
}

/// What a run flies beyond its scenario: a user's own pitch law, deck predictor and
/// blocks.
#[derive(Default)]
pub(crate) struct UserParts<'a> {
    pub pitch_law: Option<&'a PitchLawFactory>,
    pub deck_predictor: Option<&'a dyn DeckPredictor>,
    pub blocks: &'a [(BlockPosition, Arc<dyn Block>)],
}

/// Builds the loop for `scenario`, with the user's parts flying instead of the
/// scenario's where given, and the users' blocks at their positions.
pub(crate) fn build(scenario: &Scenario, user: UserParts<'_>) -> Result<Setup, SetupError> {
    scenario.validate()?;
    let section = &scenario.aircraft;
    let aircraft = section.longitudinal_aircraft()?;
    let streams = RandomStreams::new(scenario.seed);
    let environment = EnvironmentModels::new(scenario, &streams)?;
    let (outer, gamma, end_time_s) = outer_loops(scenario, &aircraft, &environment.steady_wind)?;
    let controllers = design_controllers(
        scenario,
        &aircraft,
        outer,
        gamma,
        &environment,
        (&streams, &user),
    )?;
    let position = initial_position(scenario, &controllers.trim_point, &environment.steady_wind);
    let blocks = lay_out_blocks(
        scenario,
        aircraft,
        &controllers,
        gamma,
        &streams,
        user.blocks,
    )?;
    Ok(start(
        scenario,
        environment,
        controllers,
        blocks,
        position,
        &streams,
        end_time_s,
    ))
}

/// The environment's models of a run with their random streams: the ship in its
/// stationary initial state, the air mass, the pitch sensor.
struct EnvironmentModels {
    ship: ShipMotion,
    ship_state: ShipMotionState,
    ship_heave: NoiseStream,
    ship_pitch: NoiseStream,
    wind: WindModel,
    sensor: PitchSensor,
    /// The steady wind the aircraft trims in: the mean wind over the deck, or none.
    steady_wind: Wind,
}

impl EnvironmentModels {
    /// The models of `scenario`'s environment on `streams`.
    fn new(scenario: &Scenario, streams: &RandomStreams) -> Result<Self, SetupError> {
        let env = &scenario.environment;
        let ship = env.ship_motion()?;
        let mut ship_heave = streams.stream(stream_names::SHIP_HEAVE);
        let mut ship_pitch = streams.stream(stream_names::SHIP_PITCH);
        let ship_state = ship.stationary_initial_state(&mut ship_heave, &mut ship_pitch);
        let wind = WindModel::new(env.wind, env.ship.forward_speed_mps, streams)?;
        let sensor = PitchSensor::new(env.pitch_noise, streams)?;
        let steady_wind = if env.wind.mean_wind {
            mean_wind(env.wind.wind_over_deck_mps, env.ship.forward_speed_mps)
        } else {
            Wind::default()
        };
        Ok(Self {
            ship,
            ship_state,
            ship_heave,
            ship_pitch,
            wind,
            sensor,
            steady_wind,
        })
    }
}

/// The controllers of a run, designed at its trim point.
struct Controllers {
    trim_point: TrimPoint,
    pitch: BuiltPitchLaw,
    outer: OuterLoops,
    speed: SpeedController,
    deck_predictor: BuiltDeckPredictor,
}

/// Trims `aircraft` on the flight path `gamma` (rad) at the approach's airspeed and
/// designs the controllers there: the pitch law (the user's, or the scenario's, whose
/// infeasible tuning is refused), the `outer` loops' shaped step, the speed loop and the
/// deck predictor (the user's, or the scenario's).
fn design_controllers(
    scenario: &Scenario,
    aircraft: &Aircraft,
    outer: OuterLoops,
    gamma: f64,
    environment: &EnvironmentModels,
    (streams, user): (&RandomStreams, &UserParts<'_>),
) -> Result<Controllers, SetupError> {
    let trim_point: TrimPoint = trim(
        aircraft,
        &TrimRequest {
            speed_mps: scenario.approach.airspeed_mps,
            flight_path_angle_rad: gamma,
        },
    )?;
    let model = linearize(aircraft, &trim_point);
    let context = PitchDesignContext {
        plant: AxisPlantDerivatives {
            rate_damping_per_s: model.pitch_damping_per_s(),
            control_power_per_s2: model.elevator_effectiveness_per_s2(),
        },
        actuator: scenario.aircraft.elevator_actuator,
        pitch_noise: scenario.environment.pitch_noise,
        time_step_s: scenario.time_step_s,
    };
    let pitch = built_pitch_law(scenario, &context, user.pitch_law)?;
    if user.pitch_law.is_none() {
        refuse_infeasible_pitch_tuning(scenario, &context, &model, trim_point.elevator_rad)?;
    }
    let outer = shape_pitch_step(outer, scenario, &context, trim_point.elevator_rad)?;
    let speed = SpeedController::new(
        &scenario.control.speed,
        aircraft.parameters().mass_kg,
        trim_point.thrust_n,
        aircraft.engines().max_total_thrust_n(),
    );
    let (ship, ship_state) = (&environment.ship, &environment.ship_state);
    let deck_predictor = BuiltDeckPredictor::for_scenario(scenario, ship, ship_state, streams)?;
    let deck_predictor = match user.deck_predictor {
        Some(custom) => BuiltDeckPredictor::Custom(custom.clone_box()),
        None => deck_predictor,
    };
    Ok(Controllers {
        trim_point,
        pitch,
        outer,
        speed,
        deck_predictor,
    })
}

/// The pitch law that flies: the user's from `factory`, or the scenario's (in the 3-D
/// approach its O-PD observer's power from tables, as its lateral laws:
/// `FractionalPower`).
fn built_pitch_law(
    scenario: &Scenario,
    context: &PitchDesignContext,
    factory: Option<&PitchLawFactory>,
) -> Result<BuiltPitchLaw, SetupError> {
    Ok(match factory {
        None if super::lateral::flies_three_dimensional(
            scenario,
            scenario.aircraft.model == PlantModel::SixDof,
        ) =>
        {
            scenario
                .control
                .pitch
                .build(context)?
                .with_tabulated_observer_power()
        }
        None => scenario.control.pitch.build(context)?,
        Some(factory) => BuiltPitchLaw::Custom(factory(context)?.into()),
    })
}

/// The aircraft's CG at the start, (x, h) (m): in an approach, the hook on the glide
/// slope at the start range (offset as the scenario says); in a pitch step or sink-rate
/// run, at its altitude aft of the ship.
fn initial_position(scenario: &Scenario, trim_point: &TrimPoint, steady_wind: &Wind) -> (f64, f64) {
    let deck = &scenario.environment.deck;
    let ship_initial_x_m = deck.landing_point_aft_of_pitch_centre_m;
    let placeholder = trim_point.state(0.0, 0.0, steady_wind);
    let (hook_dx, hook_dh) = scenario.aircraft.hook.position(&placeholder);
    match scenario.mission {
        Mission::Approach => {
            let range = scenario.approach.start_range_m;
            let slope = scenario.control.flight_path.glide_slope_deg.to_radians();
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
    }
}

/// The blocks of the loop laid out in its state vector: the plant, the direct lift, the
/// 3-D approach's parts and the users' blocks.
struct LaidOutBlocks {
    plant: BuiltPlant,
    layout: LoopLayout,
    direct_lift: Option<DirectLiftParameters>,
    three_d: Option<super::lateral::ThreeDimensional>,
    user_blocks: Vec<PlacedBlock>,
}

/// Builds the plant and the blocks beyond the controllers and lays out their states:
/// the built-in blocks' first, then the 3-D approach's, then the users' blocks', each
/// checked to read only what the blocks before it write.
fn lay_out_blocks(
    scenario: &Scenario,
    aircraft: Aircraft,
    controllers: &Controllers,
    gamma: f64,
    streams: &RandomStreams,
    blocks: &[(BlockPosition, Arc<dyn Block>)],
) -> Result<LaidOutBlocks, SetupError> {
    // Direct lift control flies the glide path: only in an approach, its close-in gain
    // scheduled on the sea state.
    let ship = scenario.environment.resolved_ship()?;
    let direct_lift = (scenario.mission == Mission::Approach
        && scenario.control.direct_lift.enabled)
        .then(|| {
            scenario.control.direct_lift.for_sea(
                ship.deck_point_height_rms_m(
                    scenario
                        .environment
                        .deck
                        .landing_point_aft_of_pitch_centre_m,
                ),
            )
        });
    // The plant: the 6-DOF is built on the same longitudinal model, trimmed wings level
    // on the bearing, where its trim is the longitudinal one.
    let section = &scenario.aircraft;
    let plant = match section.model {
        PlantModel::ThreeDof => BuiltPlant::ThreeDof(aircraft),
        PlantModel::SixDof => BuiltPlant::SixDof(
            SixDofAircraft::new(
                aircraft,
                section.lateral,
                section.aileron_actuator,
                section.rudder_actuator,
            )?
            .with_series_trig(super::lateral::flies_three_dimensional(scenario, true)),
        ),
    };
    let mut layout = LoopLayout::new(
        plant.state_names(),
        controllers.pitch.state_names(),
        controllers.speed.state_names(),
        controllers.deck_predictor.state_names(),
        direct_lift.is_some(),
    );
    let three_d = super::lateral::attach(
        scenario,
        &plant,
        (gamma, controllers.trim_point.alpha_rad),
        streams,
        &mut layout,
    )?;
    let mut user_blocks: Vec<PlacedBlock> = Vec::with_capacity(blocks.len());
    for (position, block) in blocks {
        check_placement(block.as_ref(), *position, &user_blocks)?;
        let slot = layout.states.add(block.name(), block.state_names());
        user_blocks.push(PlacedBlock {
            position: *position,
            block: Arc::clone(block),
            slot,
        });
    }
    Ok(LaidOutBlocks {
        plant,
        layout,
        direct_lift,
        three_d,
        user_blocks,
    })
}

/// The loop at its start: the initial state (the users' blocks', the aircraft at trim
/// at `(x_m, h_m)`, the ship's, the 3-D approach's, the controllers' at trim) and the
/// loop flying it, with the step's random streams.
fn start(
    scenario: &Scenario,
    environment: EnvironmentModels,
    controllers: Controllers,
    blocks: LaidOutBlocks,
    (x_m, h_m): (f64, f64),
    streams: &RandomStreams,
    end_time_s: f64,
) -> Setup {
    let env = &scenario.environment;
    let airspeed = scenario.approach.airspeed_mps;
    let mut initial = blocks.initial_state(&controllers.trim_point, (x_m, h_m), &environment);
    let (lateral, lateral_streams, wind) = super::lateral::start(
        blocks.three_d,
        &blocks.layout,
        (x_m, h_m),
        &mut initial,
        environment.wind,
        scenario,
        streams,
    );
    controllers.start(
        airspeed,
        (&environment.ship, &environment.ship_state),
        &env.deck,
        &blocks.layout,
        &mut initial,
    );
    let arrival_timing = ArrivalTimingBlock::new(
        scenario.control.arrival_timing,
        &environment.ship,
        airspeed,
        env.ship_sensing.latency_s,
    );
    let wave_off = WaveOffParameters {
        recovery: (scenario.control.wave_off.recovery).for_ship(&environment.ship, &env.deck),
        ..scenario.control.wave_off
    };
    let wave_off_in_sea = wave_off.for_ship(environment.ship.parameters(), &env.deck);
    let system = ClosedLoop {
        layout: blocks.layout,
        plant: blocks.plant,
        hook: scenario.aircraft.hook,
        ramp_strike_lift: super::deck_predictor::lift_loop(scenario, environment.ship.parameters()),
        ship: environment.ship,
        deck: env.deck,
        ship_initial_x_m: env.deck.landing_point_aft_of_pitch_centre_m,
        wind,
        sensor: environment.sensor,
        deck_predictor: controllers.deck_predictor,
        pitch: controllers.pitch,
        speed: controllers.speed,
        outer: controllers.outer,
        trim: controllers.trim_point,
        airspeed_reference_mps: airspeed,
        computer: scenario
            .control
            .flight_computer_rate_hz
            .map(|rate| FlightComputer::new(rate, initial.len())),
        wave_off,
        wave_off_in_sea,
        wake_feedforward_lead_s: wake_feedforward_lead_s(scenario),
        direct_lift: blocks.direct_lift,
        user_blocks: blocks.user_blocks,
        lateral,
        arrival_timing,
        commit: CommitPoint::default(),
    };
    Setup {
        system,
        initial,
        streams: StepStreams {
            ship_heave: environment.ship_heave,
            ship_pitch: environment.ship_pitch,
            lateral: lateral_streams,
        },
        end_time_s,
    }
}

/// The pitch law's inputs at `trim_point`: commanded, measured and trim attitude the
/// trim's, the elevator at trim.
fn trim_pitch_inputs(trim_point: &TrimPoint) -> PitchLawInputs {
    PitchLawInputs {
        theta_ref_rad: trim_point.theta_rad,
        theta_measured_rad: trim_point.theta_rad,
        elevator_actual_rad: trim_point.elevator_rad,
        theta_trim_rad: trim_point.theta_rad,
        elevator_trim_rad: trim_point.elevator_rad,
        ..PitchLawInputs::default()
    }
}

impl Controllers {
    /// Writes the controllers' initial states at trim into `initial`: the pitch law's
    /// and the speed loop's at trim and `airspeed` (m/s), the deck predictor's from its
    /// view at t = 0 of the `ship` in its initial state on `deck`.
    fn start(
        &self,
        airspeed: f64,
        (ship, ship_state): (&ShipMotion, &ShipMotionState),
        deck: &DeckGeometry,
        layout: &LoopLayout,
        initial: &mut [f64],
    ) {
        self.pitch.initial_state(
            &trim_pitch_inputs(&self.trim_point),
            layout.pitch_law.of_mut(initial),
        );
        self.speed
            .initial_state(airspeed, layout.speed.of_mut(initial));
        let pose = ship.pose(ship_state, deck.landing_point_aft_of_pitch_centre_m, 0.0);
        let pose_rate = ship.pose_rate(ship_state);
        let view = DeckView {
            ship_model: ship,
            ship_state: &ShipMotionState::from_slice(layout.ship.of(initial)),
            deck,
            pose: &pose,
            rate: &pose_rate,
            roll: None,
        };
        self.deck_predictor
            .initial_state(&view, layout.deck_predictor.of_mut(initial));
    }
}

impl LaidOutBlocks {
    /// The initial state with the users' blocks', the aircraft's at `trim_point` at
    /// `(x_m, h_m)` in the steady wind and the ship's written; the others' still 0.
    fn initial_state(
        &self,
        trim_point: &TrimPoint,
        (x_m, h_m): (f64, f64),
        environment: &EnvironmentModels,
    ) -> Vec<f64> {
        let mut initial = vec![0.0; self.layout.dimension()];
        for placed in &self.user_blocks {
            placed.block.initial_state(placed.slot.of_mut(&mut initial));
        }
        self.plant.write_longitudinal_state(
            &trim_point.state(x_m, h_m, &environment.steady_wind),
            &mut initial,
            self.layout.aircraft.offset,
        );
        self.layout
            .ship
            .of_mut(&mut initial)
            .copy_from_slice(&environment.ship_state.to_array());
        initial
    }
}

/// The lead (s) with which the steady air wake is fed forward into the pitch command:
/// in an approach that asks for it in a wind with the steady wake; `None` otherwise.
fn wake_feedforward_lead_s(scenario: &Scenario) -> Option<f64> {
    let flight_path = &scenario.control.flight_path;
    (scenario.mission == Mission::Approach
        && flight_path.wake_feedforward
        && scenario.environment.wind.steady_wake)
        .then_some(flight_path.wake_feedforward_lead_s)
}
