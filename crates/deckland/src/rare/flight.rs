//! An approach as a trajectory splitting can branch: a [`Simulation`] with the score of
//! one event ([`EventScore`]).

use std::sync::Arc;

use super::ramp_calibration::RampCalibration;
use super::score::{EventScore, EventThresholds, RareEvent};
use super::splitting::{Advance, Trajectory};
use crate::experiments::{ApproachRun, APPROACH_COLUMNS, APPROACH_RECORD_INTERVAL_S};
use crate::monte_carlo::dispersed_run_scenario;
use crate::recording::TimeSeriesRecorder;
use crate::scenario::Scenario;
use crate::simulation::{
    Event, Recorder, RunSummary, SetupError, SignalId, Signals, Simulation, SIGNALS,
};

/// Why an approach cannot be scored.
#[derive(Debug, thiserror::Error)]
pub enum FlightError {
    /// The scenario cannot be flown.
    #[error(transparent)]
    Setup(#[from] SetupError),
    /// An event whose score reads a signal the loop does not compute
    /// ([`RareEvent::signals_read`]): `off_centre` asked of the longitudinal approach.
    #[error(
        "the event `{event}` reads `{signal}`, which only the 3-D approach computes \
         ([aircraft] model = \"6dof\"); this scenario flies the longitudinal one"
    )]
    NeedsThreeDimensions {
        /// The event's name.
        event: &'static str,
        /// The signal's name.
        signal: &'static str,
    },
}

/// One approach of a scenario, scored for one event.
#[derive(Debug, Clone)]
pub struct ApproachFlight {
    scenario: Arc<Scenario>,
    event: RareEvent,
    thresholds: EventThresholds,
    simulation: Simulation,
    score: EventScore,
    /// Why a fresh approach could not be set up (a dispersion drew an invalid
    /// scenario): it then ends at once, short of the event.
    setup_error: Option<String>,
    /// Every step's signals and the events, when the flight is recorded
    /// ([`ApproachFlight::recorded`]).
    recording: Option<TimeSeriesRecorder>,
    /// The ramp score's calibration, if calibrated ([`ApproachFlight::with_ramp_calibration`]).
    ramp_calibration: Option<Arc<RampCalibration>>,
}

impl ApproachFlight {
    /// An approach of `scenario` (as the campaign run with the scenario's seed flies it),
    /// scored for `event` with these thresholds. A fresh start ([`Trajectory::reseed`]
    /// before the first step) flies the campaign run of another seed.
    pub fn new(
        scenario: &Scenario,
        event: RareEvent,
        thresholds: EventThresholds,
    ) -> Result<Self, FlightError> {
        let scenario = Arc::new(*scenario);
        let simulation = Simulation::new(&dispersed_run_scenario(&scenario, scenario.seed).0)?;
        let computes = |signal: &SignalId| {
            let mut columns = APPROACH_COLUMNS.iter().chain(simulation.lateral_columns());
            columns.any(|column| column.signal == *signal)
        };
        if let Some(missing) = event.signals_read().iter().find(|s| !computes(s)) {
            let spec = SIGNALS.iter().find(|spec| spec.id == *missing);
            return Err(FlightError::NeedsThreeDimensions {
                event: event.name(),
                signal: spec.map_or("?", |spec| spec.name),
            });
        }
        let score = EventScore::new(event, thresholds, &scenario, &simulation);
        Ok(Self {
            scenario,
            event,
            thresholds,
            simulation,
            score,
            setup_error: None,
            recording: None,
            ramp_calibration: None,
        })
    }

    /// This flight scored with the ramp's forecast calibrated (every fresh start too).
    pub fn with_ramp_calibration(mut self, calibration: Option<Arc<RampCalibration>>) -> Self {
        self.score = self.score.with_ramp_calibration(calibration.clone());
        self.ramp_calibration = calibration;
        self
    }

    /// This flight, recording every step from here (to save a flight that reached the
    /// event: re-flown from its start along its branches, it flies the same, bit for bit).
    pub fn recorded(mut self) -> Self {
        self.recording = Some(TimeSeriesRecorder::every(0.0));
        self
    }

