//! Experiments: the runs that the command line, the examples, the Python package and the
//! reproduction report all fly, each a library function that returns what was measured.
//!
//! - [`fly_approach`]: one approach to the deck, with its time series and events;
//! - [`fly_pitch_step`]: a pitch-attitude step with its step-response and elevator
//!   figures (paper Fig. 10–12);
//! - [`fly_sink_rate`]: a commanded sink rate, ramped in, with its convergence (Fig. 13);
//! - [`record_environment`]: the ship motion and the wind alone (Fig. 7, 8);
//! - [`fly_seeds`] and [`OutcomeCounts`]: one scenario over many seeds, in parallel;
//! - [`reproduction`]: every study of the paper's reproduction (`deckland reproduce`);
//! - campaigns with dispersions and confidence intervals: [`crate::monte_carlo`].
//!
//! Every function takes a complete [`Scenario`](crate::scenario::Scenario) (choose its conditions with
//! [`Conditions`]) and returns an [`ExperimentError`] naming what could not be set up or
//! measured.

mod approach;
mod conditions;
mod environment;
mod lateral_step;
mod pitch_step;
pub mod reproduction;
mod sink_rate;
mod sweep;

pub use approach::{
    fly_approach, fly_approach_with_law, ApproachRow, ApproachRun, APPROACH_COLUMNS,
    APPROACH_RECORD_INTERVAL_S, LATERAL_APPROACH_COLUMNS, OBSERVATION_COLUMNS,
};
pub use conditions::Conditions;
pub use environment::{record_environment, EnvironmentRecord, EnvironmentSample};
pub use lateral_step::{
    fly_lateral_step, CrosswindGust, LateralAxis, LateralLaws, LateralSample, LateralSetup,
    LateralStep, LateralStepError, LateralStepReport, LateralStepResponse, LateralStepRun,
    LATERAL_SETTLING_BAND_FRACTION, LATERAL_STEP_TIME_S, MAX_LATERAL_STEP_DEG,
    MIN_LATERAL_STEP_DEG,
};
pub use pitch_step::{
    fly_pitch_step, PitchStep, PitchStepResponse, PitchStepRun, PITCH_STEP_RECORD_INTERVAL_S,
    PITCH_STEP_TIME_S, SETTLING_BAND_FRACTION,
};
pub use sink_rate::{
    fly_sink_rate, SinkRateRun, SinkRateSample, SinkRateTracking, SINK_COMMAND_TIME_S,
};
pub use sweep::{fly_seeds, OutcomeCounts};

use crate::metrics::MetricsError;
use crate::simulation::SetupError;

/// Why an experiment could not be flown or measured.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ExperimentError {
    /// The scenario could not be set up.
    #[error(transparent)]
    Setup(#[from] SetupError),
    /// A recorded signal could not be measured.
    #[error("cannot measure the run: {0}")]
    Metrics(#[from] MetricsError),
    /// The run recorded nothing.
    #[error("the run recorded no samples")]
    NoSamples,
}
