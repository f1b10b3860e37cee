//! Recorders: what a simulation hands out as it runs (argmin-style observers).
//!
//! [`crate::simulation::Simulation`] owns the loop and calls a [`Recorder`] with signals
//! every `sample_interval_steps()` steps, with events as they happen, and once at the end.
//! Monte Carlo campaigns use [`SummaryRecorder`] (nothing kept); single runs a
//! [`TimeSeriesRecorder`].

use crate::simulation::{Event, RunSummary, Signals};

/// Receives what a running simulation produces. Every method has a no-op default.
pub trait Recorder {
    /// Record signals every this many steps; 0 records none.
    fn sample_interval_steps(&self) -> usize {
        0
    }

    /// Signals at one step.
    fn sample(&mut self, _signals: &Signals) {}

    /// An event (ramp crossing, touchdown).
    fn event(&mut self, _event: &Event) {}

    /// The run's summary, once, at the end.
    fn finish(&mut self, _summary: &RunSummary) {}
}

/// Keeps nothing: for Monte Carlo runs, where the summary is all that is needed.
#[derive(Debug, Clone, Copy, Default)]
pub struct SummaryRecorder;

impl Recorder for SummaryRecorder {}

/// Keeps a decimated time series of every signal, and the events.
#[derive(Debug, Clone, Default)]
pub struct TimeSeriesRecorder {
    interval_steps: usize,
    /// The recorded signals, in time order.
    pub samples: Vec<Signals>,
    /// The events, in time order.
    pub events: Vec<Event>,
}

impl TimeSeriesRecorder {
    /// Records every `interval_steps` steps (at least 1).
    pub fn new(interval_steps: usize) -> Self {
        Self {
            interval_steps: interval_steps.max(1),
            samples: Vec::new(),
            events: Vec::new(),
        }
    }
}

impl Recorder for TimeSeriesRecorder {
    fn sample_interval_steps(&self) -> usize {
        self.interval_steps
    }

    fn sample(&mut self, signals: &Signals) {
        self.samples.push(*signals);
    }

    fn event(&mut self, event: &Event) {
        self.events.push(*event);
    }
}
