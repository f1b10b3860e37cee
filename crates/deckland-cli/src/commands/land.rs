//! `deckland land`: one approach from 1500 m to the moving deck, the main job.
//!
//! Writes into the output folder the scenario it flew (`scenario.toml`), a time series
//! (`approach.csv`, every 10 ms), the summary (`summary.json`) and plots (PNG and SVG):
//! altitude against the glide path and the deck, the glide-path error (paper Fig. 14),
//! pitch and pitch command (Fig. 15), elevator and thrust, airspeed, and the wind seen.

use super::common::{
    check_set_up, seed_parser, Conditions, ControllerChoice, HardwareChoice, OutputArgs,
};
use crate::html;
use crate::output::OutputDir;
use crate::plot::{Figure, MarkerShape, Panel, DECK_COLOUR};
use anyhow::{Context, Result};
use clap::Args;
use deckland::experiments::{fly_approach, ApproachRow, ApproachRun};
use deckland::scenario::Scenario;
use deckland::simulation::{Event, Outcome, RunSummary, Signals};
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
    /// Hardware: `realistic` (40 °/s stabilator, 80 Hz flight computer, controllers
    /// designed for them) or `paper` (the paper's ideal actuator and gains).
    #[arg(long, value_enum, default_value = "realistic")]
    pub hardware: HardwareChoice,
    /// Seed of every random stream, 0 to 2⁶³ − 1.
    #[arg(long, default_value_t = 1, value_parser = seed_parser(), allow_negative_numbers = true)]
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
    /// The run's summary: outcome (`trap`, `bolter`, `wave_off`, `ramp_strike`,
    /// `hard_landing`, `diverged`, `timeout`), wire, touchdown, ramp clearance, glide-path error. Its
    /// keys are the document's own (flattened), so none may repeat a key above.
    #[serde(flatten)]
    pub summary: &'a RunSummary,
}

/// Points (time, value) of one signal.
fn series(samples: &[Signals], value: impl Fn(&Signals) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time_s, value(s))).collect()
}

/// Points (time, value) of a signal where it applies.
fn series_where_applicable(
    samples: &[Signals],
    value: impl Fn(&Signals) -> Option<f64>,
) -> Vec<(f64, f64)> {
    samples
        .iter()
        .filter_map(|s| value(s).map(|v| (s.time_s, v)))
        .collect()
}

/// The outcome in words, with what decided it: "trap on wire 4", "ramp strike: hook
/// 3.29 m below the ramp".
pub(crate) fn outcome_text(summary: &RunSummary) -> String {
    let name = summary.outcome.name().replace('_', " ");
    match (summary.outcome, summary.wire, &summary.reason) {
        (Outcome::Trap, Some(wire), _) => format!("trap on wire {wire}"),
        (_, _, Some(reason)) => format!("{name}: {reason}"),
        _ => name,
    }
}

/// The hook height at `time_s`, interpolated between the recorded samples.
fn hook_height_at(samples: &[Signals], time_s: f64) -> Option<f64> {
    let after = samples.iter().position(|s| s.time_s >= time_s)?;
    let b = &samples[after];
    let Some(a) = after.checked_sub(1).map(|i| &samples[i]) else {
        return Some(b.hook_h_m);
    };
    let span = b.time_s - a.time_s;
    let fraction = if span > 0.0 {
        (time_s - a.time_s) / span
    } else {
        1.0
    };
    Some(a.hook_h_m + fraction * (b.hook_h_m - a.hook_h_m))
}

/// Length of the final approach shown in the upper panel of `approach` (m).
const FINAL_APPROACH_M: f64 = 1000.0;
/// Distance aft of the ramp where the close-up over the deck starts (m).
const CLOSE_UP_AFT_OF_RAMP_M: f64 = 190.0;

