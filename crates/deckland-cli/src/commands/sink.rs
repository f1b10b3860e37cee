//! `deckland sink`: tracking a constant commanded sink rate (paper Fig. 13).
//!
//! From level trim, the sink-rate controller is commanded a constant sink rate at t = 1 s
//! (guidance off); the pitch controller and the speed loop run as in the approach. The
//! convergence time is the 2 % settling time of the sink rate towards the command,
//! measured from the command (definitions in `deckland::metrics`).

use super::common::{Conditions, ControllerChoice, OutputArgs};
use crate::output::OutputDir;
use crate::plot::{Figure, Panel};
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::metrics::{step_response_metrics, StepResponseMetrics, StepResponseSpec};
use deckland::recording::TimeSeriesRecorder;
use deckland::scenario::Mission;
use deckland::simulation::{Outcome, Simulation};
use serde::Serialize;

/// Options of `deckland sink`.
#[derive(Debug, Clone, Args)]
pub struct SinkArgs {
    /// Commanded sink rate (m/s, positive down); the paper uses 10 m/s.
    #[arg(
        long = "sink-rate",
        value_name = "M_S",
        default_value_t = 10.0,
        allow_negative_numbers = true
    )]
    pub sink_rate_mps: f64,
    /// Time over which the command ramps in (s); 0 gives the paper's step, which at
    /// 10 m/s pitches the nose down faster than the flight path can follow.
    #[arg(long = "ramp-s", value_name = "S", default_value_t = 5.0)]
    pub ramp_s: f64,
    /// Pitch controller.
    #[arg(long, value_enum, default_value = "opd")]
    pub controller: ControllerChoice,
    /// Disturbances (`ideal` by default, as the paper's Fig. 13).
    #[arg(long, value_enum, default_value = "ideal")]
    pub conditions: Conditions,
    /// Length of the run (s).
    #[arg(long, default_value_t = 20.0)]
    pub seconds: f64,
    /// Seed of every random stream.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// Time of the sink-rate command after the start (s).
const COMMAND_TIME_S: f64 = 1.0;

/// The summary of a sink-rate run (`summary.json`).
#[derive(Debug, Serialize)]
pub(crate) struct SinkReport {
    controller: &'static str,
    conditions: &'static str,
    seed: u64,
    sink_rate_command_mps: f64,
    ramp_s: f64,
    pub(crate) outcome: &'static str,
    pub(crate) reason: Option<String>,
    /// Sink-rate response metrics (2 % band of the command).
    pub(crate) metrics: Option<StepResponseMetrics>,
    /// Largest pitch-attitude deviation from level trim (deg).
    max_pitch_change_deg: f64,
    altitude_lost_m: f64,
}

#[derive(Debug, Serialize)]
struct Row {
    time_s: f64,
    sink_rate_command_mps: f64,
    sink_rate_mps: f64,
    sink_rate_error_mps: f64,
    altitude_m: f64,
    theta_deg: f64,
    theta_command_deg: f64,
    elevator_deg: f64,
    airspeed_mps: f64,
}

/// The commanded sink rate at `time_s` (m/s): zero, then a ramp to the command.
fn command_at(time_s: f64, args: &SinkArgs) -> f64 {
    if time_s < COMMAND_TIME_S {
        0.0
    } else if args.ramp_s > 0.0 {
        args.sink_rate_mps * ((time_s - COMMAND_TIME_S) / args.ramp_s).min(1.0)
    } else {
        args.sink_rate_mps
    }
}

/// A flown sink-rate run: the rows recorded every 10 ms and the report.
pub(crate) struct SinkRun {
    /// The recorded rows.
    rows: Vec<Row>,
    /// The summary, as in `summary.json`.
    pub(crate) report: SinkReport,
}

