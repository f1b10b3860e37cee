//! Sharded campaigns: the shards of a campaign together are the campaign, run for run,
//! and a merge refuses shards that do not belong together, naming what differs.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use deckland::aircraft::PlantModel;
use deckland::monte_carlo::{
    merge_shards, run_campaign, CampaignResult, CampaignSpec, CampaignStatistics, CampaignSummary,
    MergeError, RunRecord, RunRow, RunsSchema, RunsTable, Shard, ShardIdentity, ShardRows,
    DEFAULT_TARGET_RATE,
};
use deckland::scenario::Scenario;
use std::sync::atomic::AtomicBool;

/// The longitudinal aircraft (a 3-DOF campaign: no lateral columns), adverse
/// conditions, a short approach (500 m) and every dispersion on.
fn short_dispersed_scenario() -> Scenario {
    let mut scenario = Scenario::default();
    scenario.aircraft.model = PlantModel::ThreeDof;
    scenario.approach.start_range_m = 500.0;
    scenario.dispersion = common::every_dispersion();
    scenario
}

/// Asserts that a merge of `shards` is refused with an error that says `expected`.
fn assert_refused(shards: Vec<ShardRows>, expected: &str) {
    let error = merge_shards(shards).unwrap_err().to_string();
    assert!(error.contains(expected), "{error}");
}

fn fly(spec: &CampaignSpec) -> CampaignResult {
    run_campaign(spec, 2, &|_: &RunRecord| {}, &AtomicBool::new(false)).unwrap()
}

fn shard_rows(result: &CampaignResult, seed: u64, source: &str) -> ShardRows {
    ShardRows {
        identity: ShardIdentity {
            source: source.to_owned(),
            scenario_toml: toml::to_string(&short_dispersed_scenario()).unwrap(),
            campaign_seed: seed,
            requested_runs: result.requested_runs,
            controllers: result.controller_labels.clone(),
            shard: result.shard,
            partial: result.partial,
        },
        table: RunsTable {
            rows: result
                .records
                .iter()
                // As read back from a file: owning its text.
                .map(|r| RunRow::new(r, &result.controller_labels).into_owned())
                .collect(),
            ..RunsTable::empty(RunsSchema::LONGITUDINAL)
        },
    }
}

#[test]
fn three_shards_merged_are_the_campaign_flown_whole() {
    let (runs, seed) = (17, 5);
    let spec =
        CampaignSpec::new(short_dispersed_scenario(), runs, seed).comparing_pitch_controllers();
    let whole = fly(&spec);
    let mut shards = Vec::new();
    for index in [2, 0, 1] {
        let shard = Shard::new(index, 3).unwrap();
        let result = fly(&spec.clone().sharded(shard));
        assert_eq!(result.records.len() as u64, 2 * shard.runs_of(runs));
        assert!(result.records.iter().all(|r| shard.contains(r.run_index)));
        shards.push(shard_rows(&result, seed, &format!("shard-{index}")));
    }
    let merged = merge_shards(shards).unwrap();
    let expected: Vec<RunRow> = whole
        .records
        .iter()
        .map(|r| RunRow::new(r, &whole.controller_labels))
        .collect();
    assert_eq!(merged.table.rows, expected);
    assert_eq!(merged.sources, ["shard-0", "shard-1", "shard-2"]);
    // The statistics from the rows are those from the records.
    let summary = CampaignSummary::of_rows(
        &merged.table.rows,
        &merged.controllers,
        seed,
        runs,
        2 * runs,
        DEFAULT_TARGET_RATE,
    );
    assert_eq!(
        summary,
        CampaignSummary::of_result(&whole, seed, DEFAULT_TARGET_RATE)
    );
    assert_eq!(summary.controllers, whole.statistics());
    assert!(!summary.partial);
    let opd: Vec<RunRow> = expected
        .iter()
        .filter(|r| r.controller == "O-PD")
        .cloned()
        .collect();
    assert_eq!(
        CampaignStatistics::of_rows(&opd, "O-PD"),
        whole.statistics()[0]
    );
}