/// The final approach in metres around the deck: the hook, the glide path and the
/// landing point against the hook's distance along the deck from the aim point, heights
/// above the deck's mean height; the ramp as the hook crossed it, the wires, the deck at
/// touchdown and the touchdown point, with the outcome written on it. Two panels: the
/// last 1000 m, and a close-up from 190 m aft of the ramp over the deck.
fn approach_figure(run: &ApproachRun, scenario: &Scenario, flown: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let mean_deck_m = deck.deck_height_m;
    let along = |s: &Signals| deck.distance_along_deck(&s.ship, s.hook_x_m);
    // Points (distance along the deck, height above the mean deck) where the signal
    // applies and the hook is at or forward of `from_m`.
    let curve = |from_m: f64, value: &dyn Fn(&Signals) -> Option<f64>| -> Vec<(f64, f64)> {
        samples
            .iter()
            .filter_map(|s| value(s).map(|v| (along(s), v - mean_deck_m)))
            .filter(|(x, _)| *x >= from_m)
            .collect()
    };
    let outcome = outcome_text(&run.summary);
    let ramp_m = -deck.ramp_aft_of_aim_point_m;
    let ramp_crossing = run.events.iter().find_map(|event| match event {
        Event::RampCrossing {
            time_s,
            clearance_m,
        } => hook_height_at(samples, *time_s)
            .map(|hook| (hook - clearance_m - mean_deck_m, *clearance_m)),
        _ => None,
    });
    let touchdown = run
        .summary
        .touchdown
        .and_then(|t| hook_height_at(samples, t.time_s).map(|hook| (t, hook - mean_deck_m)));
    // The deck as it stood at touchdown (or at the end of the run), ramp to bow side.
    let deck_time_s = touchdown.map_or(run.summary.end_time_s, |(t, _)| t.time_s);
    let deck_pose = samples
        .iter()
        .min_by(|a, b| {
            (a.time_s - deck_time_s)
                .abs()
                .total_cmp(&(b.time_s - deck_time_s).abs())
        })
        .map(|s| s.ship);
    let last_wire_m = deck.wire_positions_m[3];
    let forward_end_m =
        touchdown.map_or(last_wire_m, |(t, _)| t.distance_from_aim_m.max(last_wire_m)) + 20.0;
    let deck_line: Vec<(f64, f64)> = deck_pose
        .map(|pose| {
            [ramp_m, forward_end_m]
                .iter()
                .map(|&s_m| (s_m, deck.point_along_deck(&pose, s_m).h_m - mean_deck_m))
                .collect()
        })
        .unwrap_or_default();
    let deck_name = if touchdown.is_some() {
        "deck at touchdown"
    } else {
        "deck at the end of the run"
    };
    let panel = |title: String, from_m: f64, close_up: bool| {
        let mut panel = Panel::new(
            title,
            "hook distance along the deck from the aim point (m, positive forward)",
            "height above the mean deck (m)",
        )
        .x_limits(from_m..forward_end_m)
        .series("hook", curve(from_m, &|s| Some(s.hook_h_m)))
        .dashed_series("glide path", curve(from_m, &|s| s.path_height_m))
        .series("landing point", curve(from_m, &|s| Some(s.aim_point.h_m)))
        .coloured_series(deck_name, deck_line.clone(), DECK_COLOUR)
        .vertical_line("ramp", ramp_m);
        if let Some((height, clearance)) = ramp_crossing {
            panel = panel.marker(
                if clearance >= 0.0 {
                    format!("ramp as crossed, {clearance:.2} m below the hook")
                } else {
                    format!("ramp as crossed, {:.2} m above the hook", -clearance)
                },
                (ramp_m, height),
                MarkerShape::Triangle,
            );
        }
        if let Some((t, height)) = touchdown {
            panel = panel.marker(
                format!(
                    "touchdown {:+.1} m, sink {:.2} m/s",
                    t.distance_from_aim_m, t.sink_rate_mps
                ),
                (t.distance_from_aim_m, height),
                MarkerShape::Circle,
            );
        }
        if close_up {
            // Wires 12 m apart are numbered only: names would run into each other.
            for (index, wire) in deck.wire_positions_m.iter().enumerate() {
                panel = panel.vertical_line(format!("{}", index + 1), *wire);
            }
            panel = panel.note(outcome.clone());
        }
        panel
    };
    let close_up_m = ramp_m - CLOSE_UP_AFT_OF_RAMP_M;
    Figure::new()
        .title(format!("Final approach — {flown}: {outcome}"))
        .panel(panel(
            format!("The last {FINAL_APPROACH_M:.0} m"),
            -FINAL_APPROACH_M,
            false,
        ))
        .panel(panel(
            format!(
                "Over the deck: {:.0} m aft of the ramp to the wires (numbered 1–4)",
                CLOSE_UP_AFT_OF_RAMP_M
            ),
            close_up_m,
            true,
        ))
        .panel_height(440)
}

