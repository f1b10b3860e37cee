//! Guidance controller: climb-rate command from the hook's height error to the glide
//! path (paper §4.5, Eq. 44).
//!
//! ḣ_cmd = ḣ_path + K_Pz·e_h + K_Iz·∫e_h + K_Dz·ė_h, e_h = h_ref − h_hook: the path's own
//! climb rate is fed forward (docs/model.md §5) and the correction is limited to
//! ±`climb_rate_authority_mps` with conditional-integration anti-windup.

use super::loop_controller::{LoopController, LoopGains};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Gains and limits of the guidance loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GuidanceParameters {
    /// Proportional gain K_Pz (1/s: m/s of climb rate per m of height error).
    pub proportional_per_s: f64,
    /// Integral gain K_Iz (1/s²).
    pub integral_per_s2: f64,
    /// Derivative gain K_Dz (–).
    pub derivative: f64,
    /// Largest climb-rate correction either side of the path's climb rate (m/s).
    pub climb_rate_authority_mps: f64,
}

impl Default for GuidanceParameters {
    /// The project's design (docs/model.md §5): K_Pz = 0.3, K_Iz = 0.02, K_Dz = 0, ±5 m/s.
    fn default() -> Self {
        Self {
            proportional_per_s: 0.3,
            integral_per_s2: 0.02,
            derivative: 0.0,
            climb_rate_authority_mps: 5.0,
        }
    }
}

impl GuidanceParameters {
    /// The paper's gains (§4.5): K_Pz = 1, K_Iz = 0.5, K_Dz = 0.01. Faster than the sink
    /// loop they command; the cascade diverges with them (docs/model.md §5).
    pub fn paper() -> Self {
        Self {
            proportional_per_s: 1.0,
            integral_per_s2: 0.5,
            derivative: 0.01,
            ..Self::default()
        }
    }

    /// Checks gains are finite and the authority positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.guidance";
        let gain = Bounds::closed(-10.0, 10.0);
        gain.check(SECTION, "proportional_per_s", self.proportional_per_s)?;
        gain.check(SECTION, "integral_per_s2", self.integral_per_s2)?;
        gain.check(SECTION, "derivative", self.derivative)?;
        check_ranges!(SECTION, self, {
            climb_rate_authority_mps: Bounds::positive_up_to(30.0),
        });
        Ok(())
    }

    /// The loop as a limited PID controller (output: climb-rate correction in m/s).
    pub fn controller(&self) -> LoopController {
        LoopController {
            gains: LoopGains {
                proportional: self.proportional_per_s,
                integral: self.integral_per_s2,
                derivative: self.derivative,
            },
            output_min: -self.climb_rate_authority_mps,
            output_max: self.climb_rate_authority_mps,
        }
    }
}
