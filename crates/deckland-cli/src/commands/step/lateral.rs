//! `deckland step --axis roll|yaw`: a bank-angle or sideslip step of the 6-DOF aircraft
//! with the lateral O-PD and/or PID (`experiments::fly_lateral_step`,
//! docs/lateral-control.md): the same metrics table, CSV, plots and JSON as the pitch step.
//! The aircraft, its approach airspeed and the laws are the scenario's (`--scenario FILE`,
//! or the realistic set's defaults): `[aircraft]` with its aileron and rudder actuators,
//! `approach.airspeed_mps`, and `[control.roll]`, `[control.yaw]` for the controller
//! flown (`--controller opd` flies the file's O-PD where it names one, else the designed
//! O-PD; likewise the PID).

use std::path::PathBuf;

use anyhow::{anyhow, bail, Context, Result};
use deckland::experiments::{
    fly_lateral_step, LateralAxis, LateralSample, LateralSetup, LateralStep, LateralStepReport,
    LATERAL_STEP_TIME_S, MAX_LATERAL_STEP_DEG, MIN_LATERAL_STEP_DEG,
};
use deckland::parameters::readable_number;
use deckland::scenario::HardwareSet;
use serde::Serialize;

use super::flight::LateralRun;
use super::{
    format_option, prefix, settling_cell, write_sample_rows, StepArgs, MAX_SECONDS, MIN_SECONDS,
};
use crate::commands::common::{Conditions, ControllerChoice};
use crate::plot::step::lateral::lateral_figures;

/// The JSON document of `deckland step --axis roll|yaw --json`: the library's report and
/// where the files went.
#[derive(Debug, Serialize)]
struct LateralReport {
    #[serde(flatten)]
    report: LateralStepReport,
    output_folder: String,
}

fn law_name(choice: ControllerChoice) -> &'static str {
    match choice {
        ControllerChoice::Opd => "observer_pd",
        ControllerChoice::Pid => "pid",
    }
}

