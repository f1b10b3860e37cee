//! The `deckland` command line: trim, linearise, simulate and plot carrier landings.
//!
//! The binary's whole work is [`main`]; the library exists so that another front end
//! (the Python package) writes the same result folders, plots and reports through
//! [`folders`].

#[macro_use]
mod output;
mod commands;
pub mod folders;
mod html;
mod interrupt;
mod parquet;
mod plot;
mod progress;

use anyhow::Result;
use clap::{Parser, Subcommand};
use output::StdoutError;
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
    Trim(commands::flight_condition::TrimArgs),
    /// Linearise about a trim point (paper Eq. 14 form): A, B, eigenvalues and modes.
    Linearize(commands::flight_condition::TrimArgs),
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
    /// Print the F/A-18 as a commented aircraft definition file, or check one.
    Aircraft(commands::aircraft::AircraftArgs),
    /// Fly one approach of a scenario file: CSV, summary and plots, as `land`.
    Run(commands::run::RunArgs),
    /// Fly N approaches of a scenario file in parallel (Monte Carlo): rates with
    /// confidence intervals, touchdown statistics, runs.csv and plots.
    Campaign(commands::campaign::CampaignArgs),
    /// Merge the shard folders of a campaign (`campaign --shard K/M`) into the campaign
    /// folder of the campaign flown whole.
    Merge(commands::merge::MergeArgs),
    /// Estimate the probability per approach of a catastrophe (ramp strike, hard
    /// landing, …) down to one in a million, by splitting: summary, levels, the flights.
    Rare(commands::rare::RareArgs),
}

/// The figure options of a command that writes figures.
fn figure_args(command: &Command) -> Option<&plot::FigureArgs> {
    match command {
        Command::Land(args) => Some(&args.written.folder.figures),
        Command::Sink(args) => Some(&args.folder.figures),
        Command::Environment(args) => Some(&args.figures),
        Command::Step(args) => Some(&args.folder.figures),
        Command::Reproduce(args) => Some(&args.figures),
        Command::Run(args) => Some(&args.written.folder.figures),
        Command::Campaign(args) => Some(&args.figures),
        Command::Merge(args) => Some(&args.figures),
        Command::Rare(args) => Some(&args.figures),
        Command::Trim(_) | Command::Linearize(_) | Command::Scenario(_) | Command::Aircraft(_) => {
            None
        }
    }
}

fn run(cli: &Cli) -> Result<()> {
    // Every figure the command writes is sized by its options, checked before anything
    // is flown or written.
    if let Some(figures) = figure_args(&cli.command) {
        plot::options::set(figures.options()?);
    }
    match &cli.command {
        // The model's own command, from the CLI's registry of the models.
        Command::Trim(args) => (commands::models::commands(args.model).trim)(args),
        Command::Linearize(args) => (commands::models::commands(args.model).linearize)(args),
        Command::Environment(args) => commands::environment::run(args),
        Command::Land(args) => commands::land::run(args),
        Command::Sink(args) => commands::sink::run(args),
        Command::Step(args) => commands::step::run(args),
        Command::Reproduce(args) => commands::reproduce::run(args),
        Command::Scenario(args) => commands::scenario::run(args),
        Command::Aircraft(args) => commands::aircraft::run(args),
        Command::Run(args) => commands::run::run(args),
        Command::Campaign(args) => commands::campaign::run(args),
        Command::Merge(args) => commands::merge::run(args),
        Command::Rare(args) => commands::rare::run(args),
    }
}

/// The command line: parses the arguments, runs the command and reports its error.
pub fn main() -> ExitCode {
    let cli = Cli::parse();
    interrupt::install();
    match run(&cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(error) => {
            // A reader that went away (`deckland trim | head -1`) ends the command
            // quietly, as Unix tools do; results already written to files stay.
            if error.chain().any(|cause| {
                cause
                    .downcast_ref()
                    .is_some_and(StdoutError::is_closed_pipe)
            }) {
                return ExitCode::SUCCESS;
            }
            warnln!("error: {}", error_chain(&error));
            ExitCode::FAILURE
        }
    }
}

/// The error and its causes on one line, without a backtrace; a cause whose words the
/// message before it already holds (a library error that shows its source) is left out,
/// so nothing is printed twice (what the command line prints after `error: `).
pub fn error_chain(error: &anyhow::Error) -> String {
    let mut line = String::new();
    for cause in error.chain() {
        let text = cause.to_string();
        if !line.contains(&text) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&text);
        }
    }
    line
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression (issue 14, class 8): a trim error was printed twice, once by the
    /// set-up error that shows its source and once as that source.
    #[test]
    fn regression_a_cause_already_in_the_message_is_printed_once() {
        let inner = std::io::Error::other("trim needs total thrust beyond the limit");
        let outer = anyhow::Error::new(inner)
            .context("cannot trim: trim needs total thrust beyond the limit")
            .context("cannot set up the approach");
        assert_eq!(
            error_chain(&outer),
            "cannot set up the approach: cannot trim: trim needs total thrust beyond the limit"
        );
    }
}
