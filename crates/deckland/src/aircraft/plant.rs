//! The plant interface: what the closed loop needs of an aircraft model, and the
//! longitudinal F/A-18 as its first implementation (the 6-DOF aircraft is the second,
//! `six_dof::plant`).
//!
//! A plant has a named state that converts to and from a vector (its names and units),
//! named control surfaces with their actuators, and outputs evaluated in two stages:
//! its kinematics from the state alone (position, attitude, rates, the hook in three
//! dimensions), then its air data in the wind at the aircraft. Its state rate follows
//! from both and the commands. Each plant carries what one stage hands the next in its
//! own types ([`Plant::Kinematic`], [`Plant::Air`]), so that a loop generic over the plant
//! compiles to the plant's own arithmetic, with nothing computed twice.

use super::dynamics::{AirData, Aircraft, AircraftCommands};
use super::hook::HookGeometry;
use super::state::AircraftState;
use super::{AircraftParameters, ElevatorActuator, Engines};
use crate::environment::{EarthPoint, EarthVelocity, Wind};
use serde::{Deserialize, Serialize};

/// The aircraft model a scenario flies (`[aircraft] model`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
pub enum PlantModel {
    /// The longitudinal F/A-18: 3 degrees of freedom in the vertical plane
    /// (docs/model.md §2); the paper's set flies it.
    #[serde(rename = "3dof")]
    ThreeDof,
    /// The 6-DOF F/A-18 (docs/six-dof.md): the longitudinal model with the
    /// lateral-directional data, the inertias, the aileron and the rudder; the realistic
    /// set's default, which flies the 3-D approach (docs/three-d-approach.md).
    #[default]
    #[serde(rename = "6dof")]
    SixDof,
}

impl PlantModel {
    /// Every model, in the order of their names.
    pub const ALL: [Self; 2] = [Self::ThreeDof, Self::SixDof];

    /// The model's name in a scenario file and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Self::ThreeDof => "3dof",
            Self::SixDof => "6dof",
        }
    }

    /// The model called `name` ([`PlantModel::name`]), if any.
    pub fn from_name(name: &str) -> Option<Self> {
        Self::ALL.into_iter().find(|model| model.name() == name)
    }

    /// What an approach flown with the model reports, on an approach that is
    /// `three_dimensional_approach` or not: the lateral touchdown and the trap sheet too
    /// for the 6-DOF aircraft on the 3-D approach, the longitudinal outcome alone
    /// otherwise (the 3-DOF model has no lateral motion; the 6-DOF one on a longitudinal
    /// approach keeps the wings level). A campaign's runs table has the columns of what
    /// its approaches report (`monte_carlo::RunsSchema::of`).
    pub fn approach_outcome(self, three_dimensional_approach: bool) -> ApproachOutcome {
        match (self, three_dimensional_approach) {
            (Self::SixDof, true) => ApproachOutcome::WithLateral,
            (Self::SixDof, false) | (Self::ThreeDof, _) => ApproachOutcome::Longitudinal,
        }
    }

    /// One line on what the model is (for a command's help).
    pub fn summary(self) -> &'static str {
        match self {
            Self::ThreeDof => "The longitudinal model of the paper (u, w, q, θ)",
            Self::SixDof => "The rigid-body 6-DOF model with the lateral-directional axes",
        }
    }
}

/// What an approach flown with a plant reports ([`PlantModel::approach_outcome`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ApproachOutcome {
    /// The longitudinal outcome alone: the touchdown along the deck, the sink rate, the
    /// ramp clearance, the glide-path error, …
    Longitudinal,
    /// The longitudinal outcome with the lateral touchdown and the trap sheet.
    WithLateral,
}

/// The lateral part of a plant's kinematic outputs (a plant without lateral motion has
/// none).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LateralKinematics {
    /// Bank angle φ (rad), right wing down positive.
    pub phi_rad: f64,
    /// Heading ψ from the final bearing (rad), nose right positive.
    pub psi_rad: f64,
    /// Roll rate p (rad/s).
    pub p_radps: f64,
    /// Yaw rate r (rad/s).
    pub r_radps: f64,
    /// Aileron position δa (rad).
    pub aileron_rad: f64,
    /// Rudder position δr (rad).
    pub rudder_rad: f64,
}

