//! Options shared by the simulation commands (`step`, `land`, `sink`) and the loading of
//! scenario files (`run`, `campaign`).

use clap::ValueEnum;
use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::scenario::Scenario;

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
    /// Overwrite results in an existing `--out` folder.
    #[arg(long)]
    pub force: bool,
    /// Print the result as one JSON document instead of text.
    #[arg(long)]
    pub json: bool,
}
