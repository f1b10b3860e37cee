//! Recorders: what a simulation hands out as it runs (argmin-style observers).
//!
//! [`crate::simulation::Simulation`] owns the loop and calls a [`Recorder`] with signals
//! at the recorder's own interval, with events as they happen, and once at the end.
//! Monte Carlo campaigns use [`SummaryRecorder`] (nothing kept); single runs a
//! [`TimeSeriesRecorder`].

pub mod acmi;
mod columns;

pub use crate::simulation::Recorder;
use crate::simulation::{Event, RunSummary, Signals};
pub use columns::{Cell, ColumnError, Columns};

/// Keeps nothing: for Monte Carlo runs, where the summary is all that is needed.
#[derive(Debug, Clone, Copy, Default)]
pub struct SummaryRecorder;

impl Recorder for SummaryRecorder {}

/// Keeps a time series of every signal at a fixed interval of simulated time, the
/// events, and the summary.
#[derive(Debug, Clone, Default)]
pub struct TimeSeriesRecorder {
    interval_s: f64,
    /// The recorded signals, in time order.
    pub samples: Vec<Signals>,
    /// The events, in time order.
    pub events: Vec<Event>,
    /// The run's summary, once it has ended.
    pub summary: Option<RunSummary>,
}

impl TimeSeriesRecorder {
    /// Records every `interval_s` seconds of simulated time (rounded to whole
    /// integration steps, at least one step).
    pub fn every(interval_s: f64) -> Self {
        Self {
            interval_s,
            ..Self::default()
        }
    }
}

impl Recorder for TimeSeriesRecorder {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(self.interval_s)
    }

    fn sample(&mut self, signals: &Signals) {
        self.samples.push(*signals);
    }

    fn event(&mut self, event: &Event) {
        self.events.push(*event);
    }

    fn finish(&mut self, summary: &RunSummary) {
        self.summary = Some(summary.clone());
    }
}
