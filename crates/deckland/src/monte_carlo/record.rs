//! One run of a campaign as it is kept: its index, controller, seed, dispersions and
//! summary, or why it produced no flight.

use crate::scenario::DispersionSample;
use crate::simulation::lateral::LateralTouchdown;
use crate::simulation::{RunSummary, SetupError};

/// Why a run produced no flight.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum RunFailure {
    /// The (dispersed) scenario could not be set up: a value out of range, or no trim.
    #[error("invalid dispersed scenario: {0}")]
    Invalid(#[from] SetupError),
    /// The simulation panicked (a bug); the message is the panic's.
    #[error("the simulation panicked: {0}")]
    Panicked(String),
}

/// One run of a campaign: one small row, kept for every run however it ended.
#[derive(Debug, Clone, PartialEq)]
pub struct RunRecord {
    /// Index of the run (from 0).
    pub run_index: u64,
    /// Index of the controller in the campaign's `CampaignSpec::controllers`.
    pub controller: usize,
    /// The run's seed.
    pub seed: u64,
    /// The dispersions drawn for the run.
    pub dispersion: DispersionSample,
    /// The run's summary, or why it could not fly.
    pub result: Result<RunSummary, RunFailure>,
}

impl RunRecord {
    /// The outcome's name: a [`crate::simulation::Outcome`] name, `invalid` or `panicked`.
    pub fn outcome_name(&self) -> &'static str {
        match &self.result {
            Ok(summary) => summary.outcome.name(),
            Err(RunFailure::Invalid(_)) => "invalid",
            Err(RunFailure::Panicked(_)) => "panicked",
        }
    }

    /// The lateral outcome, if the run is a 3-D approach that touched down.
    pub fn lateral_touchdown(&self) -> Option<LateralTouchdown> {
        self.result.as_ref().ok()?.lateral_touchdown().copied()
    }

    /// Why the run did not trap, in words (`None` for a trap).
    pub fn failure_reason(&self) -> Option<String> {
        match &self.result {
            Ok(summary) => summary.reason.clone(),
            Err(failure) => Some(failure.to_string()),
        }
    }
}
