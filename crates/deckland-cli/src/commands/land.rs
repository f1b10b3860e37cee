//! `deckland land`: one approach from 1500 m to the moving deck, the main job.
//!
//! Writes into the output folder the scenario it flew (`scenario.toml`), a time series
//! (`approach.csv`, every 10 ms), the summary (`summary.json`) and plots (PNG and SVG):
//! altitude against the glide path and the deck, the glide-path error (paper Fig. 14),
//! pitch and pitch command (Fig. 15), elevator and thrust, airspeed, and the wind seen.

use super::common::{Conditions, ControllerChoice, OutputArgs};
use crate::output::OutputDir;
use crate::plot::{Figure, Panel};
use anyhow::{Context, Result};
use clap::Args;
use deckland::experiments::{fly_approach, ApproachRow};
use deckland::scenario::Scenario;
use deckland::simulation::{RunSummary, Signals};
use serde::Serialize;

/// Options of `deckland land`.
#[derive(Debug, Clone, Args)]
pub struct LandArgs {
    /// Pitch controller.
    #[arg(long, value_enum, default_value = "opd")]
    pub controller: ControllerChoice,
    /// Disturbances: `adverse` (wind, air wake, turbulence, sensor noise, deck motion) or
    /// `ideal` (none).
    #[arg(long, value_enum, default_value = "adverse")]
    pub conditions: Conditions,
    /// Seed of every random stream.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Fly without deck-motion compensation (track the mean deck to the end).
    #[arg(long)]
    pub no_deck_compensation: bool,
    /// Write no plots (the CSV, the summary and the scenario only).
    #[arg(long)]
    pub no_plots: bool,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
}

/// What `summary.json` and `--json` hold: the run's summary with what was flown.
#[derive(Debug, Serialize)]
pub struct LandingReport<'a> {
    /// Pitch controller.
    pub controller: &'a str,
    /// `ideal`, `adverse`, or the scenario file's name.
    pub conditions: &'a str,
    /// Seed of the random streams.
    pub seed: u64,
    /// Outcome name (`trap`, `bolter`, `ramp_strike`, `hard_landing`, `diverged`, `timeout`).
    pub outcome: &'static str,
    /// The run's summary (outcome, wire, touchdown, ramp clearance, glide-path error).
    #[serde(flatten)]
    pub summary: &'a RunSummary,
}

/// Points (time, value) of one signal.
fn series(samples: &[Signals], value: impl Fn(&Signals) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time_s, value(s))).collect()
}

/// The approach's figures, each with its file stem: `altitude`, `glide_path_error`
/// (paper Fig. 14), `pitch` (Fig. 15), `controls`, `airspeed` and `wind`.
pub(crate) fn figures(samples: &[Signals], title: &str) -> Vec<(&'static str, Figure)> {
    let time = "time (s)";
    let altitude = Figure::new().title(format!("Approach — {title}")).panel(
        Panel::new(
            "Hook height, glide path and deck",
            time,
            "height above sea (m)",
        )
        .series(
            "glide path (hook reference)",
            series(samples, |s| s.path_height_m),
        )
        .series("hook", series(samples, |s| s.hook_h_m))
        .series(
            "landing point on the deck",
            series(samples, |s| s.aim_point.h_m),
        ),
    );
    let error = Figure::new()
        .title(format!(
            "Position error to the glide path (cf. paper Fig. 14) — {title}"
        ))
        .panel(
            Panel::new(
                "Glide-path error h_ref − h_hook (positive: below the path)",
                time,
                "error (m)",
            )
            .series(
                "glide-path error",
                series(samples, |s| s.glide_path_error_m),
            )
            .reference_line("on the path", 0.0),
        );
    let pitch = Figure::new()
        .title(format!(
            "Pitch angle on approach (cf. paper Fig. 15) — {title}"
        ))
        .panel(
            Panel::new("Pitch attitude and command", time, "pitch (deg)")
                .series(
                    "pitch command θ_ref",
                    series(samples, |s| s.theta_ref_rad.to_degrees()),
                )
                .series("pitch θ", series(samples, |s| s.theta_rad.to_degrees())),
        );
    let controls = Figure::new()
        .title(format!("Controls — {title}"))
        .panel(
            Panel::new(
                "Elevator (positive trailing edge down)",
                time,
                "elevator (deg)",
            )
            .series("elevator", series(samples, |s| s.elevator_rad.to_degrees()))
            .reference_line("limit −25°", -25.0)
            .reference_line("limit +10°", 10.0),
        )
        .panel(
            Panel::new("Thrust, both engines", time, "thrust (kN)")
                .series("command", series(samples, |s| s.thrust_command_n / 1000.0))
                .series("actual", series(samples, |s| s.thrust_n / 1000.0)),
        );
    let airspeed = Figure::new()
        .title(format!("Airspeed and angle of attack — {title}"))
        .panel(
            Panel::new("True airspeed", time, "airspeed (m/s)")
                .series("airspeed", series(samples, |s| s.airspeed_mps)),
        )
        .panel(
            Panel::new("Angle of attack", time, "α (deg)")
                .series("α", series(samples, |s| s.alpha_rad.to_degrees())),
        );
    let wind = Figure::new()
        .title(format!("Wind at the aircraft — {title}"))
        .panel(
            Panel::new("Wind in earth axes", time, "wind (m/s)")
                .series(
                    "x (positive forward; headwind negative)",
                    series(samples, |s| s.wind.x_mps),
                )
                .series("z (positive down)", series(samples, |s| s.wind.z_mps)),
        );
    vec![
        ("altitude", altitude),
        ("glide_path_error", error),
        ("pitch", pitch),
        ("controls", controls),
        ("airspeed", airspeed),
        ("wind", wind),
    ]
}

