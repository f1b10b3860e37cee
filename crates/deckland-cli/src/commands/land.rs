//! `deckland land`: one approach from 1500 m to the moving deck, the main job.
//!
//! Writes into the output folder the scenario it flew (`scenario.toml`), a time series
//! (`approach.csv`, every 10 ms), the summary (`summary.json`) and plots (PNG and SVG):
//! altitude against the glide path and the deck, the glide-path error (paper Fig. 14),
//! pitch and pitch command (Fig. 15), elevator and thrust, airspeed, and the wind seen.

use super::common::{
    check_set_up, seed_parser, Conditions, ControllerChoice, FolderArgs, HardwareChoice,
};
use super::outcome::outcome_text;
use super::trap_sheet_file::trap_sheet_csv;
use crate::html;
use crate::output::OutputDir;
pub(crate) use crate::plot::land::figures;
use anyhow::{Context, Result};
use clap::Args;
use deckland::experiments::{fly_approach, ApproachRun};
use deckland::metrics::TrapSheetPosition;
use deckland::recording::acmi::{write_acmi, AcmiReference};
use deckland::scenario::Scenario;
use deckland::simulation::RunSummary;
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
    /// designed for them; the 3-D approach of the 6-DOF aircraft to the 9° angled deck of
    /// a ship steaming at 15 kn) or `paper` (the paper's ideal actuator and gains; its
    /// 3-DOF aircraft behind a stationary ship).
    #[arg(long, value_enum, default_value = "realistic")]
    pub hardware: HardwareChoice,
    /// Seed of every random stream, 0 to 2⁶³ − 1.
    #[arg(long, default_value_t = 1, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: u64,
    /// Fly without deck-motion compensation (track the mean deck to the end).
    #[arg(long)]
    pub no_deck_compensation: bool,
    /// The plots, the replay and the output folder.
    #[command(flatten)]
    pub written: ApproachFolderArgs,
}

/// What `land` and `run` write of the approach they fly, and where.
#[derive(Debug, Clone, Args)]
pub struct ApproachFolderArgs {
    /// Write no plots (the CSV, the summary and the scenario only).
    #[arg(long)]
    pub no_plots: bool,
    /// Also write the approach as a Tacview replay, `approach.acmi` (ACMI 2.2 text):
    /// the aircraft and the carrier every 0.1 s, the ramp crossing, the touchdown and
    /// the outcome as events.
    #[arg(long)]
    pub acmi: bool,
    /// Figure size, output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub folder: FolderArgs,
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

/// Flies `scenario`, writes every result into `output` and prints the summary (as text,
/// or as JSON with `json`). Shared by `land` and `run`.
pub fn fly_and_write(
    scenario: &Scenario,
    output: &OutputDir,
    controller: &str,
    conditions: &str,
    written: &ApproachFolderArgs,
) -> Result<RunSummary> {
    let run = fly_approach(scenario).context("cannot set up the approach")?;
    let flown = Flown {
        scenario,
        controller,
        conditions,
    };
    write_approach_folder(&run, &flown, output, !written.no_plots, written.acmi)?;
    let report = flown.report(&run.summary);
    if written.folder.output.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_summary(&report, output)?;
    }
    Ok(run.summary)
}

/// What was flown: the scenario, the pitch controller's label and the conditions' name.
pub struct Flown<'a> {
    /// The scenario flown (its seed is the run's).
    pub scenario: &'a Scenario,
    /// Pitch controller label.
    pub controller: &'a str,
    /// `ideal`, `adverse`, or the scenario file's name.
    pub conditions: &'a str,
}

impl Flown<'_> {
    fn report<'a>(&'a self, summary: &'a RunSummary) -> LandingReport<'a> {
        LandingReport {
            controller: self.controller,
            conditions: self.conditions,
            seed: self.scenario.seed,
            summary,
        }
    }
}

