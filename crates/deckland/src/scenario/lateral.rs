//! The scenario's lateral laws (`[control.roll]`, `[control.yaw]`): what the 6-DOF
//! aircraft's roll and yaw channels fly (docs/lateral-control.md), and their checks.

use super::{check_observer_resolved, HardwareSet, Scenario};
use crate::control::lateral::{LateralChannel, LateralLawParameters};
use crate::parameters::ParameterError;

/// Why a lateral section is refused with the paper's hardware set.
const PAPER_HAS_NO_LATERAL_AXES: &str =
    "the channel's designed law with `hardware = \"paper\"`: the paper's set flies the 3-DOF \
     model, which has no roll or yaw channel (remove the section, or use \
     `hardware = \"realistic\"`)";

impl Scenario {
    /// The roll law (bank → aileron) and the yaw law (sideslip → rudder) the 6-DOF
    /// aircraft flies: `[control.roll]` and `[control.yaw]`, each the channel's
    /// registered O-PD unless the scenario names another law or tuning. Build them with
    /// [`LateralLawParameters::build_roll`] and [`LateralLawParameters::build_yaw`].
    pub fn lateral_laws(&self) -> (LateralLawParameters, LateralLawParameters) {
        (self.control.roll, self.control.yaw)
    }

    /// The lateral laws' checks beyond each key's range: the paper's set flies none of its
    /// own (its lateral laws must be the designed ones, which a file may write or leave
    /// out, as a paper scenario written to TOML does), and an O-PD's observer (k3/ε rad/s) must be resolved by the integration step
    /// (k3·dt/ε ≤ 0.5), as the pitch O-PD's.
    pub(super) fn check_lateral_laws(&self) -> Result<(), ParameterError> {
        for (channel, law) in [
            (LateralChannel::Roll, self.control.roll),
            (LateralChannel::Yaw, self.control.yaw),
        ] {
            let section = channel.section();
            if self.hardware == HardwareSet::Paper
                && law != LateralLawParameters::default_for(channel)
            {
                return Err(ParameterError::new(
                    "control",
                    channel_key(channel),
                    law.label(),
                    PAPER_HAS_NO_LATERAL_AXES,
                ));
            }
            if let LateralLawParameters::ObserverPd(opd) = law {
                check_observer_resolved(
                    &opd.observer,
                    &crate::parameters::join(section, "observer"),
                    self.time_step_s,
                )?;
            }
        }
        Ok(())
    }
}

/// The channel's key under `[control]`.
fn channel_key(channel: LateralChannel) -> &'static str {
    match channel {
        LateralChannel::Roll => "roll",
        LateralChannel::Yaw => "yaw",
    }
}
