//! `deckland aircraft`: the F/A-18's definition file, and checking a definition file.

use anyhow::{Context, Result};
use clap::Args;
use deckland::scenario::{
    load_aircraft_definition, read_text_file, FA18_DEFINITION_TOML, MAX_AIRCRAFT_FILE_BYTES,
};
use std::path::PathBuf;

/// Options of `deckland aircraft`.
#[derive(Debug, Clone, Args)]
#[group(required = true, multiple = false)]
pub struct AircraftArgs {
    /// Print the F/A-18 that every scenario flies as an aircraft definition file: mass,
    /// inertias, geometry, engines, actuators, hook and the aerodynamic polynomials,
    /// every key commented with its unit, range and source. Redirect it to a file, edit
    /// it, and name it in a scenario as `[aircraft] definition = "FILE"`.
    #[arg(long)]
    pub print_default: bool,
    /// Check an aircraft definition file: every key known, every value of the right
    /// type and range (a scenario that names it also trims it and designs its laws:
    /// `deckland scenario --check`).
    #[arg(long, value_name = "FILE")]
    pub check: Option<PathBuf>,
}

/// Runs `deckland aircraft`.
pub fn run(args: &AircraftArgs) -> Result<()> {
    if let Some(path) = &args.check {
        let text = read_text_file(path, MAX_AIRCRAFT_FILE_BYTES, "aircraft definition")
            .with_context(|| format!("cannot read the aircraft definition {}", path.display()))?;
        let definition = load_aircraft_definition(&text, &path.display().to_string())?;
        outln!(
            "{}: valid aircraft definition: {}, {} kg",
            path.display(),
            definition.name,
            definition.parameters.mass_kg
        )?;
    } else {
        out!("{FA18_DEFINITION_TOML}")?;
    }
    Ok(())
}
