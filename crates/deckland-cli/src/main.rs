//! The `deckland` command line.

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
enum Command {}

fn main() -> Result<()> {
    let cli = Cli::parse();
    match cli.command {}
}