/// The approach's figures, each with its file stem: `approach` (the final approach in
/// metres around the deck), `altitude` (the whole approach), `glide_path_error` (paper
/// Fig. 14), `pitch` (Fig. 15), `controls`, `airspeed` and `wind`. `flown` names the
/// controller, the conditions and the seed.
pub(crate) fn figures(
    run: &ApproachRun,
    scenario: &Scenario,
    flown: &str,
) -> Vec<(&'static str, Figure)> {
    let samples = &run.samples;
    let title = format!("{flown}: {}", outcome_text(&run.summary));
    let time = "time (s)";
    let altitude = Figure::new()
        .title(format!("Whole approach — {title}"))
        .panel(
            Panel::new(
                "Hook height, glide path and the landing point on the deck",
                time,
                "height above mean sea level (m)",
            )
            .series("hook", series(samples, |s| s.hook_h_m))
            .dashed_series(
                "glide path (hook reference)",
                series_where_applicable(samples, |s| s.path_height_m),
            )
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
            Panel::new("Pitch attitude and command", time, "pitch θ (deg)")
                .series(
                    "pitch command θ_ref",
                    series(samples, |s| s.theta_ref_rad.to_degrees()),
                )
                .series("pitch θ", series(samples, |s| s.theta_rad.to_degrees())),
        );
    let actuator = scenario.aircraft.elevator_actuator;
    let controls = Figure::new()
        .title(format!("Controls — {title}"))
        .panel(
            Panel::new(
                "Elevator (positive trailing edge down)",
                time,
                "elevator δe (deg)",
            )
            .series("elevator", series(samples, |s| s.elevator_rad.to_degrees()))
            .reference_line(
                format!("lower stop {}°", signed(actuator.min_deflection_deg)),
                actuator.min_deflection_deg,
            )
            .reference_line(
                format!("upper stop {}°", signed(actuator.max_deflection_deg)),
                actuator.max_deflection_deg,
            ),
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
            Panel::new("Angle of attack", time, "angle of attack α (deg)")
                .series("α", series(samples, |s| s.alpha_rad.to_degrees())),
        );
    let wind = Figure::new()
        .title(format!("Wind at the aircraft — {title}"))
        .panel(
            Panel::new(
                "Total wind in earth axes (mean, turbulence and air wake)",
                time,
                "wind (m/s)",
            )
            .series(
                "x (positive forward; headwind negative)",
                series(samples, |s| s.wind.x_mps),
            )
            .series("z (positive down)", series(samples, |s| s.wind.z_mps)),
        );
    vec![
        ("approach", approach_figure(run, scenario, flown)),
        ("altitude", altitude),
        ("glide_path_error", error),
        ("pitch", pitch),
        ("controls", controls),
        ("airspeed", airspeed),
        ("wind", wind),
    ]
}

/// `value` with its sign, a true minus for negative values: "+10", "−25".
pub(crate) fn signed(value: f64) -> String {
    if value < 0.0 {
        format!("\u{2212}{}", -value)
    } else {
        format!("+{value}")
    }
}

/// Flies `scenario`, writes every result into `output` and prints the summary (as text,
/// or as JSON with `json`). Shared by `land` and `run`.
pub fn fly_and_write(
    scenario: &Scenario,
    output: &OutputDir,
    controller: &str,
    conditions: &str,
    json: bool,
    with_plots: bool,
) -> Result<RunSummary> {
    let run = fly_approach(scenario).context("cannot set up the approach")?;
    let summary = run.summary.clone();
    let report = LandingReport {
        controller,
        conditions,
        seed: scenario.seed,
        summary: &summary,
    };
    let scenario_toml = toml::to_string(scenario).context("cannot write the scenario as TOML")?;
    output.write_bytes("scenario.toml", scenario_toml.as_bytes())?;
    let mut csv = csv::Writer::from_writer(Vec::new());
    for sample in &run.samples {
        csv.serialize(ApproachRow::from(sample))?;
    }
    let bytes = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
    output.write_bytes("approach.csv", &bytes)?;
    let summary_json = serde_json::to_string_pretty(&report)?;
    output.write_bytes("summary.json", summary_json.as_bytes())?;
    let flown = format!("{controller}, {conditions}, seed {}", scenario.seed);
    let mut plots = Vec::new();
    if with_plots {
        for (stem, figure) in figures(&run, scenario, &flown) {
            plots.push((stem, figure.save_with_svg(output, stem)?.1));
        }
    }
    let page = html_report(&report, &flown, &plots, &scenario_toml, &summary_json);
    output.write_bytes("report.html", page.as_bytes())?;
    if json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_summary(&report, output)?;
    }
    Ok(summary)
}