/// What follows from a plant's state alone: position, attitude, rates and the hook.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlantKinematics {
    /// The CG in earth axes (y = 0 for a longitudinal plant).
    pub position: EarthPoint,
    /// The CG's inertial velocity in earth axes.
    pub velocity: EarthVelocity,
    /// The hook point in earth axes.
    pub hook: EarthPoint,
    /// The hook point's inertial velocity in earth axes.
    pub hook_velocity: EarthVelocity,
    /// Pitch angle θ (rad).
    pub theta_rad: f64,
    /// Pitch rate q (rad/s).
    pub q_radps: f64,
    /// Elevator position δe (rad).
    pub elevator_rad: f64,
    /// Elevator rate δ̇e (rad/s).
    pub elevator_rate_radps: f64,
    /// Total actual thrust (N).
    pub thrust_n: f64,
    /// Bank, heading, roll and yaw rates, aileron and rudder; `None` for a longitudinal
    /// plant.
    pub lateral: Option<LateralKinematics>,
}

/// A plant's air data in the wind at the aircraft.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlantAirData {
    /// True airspeed V_T (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack α (rad).
    pub alpha_rad: f64,
    /// Sideslip β (rad), relative wind from the right positive; `None` for a
    /// longitudinal plant.
    pub beta_rad: Option<f64>,
    /// Dynamic pressure q̄ = ½ρV_T² (Pa).
    pub dynamic_pressure_pa: f64,
}

/// The commands to a plant's surfaces and engines, and direct lift's increment.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PlantCommands {
    /// Elevator command (rad).
    pub elevator_rad: f64,
    /// Total thrust command (N).
    pub thrust_n: f64,
    /// Aileron command (rad); a plant without an aileron ignores it.
    pub aileron_rad: f64,
    /// Rudder command (rad); a plant without a rudder ignores it.
    pub rudder_rad: f64,
    /// Direct lift control's lift-coefficient increment ΔC_L (–), acting as the wing's
    /// own lift does (docs/model.md §5.9); 0 without it.
    pub lift_coefficient_increment: f64,
}

/// An aircraft model the closed loop can fly.
pub trait Plant: Clone + std::fmt::Debug + Send + Sync + 'static {
    /// The plant's state as a named struct.
    type State: Copy + std::fmt::Debug;
    /// What the kinematics hand the air data and the rate (the state and what they reuse).
    type Kinematic: Copy;
    /// What the air data hand the rate.
    type Air: Copy;

    /// The model's name (`[aircraft] model`).
    const MODEL: PlantModel;
    /// The names of the state vector's components, in order.
    const STATE_NAMES: &'static [&'static str];
    /// Their units, in the same order.
    const STATE_UNITS: &'static [&'static str];
    /// The control surfaces, in the order of [`Plant::surface_actuator`].
    const SURFACES: &'static [&'static str];

    /// The state from its vector, the `STATE_NAMES.len()` values of `x` from `offset`.
    fn state_at(x: &[f64], offset: usize) -> Self::State;
    /// Writes the state into its vector, in `x` from `offset`.
    fn write_state_at(state: &Self::State, x: &mut [f64], offset: usize);
    /// The plant's state of a longitudinal state: wings level on the final bearing, no
    /// lateral motion, the lateral surfaces at neutral.
    fn from_longitudinal(state: &AircraftState) -> Self::State;
    /// The longitudinal part of a state (u, w, q, θ, x, h, engines, elevator).
    fn longitudinal_state(state: &Self::State) -> AircraftState;
    /// The airframe's mass, geometry and the air it flies in.
    fn parameters(&self) -> &AircraftParameters;
    /// Its engines.
    fn engines(&self) -> &Engines;
    /// Its stabilator's actuator (surface 0 of [`Plant::SURFACES`]).
    fn stabilator(&self) -> &ElevatorActuator;
    /// The actuator of surface `index` of [`Plant::SURFACES`].
    fn surface_actuator(&self, index: usize) -> Option<&ElevatorActuator>;
    /// The commands the plant's lateral surfaces are held at while no lateral law flies
    /// them (aileron, rudder) (rad); `None` for a plant without them.
    fn held_lateral_commands(&self) -> Option<(f64, f64)>;

    /// The kinematic outputs of `state`, with the hook at `hook`.
    fn kinematics(
        &self,
        hook: &HookGeometry,
        state: Self::State,
    ) -> (Self::Kinematic, PlantKinematics);
    /// The air data in `wind` (earth axes).
    fn air_data(&self, kinematic: &Self::Kinematic, wind: &Wind) -> (Self::Air, PlantAirData);
    /// The state's rate under `commands`.
    fn derivative(
        &self,
        kinematic: &Self::Kinematic,
        air: &Self::Air,
        commands: &PlantCommands,
    ) -> Self::State;
    /// Holds the actuators at their stops after a step (`x`: the plant's state vector).
    fn constrain(&self, x: &mut [f64]);
}

