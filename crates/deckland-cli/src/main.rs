//! The `deckland` command line.

mod commands;
mod output;
mod plot;

use anyhow::Result;
use clap::{Parser, Subcommand};

/// Simulate and control the automatic landing of an unmanned F/A-18 on a moving carrier.
#[derive(Debug, Parser)]
#[command(name = "deckland", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Simulate the ship motion and the wind alone; write a CSV and plots (paper Fig. 7, 8).
    Environment(commands::environment::EnvironmentArgs),
}

fn main() -> Result<()> {
    let cli = Cli::parse();
    match cli.command {
        Command::Environment(args) => commands::environment::run(&args),
    }
}