/// Writes a flown approach's files into `output`: `scenario.toml`, `approach.csv`,
/// `trap_sheet.csv`, `summary.json`, with `with_plots` the plots, with `with_acmi`
/// `approach.acmi`, and `report.html`.
pub fn write_approach_folder(
    run: &ApproachRun,
    flown: &Flown,
    output: &OutputDir,
    with_plots: bool,
    with_acmi: bool,
) -> Result<()> {
    let scenario = flown.scenario;
    let report = flown.report(&run.summary);
    let scenario_toml = toml::to_string(scenario).context("cannot write the scenario as TOML")?;
    output.write_bytes("scenario.toml", scenario_toml.as_bytes())?;
    let mut csv = csv::Writer::from_writer(Vec::new());
    for row in run.rows() {
        csv.serialize(row)?;
    }
    let bytes = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
    output.write_bytes("approach.csv", &bytes)?;
    let sheet = trap_sheet_csv(run, scenario.environment.deck.ramp_aft_of_aim_point_m)?;
    output.write_bytes("trap_sheet.csv", &sheet)?;
    let summary_json = serde_json::to_string_pretty(&report)?;
    output.write_bytes("summary.json", summary_json.as_bytes())?;
    let title = format!(
        "{}, {}, seed {}",
        flown.controller, flown.conditions, scenario.seed
    );
    let mut plots = Vec::new();
    if with_plots {
        for (stem, figure) in figures(run, scenario, &title) {
            plots.push((stem, figure.save_with_svg(output, stem)?.1));
        }
    }
    if with_acmi {
        let reference = AcmiReference {
            deck_angle_deg: scenario.environment.deck.deck_angle_deg,
            ..AcmiReference::default()
        };
        let replay = write_acmi(&reference, &title, &run.samples, &run.events, &run.summary);
        output.write_bytes("approach.acmi", replay.as_bytes())?;
    }
    let page = html_report(&report, &title, &plots, &scenario_toml, &summary_json);
    output.write_bytes("report.html", page.as_bytes())?;
    Ok(())
}

/// The rows of the summary table: quantity, value, unit — the numbers of `summary.json`,
/// rounded as the terminal prints them.
/// The trap sheet's name of `position`, with its window in nautical miles.
fn position_name(position: TrapSheetPosition) -> &'static str {
    match position {
        TrapSheetPosition::Start => "start, ¾–½ nmi",
        TrapSheetPosition::Middle => "middle, ½–¼ nmi",
        TrapSheetPosition::InClose => "in close, ¼–0.1 nmi",
        TrapSheetPosition::AtRamp => "at the ramp",
    }
}

pub(crate) fn summary_rows(report: &LandingReport) -> Vec<Vec<String>> {
    let s = report.summary;
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
        if let Some(l) = &t.lateral {
            rows.extend([
                row(
                    "off the landing centreline at touchdown (positive right)",
                    html::signed_number(l.offset_m, 2),
                    "m",
                ),
                row("off centre", l.off_centre.to_string(), ""),
                row(
                    "drift across the centreline, relative to the deck",
                    html::signed_number(l.drift_rate_mps, 2),
                    "m/s",
                ),
                row(
                    "bank at touchdown (right wing down positive)",
                    html::signed_number(l.bank_deg, 2),
                    "deg",
                ),
                row(
                    "heading to the centreline at touchdown",
                    html::signed_number(l.heading_to_centreline_deg, 2),
                    "deg",
                ),
                row(
                    "lineup error at the ramp, seen from the aim point",
                    l.ramp_lineup_error_deg
                        .map_or_else(|| "—".to_string(), |e| html::signed_number(e, 2)),
                    "deg",
                ),
            ]);
        }
    }
    if let Some(sheet) = &s.trap_sheet {
        for p in &sheet.positions {
            rows.push(row(
                &format!(
                    "trap sheet, {} ({}): glide slope mean / peak (+ high), lineup mean / peak (+ right)",
                    position_name(p.position),
                    p.position.shorthand()
                ),
                format!(
                    "{} / {} m; {} / {} m ({} / {}°)",
                    html::signed_number(p.glide_slope_mean_m, 2),
                    html::signed_number(p.glide_slope_peak_m, 2),
                    html::signed_number(p.lineup_mean_m, 2),
                    html::signed_number(p.lineup_peak_m, 2),
                    html::signed_number(p.lineup_mean_deg, 2),
                    html::signed_number(p.lineup_peak_deg, 2)
                ),
                "",
            ));
        }
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
        row(
            "deck within the recovery limits",
            html::number(s.deck_within_recovery_limits_pct, 1),
            "% of the time",
        ),
    ]);
    if let Some(text) = commit_forecast_text(s) {
        rows.push(row("forecast at the commit point", text, ""));
    }
    rows
}

