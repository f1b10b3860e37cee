//! The `deckland` command line: trim, linearise, simulate and plot carrier landings.

mod commands;
mod html;
mod output;
mod plot;

use anyhow::Result;
use clap::{Parser, Subcommand};
use std::process::ExitCode;

/// Simulate and control the automatic landing of an unmanned F/A-18 on a moving carrier.
#[derive(Debug, Parser)]
#[command(name = "deckland", version, about)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Trim the F/A-18 for steady straight flight at a given airspeed and flight-path angle.
    Trim(commands::trim::TrimArgs),
    /// Linearise about a trim point (paper Eq. 14 form): A, B, eigenvalues and modes.
    Linearize(commands::trim::TrimArgs),
    /// Fly one approach to the moving deck (the main job): CSV, summary and plots.
    Land(commands::land::LandArgs),
    /// Track a constant commanded sink rate from level flight (paper Fig. 13).
    Sink(commands::sink::SinkArgs),
    /// Simulate the ship motion and the wind alone; write a CSV and plots (paper Fig. 7, 8).
    Environment(commands::environment::EnvironmentArgs),
    /// Pitch-attitude step with the O-PD and/or PID controller: metrics, CSV and plots
    /// (paper Fig. 10–12).
    Step(commands::step::StepArgs),
    /// Regenerate the paper's figures and a report of its numbers beside ours (REPORT.md).
    Reproduce(commands::reproduce::ReproduceArgs),
    /// Print the commented default scenario file, or check a scenario file.
    Scenario(commands::scenario::ScenarioArgs),
    /// Fly one approach of a scenario file: CSV, summary and plots, as `land`.
    Run(commands::run::RunArgs),
    /// Fly N approaches of a scenario file in parallel (Monte Carlo): rates with
    /// confidence intervals, touchdown statistics, runs.csv and plots.
    Campaign(commands::campaign::CampaignArgs),
}

fn run(cli: &Cli) -> Result<()> {
    match &cli.command {
        Command::Trim(args) => commands::trim::run(args),
        Command::Linearize(args) => commands::linearize::run(args),
        Command::Environment(args) => commands::environment::run(args),
        Command::Land(args) => commands::land::run(args),
        Command::Sink(args) => commands::sink::run(args),
        Command::Step(args) => commands::step::run(args),
        Command::Reproduce(args) => commands::reproduce::run(args),
        Command::Scenario(args) => commands::scenario::run(args),
        Command::Run(args) => commands::run::run(args),
        Command::Campaign(args) => commands::campaign::run(args),
    }
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // `{:#}` prints the whole chain of causes on one line, without a backtrace.
            eprintln!("error: {error:#}");
            ExitCode::FAILURE
        }
    }
}
