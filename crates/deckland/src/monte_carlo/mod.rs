//! Monte Carlo campaigns: many approaches of one scenario, each with its own seed and
//! dispersions, flown in parallel, summarised with confidence intervals.
//!
//! - Seeds: run `i` of a campaign with seed `S` flies seed [`run_seed`]`(S, i)`, the
//!   `i`-th output of the SplitMix64 generator seeded with `S`, shifted right by one bit
//!   so that it fits a scenario file (portable, specified bit for bit). Its dispersions
//!   are drawn from that seed's `"dispersion"` stream
//!   ([`crate::scenario::DispersionParameters`]), so they never disturb the
//!   environment's streams.
//! - Parallelism: [`run_campaign`] flies the runs on a rayon pool of the requested size.
//!   Every run depends only on its seed and the runs are sorted by index at the end, so
//!   the result is identical for any thread count.
//! - Memory: each run keeps only its summary ([`crate::recording::SummaryRecorder`]) and
//!   becomes one small [`RunRecord`] (flattened for files and tables as a [`RunRow`]);
//!   nothing grows with the length of a run.
//! - Failures are data (after nyx): a run that diverges, times out or whose dispersed
//!   scenario is invalid is a record with its reason, never an abort. A stop flag ends a
//!   campaign early with the runs that finished ([`CampaignResult::partial`]).

mod campaign;
mod row;
mod seeds;
mod statistics;

pub use campaign::{
    controller_label, run_campaign, CampaignError, CampaignResult, CampaignSpec, ControllerVariant,
    RunFailure, RunRecord, SharedPitchLaw,
};
pub use row::RunRow;
pub use seeds::{run_seed, splitmix64_mix, SPLITMIX64_GAMMA};
pub use statistics::{
    percentile, wilson_interval, CampaignStatistics, Distribution, Proportion, CONFIDENCE_Z_95,
};
