//! Lateral wave-off criteria of the 3-D approach (shared model §10.8; docs/model.md
//! §10.3): in the decision window of [`super::WaveOffParameters`], wave off when the
//! probability of an off-centre touchdown, or the drift across the landing area's
//! centreline, is beyond its limit.
//!
//! The lineup error at touchdown is taken as normal about the caller's prediction (the
//! lineup loop's own response), with σ² = σ_f² + σ_h²: σ_f what the ship's roll, yaw and
//! sway will add unforeseen before touchdown (`simulation::lateral::floor`), σ_h the
//! hook's lateral scatter about the prediction. The probability that it lies beyond the
//! arresting gear's off-centre limit L = 6.1 m either side is
//! P = Φ((ê − L)/σ) + Φ((−L − ê)/σ). The limits are assumptions, named here.

use super::risk::normal_cdf;
use super::wave_off::{first_out_of_limits, WaveOffCriterion, WaveOffDecision, WaveOffParameters};

/// The arresting gear's off-centre engagement limit (m): 6.1 m, 20 ft, an assumption
/// (shared model §10.8).
pub const MAX_OFF_CENTRE_M: f64 = 6.1;

/// Limits of the lateral wave-off criteria (module docs; assumptions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralWaveOffLimits {
    /// Largest probability of an off-centre touchdown (–): 10⁻⁴, the bound the ramp
    /// clearance plans for (`control.flight_path.ramp_strike_probability_limit`).
    pub max_off_centre_probability: f64,
    /// σ_h, the hook's lateral scatter about the predicted lineup error (m): 0.45, the
    /// touchdown's lateral σ of the 3-D default (0.43 m over 1000 approaches,
    /// BENCHMARKS.md), which holds the whole scatter, the deck's motion too.
    pub lineup_scatter_m: f64,
    /// Largest drift rate across the centreline (m/s): 1.5, the touchdown limit.
    pub max_drift_rate_mps: f64,
}

impl Default for LateralWaveOffLimits {
    fn default() -> Self {
        Self {
            max_off_centre_probability: 1e-4,
            lineup_scatter_m: 0.45,
            max_drift_rate_mps: 1.5,
        }
    }
}

/// The probability that a lineup error normal about `predicted_m` with σ `sigma_m`
/// lies beyond `limit_m` either side (module docs); with σ = 0, whether it does.
pub fn off_centre_probability(predicted_m: f64, sigma_m: f64, limit_m: f64) -> f64 {
    if sigma_m <= 0.0 {
        return f64::from(u8::from(predicted_m.abs() > limit_m));
    }
    normal_cdf((predicted_m - limit_m) / sigma_m) + normal_cdf((-limit_m - predicted_m) / sigma_m)
}

impl LateralWaveOffLimits {
    /// The probability of an off-centre touchdown (module docs) for a lineup error
    /// predicted to be `predicted_error_m` at touchdown, the deck's unforeseen motion
    /// adding σ `forecast_sigma_m`: σ = hypot(σ_f, σ_h) beyond [`MAX_OFF_CENTRE_M`]
    /// either side; what the off-centre criterion compares with its limit.
    pub fn probability(&self, predicted_error_m: f64, forecast_sigma_m: f64) -> f64 {
        let sigma = forecast_sigma_m.hypot(self.lineup_scatter_m);
        off_centre_probability(predicted_error_m, sigma, MAX_OFF_CENTRE_M)
    }

