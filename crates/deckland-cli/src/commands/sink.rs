//! `deckland sink`: tracking a constant commanded sink rate (paper Fig. 13).
//!
//! From level trim, the sink-rate controller is commanded a constant sink rate at t = 1 s
//! (guidance off); the pitch controller and the speed loop run as in the approach. The
//! convergence time is the 2 % settling time of the sink rate towards the command,
//! measured from the command (definitions in `deckland::metrics`).

pub(crate) mod report;

use super::common::{
    seed_parser, validate_options, BaseScenarioArgs, Conditions, ControllerChoice, FolderArgs,
};
pub(crate) use crate::plot::sink::figure;
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::experiments::{
    fly_sink_rate, SinkRateRun, SinkRateTracking, SINK_COMMAND_TIME_S as COMMAND_TIME_S,
};
use deckland::scenario::{Mission, Scenario};
use report::{SinkReport, SinkRun};

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
    /// Time over which the command ramps in (s), 0 to the run's length; 0 gives the
    /// paper's step, which at 10 m/s pitches the nose down faster than the flight path
    /// can follow.
    #[arg(
        long = "ramp-s",
        value_name = "S",
        default_value_t = 5.0,
        allow_negative_numbers = true
    )]
    pub ramp_s: f64,
    /// Pitch controller.
    #[arg(long, value_enum, default_value = "opd")]
    pub controller: ControllerChoice,
    /// Disturbances (`ideal` by default, as the paper's Fig. 13); `adverse` is wind,
    /// turbulence and sensor noise without the carrier's air wake, which its model does
    /// not describe 20 km from the ship where the test is flown.
    #[arg(long, value_enum, default_value = "ideal")]
    pub conditions: Conditions,
    /// Length of the run (s), more than 2 and at most 600; the default 30 s holds the
    /// default command's settling (about 20 s) and its 0.5 s confirmation.
    #[arg(long, default_value_t = 30.0, allow_negative_numbers = true)]
    pub seconds: f64,
    /// Seed of every random stream, 0 to 2⁶³ − 1.
    #[arg(long, default_value_t = 1, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: u64,
    /// The hardware set, or a scenario file, to fly the command with.
    #[command(flatten)]
    pub base: BaseScenarioArgs,
    /// Figure size, output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub folder: FolderArgs,
}

/// Checks `args`, flies the sink-rate command and measures its convergence.
pub(crate) fn fly(args: &SinkArgs) -> Result<SinkRun> {
    if !(args.seconds.is_finite() && args.seconds > COMMAND_TIME_S + 1.0 && args.seconds <= 600.0) {
        bail!(
            "--seconds {:?} is out of range: expected more than {} s and at most 600 s",
            args.seconds,
            COMMAND_TIME_S + 1.0
        );
    }
    let tracking = SinkRateTracking {
        sink_rate_mps: args.sink_rate_mps,
        ramp_s: args.ramp_s,
        seconds: args.seconds,
    };
    // The rest as the library checks the mission flown, naming the options.
    let base = args.base.longitudinal_base()?;
    let mut scenario = args.conditions.conditions().apply(base, args.seed);
    scenario.control.pitch = args.controller.parameters_for(&base);
    scenario.mission = Mission::sink_rate(args.sink_rate_mps, args.ramp_s, args.seconds);
    validate_options(
        &scenario,
        &[
            ("mission.sink_rate_mps", "--sink-rate"),
            ("mission.ramp_s", "--ramp-s"),
            ("mission.duration_s", "--seconds"),
        ],
    )?;
    fly_tracking(
        &base,
        args.controller,
        args.conditions,
        args.seed,
        &tracking,
    )
}

/// Flies `tracking` on `base` with `controller` in `conditions` and measures it.
pub(crate) fn fly_tracking(
    base: &Scenario,
    controller: ControllerChoice,
    conditions: Conditions,
    seed: u64,
    tracking: &SinkRateTracking,
) -> Result<SinkRun> {
    let mut scenario = conditions.conditions().apply(*base, seed);
    scenario.control.pitch = controller.parameters_for(base);
    let run = fly_sink_rate(&scenario, tracking).context("cannot set up the sink-rate run")?;
    Ok(sink_run(run, controller, conditions, seed, tracking))
}

/// The library's `run` of `tracking`, flown with `controller` in `conditions` and
/// `seed`, with its report as `summary.json` holds it.
pub(crate) fn sink_run(
    run: SinkRateRun,
    controller: ControllerChoice,
    conditions: Conditions,
    seed: u64,
    tracking: &SinkRateTracking,
) -> SinkRun {
    let summary = run.summary;
    let report = SinkReport {
        controller: controller.label(),
        conditions: conditions.name(),
        seed,
        sink_rate_command_mps: tracking.sink_rate_mps,
        ramp_s: tracking.ramp_s,
        outcome: summary.outcome.name(),
        reason: summary.reason.clone(),
        metrics: run.metrics,
        max_pitch_change_deg: run.max_pitch_change_deg,
        altitude_lost_m: run.altitude_lost_m,
    };
    SinkRun {
        rows: run.samples,
        report,
    }
}

/// Runs `deckland sink`.
pub fn run(args: &SinkArgs) -> Result<()> {
    let flown = fly(args)?;
    let output = args.folder.prepare("sink")?;
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
    figure(&flown).save(&output, "sink_rate")?;

    if args.folder.output.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
        return Ok(());
    }
    outln!(
        "Sink-rate tracking — command {} m/s from t = {COMMAND_TIME_S} s (ramp {} s), {} pitch control, {} conditions",
        args.sink_rate_mps,
        args.ramp_s,
        report.controller,
        report.conditions
    )?;
    outln!("  outcome               {}", report.outcome)?;
    if let Some(reason) = &report.reason {
        outln!("  reason                {reason}")?;
    }
    if let Some(m) = &report.metrics {
        match m.settling_time_s {
            Some(t) => outln!("  converged (2 % band)  {t:.2} s after the command started"),
            None => outln!(
                "  converged (2 % band)  not settled: {}",
                m.not_settled_reason.as_deref().unwrap_or("unknown")
            ),
        }?;
        if let Some(t) = m.rise_time_s {
            outln!("  rise time 10–90 %     {t:.2} s")?;
        }
        outln!("  overshoot             {:.1} %", m.overshoot_pct)?;
        if let Some(e) = m.steady_state_error {
            outln!("  steady-state error    {e:.3} m/s (mean over the last second)")?;
        }
    }
    outln!(
        "  pitch change          up to {:.1}°",
        report.max_pitch_change_deg
    )?;
    outln!("  altitude lost         {:.0} m", report.altitude_lost_m)?;
    outln!("  results in            {}", output.path().display())?;
    Ok(())
}
