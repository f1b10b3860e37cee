//! The approach trim and the laws a lateral step flies.

use super::spec::LateralStepError;
use crate::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, SixDofAircraft, SixDofTrimPoint, SixDofTrimRequest,
};
use crate::aircraft::{PlantModel, TrimRequest};
use crate::control::lateral::design::{channel_hardware, channel_plants};
use crate::control::lateral::{
    LateralChannel, LateralDesignContext, LateralLawParameters, RollLaw, YawLaw,
};
use crate::parameters::ParameterError;
use crate::scenario::{HardwareSet, Scenario};

/// The approach trim, its linearisation's channel plants and each channel's design
/// context: what the laws are built from.
#[derive(Debug, Clone, Copy)]
pub struct LateralSetup {
    /// The aircraft.
    pub aircraft: SixDofAircraft,
    /// The trim point.
    pub trim: SixDofTrimPoint,
    /// The roll channel's design context.
    pub roll: LateralDesignContext,
    /// The yaw channel's design context.
    pub yaw: LateralDesignContext,
}

impl LateralSetup {
    /// The default aircraft at the approach trim (69.1 m/s, level): the default
    /// scenario's ([`LateralSetup::from_scenario`]).
    pub fn approach() -> Result<Self, LateralStepError> {
        Self::from_scenario(&Scenario::default())
    }

    /// The 6-DOF aircraft of `scenario` (its `[aircraft]` section: mass, configuration,
    /// engines, span and inertias, and the aileron and rudder actuators of its hardware
    /// set), trimmed level at its approach airspeed (`approach.airspeed_mps`). The paper's
    /// set and a scenario whose `aircraft.model` is the 3-DOF aircraft have no lateral axes
    /// and are refused.
    pub fn from_scenario(scenario: &Scenario) -> Result<Self, LateralStepError> {
        if scenario.hardware == HardwareSet::Paper {
            return Err(LateralStepError::Setup(
                "`hardware` = \"paper\" has no lateral axes: the paper's set flies the 3-DOF \
                 model; a roll or yaw step flies the realistic set or a scenario file on it"
                    .to_owned(),
            ));
        }
        if scenario.aircraft.model == PlantModel::ThreeDof {
            return Err(LateralStepError::Setup(
                "the scenario file sets `aircraft.model` = \"3dof\", the longitudinal aircraft, \
                 which has no roll or yaw axis; write `model = \"6dof\"` (or leave the key out) \
                 to fly a lateral step"
                    .to_owned(),
            ));
        }
        scenario.validate()?;
        let section = &scenario.aircraft;
        let longitudinal = section.longitudinal_aircraft()?;
        let aircraft = SixDofAircraft::new(
            longitudinal,
            section.lateral,
            section.aileron_actuator,
            section.rudder_actuator,
        )?;
        let request = SixDofTrimRequest {
            longitudinal: TrimRequest {
                speed_mps: scenario.approach.airspeed_mps,
                ..TrimRequest::default()
            },
            ..SixDofTrimRequest::default()
        };
        let trim = trim_six_dof(&aircraft, &request).map_err(|e| {
            LateralStepError::Setup(format!(
                "the approach does not trim at `approach.airspeed_mps` = {} m/s: {e}",
                scenario.approach.airspeed_mps
            ))
        })?;
        let model = linearize_six_dof(&aircraft, &trim);
        let (roll, yaw) = channel_plants(&model);
        let context = |channel, plant| LateralDesignContext {
            plant,
            actuator: channel_hardware(&aircraft, &model, channel).actuator,
        };
        Ok(Self {
            aircraft,
            trim,
            roll: context(LateralChannel::Roll, roll),
            yaw: context(LateralChannel::Yaw, yaw),
        })
    }

    /// The roll law `roll` and the yaw law `yaw` built on this trim's channels.
    pub fn laws(
        &self,
        roll: &LateralLawParameters,
        yaw: &LateralLawParameters,
    ) -> Result<LateralLaws, ParameterError> {
        Ok((roll.build_roll(&self.roll)?, yaw.build_yaw(&self.yaw)?))
    }

    /// The registered law `name` on both channels, with its designed tuning.
    pub fn registered_laws(&self, name: &str) -> Result<LateralLaws, ParameterError> {
        let (roll, yaw) = registered_pair(name)?;
        self.laws(&roll, &yaw)
    }

    /// The law `name` on both channels: `scenario`'s own section where it names that law
    /// (`[control.roll]`, `[control.yaw]`, with its tuning), else the registered law's
    /// designed tuning. This is how `deckland step --axis roll|yaw --scenario FILE` flies
    /// the O-PD and the PID of a file that tunes only one of them.
    pub fn scenario_laws(
        &self,
        scenario: &Scenario,
        name: &str,
    ) -> Result<LateralLaws, ParameterError> {
        let (registered_roll, registered_yaw) = registered_pair(name)?;
        let (own_roll, own_yaw) = scenario.lateral_laws();
        let pick = |own: LateralLawParameters, registered: LateralLawParameters| {
            if own.type_name() == name {
                own
            } else {
                registered
            }
        };
        self.laws(
            &pick(own_roll, registered_roll),
            &pick(own_yaw, registered_yaw),
        )
    }
}

/// The registered law `name` on the roll and the yaw channel.
fn registered_pair(
    name: &str,
) -> Result<(LateralLawParameters, LateralLawParameters), ParameterError> {
    let unknown = |section| {
        ParameterError::new(
            section,
            "type",
            name,
            "one of the registered lateral laws: observer_pd, pid",
        )
    };
    let roll = LateralLawParameters::registered(name, LateralChannel::Roll)
        .ok_or_else(|| unknown(LateralChannel::Roll.section()))?;
    let yaw = LateralLawParameters::registered(name, LateralChannel::Yaw)
        .ok_or_else(|| unknown(LateralChannel::Yaw.section()))?;
    Ok((roll, yaw))
}

/// A roll law and a yaw law.
pub type LateralLaws = (Box<dyn RollLaw>, Box<dyn YawLaw>);
