//! Deck-motion estimation: a Kalman filter on the ship-motion model (paper Eq. 15–16;
//! docs/model.md §3.5).
//!
//! The ship's heave and pitch are the outputs of two independent shaping filters, each
//! ż = A z + B n in controllable canonical form with white noise n of intensity q
//! ([`crate::environment::ShipMotion`]). The ship's inertial navigation measures each
//! motion g·z_k and its rate g·z_{k+1} ([`crate::environment::ShapingFilter`]; the paper's
//! heave 1.21·z₁ and 1.21·z₂, pitch 0.773·z₃ and 0.773·z₄), with white noise, at its
//! sample rate; the samples
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
//! By default the filter starts as it stands after tracking the ship since long before
//! the run ([`DeckMotionEstimator::converged`]): its covariance the steady-state prior of
//! the discrete Riccati equation (solved by doubling), its error drawn from that
//! covariance given the ship's true state. A `cold` start knows nothing but the model:
//! ẑ = 0, P = q P∞ (the stationary distribution the ship starts from). Its estimate stands for the time of the last
//! measurement received, so a prediction T seconds ahead of *now* is a prediction
//! (now − that time) + T ahead of the estimate: the data link's latency adds to the
//! horizon ([`crate::environment::ShipMotionPropagator::forecast`] gives the mean and the
//! error variance).

use nalgebra::{Cholesky, Matrix2, Matrix2x4, Matrix4, Vector2, Vector4};

use crate::environment::{
    Matrix4Array, ShapingFilter, ShipMotion, ShipMotionEstimate, ShipMotionState,
};
use crate::random::NoiseStream;
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
    /// The filter's companion matrix A and unit-intensity stationary covariance P∞.
    companion: Matrix4<f64>,
    stationary: Matrix4<f64>,
    /// The transitions of the intervals met so far (on a fixed grid there are one or two).
    transitions: Vec<Transition>,
}

impl Channel {
    /// A channel of `filter` observing its motion and rate (states k and k + 1 times
    /// the gain), with noise σ.
    fn new(filter: &ShapingFilter, intensity: f64, sigmas: [f64; 2]) -> Self {
        let p = filter
            .unit_intensity_state_covariance()
            .expect("a ShipMotion's filters are checked stable");
        let stationary = Matrix4::from_fn(|i, j| p[i][j]);
        let first = filter.output_state;
        let mut observation = Matrix2x4::zeros();
        observation[(0, first)] = filter.gain;
        observation[(1, first + 1)] = filter.gain;
        Self {
            mean: Vector4::zeros(),
            covariance: stationary * intensity,
            intensity,
            observation,
            measurement_covariance: Matrix2::new(sigmas[0].powi(2), 0.0, 0.0, sigmas[1].powi(2)),
            companion: filter.companion(),
            stationary,
            transitions: Vec::with_capacity(2),
        }
    }

