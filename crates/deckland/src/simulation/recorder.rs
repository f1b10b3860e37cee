//! What the run loop hands out as it runs (argmin-style observers): signals at each
//! recorder's own cadence, events as they happen, and the summary at the end.

use super::outcome::{Event, RunSummary};
use super::signals::Signals;

/// Receives what a running simulation produces. Every method has a no-op default.
pub trait Recorder {
    /// Record signals every this many seconds of simulated time (rounded to whole
    /// integration steps, at least one); `None` records none.
    fn sample_interval_s(&self) -> Option<f64> {
        None
    }

    /// Signals at one recorded step (and at the last step of the run).
    fn sample(&mut self, _signals: &Signals) {}

    /// An event (ramp crossing, touchdown, passing the last wire).
    fn event(&mut self, _event: &Event) {}

    /// The run's summary, once, at the end.
    fn finish(&mut self, _summary: &RunSummary) {}
}

/// Running statistics of the hook's height error to the glide path over an approach:
/// an observer of every step.
#[derive(Debug, Clone, Copy, Default)]
pub struct GlidePathStatistics {
    count: u64,
    sum_squares: f64,
    max_abs: f64,
}

impl GlidePathStatistics {
    /// Adds one step's error (m).
    pub fn add(&mut self, error_m: f64) {
        self.count += 1;
        self.sum_squares += error_m * error_m;
        self.max_abs = self.max_abs.max(error_m.abs());
    }

    /// RMS of the errors (m), if any.
    pub fn rms_m(&self) -> Option<f64> {
        (self.count > 0).then(|| (self.sum_squares / self.count as f64).sqrt())
    }

    /// Largest absolute error (m), if any.
    pub fn max_m(&self) -> Option<f64> {
        (self.count > 0).then_some(self.max_abs)
    }
}

impl Recorder for GlidePathStatistics {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0)
    }

    fn sample(&mut self, signals: &Signals) {
        self.add(signals.glide_path_error_m);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn statistics_give_rms_and_largest_error() {
        let mut statistics = GlidePathStatistics::default();
        assert_eq!(statistics.rms_m(), None);
        for error in [3.0, -4.0] {
            statistics.add(error);
        }
        // RMS of 3 and −4: √((9 + 16)/2) = 3.5355…
        assert!((statistics.rms_m().expect("two") - 12.5f64.sqrt()).abs() < 1e-15);
        assert_eq!(statistics.max_m(), Some(4.0));
    }
}