#[test]
fn a_merge_refuses_shards_that_do_not_belong_together() {
    let (runs, seed) = (6, 9);
    let spec = CampaignSpec::new(short_dispersed_scenario(), runs, seed);
    let shard = |index: u64| {
        let result = fly(&spec.clone().sharded(Shard::new(index, 3).unwrap()));
        shard_rows(&result, seed, &format!("s{index}"))
    };
    let (one, two, three) = (shard(0), shard(1), shard(2));
    let all = || vec![one.clone(), two.clone(), three.clone()];
    assert!(merge_shards(all()).is_ok());
    assert_eq!(merge_shards(Vec::new()), Err(MergeError::NoShards));

    // One shard with a 3-D campaign's lateral columns among 3-DOF ones.
    let mut lateral = all();
    let blank = deckland::monte_carlo::LateralRow {
        touchdown: (None, None, None, None, None, None),
        trap_sheet: [None; 24],
    };
    lateral[1].table.schema = RunsSchema::WITH_LATERAL;
    lateral[1].table.lateral_rows = vec![blank; lateral[1].table.rows.len()];
    let error = merge_shards(lateral.clone()).unwrap_err().to_string();
    assert!(error.contains("runs.csv columns"), "{error}");
    assert!(error.contains("`aircraft.model` = \"3dof\""), "{error}");
    // Lateral columns for fewer rows than the shard has, under a 3-D scenario.
    let mut three_d = short_dispersed_scenario();
    three_d.aircraft.model = PlantModel::SixDof;
    for shard in &mut lateral {
        shard.table.schema = RunsSchema::WITH_LATERAL;
        shard.table.lateral_rows = vec![blank; shard.table.rows.len()];
        shard.identity.scenario_toml = toml::to_string(&three_d).unwrap();
    }
    lateral[2].table.lateral_rows.pop();
    assert_refused(lateral, "one per row");

    let error = merge_shards(vec![one.clone(), three.clone()]).unwrap_err();
    assert_eq!(
        error,
        MergeError::MissingShards {
            missing: vec![1],
            total: 1,
            count: 3
        }
    );
    assert_eq!(
        error.to_string(),
        "missing shard 1/3: a merge needs every shard"
    );

    let error =
        merge_shards(vec![one.clone(), two.clone(), two.clone(), three.clone()]).unwrap_err();
    assert!(matches!(error, MergeError::Overlapping { .. }), "{error}");
    assert!(error.to_string().contains("both shard 1/3"), "{error}");

    let mut partial = all();
    partial[1].identity.partial = true;
    partial[1].table.rows.pop();
    assert_refused(partial, "s1 is shard 1/3 stopped");

    let mut other_seed = all();
    other_seed[2].identity.campaign_seed = 10;
    let error = merge_shards(other_seed).unwrap_err();
    assert_eq!(
        error.to_string(),
        "s2 is not a shard of the same campaign as s0: `campaign_seed` is 10 there and 9 in s0"
    );

    let mut other_runs = all();
    other_runs[1].identity.requested_runs = 7;
    assert_refused(other_runs, "`requested_runs` is 7");

    let mut other_count = all();
    other_count[1].identity.shard = Shard::new(1, 4).unwrap();
    assert_refused(other_count, "`shard count M` is 1/4");

    let mut other_scenario = all();
    other_scenario[1].identity.scenario_toml =
        "seed = 1\n[aircraft]\nmodel = \"3dof\"\n".to_owned();
    other_scenario[0].identity.scenario_toml =
        "seed = 1\n[aircraft]\nmodel = \"3dof\"\n[approach]\nstart_range_m = 500.0\n".to_owned();
    other_scenario[2].identity.scenario_toml = other_scenario[0].identity.scenario_toml.clone();
    assert_refused(other_scenario, "s1 flew another scenario than s0");

    // A truncated shard: its last row lost.
    let mut truncated = all();
    truncated[2].table.rows.pop();
    assert_refused(
        truncated,
        "s2 (shard 2/3) holds 1 of its 2 rows; the first missing is run 5",
    );

    // A row of another shard, a row twice, a row with another campaign's seed.
    let mut foreign = all();
    let stray = foreign[0].table.rows[0].clone();
    foreign[1].table.rows.push(stray);
    assert_refused(foreign, "run 0 (O-PD) belongs to shard 0/3");
    let mut twice = all();
    let copy = twice[0].table.rows[0].clone();
    twice[0].table.rows.push(copy);
    assert_refused(twice, "appears twice");
    let mut reseeded = all();
    reseeded[0].table.rows[1].seed += 1;
    assert_refused(reseeded, "where campaign seed 9 gives");
}

#[test]
fn a_shard_beyond_the_runs_is_refused() {
    let spec =
        CampaignSpec::new(short_dispersed_scenario(), 2, 1).sharded(Shard::new(2, 3).unwrap());
    let error = run_campaign(&spec, 1, &|_: &RunRecord| {}, &AtomicBool::new(false)).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("shard 2/3 of a campaign of 2 runs holds no run"),
        "{error}"
    );
}
