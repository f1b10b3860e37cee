//! Minimum-variance prediction of the ship's heave and pitch (docs/model.md §3.1 filters,
//! §3.5).
//!
//! Each shaping filter is ż = A z + B n with white noise n of intensity q. Given the state
//! now, the expected state T seconds ahead is e^{AT} z (the noise to come has zero mean),
//! so the predicted heave is 1.21·e₁ᵀe^{AT}z and the predicted pitch 0.773·e₃ᵀe^{AT}z.
//! The transitions e^{AT} are tabulated once on a fine grid of T and interpolated
//! linearly.
//!
//! Given instead an *estimate* of the state with error covariance P (a Kalman filter's,
//! `estimation::DeckMotionEstimator`), the prediction is the same map of the
//! estimate and its error variance, for an output row c, is
//! c e^{AT} P e^{AᵀT} cᵀ + q·c (P∞ − e^{AT} P∞ e^{AᵀT}) cᵀ: the estimate's own error
//! carried forward, plus the noise still to come, where P∞ is the filter's stationary
//! covariance for unit intensity (A P∞ + P∞ Aᵀ + B Bᵀ = 0 gives
//! ∫₀ᵀ e^{As}BBᵀe^{Aᵀs} ds = P∞ − e^{AT} P∞ e^{AᵀT} exactly). With P = 0 (the true
//! state known: the `oracle`) only the second term is left: the physics floor of
//! prediction, docs/model.md §3.6.

pub use super::ship::Matrix4Array;
use super::ship::{ShapingFilter, ShipMotion, ShipMotionState};
use nalgebra::Matrix4;
use std::sync::Arc;

/// Grid spacing of the tabulated transitions (s).
const GRID_S: f64 = 0.02;

/// One filter's tabulated transitions e^{AT} and unit-intensity stationary covariance.
#[derive(Debug, Clone, PartialEq)]
struct FilterTable {
    filter: ShapingFilter,
    transitions: Arc<Vec<Matrix4Array>>,
    stationary: Matrix4Array,
}

impl FilterTable {
    fn new(filter: ShapingFilter, count: usize) -> Self {
        let step = (filter.companion() * GRID_S).exp();
        let mut transition = Matrix4::identity();
        let mut transitions = Vec::with_capacity(count);
        for _ in 0..count {
            transitions.push(std::array::from_fn(|i| {
                std::array::from_fn(|j| transition[(i, j)])
            }));
            transition *= step;
        }
        Self {
            filter,
            transitions: Arc::new(transitions),
            stationary: filter
                .unit_intensity_state_covariance()
                .expect("a ShipMotion's filters are checked stable"),
        }
    }

    /// Row `row` of e^{AT}, interpolated at the grid position.
    #[inline]
    fn row(&self, (index, fraction): (usize, f64), row: usize) -> [f64; 4] {
        let (r0, r1) = (
            &self.transitions[index][row],
            &self.transitions[index + 1][row],
        );
        std::array::from_fn(|j| r0[j] + fraction * (r1[j] - r0[j]))
    }

    /// The motion e^{AT}·z predicts (row k of e^{AT}, interpolated, times z, times g).
    #[inline(always)]
    fn output(&self, (index, fraction): (usize, f64), z: &[f64; 4]) -> f64 {
        let row = self.filter.output_state;
        let (r0, r1) = (
            &self.transitions[index][row],
            &self.transitions[index + 1][row],
        );
        self.filter.gain
            * (0..4)
                .map(|j| (r0[j] + fraction * (r1[j] - r0[j])) * z[j])
                .sum::<f64>()
    }

    /// The unpredictable part of state `i`'s variance after the transition row `row`,
    /// per unit intensity.
    #[inline]
    fn unpredictable(&self, row: &[f64; 4], i: usize) -> f64 {
        (self.stationary[i][i] - quadratic_form(row, &self.stationary)).max(0.0)
    }
}

/// Tabulated transitions e^{AT} of the ship's shaping filters.
#[derive(Debug, Clone, PartialEq)]
pub struct ShipMotionPropagator {
    heave: FilterTable,
    pitch: FilterTable,
}

/// Predicted heave (m) and pitch (rad).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct PredictedShipMotion {
    /// Heave (m, up).
    pub heave_m: f64,
    /// Pitch (rad, bow up).
    pub pitch_rad: f64,
}

