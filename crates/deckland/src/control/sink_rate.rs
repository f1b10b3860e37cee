//! Sink-rate controller: pitch command from the climb-rate error (paper §4.4, Eq. 43).
//!
//! θ_ref = θ*_gs + K_Ps·e_s + K_Is·∫e_s, e_s = ḣ_cmd − ḣ (climb rates, positive up; the
//! sink rate is −ḣ), where θ*_gs is the trim pitch on the glide path (docs/model.md §5). The
//! correction is limited to ±`pitch_authority_deg` with conditional-integration
//! anti-windup.

use super::loop_controller::{LoopController, LoopGains};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Gains and limits of the sink-rate loop.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct SinkRateControllerParameters {
    /// Proportional gain K_Ps (rad of pitch per m/s of climb-rate error).
    pub proportional_rad_per_mps: f64,
    /// Integral gain K_Is (rad of pitch per m of integrated climb-rate error).
    pub integral_rad_per_m: f64,
    /// Largest pitch correction either side of θ*_gs (deg).
    pub pitch_authority_deg: f64,
    /// Angle-of-attack protection on the approach (envelope protection, as fly-by-wire
    /// control laws have): the pitch command is kept at or above θ − α_p + α_min, with
    /// α_p = α + τ·q the angle of attack predicted `alpha_lead_s` ahead, so that the
    /// aircraft never pushes over below `min_alpha_deg` to follow the path. On in the
    /// realistic set; off in the paper's, which has no such law.
    pub alpha_protection: bool,
    /// The floor α_min of the protection (deg): −1°, 4° inside the aerodynamic model's
    /// range (it ends at −5°; the pitch loop's lag lets α undershoot the floor by up to
    /// 3° in the heavy sea) and 8° below the approach's α ≈ 7°, so that it acts on a
    /// push-over and seldom on an ordinary approach (docs/landing-design.md); [−5, 15].
    pub min_alpha_deg: f64,
    /// The lead τ of the predicted angle of attack α + τ·q (s): the pitch loop lags its
    /// command by a few tenths of a second, so the floor acts on where α is going;
    /// 0.3 s; [0, 2].
    pub alpha_lead_s: f64,
}

impl Default for SinkRateControllerParameters {
    /// The design for the realistic hardware: K_Ps = 0.035, K_Is = 0.006, ±8°.
    ///
    /// Behind the slower pitch loop of the rate-limited stabilator (crossover 4.3 rad/s
    /// against 22.5), the ideal actuator's K_Is = 0.012 leaves the sink-rate loop 36.7° of
    /// phase margin; halving the integral gain restores 47° at 0.96 rad/s, with guidance
    /// at 52° and the speed loop at 49° (docs/landing-design.md, `--example margins`).
    fn default() -> Self {
        Self {
            integral_rad_per_m: 0.006,
            alpha_protection: true,
            ..Self::for_ideal_actuator()
        }
    }
}

impl SinkRateControllerParameters {
    /// The project's design for the paper's ideal actuator: K_Ps = 0.035, K_Is = 0.012,
    /// ±8°, no angle-of-attack protection (the paper's set).
    ///
    /// Chosen below docs/model.md §5's starting point (0.05, 0.02): in adverse conditions that
    /// gain lets the wake's climb-rate swings (vertical gusts of about ±3 m/s met at
    /// 5.8 rad/s) into the pitch command and saturates the elevator; over seeds 1–50 it
    /// boarded 68 % with 3 hard landings, against 76 % and none at 0.035/0.012, while
    /// 0.025/0.008 bolted more (docs/landing-design.md; `cargo run --release -p deckland
    /// --example outer_loop_sweep`). The authority is a margin; these gains do not reach it.
    pub fn for_ideal_actuator() -> Self {
        Self {
            proportional_rad_per_mps: 0.035,
            integral_rad_per_m: 0.012,
            pitch_authority_deg: 8.0,
            alpha_protection: false,
            min_alpha_deg: -1.0,
            alpha_lead_s: 0.3,
        }
    }
}

impl SinkRateControllerParameters {
    /// The paper's gains (§4.4): K_Ps = 0.0061, K_Is = 0.018. They do not fly this plant
    /// together with the paper's guidance gains (docs/model.md §5).
    pub fn paper() -> Self {
        Self {
            proportional_rad_per_mps: 0.0061,
            integral_rad_per_m: 0.018,
            ..Self::default()
        }
    }

    /// Checks gains are finite, the authority positive, the protection's floor within
    /// [−5°, 15°] (the aerodynamic model's lower end to the stall's side of the approach)
    /// and its lead within [0, 2] s.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "control.sink_rate";
        let gain = Bounds::closed(-10.0, 10.0);
        gain.check(
            SECTION,
            "proportional_rad_per_mps",
            self.proportional_rad_per_mps,
        )?;
        gain.check(SECTION, "integral_rad_per_m", self.integral_rad_per_m)?;
        check_ranges!(SECTION, self, {
            pitch_authority_deg: Bounds::positive_up_to(30.0),
            min_alpha_deg: Bounds::closed(-5.0, 15.0),
            alpha_lead_s: Bounds::closed(0.0, 2.0),
        });
        Ok(())
    }

    /// The loop as a limited PI controller (output: pitch correction in rad).
    pub fn controller(&self) -> LoopController {
        let authority = self.pitch_authority_deg.to_radians();
        LoopController {
            gains: LoopGains {
                proportional: self.proportional_rad_per_mps,
                integral: self.integral_rad_per_m,
                derivative: 0.0,
            },
            output_min: -authority,
            output_max: authority,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The angle-of-attack protection is on in the realistic set and off in the paper's;
    /// a floor below the aerodynamic model's −5° or a negative lead is refused, named.
    #[test]
    fn the_alpha_protection_keys_are_checked_by_name() {
        assert!(SinkRateControllerParameters::default().alpha_protection);
        assert!(!SinkRateControllerParameters::for_ideal_actuator().alpha_protection);
        assert!(SinkRateControllerParameters::default().validate().is_ok());
        let low = SinkRateControllerParameters {
            min_alpha_deg: -6.0,
            ..SinkRateControllerParameters::default()
        };
        let error = low.validate().expect_err("below −5°");
        assert_eq!(error.path, "control.sink_rate.min_alpha_deg");
        assert!(error.to_string().contains("-6"), "{error}");
        let lead = SinkRateControllerParameters {
            alpha_lead_s: -0.1,
            ..SinkRateControllerParameters::default()
        };
        let error = lead.validate().expect_err("negative lead");
        assert_eq!(error.path, "control.sink_rate.alpha_lead_s");
    }
}
