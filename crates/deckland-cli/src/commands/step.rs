//! `deckland step`: a pitch-attitude step from level trim with the O-PD and/or the PID
//! pitch controller (paper §5, Fig. 10–12): step-response metrics, elevator activity, a
//! CSV of the time series and plots; with `--axis roll|yaw` a bank or sideslip step of
//! the 6-DOF aircraft with the lateral laws ([`lateral`]).

pub(crate) mod flight;
pub(crate) mod lateral;

use std::path::PathBuf;

use anyhow::{anyhow, bail, Result};
use clap::ValueEnum;
use deckland::control::pitch::PitchControllerParameters;
use deckland::experiments::{PitchStep, PITCH_STEP_TIME_S as STEP_TIME_S, SETTLING_BAND_FRACTION};
use deckland::scenario::Mission;
use deckland::simulation::Signals;
use serde::Serialize;

use super::common::{
    seed_parser, validate_options, BaseScenarioArgs, Conditions, ControllerChoice, FolderArgs,
};
pub(crate) use crate::plot::step::figures;
use flight::{controller_parameters, ControllerResult, ControllerRun, StepFlight};

/// Largest |--step-deg| accepted (deg): beyond it the elevator is saturated for most of
/// the transient and the step says little about the controller.
const MAX_STEP_DEG: f64 = 10.0;
/// Longest run accepted (s).
const MAX_SECONDS: f64 = 600.0;
/// Shortest run accepted (s): the step at 1 s plus one second of response.
const MIN_SECONDS: f64 = 2.0;

/// Which pitch controllers fly the step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StepControllers {
    /// Observer-based PD only.
    Opd,
    /// PID only.
    Pid,
    /// Both, one after the other, for comparison (paper Fig. 10–12).
    Both,
}

impl StepControllers {
    pub(crate) fn choices(self) -> Vec<ControllerChoice> {
        match self {
            Self::Opd => vec![ControllerChoice::Opd],
            Self::Pid => vec![ControllerChoice::Pid],
            Self::Both => vec![ControllerChoice::Opd, ControllerChoice::Pid],
        }
    }
}

/// Which axis the step commands.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum StepAxis {
    /// Pitch attitude (the scenario's pitch law; on a hardware set's default the 3-DOF
    /// aircraft behind a stationary ship).
    Pitch,
    /// Bank angle (the 6-DOF aircraft; roll law, the yaw law holding β = 0).
    Roll,
    /// Sideslip (the 6-DOF aircraft; yaw law, the roll law holding φ = 0).
    Yaw,
}

/// Options of `deckland step`.
#[derive(Debug, clap::Args)]
pub struct StepArgs {
    /// The axis stepped: pitch (default), roll or yaw. Roll and yaw fly the 6-DOF
    /// aircraft at the approach trim with the lateral laws (docs/lateral-control.md): the
    /// scenario file's aircraft, airspeed and `[control.roll]`/`[control.yaw]` laws, or the
    /// realistic set's (the paper's set has no lateral axes).
    #[arg(long, value_enum, default_value_t = StepAxis::Pitch)]
    pub(crate) axis: StepAxis,
    /// Which pitch controller(s) fly the step.
    #[arg(long, value_enum, default_value_t = StepControllers::Both)]
    pub(crate) controller: StepControllers,
    /// Ideal (no disturbance) or adverse (wind, air wake, turbulence, sensor noise, deck
    /// motion).
    #[arg(long, value_enum, default_value_t = Conditions::Ideal)]
    pub(crate) conditions: Conditions,
    /// Step (deg), applied at t = 1 s, nonzero: pitch (positive nose-up) |D| <= 10; bank
    /// (positive right wing down) or sideslip (positive wind from the right) |D| <= 30.
    #[arg(
        long = "step-deg",
        default_value_t = 2.0,
        allow_negative_numbers = true
    )]
    pub(crate) step_deg: f64,
    /// Simulated time (s), at least 2 (the step comes at 1 s), at most 600.
    #[arg(long, default_value_t = 6.0, allow_negative_numbers = true)]
    pub(crate) seconds: f64,
    /// Scenario seed of the random streams (matters in adverse conditions), 0 to
    /// 2⁶³ − 1.
    #[arg(long, default_value_t = 1, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub(crate) seed: u64,
    /// O-PD observer bandwidth parameter ε, below 1 and at least 0.006 (so that the
    /// observer, k3/ε rad/s, is resolved by the 1 ms step); default: the hardware set's.
    #[arg(long, allow_negative_numbers = true)]
    pub(crate) epsilon: Option<f64>,
    /// The hardware set, or a scenario file, to fly the step with.
    #[command(flatten)]
    pub base: BaseScenarioArgs,
    /// Figure size, output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub folder: FolderArgs,
}