/// An estimate of both shaping filters' state with its error covariances (filter units).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipMotionEstimate {
    /// The estimated state.
    pub mean: ShipMotionState,
    /// Error covariance of the heave filter's state.
    pub heave_covariance: Matrix4Array,
    /// Error covariance of the pitch filter's state.
    pub pitch_covariance: Matrix4Array,
}

/// The predicted ship motion at one horizon, with the variances of its prediction error.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ShipMotionForecast {
    /// Heave (m, up).
    pub heave_m: f64,
    /// Heave rate (m/s, up).
    pub heave_rate_mps: f64,
    /// Pitch (rad, bow up).
    pub pitch_rad: f64,
    /// Pitch rate (rad/s).
    pub pitch_rate_radps: f64,
    /// Variance of the heave prediction's error (m²).
    pub heave_variance_m2: f64,
    /// Variance of the pitch prediction's error (rad²).
    pub pitch_variance_rad2: f64,
}

impl ShipMotionForecast {
    /// Predicted height change of a deck point `lever_arm_m` aft of the pitch centre
    /// (m, up): heave − r·sin θ (docs/model.md §3.1, Eq. 17–18 without the deck height).
    pub fn deck_point_height_m(&self, lever_arm_m: f64) -> f64 {
        self.deck_point_height_at_sine_m(lever_arm_m, self.pitch_rad.sin())
    }

    /// [`ShipMotionForecast::deck_point_height_m`] with sin θ given (`sin_pitch`, by
    /// whatever means the caller computes it).
    #[inline]
    pub fn deck_point_height_at_sine_m(&self, lever_arm_m: f64, sin_pitch: f64) -> f64 {
        self.heave_m - lever_arm_m * sin_pitch
    }

    /// Predicted vertical velocity of that deck point (m/s, up): ż − r·cos θ·θ̇.
    pub fn deck_point_climb_rate_mps(&self, lever_arm_m: f64) -> f64 {
        self.deck_point_climb_rate_at_cosine_mps(lever_arm_m, self.pitch_rad.cos())
    }

    /// [`ShipMotionForecast::deck_point_climb_rate_mps`] with cos θ given (`cos_pitch`).
    #[inline]
    pub fn deck_point_climb_rate_at_cosine_mps(&self, lever_arm_m: f64, cos_pitch: f64) -> f64 {
        self.heave_rate_mps - lever_arm_m * cos_pitch * self.pitch_rate_radps
    }

    /// Standard deviation of that deck point's height prediction (m), linearised in the
    /// pitch error (heave and pitch are independent): √(σ²_z + (r cos θ)² σ²_θ).
    pub fn deck_point_height_sigma_m(&self, lever_arm_m: f64) -> f64 {
        let arm = lever_arm_m * self.pitch_rad.cos();
        (self.heave_variance_m2 + arm * arm * self.pitch_variance_rad2)
            .max(0.0)
            .sqrt()
    }
}

/// The standard deviations of a deck point's predicted height and climb rate.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct DeckPointUncertainty {
    /// σ of the height prediction (m).
    pub height_sigma_m: f64,
    /// σ of the climb-rate prediction (m/s).
    pub climb_rate_sigma_mps: f64,
}

/// r·P·rᵀ for a row r and a symmetric P.
#[inline]
fn quadratic_form(row: &[f64; 4], p: &Matrix4Array) -> f64 {
    let mut sum = 0.0;
    for i in 0..4 {
        let mut inner = 0.0;
        for j in 0..4 {
            inner += p[i][j] * row[j];
        }
        sum += row[i] * inner;
    }
    sum
}

impl ShipMotionPropagator {
    /// Tabulates the transitions of `ship`'s filters for horizons from 0 to
    /// `max_horizon_s` (s); longer horizons are clamped to it.
    pub fn new(ship: &ShipMotion, max_horizon_s: f64) -> Self {
        let count = (max_horizon_s.max(0.0) / GRID_S).ceil() as usize + 2;
        let heave = FilterTable::new(*ship.heave_filter(), count);
        let pitch = if ship.pitch_filter().denominator == ship.heave_filter().denominator {
            // The paper's ship: one table serves both filters.
            FilterTable {
                filter: *ship.pitch_filter(),
                ..heave.clone()
            }
        } else {
            FilterTable::new(*ship.pitch_filter(), count)
        };
        Self { heave, pitch }
    }

