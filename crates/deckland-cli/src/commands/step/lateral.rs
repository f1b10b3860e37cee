//! `deckland step --axis roll|yaw`: a bank-angle or sideslip step of the 6-DOF aircraft
//! with the lateral O-PD and/or PID (`experiments::fly_lateral_step`,
//! docs/lateral-control.md): the same metrics table, CSV, plots and JSON as the pitch step.

use std::path::PathBuf;

use anyhow::{anyhow, bail, Context, Result};
use deckland::experiments::{
    fly_lateral_step, LateralAxis, LateralSample, LateralSetup, LateralStep, LateralStepResponse,
    LATERAL_SETTLING_BAND_FRACTION, LATERAL_STEP_TIME_S,
};
use serde::Serialize;

use super::{format_option, prefix, StepArgs, MAX_SECONDS, MIN_SECONDS};
use crate::commands::common::{Conditions, ControllerChoice};
use crate::output::OutputDir;
use crate::plot::step::lateral::lateral_figures;

/// Largest |--step-deg| accepted on the lateral axes (deg).
const MAX_LATERAL_STEP_DEG: f64 = 30.0;

/// One controller's lateral run.
pub(crate) struct LateralRun {
    /// Which controller flew (on both channels).
    pub(crate) choice: ControllerChoice,
    /// The recorded samples (every 2 ms).
    pub(crate) samples: Vec<LateralSample>,
    /// The response.
    pub(crate) result: LateralStepResponse,
}

/// The JSON document of `deckland step --axis roll|yaw --json`.
#[derive(Debug, Serialize)]
struct LateralReport {
    axis: LateralAxis,
    conditions: &'static str,
    step_deg: f64,
    seed: u64,
    seconds: f64,
    step_time_s: f64,
    airspeed_mps: f64,
    settling_band_pct: f64,
    aileron_rate_limit_degps: Option<f64>,
    rudder_rate_limit_degps: Option<f64>,
    controllers: Vec<LateralStepResponse>,
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
        && args.step_deg != 0.0
        && args.step_deg.abs() <= MAX_LATERAL_STEP_DEG)
    {
        bail!(
            "--step-deg must be nonzero with |D| <= {MAX_LATERAL_STEP_DEG} on the {} axis, got {}",
            axis_name(axis),
            args.step_deg
        );
    }
    if !(args.seconds.is_finite() && (MIN_SECONDS..=MAX_SECONDS).contains(&args.seconds)) {
        bail!(
            "--seconds must lie in [{MIN_SECONDS}, {MAX_SECONDS}] s (the step comes at \
             {LATERAL_STEP_TIME_S} s), got {}",
            args.seconds
        );
    }
    if args.epsilon.is_some() {
        bail!(
            "--epsilon sets the pitch O-PD's observer; the {} axis flies the lateral laws' \
             designed ε (docs/lateral-control.md)",
            axis_name(axis)
        );
    }
    let setup = LateralSetup::approach().map_err(|e| anyhow!("{e}"))?;
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
            let (roll, yaw) = setup.registered_laws(law_name(choice))?;
            let run = fly_lateral_step(&setup, &step, roll.as_ref(), yaw.as_ref())
                .with_context(|| format!("cannot fly the {} lateral step", choice.label()))?;
            Ok(LateralRun {
                choice,
                samples: run.samples,
                result: run.response,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    let output = OutputDir::prepare("step", args.output.out.as_deref(), args.output.force)?;
    let mut written = vec![output.write_bytes("step.csv", &csv_bytes(&runs)?)?];
    for (stem, figure) in lateral_figures(&runs, &step, args.conditions) {
        written.extend(figure.save(&output, stem)?);
    }
    let report = LateralReport {
        axis,
        conditions: args.conditions.name(),
        step_deg: args.step_deg,
        seed: args.seed,
        seconds: args.seconds,
        step_time_s: LATERAL_STEP_TIME_S,
        airspeed_mps: setup.trim.speed_mps,
        settling_band_pct: LATERAL_SETTLING_BAND_FRACTION * 100.0,
        aileron_rate_limit_degps: setup.aircraft.aileron().parameters().rate_limit_degps,
        rudder_rate_limit_degps: setup.aircraft.rudder().parameters().rate_limit_degps,
        controllers: runs.into_iter().map(|r| r.result).collect(),
        output_folder: output.path().display().to_string(),
    };
    if args.output.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_table(&report, &written)?;
    }
    Ok(())
}

/// `roll` or `yaw`.
pub(crate) fn axis_name(axis: LateralAxis) -> &'static str {
    match axis {
        LateralAxis::Roll => "roll",
        LateralAxis::Yaw => "yaw",
    }
}

/// The columns of one controller's samples in `step.csv`.
const COLUMNS: [&str; 12] = [
    "bank_deg",
    "bank_command_deg",
    "sideslip_deg",
    "sideslip_command_deg",
    "heading_deg",
    "roll_rate_degps",
    "yaw_rate_degps",
    "aileron_deg",
    "aileron_rate_degps",
    "rudder_deg",
    "rudder_rate_degps",
    "wind_y_mps",
];

fn values(s: &LateralSample) -> [f64; 12] {
    [
        s.bank_deg,
        s.bank_command_deg,
        s.sideslip_deg,
        s.sideslip_command_deg,
        s.heading_deg,
        s.roll_rate_degps,
        s.yaw_rate_degps,
        s.aileron_deg,
        s.aileron_rate_degps,
        s.rudder_deg,
        s.rudder_rate_degps,
        s.wind_y_mps,
    ]
}

fn csv_bytes(runs: &[LateralRun]) -> Result<Vec<u8>> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    let mut header = vec!["time_s".to_string()];
    for run in runs {
        for column in COLUMNS {
            header.push(format!("{}_{column}", prefix(run.choice)));
        }
    }
    writer.write_record(&header)?;
    let rows = runs.iter().map(|r| r.samples.len()).max().unwrap_or(0);
    let longest = runs.iter().find(|r| r.samples.len() == rows);
    for index in 0..rows {
        let mut record = Vec::with_capacity(header.len());
        record.push(
            longest
                .map_or(f64::NAN, |r| r.samples[index].time_s)
                .to_string(),
        );
        for run in runs {
            match run.samples.get(index) {
                Some(s) => record.extend(values(s).iter().map(f64::to_string)),
                None => record.extend(std::iter::repeat_n(String::new(), COLUMNS.len())),
            }
        }
        writer.write_record(&record)?;
    }
    writer.into_inner().map_err(|e| anyhow!("{e}"))
}

fn print_table(report: &LateralReport, written: &[PathBuf]) -> Result<()> {
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
        if c.settled {
            format_option(c.settling_time_s, 3, "s")
        } else {
            "not settled".to_string()
        }
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
    outln!("Wrote {} files to {}:", written.len(), report.output_folder)?;
    for path in written {
        if let Some(name) = path.file_name() {
            outln!("  {}", name.to_string_lossy())?;
        }
    }
    Ok(())
}
