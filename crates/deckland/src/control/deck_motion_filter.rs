//! The `filter_lead` predictor's filter on the landing point's height (docs/model.md §5.7).

/// Critically damped second-order low-pass filter on the landing point's height:
/// ĥ̈ = ω²(h_L − ĥ) − 2ω·ĥ̇. Its two states are the smooth height and rate estimates.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeckMotionFilter {
    omega: f64,
}

impl DeckMotionFilter {
    /// A filter of natural frequency `frequency_radps` (rad/s).
    pub fn new(frequency_radps: f64) -> Self {
        Self {
            omega: frequency_radps,
        }
    }

    /// Derivatives of (ĥ, ĥ̇) given the measured landing-point height (m).
    #[inline]
    pub fn derivative(&self, estimate: [f64; 2], measured_height_m: f64) -> [f64; 2] {
        [
            estimate[1],
            self.omega * self.omega * (measured_height_m - estimate[0])
                - 2.0 * self.omega * estimate[1],
        ]
    }
}
