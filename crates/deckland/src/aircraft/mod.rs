//! The longitudinal F/A-18 plant (docs/model.md §2): aerodynamics, engines, elevator
//! actuator and the 3-DOF equations of motion.
//!
//! The plant's state is [`AircraftState`]; [`Aircraft::derivative`] gives its time
//! derivative for given [`AircraftCommands`] and wind. Wind enters only through the
//! air-relative velocity.
//!
//! [`Plant`] is the interface the closed loop flies: [`Aircraft`] implements it, and so
//! does the 6-DOF aircraft ([`six_dof::SixDofAircraft`]); [`PlantModel`] names them.

mod actuator;
mod aerodynamic_data;
mod aerodynamics;
mod built_plant;
mod central_difference;
mod configuration;
mod dynamics;
mod engine;
mod hook;
mod linearize;
mod parameters;
mod plant;
pub mod six_dof;
mod state;
mod trim;

pub use crate::environment::Wind;
pub use actuator::{ActuatorLimit, ElevatorActuator, ElevatorActuatorParameters};
pub use aerodynamic_data::{
    powers_of, AerodynamicData, Configurations, ForceCoefficient, LateralCoefficient,
    PitchingMomentCoefficient, Polynomial, MAX_POLYNOMIAL_TERMS,
};
pub use aerodynamics::{
    aerodynamic_coefficients, aerodynamic_coefficients_trig, AerodynamicCoefficients,
    ALPHA_MAX_RAD, ALPHA_MIN_RAD,
};
pub use built_plant::{BuiltPlant, WithPlant};
pub use configuration::{AerodynamicConfiguration, ConfigurationName};
pub use dynamics::{AirData, Aircraft, AircraftCommands, AirframeInputs, OpenLoopAircraft};
pub use engine::{EngineParameters, Engines};
pub use hook::HookGeometry;
pub use linearize::{linearize, LinearModel, INPUT_NAMES, INPUT_UNITS, STATE_NAMES, STATE_UNITS};
pub use parameters::AircraftParameters;
pub use plant::{
    ApproachOutcome, LateralKinematics, LongitudinalKinematic, Plant, PlantAirData, PlantCommands,
    PlantKinematics, PlantModel,
};
pub use state::AircraftState;
pub use trim::{trim, TrimError, TrimPoint, TrimReport, TrimRequest, TrimResiduals};