    /// The longest horizon tabulated (s).
    pub fn max_horizon_s(&self) -> f64 {
        (self.heave.transitions.len() - 2) as f64 * GRID_S
    }

    /// The grid index and the fraction towards the next point of `horizon_s`.
    #[inline]
    fn grid(&self, horizon_s: f64) -> (usize, f64) {
        let position = (horizon_s.max(0.0) / GRID_S).min((self.heave.transitions.len() - 2) as f64);
        let index = position as usize;
        (index, position - index as f64)
    }

    /// [`ShipMotionPropagator::grid`] of `horizon_s`, or `None` when the ship motion of
    /// `ship` is disabled (every prediction then zero).
    #[inline(always)]
    fn grid_if_enabled(&self, ship: &ShipMotion, horizon_s: f64) -> Option<(usize, f64)> {
        ship.parameters().enabled.then(|| self.grid(horizon_s))
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
        let Some(grid) = self.grid_if_enabled(ship, horizon_s) else {
            return PredictedShipMotion::default();
        };
        PredictedShipMotion {
            heave_m: self.heave.output(grid, &state.heave_filter),
            pitch_rad: self.pitch.output(grid, &state.pitch_filter),
        }
    }

    /// As [`ShipMotionPropagator::forecast`] without the error variances (left zero): the
    /// mean alone, for the loop's every step (a third of the work).
    #[inline]
    pub fn forecast_mean(
        &self,
        ship: &ShipMotion,
        estimate: &ShipMotionEstimate,
        lead_s: f64,
    ) -> ShipMotionForecast {
        let Some(grid) = self.grid_if_enabled(ship, lead_s) else {
            return ShipMotionForecast::default();
        };
        let dot = |r: &[f64; 4], z: &[f64; 4]| (0..4).map(|j| r[j] * z[j]).sum::<f64>();
        let value = |table: &FilterTable, z: &[f64; 4], derivative: usize| {
            table.filter.gain * dot(&table.row(grid, table.filter.output_state + derivative), z)
        };
        let (zh, zp) = (&estimate.mean.heave_filter, &estimate.mean.pitch_filter);
        ShipMotionForecast {
            heave_m: value(&self.heave, zh, 0),
            heave_rate_mps: value(&self.heave, zh, 1),
            pitch_rad: value(&self.pitch, zp, 0),
            pitch_rate_radps: value(&self.pitch, zp, 1),
            ..ShipMotionForecast::default()
        }
    }

    /// The prediction `lead_s` seconds after the time of `estimate`, with its error
    /// variances (module docs); zero when the ship motion of `ship` is disabled. The
    /// values and rates are [`ShipMotionPropagator::forecast_mean`]'s.
    pub fn forecast(
        &self,
        ship: &ShipMotion,
        estimate: &ShipMotionEstimate,
        lead_s: f64,
    ) -> ShipMotionForecast {
        let mean = self.forecast_mean(ship, estimate, lead_s);
        let Some(grid) = self.grid_if_enabled(ship, lead_s) else {
            return mean;
        };
        // Each motion's error variance, from the output row of e^{AT}.
        let variance = |table: &FilterTable, covariance, intensity: f64| {
            let k = table.filter.output_state;
            let row = table.row(grid, k);
            table.filter.gain.powi(2)
                * (quadratic_form(&row, covariance) + intensity * table.unpredictable(&row, k))
        };
        ShipMotionForecast {
            heave_variance_m2: variance(
                &self.heave,
                &estimate.heave_covariance,
                ship.heave_noise_intensity(),
            ),
            pitch_variance_rad2: variance(
                &self.pitch,
                &estimate.pitch_covariance,
                ship.pitch_noise_intensity(),
            ),
            ..mean
        }
    }
}

