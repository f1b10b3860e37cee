//! What a campaign folder holds before it is written: the report (`summary.json`), the
//! rows, the scenario and the title, and the outcome classes in table order. Both the
//! report's writer (`report`) and the campaign's figures (`plot::campaign`) read it.

use deckland::monte_carlo::{
    CampaignStatistics, CampaignSummary, LateralStatistics, Proportion, RunsTable, Shard,
    TrapSheetStatistics, SHARD_SCHEME,
};
use deckland::scenario::Scenario;
use serde::Serialize;

/// What `summary.json` and `--json` hold: where and how the campaign was flown around
/// the statistics ([`CampaignSummary`], flattened in the middle, so that its text is one
/// block, the same in a merged campaign as in the campaign flown whole).
#[derive(Debug, Serialize)]
pub struct CampaignReport<'a> {
    /// The scenario file given (of the first shard, for a merge).
    pub scenario_file: String,
    /// The statistics.
    #[serde(flatten)]
    pub summary: &'a CampaignSummary,
    /// Worker threads (`None` for a merge).
    pub threads: Option<usize>,
    /// Wall-clock time of the command (s).
    pub elapsed_s: f64,
    /// Runs finished per second (`None` for a merge: nothing was flown).
    pub runs_per_s: Option<f64>,
    /// The part of the campaign flown, `K/M` (`0/1` for the whole campaign).
    pub shard: String,
    /// How shards divide the runs.
    pub shard_scheme: &'static str,
    /// The shard folders a merged campaign was made from, by shard index (empty when flown).
    pub merged_from: Vec<String>,
    /// A 3-D approach campaign's lateral statistics (docs/model.md §10.4), computed
    /// from the rows' lateral columns (so a merge has them too); absent (not written) for
    /// a 3-DOF campaign.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub lateral: Option<LateralStatistics>,
    /// A 3-D approach campaign's trap-sheet statistics per position (docs/model.md
    /// §10.8), from the rows' trap-sheet columns; absent for a 3-DOF campaign.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub trap_sheet: Option<TrapSheetStatistics>,
}

impl<'a> CampaignReport<'a> {
    /// The report of a campaign merged from the shard folders `merged_from` (by shard
    /// index) in `elapsed_s`, with its statistics `summary` and, for a 3-D campaign, its
    /// `lateral` and `trap_sheet` statistics: no threads and no rate (nothing was flown),
    /// the whole campaign.
    pub fn merged(
        scenario_file: String,
        summary: &'a CampaignSummary,
        elapsed_s: f64,
        merged_from: Vec<String>,
        lateral: Option<LateralStatistics>,
        trap_sheet: Option<TrapSheetStatistics>,
    ) -> Self {
        Self {
            scenario_file,
            summary,
            threads: None,
            elapsed_s,
            runs_per_s: None,
            shard: Shard::WHOLE.to_string(),
            shard_scheme: SHARD_SCHEME,
            merged_from,
            lateral,
            trap_sheet,
        }
    }
}

/// A campaign folder's content before it is written.
pub struct CampaignFolder<'a> {
    /// The scenario flown.
    pub scenario: &'a Scenario,
    /// Its TOML text, written as `scenario.toml`.
    pub scenario_toml: &'a str,
    /// The runs table (`runs.csv`), its rows sorted by run index and controller.
    pub table: &'a RunsTable<'a>,
    /// The report (`summary.json`).
    pub report: &'a CampaignReport<'a>,
    /// The title of the plots and the page.
    pub title: String,
}

/// The title of a campaign's plots and page: scenario file name, seed, runs, shard.
pub fn title(scenario_file: &std::path::Path, report: &CampaignReport) -> String {
    let name = scenario_file.file_name().map_or_else(
        || scenario_file.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let statistics = &report.summary.controllers;
    let per_controller = statistics.first().map_or(0, |s| s.runs);
    format!(
        "{name}, seed {}, {per_controller} runs{}{}",
        report.summary.campaign_seed,
        if statistics.len() > 1 {
            " per controller"
        } else {
            ""
        },
        if report.shard == "0/1" {
            String::new()
        } else {
            format!(", shard {}", report.shard)
        }
    )
}

/// The outcome classes with their names, in table order.
pub(crate) fn proportions(s: &CampaignStatistics) -> [(&'static str, Proportion); 8] {
    [
        ("boarding (trap)", s.boarding),
        ("bolter", s.bolter),
        ("wave-off (safe)", s.wave_off),
        ("ramp strike", s.ramp_strike),
        ("hard landing", s.hard_landing),
        ("diverged", s.divergence),
        ("timeout", s.timeout),
        ("invalid scenario", s.invalid),
    ]
}
