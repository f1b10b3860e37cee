//! Building the 3-D approach's parts of the loop from a scenario (docs/model.md §10.1).

use std::sync::Arc;

use super::part::{LateralHold, WithLateralPart, WithLateralPartMut};
use super::{forecast, LateralLoop, LateralStreams, SurfaceTrim};
use crate::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, SixDofAircraft, SixDofTrimPoint, SixDofTrimRequest,
};
use crate::aircraft::{ElevatorActuator, TrimRequest};
use crate::control::heading_hold::HeadingHold;
use crate::control::lateral::design::{channel_hardware, channel_plants};
use crate::control::lateral::{
    LateralChannel, LateralDesignContext, LateralLawParameters, ObserverPower, RollLaw, YawLaw,
};
use crate::control::lineup::LineupParameters;
use crate::control::wave_off_lateral::LateralWaveOffLimits;
use crate::environment::{
    mean_wind_over_angled_deck, DeckGeometry, LateralShipMotion, LateralShipMotionState,
    LateralShipStreams, ShipPose, Wind,
};
use crate::parameters::ParameterError;
use crate::random::{stream_names, RandomStreams, Reseed};
use crate::scenario::{Mission, Scenario};
use crate::sensors::LateralShipMotionSensor;

/// The roll and yaw laws the 3-D approach flies: the scenario's `[control.roll]` and
/// `[control.yaw]` (by default the O-PD designed on each channel;
/// docs/lateral-control.md). The one place the laws are chosen.
pub fn lateral_laws(scenario: &Scenario) -> (LateralLawParameters, LateralLawParameters) {
    scenario.lateral_laws()
}

/// The loop's lateral part as built for a configuration: the 3-D approach's lateral
/// loop, or the lateral hold of a loop without it ([`LateralHold`]).
// One per loop, held inline as the plant is (`BuiltPlant`): a box would add a pointer
// chase to every evaluation.
#[allow(clippy::large_enum_variant)]
#[derive(Debug, Clone)]
pub(crate) enum BuiltLateral {
    /// The 3-D approach's parts (docs/model.md §10.1).
    ThreeDimensional(LateralLoop),
    /// The plant's lateral commands held at trim.
    Hold,
}

impl BuiltLateral {
    /// Does `work` with the lateral part, whichever it is: the one place the loop
    /// chooses by it, as [`crate::aircraft::BuiltPlant::with`] by the plant (no dynamic
    /// dispatch in the step).
    #[inline(always)]
    pub(crate) fn with<W: WithLateralPart>(&self, work: W) -> W::Output {
        match self {
            Self::ThreeDimensional(lateral) => work.with(lateral),
            Self::Hold => work.with(&LateralHold),
        }
    }

    /// Does `work` that changes the lateral part, whichever it is, as [`Self::with`].
    #[inline(always)]
    pub(crate) fn with_mut<W: WithLateralPartMut>(&mut self, work: W) -> W::Output {
        match self {
            Self::ThreeDimensional(lateral) => work.with(lateral),
            Self::Hold => work.with(&mut LateralHold),
        }
    }

    /// The 3-D approach's lateral loop, to change; `None` in a loop without it.
    pub(crate) fn three_dimensional_mut(&mut self) -> Option<&mut LateralLoop> {
        match self {
            Self::ThreeDimensional(lateral) => Some(lateral),
            Self::Hold => None,
        }
    }
}

impl Reseed for BuiltLateral {
    fn reseed(&mut self, key: u64) {
        if let Self::ThreeDimensional(lateral) = self {
            lateral.reseed(key);
        }
    }
}

/// What the 3-D approach adds to a run at its start.
pub(crate) struct ThreeDimensional {
    pub lateral: LateralLoop,
    pub streams: LateralStreams,
    /// The roll, yaw and sway filters' initial (stationary) state.
    pub ship_state: LateralShipMotionState,
    /// The 6-DOF trim in the crab that holds the track along the drifting centreline,
    /// its wind the full steady wind (so that its state drifts with the centreline).
    pub trim: SixDofTrimPoint,
}

/// Whether `scenario` flies the 3-D approach with `aircraft`.
pub(crate) fn flies_three_dimensional(scenario: &Scenario, six_dof: bool) -> bool {
    six_dof && scenario.mission == Mission::Approach && scenario.approach.three_dimensional
}

