//! `deckland campaign`: N approaches of a scenario file in parallel (Monte Carlo).
//!
//! Run `i` flies seed SplitMix64(S, i) (`deckland::monte_carlo::run_seed`) with the
//! scenario's dispersions drawn from that seed, on a pool of `--threads` workers; the
//! results are sorted by run index, so every file except the timing in `summary.json` is
//! identical for any thread count. Writes into the output folder:
//!
//! - `scenario.toml`: the nominal scenario flown;
//! - `runs.csv`: one row per run and controller (outcome, wire, touchdown, ramp
//!   clearance, glide-path error, the dispersions drawn, the failure reason);
//! - `summary.json`: outcome rates with 95 % Wilson score intervals, touchdown distance
//!   and sink-rate mean, standard deviation and percentiles, per controller;
//! - plots: `touchdown_dispersion` (touchdown point along the deck against sink rate,
//!   with the wires and the ramp), `touchdown_histograms`, `outcomes`.
//!
//! Ctrl-C or SIGTERM stops the workers before their next run; the finished runs are
//! written, marked `"partial": true`, and the command exits with status 130.
//!
//! `--runs` is at most [`MAX_RUNS`] and `--threads` at most [`MAX_THREADS`]: the records
//! of every run are kept in memory, and threads beyond the cores buy nothing.

use super::common::{check_set_up, load_scenario_file, seed_parser, OutputArgs};
use crate::html;
use crate::output::OutputDir;
use crate::plot::{BarGroup, Figure, Panel};
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::monte_carlo::{
    run_campaign, CampaignResult, CampaignSpec, CampaignStatistics, Distribution, Proportion,
    RunRecord, RunRow,
};
use deckland::scenario::{Mission, Scenario};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressState, ProgressStyle};
use serde::Serialize;
use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

/// Options of `deckland campaign`.
#[derive(Debug, Clone, Args)]
pub struct CampaignArgs {
    /// Scenario file (TOML); its `[dispersion]` section sets the per-run dispersions.
    pub scenario: PathBuf,
    /// Number of approaches (per controller with `--compare`), 1 to 100 000.
    #[arg(long, value_parser = clap::value_parser!(u64).range(1..=MAX_RUNS), allow_negative_numbers = true)]
    pub runs: u64,
    /// Campaign seed S, 0 to 2⁶³ − 1; run i flies seed SplitMix64(S, i) (default: the
    /// scenario's seed).
    #[arg(long, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: Option<u64>,
    /// Worker threads, 1 to 256 (default: the number of CPUs). The results do not depend
    /// on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=MAX_THREADS), allow_negative_numbers = true)]
    pub threads: Option<u16>,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
    /// Fly the same seeds and dispersions under O-PD and PID and report them side by side.
    #[arg(long)]
    pub compare: bool,
}

/// Most approaches of one campaign (per controller): a record of each is kept, about
/// 0.3 kB, and 100 000 runs already give a rate to ±0.3 points.
pub const MAX_RUNS: u64 = 100_000;

/// Most worker threads: more than the cores only adds switching.
pub const MAX_THREADS: i64 = 256;

/// What `summary.json` and `--json` hold.
#[derive(Debug, Serialize)]
struct CampaignReport<'a> {
    scenario_file: String,
    campaign_seed: u64,
    seed_derivation: &'static str,
    requested_runs: u64,
    finished_runs: u64,
    partial: bool,
    partial_note: Option<String>,
    threads: usize,
    elapsed_s: f64,
    runs_per_s: f64,
    confidence_interval: &'static str,
    percentiles: &'static str,
    controllers: &'a [CampaignStatistics],
}

/// Writes `runs.csv` (atomically, streamed to the file): one row per finished run and
/// controller, sorted by run index.
fn write_runs_csv(result: &CampaignResult, output: &OutputDir) -> Result<()> {
    output.write_with("runs.csv", |path| {
        let mut csv = csv::Writer::from_path(path)?;
        for record in &result.records {
            csv.serialize(RunRow::new(record, &result.controller_labels))?;
        }
        csv.flush()?;
        Ok(())
    })?;
    Ok(())
}

