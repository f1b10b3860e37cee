//! The aircraft section of a scenario: the model flown and its parameters.

use crate::aircraft::six_dof::{LateralParameters, SixDofAircraft, SurfaceActuatorParameters};
use crate::aircraft::{
    AerodynamicConfiguration, AircraftParameters, ConfigurationName, ElevatorActuatorParameters,
    EngineParameters, HookGeometry, PlantModel,
};
use crate::parameters::ParameterError;
use serde::{Deserialize, Serialize};

/// The aircraft section of a scenario.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AircraftSection {
    /// The aircraft model: `6dof` (docs/six-dof.md; the realistic set's default, which
    /// flies the 3-D approach) or `3dof` (the longitudinal F/A-18; the paper's set always
    /// flies it).
    pub model: PlantModel,
    /// Aerodynamic configuration: `landing` (default) or `clean` (docs/model.md §2.3).
    pub configuration: ConfigurationName,
    /// Mass, geometry, atmosphere (paper Table 2).
    pub parameters: AircraftParameters,
    /// Engines (docs/model.md §2.5).
    pub engines: EngineParameters,
    /// Elevator actuator (docs/model.md §2.6).
    pub elevator_actuator: ElevatorActuatorParameters,
    /// Hook point (docs/model.md §2.7).
    pub hook: HookGeometry,
    /// The 6-DOF model's span and inertias (docs/six-dof.md).
    pub lateral: LateralParameters,
    /// The 6-DOF model's aileron actuator (docs/six-dof.md).
    pub aileron_actuator: SurfaceActuatorParameters,
    /// The 6-DOF model's rudder actuator (docs/six-dof.md).
    pub rudder_actuator: SurfaceActuatorParameters,
}

impl Default for AircraftSection {
    fn default() -> Self {
        Self {
            model: PlantModel::default(),
            configuration: ConfigurationName::default(),
            parameters: AircraftParameters::default(),
            engines: EngineParameters::default(),
            elevator_actuator: ElevatorActuatorParameters::default(),
            hook: HookGeometry::default(),
            lateral: LateralParameters::default(),
            aileron_actuator: SurfaceActuatorParameters::AILERON,
            rudder_actuator: SurfaceActuatorParameters::RUDDER,
        }
    }
}

impl AircraftSection {
    /// The aerodynamic increments of the named configuration.
    pub fn aerodynamics(&self) -> AerodynamicConfiguration {
        AerodynamicConfiguration::named(self.configuration)
    }

    /// Checks every part of the aircraft.
    pub fn validate(&self) -> Result<(), ParameterError> {
        self.parameters.validate()?;
        self.engines.validate()?;
        self.elevator_actuator.validate()?;
        self.hook.validate()?;
        self.lateral.validate()?;
        self.aileron_actuator
            .validate(SixDofAircraft::AILERON_SECTION)?;
        self.rudder_actuator
            .validate(SixDofAircraft::RUDDER_SECTION)
    }
}