/// Refuses a crab (the trim's heading off the final bearing, deg) beyond
/// `environment.wind.max_crab_deg`, naming the crosswind, the airspeed and the limit.
fn check_crab(scenario: &Scenario, crab_deg: f64) -> Result<(), ParameterError> {
    let wind = &scenario.environment.wind;
    if crab_deg.abs() <= wind.max_crab_deg {
        return Ok(());
    }
    Err(ParameterError::new(
        "environment.wind",
        "crosswind_mps",
        wind.crosswind_mps,
        format_args!(
            "a crosswind the aircraft can crab into: at `approach.airspeed_mps` = {} it needs \
             a crab of {:.1}°, beyond `environment.wind.max_crab_deg` = {}° (lower the \
             crosswind or raise the limit)",
            scenario.approach.airspeed_mps,
            crab_deg.abs(),
            wind.max_crab_deg
        ),
    ))
}

/// The steady wind of the 3-D approach (docs/model.md §3.9): down the angled deck, with
/// the crosswind; none when the mean wind is off.
pub(crate) fn steady_wind(scenario: &Scenario) -> Wind {
    let env = &scenario.environment;
    if !env.wind.mean_wind {
        return Wind::default();
    }
    mean_wind_over_angled_deck(
        env.wind.wind_over_deck_mps,
        env.ship.forward_speed_mps,
        env.deck.ship_mean_heading_rad(),
        env.wind.crosswind_mps,
    )
}

/// The 3-D approach's parts for `aircraft` on the air-relative flight path
/// `flight_path_angle_rad` at the on-speed angle of attack `on_speed_alpha_rad` (the
/// approach's trim); a crosswind the aircraft cannot crab into is refused, naming it.
pub(crate) fn build(
    scenario: &Scenario,
    aircraft: &SixDofAircraft,
    (flight_path_angle_rad, on_speed_alpha_rad): (f64, f64),
    streams: &RandomStreams,
) -> Result<ThreeDimensional, ParameterError> {
    let env = &scenario.environment;
    let deck = &env.deck;
    let speed = env.ship.forward_speed_mps;
    let (sin, cos) = deck.ship_mean_heading_rad().sin_cos();
    let drift = speed * sin;
    let wind = steady_wind(scenario);
    let trim = crab_trim(scenario, aircraft, flight_path_angle_rad, &wind, drift)?;
    let (roll, yaw) = built_laws(scenario, aircraft, &trim)?;
    let ship = LateralShipMotion::new(&env.resolved_ship()?)?;
    let mut ship_streams = LateralShipStreams::new(streams);
    let ship_state = ship.stationary_initial_state(&mut ship_streams);
    let (lineup, heading_hold) = lineup_and_heading_hold(scenario, aircraft, &trim)?;
    let floor = super::floor::AimPointLateralFloor::new(&ship, deck);
    let lateral = LateralLoop {
        ship,
        initial_pitch_centre_m: initial_pitch_centre_m(deck),
        mean_heading_sin_cos: deck.ship_mean_heading_rad().sin_cos(),
        mean_drift_rate_mps: drift,
        closure_mps: (scenario.approach.airspeed_mps * flight_path_angle_rad.cos() + wind.x_mps
            - speed * cos)
            .max(1.0),
        roll: Arc::from(roll),
        yaw: Arc::from(yaw),
        lineup,
        heading_hold,
        wave_off: LateralWaveOffLimits::default(),
        floor,
        aileron: surface_trim(aircraft.aileron(), trim.aileron_rad),
        rudder: surface_trim(aircraft.rudder(), trim.rudder_rad),
        trim_bank_rad: trim.phi_rad,
        trim_sideslip_rad: trim.sideslip_rad,
        bank_noise: env.pitch_noise,
        sensor: LateralShipMotionSensor::new(env.ship_sensing, streams)?,
        last_measurement: None,
        roll_rise_m: (
            forecast::roll_rise_per_sine_m(deck, 0.0),
            forecast::roll_rise_per_sine_m(deck, -deck.ramp_aft_of_aim_point_m),
        ),
        read: (trim.phi_rad, trim.sideslip_rad),
        view_memo: Default::default(),
        step_view: None,
        forecaster: forecast::CentrelineForecaster::new(deck),
        guidance_frames: scenario
            .control
            .flight_computer_rate_hz
            .map(super::hold::GuidanceFrames::new),
        view_frame_period_s: scenario
            .control
            .flight_computer_rate_hz
            .map(|rate_hz| 1.0 / rate_hz),
        observation: super::observe::ApproachObservation::new(deck, on_speed_alpha_rad),
    };
    Ok(ThreeDimensional {
        lateral,
        streams: LateralStreams {
            ship: ship_streams,
            bank: streams.stream(stream_names::BANK_NOISE),
            sideslip: streams.stream(stream_names::SIDESLIP_NOISE),
            heading: streams.stream(stream_names::HEADING_NOISE),
        },
        ship_state,
        trim: SixDofTrimPoint { wind, ..trim },
    })
}