    /// Flies a recorded flight on to its end and returns it as `land` records an
    /// approach: every signal each [`APPROACH_RECORD_INTERVAL_S`] (and the last step),
    /// the events and the summary; `None` for a flight not recorded or never set up.
    pub fn into_run(mut self) -> Option<ApproachRun> {
        let mut recorder = self.recording.take()?;
        if self.setup_error.is_some() {
            return None;
        }
        let every =
            ((APPROACH_RECORD_INTERVAL_S / self.simulation.time_step_s()).round() as usize).max(1);
        let lateral_columns = self.simulation.lateral_columns();
        let summary = self.simulation.run(&mut recorder);
        let last = recorder.samples.len().saturating_sub(1);
        let samples = recorder
            .samples
            .into_iter()
            .enumerate()
            .filter(|(i, _)| i % every == 0 || *i == last)
            .map(|(_, sample)| sample)
            .collect();
        Some(ApproachRun {
            samples,
            events: recorder.events,
            summary,
            lateral_columns,
        })
    }

    /// The simulation flying (to replay it with a recorder attached).
    pub fn simulation(&self) -> &Simulation {
        &self.simulation
    }

    /// Why this fresh approach could not be set up, if it could not.
    pub fn setup_error(&self) -> Option<&str> {
        self.setup_error.as_deref()
    }

    /// The seed of the campaign run a fresh start with `key` flies (below 2⁶³, so that
    /// it can be written in a scenario file and flown again with `deckland run`).
    pub fn start_seed(key: u64) -> u64 {
        key >> 1
    }

    /// Starts afresh as the campaign run of the seed of `key`.
    fn restart(&mut self, key: u64) {
        let seed = Self::start_seed(key);
        let (scenario, _) = dispersed_run_scenario(&self.scenario, seed);
        match Simulation::new(&scenario) {
            Ok(simulation) => {
                self.simulation = simulation;
                self.setup_error = None;
                if self.recording.is_some() {
                    self.recording = Some(TimeSeriesRecorder::every(0.0));
                }
            }
            Err(error) => self.setup_error = Some(format!("seed {seed}: {error}")),
        }
        self.score = EventScore::new(
            self.event,
            self.thresholds,
            &self.scenario,
            &self.simulation,
        )
        .with_ramp_calibration(self.ramp_calibration.clone());
    }
}

impl Trajectory for ApproachFlight {
    fn advance(&mut self) -> Advance {
        if self.setup_error.is_some() {
            return Advance {
                score: f64::NEG_INFINITY,
                ended: true,
            };
        }
        self.score.observe(&self.simulation);
        match &mut self.recording {
            Some(recording) => self
                .simulation
                .advance(&mut Both(&mut self.score, recording)),
            None => self.simulation.advance(&mut self.score),
        };
        Advance {
            score: self.score.score(),
            ended: self.score.finished(),
        }
    }

    /// Before the first step, a fresh approach: the campaign run of the seed `key`
    /// gives ([`ApproachFlight::start_seed`]), its initial ship, turbulence and dispersions
    /// drawn anew; after, the same flight from here with every noise stream re-keyed.
    fn reseed(&mut self, key: u64) {
        if self.simulation.steps() == 0 {
            self.restart(key);
        } else {
            self.simulation.reseed(key);
        }
    }

    fn score(&self) -> f64 {
        if self.setup_error.is_some() {
            return f64::NEG_INFINITY;
        }
        self.score.score()
    }
}

/// Two recorders of every step as one.
struct Both<'a, A: Recorder, B: Recorder>(&'a mut A, &'a mut B);

impl<A: Recorder, B: Recorder> Recorder for Both<'_, A, B> {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0)
    }

    fn sample(&mut self, signals: &Signals) {
        self.0.sample(signals);
        self.1.sample(signals);
    }

    fn event(&mut self, event: &Event) {
        self.0.event(event);
        self.1.event(event);
    }

    fn finish(&mut self, summary: &RunSummary) {
        self.0.finish(summary);
        self.1.finish(summary);
    }
}
