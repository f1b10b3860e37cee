//! The statistics of a campaign as every front end writes them: the part of the CLI's
//! `summary.json` (and of the Python package's summary) that depends only on the runs.
//!
//! A campaign's summary has two parts. [`CampaignSummary`] holds the *statistics*: what
//! was asked (campaign seed, runs), what finished, and per controller the rates with their
//! intervals and bounds and the touchdown and actuator statistics. It is a function of the
//! scenario, the campaign seed, the run count and the rare-event target alone, so it is
//! the same, byte for byte, for any thread count, machine count or front end, and for a
//! campaign merged from its shards. The front ends add the *execution* beside it (the
//! scenario file's path, threads, elapsed time, shards), which describes how it was flown.

use serde::Serialize;

use super::calibration::Calibration;
use super::campaign::CampaignResult;
use super::rare_events::{RareEventTarget, UPPER_BOUND_METHOD};
use super::row::RunRow;
use super::statistics::CampaignStatistics;

/// How run seeds derive from the campaign seed, in words.
pub const SEED_DERIVATION: &str = "run i (from 0) flies seed SplitMix64 output i of the campaign \
     seed, shifted right by one bit (mix(S + (i + 1)·0x9e3779b97f4a7c15) >> 1); its dispersions \
     come from that seed's \"dispersion\" stream; `deckland run FILE --seed SEED --disperse` \
     flies it again";

/// The confidence-interval method, in words.
pub const CONFIDENCE_INTERVAL_METHOD: &str = "95 % Wilson score interval of each rate";

/// The percentile method, in words.
pub const PERCENTILE_METHOD: &str =
    "linear interpolation between closest ranks (Hyndman & Fan type 7)";

/// The statistics of a campaign (or of a shard): see the module's documentation.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampaignSummary {
    /// The campaign seed S.
    pub campaign_seed: u64,
    /// How run seeds derive from S ([`SEED_DERIVATION`]).
    pub seed_derivation: &'static str,
    /// Approaches asked for per controller, in the whole campaign.
    pub requested_runs: u64,
    /// Rows the statistics cover (runs × controllers that finished).
    pub finished_runs: u64,
    /// Whether the campaign or shard was stopped before every run finished.
    pub partial: bool,
    /// What a partial result covers, in words (`None` when complete).
    pub partial_note: Option<String>,
    /// The confidence-interval method ([`CONFIDENCE_INTERVAL_METHOD`]).
    pub confidence_interval: &'static str,
    /// The upper-bound method ([`UPPER_BOUND_METHOD`]).
    pub upper_bound: &'static str,
    /// The percentile method ([`PERCENTILE_METHOD`]).
    pub percentiles: &'static str,
    /// The rate rare events are read against, and the runs it takes to show it.
    pub rare_event_target: RareEventTarget,
    /// The statistics of each controller, in order.
    pub controllers: Vec<CampaignStatistics>,
}

impl CampaignSummary {
    /// The summary of merged shards: complete when every run of every controller is
    /// there, which [`super::merge_shards`] has checked.
    pub fn of_merged(merged: &super::MergedCampaign, target_rate: f64) -> Self {
        let expected_rows = merged
            .requested_runs
            .saturating_mul(merged.controllers.len() as u64);
        let off_centre = merged.table.off_centre();
        Self::of_rows_observed(
            &merged.table.rows,
            off_centre.as_deref(),
            &merged.controllers,
            merged.campaign_seed,
            (merged.requested_runs, expected_rows),
            target_rate,
        )
    }

    /// The summary of `rows` (any order of runs; each row's controller one of `labels`):
    /// `expected_rows` is how many a complete result holds, for `partial`.
    pub fn of_rows(
        rows: &[RunRow],
        labels: &[String],
        campaign_seed: u64,
        requested_runs: u64,
        expected_rows: u64,
        target_rate: f64,
    ) -> Self {
        Self::of_rows_observed(
            rows,
            None,
            labels,
            campaign_seed,
            (requested_runs, expected_rows),
            target_rate,
        )
    }

    /// As [`Self::of_rows`], with each row's `off_centre` column (`off_centre`, in the
    /// rows' order: a 3-D campaign's) for the calibration of the off-centre probability
    /// ([`CampaignStatistics::of_rows_observed`]); the runs are given as (requested
    /// runs, expected rows).
    pub fn of_rows_observed(
        rows: &[RunRow],
        off_centre: Option<&[Option<bool>]>,
        labels: &[String],
        campaign_seed: u64,
        (requested_runs, expected_rows): (u64, u64),
        target_rate: f64,
    ) -> Self {
        let off_centre = off_centre.filter(|o| o.len() == rows.len());
        let controllers = labels
            .iter()
            .map(|label| {
                let own: Vec<usize> = (0..rows.len())
                    .filter(|&i| rows[i].controller == label.as_str())
                    .collect();
                let own_rows: Vec<RunRow> = own.iter().map(|&i| rows[i].clone()).collect();
                let observed: Option<Vec<Option<bool>>> =
                    off_centre.map(|o| own.iter().map(|&i| o[i]).collect());
                CampaignStatistics::of_rows_observed(&own_rows, observed.as_deref(), label)
            })
            .collect();
        let finished_runs = rows.len() as u64;
        let partial = finished_runs < expected_rows;
        Self {
            campaign_seed,
            seed_derivation: SEED_DERIVATION,
            requested_runs,
            finished_runs,
            partial,
            partial_note: partial.then(|| {
                format!(
                    "stopped before every run finished: {finished_runs} of {expected_rows} runs \
                     finished; the statistics cover the finished runs only, listed by index in \
                     runs.csv"
                )
            }),
            confidence_interval: CONFIDENCE_INTERVAL_METHOD,
            upper_bound: UPPER_BOUND_METHOD,
            percentiles: PERCENTILE_METHOD,
            rare_event_target: RareEventTarget::new(target_rate),
            controllers,
        }
    }

    /// The summary of a campaign's (or shard's) result flown with campaign seed
    /// `campaign_seed`.
    pub fn of_result(result: &CampaignResult, campaign_seed: u64, target_rate: f64) -> Self {
        let rows = result.rows();
        let expected = result
            .shard
            .runs_of(result.requested_runs)
            .saturating_mul(result.controller_labels.len() as u64);
        let records: Vec<&super::RunRecord> = result.records.iter().collect();
        Self::of_rows_observed(
            &rows,
            Some(&Calibration::off_centre_of(&records)),
            &result.controller_labels,
            campaign_seed,
            (result.requested_runs, expected),
            target_rate,
        )
    }
}
