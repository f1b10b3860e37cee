//! The shard and row schema of a merge (issue 28, D1, D4 and D8): a merge accepts every
//! row a campaign writes and refuses every row, identity or `runs.csv` text no campaign
//! can write, naming the row and the column.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod shard_fixture;

use deckland::monte_carlo::{
    merge_shards, parse_runs_csv, MergeError, Shard, ShardError, ShardRows, LSO_RUN_COLUMNS,
    MAX_RUNS, RUN_COLUMNS,
};
use shard_fixture::{edit_csv, flown_shards, rows_csv};

/// The error of merging `shards` after `edit`.
fn merge_after(shards: &[ShardRows], edit: impl FnOnce(&mut Vec<ShardRows>)) -> MergeError {
    let mut shards = shards.to_vec();
    edit(&mut shards);
    merge_shards(shards).unwrap_err()
}

#[test]
fn every_row_a_campaign_writes_passes_the_schema_and_reads_back() {
    let shards = flown_shards();
    let outcomes: std::collections::BTreeSet<String> = shards
        .iter()
        .flat_map(|s| s.table.rows.iter().map(|r| r.outcome.to_string()))
        .collect();
    // The fixture reaches several outcome classes, so the schema is tried on each.
    assert!(outcomes.len() >= 2, "{outcomes:?}");
    for shard in &shards {
        for row in &shard.table.rows {
            row.check().unwrap_or_else(|e| panic!("{row:?}: {e}"));
        }
        let text = rows_csv(&shard.table.rows);
        assert_eq!(
            parse_runs_csv("runs.csv", &text).unwrap().rows,
            shard.table.rows
        );
    }
    assert!(merge_shards(shards).is_ok());
}

/// Regression (issue 28, D8): rows no campaign writes were merged.
#[test]
fn regression_rows_no_campaign_writes_are_refused_by_row_and_column() {
    let shards = flown_shards();
    let text = rows_csv(&shards[0].table.rows);
    let trap = shards[0]
        .table
        .rows
        .iter()
        .position(|r| r.outcome == "trap")
        .expect("a trap in the fixture")
        + 1;
    let not_trap = shards[0]
        .table
        .rows
        .iter()
        .position(|r| r.outcome != "trap")
        .expect("another outcome in the fixture")
        + 1;
    let committed = shards[0]
        .table
        .rows
        .iter()
        .position(|r| r.commit_ramp_strike_probability.is_some())
        .expect("a run of the fixture that reached the commit point")
        + 1;
    // (row, column, new value): the error names the column edited.
    let cases: &[(usize, &str, &str)] = &[
        (trap, "outcome", "crash"),
        (trap, "outcome", "completed"),
        (trap, "outcome", ""),
        (trap, "wire", "9"),
        (trap, "wire", "0"),
        (trap, "wire", ""),
        (not_trap, "wire", "2"),
        (trap, "touchdown_distance_m", ""),
        (trap, "touchdown_distance_m", "1.7976931348623157e308"),
        (trap, "touchdown_sink_rate_mps", "NaN"),
        (trap, "touchdown_airspeed_mps", "-1"),
        (trap, "end_time_s", "inf"),
        (trap, "end_time_s", ""),
        (trap, "time_on_stops_pct", "100.5"),
        (trap, "deck_within_limits_pct", "100.5"),
        (trap, "deck_within_limits_pct", "-0.1"),
        (trap, "deck_within_limits_pct", "NaN"),
        (trap, "deck_within_limits_pct", ""),
        // The commit point's probabilities (issue 45, item 1): within [0, 1], finite,
        // the ramp strike's and the hard landing's both or neither.
        (committed, "commit_ramp_strike_probability", "1.5"),
        (committed, "commit_hard_landing_probability", "-1e-3"),
        (committed, "commit_ramp_strike_probability", "NaN"),
        (committed, "commit_hard_landing_probability", ""),
        (committed, "commit_off_centre_probability", "inf"),
        // The clearance the ramp strike's probability is taken on and its σ: finite,
        // the σ not negative, both with the probabilities.
        (committed, "commit_ramp_clearance_m", "NaN"),
        (committed, "commit_ramp_clearance_sigma_m", "-0.1"),
        (committed, "commit_ramp_clearance_sigma_m", ""),
        (trap, "sea_state_scale", "0"),
        (trap, "reason", "edited"),
        (not_trap, "reason", ""),
    ];
    // (row, column, new value, the column the error names): an outcome without a wire on
    // a row that has one is refused at the wire.
    let named_otherwise: &[(usize, &str, &str, &str)] = &[
        (trap, "outcome", "invalid", "wire"),
        (trap, "outcome", "ramp_strike", "wire"),
    ];
    let same_column = cases
        .iter()
        .map(|&(row, column, value)| (row, column, value, column));
    for (row, column, value, named) in same_column.chain(named_otherwise.iter().copied()) {
        let edited = edit_csv(&text, row, column, value);
        let error = parse_runs_csv("s0/runs.csv", &edited).unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains(&format!("`{named}`")) && message.starts_with("s0/runs.csv"),
            "{column} = {value:?}: {message}"
        );
        if let MergeError::BadRow { row: found, .. } = error {
            assert_eq!(found, row as u64, "{message}");
        }
    }
    // An off-centre probability without the commit point's others; probabilities for a
    // run that never flew.
    const BOTH: [&str; 2] = [
        "commit_ramp_strike_probability",
        "commit_hard_landing_probability",
    ];
    let set_both = |row: usize, value: &str| {
        BOTH.iter()
            .fold(text.clone(), |t, column| edit_csv(&t, row, column, value))
    };
    let edited = set_both(committed, "");
    let edited = edit_csv(&edited, committed, "commit_off_centre_probability", "0.5");
    let error = parse_runs_csv("s0/runs.csv", &edited)
        .unwrap_err()
        .to_string();
    assert!(error.contains("`commit_off_centre_probability`"), "{error}");
    if let Some(never) = shards[0].table.rows.iter().position(|r| !r.flown()) {
        let error = parse_runs_csv("s0/runs.csv", &set_both(never + 1, "0.1")).unwrap_err();
        let error = error.to_string();
        assert!(
            error.contains("`commit_ramp_strike_probability`"),
            "{error}"
        );
    }
    // Numbers a field's type cannot hold, named by column and line.
    for (column, value) in [("wire", "300"), ("run_index", "-1"), ("seed", "x")] {
        let error = parse_runs_csv("r", &edit_csv(&text, trap, column, value)).unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains(&format!("line {}", trap + 1)) && message.contains(column),
            "{message}"
        );
    }
}

