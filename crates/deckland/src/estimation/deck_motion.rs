//! Deck-motion estimation: a Kalman filter on the ship-motion model (paper Eq. 15–16;
//! docs/model.md §3.5).
//!
//! The ship's heave and pitch are the outputs of two independent shaping filters, each
//! ż = A z + B n in controllable canonical form with white noise n of intensity q
//! ([`crate::environment::ShipMotion`]). The ship's inertial navigation measures heave
//! 1.21·z₁ and heave rate 1.21·z₂ of the heave filter, pitch 0.773·z₃ and pitch rate
//! 0.773·z₄ of the pitch filter, with white noise, at its sample rate; the samples
//! arrive a latency later ([`crate::sensors::ShipMotionSensor`]). So each filter has its
//! own Kalman filter with two measurements (Gelb, *Applied Optimal Estimation*, §4.2,
//! Table 4.2-1, the discrete filter):
//!
//! - propagation from the last measurement time over Δ: ẑ ← Φ ẑ, P ← Φ P Φᵀ + Q_d, with
//!   Φ = e^{AΔ} and Q_d = q (P∞ − Φ P∞ Φᵀ), the exact integral of the noise over Δ
//!   (P∞: the filter's stationary covariance for unit intensity);
//! - update with y = H z + v, R = diag(σ²): K = P Hᵀ (H P Hᵀ + R)⁻¹, ẑ ← ẑ + K (y − H ẑ),
//!   P ← (I − K H) P (I − K H)ᵀ + K R Kᵀ (Joseph form, symmetric and positive by
//!   construction).
//!
//! The filter starts knowing nothing but the model: ẑ = 0, P = q P∞ (the stationary
//! distribution the ship starts from). Its estimate stands for the time of the last
//! measurement received, so a prediction T seconds ahead of *now* is a prediction
//! (now − that time) + T ahead of the estimate: the data link's latency adds to the
//! horizon ([`crate::environment::ShipMotionPredictor::forecast`] gives the mean and the
//! error variance).

use nalgebra::{Matrix2, Matrix2x4, Matrix4, Vector2, Vector4};

use crate::environment::{
    shaping_filter_companion, unit_intensity_state_covariance, Matrix4Array, ShipMotion,
    ShipMotionEstimate, ShipMotionState, HEAVE_FILTER_GAIN, PITCH_FILTER_GAIN,
};
use crate::sensors::{ShipMotionMeasurement, ShipMotionSensingParameters};

fn to_array(m: &Matrix4<f64>) -> Matrix4Array {
    std::array::from_fn(|i| std::array::from_fn(|j| m[(i, j)]))
}

/// The Kalman filter of one shaping filter.
#[derive(Debug, Clone, PartialEq)]
struct Channel {
    mean: Vector4<f64>,
    covariance: Matrix4<f64>,
    intensity: f64,
    observation: Matrix2x4<f64>,
    measurement_covariance: Matrix2<f64>,
}

impl Channel {
    /// A channel observing z[first] and z[first + 1] times `gain`, with noise σ.
    fn new(
        intensity: f64,
        stationary: &Matrix4<f64>,
        first: usize,
        gain: f64,
        sigmas: [f64; 2],
    ) -> Self {
        let mut observation = Matrix2x4::zeros();
        observation[(0, first)] = gain;
        observation[(1, first + 1)] = gain;
        Self {
            mean: Vector4::zeros(),
            covariance: stationary * intensity,
            intensity,
            observation,
            measurement_covariance: Matrix2::new(sigmas[0].powi(2), 0.0, 0.0, sigmas[1].powi(2)),
        }
    }

    fn propagate(&mut self, step: &Transition) {
        self.mean = step.transition * self.mean;
        self.covariance = step.transition * self.covariance * step.transition.transpose()
            + step.unit_noise * self.intensity;
    }

    fn update(&mut self, measured: Vector2<f64>) {
        let h = &self.observation;
        let innovation_covariance =
            h * self.covariance * h.transpose() + self.measurement_covariance;
        let Some(inverse) = innovation_covariance.try_inverse() else {
            return;
        };
        let gain = self.covariance * h.transpose() * inverse;
        self.mean += gain * (measured - h * self.mean);
        let factor = Matrix4::identity() - gain * h;
        let covariance = factor * self.covariance * factor.transpose()
            + gain * self.measurement_covariance * gain.transpose();
        self.covariance = (covariance + covariance.transpose()) * 0.5;
    }
}

/// e^{AΔ} and the unit-intensity process noise P∞ − e^{AΔ} P∞ e^{AᵀΔ} over one interval.
#[derive(Debug, Clone, PartialEq)]
struct Transition {
    interval_s: f64,
    transition: Matrix4<f64>,
    unit_noise: Matrix4<f64>,
}

