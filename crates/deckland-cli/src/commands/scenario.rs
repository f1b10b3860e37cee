//! `deckland scenario`: the commented default scenario file, and checking a file.

use super::common::{check_set_up, load_scenario_file};
use anyhow::{Context, Result};
use clap::Args;
use deckland::scenario::{Mission, DEFAULT_SCENARIO_TOML};
use std::path::PathBuf;

/// Options of `deckland scenario`.
#[derive(Debug, Clone, Args)]
#[group(required = true, multiple = false)]
pub struct ScenarioArgs {
    /// Print the complete default scenario as TOML, every key commented with its unit,
    /// meaning and allowed range (redirect it to a file and edit it).
    #[arg(long)]
    pub print_default: bool,
    /// Check a scenario file: every key known, every value of the right type and range,
    /// and the run set up as it would be flown (trim, linearisation, controller design),
    /// so that a file it accepts can be flown.
    #[arg(long, value_name = "FILE")]
    pub check: Option<PathBuf>,
}

/// Runs `deckland scenario`.
pub fn run(args: &ScenarioArgs) -> Result<()> {
    if let Some(path) = &args.check {
        let scenario = load_scenario_file(path)?;
        check_set_up(&scenario)
            .with_context(|| format!("{}: the scenario cannot be flown", path.display()))?;
        let mission = match scenario.mission {
            Mission::Approach => "an approach, for `deckland run` and `deckland campaign`",
            Mission::PitchStep { .. } => {
                "a pitch step (`deckland run` and `campaign` fly approaches only)"
            }
            Mission::SinkRate { .. } => {
                "a sink-rate test (`deckland run` and `campaign` fly approaches only)"
            }
        };
        outln!(
            "{}: valid scenario, set up and trimmed: {mission}",
            path.display()
        )?;
    } else {
        out!("{DEFAULT_SCENARIO_TOML}")?;
    }
    Ok(())
}
