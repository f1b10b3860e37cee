//! `deckland rare`: the probability per approach of a catastrophe, by adaptive multilevel
//! splitting (docs/rare-events.md).
//!
//! Writes `summary.json` (the estimate, its 95 % interval, the levels, the work done and
//! what a plain campaign would have cost), `levels.csv` and the `levels` plot, `report.html`,
//! and under `event_flights/` each saved flight that reached the event, replayed from its
//! start along its branches: `approach.csv`, `summary.json` and the plots of `land`.

use super::campaign::{threads_or_cpus, MAX_THREADS};
use super::common::{load_scenario_file, seed_parser, OutputArgs};
use crate::commands::land::figures;
use crate::html::{number, Report};
use crate::output::print_stderr;
use crate::output::OutputDir;
use crate::plot::{Figure, Panel};
use crate::progress::Progress;
use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::rare::{
    estimate_rate, replay_event_flight, RareEvent, RareRequest, RareResult, Run, Stop,
};
use deckland::scenario::{Mission, Scenario};
use std::path::PathBuf;

/// Options of `deckland rare`.
#[derive(Debug, Clone, Args)]
pub struct RareArgs {
    /// Scenario file (TOML).
    pub scenario: PathBuf,
    /// The event: ramp_strike, hard_landing, off_centre (3-D approach), divergence, or
    /// lost (any of them).
    #[arg(long, value_parser = parse_event)]
    pub event: RareEvent,
    /// The event's threshold (default: the campaign's): a ramp clearance below it (m,
    /// 0 is a ramp strike), a touchdown sink rate above it (m/s), a touchdown offset
    /// from the centreline above it (m).
    #[arg(long, allow_negative_numbers = true)]
    pub threshold: Option<f64>,
    /// Stop once the estimate's relative standard error is at most this (0 to 1;
    /// checked from 32 repetitions on).
    #[arg(long, default_value_t = 0.1)]
    pub target_rel_error: f64,
    /// Stop once this many approaches' worth of simulation is spent.
    #[arg(long, default_value_t = 100_000)]
    pub max_runs: u64,
    /// Particles per splitting repetition.
    #[arg(long, default_value_t = 100)]
    pub particles: usize,
    /// Flights that calibrate the ramp's score first (`ramp_strike` and `lost`; 0, the
    /// plain score): the first runs of the campaign with the seed, whose forecasts' misses
    /// give the score its mean and spread at each time before the ramp (docs/rare-events.md).
    #[arg(long, default_value_t = 0)]
    pub calibrate_score: u64,
    /// Seed of the splitting, 0 to 2⁶³ − 1 (default: the file's `seed`).
    #[arg(long, value_parser = seed_parser(), allow_negative_numbers = true)]
    pub seed: Option<u64>,
    /// Worker threads, 1 to 256 (default: the number of CPUs). The result does not
    /// depend on it.
    #[arg(long, value_parser = clap::value_parser!(u16).range(1..=MAX_THREADS), allow_negative_numbers = true)]
    pub threads: Option<u16>,
    /// Flights that reached the event to save with their plots (at most 20).
    #[arg(long, default_value_t = 3)]
    pub save_flights: usize,
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub figures: crate::plot::FigureArgs,
    /// Output folder, overwriting and JSON printing.
    #[command(flatten)]
    pub output: OutputArgs,
}

fn parse_event(name: &str) -> Result<RareEvent, String> {
    RareEvent::from_name(name)
}

/// Runs `deckland rare`.
pub fn run(args: &RareArgs) -> Result<()> {
    let scenario = load_scenario_file(&args.scenario)?;
    if !matches!(scenario.mission, Mission::Approach) {
        bail!(
            "{}: `mission.kind` is not \"approach\": `deckland rare` estimates the rates of \
             approaches",
            args.scenario.display()
        );
    }
    let request = RareRequest {
        threshold: args.threshold,
        target_rel_error: args.target_rel_error,
        max_runs: args.max_runs,
        particles: args.particles,
        calibration_runs: args.calibrate_score,
        ..RareRequest::new(args.event, args.seed.unwrap_or(scenario.seed))
    };
    // The scenario must fly and be scored before the output folder is made.
    request.start_plain(&scenario)?;
    let threads = threads_or_cpus(args.threads);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .with_context(|| format!("cannot start {threads} worker threads"))?;
    let output = OutputDir::prepare("rare", args.output.out.as_deref(), args.output.force)?;
    let bar = Progress::spinner("rare");
    let started = std::time::Instant::now();
    let result = pool
        .install(|| estimate_rate(&scenario, &request, |r, run| show(&bar, r, run)))
        .with_context(|| {
            format!(
                "cannot estimate the rate within --max-runs {} (a repetition of {} particles \
                 must finish within its share of it: raise --max-runs)",
                args.max_runs, args.particles
            )
        })?;
    bar.finish_and_clear();
    let elapsed_s = started.elapsed().as_secs_f64();
    warn_if_extinct(&result);
    write_outputs(&scenario, &result, &output, args.save_flights, elapsed_s)?;
    if args.output.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&Summary::of(&result, elapsed_s, &output))?
        )?;
    } else {
        print_result(&result, elapsed_s, &output)?;
    }
    Ok(())
}