impl Transition {
    fn new(interval_s: f64, a: &Matrix4<f64>, stationary: &Matrix4<f64>) -> Self {
        let transition = (a * interval_s).exp();
        let unit_noise = stationary - transition * stationary * transition.transpose();
        Self {
            interval_s,
            transition,
            unit_noise: (unit_noise + unit_noise.transpose()) * 0.5,
        }
    }
}

/// The Kalman filter of the ship's motion: both shaping filters' state estimated from the
/// ship's measurements (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct DeckMotionEstimator {
    heave: Channel,
    pitch: Channel,
    /// The time the estimate stands for: the last measurement's (s).
    time_s: f64,
    companion: Matrix4<f64>,
    stationary: Matrix4<f64>,
    /// The transitions of the intervals met so far (on a fixed grid there are one or two).
    transitions: Vec<Transition>,
    updates: u64,
}

impl DeckMotionEstimator {
    /// A filter for the ship model `ship` measured by a sensor with `sensing`, knowing
    /// nothing at t = 0 but the stationary distribution.
    pub fn new(ship: &ShipMotion, sensing: &ShipMotionSensingParameters) -> Self {
        let p = unit_intensity_state_covariance();
        let stationary = Matrix4::from_fn(|i, j| p[i][j]);
        let [heave_sigma, heave_rate_sigma, pitch_sigma, pitch_rate_sigma] = sensing.sigmas_si();
        let (heave_intensity, pitch_intensity) = if ship.parameters().enabled {
            (ship.heave_noise_intensity(), ship.pitch_noise_intensity())
        } else {
            (0.0, 0.0)
        };
        Self {
            heave: Channel::new(
                heave_intensity,
                &stationary,
                0,
                HEAVE_FILTER_GAIN,
                [heave_sigma, heave_rate_sigma],
            ),
            pitch: Channel::new(
                pitch_intensity,
                &stationary,
                2,
                PITCH_FILTER_GAIN,
                [pitch_sigma, pitch_rate_sigma],
            ),
            time_s: 0.0,
            companion: shaping_filter_companion(),
            stationary,
            transitions: Vec::with_capacity(4),
            updates: 0,
        }
    }

    /// The time the estimate stands for (s): that of the last measurement, 0 before any.
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// The number of measurements taken in.
    pub fn updates(&self) -> u64 {
        self.updates
    }

    /// Takes in one measurement (taken at `measurement.time_s`, not before the last one).
    pub fn update(&mut self, measurement: &ShipMotionMeasurement) {
        let interval_s = (measurement.time_s - self.time_s).max(0.0);
        if interval_s > 0.0 {
            let index = match self
                .transitions
                .iter()
                .position(|t| (t.interval_s - interval_s).abs() <= 1e-12)
            {
                Some(index) => index,
                None => {
                    self.transitions.push(Transition::new(
                        interval_s,
                        &self.companion,
                        &self.stationary,
                    ));
                    self.transitions.len() - 1
                }
            };
            let step = &self.transitions[index];
            self.heave.propagate(step);
            self.pitch.propagate(step);
        }
        self.heave.update(Vector2::new(
            measurement.heave_m,
            measurement.heave_rate_mps,
        ));
        self.pitch.update(Vector2::new(
            measurement.pitch_rad,
            measurement.pitch_rate_radps,
        ));
        self.time_s = measurement.time_s;
        self.updates += 1;
    }