/// Regression (issue 28, D8): a missing column, a row cut short, a file cut inside a
/// row's text were merged.
#[test]
fn regression_runs_csv_text_must_be_a_whole_campaign_table() {
    let shards = flown_shards();
    let text = rows_csv(&shards[0].table.rows);
    // A column removed (from the header and every row): the last, the σ of the
    // clearance at the commit point (since issue 45, item 1).
    let without_last: String = text
        .lines()
        .map(|line| line.rsplit_once(',').unwrap().0.to_owned() + "\n")
        .collect();
    let error = parse_runs_csv("r", &without_last).unwrap_err();
    assert!(
        error
            .to_string()
            .contains("`commit_ramp_clearance_sigma_m` is missing"),
        "{error}"
    );
    let error = parse_runs_csv("r", &text.replacen("wire,", "wires,", 1)).unwrap_err();
    assert!(error.to_string().contains("`wires`"), "{error}");
    assert!(parse_runs_csv("r", "").is_err());
    // Cut anywhere inside the last row: refused (never a shorter valid table).
    let last_line_start = text.trim_end().rfind('\n').unwrap() + 1;
    for cut in last_line_start + 1..text.len() {
        let error = parse_runs_csv("r", &text[..cut]);
        assert!(error.is_err(), "cut at byte {cut} was accepted");
    }
    // A row with a field less: the first row's last.
    let (header_line, rows) = text.split_once('\n').unwrap();
    let (first_row, rest) = rows.split_once('\n').unwrap();
    let short = format!(
        "{header_line}\n{}\n{rest}",
        first_row.rsplit_once(',').unwrap().0
    );
    assert!(parse_runs_csv("r", &short).is_err());
    // A quote that never closes swallows the rest of the file.
    let open_quote = text.replacen(",O-PD,", ",\"O-PD,", 1);
    assert!(parse_runs_csv("r", &open_quote).is_err());
    let header: Vec<&str> = RUN_COLUMNS.into_iter().chain(LSO_RUN_COLUMNS).collect();
    assert_eq!(header.join(","), text.lines().next().unwrap());
}

/// Regression (issue 28, D1 and D4): a huge shard count made a merge allocate petabytes;
/// a shard with no controllers and no rows made the report panic; zero runs was merged.
#[test]
fn regression_shard_identities_beyond_the_limits_are_refused() {
    let shards = flown_shards();
    assert!(matches!(
        Shard::new(0, 100_000_000_000_000),
        Err(ShardError::TooMany { .. })
    ));
    let error = merge_after(&shards, |s| {
        for shard in s.iter_mut() {
            shard.identity.controllers.clear();
            shard.table.rows.clear();
        }
    });
    assert!(error.to_string().contains("`controllers` is []"), "{error}");
    let error = merge_after(&shards, |s| {
        for shard in s.iter_mut() {
            shard.identity.requested_runs = 0;
        }
    });
    assert!(
        error.to_string().contains("`requested_runs` is 0"),
        "{error}"
    );
    let error = merge_after(&shards, |s| s[0].identity.requested_runs = MAX_RUNS + 1);
    assert!(
        error.to_string().contains("`requested_runs` is 100001"),
        "{error}"
    );
    let error = merge_after(&shards, |s| {
        let label = s[0].identity.controllers[0].clone();
        s[0].identity.controllers.push(label);
    });
    assert!(error.to_string().contains("listed twice"), "{error}");
    // More shards than runs: one of them could never be flown.
    let error = merge_after(&shards, |s| {
        s[0].identity.shard = Shard::new(0, s[0].identity.requested_runs + 1).unwrap();
    });
    assert!(error.to_string().contains("at most"), "{error}");
    // The most shards a merge can be told of: the message lists ten and counts the rest.
    let error = merge_after(&shards, |s| {
        for shard in s.iter_mut() {
            shard.identity.requested_runs = MAX_RUNS;
            shard.identity.shard = Shard::new(shard.identity.shard.index(), MAX_RUNS).unwrap();
        }
    });
    let message = error.to_string();
    assert!(message.contains("and 99987 more"), "{message}");
    assert!(message.len() < 300, "{message}");
}