impl ShipMotionPropagator {
    /// The standard deviations of the predicted height and climb rate of the deck point
    /// `point` = (its lever arm aft of the pitch centre (m), the ship's pitch (rad)),
    /// `lead_s` after the time of `estimate` (the module docs' error variance for the rows of
    /// heave, heave rate, pitch and pitch rate; heave and pitch independent, linearised
    /// in the pitch error as [`ShipMotionForecast::deck_point_height_sigma_m`]); zero when
    /// the ship motion is disabled.
    pub fn deck_point_uncertainty(
        &self,
        ship: &ShipMotion,
        estimate: &ShipMotionEstimate,
        lead_s: f64,
        point: (f64, f64),
    ) -> DeckPointUncertainty {
        let sigma = |derivative| self.deck_point_sigma(ship, estimate, lead_s, point, derivative);
        DeckPointUncertainty {
            height_sigma_m: sigma(0),
            climb_rate_sigma_mps: sigma(1),
        }
    }

    /// σ of the predicted height (`derivative` 0, m) or climb rate (1, m/s) of the deck
    /// point of [`ShipMotionPropagator::deck_point_uncertainty`], computing only that
    /// one (the guidance computer needs one of each per step, at different horizons).
    pub fn deck_point_sigma(
        &self,
        ship: &ShipMotion,
        estimate: &ShipMotionEstimate,
        lead_s: f64,
        (lever_arm_m, pitch_rad): (f64, f64),
        derivative: usize,
    ) -> f64 {
        let Some(grid) = self.grid_if_enabled(ship, lead_s) else {
            return 0.0;
        };
        // Row k + derivative of e^{AT}: the motion (k) or its rate (k + 1); per unit gain.
        let variance = |table: &FilterTable, covariance: &Matrix4Array, intensity: f64| {
            let i = table.filter.output_state + derivative;
            let row = table.row(grid, i);
            quadratic_form(&row, covariance) + intensity * table.unpredictable(&row, i)
        };
        let (heave, pitch) = (
            self.heave.filter.gain * self.heave.filter.gain,
            self.pitch.filter.gain * self.pitch.filter.gain,
        );
        let (qh, qp) = (ship.heave_noise_intensity(), ship.pitch_noise_intensity());
        let arm = lever_arm_m * pitch_rad.cos();
        let value = heave * variance(&self.heave, &estimate.heave_covariance, qh)
            + arm * arm * pitch * variance(&self.pitch, &estimate.pitch_covariance, qp);
        value.max(0.0).sqrt()
    }

    /// The covariance of the errors of two deck points' predicted heights (m²): `a` and
    /// `b` each (lead after the time of `estimate` (s), (lever arm aft of the pitch
    /// centre (m), the ship's pitch (rad))), linearised in the pitch error as
    /// [`ShipMotionPropagator::deck_point_sigma`]; zero when the ship motion is disabled.
    /// For one filter's output row c and leads s ≤ t the errors' covariance is
    /// c e^{As} P e^{Aᵀt} cᵀ + q·c (P∞ − e^{As} P∞ e^{Aᵀs}) e^{Aᵀ(t−s)} cᵀ: the estimate's
    /// error carried to both leads, and the noise to come before the nearer lead, which
    /// the farther one carries on through e^{A(t−s)} (the module docs' identity for the
    /// integral). With a = b it is that point's σ².
    pub fn deck_points_height_covariance(
        &self,
        ship: &ShipMotion,
        estimate: &ShipMotionEstimate,
        a: (f64, (f64, f64)),
        b: (f64, (f64, f64)),
    ) -> f64 {
        if !ship.parameters().enabled {
            return 0.0;
        }
        let ((near_s, near), (far_s, far)) = if a.0 <= b.0 { (a, b) } else { (b, a) };
        let grids = (
            self.grid(near_s),
            self.grid(far_s),
            self.grid(far_s - near_s),
        );
        let covariance = |table: &FilterTable, p: &Matrix4Array, intensity: f64| {
            let k = table.filter.output_state;
            let (row_near, row_far, row_gap) = (
                table.row(grids.0, k),
                table.row(grids.1, k),
                table.row(grids.2, k),
            );
            let form = |m: &Matrix4Array| bilinear_form(&row_near, m, &row_far);
            let carried: f64 = (0..4).map(|j| table.stationary[k][j] * row_gap[j]).sum();
            table.filter.gain.powi(2) * (form(p) + intensity * (carried - form(&table.stationary)))
        };
        let arms = near.0 * near.1.cos() * far.0 * far.1.cos();
        covariance(
            &self.heave,
            &estimate.heave_covariance,
            ship.heave_noise_intensity(),
        ) + arms
            * covariance(
                &self.pitch,
                &estimate.pitch_covariance,
                ship.pitch_noise_intensity(),
            )
    }
}