    /// The estimate with its error covariances, at [`DeckMotionEstimator::time_s`].
    pub fn estimate(&self) -> ShipMotionEstimate {
        let state = |v: &Vector4<f64>| [v[0], v[1], v[2], v[3]];
        ShipMotionEstimate {
            mean: ShipMotionState {
                heave_filter: state(&self.heave.mean),
                pitch_filter: state(&self.pitch.mean),
            },
            heave_covariance: to_array(&self.heave.covariance),
            pitch_covariance: to_array(&self.pitch.covariance),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::environment::{ShipMotionParameters, ShipMotionPredictor, ShipMotionSimulator};
    use crate::random::RandomStreams;
    use crate::sensors::ShipMotionSensor;

    /// Steady-state a-posteriori covariances of the two channels at 50 Hz with the
    /// default sensing, in the paper's sea (heave 2 m, pitch 1.5° RMS), diagonal only, in
    /// filter units. Computed independently with `scipy.linalg.solve_discrete_are` on
    /// the same model (`tests/reference/deck_motion_kalman.py`, which prints them).
    const HEAVE_POSTERIOR_DIAGONAL: [f64; 4] =
        [3.3473845e-05, 1.7568108e-04, 2.3447115e-03, 1.8105740e-02];
    const PITCH_POSTERIOR_DIAGONAL: [f64; 4] =
        [1.2119720e-03, 3.3924175e-07, 1.3916212e-08, 2.0238543e-07];

    fn converged() -> DeckMotionEstimator {
        let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
        let mut estimator =
            DeckMotionEstimator::new(&ship, &ShipMotionSensingParameters::default());
        // 1000 s of measurements with arbitrary values (the covariance does not depend on
        // them): the pitch filter's z₁, the double integral of pitch, is observed only
        // through the dynamics and its variance settles slowly (within 1e-4 after about
        // 50 000 updates; the plain Riccati recursion in numpy does the same).
        for k in 1..=50_000 {
            estimator.update(&ShipMotionMeasurement {
                time_s: f64::from(k) * 0.02,
                ..ShipMotionMeasurement::default()
            });
        }
        estimator
    }

    #[test]
    fn steady_state_covariance_matches_an_independent_riccati_solution() {
        let estimate = converged().estimate();
        for (name, covariance, reference) in [
            ("heave", estimate.heave_covariance, HEAVE_POSTERIOR_DIAGONAL),
            ("pitch", estimate.pitch_covariance, PITCH_POSTERIOR_DIAGONAL),
        ] {
            for i in 0..4 {
                let relative = covariance[i][i] / reference[i] - 1.0;
                assert!(
                    relative.abs() < 1e-4,
                    "{name} P[{i}][{i}] = {:e}, Riccati {:e}",
                    covariance[i][i],
                    reference[i]
                );
            }
        }
    }

    /// The filter's claimed error covariance must be its actual error: fly the ship for a
    /// long time, measure it with the sensor, and compare the empirical mean square of
    /// (estimate − truth) with the filter's own P, at the measurement times.
    #[test]
    fn actual_estimation_error_matches_the_filters_covariance() {
        let parameters = ShipMotionParameters::default();
        let sensing = ShipMotionSensingParameters {
            latency_s: 0.0,
            ..ShipMotionSensingParameters::default()
        };
        let streams = RandomStreams::new(5);
        let mut ship = ShipMotionSimulator::new(parameters, &streams, 0.0).unwrap();
        let mut sensor = ShipMotionSensor::new(sensing, &streams).unwrap();
        let mut estimator = DeckMotionEstimator::new(ship.model(), &sensing);
        let predictor = ShipMotionPredictor::new(5.0);
        let dt = 0.002;
        // Errors of the heave (m) and pitch (rad) estimates, and of their 2-s predictions.
        let (mut heave, mut pitch, mut claimed_heave, mut claimed_pitch, mut n) =
            (0.0, 0.0, 0.0, 0.0, 0.0);
        let mut predictions = std::collections::VecDeque::new();
        let (mut predicted_error, mut predicted_claim, mut m) = (0.0, 0.0, 0.0);
        for k in 0..1_000_000_u32 {
            let t = f64::from(k) * dt;
            let truth = ship.outputs();
            while let Some((due, heave_predicted, claim)) = predictions.front().copied() {
                if due > t + 1e-9 {
                    break;
                }
                predictions.pop_front();
                let error: f64 = heave_predicted - truth.heave_m;
                predicted_error += error * error;
                predicted_claim += claim;
                m += 1.0;
            }
            sensor.sample(t, &truth);
            while let Some(measurement) = sensor.receive(t) {
                estimator.update(&measurement);
                if t > 100.0 {
                    let estimate = estimator.estimate();
                    let now = predictor.forecast(ship.model(), &estimate, 0.0);
                    heave += (now.heave_m - truth.heave_m).powi(2);
                    pitch += (now.pitch_rad - truth.pitch_rad).powi(2);
                    claimed_heave += now.heave_variance_m2;
                    claimed_pitch += now.pitch_variance_rad2;
                    n += 1.0;
                    if k % 100 == 0 {
                        let ahead = predictor.forecast(ship.model(), &estimate, 2.0);
                        predictions.push_back((t + 2.0, ahead.heave_m, ahead.heave_variance_m2));
                    }
                }
            }
            ship.step(dt);
        }
        // About 95 000 strongly correlated samples (the heave error's correlation time is
        // a few samples); the variance ratios are known to a few per cent.
        for (name, actual, claimed) in [
            ("heave", heave / n, claimed_heave / n),
            ("pitch", pitch / n, claimed_pitch / n),
            (
                "2-s heave prediction",
                predicted_error / m,
                predicted_claim / m,
            ),
        ] {
            assert!(
                (actual / claimed - 1.0).abs() < 0.1,
                "{name}: actual mean square {actual:e}, filter's variance {claimed:e}"
            );
        }
    }
}