fn show(bar: &Progress, repetition: u64, run: &Run) {
    // A repetition stopped by its share of the budget has no estimate: say so, with why.
    let estimate = run
        .estimate
        .map_or_else(|| run.outcome.to_string(), |p| format!("estimate {p:.3e}"));
    bar.message(format!(
        "splitting repetition {}: {} levels, {estimate}",
        repetition + 1,
        run.levels.len(),
    ));
}

/// `summary.json`: the result with the time taken and where the files are.
#[derive(serde::Serialize)]
struct Summary<'a> {
    #[serde(flatten)]
    result: &'a RareResult,
    elapsed_s: f64,
    folder: String,
    method: &'static str,
}

impl<'a> Summary<'a> {
    fn of(result: &'a RareResult, elapsed_s: f64, output: &OutputDir) -> Self {
        Self {
            result,
            elapsed_s,
            folder: output.path().display().to_string(),
            method: "generalised adaptive multilevel splitting (Bréhier, Gazeau, Goudenège, \
                     Lelièvre & Rousset, Ann. Appl. Probab. 26, 2016) over the event's score; \
                     independent repetitions, 95 % Student-t interval on the log of their mean",
        }
    }
}

pub(crate) fn write_outputs(
    scenario: &Scenario,
    result: &RareResult,
    output: &OutputDir,
    save_flights: usize,
    elapsed_s: f64,
) -> Result<()> {
    output.write_bytes(
        "scenario.toml",
        toml::to_string(scenario)
            .context("cannot write the scenario as TOML")?
            .as_bytes(),
    )?;
    let summary = serde_json::to_string_pretty(&Summary::of(result, elapsed_s, output))?;
    output.write_bytes("summary.json", summary.as_bytes())?;
    let mut levels = String::from("repetition,iteration,level\n");
    for (r, run_levels) in result.levels.iter().enumerate() {
        for (q, level) in run_levels.iter().enumerate() {
            levels.push_str(&format!("{r},{q},{level}\n"));
        }
    }
    output.write_bytes("levels.csv", levels.as_bytes())?;
    let (_, svg) = levels_figure(result).save_with_svg(output, "levels")?;
    let flights = save_event_flights(scenario, result, output, save_flights)?;
    let page = report_page(result, &svg, &flights, &summary);
    output.write_bytes("report.html", page.as_bytes())?;
    Ok(())
}

/// The levels of each repetition against the iteration, with the event's 0.
fn levels_figure(result: &RareResult) -> Figure {
    let mut panel = Panel::new(
        format!(
            "Splitting levels of `{}`: each repetition climbs to the event (score 0)",
            result.request.event.name()
        ),
        "iteration",
        "level of the event's score",
    );
    for (r, levels) in result.levels.iter().enumerate().take(12) {
        let points = levels
            .iter()
            .enumerate()
            .filter(|(_, level)| level.is_finite())
            .map(|(q, level)| (q as f64, *level))
            .collect();
        panel = panel.series(format!("repetition {}", r + 1), points);
    }
    Figure::new()
        .title("deckland rare: the levels' progression")
        .panel(panel.reference_line("the event", 0.0))
}

