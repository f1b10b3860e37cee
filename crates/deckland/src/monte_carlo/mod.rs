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
//! - Shards: a [`Shard`] K/M of a campaign flies the runs i with i mod M = K; since a
//!   run depends only on the campaign seed and its index, [`merge_shards`] puts the M
//!   shards' rows (`runs.csv`, [`RunRow`]) together into the campaign flown whole,
//!   refusing shards that do not belong together and rows no campaign writes
//!   ([`MergeError`], [`RunRow::check`]).
//! - Limits: runs, shards and controllers have one set of bounds for every front end
//!   ([`MAX_RUNS`], [`MAX_SHARDS`], [`MAX_CONTROLLERS`]), and a shard's files a size
//!   limit ([`MAX_RUNS_CSV_BYTES`], [`MAX_SUMMARY_JSON_BYTES`]).
//! - Statistics: rates with 95 % Wilson score intervals and exact one-sided upper bounds
//!   for rare events ([`upper_bound`], [`runs_to_show_below`]), computed from the rows, so
//!   a merged campaign's statistics are those of the whole campaign.
//! - The runs table ([`RunsTable`]): its column schema ([`RunsSchema`], the groups of
//!   columns a campaign writes, [`ColumnGroup`]) is decided once from the scenario by the
//!   plant registry (what its approaches report,
//!   [`crate::aircraft::PlantModel::approach_outcome`]); `runs.csv` is read,
//!   written and merged over the schema, a shard's schema compared with its scenario's.
//! - 3-D approach campaigns ([`flies_three_dimensional_approach`]): their schema has the
//!   [`ColumnGroup::Lateral`] group, each row a [`LateralRow`] (the lateral touchdown and
//!   the trap sheet, [`TRAP_SHEET_RUN_COLUMNS`]) after the columns of every campaign;
//!   their statistics ([`LateralStatistics`], [`TrapSheetStatistics`]) are computed from
//!   those columns, so merged shards have them too.
//! - Calibration ([`Calibration`]): the probabilities the forecast gave at each run's
//!   commit point (the `commit_*_probability` columns) against what the runs did, per
//!   criterion and controller, with the count's Poisson-binomial interval and reliability
//!   bins.
//! - Failures are data (after nyx): a run that diverges, times out or whose dispersed
//!   scenario is invalid is a record with its reason, never an abort. A stop flag ends a
//!   campaign early with the runs that finished ([`CampaignResult::partial`]).

mod calibration;
mod campaign;
mod greenie_board;
mod lateral;
mod limits;
mod merge;
mod merge_error;
mod rare_events;
mod record;
mod row;
mod run_scenario;
mod runs_csv;
mod runs_table;
mod seeds;
mod shard;
mod statistics;
mod summary;
mod trap_sheet;

pub use calibration::{
    clopper_pearson_interval, count_interval, poisson_binomial, reliability_bins, Calibration,
    ClearanceError, CountInterval, CriterionCalibration, IntervalMethod, ReliabilityBin,
    CALIBRATION_BIN_EDGES, CALIBRATION_METHOD, EXACT_COUNT_LIMIT, NORMAL_VARIANCE,
};
pub use campaign::{
    controller_label, run_campaign, CampaignError, CampaignResult, CampaignSpec, ControllerVariant,
    SharedPitchLaw,
};
pub use greenie_board::{DeviationCount, GradeCount, GreenieBoard, TARGET_WIRE, TOP_DEVIATIONS};
pub use lateral::{
    flies_three_dimensional_approach, lateral_row_columns, lateral_run_values, lateral_statistics,
    LateralRow, LateralRunValues, LateralStatistics, LATERAL_RUN_COLUMNS, RAMP_LINEUP_PASS_DEG,
};
pub use limits::{
    check_runs, check_seed, check_threads, LimitError, MAX_CAMPAIGN_SEED, MAX_CONTROLLERS,
    MAX_CONTROLLER_LABEL_BYTES, MAX_RUNS, MAX_RUNS_CSV_BYTES, MAX_SHARDS, MAX_SUMMARY_JSON_BYTES,
    MAX_THREADS,
};
pub use merge::{merge_shards, MergedCampaign, ShardIdentity, ShardRows};
pub use merge_error::MergeError;
pub use rare_events::{
    binomial_cdf, regularized_incomplete_beta, runs_to_show_below, upper_bound, RareEventTarget,
    RunsNeeded, DEFAULT_TARGET_RATE, UPPER_BOUND_CONFIDENCE, UPPER_BOUND_METHOD,
};
pub use record::{RunFailure, RunRecord};
pub use row::{
    wave_off_criterion, RowError, RunRow, CAMPAIGN_OUTCOMES, LSO_RUN_COLUMNS, RANGES, RUN_COLUMNS,
};
pub use run_scenario::dispersed_run_scenario;
pub use runs_csv::{parse_runs_csv, runs_csv_text};
pub use runs_table::{ColumnGroup, RunsSchema, RunsTable, ShapeError};
pub use seeds::{run_seed, splitmix64_mix, SPLITMIX64_GAMMA};
pub use shard::{Shard, ShardError, SHARD_SCHEME};
pub use statistics::{
    percentile, wilson_interval, CampaignStatistics, Distribution, Proportion, CONFIDENCE_Z_95,
};
pub use summary::{
    CampaignSummary, CONFIDENCE_INTERVAL_METHOD, PERCENTILE_METHOD, SEED_DERIVATION,
};
pub use trap_sheet::{
    position_values, sheet_values, trap_sheet_run_values, DeviationStatistics, PositionStatistics,
    TrapSheetRunValues, TrapSheetStatistics, TRAP_SHEET_DEVIATIONS, TRAP_SHEET_INTERVALS,
    TRAP_SHEET_RUN_COLUMNS,
};
