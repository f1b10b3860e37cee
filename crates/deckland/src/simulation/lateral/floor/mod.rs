//! What no lateral forecast can see (docs/model.md §10.3): the σ of the aim point's
//! displacement across the bearing that the ship's roll, yaw and sway filters will add
//! over a horizon τ, given their exact state now.
//!
//! Each filter is ż = A z + B n with white noise n of intensity q (roll: the oscillator
//! 1/(s² + 2ζωs + ω²); yaw and sway: the canonical 1/D(s), docs/model.md §3.7). From a
//! known state the output's error after τ is the noise still to come, of variance
//! q·[P∞ − e^{Aτ} P∞ e^{Aᵀτ}]₁₁, P∞ the filter's stationary covariance for unit
//! intensity (as for heave and pitch, `environment::ship_prediction`). The three are
//! independent, and the aim point moves across the bearing by k_φ·φ_s + k_ψ·ψ_s + k_y·y_s
//! to first order, k the deck geometry's sensitivities
//! ([`super::forecast::aim_point_displacement_m`] by central differences), so
//!
//! ```text
//! σ²(τ) = k_φ²·q_φ·U_φ(τ) + (k_ψ²·q_ψ + k_y²·q_y)·U_D(τ)
//! ```
//!
//! tabulated once per run on a 0.05-s grid and interpolated linearly. Beyond the table
//! the stationary value, an upper bound, is used. It is the floor: the approach's own
//! forecast (the dominant mode of yaw and sway, a measurement with noise and latency)
//! sees less, which the lateral wave-off's hook scatter covers
//! ([`crate::control::wave_off_lateral`]).

use nalgebra::{Matrix2, Matrix4};

use super::forecast::aim_point_displacement_m;
use crate::environment::{
    roll_filter_companion, roll_unit_intensity_state_covariance, shaping_filter_companion,
    unit_intensity_state_covariance, DeckGeometry, LateralShipMotion,
};

/// Grid spacing of the table (s).
const GRID_S: f64 = 0.05;
/// The longest horizon tabulated (s): the time to go is clamped to 60 s.
const MAX_HORIZON_S: f64 = 62.0;
/// Step of the central differences for the sensitivities (rad for roll and yaw, m for
/// sway): small against the motion, large against rounding.
const DIFFERENCE_STEP: f64 = 1e-4;

/// The tabulated floor of the aim point's lateral forecast (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct AimPointLateralFloor {
    /// σ²(τ) at τ = k·[`GRID_S`] (m²).
    variances: Vec<f64>,
    /// The stationary variance (m²): the limit as τ grows.
    stationary_m2: f64,
}

/// The unforeseeable part after `horizon_s` of a unit-intensity filter's first state:
/// P∞₁₁ − (e^{Aτ} P∞ e^{Aᵀτ})₁₁, for the transition's first row `row`.
fn unforeseeable<const N: usize>(row: &[f64; N], stationary: &[[f64; N]; N]) -> f64 {
    let mut carried = 0.0;
    for i in 0..N {
        for j in 0..N {
            carried += row[i] * stationary[i][j] * row[j];
        }
    }
    (stationary[0][0] - carried).max(0.0)
}

impl AimPointLateralFloor {
    /// The floor for the ship `ship` (its noise intensities) and the deck `deck` (its
    /// geometry's sensitivities).
    pub fn new(ship: &LateralShipMotion, deck: &DeckGeometry) -> Self {
        let [q_roll, q_yaw, q_sway] = ship.noise_intensities();
        let [k_roll, k_yaw, k_sway] = aim_point_sensitivities(deck);
        let roll_weight = k_roll * k_roll * q_roll;
        let canonical_weight = k_yaw * k_yaw * q_yaw + k_sway * k_sway * q_sway;
        let roll_p = roll_unit_intensity_state_covariance();
        let canonical_p = unit_intensity_state_covariance();
        let roll_step = (roll_filter_companion() * GRID_S).exp();
        let canonical_step = (shaping_filter_companion() * GRID_S).exp();
        let count = (MAX_HORIZON_S / GRID_S).ceil() as usize + 1;
        let (mut roll_transition, mut canonical_transition) =
            (Matrix2::<f64>::identity(), Matrix4::<f64>::identity());
        let mut variances = Vec::with_capacity(count);
        for _ in 0..count {
            let roll_row = [roll_transition[(0, 0)], roll_transition[(0, 1)]];
            let canonical_row: [f64; 4] = std::array::from_fn(|j| canonical_transition[(0, j)]);
            variances.push(
                roll_weight * unforeseeable(&roll_row, &roll_p)
                    + canonical_weight * unforeseeable(&canonical_row, &canonical_p),
            );
            roll_transition *= roll_step;
            canonical_transition *= canonical_step;
        }
        Self {
            variances,
            stationary_m2: roll_weight * roll_p[0][0] + canonical_weight * canonical_p[0][0],
        }
    }

    /// σ of the aim point's displacement across the bearing that no forecast made
    /// `horizon_s` earlier can see (m).
    pub fn sigma_m(&self, horizon_s: f64) -> f64 {
        let position = horizon_s.max(0.0) / GRID_S;
        let index = position as usize;
        if index + 1 >= self.variances.len() {
            return self.stationary_m2.sqrt();
        }
        let fraction = position - index as f64;
        let (v0, v1) = (self.variances[index], self.variances[index + 1]);
        (v0 + fraction * (v1 - v0)).max(0.0).sqrt()
    }

    /// The stationary σ (m): the aim point's lateral RMS, to first order.
    pub fn stationary_sigma_m(&self) -> f64 {
        self.stationary_m2.sqrt()
    }
}

/// The aim point's displacement across the bearing per unit ship roll (m/rad), yaw
/// (m/rad) and sway (m/m), from the deck's geometry by central differences.
pub fn aim_point_sensitivities(deck: &DeckGeometry) -> [f64; 3] {
    let h = DIFFERENCE_STEP;
    let slope = |f: &dyn Fn(f64) -> f64| (f(h) - f(-h)) / (2.0 * h);
    [
        slope(&|x| aim_point_displacement_m(deck, x, 0.0, 0.0)),
        slope(&|x| aim_point_displacement_m(deck, 0.0, x, 0.0)),
        slope(&|x| aim_point_displacement_m(deck, 0.0, 0.0, x)),
    ]
}

#[cfg(test)]
mod tests;