/// The progress bar on stderr: hidden when stderr is not a terminal or with `--json`.
fn progress_bar(total: u64, hidden: bool) -> ProgressBar {
    if hidden || !std::io::stderr().is_terminal() {
        return ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::hidden());
    }
    let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
    let style = ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} runs, {rate}, ETA {eta}",
    )
    .map(|s| {
        s.progress_chars("=> ").with_key(
            "rate",
            |state: &ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = write!(w, "{:.0} runs/s", state.per_sec());
            },
        )
    })
    .unwrap_or_else(|_| ProgressStyle::default_bar());
    bar.set_style(style);
    bar
}

/// The plots of a campaign, each with its file stem.
fn figures(
    result: &CampaignResult,
    scenario: &Scenario,
    title: &str,
) -> Vec<(&'static str, Figure)> {
    let deck = &scenario.environment.deck;
    let labels = &result.controller_labels;
    let touchdowns = |controller: usize| -> Vec<(f64, f64)> {
        result
            .records
            .iter()
            .filter(|r| r.controller == controller)
            .filter_map(|r| r.result.as_ref().ok().and_then(|s| s.touchdown))
            .map(|t| (t.distance_from_aim_m, t.sink_rate_mps))
            .collect()
    };
    let mut dispersion = Panel::new(
        "Touchdown point along the deck and sink rate relative to the deck",
        "touchdown along the deck from the aim point (m, positive forward)",
        "sink rate at touchdown (m/s)",
    );
    for (index, label) in labels.iter().enumerate() {
        let points = touchdowns(index);
        dispersion = dispersion.scatter(format!("{label} ({} touchdowns)", points.len()), points);
    }
    dispersion = dispersion.vertical_line("ramp", -deck.ramp_aft_of_aim_point_m);
    for (index, wire) in deck.wire_positions_m.iter().enumerate() {
        dispersion = dispersion.vertical_line(format!("wire {}", index + 1), *wire);
    }
    dispersion = dispersion.reference_line(
        "hard-landing limit",
        scenario.outcome.hard_landing_sink_rate_mps,
    );

    let bins = 30;
    let mut sink = Panel::new(
        "Touchdown sink rate relative to the deck",
        "sink rate (m/s)",
        "runs",
    );
    let mut distance = Panel::new(
        "Touchdown point along the deck from the aim point",
        "distance (m, positive forward)",
        "runs",
    );
    for (index, label) in labels.iter().enumerate() {
        let points = touchdowns(index);
        sink = sink.histogram(label.clone(), points.iter().map(|p| p.1).collect(), bins);
        distance = distance.histogram(label.clone(), points.iter().map(|p| p.0).collect(), bins);
    }

    let statistics = result.statistics();
    let categories = [
        "trap",
        "bolter",
        "wave-off",
        "ramp strike",
        "hard landing",
        "diverged",
        "timeout",
        "invalid",
    ];
    let mut outcomes = Panel::new(
        "Share of runs by outcome, with 95 % Wilson score intervals (bar labels: runs)",
        "outcome",
        "share of runs (%)",
    )
    .categories(categories.iter().map(|c| (*c).to_owned()).collect())
    .interval_name("95 % Wilson score interval");
    for s in &statistics {
        let classes = proportions(s);
        outcomes = outcomes.bar_group(BarGroup {
            name: format!("{} ({} runs)", s.controller, s.runs),
            values: classes.iter().map(|(_, p)| 100.0 * p.rate).collect(),
            intervals: classes
                .iter()
                .map(|(_, p)| (100.0 * p.ci95_low, 100.0 * p.ci95_high))
                .collect(),
            labels: classes.iter().map(|(_, p)| p.count.to_string()).collect(),
        });
    }
    vec![
        (
            "touchdown_dispersion",
            Figure::new()
                .title(format!("Touchdown dispersion — {title}"))
                .panel(dispersion),
        ),
        (
            "touchdown_histograms",
            Figure::new()
                .title(format!("Touchdown histograms — {title}"))
                .panel(sink)
                .panel(distance),
        ),
        (
            "outcomes",
            Figure::new()
                .title(format!("Outcomes — {title}"))
                .panel(outcomes),
        ),
    ]
}

