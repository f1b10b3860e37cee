//! Free-air turbulence (paper Eq. 19–20; docs/model.md §3.2).
//!
//! Φ(Ω) = a/(1 + (100Ω)²), Ω in rad/ft, is a first-order Dryden spectrum of scale
//! L = 100 ft = 30.48 m with σ² = a·π/(2L): σ_u = 0.540 m/s, σ_w = 0.323 m/s. Seen by an
//! aircraft flying at airspeed V through the frozen field, each component is a
//! Gauss–Markov process with time constant τ = L/V, advanced exactly per step:
//! x ← e^(−dt/τ)·x + σ·√(1 − e^(−2dt/τ))·n, n ~ N(0, 1), which keeps the variance σ² and
//! the autocorrelation e^(−|lag|/τ) for any dt. u1 is positive forward, w1 positive down.

use super::wind::{Wind, WindParameters};
use crate::random::{stream_names, NoiseStream, RandomStreams, Reseed};

/// The turbulence state (u1, w1) and its two random streams.
#[derive(Debug, Clone)]
pub struct Turbulence {
    enabled: bool,
    sigma_u_mps: f64,
    sigma_w_mps: f64,
    scale_m: f64,
    u_mps: f64,
    w_mps: f64,
    u_stream: NoiseStream,
    w_stream: NoiseStream,
}

impl Turbulence {
    /// Turbulence started from its stationary distribution, u1 = σ_u·n, w1 = σ_w·n, with
    /// the `turbulence_u` and `turbulence_w` streams; zero with nothing drawn when off.
    pub fn new(parameters: &WindParameters, streams: &RandomStreams) -> Self {
        let mut turbulence = Self {
            enabled: parameters.turbulence,
            sigma_u_mps: parameters.turbulence_sigma_u_mps,
            sigma_w_mps: parameters.turbulence_sigma_w_mps,
            scale_m: parameters.turbulence_scale_m,
            u_mps: 0.0,
            w_mps: 0.0,
            u_stream: streams.stream(stream_names::TURBULENCE_U),
            w_stream: streams.stream(stream_names::TURBULENCE_W),
        };
        if turbulence.enabled {
            turbulence.u_mps = turbulence.sigma_u_mps * turbulence.u_stream.standard_normal();
            turbulence.w_mps = turbulence.sigma_w_mps * turbulence.w_stream.standard_normal();
        }
        turbulence
    }

    /// Advances both components by `dt` (s) at airspeed `airspeed_mps` (m/s), τ = L/|V|;
    /// one sample from each stream. At zero airspeed the field is frozen (τ = ∞).
    pub fn advance(&mut self, dt: f64, airspeed_mps: f64) {
        if !self.enabled {
            return;
        }
        // dt/τ = dt·V/L, written without dividing by V.
        let decay = (-dt * airspeed_mps.abs() / self.scale_m).exp();
        let spread = (1.0 - decay * decay).max(0.0).sqrt();
        self.u_mps =
            decay * self.u_mps + self.sigma_u_mps * spread * self.u_stream.standard_normal();
        self.w_mps =
            decay * self.w_mps + self.sigma_w_mps * spread * self.w_stream.standard_normal();
    }

    /// The current turbulence (u1, w1) as a wind: x positive forward, z positive down.
    pub fn wind(&self) -> Wind {
        Wind::longitudinal(self.u_mps, self.w_mps)
    }
}

impl Reseed for Turbulence {
    fn reseed(&mut self, key: u64) {
        self.u_stream.reseed(key);
        self.w_stream.reseed(key);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Sample variance and lag-k autocorrelation coefficient of a zero-mean record.
    fn variance_and_autocorrelation(samples: &[f64], lag: usize) -> (f64, f64) {
        let n = samples.len();
        let variance = samples.iter().map(|x| x * x).sum::<f64>() / n as f64;
        let covariance = samples
            .iter()
            .zip(&samples[lag..])
            .map(|(a, b)| a * b)
            .sum::<f64>()
            / (n - lag) as f64;
        (variance, covariance / variance)
    }

    #[test]
    fn turbulence_has_specified_sigma_and_exponential_autocorrelation() {
        let parameters = WindParameters::default();
        let mut turbulence = Turbulence::new(&parameters, &RandomStreams::new(5));
        let airspeed_mps = 69.1; // Trim airspeed, paper Table 3.
        let tau_s = parameters.turbulence_scale_m / airspeed_mps; // 0.441 s
        let dt = 0.01;
        let lag = (tau_s / dt).round() as usize;
        let lag_s = lag as f64 * dt;
        let steps = 1_000_000; // 10 000 s ≈ 22 700 τ
        let (mut u, mut w) = (Vec::with_capacity(steps), Vec::with_capacity(steps));
        for _ in 0..steps {
            turbulence.advance(dt, airspeed_mps);
            let wind = turbulence.wind();
            u.push(wind.x_mps);
            w.push(wind.z_mps);
        }
        // Sampling error for a record of length T = 10 000 s with τ = 0.441 s: the sample
        // variance of a Gauss–Markov process has relative standard error √(2τ/T) = 0.0094,
        // so the RMS has 0.47 %; Bartlett's formula gives the lag-τ autocorrelation a
        // standard error √((τ/T)(1 − 3e⁻²)) = 0.005. Tolerances: 4 and 5 standard errors.
        let expected_correlation = (-lag_s / tau_s).exp(); // ≈ e⁻¹
        for (record, sigma, name) in [
            (&u, parameters.turbulence_sigma_u_mps, "u"),
            (&w, parameters.turbulence_sigma_w_mps, "w"),
        ] {
            let (variance, correlation) = variance_and_autocorrelation(record, lag);
            let rms = variance.sqrt();
            assert!(
                (rms / sigma - 1.0).abs() < 0.02,
                "{name}: rms {rms}, σ {sigma}"
            );
            assert!(
                (correlation - expected_correlation).abs() < 0.025,
                "{name}: autocorrelation at lag τ {correlation}, expected {expected_correlation}"
            );
        }
        assert!((expected_correlation - (-1.0f64).exp()).abs() < 0.01);
    }

    #[test]
    fn switched_off_turbulence_is_zero() {
        let parameters = WindParameters {
            turbulence: false,
            ..WindParameters::default()
        };
        let mut turbulence = Turbulence::new(&parameters, &RandomStreams::new(5));
        turbulence.advance(0.01, 69.1);
        assert_eq!(turbulence.wind(), Wind::default());
    }
}
