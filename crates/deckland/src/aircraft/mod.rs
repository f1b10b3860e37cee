//! The longitudinal F/A-18 plant (MODEL.md §2): aerodynamics, engines, elevator
//! actuator and the 3-DOF equations of motion.
//!
//! The plant's state is [`AircraftState`]; [`Aircraft::derivative`] gives its time
//! derivative for given [`AircraftCommands`] and wind. Wind enters only through the
//! air-relative velocity.

mod actuator;
mod aerodynamics;
mod configuration;
mod dynamics;
mod engine;
mod error;
mod hook;
mod parameters;
mod state;

pub use crate::environment::Wind;
pub use actuator::{ActuatorLimit, ElevatorActuator, ElevatorActuatorParameters};
pub use aerodynamics::{
    aerodynamic_coefficients, aerodynamic_coefficients_trig, AerodynamicCoefficients,
    ALPHA_MAX_RAD, ALPHA_MIN_RAD,
};
pub use configuration::{AerodynamicConfiguration, ConfigurationName};
pub use dynamics::{AirData, Aircraft, AircraftCommands, AirframeInputs, OpenLoopAircraft};
pub use engine::{EngineParameters, Engines};
pub use error::AircraftError;
pub use hook::HookGeometry;
pub use parameters::AircraftParameters;
pub use state::AircraftState;