/// The rows of the summary table: quantity, value, unit — the numbers of `summary.json`,
/// rounded as the terminal prints them.
pub(crate) fn summary_rows(report: &LandingReport) -> Vec<Vec<String>> {
    let s = report.summary;
    let row = |quantity: &str, value: String, unit: &str| {
        vec![quantity.to_string(), value, unit.to_string()]
    };
    let mut rows = vec![
        row("controller", report.controller.to_string(), ""),
        row("conditions", report.conditions.to_string(), ""),
        row("seed", report.seed.to_string(), ""),
        row("outcome", s.outcome.name().to_string(), ""),
        row(
            "wire",
            s.wire.map_or_else(|| "—".to_string(), |w| w.to_string()),
            "",
        ),
    ];
    if let Some(reason) = &s.reason {
        rows.push(row("reason", reason.clone(), ""));
    }
    if let Some(t) = &s.touchdown {
        rows.extend([
            row("touchdown time", html::number(t.time_s, 2), "s"),
            row(
                "touchdown from the aim point (positive forward)",
                html::signed_number(t.distance_from_aim_m, 2),
                "m",
            ),
            row(
                "sink rate relative to the deck",
                html::number(t.sink_rate_mps, 2),
                "m/s",
            ),
            row("pitch at touchdown", html::number(t.pitch_deg, 2), "deg"),
            row(
                "airspeed at touchdown",
                html::number(t.airspeed_mps, 2),
                "m/s",
            ),
        ]);
    }
    rows.extend([
        row(
            "hook over the ramp",
            html::optional(s.ramp_clearance_m, 2),
            "m",
        ),
        row(
            "glide-path error, RMS",
            html::optional(s.glide_path_error_rms_m, 2),
            "m",
        ),
        row(
            "glide-path error, maximum",
            html::optional(s.glide_path_error_max_m, 2),
            "m",
        ),
        row("end of the run", html::number(s.end_time_s, 2), "s"),
        row("integration steps", s.steps.to_string(), ""),
    ]);
    rows
}

/// `report.html` of an approach: the summary, every plot, the scenario flown and
/// `summary.json` itself.
fn html_report(
    report: &LandingReport,
    flown: &str,
    plots: &[(&str, String)],
    scenario_toml: &str,
    summary_json: &str,
) -> String {
    let mut page = html::Report::new(format!(
        "Approach — {flown}: {}",
        outcome_text(report.summary)
    ));
    page.section("Summary")
        .paragraph(
            "The numbers of `summary.json`, rounded (the file itself is at the end of the page).",
        )
        .table(&["quantity", "value", "unit"], summary_rows(report));
    let plots_section = page.section("Plots");
    for (stem, svg) in plots {
        plots_section.figure(svg, format!("`{stem}.svg` (also `{stem}.png`)"));
    }
    page.section("Scenario flown")
        .paragraph("Every parameter of the run; `deckland run scenario.toml` flies it again.")
        .verbatim("scenario.toml", scenario_toml);
    page.section("summary.json")
        .verbatim("summary.json", summary_json);
    page.to_html()
}

fn print_summary(report: &LandingReport, output: &OutputDir) -> Result<()> {
    let s = report.summary;
    let outcome = match s.wire {
        Some(wire) => format!("{} (wire {wire})", s.outcome.name()),
        None => s.outcome.name().to_string(),
    };
    outln!(
        "Approach — {} pitch control, {} conditions, seed {}",
        report.controller,
        report.conditions,
        report.seed
    )?;
    outln!("  outcome               {outcome}")?;
    if let Some(reason) = &s.reason {
        outln!("  reason                {reason}")?;
    }
    if let Some(t) = &s.touchdown {
        outln!(
            "  touchdown             {:.2} s, {:+.1} m from the aim point (positive forward)",
            t.time_s,
            t.distance_from_aim_m
        )?;
        outln!(
            "  sink rate at deck     {:.2} m/s   pitch {:.1}°   airspeed {:.1} m/s",
            t.sink_rate_mps,
            t.pitch_deg,
            t.airspeed_mps
        )?;
    }
    if let Some(c) = s.ramp_clearance_m {
        outln!("  hook over the ramp    {c:.2} m")?;
    }
    if let (Some(rms), Some(max)) = (s.glide_path_error_rms_m, s.glide_path_error_max_m) {
        outln!("  glide-path error      RMS {rms:.2} m, max {max:.2} m")?;
    }
    let a = &s.actuator;
    outln!(
        "  elevator              rate RMS {:.1}°/s, on the rate limit {:.2} s ({:.1} %), \
         on the stops {:.2} s ({:.1} %), travel {:.0}°",
        a.elevator_rate_rms_degps,
        a.time_on_rate_limit_s,
        a.time_on_rate_limit_pct,
        a.time_on_stops_s,
        a.time_on_stops_pct,
        a.elevator_travel_deg
    )?;
    outln!(
        "  thrust rate           RMS {:.1} kN/s",
        a.thrust_rate_rms_knps
    )?;
    outln!("  results in            {}", output.path().display())?;
    Ok(())
}

/// Runs `deckland land`.
pub fn run(args: &LandArgs) -> Result<()> {
    let mut scenario = args.conditions.scenario(args.hardware.set(), args.seed);
    scenario.control.pitch = args.controller.parameters_for(&scenario);
    if args.no_deck_compensation {
        scenario.control.flight_path.deck_motion_compensation = false;
    }
    check_set_up(&scenario)?;
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
