//! Lateral wave-off criteria of the 3-D approach (shared model §10.8; docs/model.md
//! §10.3): in the decision window of [`super::WaveOffParameters`], wave off when the
//! lineup error predicted at touchdown (the caller's forecast, under the lineup loop),
//! or the drift across the landing area's centreline, is beyond its limit. The limits are assumptions, named here: half the
//! arresting gear's off-centre limit (6.1 m) for the predicted error, so that the
//! scatter of the last seconds stays within it, and the touchdown drift limit (1.5 m/s)
//! for the drift.

use super::wave_off::{WaveOffCriterion, WaveOffDecision, WaveOffParameters};

/// Limits of the lateral wave-off criteria (module docs; assumptions).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralWaveOffLimits {
    /// Largest lineup error predicted at touchdown (m): 3.05, half of 6.1 m.
    pub max_predicted_lineup_error_m: f64,
    /// Largest drift rate across the centreline (m/s): 1.5, the touchdown limit.
    pub max_drift_rate_mps: f64,
}

impl Default for LateralWaveOffLimits {
    fn default() -> Self {
        Self {
            max_predicted_lineup_error_m: 3.05,
            max_drift_rate_mps: 1.5,
        }
    }
}

impl LateralWaveOffLimits {
    /// The decision at `time_to_go_s` for a hook whose lineup error is predicted to be
    /// `predicted_error_m` at touchdown (right of the forecast centreline) and which
    /// drifts across it at `error_rate_mps` now. `None` outside the window of `window`
    /// or within limits; `predicted_ramp_clearance_m` is carried into the decision.
    pub fn decide(
        &self,
        window: &WaveOffParameters,
        time_to_go_s: f64,
        predicted_error_m: f64,
        error_rate_mps: f64,
        predicted_ramp_clearance_m: f64,
    ) -> Option<WaveOffDecision> {
        if !window.in_window(time_to_go_s) {
            return None;
        }
        let predicted = predicted_error_m;
        let checks = [
            (
                WaveOffCriterion::LineupError,
                predicted,
                self.max_predicted_lineup_error_m,
                predicted.abs() > self.max_predicted_lineup_error_m,
            ),
            (
                WaveOffCriterion::LineupDriftRate,
                error_rate_mps,
                self.max_drift_rate_mps,
                error_rate_mps.abs() > self.max_drift_rate_mps,
            ),
        ];
        checks
            .into_iter()
            .find(|check| check.3)
            .map(|(criterion, value, limit, _)| WaveOffDecision {
                criterion,
                value,
                limit,
                predicted_ramp_clearance_m,
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_predicted_lineup_error_or_a_fast_drift_waves_off_in_the_window_only() {
        let window = WaveOffParameters::default();
        let limits = LateralWaveOffLimits::default();
        // 3 s to go, 4 m right predicted at touchdown: beyond 3.05.
        let decision = limits
            .decide(&window, 3.0, 4.0, 1.0, 2.0)
            .expect("waves off");
        assert_eq!(decision.criterion, WaveOffCriterion::LineupError);
        assert!((decision.value - 4.0).abs() < 1e-12);
        // On the line at touchdown, but drifting at 2 m/s now: too fast.
        let decision = limits
            .decide(&window, 3.0, 0.0, -2.0, 2.0)
            .expect("waves off");
        assert_eq!(decision.criterion, WaveOffCriterion::LineupDriftRate);
        assert!(limits.decide(&window, 3.0, 1.0, -0.2, 2.0).is_none());
        assert!(
            limits.decide(&window, 10.0, 5.0, 1.0, 2.0).is_none(),
            "outside the window"
        );
    }
}
