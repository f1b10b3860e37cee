//! `deckland run`: one approach of a scenario file, with the outputs of `land`.
//!
//! Flies the file's scenario as it is (its `seed`; the `[dispersion]` section is for
//! campaigns and is ignored) and writes `scenario.toml`, `approach.csv`, `summary.json`
//! and the plots, like `deckland land`.

use super::common::load_scenario_file;
use super::land::fly_and_write;
use crate::output::OutputDir;
use anyhow::Result;
use clap::Args;
use deckland::monte_carlo::controller_label;
use std::path::PathBuf;

/// Options of `deckland run`.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Scenario file (TOML; `deckland scenario --print-default` writes a template).
    pub scenario: PathBuf,
    /// Output folder (default: a new `runs/run-<UTC time>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Overwrite results in an existing `--out` folder.
    #[arg(long)]
    pub force: bool,
    /// Print the summary as one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
}

/// Runs `deckland run`.
pub fn run(args: &RunArgs) -> Result<()> {
    let scenario = load_scenario_file(&args.scenario)?;
    let output = OutputDir::prepare("run", args.out.as_deref(), args.force)?;
    let name = args.scenario.file_name().map_or_else(
        || args.scenario.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    fly_and_write(
        &scenario,
        &output,
        controller_label(&scenario.control.pitch),
        &name,
        args.json,
    )?;
    Ok(())
}