    /// The decision at `time_to_go_s` for a hook whose lineup error is predicted to be
    /// `predicted_error_m` at touchdown (right of the forecast centreline), the deck's
    /// unforeseen motion adding σ `forecast_sigma_m` by then, and which drifts across
    /// it at `error_rate_mps` now. `None` outside the window of `window` or within
    /// limits; `predicted_ramp_clearance_m` is carried into the decision. The
    /// probability's value and limit are in percent, as the ramp strike's.
    pub fn decide(
        &self,
        window: &WaveOffParameters,
        time_to_go_s: f64,
        predicted_error_m: f64,
        forecast_sigma_m: f64,
        error_rate_mps: f64,
        predicted_ramp_clearance_m: f64,
    ) -> Option<WaveOffDecision> {
        if !window.in_window(time_to_go_s) {
            return None;
        }
        let probability = self.probability(predicted_error_m, forecast_sigma_m);
        let checks = [
            (
                WaveOffCriterion::OffCentreProbability,
                100.0 * probability,
                100.0 * self.max_off_centre_probability,
                probability > self.max_off_centre_probability,
            ),
            (
                WaveOffCriterion::LineupDriftRate,
                error_rate_mps,
                self.max_drift_rate_mps,
                error_rate_mps.abs() > self.max_drift_rate_mps,
            ),
        ];
        first_out_of_limits(checks, predicted_ramp_clearance_m)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_off_centre_probability_or_a_fast_drift_waves_off_in_the_window_only() {
        // By hand (Python's math.erfc): σ = hypot(0.3, 0.45) = 0.54083 m, and
        // P = Φ((ê − 6.1)/σ) + Φ((−6.1 − ê)/σ) is 2.09808 % at ê = 5 m right,
        // 0.154620 % at 4.5 m left, 0.0051609 % at 4 m and 7.645e−5 % at 3.5 m, against
        // the limit 10⁻⁴ = 0.01 %; Φ's fit is good to 1.2·10⁻⁷ of its value
        // (`control::risk`).
        let window = WaveOffParameters::default();
        let limits = LateralWaveOffLimits::default();
        let decision = limits
            .decide(&window, 3.0, 5.0, 0.3, 1.0, 2.0)
            .expect("waves off");
        assert_eq!(decision.criterion, WaveOffCriterion::OffCentreProbability);
        assert!(
            (decision.value - 2.098_080_32).abs() < 1e-6,
            "{}",
            decision.value
        );
        assert!((decision.limit - 0.01).abs() < 1e-15);
        assert_eq!(decision.predicted_ramp_clearance_m, 2.0);
        let left = limits
            .decide(&window, 3.0, -4.5, 0.3, -1.0, 2.0)
            .expect("waves off, to the left");
        assert!((left.value - 0.154_619_754).abs() < 3e-8, "{}", left.value);
        // Within the limit: 4 m and 3.5 m predicted, where a fixed 3.05 m would wave off.
        assert!(limits.decide(&window, 3.0, 4.0, 0.3, 1.0, 2.0).is_none());
        let p = off_centre_probability(3.5, 0.3_f64.hypot(0.45), MAX_OFF_CENTRE_M);
        assert!((p - 7.645_228e-7).abs() < 1e-12, "{p}");
        // A larger unforeseen motion makes the same prediction a wave-off.
        assert!(limits.decide(&window, 3.0, 4.0, 1.0, 1.0, 2.0).is_some());
        // On the line at touchdown, but drifting at 2 m/s now: too fast.
        let decision = limits
            .decide(&window, 3.0, 0.0, 0.3, -2.0, 2.0)
            .expect("waves off");
        assert_eq!(decision.criterion, WaveOffCriterion::LineupDriftRate);
        assert!(limits.decide(&window, 3.0, 1.0, 0.3, -0.2, 2.0).is_none());
        assert!(
            limits.decide(&window, 10.0, 5.0, 0.3, 1.0, 2.0).is_none(),
            "outside the window"
        );
    }

    #[test]
    fn with_no_scatter_the_probability_is_whether_the_prediction_is_off_centre() {
        assert_eq!(off_centre_probability(6.2, 0.0, 6.1), 1.0);
        assert_eq!(off_centre_probability(-6.2, 0.0, 6.1), 1.0);
        assert_eq!(off_centre_probability(6.0, 0.0, 6.1), 0.0);
        // Symmetric, and a half at the limit itself (within Φ's fit).
        let p = off_centre_probability(1.3, 0.8, 6.1);
        assert_eq!(p, off_centre_probability(-1.3, 0.8, 6.1));
        assert!((off_centre_probability(6.1, 0.5, 6.1) - 0.5).abs() < 1e-7);
    }
}