/// The 6-DOF trim on the air-relative flight path `flight_path_angle_rad` in the crab
/// that holds the track along the centreline drifting at `drift` (m/s) in the steady
/// `wind`; a crosswind the aircraft cannot crab into is refused, naming it.
fn crab_trim(
    scenario: &Scenario,
    aircraft: &SixDofAircraft,
    flight_path_angle_rad: f64,
    wind: &Wind,
    drift: f64,
) -> Result<SixDofTrimPoint, ParameterError> {
    let request = SixDofTrimRequest {
        longitudinal: TrimRequest {
            speed_mps: scenario.approach.airspeed_mps,
            flight_path_angle_rad,
        },
        sideslip_rad: 0.0,
        // Relative to the drifting centreline: the air's drift with the ship is no cross
        // wind to it.
        wind: Wind {
            y_mps: wind.y_mps - drift,
            ..*wind
        },
    };
    let trim = trim_six_dof(aircraft, &request).map_err(|error| {
        ParameterError::new(
            "environment.wind",
            "crosswind_mps",
            scenario.environment.wind.crosswind_mps,
            format_args!("a crosswind the aircraft can crab into on the approach ({error})"),
        )
    })?;
    check_crab(scenario, trim.psi_rad.to_degrees())?;
    Ok(trim)
}

/// The roll and the yaw law, built.
type BuiltLaws = (Box<dyn RollLaw>, Box<dyn YawLaw>);

/// The scenario's roll and yaw laws designed on the channels of `aircraft` linearised
/// at `trim`, their observers' fractional power by tables: eight of them a step (module
/// docs of `FractionalPower`).
fn built_laws(
    scenario: &Scenario,
    aircraft: &SixDofAircraft,
    trim: &SixDofTrimPoint,
) -> Result<BuiltLaws, ParameterError> {
    let model = linearize_six_dof(aircraft, trim);
    let (roll_plant, yaw_plant) = channel_plants(&model);
    let context = |channel, plant| LateralDesignContext {
        plant,
        actuator: channel_hardware(aircraft, &model, channel).actuator,
    };
    let (roll, yaw) = lateral_laws(scenario);
    let power = ObserverPower::Tabulated;
    let roll = roll.build_roll_with(&context(LateralChannel::Roll, roll_plant), power)?;
    let yaw = yaw.build_yaw_with(&context(LateralChannel::Yaw, yaw_plant), power)?;
    Ok((roll, yaw))
}

/// The lineup loop's parameters for `aircraft` and the scenario's approach (checked),
/// and the heading hold in close to the crab of `trim`.
fn lineup_and_heading_hold(
    scenario: &Scenario,
    aircraft: &SixDofAircraft,
    trim: &SixDofTrimPoint,
) -> Result<(LineupParameters, HeadingHold), ParameterError> {
    let approach = &scenario.approach;
    let lineup = LineupParameters {
        gravity_mps2: aircraft.longitudinal().parameters().gravity_mps2,
        close_natural_frequency_radps: approach.lineup_close_frequency_radps,
        compensation_station_aft_m: approach.lineup_station_aft_m,
        ..LineupParameters::default()
    };
    lineup.validate()?;
    let heading_hold = HeadingHold {
        time_to_go_s: approach.heading_hold_time_to_go_s,
        blend_s: approach.heading_hold_blend_s,
        crab_heading_rad: trim.psi_rad,
        trim_sideslip_rad: trim.sideslip_rad,
    };
    Ok((lineup, heading_hold))
}