/// The JSON document of `deckland step --json`.
#[derive(Debug, Serialize)]
struct StepReport {
    conditions: &'static str,
    step_deg: f64,
    seed: u64,
    seconds: f64,
    step_time_s: f64,
    airspeed_mps: f64,
    settling_band_pct: f64,
    epsilon: f64,
    /// The stabilator rate limit in force (deg/s); null when there is none.
    elevator_rate_limit_degps: Option<f64>,
    controllers: Vec<ControllerResult>,
    output_folder: String,
}

fn check_arguments(args: &StepArgs) -> Result<()> {
    if !(args.step_deg.is_finite() && args.step_deg != 0.0 && args.step_deg.abs() <= MAX_STEP_DEG) {
        bail!(
            "--step-deg must be nonzero and lie in [-{MAX_STEP_DEG}, {MAX_STEP_DEG}] deg, got {:?}",
            args.step_deg
        );
    }
    if !(args.seconds.is_finite() && (MIN_SECONDS..=MAX_SECONDS).contains(&args.seconds)) {
        bail!(
            "--seconds must lie in [{MIN_SECONDS}, {MAX_SECONDS}] s (the step comes at \
             {STEP_TIME_S} s), got {:?}",
            args.seconds
        );
    }
    // The rest as the library checks the scenario flown, naming the options.
    let flight = step_flight(args)?;
    for choice in args.controller.choices() {
        let mut scenario = flight.scenario(choice);
        scenario.mission = Mission::pitch_step(
            args.step_deg,
            args.seconds,
            scenario.hardware.pitch_command(),
        );
        validate_options(
            &scenario,
            &[
                ("control.pitch.observer.epsilon", "--epsilon"),
                ("mission.step_deg", "--step-deg"),
                ("mission.duration_s", "--seconds"),
            ],
        )?;
    }
    Ok(())
}

/// The flight of the step `args` ask for.
fn step_flight(args: &StepArgs) -> Result<StepFlight> {
    Ok(StepFlight {
        base: args.base.longitudinal_base()?,
        conditions: args.conditions,
        seed: args.seed,
        step: PitchStep::new(args.step_deg, args.seconds),
        epsilon: args.epsilon,
    })
}

fn csv_bytes(runs: &[ControllerRun]) -> Result<Vec<u8>> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["time_s".to_string()];
    for run in runs {
        let prefix = prefix(run.choice);
        for column in [
            "theta_deg",
            "theta_ref_deg",
            "theta_measured_deg",
            "elevator_deg",
            "elevator_command_deg",
            "disturbance_estimate_radps2",
        ] {
            header.push(format!("{prefix}_{column}"));
        }
    }
    writer.write_record(&header)?;
    let samples: Vec<&[Signals]> = runs.iter().map(|r| r.samples.as_slice()).collect();
    write_sample_rows(
        &mut writer,
        &samples,
        |s| s.time_s,
        6,
        |s, record| {
            record.push(s.theta_rad.to_degrees().to_string());
            record.push(s.theta_ref_rad.to_degrees().to_string());
            record.push(s.theta_measured_rad.to_degrees().to_string());
            record.push(s.elevator_rad.to_degrees().to_string());
            record.push(s.elevator_command_rad.to_degrees().to_string());
            record.push(
                s.disturbance_estimate_radps2
                    .map_or(String::new(), |d| d.to_string()),
            );
        },
    )?;
    writer.into_inner().map_err(|e| anyhow!("{e}"))
}

