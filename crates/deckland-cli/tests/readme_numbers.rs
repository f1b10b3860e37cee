//! The numbers the README states in prose are the binary's (issue 46, item 3): the hero
//! images' captions against `deckland land --seed 1` (the images themselves come from
//! docs/images/hero.sh, which flies the same command), and the `--compare` paragraph
//! against the campaign table above it (which docs_match_the_binary.rs holds against the
//! binary). Each number is compared as the README writes it: the binary's value rounded
//! to the caption's decimals.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, scratch, succeeded_json};
use serde_json::Value;

fn readme() -> String {
    std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../../README.md")).unwrap()
}

/// The caption (alt text) of the README's image `file`.
fn caption(readme: &str, file: &str) -> String {
    let end = readme
        .find(&format!("]({file})"))
        .unwrap_or_else(|| panic!("the README shows {file}"));
    let start = readme[..end].rfind("![").unwrap();
    readme[start + 2..end].to_owned()
}

/// The number written between `before` and `after` in `text` (the first such place).
fn number_between(text: &str, before: &str, after: &str) -> String {
    let start = text
        .find(before)
        .unwrap_or_else(|| panic!("{before:?} in {text:?}"))
        + before.len();
    let end = start
        + text[start..]
            .find(after)
            .unwrap_or_else(|| panic!("{after:?} after {before:?}"));
    text[start..end].trim().to_owned()
}

/// `value` written with as many decimals as `written` has.
fn as_written(value: f64, written: &str) -> String {
    let decimals = written.split('.').nth(1).map_or(0, str::len);
    format!("{value:.decimals$}")
}

fn assert_written(written: &str, value: f64, what: &str) {
    assert_eq!(
        written,
        as_written(value, written),
        "the README says {what} is {written}; the binary gives {value}"
    );
}

/// The value of `key = …` in the printed default scenario.
fn default_value(key: &str) -> f64 {
    let out = deckland(["scenario", "--print-default"]);
    let text = String::from_utf8(out.stdout).unwrap();
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with(&format!("{key} ")))
        .unwrap_or_else(|| panic!("{key} in the printed default"));
    line.split('=')
        .nth(1)
        .unwrap()
        .split('#')
        .next()
        .unwrap()
        .trim()
        .parse()
        .unwrap()
}

#[test]
fn the_hero_captions_are_what_land_flies() {
    let readme = readme();
    let approach = caption(&readme, "docs/images/approach.png");
    let plan = caption(&readme, "docs/images/plan-view.png");
    let seed = number_between(&approach, "seed ", ")");
    let out = scratch("hero");
    let run = deckland([
        "land",
        "--seed",
        &seed,
        "--json",
        "--no-plots",
        "--out",
        out.to_str().unwrap(),
    ]);
    let summary = succeeded_json(&run);
    let touchdown = &summary["touchdown"];
    let number = |v: &Value| v.as_f64().unwrap();

    assert_written(
        &number_between(&approach, "crosses the ramp ", " m above it"),
        number(&summary["ramp_clearance_m"]),
        "the hook's height over the ramp",
    );
    assert_written(
        &number_between(&approach, "touches down ", " m beyond the aim point"),
        number(&touchdown["distance_from_aim_m"]),
        "the touchdown point beyond the aim point",
    );
    assert_written(
        &number_between(&approach, "the aim point at ", " m/s"),
        number(&touchdown["sink_rate_mps"]),
        "the touchdown sink rate",
    );
    assert_eq!(summary["outcome"], "trap");
    let wire = approach.split("a trap on wire ").nth(1).unwrap();
    assert_eq!(wire.trim(), summary["wire"].to_string(), "the wire");

    // The centreline drifts at V·sin δ, the ship's speed across the final bearing.
    let drift =
        default_value("forward_speed_mps") * default_value("deck_angle_deg").to_radians().sin();
    assert_written(
        &number_between(&plan, "drifts to the right at ", " m/s"),
        drift,
        "the centreline's drift",
    );
    assert_written(
        &number_between(&plan, "the hook touches down ", " m to the right of it"),
        number(&touchdown["lateral"]["offset_m"]),
        "the touchdown's offset right of the centreline",
    );
    let _ = std::fs::remove_dir_all(out);
}

#[test]
fn the_compare_paragraph_says_what_the_table_above_it_shows() {
    let readme = readme();
    let start = readme.find("**Paired differences.**").unwrap();
    let paragraph = readme[start..start + readme[start..].find("\n\n").unwrap()]
        .split_whitespace()
        .collect::<Vec<_>>()
        .join(" ");
    // What it says of the example: from "Above," on.
    let paragraph = &paragraph[paragraph.find("Above,").unwrap()..];
    let table_end = readme[..start].rfind("```").unwrap();
    let table = &readme[readme[..table_end].rfind("```text").unwrap()..table_end];
    let table_line = |prefix: &str| {
        table
            .lines()
            .find(|l| l.trim_start().starts_with(prefix))
            .unwrap_or_else(|| panic!("{prefix:?} in the campaign table"))
            .to_owned()
    };

    // The paragraph says `expected` between `before` and `after`.
    let says = |before: &str, after: &str, expected: &str| {
        assert_eq!(
            number_between(paragraph, before, after),
            expected,
            "{paragraph}"
        );
    };

    let differs = table_line("paired differences");
    let pairs = number_between(&differs, "on the same seed: ", " pairs");
    let differ_in = differs.rsplit(' ').next().unwrap().to_owned();
    says("differs in ", " of the ", &differ_in);
    says(" of the ", " runs", &pairs);

    let touchdown = table_line("touchdown from the aim point (m)");
    let max_apart = touchdown.split_whitespace().last().unwrap();
    says("lie up to ", " m apart", max_apart);

    let rms = table_line("elevator rate RMS (deg/s): mean");
    let means: Vec<&str> = rms
        .split("mean ± sd")
        .nth(1)
        .unwrap()
        .split_whitespace()
        .filter(|w| w.parse::<f64>().is_ok())
        .collect();
    let (opd, pid) = (means[0], means[2]);
    says("half as fast (", " against", pid);
    says(" against ", " deg/s", opd);
    let ratio = pid.parse::<f64>().unwrap() / opd.parse::<f64>().unwrap();
    assert!((0.4..0.6).contains(&ratio), "half as fast: {ratio}");
}
