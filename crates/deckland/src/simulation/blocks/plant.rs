//! The aircraft's blocks: `aircraft`, its kinematic outputs (position, attitude, the
//! hook, from the state alone) onto the bus and its state rate from the commands on the
//! bus; and `air_data`, airspeed and angle of attack in the wind on the bus
//! (docs/model.md §2).

use crate::aircraft::{AirData, Aircraft, AircraftCommands, AircraftState, HookGeometry};
use crate::simulation::Signals;

/// What the aircraft's outputs leave for the other blocks beside the registered signals:
/// the state and the quantities its rate reuses.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlantOutputs {
    pub state: AircraftState,
    pub sin_theta: f64,
    pub cos_theta: f64,
    pub air: AirData,
    /// The CG's earth x rate (m/s).
    pub x_rate_mps: f64,
}

/// The aircraft's kinematics for `state`, written onto `bus` (the ship's pose on the bus
/// gives the distance aft of its pitch centre).
#[inline(always)]
pub(crate) fn kinematics(
    hook: &HookGeometry,
    state: AircraftState,
    bus: &mut Signals,
) -> Kinematics {
    let (sin_t, cos_t) = state.theta_rad.sin_cos();
    let (hook_x_m, hook_h_m) = hook.position_trig(&state, sin_t, cos_t);
    let (hook_x_rate_mps, hook_climb_rate_mps) = hook.velocity_trig(&state, sin_t, cos_t);
    let (x_rate_mps, climb_rate_mps) = state.earth_velocity_trig(sin_t, cos_t);
    bus.x_m = state.x_m;
    bus.h_m = state.h_m;
    bus.hook_x_m = hook_x_m;
    bus.hook_h_m = hook_h_m;
    bus.hook_climb_rate_mps = hook_climb_rate_mps;
    bus.hook_x_rate_mps = hook_x_rate_mps;
    bus.theta_rad = state.theta_rad;
    bus.q_radps = state.q_radps;
    bus.climb_rate_mps = climb_rate_mps;
    bus.elevator_rad = state.elevator_rad;
    bus.elevator_rate_radps = state.elevator_rate_radps;
    bus.thrust_n = state.total_thrust_n();
    bus.distance_aft_m = bus.ship.distance_aft_of_pitch_centre_m(state.x_m);
    bus.range_to_go_m = bus.aim_point.x_m - hook_x_m;
    Kinematics {
        state,
        sin_theta: sin_t,
        cos_theta: cos_t,
        x_rate_mps,
    }
}

/// The aircraft's kinematics beside the registered signals: the state and what the air
/// data and the rate reuse.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kinematics {
    pub state: AircraftState,
    pub sin_theta: f64,
    pub cos_theta: f64,
    /// The CG's earth x rate (m/s).
    pub x_rate_mps: f64,
}

/// The air data in the wind on `bus`, written onto it: the plant's outputs complete.
#[inline(always)]
pub(crate) fn air_data(
    aircraft: &Aircraft,
    kinematics: Kinematics,
    bus: &mut Signals,
) -> PlantOutputs {
    let state = kinematics.state;
    let air = aircraft.air_data_trig(
        state.u_mps,
        state.w_mps,
        kinematics.sin_theta,
        kinematics.cos_theta,
        &bus.wind,
    );
    bus.airspeed_mps = air.airspeed_mps;
    bus.alpha_rad = air.alpha_rad;
    PlantOutputs {
        state,
        sin_theta: kinematics.sin_theta,
        cos_theta: kinematics.cos_theta,
        air,
        x_rate_mps: kinematics.x_rate_mps,
    }
}

/// The aircraft's state rate under the commands on `bus` (elevator, thrust, the direct
/// lift increment).
#[inline(always)]
pub(crate) fn derivative(
    aircraft: &Aircraft,
    plant: &PlantOutputs,
    bus: &Signals,
) -> AircraftState {
    let commands = AircraftCommands {
        elevator_rad: bus.elevator_command_rad,
        thrust_n: bus.thrust_command_n,
    };
    aircraft.derivative_with_direct_lift(
        &plant.state,
        &commands,
        &plant.air,
        plant.sin_theta,
        plant.cos_theta,
        bus.direct_lift_coefficient.unwrap_or(0.0),
    )
}
