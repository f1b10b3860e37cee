//! Angle-of-attack protection on the approach's pitch command (docs/landing-design.md,
//! "Angle-of-attack protection"): the floor the outer loops put under θ_ref.

use super::outer_loop_signals::OuterLoopInputs;

/// Angle-of-attack protection on the approach's pitch command (envelope protection, as
/// fly-by-wire control laws have): θ_ref ≥ θ − α_p + α_min, with α_p = α + τ·q the
/// angle of attack predicted a lead τ ahead. Where the pitch command would take α_p
/// below α_min it becomes the command that holds α_p there; the floor is a continuous
/// function of the aircraft's state, so the command never steps as it engages
/// (`tests/command_continuity.rs`). In the heavy sea, a path moved by metres far out
/// asked for a climb and then a dive that took α below the aerodynamic model's −5°
/// (docs/landing-design.md).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AlphaFloor {
    /// The floor α_min (rad).
    pub min_alpha_rad: f64,
    /// The lead τ of the predicted angle of attack (s).
    pub lead_s: f64,
}

impl AlphaFloor {
    /// The pitch command `theta_rad` limited from below, and whether the floor raised it.
    #[inline(always)]
    pub(crate) fn floored_pitch(&self, theta_rad: f64, inputs: &OuterLoopInputs) -> (f64, bool) {
        let predicted_alpha = inputs.alpha_rad + self.lead_s * inputs.pitch_rate_radps;
        let floor = inputs.theta_rad - predicted_alpha + self.min_alpha_rad;
        if theta_rad < floor {
            (floor, true)
        } else {
            (theta_rad, false)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Hook and aircraft inputs with attitude `theta_deg`, angle of attack `alpha_deg`
    /// and pitch rate `q_degps`.
    fn inputs(theta_deg: f64, alpha_deg: f64, q_degps: f64) -> OuterLoopInputs {
        OuterLoopInputs {
            time_s: 15.0,
            theta_trim_rad: 4.0_f64.to_radians(),
            climb_rate_mps: -3.5,
            air_path_angle_rad: (theta_deg - alpha_deg).to_radians(),
            theta_rad: theta_deg.to_radians(),
            alpha_rad: alpha_deg.to_radians(),
            pitch_rate_radps: q_degps.to_radians(),
            hook_x_m: -500.0,
            hook_h_m: 30.0,
            hook_x_rate_mps: 65.0,
            hook_climb_rate_mps: -3.5,
            sink_rate_integral_m: 0.0,
            guidance_integral_m_s: 0.0,
            wake_pitch_feedforward_rad: 0.0,
        }
    }

    /// Floor 0°, lead 0.3 s. At θ = 4°, α = 7°, q = 0 the predicted α is 7°, the floor on
    /// the command θ − 7° = −3°: a command of 2° passes untouched, −5° is raised to −3°.
    /// Pitching down at 10 °/s the predicted α is 4°, the floor 0°: 2° passes, −1° is
    /// raised to 0°. Pitching up at 10 °/s it is 10°, and −5° passes (−6° floor).
    #[test]
    fn the_alpha_floor_limits_the_command_only_near_the_floor() {
        let floor = AlphaFloor {
            min_alpha_rad: 0.0,
            lead_s: 0.3,
        };
        let check = |theta, alpha, q, command_deg: f64, expected_deg: f64, floored| {
            let (theta_ref, was) =
                floor.floored_pitch(command_deg.to_radians(), &inputs(theta, alpha, q));
            assert!(
                (theta_ref.to_degrees() - expected_deg).abs() < 1e-9,
                "θ {theta}°, α {alpha}°, q {q}°/s: {command_deg}° → {}°",
                theta_ref.to_degrees()
            );
            assert_eq!(was, floored);
        };
        check(4.0, 7.0, 0.0, 2.0, 2.0, false);
        check(4.0, 7.0, 0.0, -5.0, -3.0, true);
        check(4.0, 7.0, -10.0, 2.0, 2.0, false);
        check(4.0, 7.0, -10.0, -1.0, 0.0, true);
        check(4.0, 7.0, 10.0, -5.0, -5.0, false);
        // The floored command is continuous across the floor: just above it, itself.
        check(4.0, 7.0, 0.0, -3.0 + 1e-9, -3.0 + 1e-9, false);
    }
}