/// A surface's trim deflection `trim_rad` and its `actuator`'s position limits (rad).
fn surface_trim(actuator: &ElevatorActuator, trim_rad: f64) -> SurfaceTrim {
    SurfaceTrim {
        trim_rad,
        min_rad: actuator.min_rad(),
        max_rad: actuator.max_rad(),
    }
}

/// The pitch centre's earth (x, y) at t = 0 that puts the mean aim point at the origin.
fn initial_pitch_centre_m(deck: &DeckGeometry) -> (f64, f64) {
    let aim = deck.aim_point_3d(&ShipPose::default());
    (-aim.x_m, -aim.y_m)
}

/// A loop for the unit tests of the 3-D view: the default laws on the default aircraft.
#[cfg(test)]
pub(crate) fn test_loop(deck: &DeckGeometry, ship: &crate::environment::ShipMotion) -> LateralLoop {
    let mut scenario = Scenario::default();
    scenario.environment.deck = *deck;
    scenario.environment.ship = *ship.parameters();
    let aircraft = SixDofAircraft::default();
    let built = build(
        &scenario,
        &aircraft,
        (-3.5_f64.to_radians(), 0.14),
        &RandomStreams::new(1),
    )
    .expect("the default 3-D approach builds");
    // The views of the states asked for, not carried over a flight computer's frame.
    LateralLoop {
        view_frame_period_s: None,
        ..built.lateral
    }
}

/// Builds the 3-D approach's parts when `scenario` flies it with `plant` (on the flight
/// path and at the on-speed angle of attack of [`build`]), and lays out their states in
/// `layout`.
pub(crate) fn attach(
    scenario: &Scenario,
    plant: &crate::simulation::blocks::plant::BuiltPlant,
    flight_path_and_alpha_rad: (f64, f64),
    streams: &RandomStreams,
    layout: &mut crate::simulation::layout::LoopLayout,
) -> Result<Option<ThreeDimensional>, ParameterError> {
    let crate::simulation::blocks::plant::BuiltPlant::SixDof(aircraft) = plant else {
        return Ok(None);
    };
    if !flies_three_dimensional(scenario, true) {
        return Ok(None);
    }
    let built = build(scenario, aircraft, flight_path_and_alpha_rad, streams)?;
    layout.add_lateral(
        built.lateral.roll.state_names(),
        built.lateral.yaw.state_names(),
    );
    Ok(Some(built))
}

/// Starts the 3-D approach's parts: the aircraft in its crab at the CG (`x_m`, `h_m`)
/// on the mean centreline, the lateral ship filters and the laws' states in `initial`;
/// the wind in three dimensions. Returns the loop's part, its streams and the wind.
pub(crate) fn start(
    built: Option<ThreeDimensional>,
    layout: &crate::simulation::layout::LoopLayout,
    (x_m, h_m): (f64, f64),
    initial: &mut [f64],
    wind: crate::environment::WindModel,
    scenario: &Scenario,
    streams: &RandomStreams,
) -> (
    BuiltLateral,
    Option<LateralStreams>,
    crate::environment::WindModel,
) {
    use crate::aircraft::Plant;
    let Some(built) = built else {
        return (BuiltLateral::Hold, None, wind);
    };
    SixDofAircraft::write_state_at(
        &built.trim.state(x_m, 0.0, h_m),
        initial,
        layout.aircraft.offset,
    );
    layout
        .ship_lateral
        .write_array(initial, &built.ship_state.to_array());
    let lateral = built.lateral;
    let trim = &built.trim;
    let measured = super::LateralMeasurements {
        bank_rad: trim.phi_rad,
        sideslip_rad: trim.sideslip_rad,
        aileron_rad: trim.aileron_rad,
        rudder_rad: trim.rudder_rad,
        ..super::LateralMeasurements::default()
    };
    let (roll, yaw) = lateral.law_inputs(
        (trim.phi_rad, lateral.trim_sideslip_rad),
        &measured,
        &super::HeldLateral::default(),
    );
    lateral
        .roll
        .initial_state(&roll, layout.roll_law.of_mut(initial));
    lateral
        .yaw
        .initial_state(&yaw, layout.yaw_law.of_mut(initial));
    let deck_angle = scenario.environment.deck.ship_mean_heading_rad();
    (
        BuiltLateral::ThreeDimensional(lateral),
        Some(built.streams),
        wind.three_dimensional(deck_angle, streams),
    )
}