/// The longitudinal plant's kinematics beside its outputs: the state and what the air
/// data and the rate reuse.
#[derive(Debug, Clone, Copy)]
pub struct LongitudinalKinematic {
    /// The state.
    pub state: AircraftState,
    /// sin θ.
    pub sin_theta: f64,
    /// cos θ.
    pub cos_theta: f64,
}

impl Plant for Aircraft {
    type State = AircraftState;
    type Kinematic = LongitudinalKinematic;
    type Air = AirData;

    const MODEL: PlantModel = PlantModel::ThreeDof;
    const STATE_NAMES: &'static [&'static str] = &AircraftState::NAMES;
    const STATE_UNITS: &'static [&'static str] = &[
        "m/s", "m/s", "rad/s", "rad", "m", "m", "N", "N", "rad", "rad/s",
    ];
    const SURFACES: &'static [&'static str] = &["elevator"];

    #[inline(always)]
    fn state_at(x: &[f64], offset: usize) -> AircraftState {
        let mut array = [0.0; AircraftState::DIMENSION];
        array.copy_from_slice(&x[offset..offset + AircraftState::DIMENSION]);
        AircraftState::from_array(&array)
    }

    #[inline(always)]
    fn write_state_at(state: &AircraftState, x: &mut [f64], offset: usize) {
        x[offset..offset + AircraftState::DIMENSION].copy_from_slice(&state.to_array());
    }

    fn from_longitudinal(state: &AircraftState) -> AircraftState {
        *state
    }

    #[inline(always)]
    fn longitudinal_state(state: &AircraftState) -> AircraftState {
        *state
    }

    #[inline(always)]
    fn parameters(&self) -> &AircraftParameters {
        Aircraft::parameters(self)
    }

    #[inline(always)]
    fn engines(&self) -> &Engines {
        Aircraft::engines(self)
    }

    #[inline(always)]
    fn stabilator(&self) -> &ElevatorActuator {
        self.actuator()
    }

    fn surface_actuator(&self, index: usize) -> Option<&ElevatorActuator> {
        (index == 0).then(|| self.actuator())
    }

    #[inline(always)]
    fn held_lateral_commands(&self) -> Option<(f64, f64)> {
        None
    }

    #[inline(always)]
    fn kinematics(
        &self,
        hook: &HookGeometry,
        state: AircraftState,
    ) -> (LongitudinalKinematic, PlantKinematics) {
        let (sin_t, cos_t) = state.theta_rad.sin_cos();
        let (hook_x_m, hook_h_m) = hook.position_trig(&state, sin_t, cos_t);
        let (hook_x_rate_mps, hook_climb_rate_mps) = hook.velocity_trig(&state, sin_t, cos_t);
        let (x_rate_mps, climb_rate_mps) = state.earth_velocity_trig(sin_t, cos_t);
        let outputs = PlantKinematics {
            position: EarthPoint {
                x_m: state.x_m,
                y_m: 0.0,
                h_m: state.h_m,
            },
            velocity: EarthVelocity {
                x_mps: x_rate_mps,
                y_mps: 0.0,
                h_mps: climb_rate_mps,
            },
            hook: EarthPoint {
                x_m: hook_x_m,
                y_m: 0.0,
                h_m: hook_h_m,
            },
            hook_velocity: EarthVelocity {
                x_mps: hook_x_rate_mps,
                y_mps: 0.0,
                h_mps: hook_climb_rate_mps,
            },
            theta_rad: state.theta_rad,
            q_radps: state.q_radps,
            elevator_rad: state.elevator_rad,
            elevator_rate_radps: state.elevator_rate_radps,
            thrust_n: state.total_thrust_n(),
            lateral: None,
        };
        let kinematic = LongitudinalKinematic {
            state,
            sin_theta: sin_t,
            cos_theta: cos_t,
        };
        (kinematic, outputs)
    }

    #[inline(always)]
    fn air_data(&self, kinematic: &LongitudinalKinematic, wind: &Wind) -> (AirData, PlantAirData) {
        let state = &kinematic.state;
        let air = self.air_data_trig(
            state.u_mps,
            state.w_mps,
            kinematic.sin_theta,
            kinematic.cos_theta,
            wind,
        );
        let outputs = PlantAirData {
            airspeed_mps: air.airspeed_mps,
            alpha_rad: air.alpha_rad,
            beta_rad: None,
            dynamic_pressure_pa: air.dynamic_pressure_pa,
        };
        (air, outputs)
    }

    #[inline(always)]
    fn derivative(
        &self,
        kinematic: &LongitudinalKinematic,
        air: &AirData,
        commands: &PlantCommands,
    ) -> AircraftState {
        self.derivative_with_direct_lift(
            &kinematic.state,
            &AircraftCommands {
                elevator_rad: commands.elevator_rad,
                thrust_n: commands.thrust_n,
            },
            air,
            kinematic.sin_theta,
            kinematic.cos_theta,
            commands.lift_coefficient_increment,
        )
    }

    #[inline]
    fn constrain(&self, x: &mut [f64]) {
        let (mut position, mut rate) = (
            x[AircraftState::ELEVATOR_INDEX],
            x[AircraftState::ELEVATOR_RATE_INDEX],
        );
        self.actuator().constrain(&mut position, &mut rate);
        x[AircraftState::ELEVATOR_INDEX] = position;
        x[AircraftState::ELEVATOR_RATE_INDEX] = rate;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_longitudinal_state_round_trips_through_its_vector() {
        let x: Vec<f64> = (1..=11).map(f64::from).collect();
        let state = Aircraft::state_at(&x, 1);
        assert_eq!((state.u_mps, state.h_m), (2.0, 7.0));
        let mut back = vec![0.0; 13];
        Aircraft::write_state_at(&state, &mut back, 3);
        assert_eq!(back[3..], x[1..]);
        assert_eq!(Aircraft::STATE_NAMES.len(), Aircraft::STATE_UNITS.len());
    }

    #[test]
    fn the_model_names_are_the_scenario_keys() {
        #[derive(Deserialize)]
        struct Section {
            model: PlantModel,
        }
        for model in [PlantModel::ThreeDof, PlantModel::SixDof] {
            let text = format!("model = \"{}\"", model.name());
            let section: Section = toml::from_str(&text).unwrap();
            assert_eq!(section.model, model);
        }
        let error = toml::from_str::<Section>("model = \"4dof\"")
            .err()
            .expect("an unknown model is refused")
            .to_string();
        assert!(error.contains("4dof") && error.contains("6dof"), "{error}");
    }

    /// The command line's names are the scenario file's: each model's name reads back
    /// as that model, with serde as with `from_name`, and no other name does.
    #[test]
    fn model_names_read_back() {
        for model in PlantModel::ALL {
            assert_eq!(PlantModel::from_name(model.name()), Some(model));
            let quoted: PlantModel =
                serde_json::from_str(&format!("\"{}\"", model.name())).expect("a model name");
            assert_eq!(quoted, model);
        }
        assert_eq!(PlantModel::from_name("4dof"), None);
        assert_eq!(PlantModel::from_name("6DOF"), None);
    }
}
