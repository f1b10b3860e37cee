//! The free response of a damped oscillator, the lateral forecast's model of each ship
//! channel (docs/model.md §10.3): x(τ) = e^(−ζωτ)·[x₀·cos ω_d τ + (ẋ₀ + ζωx₀)/ω_d·sin ω_d τ].

/// A damped oscillator's (ω, ζ < 1) free response after τ for any initial condition: the
/// decay e^(−ζωτ) and sin, cos ω_d τ, evaluated once for the value and the rate of
/// several channels of the same mode and horizon (the same operations as evaluating
/// them for each, so the same results to the bit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FreeResponse {
    /// ζω (1/s).
    decay_rate: f64,
    /// ω_d = ω√(1 − ζ²) (rad/s).
    damped: f64,
    /// sin ω_d τ, cos ω_d τ.
    sin_cos: (f64, f64),
    /// e^(−ζωτ).
    decay: f64,
}

impl FreeResponse {
    /// The response of the mode (ω rad/s, ζ) after `tau` s.
    #[inline]
    pub fn new(omega: f64, zeta: f64, tau: f64) -> Self {
        let damped = omega * (1.0 - zeta * zeta).sqrt();
        Self {
            decay_rate: zeta * omega,
            damped,
            sin_cos: (damped * tau).sin_cos(),
            decay: (-zeta * omega * tau).exp(),
        }
    }

    /// x(τ) from (x₀, ẋ₀): [`oscillator_forecast`](super::forecast::oscillator_forecast).
    #[inline]
    pub fn value(&self, x0: f64, rate0: f64) -> f64 {
        let (sin, cos) = self.sin_cos;
        self.decay * (x0 * cos + (rate0 + self.decay_rate * x0) / self.damped * sin)
    }

    /// ẋ(τ) from (x₀, ẋ₀): [`oscillator_forecast_rate`](super::forecast::oscillator_forecast_rate).
    #[inline]
    pub fn rate(&self, x0: f64, rate0: f64) -> f64 {
        let (sin, cos) = self.sin_cos;
        let b = (rate0 + self.decay_rate * x0) / self.damped;
        self.decay * (rate0 * cos - (self.decay_rate * b + self.damped * x0) * sin)
    }
}