    /// Propagates over `interval_s` (> 0) with its (cached) transition.
    fn propagate_over(&mut self, interval_s: f64) {
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

    /// The steady-state prior covariance of this channel measured every `step`: the
    /// solution P of the filter's discrete Riccati equation
    /// P = Φ P Φᵀ − Φ P Hᵀ (H P Hᵀ + R)⁻¹ H P Φᵀ + Q_d, by the structure-preserving
    /// doubling algorithm (Chu, Fan & Lin, Linear Algebra Appl. 396, 2005) on its dual
    /// control form A = Φᵀ, G = Hᵀ R⁻¹ H, H₀ = Q_d: each iteration doubles the horizon,
    /// where the plain recursion needs about 50 000 steps for the pitch filter's slow
    /// state. `None` if a matrix to invert is singular.
    fn steady_state_prior(&self, step: &Transition) -> Option<Matrix4<f64>> {
        let r_inverse = self.measurement_covariance.try_inverse()?;
        let mut a = step.transition.transpose();
        let mut g = self.observation.transpose() * r_inverse * self.observation;
        let mut x = step.unit_noise * self.intensity;
        for _ in 0..STEADY_STATE_MAX_DOUBLINGS {
            let w = (Matrix4::identity() + g * x).try_inverse()?;
            let next_x = x + a.transpose() * x * w * a;
            let next_g = g + a * w * g * a.transpose();
            a = a * w * a;
            let change = (next_x - x).abs().max();
            x = (next_x + next_x.transpose()) * 0.5;
            g = (next_g + next_g.transpose()) * 0.5;
            if change <= STEADY_STATE_TOLERANCE * x.abs().max() {
                return Some(x);
            }
        }
        Some(x)
    }

    /// Starts the channel at the steady-state prior `prior`, its mean the true state
    /// `truth` less an error drawn from the error's distribution given the truth:
    /// e | z ~ N(P P∞⁻¹ z, P − P P∞⁻¹ P), with P∞ = q·`stationary` (the truth and the
    /// estimate of a converged filter are jointly Gaussian, e ⊥ ẑ, so cov(z, e) = P).
    /// Draws four numbers from `stream`; keeps the cold start if P∞ is singular (no
    /// motion).
    fn start_converged(&mut self, prior: Matrix4<f64>, truth: &[f64; 4], stream: &mut NoiseStream) {
        let draws = Vector4::from_fn(|_, _| stream.standard_normal());
        let Some(stationary_inverse) = (self.stationary * self.intensity).try_inverse() else {
            return;
        };
        let z = Vector4::from_column_slice(truth);
        let gain = prior * stationary_inverse;
        let conditional = prior - gain * prior;
        let conditional = (conditional + conditional.transpose()) * 0.5;
        // Positive semi-definite up to rounding: add the least jitter that factors it.
        let scale = conditional.diagonal().abs().max().max(f64::MIN_POSITIVE);
        let factor = std::iter::once(0.0)
            .chain((0..10).map(|k| 1e-14 * scale * 10_f64.powi(k)))
            .find_map(|jitter| {
                Cholesky::new(conditional + Matrix4::identity() * jitter).map(|c| c.l())
            });
        let Some(factor) = factor else {
            return;
        };
        let error = gain * z + factor * draws;
        self.mean = z - error;
        self.covariance = prior;
    }
}

/// Most doublings of [`Channel::steady_state_prior`]: 2⁶⁰ steps, never reached.
const STEADY_STATE_MAX_DOUBLINGS: usize = 60;
/// Relative change of the doubling's iterate below which it has converged.
const STEADY_STATE_TOLERANCE: f64 = 1e-13;

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
    updates: u64,
}

impl DeckMotionEstimator {
    /// A filter for the ship model `ship` measured by a sensor with `sensing`, knowing
    /// nothing at t = 0 but the stationary distribution.
    pub fn new(ship: &ShipMotion, sensing: &ShipMotionSensingParameters) -> Self {
        let [heave_sigma, heave_rate_sigma, pitch_sigma, pitch_rate_sigma] = sensing.sigmas_si();
        let (heave_intensity, pitch_intensity) = if ship.parameters().enabled {
            (ship.heave_noise_intensity(), ship.pitch_noise_intensity())
        } else {
            (0.0, 0.0)
        };
        Self {
            heave: Channel::new(
                ship.heave_filter(),
                heave_intensity,
                [heave_sigma, heave_rate_sigma],
            ),
            pitch: Channel::new(
                ship.pitch_filter(),
                pitch_intensity,
                [pitch_sigma, pitch_rate_sigma],
            ),
            time_s: 0.0,
            updates: 0,
        }
    }

    /// The filter as it stands at t = 0 after tracking the ship, sampled at the sensing's
    /// rate, since long before (docs/model.md §3.5): each channel at its steady-state
    /// prior covariance, its estimate the true state `truth` less an error drawn from
    /// that covariance given the truth (four numbers per moving channel from `stream`).
    /// The aircraft's guidance computer receives the ship's motion over the data link
    /// during the whole approach, not only from the scenario's start 1500 m out. A
    /// channel with no motion starts cold.
    pub fn converged(
        ship: &ShipMotion,
        sensing: &ShipMotionSensingParameters,
        truth: &ShipMotionState,
        stream: &mut NoiseStream,
    ) -> Self {
        let mut filter = Self::new(ship, sensing);
        for (channel, state) in [
            (&mut filter.heave, &truth.heave_filter),
            (&mut filter.pitch, &truth.pitch_filter),
        ] {
            if channel.intensity <= 0.0 {
                continue; // no motion: nothing to have tracked
            }
            let step = Transition::new(
                1.0 / sensing.sample_rate_hz,
                &channel.companion,
                &channel.stationary,
            );
            if let Some(prior) = channel.steady_state_prior(&step) {
                channel.start_converged(prior, state, stream);
            }
        }
        filter
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
            self.heave.propagate_over(interval_s);
            self.pitch.propagate_over(interval_s);
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
mod tests;