/// Flies and reports the lateral step.
pub(crate) fn run(args: &StepArgs, axis: LateralAxis) -> Result<()> {
    if !(args.step_deg.is_finite()
        && (MIN_LATERAL_STEP_DEG..=MAX_LATERAL_STEP_DEG).contains(&args.step_deg.abs()))
    {
        bail!(
            "--step-deg must have {MIN_LATERAL_STEP_DEG} <= |D| <= {MAX_LATERAL_STEP_DEG} on \
             the {} axis (below {MIN_LATERAL_STEP_DEG}° the step is lost in the sensors' \
             noise and the trim's residue), got {}",
            axis_name(axis),
            readable_number(args.step_deg)
        );
    }
    if !(args.seconds.is_finite() && (MIN_SECONDS..=MAX_SECONDS).contains(&args.seconds)) {
        bail!(
            "--seconds must lie in [{MIN_SECONDS}, {MAX_SECONDS}] s (the step comes at \
             {LATERAL_STEP_TIME_S} s), got {}",
            readable_number(args.seconds)
        );
    }
    if args.epsilon.is_some() {
        bail!(
            "--epsilon sets the pitch O-PD's observer; the {} axis flies the lateral laws' \
             designed ε (docs/lateral-control.md)",
            axis_name(axis)
        );
    }
    let scenario = args.base.base()?;
    if scenario.hardware == HardwareSet::Paper {
        bail!(
            "{} has no {} axis: the paper's hardware set flies the 3-DOF model; fly the \
             lateral step on the realistic set (the default) or on a scenario file of it",
            if args.base.scenario.is_some() {
                "a scenario file with `hardware = \"paper\"`"
            } else {
                "--hardware paper"
            },
            axis_name(axis)
        );
    }
    let setup = LateralSetup::from_scenario(&scenario).map_err(|e| anyhow!("{e}"))?;
    let step = LateralStep {
        adverse: args.conditions == Conditions::Adverse,
        seed: args.seed,
        ..LateralStep::new(axis, args.step_deg, args.seconds)
    };
    let runs = args
        .controller
        .choices()
        .into_iter()
        .map(|choice| {
            let (roll, yaw) = setup.scenario_laws(&scenario, law_name(choice))?;
            let run = fly_lateral_step(&setup, &step, roll.as_ref(), yaw.as_ref())
                .with_context(|| format!("cannot fly the {} lateral step", choice.label()))?;
            Ok(LateralRun {
                choice,
                samples: run.samples,
                result: run.response,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let output = args.folder.prepare("step")?;
    let mut written = vec![output.write_bytes("step.csv", &csv_bytes(&runs)?)?];
    for (stem, figure) in lateral_figures(&runs, &step, args.conditions) {
        written.extend(figure.save(&output, stem)?);
    }
    let report = LateralReport {
        report: LateralStepReport::new(&setup, &step, runs.into_iter().map(|r| r.result).collect()),
        output_folder: output.path().display().to_string(),
    };
    crate::commands::common::print_json_or(
        args.folder.output.json,
        || &report,
        || print_table(&report, &written),
    )
}

/// `roll` or `yaw`.
pub(crate) fn axis_name(axis: LateralAxis) -> &'static str {
    match axis {
        LateralAxis::Roll => "roll",
        LateralAxis::Yaw => "yaw",
    }
}

fn csv_bytes(runs: &[LateralRun]) -> Result<Vec<u8>> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["time_s".to_string()];
    for run in runs {
        for column in LateralSample::COLUMNS {
            header.push(format!("{}_{column}", prefix(run.choice)));
        }
    }
    writer.write_record(&header)?;
    let samples: Vec<&[LateralSample]> = runs.iter().map(|r| r.samples.as_slice()).collect();
    let width = LateralSample::COLUMNS.len();
    write_sample_rows(
        &mut writer,
        &samples,
        |s| s.time_s,
        width,
        |s, record| record.extend(s.values().iter().map(f64::to_string)),
    )?;
    writer.into_inner().map_err(|e| anyhow!("{e}"))
}

fn print_table(document: &LateralReport, written: &[PathBuf]) -> Result<()> {
    let report = &document.report;
    let (angle, channel) = match report.axis {
        LateralAxis::Roll => ("Bank", "sideslip held at 0 by the yaw law"),
        LateralAxis::Yaw => ("Sideslip", "bank held at 0 by the roll law"),
    };
    outln!(
        "{angle} step {:+}° at t = {} s from the approach trim ({:.1} m/s, 6-DOF), {channel}; \
         {} conditions, seed {}, {} s",
        report.step_deg,
        report.step_time_s,
        report.airspeed_mps,
        report.conditions,
        report.seed,
        report.seconds,
    )?;
    if let Some(first) = report.controllers.first() {
        outln!(
            "Command: the jerk-limited reference to {:+}° in {:.3} s",
            report.step_deg,
            first.reference_duration_s
        )?;
    }
    let row = super::controller_columns(&report.controllers, |c| &c.controller, 30, 16)?;
    row("settling time (±5 %)", &|c| {
        settling_cell(c.settled, c.settling_time_s)
    })?;
    row("overshoot", &|c| format!("{:.1} %", c.overshoot_pct))?;
    row("rise time 10–90 %", &|c| {
        format_option(c.rise_time_s, 3, "s")
    })?;
    row("peak |β − β_ref|", &|c| {
        format!("{:.2} °", c.max_sideslip_error_deg)
    })?;
    row("peak |φ − φ_ref| (see docs)", &|c| {
        format!("{:.2} °", c.max_bank_error_deg)
    })?;
    row("peak |aileron|", &|c| format!("{:.1} °", c.max_aileron_deg))?;
    row("aileron rate RMS", &|c| {
        format!("{:.1} °/s", c.aileron_rate_rms_degps)
    })?;
    row("aileron on its rate limit", &|c| {
        format!("{:.1} %", 100.0 * c.aileron_rate_limited_fraction)
    })?;
    row("peak |rudder|", &|c| format!("{:.1} °", c.max_rudder_deg))?;
    row("rudder rate RMS", &|c| {
        format!("{:.1} °/s", c.rudder_rate_rms_degps)
    })?;
    row("outcome", &|c| c.outcome.to_string())?;
    for c in &report.controllers {
        if let Some(reason) = &c.not_settled_reason {
            outln!("  {} did not settle: {reason}", c.controller)?;
        }
    }
    outln!(
        "Wrote {} files to {}:",
        written.len(),
        document.output_folder
    )?;
    for path in written {
        if let Some(name) = path.file_name() {
            outln!("  {}", name.to_string_lossy())?;
        }
    }
    Ok(())
}
