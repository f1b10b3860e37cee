//! The arresting hook's position (docs/model.md §2.7).

use super::state::AircraftState;
use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Where the hook point sits relative to the CG, in body axes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct HookGeometry {
    /// Distance of the hook point aft of the CG along body x (m); 7.0 m (docs/model.md §2.7).
    pub aft_of_cg_m: f64,
    /// Distance of the hook point below the CG along body z (m); 1.8 m (docs/model.md §2.7).
    pub below_cg_m: f64,
}

impl Default for HookGeometry {
    fn default() -> Self {
        Self {
            aft_of_cg_m: 7.0,
            below_cg_m: 1.8,
        }
    }
}

impl HookGeometry {
    /// Checks that both offsets are finite.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.hook";
        check_ranges!(SECTION, self, {
            aft_of_cg_m: Bounds::closed(-20.0, 20.0),
            below_cg_m: Bounds::closed(-5.0, 5.0),
        });
        Ok(())
    }

    /// Earth position (x, h) of the hook point (m): body offset (−aft, +below) rotated by θ.
    #[inline]
    pub fn position(&self, state: &AircraftState) -> (f64, f64) {
        let (sin_t, cos_t) = state.theta_rad.sin_cos();
        self.position_trig(state, sin_t, cos_t)
    }

    /// As [`HookGeometry::position`], with sin θ and cos θ already computed.
    #[inline]
    pub fn position_trig(&self, state: &AircraftState, sin_t: f64, cos_t: f64) -> (f64, f64) {
        (
            state.x_m - self.aft_of_cg_m * cos_t + self.below_cg_m * sin_t,
            state.h_m - self.aft_of_cg_m * sin_t - self.below_cg_m * cos_t,
        )
    }

    /// Earth velocity (ẋ, ḣ) of the hook point (m/s), including the pitch-rate term.
    #[inline]
    pub fn velocity(&self, state: &AircraftState) -> (f64, f64) {
        let (sin_t, cos_t) = state.theta_rad.sin_cos();
        self.velocity_trig(state, sin_t, cos_t)
    }

    /// As [`HookGeometry::velocity`], with sin θ and cos θ already computed.
    #[inline]
    pub fn velocity_trig(&self, state: &AircraftState, sin_t: f64, cos_t: f64) -> (f64, f64) {
        let (x_dot, h_dot) = state.earth_velocity_trig(sin_t, cos_t);
        let q = state.q_radps;
        (
            x_dot + q * (self.aft_of_cg_m * sin_t + self.below_cg_m * cos_t),
            h_dot + q * (-self.aft_of_cg_m * cos_t + self.below_cg_m * sin_t),
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn level_hook_is_aft_and_below() {
        let hook = HookGeometry::default();
        let state = AircraftState {
            x_m: 100.0,
            h_m: 50.0,
            ..Default::default()
        };
        assert_eq!(hook.position(&state), (93.0, 48.2));
    }

    #[test]
    fn nose_up_lowers_the_hook() {
        let hook = HookGeometry::default();
        let theta: f64 = 0.1;
        let state = AircraftState {
            theta_rad: theta,
            ..Default::default()
        };
        let (x, h) = hook.position(&state);
        // By hand: x = −7 cos θ + 1.8 sin θ, h = −7 sin θ − 1.8 cos θ.
        assert!((x - (-7.0 * theta.cos() + 1.8 * theta.sin())).abs() < 1e-12);
        assert!((h - (-7.0 * theta.sin() - 1.8 * theta.cos())).abs() < 1e-12);
        assert!(h < -1.8);
    }

    #[test]
    fn velocity_is_the_derivative_of_position() {
        let hook = HookGeometry::default();
        let state = AircraftState {
            u_mps: 70.0,
            w_mps: 5.0,
            q_radps: 0.2,
            theta_rad: 0.1,
            ..Default::default()
        };
        let (x_dot, h_dot) = state.earth_velocity_mps();
        let dt = 1e-6;
        let later = AircraftState {
            theta_rad: state.theta_rad + state.q_radps * dt,
            x_m: x_dot * dt,
            h_m: h_dot * dt,
            ..state
        };
        let (x0, h0) = hook.position(&state);
        let (x1, h1) = hook.position(&later);
        let (vx, vh) = hook.velocity(&state);
        assert!(((x1 - x0) / dt - vx).abs() < 1e-4);
        assert!(((h1 - h0) / dt - vh).abs() < 1e-4);
    }
}
