//! The aircraft's blocks, for any plant ([`Plant`]): `aircraft`, its kinematic outputs
//! (position, attitude, rates, the hook, from the state alone) onto the bus and its state
//! rate from the commands on the bus; `air_data`, airspeed, angle of attack and (for a
//! lateral plant) sideslip in the wind on the bus (docs/model.md §2); and
//! `lateral_hold`, the aileron and rudder commands while no lateral law flies them.

pub use crate::aircraft::BuiltPlant;
use crate::aircraft::{HookGeometry, Plant, PlantCommands};
use crate::simulation::signals::Signals;

/// What the aircraft's outputs leave for the other blocks beside the registered signals:
/// the plant's own intermediate results and the CG's earth x rate.
#[derive(Debug, Clone, Copy)]
pub(crate) struct PlantOutputs<P: Plant> {
    pub kinematic: P::Kinematic,
    pub air: P::Air,
    /// The CG's earth x rate (m/s).
    pub x_rate_mps: f64,
    /// Dynamic pressure q̄ (Pa).
    pub dynamic_pressure_pa: f64,
}

/// The aircraft's kinematics beside the registered signals.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Kinematics<P: Plant> {
    pub kinematic: P::Kinematic,
    /// The hook's and the CG's earth velocity (m/s).
    pub hook_velocity: crate::environment::EarthVelocity,
    pub velocity: crate::environment::EarthVelocity,
    /// The CG's earth x rate (m/s).
    pub x_rate_mps: f64,
}

/// The aircraft's kinematics for `state`, written onto `bus` (the ship's pose on the bus
/// gives the distance aft of its pitch centre).
#[inline(always)]
pub(crate) fn kinematics<P: Plant>(
    plant: &P,
    hook: &HookGeometry,
    state: P::State,
    bus: &mut Signals,
) -> Kinematics<P> {
    let (kinematic, out) = plant.kinematics(hook, state);
    bus.x_m = out.position.x_m;
    bus.h_m = out.position.h_m;
    bus.hook_x_m = out.hook.x_m;
    bus.hook_h_m = out.hook.h_m;
    bus.hook_climb_rate_mps = out.hook_velocity.h_mps;
    bus.hook_x_rate_mps = out.hook_velocity.x_mps;
    bus.theta_rad = out.theta_rad;
    bus.q_radps = out.q_radps;
    bus.climb_rate_mps = out.velocity.h_mps;
    bus.elevator_rad = out.elevator_rad;
    bus.elevator_rate_radps = out.elevator_rate_radps;
    bus.thrust_n = out.thrust_n;
    bus.distance_aft_m = bus.ship.distance_aft_of_pitch_centre_m(out.position.x_m);
    bus.range_to_go_m = bus.aim_point.x_m - out.hook.x_m;
    if let Some(lateral) = out.lateral {
        bus.y_m = Some(out.position.y_m);
        bus.hook_y_m = Some(out.hook.y_m);
        bus.phi_rad = Some(lateral.phi_rad);
        bus.psi_rad = Some(lateral.psi_rad);
        bus.p_radps = Some(lateral.p_radps);
        bus.r_radps = Some(lateral.r_radps);
        bus.aileron_rad = Some(lateral.aileron_rad);
        bus.rudder_rad = Some(lateral.rudder_rad);
    }
    Kinematics {
        kinematic,
        hook_velocity: out.hook_velocity,
        velocity: out.velocity,
        x_rate_mps: out.velocity.x_mps,
    }
}

/// The air data in the wind on `bus`, written onto it: the plant's outputs complete.
#[inline(always)]
pub(crate) fn air_data<P: Plant>(
    plant: &P,
    kinematics: Kinematics<P>,
    bus: &mut Signals,
) -> PlantOutputs<P> {
    let (air, out) = plant.air_data(&kinematics.kinematic, &bus.wind);
    bus.airspeed_mps = out.airspeed_mps;
    bus.alpha_rad = out.alpha_rad;
    bus.beta_rad = out.beta_rad;
    PlantOutputs {
        kinematic: kinematics.kinematic,
        air,
        x_rate_mps: kinematics.x_rate_mps,
        dynamic_pressure_pa: out.dynamic_pressure_pa,
    }
}

/// `lateral_hold`: the aileron and rudder commands of a plant that has them, held where
/// the plant holds them until lateral laws fly them.
#[inline(always)]
pub(crate) fn lateral_hold<P: Plant>(plant: &P, bus: &mut Signals) {
    if let Some((aileron_rad, rudder_rad)) = plant.held_lateral_commands() {
        bus.aileron_command_rad = Some(aileron_rad);
        bus.rudder_command_rad = Some(rudder_rad);
    }
}

/// The aircraft's state rate under the commands on `bus` (elevator, thrust, aileron,
/// rudder, the direct lift increment).
#[inline(always)]
pub(crate) fn derivative<P: Plant>(
    plant: &P,
    outputs: &PlantOutputs<P>,
    bus: &Signals,
) -> P::State {
    let commands = PlantCommands {
        elevator_rad: bus.elevator_command_rad,
        thrust_n: bus.thrust_command_n,
        aileron_rad: bus.aileron_command_rad.unwrap_or(0.0),
        rudder_rad: bus.rudder_command_rad.unwrap_or(0.0),
        lift_coefficient_increment: bus.direct_lift_coefficient.unwrap_or(0.0),
    };
    plant.derivative(&outputs.kinematic, &outputs.air, &commands)
}