/// Checks `args`, flies the sink-rate command and measures its convergence.
pub(crate) fn fly(args: &SinkArgs) -> Result<SinkRun> {
    if !(args.seconds.is_finite() && args.seconds > COMMAND_TIME_S + 1.0 && args.seconds <= 600.0) {
        bail!(
            "--seconds {} is out of range: expected more than {} s and at most 600 s",
            args.seconds,
            COMMAND_TIME_S + 1.0
        );
    }
    let mut scenario = args.conditions.scenario(args.seed);
    scenario.control.pitch = args.controller.parameters();
    scenario.mission = Mission::SinkRate {
        sink_rate_mps: args.sink_rate_mps,
        step_time_s: COMMAND_TIME_S,
        ramp_s: args.ramp_s,
        duration_s: args.seconds,
        altitude_m: 600.0,
    };
    let simulation = Simulation::new(&scenario).context("cannot set up the sink-rate run")?;
    let mut recorder = TimeSeriesRecorder::every(0.01);
    let summary = simulation.run(&mut recorder);
    let samples = &recorder.samples;
    let rows: Vec<Row> = samples
        .iter()
        .map(|s| {
            let command = command_at(s.time_s, args);
            Row {
                time_s: s.time_s,
                sink_rate_command_mps: command,
                sink_rate_mps: -s.climb_rate_mps,
                sink_rate_error_mps: command + s.climb_rate_mps,
                altitude_m: s.h_m,
                theta_deg: s.theta_rad.to_degrees(),
                theta_command_deg: s.theta_ref_rad.to_degrees(),
                elevator_deg: s.elevator_rad.to_degrees(),
                airspeed_mps: s.airspeed_mps,
            }
        })
        .collect();
    let time: Vec<f64> = rows.iter().map(|r| r.time_s).collect();
    let sink: Vec<f64> = rows.iter().map(|r| r.sink_rate_mps).collect();
    let metrics = if summary.outcome == Outcome::Completed && args.sink_rate_mps != 0.0 {
        Some(step_response_metrics(
            &time,
            &sink,
            &StepResponseSpec::new(COMMAND_TIME_S, 0.0, args.sink_rate_mps),
        )?)
    } else {
        None
    };
    let trim_theta = rows.first().map_or(0.0, |r| r.theta_deg);
    let report = SinkReport {
        controller: args.controller.label(),
        conditions: args.conditions.name(),
        seed: args.seed,
        sink_rate_command_mps: args.sink_rate_mps,
        ramp_s: args.ramp_s,
        outcome: summary.outcome.name(),
        reason: summary.reason.clone(),
        metrics,
        max_pitch_change_deg: rows
            .iter()
            .map(|r| (r.theta_deg - trim_theta).abs())
            .fold(0.0, f64::max),
        altitude_lost_m: rows.first().map_or(0.0, |r| r.altitude_m)
            - rows.last().map_or(0.0, |r| r.altitude_m),
    };
    Ok(SinkRun { rows, report })
}

/// The sink-rate figure (paper Fig. 13): sink rate and command, error, altitude.
pub(crate) fn figure(run: &SinkRun, args: &SinkArgs) -> Figure {
    let rows = &run.rows;
    let points =
        |f: &dyn Fn(&Row) -> f64| rows.iter().map(|r| (r.time_s, f(r))).collect::<Vec<_>>();
    let title = format!(
        "Constant sink-rate command {} m/s (cf. paper Fig. 13) — {}, {}",
        args.sink_rate_mps,
        args.controller.label(),
        args.conditions.name()
    );
    Figure::new()
        .title(title)
        .panel(
            Panel::new("Sink rate", "time (s)", "sink rate (m/s, positive down)")
                .series("command", points(&|r| r.sink_rate_command_mps))
                .series("sink rate", points(&|r| r.sink_rate_mps)),
        )
        .panel(
            Panel::new("Sink-rate error", "time (s)", "error (m/s)")
                .series("command − sink rate", points(&|r| r.sink_rate_error_mps))
                .reference_line("zero", 0.0),
        )
        .panel(
            Panel::new("Trajectory", "time (s)", "altitude (m)")
                .series("altitude", points(&|r| r.altitude_m)),
        )
}

/// Runs `deckland sink`.
pub fn run(args: &SinkArgs) -> Result<()> {
    let flown = fly(args)?;
    let output = OutputDir::prepare("sink", args.output.out.as_deref(), args.output.force)?;
    let report = &flown.report;
    let mut csv = csv::Writer::from_writer(Vec::new());
    for row in &flown.rows {
        csv.serialize(row)?;
    }
    output.write_bytes(
        "sink.csv",
        &csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?,
    )?;
    output.write_bytes(
        "summary.json",
        serde_json::to_string_pretty(report)?.as_bytes(),
    )?;
    figure(&flown, args).save(&output, "sink_rate")?;

    if args.output.json {
        println!("{}", serde_json::to_string_pretty(&report)?);
        return Ok(());
    }
    println!(
        "Sink-rate tracking — command {} m/s from t = {COMMAND_TIME_S} s (ramp {} s), {} pitch control, {} conditions",
        args.sink_rate_mps,
        args.ramp_s,
        report.controller,
        report.conditions
    );
    println!("  outcome               {}", report.outcome);
    if let Some(reason) = &report.reason {
        println!("  reason                {reason}");
    }
    if let Some(m) = &report.metrics {
        match m.settling_time_s {
            Some(t) => println!("  converged (2 % band)  {t:.2} s after the command started"),
            None => println!(
                "  converged (2 % band)  not settled: {}",
                m.not_settled_reason.as_deref().unwrap_or("unknown")
            ),
        }
        if let Some(t) = m.rise_time_s {
            println!("  rise time 10–90 %     {t:.2} s");
        }
        println!("  overshoot             {:.1} %", m.overshoot_pct);
        if let Some(e) = m.steady_state_error {
            println!("  steady-state error    {e:.3} m/s (mean over the last second)");
        }
    }
    println!(
        "  pitch change          up to {:.1}°",
        report.max_pitch_change_deg
    );
    println!("  altitude lost         {:.0} m", report.altitude_lost_m);
    println!("  results in            {}", output.path().display());
    Ok(())
}