/// Writes the rows of a CSV of `runs`' samples side by side. Every run ends at the same
/// time unless one diverged: the rows run to the longest, each its time, then each run's
/// `width` cells from `cells`, empty for a run that ended earlier.
pub(super) fn write_sample_rows<S>(
    writer: &mut csv::Writer<Vec<u8>>,
    runs: &[&[S]],
    time_s: impl Fn(&S) -> f64,
    width: usize,
    cells: impl Fn(&S, &mut Vec<String>),
) -> Result<()> {
    let rows = runs.iter().map(|r| r.len()).max().unwrap_or(0);
    let longest = runs.iter().find(|r| r.len() == rows);
    for index in 0..rows {
        let mut record = Vec::with_capacity(1 + width * runs.len());
        record.push(longest.map_or(f64::NAN, |r| time_s(&r[index])).to_string());
        for run in runs {
            match run.get(index) {
                Some(s) => cells(s, &mut record),
                None => record.extend(std::iter::repeat_n(String::new(), width)),
            }
        }
        writer.write_record(&record)?;
    }
    Ok(())
}

/// Column prefix of a controller: `opd` or `pid`.
fn prefix(choice: ControllerChoice) -> &'static str {
    match choice {
        ControllerChoice::Opd => "opd",
        ControllerChoice::Pid => "pid",
    }
}

/// `value` with `digits` decimals and a sign, a true minus for negative values.
fn signed_fixed(value: f64, digits: usize) -> String {
    if value < 0.0 {
        format!("\u{2212}{:.digits$}", -value)
    } else {
        format!("+{value:.digits$}")
    }
}

fn format_option(value: Option<f64>, digits: usize, unit: &str) -> String {
    value.map_or_else(|| "—".to_string(), |v| format!("{v:.digits$} {unit}"))
}

/// A settling time's cell: the time in s with 3 decimals, or "not settled".
fn settling_cell(settled: bool, settling_time_s: Option<f64>) -> String {
    if settled {
        format_option(settling_time_s, 3, "s")
    } else {
        "not settled".to_string()
    }
}

fn print_table(report: &StepReport, written: &[PathBuf]) -> Result<()> {
    outln!(
        "Pitch step {:+}° at t = {} s from level trim ({} m/s), {} conditions, seed {}, \
         {} s, O-PD ε = {}",
        report.step_deg,
        report.step_time_s,
        report.airspeed_mps,
        report.conditions,
        report.seed,
        report.seconds,
        report.epsilon
    )?;
    let reference_s = report
        .controllers
        .first()
        .map_or(0.0, |c| c.reference_duration_s);
    if reference_s > 0.0 {
        outln!(
            "Command: the jerk-limited reference (prefilter) from trim to {:+}° in {reference_s:.3} s",
            report.step_deg
        )?;
    } else {
        outln!("Command: a step (no prefilter)")?;
    }
    let row = controller_columns(&report.controllers, |c| &c.controller, 26, 18)?;
    row("settling time (±2 %)", &|c| {
        settling_cell(c.settled, c.settling_time_s)
    })?;
    if reference_s > 0.0 {
        row(
            "  after the reference ends",
            &|c| match c.settling_after_reference_s {
                Some(t) if c.settled => format!("{} s", signed_fixed(t, 3)),
                _ => "not settled".to_string(),
            },
        )?;
    }
    row("overshoot", &|c| format!("{:.1} %", c.overshoot_pct))?;
    row("rise time 10–90 %", &|c| {
        format_option(c.rise_time_s, 3, "s")
    })?;
    row("steady-state error", &|c| {
        format_option(c.steady_state_error_deg, 4, "°")
    })?;
    row("peak |elevator|", &|c| {
        format!("{:.1} °", c.max_elevator_deg)
    })?;
    row("peak elevator − trim", &|c| {
        format!("{:.1} °", c.max_elevator_change_deg)
    })?;
    row("time on elevator limit", &|c| {
        format!("{:.3} s", c.elevator_saturation_s)
    })?;
    row("elevator total travel", &|c| {
        format!("{:.0} °", c.elevator_total_variation_deg)
    })?;
    row("elevator rate RMS", &|c| {
        format!("{:.1} °/s", c.actuator.elevator_rate_rms_degps)
    })?;
    row("time on the rate limit", &|c| {
        format!(
            "{:.3} s ({:.1} %)",
            c.actuator.time_on_rate_limit_s, c.actuator.time_on_rate_limit_pct
        )
    })?;
    row("thrust rate RMS", &|c| {
        format!("{:.1} kN/s", c.actuator.thrust_rate_rms_knps)
    })?;
    for c in &report.controllers {
        if let Some(reason) = &c.not_settled_reason {
            outln!("  {} did not settle: {reason}", c.controller)?;
        }
    }
    outln!(
        "Settling time: from the step to the last entry into the ±2 % band around the target \
         (it must stay there to the end, at least 0.5 s){}.",
        if reference_s > 0.0 {
            "; after the reference ends: the same, less the reference's duration (negative: \
             settled before the reference reached the target)"
        } else {
            ""
        }
    )?;
    outln!("Wrote {} files to {}:", written.len(), report.output_folder)?;
    for path in written {
        if let Some(name) = path.file_name() {
            outln!("  {}", name.to_string_lossy())?;
        }
    }
    Ok(())
}

