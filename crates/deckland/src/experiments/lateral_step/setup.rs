//! The approach trim and the registered laws a lateral step flies.

use super::spec::LateralStepError;
use crate::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, SixDofAircraft, SixDofTrimPoint, SixDofTrimRequest,
};
use crate::control::lateral::design::{channel_hardware, channel_plants};
use crate::control::lateral::{
    LateralChannel, LateralDesignContext, LateralLawParameters, RollLaw, YawLaw,
};
use crate::parameters::ParameterError;

/// The approach trim, its linearisation's channel plants and each channel's design
/// context: what the registered laws are built from.
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
    /// The default aircraft at the approach trim (69.1 m/s, level).
    pub fn approach() -> Result<Self, LateralStepError> {
        let aircraft = SixDofAircraft::default();
        let trim = trim_six_dof(&aircraft, &SixDofTrimRequest::default())
            .map_err(|e| LateralStepError::Setup(format!("the approach does not trim: {e}")))?;
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

    /// The registered law `name` on both channels.
    pub fn registered_laws(&self, name: &str) -> Result<LateralLaws, ParameterError> {
        let unknown = |section| {
            ParameterError::new(
                section,
                "type",
                f64::NAN,
                "one of the registered lateral laws: observer_pd, pid",
            )
        };
        let roll = LateralLawParameters::registered(name, LateralChannel::Roll)
            .ok_or_else(|| unknown(LateralChannel::Roll.section()))?;
        let yaw = LateralLawParameters::registered(name, LateralChannel::Yaw)
            .ok_or_else(|| unknown(LateralChannel::Yaw.section()))?;
        Ok((roll.build_roll(&self.roll)?, yaw.build_yaw(&self.yaw)?))
    }
}

/// A roll law and a yaw law.
pub type LateralLaws = (Box<dyn RollLaw>, Box<dyn YawLaw>);
