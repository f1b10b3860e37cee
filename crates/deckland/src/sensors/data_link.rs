//! The data link both of the ship's motion sensors send over: a sample taken at the first
//! integration step at or after each multiple of the sample period, delivered at the
//! first step at or after its time plus the latency.

use std::collections::VecDeque;

use super::ShipMotionSensingParameters;
use crate::parameters::ParameterError;

/// A measurement as the data link carries it: stamped with the time it was taken.
pub trait Stamped {
    /// The time the sample was taken (s).
    fn time_s(&self) -> f64;
}

/// The sample schedule and the measurements in transit of one sensor.
#[derive(Debug, Clone)]
pub(super) struct DataLink<M> {
    parameters: ShipMotionSensingParameters,
    last_sample: Option<i64>,
    in_transit: VecDeque<M>,
}

impl<M: Stamped> DataLink<M> {
    /// An empty link with these (checked) parameters.
    pub(super) fn new(parameters: ShipMotionSensingParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        Ok(Self {
            parameters,
            last_sample: None,
            in_transit: VecDeque::with_capacity(16),
        })
    }

    /// The parameters.
    pub(super) fn parameters(&self) -> &ShipMotionSensingParameters {
        &self.parameters
    }

    /// The index of the sample period the step from `time_s` falls in.
    fn sample_index(&self, time_s: f64) -> i64 {
        // A hair above an integer counts as that integer: k·T computed as a multiple of
        // the step may round below it.
        (time_s * self.parameters.sample_rate_hz + 1e-9).floor() as i64
    }

    /// Whether a sample is due at the step from `time_s`.
    pub(super) fn sample_due(&self, time_s: f64) -> bool {
        self.last_sample != Some(self.sample_index(time_s))
    }

    /// Sends the measurement `measure` takes if a sample is due at `time_s`.
    pub(super) fn sample(&mut self, time_s: f64, measure: impl FnOnce() -> M) {
        if !self.sample_due(time_s) {
            return;
        }
        self.last_sample = Some(self.sample_index(time_s));
        self.in_transit.push_back(measure());
    }

    /// The oldest measurement that has arrived by `time_s` (taken at or before `time_s`
    /// − latency), if any.
    pub(super) fn receive(&mut self, time_s: f64) -> Option<M> {
        let arrived = self
            .in_transit
            .front()
            .is_some_and(|m| m.time_s() + self.parameters.latency_s <= time_s + 1e-9);
        if arrived {
            self.in_transit.pop_front()
        } else {
            None
        }
    }
}