/// Flies `scenario`, writes every result into `output` and prints the summary (as text,
/// or as JSON with `json`). Shared by `land` and `run`.
pub fn fly_and_write(
    scenario: &Scenario,
    output: &OutputDir,
    controller: &str,
    conditions: &str,
    json: bool,
    plots: bool,
) -> Result<RunSummary> {
    let run = fly_approach(scenario).context("cannot set up the approach")?;
    let summary = run.summary;
    let report = LandingReport {
        controller,
        conditions,
        seed: scenario.seed,
        outcome: summary.outcome.name(),
        summary: &summary,
    };
    output.write_bytes(
        "scenario.toml",
        toml::to_string(scenario)
            .context("cannot write the scenario as TOML")?
            .as_bytes(),
    )?;
    let mut csv = csv::Writer::from_writer(Vec::new());
    for sample in &run.samples {
        csv.serialize(ApproachRow::from(sample))?;
    }
    let bytes = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
    output.write_bytes("approach.csv", &bytes)?;
    output.write_bytes(
        "summary.json",
        serde_json::to_string_pretty(&report)?.as_bytes(),
    )?;
    if plots {
        let title = format!("{controller}, {conditions}, seed {}", scenario.seed);
        for (stem, figure) in figures(&run.samples, &title) {
            figure.save(output, stem)?;
        }
    }
    if json {
        println!("{}", serde_json::to_string_pretty(&report)?);
    } else {
        print_summary(&report, output);
    }
    Ok(summary)
}

fn print_summary(report: &LandingReport, output: &OutputDir) {
    let s = report.summary;
    let outcome = match s.wire {
        Some(wire) => format!("{} (wire {wire})", report.outcome),
        None => report.outcome.to_string(),
    };
    println!(
        "Approach — {} pitch control, {} conditions, seed {}",
        report.controller, report.conditions, report.seed
    );
    println!("  outcome               {outcome}");
    if let Some(reason) = &s.reason {
        println!("  reason                {reason}");
    }
    if let Some(t) = &s.touchdown {
        println!(
            "  touchdown             {:.2} s, {:+.1} m from the aim point (positive forward)",
            t.time_s, t.distance_from_aim_m
        );
        println!(
            "  sink rate at deck     {:.2} m/s   pitch {:.1}°   airspeed {:.1} m/s",
            t.sink_rate_mps, t.pitch_deg, t.airspeed_mps
        );
    }
    if let Some(c) = s.ramp_clearance_m {
        println!("  hook over the ramp    {c:.2} m");
    }
    if let (Some(rms), Some(max)) = (s.glide_path_error_rms_m, s.glide_path_error_max_m) {
        println!("  glide-path error      RMS {rms:.2} m, max {max:.2} m");
    }
    println!("  results in            {}", output.path().display());
}

/// Runs `deckland land`.
pub fn run(args: &LandArgs) -> Result<()> {
    let mut scenario = args.conditions.scenario(args.seed);
    scenario.control.pitch = args.controller.parameters();
    if args.no_deck_compensation {
        scenario.control.flight_path.deck_motion_compensation = false;
    }
    let output = OutputDir::prepare("land", args.output.out.as_deref(), args.output.force)?;
    fly_and_write(
        &scenario,
        &output,
        args.controller.label(),
        args.conditions.name(),
        args.output.json,
        !args.no_plots,
    )?;
    Ok(())
}
