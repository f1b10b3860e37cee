//! The lateral component v1 of free-air turbulence (docs/model.md §3.9; shared model
//! §10.6).
//!
//! MIL-F-8785C at low altitude gives the lateral component the longitudinal one's RMS
//! and scale, σ_v = σ_u and L_v = L_u (here L = 100 ft = 30.48 m, paper Eq. 19). As for
//! u1 and w1 ([`super::Turbulence`]), v1 is taken as a first-order Dryden process: seen
//! at airspeed V through the frozen field it is a Gauss–Markov process with time
//! constant τ = L/V, whose two-sided spectrum in time frequency ω (rad/s) is
//! Φ_v(ω) = 2σ²τ/(1 + (τω)²) (∫Φ_v dω/2π over all ω is σ²), and its autocorrelation
//! σ²·e^(−|lag|/τ). It is advanced exactly per step:
//! v ← e^(−dt/τ)·v + σ·√(1 − e^(−2dt/τ))·n. It draws from its own stream,
//! `turbulence_v`, so u1 and w1 are unchanged. v1 is positive to the right (earth y).

use super::wind::{Wind, WindParameters};
use crate::random::{stream_names, NoiseStream, RandomStreams, Reseed};

/// The lateral turbulence state v1 and its random stream.
#[derive(Debug, Clone)]
pub struct LateralTurbulence {
    enabled: bool,
    sigma_mps: f64,
    scale_m: f64,
    v_mps: f64,
    stream: NoiseStream,
}

impl LateralTurbulence {
    /// Lateral turbulence with σ_v = `turbulence_sigma_u_mps` and the scale
    /// `turbulence_scale_m`, started from its stationary distribution v1 = σ_v·n with the
    /// `turbulence_v` stream; zero, with nothing drawn, when turbulence is off.
    pub fn new(parameters: &WindParameters, streams: &RandomStreams) -> Self {
        let mut turbulence = Self {
            enabled: parameters.turbulence,
            sigma_mps: parameters.turbulence_sigma_u_mps,
            scale_m: parameters.turbulence_scale_m,
            v_mps: 0.0,
            stream: streams.stream(stream_names::TURBULENCE_V),
        };
        if turbulence.enabled {
            turbulence.v_mps = turbulence.sigma_mps * turbulence.stream.standard_normal();
        }
        turbulence
    }

    /// No lateral turbulence (the longitudinal approach's): v1 = 0, nothing drawn from
    /// the `turbulence_v` stream.
    pub fn off(parameters: &WindParameters, streams: &RandomStreams) -> Self {
        Self::new(
            &WindParameters {
                turbulence: false,
                ..*parameters
            },
            streams,
        )
    }

    /// σ_v (m/s).
    pub fn sigma_mps(&self) -> f64 {
        self.sigma_mps
    }

    /// Advances v1 by `dt` (s) at airspeed `airspeed_mps` (m/s), τ = L/|V|; one sample
    /// from the stream. At zero airspeed the field is frozen.
    pub fn advance(&mut self, dt: f64, airspeed_mps: f64) {
        if !self.enabled {
            return;
        }
        let decay = (-dt * airspeed_mps.abs() / self.scale_m).exp();
        let spread = (1.0 - decay * decay).max(0.0).sqrt();
        self.v_mps = decay * self.v_mps + self.sigma_mps * spread * self.stream.standard_normal();
    }

    /// The current lateral turbulence as a wind: W_y = v1, W_x = W_z = 0.
    pub fn wind(&self) -> Wind {
        Wind {
            y_mps: self.v_mps,
            ..Wind::default()
        }
    }
}

impl Reseed for LateralTurbulence {
    fn reseed(&mut self, key: u64) {
        self.stream.reseed(key);
    }
}