/// Replays and writes up to `count` flights that reached the event; their folder names.
fn save_event_flights(
    scenario: &Scenario,
    result: &RareResult,
    output: &OutputDir,
    count: usize,
) -> Result<Vec<String>> {
    let mut names = Vec::new();
    for (r, particle) in result.event_flights.iter().take(count.min(20)) {
        let Some(run) =
            replay_event_flight(scenario, result.thresholds, result.request.event, particle)?
        else {
            continue;
        };
        let name = format!("event_flights/{:02}", names.len() + 1);
        let folder = OutputDir::prepare("rare", Some(&output.path().join(&name)), true)?;
        let mut csv = csv::Writer::from_writer(Vec::new());
        for row in run.rows() {
            csv.serialize(row)?;
        }
        let bytes = csv.into_inner().map_err(|e| anyhow::anyhow!("{e}"))?;
        folder.write_bytes("approach.csv", &bytes)?;
        let lineage = serde_json::json!({
            "repetition": r,
            "particle": particle,
            "summary": run.summary,
        });
        folder.write_bytes(
            "summary.json",
            serde_json::to_string_pretty(&lineage)?.as_bytes(),
        )?;
        let flown = format!(
            "{} flight {} of `deckland rare` (repetition {}, {} branches)",
            result.request.event.name(),
            names.len() + 1,
            r + 1,
            particle.lineage.len()
        );
        for (stem, figure) in figures(&run, scenario, &flown) {
            figure.save(&folder, stem)?;
        }
        names.push(name);
    }
    Ok(names)
}

fn report_page(result: &RareResult, levels_svg: &str, flights: &[String], summary: &str) -> String {
    let mut report = Report::new(format!("deckland rare: {}", result.request.event.name()));
    report
        .section("Estimate")
        .table(&["quantity", "value"], result_rows(result))
        .paragraph(
            "The probability per approach, by adaptive multilevel splitting over the event's \
             score (docs/rare-events.md); the interval is 95 %.",
        );
    report.section("Levels").figure(
        levels_svg,
        "Each repetition's levels (score units; the event is 0).",
    );
    let flights_section = report.section("Flights that reached the event");
    if flights.is_empty() {
        flights_section.paragraph("None saved.");
    } else {
        flights_section.paragraph(format!(
            "Replayed from the start along their branches, with `land`'s files and plots: {}.",
            flights.join(", ")
        ));
    }
    report
        .section("summary.json")
        .verbatim("summary.json", summary);
    report.to_html()
}

fn result_rows(result: &RareResult) -> Vec<Vec<String>> {
    let e = &result.estimate;
    let row = |q: &str, v: String| vec![q.to_owned(), v];
    let (low, high) = e.interval.unwrap_or((f64::NAN, f64::NAN));
    vec![
        row("event", result.request.event.name().to_owned()),
        row("probability per approach", format!("{:.3e}", e.probability)),
        row("95 % interval", format!("{low:.3e} – {high:.3e}")),
        row(
            "relative standard error",
            e.relative_standard_error
                .map_or_else(|| "—".to_owned(), |r| number(100.0 * r, 1) + " %"),
        ),
        row(
            "repetitions (extinct)",
            format!("{} ({})", e.repetitions, e.extinct_repetitions),
        ),
        row("approaches spent", number(result.approaches_spent, 0)),
        row(
            "a plain campaign would need",
            result
                .brute_force_approaches
                .map_or_else(|| "—".to_owned(), |n| format!("{n:.3e} approaches")),
        ),
        row("stopped", stop_text(e.stop).to_owned()),
    ]
}

fn stop_text(stop: Stop) -> &'static str {
    match stop {
        Stop::TargetMet => "the target relative error was met",
        Stop::MaxRepetitions => "the most repetitions were run",
        Stop::StepBudget => "the budget (--max-runs) was spent before the target: a partial result",
        Stop::IterationLimit => "a repetition reached its iteration limit: a partial result",
    }
}

fn print_result(result: &RareResult, elapsed_s: f64, output: &OutputDir) -> Result<()> {
    for row in result_rows(result) {
        outln!("{:<28} {}", row[0], row[1])?;
    }
    if let Some(factor) = result.cost_factor {
        outln!(
            "{:<28} {:.2} % of a plain campaign's approaches",
            "cost",
            100.0 * factor
        )?;
    }
    outln!("{:<28} {:.0} s", "time", elapsed_s)?;
    outln!("results in {}", output.path().display())?;
    Ok(())
}

/// The warning of an estimate of 0: every repetition went extinct (on stderr, with or
/// without `--json`, which also holds `extinct_repetitions`).
fn warn_if_extinct(result: &RareResult) {
    let e = &result.estimate;
    if e.probability == 0.0 {
        let level = result
            .levels
            .iter()
            .filter_map(|levels| levels.last())
            .fold(f64::NEG_INFINITY, |a, b| a.max(*b));
        print_stderr(format_args!(
            "warning: no repetition reached the event: every one went extinct, the highest \
             level {level:.3} (0 is the event); the event may be out of reach of this \
             scenario, or rarer than these {} repetitions can show\n",
            e.repetitions
        ));
    }
}
