//! Shards of one small campaign, flown once per test binary, and `runs.csv` text edits
//! for the merge tests (`shard_schema`, `merge_fuzz`).

#![allow(clippy::unwrap_used, dead_code)] // tests fail loudly by design; each uses a part

use deckland::monte_carlo::{
    run_campaign, CampaignSpec, RunRecord, RunRow, Shard, ShardIdentity, ShardRows,
};
use deckland::scenario::{DispersionParameters, Scenario};
use std::sync::atomic::AtomicBool;
use std::sync::OnceLock;

/// Runs of the fixture campaign, and its shards.
pub const RUNS: u64 = 12;
/// Shards of the fixture campaign.
pub const SHARDS: u64 = 3;

/// A short (500 m) approach of the longitudinal aircraft (a 3-DOF campaign, without
/// lateral columns) with wide dispersions, so that the runs end in several ways (traps,
/// bolters, hard landings, wave-offs, invalid dispersed scenarios).
pub fn wide_scenario() -> Scenario {
    let mut scenario = Scenario::default();
    scenario.aircraft.model = deckland::aircraft::PlantModel::ThreeDof;
    scenario.approach.start_range_m = 500.0;
    scenario.dispersion = DispersionParameters {
        start_height_offset_sd_m: 6.0,
        airspeed_error_sd_mps: 8.0,
        sea_state_log_sd: 0.8,
        wind_over_deck_sd_mps: 6.0,
    };
    scenario
}

/// The 3 shards of a 12-run campaign under O-PD and PID, as read back from files.
pub fn flown_shards() -> Vec<ShardRows> {
    static SHARDS_FLOWN: OnceLock<Vec<ShardRows>> = OnceLock::new();
    SHARDS_FLOWN
        .get_or_init(|| {
            let spec = CampaignSpec::new(wide_scenario(), RUNS, 7).comparing_pitch_controllers();
            (0..SHARDS)
                .map(|index| {
                    let shard = Shard::new(index, SHARDS).unwrap();
                    let result = run_campaign(
                        &spec.clone().sharded(shard),
                        2,
                        &|_: &RunRecord| {},
                        &AtomicBool::new(false),
                    )
                    .unwrap();
                    let rows: Vec<RunRow<'static>> = result
                        .records
                        .iter()
                        .map(|r| RunRow::new(r, &result.controller_labels).into_owned())
                        .collect();
                    // As a file carries them: through runs.csv text.
                    let table =
                        deckland::monte_carlo::parse_runs_csv("fixture", &rows_csv(&rows)).unwrap();
                    ShardRows {
                        identity: ShardIdentity {
                            source: format!("s{index}"),
                            scenario_toml: toml::to_string(&spec.scenario).unwrap(),
                            campaign_seed: 7,
                            requested_runs: RUNS,
                            controllers: result.controller_labels.clone(),
                            shard,
                            partial: result.partial,
                        },
                        table,
                    }
                })
                .collect()
        })
        .clone()
}

/// `rows` as the text of `runs.csv`.
pub fn rows_csv(rows: &[RunRow]) -> String {
    let mut writer = csv::Writer::from_writer(Vec::new());
    for row in rows {
        writer.serialize(row).unwrap();
    }
    String::from_utf8(writer.into_inner().unwrap()).unwrap()
}

/// `text` (runs.csv) with `column` of data row `row` (from 1) set to `value`.
pub fn edit_csv(text: &str, row: usize, column: &str, value: &str) -> String {
    let mut reader = csv::Reader::from_reader(text.as_bytes());
    let header = reader.headers().unwrap().clone();
    let position = header.iter().position(|c| c == column).unwrap();
    let mut writer = csv::Writer::from_writer(Vec::new());
    writer.write_record(&header).unwrap();
    for (index, record) in reader.records().enumerate() {
        let record = record.unwrap();
        let fields: Vec<&str> = record
            .iter()
            .enumerate()
            .map(|(i, f)| {
                if index + 1 == row && i == position {
                    value
                } else {
                    f
                }
            })
            .collect();
        writer.write_record(&fields).unwrap();
    }
    String::from_utf8(writer.into_inner().unwrap()).unwrap()
}