/// What the forecast gave at the commit point (`RunSummary::commit_forecast`), in words:
/// "P(ramp strike) 2.7e-2, P(hard landing) 2.3e-4, P(off centre) 3.3e-38"; `None` for a
/// run that never reached it.
fn commit_forecast_text(s: &deckland::simulation::RunSummary) -> Option<String> {
    let c = s.commit_forecast?;
    let off_centre = c
        .off_centre_probability
        .map_or_else(String::new, |p| format!(", P(off centre) {p:.1e}"));
    Some(format!(
        "P(ramp strike) {:.1e}, P(hard landing) {:.1e}{off_centre}",
        c.ramp_strike_probability, c.hard_landing_probability
    ))
}

/// The actuator block of `report.html`, as the terminal prints it.
fn actuator_rows(report: &LandingReport) -> Vec<Vec<String>> {
    let a = &report.summary.actuator;
    vec![
        row(
            "elevator rate, RMS",
            html::number(a.elevator_rate_rms_degps, 1),
            "deg/s",
        ),
        row(
            "time on the elevator's rate limit",
            format!(
                "{} ({} %)",
                html::number(a.time_on_rate_limit_s, 2),
                html::number(a.time_on_rate_limit_pct, 1)
            ),
            "s",
        ),
        row(
            "time on the elevator's stops",
            format!(
                "{} ({} %)",
                html::number(a.time_on_stops_s, 2),
                html::number(a.time_on_stops_pct, 1)
            ),
            "s",
        ),
        row(
            "elevator travel Σ|Δδe|",
            html::number(a.elevator_travel_deg, 0),
            "deg",
        ),
        row(
            "thrust rate, RMS",
            html::number(a.thrust_rate_rms_knps, 1),
            "kN/s",
        ),
    ]
}

/// A row of the summary and actuator tables: quantity, value, unit.
fn row(quantity: &str, value: String, unit: &str) -> Vec<String> {
    vec![quantity.to_owned(), value, unit.to_owned()]
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
    page.section("Actuators")
        .paragraph(
            "What the stabilator and the engines did over the run (`actuator` in `summary.json`).",
        )
        .table(&["quantity", "value", "unit"], actuator_rows(report));
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
    if let Some(grade) = &s.lso_grade {
        let comment = if grade.comment.is_empty() {
            "no deviation called"
        } else {
            &grade.comment
        };
        outln!(
            "  LSO grade             {} ({} points): {comment}",
            grade.grade.shorthand(),
            grade.points
        )?;
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
        if let Some(l) = &t.lateral {
            outln!(
                "  lineup at touchdown   {:+.2} m off the centreline{}, drift {:+.2} m/s, bank {:+.1}°, heading {:+.1}° to it",
                l.offset_m,
                if l.off_centre { " (off centre)" } else { "" },
                l.drift_rate_mps,
                l.bank_deg,
                l.heading_to_centreline_deg
            )?;
            if let Some(e) = l.ramp_lineup_error_deg {
                outln!("  lineup at the ramp    {e:+.2}° seen from the aim point")?;
            }
        }
    }
    if let Some(c) = s.ramp_clearance_m {
        outln!("  hook over the ramp    {c:.2} m")?;
    }
    if let Some(sheet) = &s.trap_sheet {
        outln!("  trap sheet (mean deviation: glide slope + high, lineup + right)")?;
        for p in &sheet.positions {
            outln!(
                "    {:<3}{:<22}glide slope {:+.2} m, lineup {:+.2} m ({:+.2}° from the aim point)",
                p.position.shorthand(),
                position_name(p.position),
                p.glide_slope_mean_m,
                p.lineup_mean_m,
                p.lineup_mean_deg
            )?;
        }
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
    outln!(
        "  deck                  within the recovery limits {:.1} % of the time",
        s.deck_within_recovery_limits_pct
    )?;
    if let Some(text) = commit_forecast_text(s) {
        outln!("  commit point          forecast {text}")?;
    }
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
    let output = args.written.folder.prepare("land")?;
    fly_and_write(
        &scenario,
        &output,
        args.controller.label(),
        args.conditions.name(),
        &args.written,
    )?;
    Ok(())
}
