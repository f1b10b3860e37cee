//! The aircraft section of a scenario: the model flown and its parameters.

use super::hardware::HardwareSet;
use crate::aircraft::six_dof::{LateralParameters, SixDofAircraft, SurfaceActuatorParameters};
use crate::aircraft::{
    AerodynamicConfiguration, AerodynamicData, Aircraft, AircraftParameters, ConfigurationName,
    ElevatorActuatorParameters, EngineParameters, HookGeometry, PlantModel,
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
    /// The aerodynamic coefficients' polynomials and the configurations' increments
    /// (docs/model.md "The aircraft as data"); the F/A-18's unless the scenario names
    /// another aircraft, and then written out in full.
    #[serde(skip_serializing_if = "AerodynamicData::is_fa18")]
    pub aerodynamics: AerodynamicData,
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
            aerodynamics: AerodynamicData::FA18,
        }
    }
}

impl AircraftSection {
    /// The aerodynamic increments of the named configuration.
    pub fn configuration_increments(&self) -> AerodynamicConfiguration {
        self.aerodynamics.configuration(self.configuration)
    }

    /// The longitudinal (3-DOF) aircraft of this section.
    pub fn longitudinal_aircraft(&self) -> Result<Aircraft, ParameterError> {
        Aircraft::new(
            self.parameters,
            self.configuration_increments(),
            self.engines,
            self.elevator_actuator,
        )?
        .with_aerodynamics(self.aerodynamics)
    }

    /// The 6-DOF aircraft of this section.
    pub fn six_dof_aircraft(&self) -> Result<SixDofAircraft, ParameterError> {
        SixDofAircraft::new(
            self.longitudinal_aircraft()?,
            self.lateral,
            self.aileron_actuator,
            self.rudder_actuator,
        )
    }

    /// Checks every part of the aircraft, and that `hardware` flies its model (the paper's
    /// set flies the 3-DOF model only).
    pub fn validate(&self, hardware: HardwareSet) -> Result<(), ParameterError> {
        self.validate_parts()?;
        if hardware == HardwareSet::Paper && self.model != PlantModel::ThreeDof {
            return Err(ParameterError::new(
                "aircraft",
                "model",
                self.model.name(),
                "\"3dof\" with `hardware = \"paper\"` (the paper's set flies the 3-DOF model)",
            ));
        }
        Ok(())
    }

    /// Checks every part of the aircraft.
    fn validate_parts(&self) -> Result<(), ParameterError> {
        self.parameters.validate()?;
        self.engines.validate()?;
        self.elevator_actuator.validate()?;
        self.hook.validate()?;
        self.lateral.validate()?;
        self.aileron_actuator
            .validate(SixDofAircraft::AILERON_SECTION)?;
        self.rudder_actuator
            .validate(SixDofAircraft::RUDDER_SECTION)?;
        self.aerodynamics.validate()
    }

    /// The natural frequency (rad/s) of the fastest surface actuator the model flies: the
    /// elevator's, and for the 6-DOF model the aileron's and the rudder's too.
    pub fn fastest_actuator_rad_s(&self) -> f64 {
        let elevator = self.elevator_actuator.natural_frequency_rad_s;
        match self.model {
            PlantModel::ThreeDof => elevator,
            PlantModel::SixDof => elevator
                .max(self.aileron_actuator.natural_frequency_rad_s)
                .max(self.rudder_actuator.natural_frequency_rad_s),
        }
    }
}

/// An aircraft definition file: everything that makes the aircraft, as data (docs/model.md
/// "The aircraft as data"). `deckland aircraft --print-default` prints the F/A-18's
/// ([`FA18_DEFINITION_TOML`]); a scenario flies another with `[aircraft] definition =
/// "FILE"`. Every section is required: an aircraft file says what the aircraft is.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AircraftDefinition {
    /// The aircraft's name, for the reader.
    pub name: String,
    /// Mass, reference geometry, pitch inertia and the (constant) atmosphere.
    pub parameters: AircraftParameters,
    /// Span and the roll and yaw inertias.
    pub lateral: LateralParameters,
    /// Engines.
    pub engines: EngineParameters,
    /// Elevator (stabilator) actuator.
    pub elevator_actuator: ElevatorActuatorParameters,
    /// Aileron actuator.
    pub aileron_actuator: SurfaceActuatorParameters,
    /// Rudder actuator.
    pub rudder_actuator: SurfaceActuatorParameters,
    /// Hook point.
    pub hook: HookGeometry,
    /// Aerodynamic polynomials and configurations.
    pub aerodynamics: AerodynamicData,
}

/// The F/A-18 as an aircraft definition file, commented with units and sources: the
/// built-in aircraft (a test checks that it is exactly [`AircraftSection::default`]'s).
pub const FA18_DEFINITION_TOML: &str = include_str!("fa18.toml");

/// The keys of `[aircraft]` that an aircraft definition holds.
const DEFINITION_SECTIONS: [&str; 8] = [
    "parameters",
    "lateral",
    "engines",
    "elevator_actuator",
    "aileron_actuator",
    "rudder_actuator",
    "hook",
    "aerodynamics",
];

impl AircraftDefinition {
    /// Whether the scenario key at dotted `path` (`aircraft.parameters.mass_kg`) is one
    /// that an aircraft definition holds.
    pub fn holds(path: &str) -> bool {
        path.strip_prefix("aircraft.").is_some_and(|rest| {
            let section = rest.split('.').next().unwrap_or(rest);
            DEFINITION_SECTIONS.contains(&section)
        })
    }

    /// Puts the definition's data into a scenario's aircraft section (its model and
    /// configuration stay the scenario's).
    pub fn apply_to(&self, section: &mut AircraftSection) {
        section.parameters = self.parameters;
        section.lateral = self.lateral;
        section.engines = self.engines;
        section.elevator_actuator = self.elevator_actuator;
        section.aileron_actuator = self.aileron_actuator;
        section.rudder_actuator = self.rudder_actuator;
        section.hook = self.hook;
        section.aerodynamics = self.aerodynamics;
    }

    /// Checks every part, as a scenario's aircraft section does.
    pub fn validate(&self) -> Result<(), ParameterError> {
        let mut section = AircraftSection::default();
        self.apply_to(&mut section);
        section.validate_parts()
    }
}
