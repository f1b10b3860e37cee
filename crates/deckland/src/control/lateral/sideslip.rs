//! The sideslip the yaw law reads: the air data's β blended with the inertial β̇ (a
//! complementary filter; docs/lateral-control.md, "Sideslip estimate").
//!
//! The air-data sideslip is right on average but noisy (σ 0.2° per sample, docs/model.md
//! §10.7), and the yaw law's control power is small (1/|N_δr| ≈ 2.1 rad of rudder per
//! rad/s² asked), so its noise reaches the rudder amplified. The inertial sensors give
//! β's rate cleanly: β ≈ v_a/V, so β̇ ≈ v̇/V from the body-axis acceleration (the
//! accelerometers and the attitude: v̇ = a_y + g·sinφ·cosθ + p·w − r·u), wrong only by
//! the wind's changes. The blend integrates the inertial rate and pulls the result
//! towards the air data with the crossover frequency k_c:
//!
//! β̂̇ = β̇_inertial + k_c·(β_air − β̂),
//!
//! so the air data passes below k_c (where the wind acts) and the inertial rate above it
//! (where the noise is). Sampled each frame T of the flight computer: the inertial rate
//! predicts, the air data corrects with the gain a first-order lag of k_c has over a
//! frame, β̂⁻ = β̂ + T·β̇_inertial, β̂ ← β̂⁻ + (1 − e^(−k_c·T))·(β_air − β̂⁻).

use crate::parameters::{Bounds, ParameterError};

/// Crossover k_c of the registered blend (rad/s): docs/lateral-control.md.
pub const SIDESLIP_BLEND_CROSSOVER_RADPS: f64 = 5.0;

/// The complementary filter on sideslip.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SideslipBlend {
    crossover_radps: f64,
    estimate_rad: Option<f64>,
}

impl SideslipBlend {
    /// A blend crossing over at `crossover_radps` (rad/s), in (0, 1000]; it starts at the
    /// first air-data sample.
    pub fn new(crossover_radps: f64) -> Result<Self, ParameterError> {
        Bounds::positive_up_to(1000.0).check(
            "sideslip_blend",
            "crossover_radps",
            crossover_radps,
        )?;
        Ok(Self {
            crossover_radps,
            estimate_rad: None,
        })
    }

    /// The estimate after a frame of `frame_s` (s) in which the inertial sideslip rate was
    /// `inertial_rate_radps` (rad/s), given the new air-data sample `air_data_rad` (rad).
    pub fn update(&mut self, air_data_rad: f64, inertial_rate_radps: f64, frame_s: f64) -> f64 {
        let estimate = match self.estimate_rad {
            None => air_data_rad,
            Some(previous) => {
                let predicted = previous + frame_s * inertial_rate_radps;
                let gain = 1.0 - (-self.crossover_radps * frame_s).exp();
                predicted + gain * (air_data_rad - predicted)
            }
        };
        self.estimate_rad = Some(estimate);
        estimate
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A ramp in β seen by both sensors is followed without lag; the air data's offset is
    /// taken on at the crossover (63 % after 1/k_c).
    #[test]
    fn the_blend_follows_the_inertial_rate_and_converges_on_the_air_data() {
        let mut blend = SideslipBlend::new(2.0).expect("valid");
        let frame = 0.0125;
        let rate = 0.01;
        for k in 0..200 {
            let beta = rate * frame * k as f64;
            let estimate = blend.update(beta, rate, frame);
            assert!((estimate - beta).abs() < 1e-12, "{k}: {estimate} vs {beta}");
        }
        // An air-data offset of 1 mrad with no inertial rate: after 0.5 s (1/k_c)
        // 1 − e⁻¹ of it is taken on.
        let mut blend = SideslipBlend::new(2.0).expect("valid");
        blend.update(0.0, 0.0, frame);
        let mut estimate = 0.0;
        for _ in 0..40 {
            estimate = blend.update(0.001, 0.0, frame);
        }
        assert!((estimate - 0.001 * (1.0 - (-1.0f64).exp())).abs() < 1e-12);
        assert!(SideslipBlend::new(0.0).is_err());
    }
}
