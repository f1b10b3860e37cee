//! `deckland scenario`: the commented default scenario file, and checking a file.

use super::common::load_scenario_file;
use anyhow::Result;
use clap::Args;
use deckland::scenario::DEFAULT_SCENARIO_TOML;
use std::path::PathBuf;

/// Options of `deckland scenario`.
#[derive(Debug, Clone, Args)]
#[group(required = true, multiple = false)]
pub struct ScenarioArgs {
    /// Print the complete default scenario as TOML, every key commented with its unit,
    /// meaning and allowed range (redirect it to a file and edit it).
    #[arg(long)]
    pub print_default: bool,
    /// Check a scenario file: every key known, every value of the right type and range.
    #[arg(long, value_name = "FILE")]
    pub check: Option<PathBuf>,
}

/// Runs `deckland scenario`.
pub fn run(args: &ScenarioArgs) -> Result<()> {
    if let Some(path) = &args.check {
        load_scenario_file(path)?;
        println!("{}: valid scenario", path.display());
    } else {
        print!("{DEFAULT_SCENARIO_TOML}");
    }
    Ok(())
}
