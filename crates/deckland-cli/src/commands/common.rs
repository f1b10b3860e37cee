//! Options shared by the simulation commands (`step`, `land`, `sink`) and the loading of
//! scenario files (`run`, `campaign`).

use crate::output::OutputDir;
use anyhow::{bail, Context};
use clap::ValueEnum;
use deckland::control::pitch::{ObserverPdParameters, PidParameters, PitchControllerParameters};
use deckland::scenario::{HardwareSet, Scenario, MAX_SEED};
use deckland::simulation::Simulation;

/// Which hardware flies (docs/model.md §2.6).
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HardwareChoice {
    /// A real F/A-18: 40 °/s stabilator, 80 Hz flight computer, controllers designed for it.
    Realistic,
    /// What the paper simulated: an ideal actuator and the paper's gains.
    Paper,
}

impl HardwareChoice {
    /// The library's hardware set.
    pub fn set(self) -> HardwareSet {
        match self {
            Self::Realistic => HardwareSet::Realistic,
            Self::Paper => HardwareSet::Paper,
        }
    }
}

/// Prints the document `document` makes as pretty JSON when `json` is set, else what
/// `table` prints: the two forms of a command's result on standard output.
pub fn print_json_or<T: serde::Serialize>(
    json: bool,
    document: impl FnOnce() -> T,
    table: impl FnOnce() -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    if json {
        outln!("{}", serde_json::to_string_pretty(&document())?)?;
    } else {
        table()?;
    }
    Ok(())
}

/// The one seed domain of every command: 0 to 2⁶³ − 1, what a scenario file can hold
/// (TOML integers are signed 64-bit), checked by clap before anything is flown or
/// written; `--seed 9223372036854775808` is refused naming the option.
pub fn seed_parser() -> fn(&str) -> Result<u64, String> {
    parse_seed
}

/// The range of a seed in words, as every seed error says it.
pub const SEED_RANGE: &str = "an integer from 0 to 2⁶³ − 1 = 9223372036854775807";

/// A seed from the command line: an integer from 0 to [`MAX_SEED`].
fn parse_seed(text: &str) -> Result<u64, String> {
    text.parse::<u64>()
        .ok()
        .filter(|seed| *seed <= MAX_SEED)
        .ok_or_else(|| format!("expected {SEED_RANGE}"))
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
    /// PID (paper Eq. 37).
    Pid,
}

impl ControllerChoice {
    /// The controller's parameters: `base`'s own when it flies this controller, else the
    /// defaults of `base`'s hardware set.
    pub fn parameters_for(self, base: &Scenario) -> PitchControllerParameters {
        let paper = base.hardware == HardwareSet::Paper;
        match (self, base.control.pitch) {
            (Self::Opd, own @ PitchControllerParameters::ObserverPd(_))
            | (Self::Pid, own @ PitchControllerParameters::Pid(_)) => own,
            (Self::Opd, _) if paper => {
                PitchControllerParameters::ObserverPd(ObserverPdParameters::paper())
            }
            (Self::Opd, _) => PitchControllerParameters::default(),
            (Self::Pid, _) if paper => PitchControllerParameters::Pid(PidParameters::paper()),
            (Self::Pid, _) => PitchControllerParameters::Pid(PidParameters::default()),
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

    /// The default scenario of `hardware` in these conditions, with `seed`.
    pub fn scenario(self, hardware: HardwareSet, seed: u64) -> Scenario {
        self.conditions().apply(hardware.scenario(), seed)
    }

    /// The name as written in files.
    pub fn name(self) -> &'static str {
        self.conditions().name()
    }
}

/// The scenario a fixed-length test (`step`, `sink`) flies its mission with: a hardware
/// set's default, or a scenario file's aircraft, environment and controllers.
#[derive(Debug, Clone, clap::Args)]
pub struct BaseScenarioArgs {
    /// Hardware of the default scenario: `realistic` (40 °/s stabilator, 80 Hz flight
    /// computer, controllers designed for them) or `paper` (ideal actuator, paper gains).
    /// A pitch step and `sink` fly it on the longitudinal 3-DOF aircraft behind a
    /// stationary ship, the longitudinal laws' design check.
    #[arg(long, value_enum, default_value = "realistic")]
    pub hardware: HardwareChoice,
    /// Fly a scenario file's aircraft, environment and controllers instead of a default
    /// scenario (its mission is replaced by this command's; `--hardware` is then unused).
    /// The file's `[aircraft] model` flies, the realistic default `6dof` if it leaves the
    /// key out: write `model = "3dof"` for the longitudinal aircraft.
    #[arg(long, value_name = "FILE", conflicts_with = "hardware")]
    pub scenario: Option<std::path::PathBuf>,
}

impl BaseScenarioArgs {
    /// The scenario file's, or the hardware set's default scenario.
    pub fn base(&self) -> anyhow::Result<Scenario> {
        match &self.scenario {
            Some(path) => load_scenario_file(path),
            None => Ok(self.hardware.set().scenario()),
        }
    }

    /// The scenario file's, or the hardware set's default scenario flown by the 3-DOF
    /// aircraft behind a stationary ship ([`Scenario::longitudinal`]): what the
    /// longitudinal laws' design checks (a pitch step, `sink`) fly.
    pub fn longitudinal_base(&self) -> anyhow::Result<Scenario> {
        match &self.scenario {
            Some(path) => load_scenario_file(path),
            None => Ok(self.hardware.set().scenario().longitudinal()),
        }
    }
}

/// Reads and checks the scenario file at `path`; a bad file's error names the file, the
/// line and the field.
pub fn load_scenario_file(path: &std::path::Path) -> anyhow::Result<Scenario> {
    use anyhow::Context;
    let text = deckland::scenario::read_text_file(
        path,
        deckland::scenario::MAX_SCENARIO_FILE_BYTES,
        "scenario file",
    )
    .with_context(|| format!("cannot read the scenario file {}", path.display()))?;
    // An aircraft definition the file names is read relative to the file's folder.
    let folder = path.parent().unwrap_or(std::path::Path::new(""));
    Ok(deckland::scenario::load_scenario_in(
        &text,
        &path.display().to_string(),
        folder,
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

/// What a command that writes a folder with plots takes: the figures' size and the
/// output folder's options.
#[derive(Debug, Clone, clap::Args)]
pub struct FolderArgs {
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub figures: crate::plot::FigureArgs,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
}

impl FolderArgs {
    /// The output folder of `command`, made ready ([`OutputDir::prepare`]).
    pub fn prepare(&self, command: &str) -> anyhow::Result<OutputDir> {
        OutputDir::prepare(command, self.output.out.as_deref(), self.output.force)
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn seeds_are_0_to_2_63_minus_1_and_errors_say_so() {
        let parse = super::seed_parser();
        assert_eq!(parse("0"), Ok(0));
        assert_eq!(parse("9223372036854775807"), Ok((1 << 63) - 1));
        for bad in ["-1", "9223372036854775808", "abc", ""] {
            let error = parse(bad).expect_err(bad);
            assert!(error.contains("0 to 2⁶³ − 1"), "{bad}: {error}");
        }
    }
}
