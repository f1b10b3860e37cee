//! The commit point of an approach (docs/model.md §9): the first step whose time to go is
//! at or below the wave-off's `decision_time_to_go_s`, the approach not waving off by
//! then. There the guidance computer keeps what the forecast gave for the wave-off's
//! probabilistic criteria ([`CommitForecast`]), for the run's summary, so that a campaign
//! can hold the probabilities against what the flights did (`monte_carlo::calibration`).
//!
//! It costs one comparison per step: the time to go against the commit point's, until
//! it is reached. The 3-D approach's off-centre probability is the lateral guidance's,
//! worked out at its first frame from the commit point (the same step without a flight
//! computer, at most one frame later with one), from what that frame computes anyway.

use crate::control::CommitForecast;

/// What the loop keeps of its commit point.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub(crate) struct CommitPoint {
    /// The forecast at the commit point, once reached.
    forecast: Option<CommitForecast>,
    /// Whether the lateral guidance still has to add the off-centre probability.
    lateral_pending: bool,
}

impl CommitPoint {
    /// Whether the commit point was reached.
    #[inline]
    pub fn reached(&self) -> bool {
        self.forecast.is_some()
    }

    /// Keeps `forecast` as the commit point's; with `lateral`, the lateral guidance's
    /// next frame adds the off-centre probability.
    pub fn record(&mut self, forecast: CommitForecast, lateral: bool) {
        self.forecast = Some(forecast);
        self.lateral_pending = lateral;
    }

    /// Whether the off-centre probability is still to be added.
    #[inline]
    pub fn lateral_pending(&self) -> bool {
        self.lateral_pending
    }

    /// Adds the off-centre probability `probability` (–).
    pub fn record_off_centre(&mut self, probability: f64) {
        if let Some(forecast) = &mut self.forecast {
            forecast.off_centre_probability = Some(probability);
        }
        self.lateral_pending = false;
    }

    /// The forecast at the commit point; `None` before it (or if it was never reached).
    pub fn forecast(&self) -> Option<CommitForecast> {
        self.forecast
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_off_centre_probability_is_added_once_to_the_forecast_kept() {
        let mut commit = CommitPoint::default();
        assert!(!commit.reached() && commit.forecast().is_none());
        let forecast = CommitForecast {
            ramp_strike_probability: 0.01,
            hard_landing_probability: 1e-5,
            off_centre_probability: None,
            ramp_clearance_m: 3.1,
            ramp_clearance_sigma_m: 1.3,
        };
        commit.record(forecast, true);
        assert!(commit.reached() && commit.lateral_pending());
        commit.record_off_centre(2e-4);
        assert!(!commit.lateral_pending());
        assert_eq!(
            commit.forecast(),
            Some(CommitForecast {
                off_centre_probability: Some(2e-4),
                ..forecast
            })
        );
        let mut longitudinal = CommitPoint::default();
        longitudinal.record(forecast, false);
        assert!(!longitudinal.lateral_pending());
        assert_eq!(longitudinal.forecast(), Some(forecast));
    }
}
