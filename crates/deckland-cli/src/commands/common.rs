//! Options shared by the simulation commands (`step`, `land`, `sink`) and the loading of
//! scenario files (`run`, `campaign`).

use anyhow::{bail, Context};
use clap::ValueEnum;
use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::scenario::{Scenario, MAX_SEED};
use deckland::simulation::Simulation;

/// The one seed domain of every command: 0 to 2⁶³ − 1, what a scenario file can hold
/// (TOML integers are signed 64-bit), checked by clap before anything is flown or
/// written; `--seed 9223372036854775808` is refused naming the option.
pub fn seed_parser() -> clap::builder::RangedU64ValueParser<u64> {
    clap::value_parser!(u64).range(0..=MAX_SEED)
}

/// Sets `scenario` up as a run would (validation, trim, linearisation, controller
/// design) without flying it: a scenario that passes can be flown.
pub fn check_set_up(scenario: &Scenario) -> anyhow::Result<()> {
    Simulation::new(scenario)
        .map(|_| ())
        .context("cannot set up the scenario")
}

/// Checks `scenario` with the library's ranges and, when the key at fault was set by a
/// command-line option (`options`: dotted path and option), names the option instead
/// of the key: `--epsilon 0.0005 is not allowed: expected …`.
pub fn validate_options(scenario: &Scenario, options: &[(&str, &str)]) -> anyhow::Result<()> {
    let Err(problem) = scenario.validate() else {
        return Ok(());
    };
    match options.iter().find(|(path, _)| *path == problem.path) {
        Some((_, option)) => bail!(
            "{option} {} is not allowed: expected {}",
            problem.value,
            problem.allowed
        ),
        None => Err(problem.into()),
    }
}

/// Which pitch controller flies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum ControllerChoice {
    /// Observer-based PD (paper Eq. 30–36).
    Opd,
    /// PID with the paper's gains (Eq. 37).
    Pid,
}

impl ControllerChoice {
    /// The controller's parameters with their defaults.
    pub fn parameters(self) -> PitchControllerParameters {
        match self {
            Self::Opd => PitchControllerParameters::default(),
            Self::Pid => PitchControllerParameters::Pid(PidParameters::default()),
        }
    }

    /// Short label for tables, legends and file names.
    pub fn label(self) -> &'static str {
        match self {
            Self::Opd => "O-PD",
            Self::Pid => "PID",
        }
    }
}

/// Which disturbances act.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Conditions {
    /// No wind, no sensor noise, no deck motion.
    Ideal,
    /// Wind, air wake, turbulence, sensor noise and deck motion at their defaults.
    Adverse,
}

impl Conditions {
    /// The library's conditions.
    pub fn conditions(self) -> deckland::experiments::Conditions {
        match self {
            Self::Ideal => deckland::experiments::Conditions::Ideal,
            Self::Adverse => deckland::experiments::Conditions::Adverse,
        }
    }

    /// The default scenario in these conditions, with `seed`.
    pub fn scenario(self, seed: u64) -> Scenario {
        self.conditions().apply(Scenario::default(), seed)
    }

    /// The name as written in files.
    pub fn name(self) -> &'static str {
        self.conditions().name()
    }
}

/// Reads and checks the scenario file at `path`; a bad file's error names the file, the
/// line and the field.
pub fn load_scenario_file(path: &std::path::Path) -> anyhow::Result<Scenario> {
    use anyhow::Context;
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read the scenario file {}", path.display()))?;
    Ok(deckland::scenario::load_scenario(
        &text,
        &path.display().to_string(),
    )?)
}

/// Where a command writes its results and how it prints them.
#[derive(Debug, Clone, clap::Args)]
pub struct OutputArgs {
    /// Output folder (default: a new `runs/<command>-<UTC time>`).
    #[arg(long)]
    pub out: Option<std::path::PathBuf>,
    /// Replace the results of an earlier deckland run in the `--out` folder (only the
    /// files that run wrote; other files are left alone).
    #[arg(long)]
    pub force: bool,
    /// Print the result as one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
}