/// The outcome classes with their names, in table order.
fn proportions(s: &CampaignStatistics) -> [(&'static str, Proportion); 8] {
    [
        ("boarding (trap)", s.boarding),
        ("bolter", s.bolter),
        ("wave-off (safe)", s.wave_off),
        ("ramp strike", s.ramp_strike),
        ("hard landing", s.hard_landing),
        ("diverged", s.divergence),
        ("timeout", s.timeout),
        ("invalid scenario", s.invalid),
    ]
}

/// The outcome table of `report.html`: per class and controller the count, the rate and
/// its 95 % Wilson score interval (%), as in `summary.json`.
fn outcome_rows(stats: &[CampaignStatistics]) -> Vec<Vec<String>> {
    let Some(first) = stats.first() else {
        return Vec::new();
    };
    (0..proportions(first).len())
        .map(|row| {
            let mut cells = vec![proportions(first)[row].0.to_string()];
            for s in stats {
                let (_, p) = proportions(s)[row];
                cells.push(p.count.to_string());
                cells.push(format!("{} %", html::number(100.0 * p.rate, 1)));
                cells.push(format!(
                    "[{}, {}] %",
                    html::number(100.0 * p.ci95_low, 1),
                    html::number(100.0 * p.ci95_high, 1)
                ));
            }
            cells
        })
        .collect()
}

/// The touchdown statistics of `report.html`: per quantity and controller the count,
/// mean, standard deviation, extremes and percentiles.
fn distribution_rows(stats: &[CampaignStatistics]) -> Vec<Vec<String>> {
    let quantities: [(&str, DistributionOf); 3] = [
        ("touchdown from the aim point (m, positive forward)", |s| {
            s.touchdown_distance_m
        }),
        ("touchdown sink rate relative to the deck (m/s)", |s| {
            s.touchdown_sink_rate_mps
        }),
        ("glide-path error RMS (m)", |s| s.glide_path_error_rms_m),
    ];
    let mut rows = Vec::new();
    for (name, get) in quantities {
        for s in stats {
            let mut cells = vec![name.to_string(), s.controller.clone()];
            match get(s) {
                Some(d) => {
                    cells.push(d.count.to_string());
                    cells.extend(
                        [
                            d.mean,
                            d.standard_deviation,
                            d.min,
                            d.p5,
                            d.p50,
                            d.p95,
                            d.max,
                        ]
                        .map(|v| html::number(v, 2)),
                    );
                }
                None => cells.extend(std::iter::repeat_n("—".to_string(), 8)),
            }
            rows.push(cells);
        }
    }
    rows
}

/// `report.html` of a campaign: what was flown, the outcome table with intervals, the
/// touchdown statistics, the plots and the scenario.
fn html_report(
    report: &CampaignReport,
    title: &str,
    plots: &[(&str, String)],
    scenario_toml: &str,
) -> String {
    let stats = report.controllers;
    let mut page = html::Report::new(format!("Campaign — {title}"));
    let flown = page.section("What was flown");
    flown.table(
        &["quantity", "value"],
        vec![
            vec!["scenario file".into(), report.scenario_file.clone()],
            vec!["campaign seed".into(), report.campaign_seed.to_string()],
            vec![
                "controllers".into(),
                stats
                    .iter()
                    .map(|s| s.controller.as_str())
                    .collect::<Vec<_>>()
                    .join(", "),
            ],
            vec![
                "runs requested per controller".into(),
                report.requested_runs.to_string(),
            ],
            vec![
                "runs finished (all controllers)".into(),
                report.finished_runs.to_string(),
            ],
        ],
    );
    flown.paragraph(report.seed_derivation);
    if let Some(note) = &report.partial_note {
        flown.paragraph(format!("**Partial:** {note}"));
    }
    let mut header = vec!["outcome".to_string()];
    for s in stats {
        header.push(format!("{}: runs (of {})", s.controller, s.runs));
        header.push(format!("{}: rate", s.controller));
        header.push(format!("{}: 95 % interval", s.controller));
    }
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    page.section("Outcomes")
        .paragraph(format!(
            "Intervals: the {}. The classes are exclusive and add up to the runs.",
            report.confidence_interval
        ))
        .table(&header, outcome_rows(stats));
    let wires: Vec<Vec<String>> = stats
        .iter()
        .map(|s| {
            let mut row = vec![s.controller.clone()];
            row.extend(s.traps_per_wire.iter().map(|w| w.to_string()));
            row
        })
        .collect();
    page.section("Touchdown")
        .paragraph(format!(
            "Over the runs that touched the deck; percentiles by {}.",
            report.percentiles
        ))
        .table(
            &[
                "quantity",
                "controller",
                "count",
                "mean",
                "sd",
                "min",
                "p5",
                "p50",
                "p95",
                "max",
            ],
            distribution_rows(stats),
        )
        .table(
            &["controller", "wire 1", "wire 2", "wire 3", "wire 4"],
            wires,
        );
    let plots_section = page.section("Plots");
    for (stem, svg) in plots {
        plots_section.figure(svg, format!("`{stem}.svg` (also `{stem}.png`)"));
    }
    page.section("Scenario flown")
        .paragraph("The nominal scenario; `runs.csv` lists each run's seed and dispersions.")
        .verbatim("scenario.toml", scenario_toml);
    page.to_html()
}

/// Picks one distribution out of a controller's statistics.
type DistributionOf = fn(&CampaignStatistics) -> Option<Distribution>;

fn print_table(report: &CampaignReport, output: &OutputDir) -> Result<()> {
    let stats = report.controllers;
    outln!(
        "Campaign — {}, {} runs{}, seed {}, {} threads, {:.1} s ({:.0} runs/s)",
        report.scenario_file,
        report.requested_runs,
        if stats.len() > 1 {
            " per controller"
        } else {
            ""
        },
        report.campaign_seed,
        report.threads,
        report.elapsed_s,
        report.runs_per_s
    )?;
    if let Some(note) = &report.partial_note {
        outln!("  PARTIAL: {note}")?;
    }
    let width = 30;
    let label_width = 36;
    out!("  {:<label_width$}", "")?;
    for s in stats {
        out!("{:>width$}", format!("{} ({} runs)", s.controller, s.runs))?;
    }
    outln!()?;
    outln!("  outcome: count, rate [95 % Wilson score interval]")?;
    for row in 0..7 {
        out!("  {:<label_width$}", proportions(&stats[0])[row].0)?;
        for s in stats {
            let (_, p) = proportions(s)[row];
            out!(
                "{:>width$}",
                format!(
                    "{:>5} {:5.1} % [{:5.1}, {:5.1}]",
                    p.count,
                    100.0 * p.rate,
                    100.0 * p.ci95_low,
                    100.0 * p.ci95_high
                )
            )?;
        }
        outln!()?;
    }
    out!("  {:<label_width$}", "traps on wires 1/2/3/4")?;
    for s in stats {
        let w = s.traps_per_wire;
        out!("{:>width$}", format!("{}/{}/{}/{}", w[0], w[1], w[2], w[3]))?;
    }
    outln!()?;
    let distribution_rows: [(&str, DistributionOf); 6] = [
        ("touchdown from aim (m)", |s| s.touchdown_distance_m),
        ("touchdown sink rate (m/s)", |s| s.touchdown_sink_rate_mps),
        ("elevator rate RMS (deg/s)", |s| s.elevator_rate_rms_degps),
        ("on the rate limit (% of run)", |s| s.time_on_rate_limit_pct),
        ("on the stops (% of run)", |s| s.time_on_stops_pct),
        ("thrust rate RMS (kN/s)", |s| s.thrust_rate_rms_knps),
    ];
    for (name, get) in distribution_rows {
        for (line, part) in [": mean ± sd", "  p5 / p50 / p95"].iter().enumerate() {
            let label = if line == 0 {
                format!("{name}{part}")
            } else {
                (*part).to_owned()
            };
            out!("  {label:<label_width$}")?;
            for s in stats {
                let text = match get(s) {
                    None => "–".to_owned(),
                    Some(d) if line == 0 => format!("{:+.2} ± {:.2}", d.mean, d.standard_deviation),
                    Some(d) => format!("{:+.2} / {:+.2} / {:+.2}", d.p5, d.p50, d.p95),
                };
                out!("{text:>width$}")?;
            }
            outln!()?;
        }
    }
    outln!("  results in {}", output.path().display())?;
    Ok(())
}

/// Runs `deckland campaign`.
pub fn run(args: &CampaignArgs) -> Result<()> {
    let scenario = load_scenario_file(&args.scenario)?;
    if !matches!(scenario.mission, Mission::Approach) {
        bail!(
            "{}: `mission.kind` is not \"approach\": a campaign flies approaches",
            args.scenario.display()
        );
    }
    // The nominal scenario must fly; a dispersed run that cannot is a row of the result.
    check_set_up(&scenario)?;
    let seed = args.seed.unwrap_or(scenario.seed);
    let mut spec = CampaignSpec::new(scenario, args.runs, seed);
    if args.compare {
        spec = spec.comparing_pitch_controllers();
    }
    let threads = args.threads.map_or_else(
        || {
            std::thread::available_parallelism()
                .map(|n| n.get())
                .unwrap_or(1)
                .min(MAX_THREADS as usize)
        },
        usize::from,
    );
    let output = OutputDir::prepare("campaign", args.output.out.as_deref(), args.output.force)?;
    let total = args.runs.saturating_mul(spec.controllers.len() as u64);
    let bar = progress_bar(total, args.output.json);
    let stop = crate::interrupt::graceful_stop();
    let started = Instant::now();
    let result = run_campaign(&spec, threads, &|_: &RunRecord| bar.inc(1), stop)
        .context("cannot run the campaign")?;
    let elapsed_s = started.elapsed().as_secs_f64();
    bar.finish_and_clear();

    let statistics = result.statistics();
    let finished_runs = result.records.len() as u64;
    let report = CampaignReport {
        scenario_file: args.scenario.display().to_string(),
        campaign_seed: seed,
        seed_derivation: "run i (from 0) flies seed SplitMix64 output i of the campaign seed, \
                          shifted right by one bit (mix(S + (i + 1)·0x9e3779b97f4a7c15) >> 1); \
                          its dispersions come from that seed's \"dispersion\" stream; \
                          `deckland run FILE --seed SEED --disperse` flies it again",
        requested_runs: args.runs,
        finished_runs,
        partial: result.partial,
        partial_note: result.partial.then(|| {
            format!(
                "stopped by Ctrl-C or SIGTERM: {finished_runs} of {total} runs finished; the statistics \
                 cover the finished runs only, listed by index in runs.csv"
            )
        }),
        threads,
        elapsed_s,
        runs_per_s: finished_runs as f64 / elapsed_s.max(1e-9),
        confidence_interval: "95 % Wilson score interval of each rate",
        percentiles: "linear interpolation between closest ranks (Hyndman & Fan type 7)",
        controllers: &statistics,
    };
    let scenario_toml =
        toml::to_string(&spec.scenario).context("cannot write the scenario as TOML")?;
    output.write_bytes("scenario.toml", scenario_toml.as_bytes())?;
    write_runs_csv(&result, &output)?;
    output.write_bytes(
        "summary.json",
        serde_json::to_string_pretty(&report)?.as_bytes(),
    )?;
    let name = args.scenario.file_name().map_or_else(
        || args.scenario.display().to_string(),
        |n| n.to_string_lossy().into_owned(),
    );
    let per_controller = statistics.first().map_or(0, |s| s.runs);
    let title = format!(
        "{name}, seed {seed}, {per_controller} runs{}",
        if statistics.len() > 1 {
            " per controller"
        } else {
            ""
        }
    );
    let mut plots = Vec::new();
    for (stem, figure) in figures(&result, &spec.scenario, &title) {
        plots.push((stem, figure.save_with_svg(&output, stem)?.1));
    }
    let page = html_report(&report, &title, &plots, &scenario_toml);
    output.write_bytes("report.html", page.as_bytes())?;
    if args.output.json {
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_table(&report, &output)?;
    }
    if result.partial {
        warnln!(
            "campaign stopped by Ctrl-C or SIGTERM: partial results ({finished_runs} of {total} runs) in {}",
            output.path().display()
        );
        std::process::exit(crate::interrupt::INTERRUPTED_STATUS);
    }
    Ok(())
}
