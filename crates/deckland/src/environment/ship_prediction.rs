//! Minimum-variance prediction of the ship's heave and pitch (docs/model.md §3.1 filters).
//!
//! Each shaping filter is ż = A z + B n with white noise n. Given the state now, the
//! expected state T seconds ahead is e^{AT} z (the noise to come has zero mean), so the
//! predicted heave is 1.21·e₁ᵀe^{AT}z and the predicted pitch 0.773·e₃ᵀe^{AT}z. The rows
//! e₁ᵀe^{AT} and e₃ᵀe^{AT} are tabulated once on a fine grid of T and interpolated
//! linearly. The prediction is the best possible given the filter state; a real deck
//! motion estimator would have to estimate that state from measurements, so this is the
//! idealised (upper-bound) predictor.

use super::ship::{
    ShipMotion, ShipMotionState, HEAVE_FILTER_GAIN, PITCH_FILTER_GAIN, SHAPING_FILTER_DENOMINATOR,
};
use nalgebra::Matrix4;

/// Grid spacing of the tabulated rows (s).
const GRID_S: f64 = 0.02;

/// Tabulated prediction rows of the ship's shaping filters.
#[derive(Debug, Clone, PartialEq)]
pub struct ShipMotionPredictor {
    heave_rows: Vec<[f64; 4]>,
    pitch_rows: Vec<[f64; 4]>,
}

/// Predicted heave (m) and pitch (rad).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PredictedShipMotion {
    /// Heave (m, up).
    pub heave_m: f64,
    /// Pitch (rad, bow up).
    pub pitch_rad: f64,
}

impl ShipMotionPredictor {
    /// Tabulates the rows for horizons from 0 to `max_horizon_s` (s); longer horizons are
    /// clamped to it.
    pub fn new(max_horizon_s: f64) -> Self {
        let [d0, d1, d2, d3] = SHAPING_FILTER_DENOMINATOR;
        #[rustfmt::skip]
        let a = Matrix4::new(
            0.0, 1.0, 0.0, 0.0,
            0.0, 0.0, 1.0, 0.0,
            0.0, 0.0, 0.0, 1.0,
            -d0, -d1, -d2, -d3,
        );
        let step = (a * GRID_S).exp();
        let count = (max_horizon_s.max(0.0) / GRID_S).ceil() as usize + 2;
        let mut transition = Matrix4::identity();
        let mut heave_rows = Vec::with_capacity(count);
        let mut pitch_rows = Vec::with_capacity(count);
        for _ in 0..count {
            heave_rows.push(std::array::from_fn(|j| transition[(0, j)]));
            pitch_rows.push(std::array::from_fn(|j| transition[(2, j)]));
            transition *= step;
        }
        Self {
            heave_rows,
            pitch_rows,
        }
    }

    /// The expected heave and pitch `horizon_s` seconds after `state` (zero when the ship
    /// motion of `ship` is disabled).
    #[inline]
    pub fn predict(
        &self,
        ship: &ShipMotion,
        state: &ShipMotionState,
        horizon_s: f64,
    ) -> PredictedShipMotion {
        if !ship.parameters().enabled {
            return PredictedShipMotion::default();
        }
        let position = (horizon_s.max(0.0) / GRID_S).min((self.heave_rows.len() - 2) as f64);
        let index = position as usize;
        let fraction = position - index as f64;
        let row = |rows: &[[f64; 4]], z: &[f64; 4]| {
            let (r0, r1) = (&rows[index], &rows[index + 1]);
            (0..4)
                .map(|j| (r0[j] + fraction * (r1[j] - r0[j])) * z[j])
                .sum::<f64>()
        };
        PredictedShipMotion {
            heave_m: HEAVE_FILTER_GAIN * row(&self.heave_rows, &state.heave_filter),
            pitch_rad: PITCH_FILTER_GAIN * row(&self.pitch_rows, &state.pitch_filter),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::ShipMotionParameters;
    use crate::integration::{rk4_step, OdeSystem};

    struct Free(ShipMotion);
    impl OdeSystem<8> for Free {
        fn derivative(&self, _t: f64, x: &[f64; 8]) -> [f64; 8] {
            self.0
                .derivative(&ShipMotionState::from_array(x), Default::default())
                .to_array()
        }
    }

    /// Without noise the filters evolve deterministically, so the prediction must match a
    /// separate RK4 integration of the free response.
    #[test]
    fn prediction_matches_the_noise_free_response() {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let state = ShipMotionState {
            heave_filter: [0.5, -0.2, 0.1, 0.05],
            pitch_filter: [0.3, 0.1, -0.02, 0.04],
        };
        let predictor = ShipMotionPredictor::new(15.0);
        let system = Free(ship.clone());
        let mut x = state.to_array();
        let dt = 0.001;
        for k in 1..=12_000 {
            x = rk4_step(&system, 0.0, &x, dt);
            if k % 3000 == 0 {
                let horizon = k as f64 * dt;
                let outputs = ship.outputs(&ShipMotionState::from_array(&x));
                let predicted = predictor.predict(&ship, &state, horizon);
                assert!(
                    (predicted.heave_m - outputs.heave_m).abs() < 1e-5,
                    "{horizon}"
                );
                assert!(
                    (predicted.pitch_rad - outputs.pitch_rad).abs() < 1e-6,
                    "{horizon}"
                );
            }
        }
        let now = predictor.predict(&ship, &state, 0.0);
        assert!((now.heave_m - ship.outputs(&state).heave_m).abs() < 1e-15);
    }
}
