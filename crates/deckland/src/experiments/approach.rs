//! One approach to the deck, recorded.

use super::ExperimentError;
use crate::recording::TimeSeriesRecorder;
use crate::scenario::{Mission, Scenario};
use crate::simulation::{Event, PitchLawFactory, RunSummary, Signals, Simulation};

/// How often an approach's time series is recorded (s of simulated time): every 10 ms.
pub const APPROACH_RECORD_INTERVAL_S: f64 = 0.01;

/// A flown approach: every signal each [`APPROACH_RECORD_INTERVAL_S`], the events and
/// the summary.
#[derive(Debug, Clone)]
pub struct ApproachRun {
    /// The recorded signals, in time order (the last step always included).
    pub samples: Vec<Signals>,
    /// Ramp crossing, touchdown, passing the last wire.
    pub events: Vec<Event>,
    /// How it ended and what it measured.
    pub summary: RunSummary,
}

/// Flies `scenario` as an approach (whatever its mission says) and records it.
pub fn fly_approach(scenario: &Scenario) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::new(&scenario)?)
}

/// As [`fly_approach`], with a user's own pitch law flying.
pub fn fly_approach_with_law(
    scenario: &Scenario,
    pitch_law: &PitchLawFactory,
) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::with_pitch_law(&scenario, pitch_law)?)
}

fn approach_of(scenario: &Scenario) -> Scenario {
    Scenario {
        mission: Mission::Approach,
        ..*scenario
    }
}

fn record(simulation: Simulation) -> Result<ApproachRun, ExperimentError> {
    let mut recorder = TimeSeriesRecorder::every(APPROACH_RECORD_INTERVAL_S);
    let summary = simulation.run(&mut recorder);
    Ok(ApproachRun {
        samples: recorder.samples,
        events: recorder.events,
        summary,
    })
}