/// r·P·sᵀ for rows r, s and a matrix P.
#[inline]
fn bilinear_form(r: &[f64; 4], p: &Matrix4Array, s: &[f64; 4]) -> f64 {
    (0..4)
        .map(|i| r[i] * (0..4).map(|j| p[i][j] * s[j]).sum::<f64>())
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{
        unit_intensity_state_covariance, ShipMotionParameters, HEAVE_FILTER_GAIN, PITCH_FILTER_GAIN,
    };
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
        let predictor = ShipMotionPropagator::new(&ship, 15.0);
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

    #[test]
    fn the_mean_alone_is_the_forecasts_mean() {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let estimate = ShipMotionEstimate {
            mean: ShipMotionState {
                heave_filter: [0.5, -0.2, 0.1, 0.05],
                pitch_filter: [0.3, 0.1, -0.02, 0.04],
            },
            ..ShipMotionEstimate::default()
        };
        let predictor = ShipMotionPropagator::new(&ship, 5.0);
        for lead in [0.0, 0.37, 2.0, 9.0] {
            let full = predictor.forecast(&ship, &estimate, lead);
            let mean = predictor.forecast_mean(&ship, &estimate, lead);
            assert_eq!(
                (
                    mean.heave_m,
                    mean.heave_rate_mps,
                    mean.pitch_rad,
                    mean.pitch_rate_radps
                ),
                (
                    full.heave_m,
                    full.heave_rate_mps,
                    full.pitch_rad,
                    full.pitch_rate_radps
                )
            );
        }
    }

    /// The physics floor of docs/model.md §3.6: with the true state known (the oracle),
    /// the landing point's height T s ahead is uncertain by the noise still to come. As
    /// touchdown scatter on a 3.5° path (σ / tan 3.5°), docs/model.md quotes 5.3, 10.4, 14.5
    /// and 15.5 m at 0.5, 1, 2 and 3 s in the paper's sea (and
    /// tests/reference/deck_motion_kalman.py gives 5.34, 10.36, 14.50, 15.50 m with scipy).
    #[test]
    fn the_oracles_error_is_the_physics_floor_of_the_specification() {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let predictor = ShipMotionPropagator::new(&ship, 10.0);
        let tan = 3.5_f64.to_radians().tan();
        for (horizon, scatter_m) in [(0.5, 5.3), (1.0, 10.4), (2.0, 14.5), (3.0, 15.5)] {
            let forecast = predictor.forecast(&ship, &ShipMotionEstimate::default(), horizon);
            let scatter = forecast.deck_point_height_sigma_m(81.0) / tan;
            assert!(
                (scatter - scatter_m).abs() < 0.06,
                "{horizon} s: {scatter:.3} m against {scatter_m} m"
            );
        }
        // No horizon is worse than knowing nothing: the stationary heave variance, 4 m².
        let far = predictor.forecast(&ship, &ShipMotionEstimate::default(), 1e6);
        assert!(far.heave_variance_m2 <= 4.0 + 1e-9 && far.heave_variance_m2 > 1.0);
    }

    /// The deck point's height σ is the forecast's, the same scipy-checked physics floor
    /// above (5.3 m of touchdown scatter at 0.5 s: 5.3·tan 3.5° = 0.324 m at the landing
    /// point); its climb-rate σ is 0 with nothing to predict, grows with the horizon and
    /// never exceeds the stationary climb-rate σ, √(1.21²·q_h·P∞[1][1] +
    /// 81²·0.773²·q_p·P∞[3][3]) (knowing nothing).
    #[test]
    fn the_deck_points_uncertainty_matches_the_forecast_and_its_limits() {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let predictor = ShipMotionPropagator::new(&ship, 10.0);
        let estimate = ShipMotionEstimate::default();
        for horizon in [0.0, 0.5, 2.0, 5.0] {
            let forecast = predictor.forecast(&ship, &estimate, horizon);
            let uncertainty =
                predictor.deck_point_uncertainty(&ship, &estimate, horizon, (81.0, 0.0));
            let expected = forecast.deck_point_height_sigma_m(81.0);
            assert!(
                (uncertainty.height_sigma_m - expected).abs() < 1e-12,
                "{horizon}"
            );
        }
        let now = predictor.deck_point_uncertainty(&ship, &estimate, 0.0, (81.0, 0.0));
        assert!(now.climb_rate_sigma_mps < 1e-9, "{now:?}");
        let stationary = unit_intensity_state_covariance();
        let sigma = |horizon| {
            predictor
                .deck_point_uncertainty(&ship, &estimate, horizon, (81.0, 0.0))
                .climb_rate_sigma_mps
        };
        assert!(sigma(0.5) > 0.0 && sigma(0.5) < sigma(2.0) && sigma(2.0) < sigma(10.0));
        let expected = (HEAVE_FILTER_GAIN.powi(2)
            * ship.heave_noise_intensity()
            * stationary[1][1]
            + (81.0 * PITCH_FILTER_GAIN).powi(2) * ship.pitch_noise_intensity() * stationary[3][3])
            .sqrt();
        assert!(
            sigma(10.0) <= expected,
            "{} against {expected}",
            sigma(10.0)
        );
    }

    /// The covariance of two deck points' errors against a separate computation: the
    /// estimate's error carried by nalgebra's matrix exponential (not the tables), and the
    /// noise term as the integral q·∫₀ˢ [e^{A(s−u)}B]_k [e^{A(t−u)}B]_k du by Simpson's
    /// rule on 400 intervals (not the P∞ identity). Also: at one point and lead it is
    /// that point's σ², and it is symmetric in its two points.
    #[test]
    fn the_deck_points_covariance_matches_a_direct_integral() {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let predictor = ShipMotionPropagator::new(&ship, 12.0);
        let p0: Matrix4Array = std::array::from_fn(|i| {
            std::array::from_fn(|j| if i == j { 0.02 * (i + 1) as f64 } else { 0.003 })
        });
        let estimate = ShipMotionEstimate {
            heave_covariance: p0,
            pitch_covariance: p0,
            ..ShipMotionEstimate::default()
        };
        let direct = |filter: &ShapingFilter, q: f64, s: f64, t: f64| {
            let a = filter.companion();
            let k = filter.output_state;
            let p = Matrix4::from_fn(|i, j| p0[i][j]);
            let carried = (a * s).exp() * p * (a * t).exp().transpose();
            let response = |lag: f64| (a * lag).exp()[(k, 3)];
            let n = 400;
            let h = s / n as f64;
            let noise: f64 = (0..=n)
                .map(|i| {
                    let u = i as f64 * h;
                    let weight = if i == 0 || i == n {
                        1.0
                    } else if i % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    weight * response(s - u) * response(t - u)
                })
                .sum::<f64>()
                * h
                / 3.0;
            filter.gain.powi(2) * (carried[(k, k)] + q * noise)
        };
        let (ramp, landing): ((f64, f64), (f64, f64)) = ((141.0, 0.02), (81.0, -0.01));
        for (s, t) in [(0.4, 0.4), (1.0, 2.0), (2.5, 3.3), (5.0, 5.9)] {
            let heave = direct(ship.heave_filter(), ship.heave_noise_intensity(), s, t);
            let pitch = direct(ship.pitch_filter(), ship.pitch_noise_intensity(), s, t);
            let expected = heave + ramp.0 * ramp.1.cos() * landing.0 * landing.1.cos() * pitch;
            let covariance =
                predictor.deck_points_height_covariance(&ship, &estimate, (s, ramp), (t, landing));
            // The tables interpolate e^{AT} linearly on a 0.02-s grid.
            assert!(
                (covariance - expected).abs() < 1e-3 * expected.abs() + 1e-6,
                "({s}, {t}): {covariance} against {expected}"
            );
            let swapped =
                predictor.deck_points_height_covariance(&ship, &estimate, (t, landing), (s, ramp));
            assert_eq!(covariance, swapped);
        }
        for lead in [0.3, 1.7, 4.0] {
            let variance = predictor.deck_points_height_covariance(
                &ship,
                &estimate,
                (lead, ramp),
                (lead, ramp),
            );
            let sigma = predictor.deck_point_sigma(&ship, &estimate, lead, ramp, 0);
            assert!(
                (variance - sigma * sigma).abs() < 1e-12 * variance,
                "{lead}"
            );
        }
    }
}