/// Runs the command.
pub fn run(args: &StepArgs) -> Result<()> {
    match args.axis {
        StepAxis::Pitch => {}
        StepAxis::Roll => return lateral::run(args, deckland::experiments::LateralAxis::Roll),
        StepAxis::Yaw => return lateral::run(args, deckland::experiments::LateralAxis::Yaw),
    }
    check_arguments(args)?;
    let flight = step_flight(args)?;
    let epsilon = match controller_parameters(&flight.base, ControllerChoice::Opd, args.epsilon) {
        PitchControllerParameters::ObserverPd(opd) => opd.observer.epsilon,
        _ => f64::NAN,
    };
    let runs = flight.fly(&args.controller.choices())?;
    let output = args.folder.prepare("step")?;

    let mut written = vec![output.write_bytes("step.csv", &csv_bytes(&runs)?)?];
    for (stem, figure) in figures(&runs, &flight) {
        written.extend(figure.save(&output, stem)?);
    }
    let report = StepReport {
        conditions: args.conditions.name(),
        step_deg: args.step_deg,
        seed: args.seed,
        seconds: args.seconds,
        step_time_s: STEP_TIME_S,
        airspeed_mps: flight.base.approach.airspeed_mps,
        settling_band_pct: SETTLING_BAND_FRACTION * 100.0,
        epsilon,
        elevator_rate_limit_degps: flight.base.aircraft.elevator_actuator.rate_limit_degps,
        controllers: runs.into_iter().map(|r| r.result).collect(),
        output_folder: output.path().display().to_string(),
    };
    crate::commands::common::print_json_or(
        args.folder.output.json,
        || &report,
        || print_table(&report, &written),
    )
}

/// The printer of a row of [`controller_columns`]: the row's name, then a cell per
/// controller.
pub(super) type RowPrinter<'a, T> =
    Box<dyn Fn(&str, &dyn Fn(&T) -> String) -> Result<(), crate::output::StdoutError> + 'a>;

/// Prints a header of one column per controller (`name` of each, right-aligned in
/// `cell` characters after a `label`-wide gap) and gives the printer of a row: its name
/// in the gap, then `text(controller)` in each column.
pub(super) fn controller_columns<'a, T>(
    controllers: &'a [T],
    name: impl Fn(&T) -> &str,
    label: usize,
    cell: usize,
) -> Result<RowPrinter<'a, T>> {
    outln!(
        "  {:<label$}{}",
        "",
        controllers
            .iter()
            .map(|c| format!("{:>cell$}", name(c)))
            .collect::<String>()
    )?;
    Ok(Box::new(move |row: &str, text: &dyn Fn(&T) -> String| {
        let cells: String = controllers
            .iter()
            .map(|c| format!("{:>cell$}", text(c)))
            .collect();
        outln!("  {row:<label$}{cells}")
    }))
}
