//! `deckland scenario --check` refuses a crosswind beyond what the 3-D approach accepts
//! to crab into (`environment.wind.max_crab_deg`), naming both keys, and accepts the
//! shipped 5 m/s crosswind.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{assert_refused, assert_success, deckland, scratch};

/// `scenarios/crosswind.toml` with `crosswind_mps` set to `crosswind` and, when given,
/// `max_crab_deg` to `limit`.
fn crosswind_file(dir: &std::path::Path, crosswind: f64, limit: Option<f64>) -> String {
    let shipped = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../scenarios/crosswind.toml"),
    )
    .unwrap();
    let mut text: String = shipped
        .lines()
        .map(|line| {
            if line.starts_with("crosswind_mps") {
                let mut line = format!("crosswind_mps = {crosswind:?}");
                if let Some(limit) = limit {
                    line.push_str(&format!("\nmax_crab_deg = {limit:?}"));
                }
                line
            } else {
                line.to_owned()
            }
        })
        .collect::<Vec<_>>()
        .join("\n");
    text.push('\n');
    let path = dir.join(format!("crosswind-{crosswind}-{limit:?}.toml"));
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_owned()
}

#[test]
fn a_crosswind_beyond_the_crab_limit_is_refused_at_check_naming_both_keys() {
    let dir = scratch("crab-limit");
    std::fs::create_dir_all(&dir).unwrap();
    // 5 m/s across at 69.1 m/s: a crab of asin(5/69.1) = 4.1°, within the 6° default.
    assert_success(&deckland([
        "scenario",
        "--check",
        &crosswind_file(&dir, 5.0, None),
    ]));
    // 10 m/s (the key's largest): asin(10/69.1) = 8.3° on the horizontal airspeed
    // 69.1·cos 3.5°, 8.35°: beyond 6°.
    let refused = deckland(["scenario", "--check", &crosswind_file(&dir, 10.0, None)]);
    assert_refused(
        &refused,
        1,
        &[
            "environment.wind.crosswind_mps",
            "= 10",
            "environment.wind.max_crab_deg` = 6°",
            "approach.airspeed_mps",
            "crab of 8.",
        ],
    );
    // From the left as from the right.
    let left = deckland(["scenario", "--check", &crosswind_file(&dir, -10.0, None)]);
    assert_refused(&left, 1, &["crosswind_mps", "max_crab_deg"]);
    // A raised limit flies it.
    assert_success(&deckland([
        "scenario",
        "--check",
        &crosswind_file(&dir, 10.0, Some(9.0)),
    ]));
    // The limit's own range.
    let zero = deckland(["scenario", "--check", &crosswind_file(&dir, 5.0, Some(0.0))]);
    assert_refused(&zero, 1, &["environment.wind.max_crab_deg", "0"]);
    let _ = std::fs::remove_dir_all(&dir);
}
