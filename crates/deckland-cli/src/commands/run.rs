//! `deckland run`: one approach of a scenario file, with the outputs of `land`.
//!
//! Flies the file's scenario as it is (its `seed`; the `[dispersion]` section is for
//! campaigns and is ignored unless `--disperse`) and writes `scenario.toml`,
//! `approach.csv`, `summary.json` and the plots, like `deckland land`. The scenario is
//! set up (trimmed) before the output folder is made; a file whose mission is not an
//! approach is refused, not silently flown as one. With a campaign
//! row's seed, `--seed S --disperse` flies exactly that campaign run, with its time series.

use super::common::{check_set_up, load_scenario_file, seed_parser};
use super::land::{fly_and_write, ApproachFolderArgs};
use anyhow::{bail, Result};
use clap::Args;
use deckland::monte_carlo::controller_label;
use deckland::random::RandomStreams;
use deckland::scenario::Mission;
use std::path::PathBuf;

/// Options of `deckland run`.
#[derive(Debug, Clone, Args)]
pub struct RunArgs {
    /// Scenario file (TOML; `deckland scenario --print-default` writes a template).
    pub scenario: PathBuf,
    /// Seed of every random stream, 0 to 2⁶³ − 1 (default: the file's `seed`).
    #[arg(long, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: Option<u64>,
    /// Apply the file's `[dispersion]` section, drawn from the seed as a campaign run
    /// draws it: `--seed` with a `runs.csv` row's seed re-flies that run.
    #[arg(long)]
    pub disperse: bool,
    /// The plots, the replay and the output folder, as `land`'s.
    #[command(flatten)]
    pub written: ApproachFolderArgs,
}

/// Runs `deckland run`.
pub fn run(args: &RunArgs) -> Result<()> {
    let mut scenario = load_scenario_file(&args.scenario)?;
    if !matches!(scenario.mission, Mission::Approach) {
        bail!(
            "{}: `mission.kind` is not \"approach\": `deckland run` and `deckland campaign` \
             fly approaches; `deckland step` and `deckland sink` fly the pitch-step and \
             sink-rate tests",
            args.scenario.display()
        );
    }
    if let Some(seed) = args.seed {
        scenario.seed = seed;
    }
    if args.disperse {
        let draw = scenario
            .dispersion
            .sample(&RandomStreams::new(scenario.seed));
        scenario = draw.apply(&scenario);
    }
    check_set_up(&scenario)?;
    let output = args.written.folder.prepare("run")?;
    let name = args.scenario.file_name().map_or_else(
        || args.scenario.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    fly_and_write(
        &scenario,
        &output,
        controller_label(&scenario.control.pitch),
        &name,
        &args.written,
    )?;
    Ok(())
}
