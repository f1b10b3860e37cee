//! What a campaign folder holds, written the same way for a campaign flown whole, one of
//! its shards, and a campaign merged from its shards (`deckland merge`): `scenario.toml`,
//! `runs.csv`, `runs.parquet`, `summary.json`, the plots and `report.html`, all computed
//! from the rows of `runs.csv` and the library's [`CampaignSummary`], so a merged
//! campaign's files are those of the campaign flown whole.

use super::folder::{proportions, CampaignFolder, CampaignReport};
use super::paired::PairedComparison;
use crate::html;
use crate::output::OutputDir;
use crate::plot::campaign::figures;
use anyhow::Result;
use deckland::monte_carlo::{
    runs_csv_text, CampaignStatistics, CampaignSummary, Distribution, Proportion,
    UPPER_BOUND_CONFIDENCE,
};

/// Classes seen at most this many times get their upper bound spelt out in the report.
const RARE_COUNT: u64 = 3;

/// Writes the folder's files, each atomically: `scenario.toml`, `runs.csv`,
/// `runs.parquet` (when a run finished), `summary.json`, the plots and `report.html`.
pub fn write_folder(folder: &CampaignFolder, output: &OutputDir) -> Result<()> {
    output.write_bytes("scenario.toml", folder.scenario_toml.as_bytes())?;
    output.write_with("runs.csv", |path| {
        let text = runs_csv_text(folder.table)?;
        std::fs::write(path, text)?;
        Ok(())
    })?;
    if !folder.table.rows.is_empty() {
        output.write_with("runs.parquet", |path| {
            crate::parquet::write_runs(path, folder.table)
        })?;
    }
    output.write_bytes(
        "summary.json",
        serde_json::to_string_pretty(folder.report)?.as_bytes(),
    )?;
    let mut plots = Vec::new();
    for (stem, figure) in figures(folder) {
        plots.push((stem, figure.save_with_svg(output, stem)?.1));
    }
    let controllers: Vec<&str> = folder
        .report
        .summary
        .controllers
        .iter()
        .map(|s| s.controller.as_str())
        .collect();
    let paired = PairedComparison::of(&folder.table.rows, &controllers);
    let page = html_report(
        folder.report,
        paired.as_ref(),
        &folder.title,
        &plots,
        folder.scenario_toml,
    );
    output.write_bytes("report.html", page.as_bytes())?;
    Ok(())
}

/// The columns of a distribution's statistics, in the order the tables' rows give them.
const STATISTIC_COLUMNS: [&str; 8] = ["count", "mean", "sd", "min", "p5", "p50", "p95", "max"];

/// A table's header: the columns `first`, the statistics' columns, then `last`.
fn statistics_header<'a>(first: &[&'a str], last: &[&'a str]) -> Vec<&'a str> {
    [first, &STATISTIC_COLUMNS[..], last].concat()
}

/// The outcomes after which the aircraft is intact, aboard or flying: a trap, a bolter or a
/// wave-off (docs/model.md §9), as a proportion of the runs.
fn safe(s: &CampaignStatistics) -> Proportion {
    Proportion::new(s.boarding.count + s.bolter.count + s.wave_off.count, s.runs)
}

/// The rows of the outcome tables: the classes, exclusive and in table order, with the
/// safe outcomes (trap, bolter, wave-off) followed by their total.
fn outcome_table(s: &CampaignStatistics) -> Vec<(&'static str, Proportion)> {
    let mut rows = proportions(s).to_vec();
    rows.insert(3, ("safe: trap, bolter or wave-off", safe(s)));
    rows
}

/// The failures: the outcomes that are not safe, whose probability a campaign bounds.
const FAILURES: [&str; 4] = ["ramp strike", "hard landing", "diverged", "timeout"];

/// The outcome table of `report.html`: per class and controller the count, the rate and
/// its 95 % Wilson score interval (%), as in `summary.json`.
fn outcome_rows(stats: &[CampaignStatistics]) -> Vec<Vec<String>> {
    let Some(first) = stats.first() else {
        return Vec::new();
    };
    (0..outcome_table(first).len())
        .map(|row| {
            let mut cells = vec![outcome_table(first)[row].0.to_string()];
            for s in stats {
                let (_, p) = outcome_table(s)[row];
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
    statistics_rows(
        stats,
        &[
            ("touchdown from the aim point (m, positive forward)", |s| {
                s.touchdown_distance_m
            }),
            ("touchdown sink rate relative to the deck (m/s)", |s| {
                s.touchdown_sink_rate_mps
            }),
            ("hook over the ramp (m, the ramp-strike margin)", |s| {
                s.ramp_clearance_m
            }),
            ("glide-path error RMS (m)", |s| s.glide_path_error_rms_m),
        ],
    )
}

/// The actuator statistics of `report.html`, as the terminal shows them.
fn actuator_rows(stats: &[CampaignStatistics]) -> Vec<Vec<String>> {
    statistics_rows(
        stats,
        &ACTUATOR_QUANTITIES.map(|(name, _, get)| (name, get)),
    )
}

/// The actuator quantities: name, whether it carries a sign, and where it is.
const ACTUATOR_QUANTITIES: [(&str, bool, DistributionOf); 5] = [
    ("elevator rate RMS (deg/s)", false, |s| {
        s.elevator_rate_rms_degps
    }),
    ("on the rate limit (% of run)", false, |s| {
        s.time_on_rate_limit_pct
    }),
    ("on the stops (% of run)", false, |s| s.time_on_stops_pct),
    ("elevator total travel (deg)", false, |s| {
        s.elevator_travel_deg
    }),
    ("thrust rate RMS (kN/s)", false, |s| s.thrust_rate_rms_knps),
];

/// The paired differences of `report.html`.
fn paired_rows(paired: &PairedComparison) -> Vec<Vec<String>> {
    paired
        .differences
        .iter()
        .map(|q| {
            let mut cells = vec![q.name.to_string()];
            match (q.difference, q.largest_abs) {
                (Some(d), Some(largest)) => {
                    cells.extend(distribution_cells(&d));
                    cells.push(html::number(largest, 2));
                }
                _ => cells.extend(std::iter::repeat_n("—".to_string(), 9)),
            }
            cells
        })
        .collect()
}

/// A distribution's cells: its count, mean, standard deviation, minimum, p5, p50, p95
/// and maximum.
fn distribution_cells(d: &Distribution) -> impl Iterator<Item = String> {
    std::iter::once(d.count.to_string()).chain(
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
    )
}

/// Per quantity and controller: the count, mean, standard deviation, extremes and
/// percentiles.
fn statistics_rows(
    stats: &[CampaignStatistics],
    quantities: &[(&str, DistributionOf)],
) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    for &(name, get) in quantities {
        for s in stats {
            let mut cells = vec![name.to_string(), s.controller.clone()];
            match get(s) {
                Some(d) => {
                    cells.extend(distribution_cells(&d));
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
/// Whether a campaign plot draws the touchdowns (shown under their statistics).
fn is_touchdown_plot(stem: &str) -> bool {
    stem.starts_with("touchdown")
}

/// Adds to `section` the plots whose stem `keep` accepts, in their order, each captioned
/// with its files: so each plot stands beside the table it draws, and the outcomes'
/// chart, above their table, is on the report's first screen.
fn add_plots(section: &mut html::Section, plots: &[(&str, String)], keep: impl Fn(&str) -> bool) {
    for (stem, svg) in plots.iter().filter(|(stem, _)| keep(stem)) {
        section.figure(svg, format!("`{stem}.svg` (also `{stem}.png`)"));
    }
}

fn html_report(
    report: &CampaignReport,
    paired: Option<&PairedComparison>,
    title: &str,
    plots: &[(&str, String)],
    scenario_toml: &str,
) -> String {
    let stats = &report.summary.controllers;
    let mut page = html::Report::new(format!("Campaign — {title}"));
    let flown = page.section("What was flown");
    flown.table(
        &["quantity", "value"],
        vec![
            vec!["scenario file".into(), report.scenario_file.clone()],
            vec![
                "campaign seed".into(),
                report.summary.campaign_seed.to_string(),
            ],
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
                report.summary.requested_runs.to_string(),
            ],
            vec![
                "runs finished (all controllers)".into(),
                report.summary.finished_runs.to_string(),
            ],
        ],
    );
    flown.paragraph(report.summary.seed_derivation);
    if let Some(note) = &report.summary.partial_note {
        flown.paragraph(format!("**Partial:** {note}"));
    }
    let mut header = vec!["outcome".to_string()];
    for s in stats {
        header.push(format!("{}: runs (of {})", s.controller, s.runs));
        header.push(format!("{}: rate", s.controller));
        header.push(format!("{}: 95 % interval", s.controller));
    }
    let header: Vec<&str> = header.iter().map(String::as_str).collect();
    let distribution_header = statistics_header(&["quantity", "controller"], &[]);
    let outcomes = page.section("Outcomes");
    outcomes.paragraph(format!(
        "Intervals: the {}. The classes are exclusive and add up to the runs; the safe \
         outcomes (trap, bolter, wave-off: the aircraft is intact) are also totalled.",
        report.summary.confidence_interval
    ));
    outcomes.paragraph(
        "The greenie board: the landing signal officer's grade of every flown pass \
         (docs/model.md §11), its points (OK 4, fair 3, bolter 2.5, no grade and own \
         wave-off 2, cut 0), the wires caught and the deviations called most often.",
    );
    // The board beside the outcomes' chart, so that both stand on the first screen.
    outcomes.html(format!(
        "<div style=\"display:flex;gap:1em;align-items:flex-start\">\n\
         <div style=\"flex:2;min-width:0\">\n{}</div>\n<div style=\"flex:3;min-width:0\">\n",
        super::greenie::board_html(stats)
    ));
    add_plots(outcomes, plots, |stem| stem == "outcomes");
    outcomes.html("</div>\n</div>\n");
    outcomes.table(&header, outcome_rows(stats));
    let wires: Vec<Vec<String>> = stats
        .iter()
        .map(|s| {
            let mut row = vec![s.controller.clone()];
            row.extend(s.traps_per_wire.iter().map(|w| w.to_string()));
            row
        })
        .collect();
    let touchdown = page.section("Touchdown");
    touchdown
        .paragraph(format!(
            "Over the runs that touched the deck; percentiles by {}.",
            report.summary.percentiles
        ))
        .table(&distribution_header, distribution_rows(stats))
        .table(
            &["controller", "wire 1", "wire 2", "wire 3", "wire 4"],
            wires,
        );
    add_plots(touchdown, plots, is_touchdown_plot);
    if let Some(lateral) = &report.lateral {
        lineup_section(page.section("Lineup (3-D approach)"), lateral);
    }
    if let Some(sheet) = &report.trap_sheet {
        super::trap_sheet::html_section(page.section("LSO trap sheet (3-D approach)"), sheet);
    }
    page.section("Actuators")
        .paragraph(format!(
            "Over the runs flown, per run; percentiles by {}.",
            report.summary.percentiles
        ))
        .table(&distribution_header, actuator_rows(stats));
    if let Some(paired) = paired {
        page.section("Paired differences")
            .paragraph(format!(
                "Both controllers fly every run with the same seed (the same dispersions, \
                 turbulence and sea), so each run gives one difference {} − {}. {} runs \
                 flown by both; the outcome or the wire differs in {}. Over the runs where \
                 both have the quantity:",
                paired.second, paired.first, paired.pairs, paired.different_outcomes
            ))
            .table(
                &statistics_header(&["difference"], &["largest |difference|"]),
                paired_rows(paired),
            );
    }
    let target = &report.summary.rare_event_target;
    page.section("Rare events")
        .paragraph(format!(
            "The failures ({}) seen at most {RARE_COUNT} times, with the {} — what the \
             runs show the probability to be below. Safe outcomes (trap, bolter, \
             wave-off) are not failures.",
            FAILURES.join(", "),
            report.summary.upper_bound
        ))
        .table(
            &[
                "controller",
                "failure",
                "runs with it",
                "runs",
                "95 % upper bound",
            ],
            rare_event_rows(report.summary),
        )
        .paragraph(format!(
            "To show a probability below {:e} at {} % takes {}.",
            target.rate,
            100.0 * target.confidence,
            runs_needed(report.summary)
        ));
    if super::calibration::any(stats) {
        super::calibration::html_section(page.section("Calibration at the commit point"), stats);
    }
    let others = |stem: &str| stem != "outcomes" && !is_touchdown_plot(stem);
    if plots.iter().any(|(stem, _)| others(stem)) {
        add_plots(page.section("Plots"), plots, others);
    }
    page.section("Scenario flown")
        .paragraph("The nominal scenario; `runs.csv` lists each run's seed and dispersions.")
        .verbatim("scenario.toml", scenario_toml);
    page.to_html()
}

/// Picks one distribution out of a controller's statistics.
type DistributionOf = fn(&CampaignStatistics) -> Option<Distribution>;

/// Prints the report as a table on stdout, then where the results are.
pub fn print_table(report: &CampaignReport, output: &OutputDir) -> Result<()> {
    print_statistics(report)?;
    outln!("  results in {}", output.path().display())?;
    Ok(())
}

/// Prints the campaign's statistics as a table on stdout.
pub fn print_statistics(report: &CampaignReport) -> Result<()> {
    let stats = &report.summary.controllers;
    let how = match (report.threads, report.runs_per_s) {
        (Some(threads), Some(rate)) => format!(
            "{threads} threads, {:.1} s ({rate:.0} runs/s)",
            report.elapsed_s
        ),
        _ => format!(
            "merged from {} shards in {:.1} s",
            report.merged_from.len(),
            report.elapsed_s
        ),
    };
    let shard = if report.shard == "0/1" {
        String::new()
    } else {
        format!(", shard {}", report.shard)
    };
    outln!(
        "Campaign — {}, {} runs{}{shard}, seed {}, {how}",
        report.scenario_file,
        report.summary.requested_runs,
        if stats.len() > 1 {
            " per controller"
        } else {
            ""
        },
        report.summary.campaign_seed,
    )?;
    if let Some(note) = &report.summary.partial_note {
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
    for row in 0..outcome_table(&stats[0]).len() {
        out!("  {:<label_width$}", outcome_table(&stats[0])[row].0)?;
        for s in stats {
            let (_, p) = outcome_table(s)[row];
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
    super::greenie::print(stats, label_width, width)?;
    if let Some(lateral) = &report.lateral {
        print_lateral(lateral)?;
    }
    if let Some(sheet) = &report.trap_sheet {
        super::trap_sheet::print(sheet)?;
    }
    let touchdown: [(&str, bool, DistributionOf); 3] = [
        ("touchdown from aim (m)", true, |s| s.touchdown_distance_m),
        ("touchdown sink rate (m/s)", false, |s| {
            s.touchdown_sink_rate_mps
        }),
        ("hook over the ramp (m)", false, |s| s.ramp_clearance_m),
    ];
    for (name, signed, get) in touchdown.into_iter().chain(ACTUATOR_QUANTITIES) {
        for (line, part) in [": mean ± sd", "  p5 / p50 / p95"].iter().enumerate() {
            let label = if line == 0 {
                format!("{name}{part}")
            } else {
                (*part).to_owned()
            };
            out!("  {label:<label_width$}")?;
            // A sign only where the quantity has one (a distance from the aim point).
            let number = |v: f64| {
                if signed {
                    format!("{v:+.2}")
                } else {
                    format!("{v:.2}")
                }
            };
            for s in stats {
                let text = match get(s) {
                    None => "–".to_owned(),
                    Some(d) if line == 0 => {
                        format!("{} ± {:.2}", number(d.mean), d.standard_deviation)
                    }
                    Some(d) => format!("{} / {} / {}", number(d.p5), number(d.p50), number(d.p95)),
                };
                out!("{text:>width$}")?;
            }
            outln!()?;
        }
    }
    for line in deck_within_limits_lines(stats) {
        outln!("  {line}")?;
    }
    for line in rare_event_lines(report.summary) {
        outln!("  {line}")?;
    }
    super::calibration::print(stats)
}

/// The share of the runs' time with the true deck within the recovery limits
/// (`deck_within_limits_pct` of `runs.csv`): its mean and its least over the flown runs,
/// one line per controller (named when there are several); none without a flown run.
pub fn deck_within_limits_lines(stats: &[CampaignStatistics]) -> Vec<String> {
    stats
        .iter()
        .filter_map(|s| {
            let d = s.deck_within_limits_pct?;
            let whose = if stats.len() > 1 {
                format!(" ({})", s.controller)
            } else {
                String::new()
            };
            Some(format!(
                "deck within the recovery limits{whose}: mean {:.1} % of the time (min {:.1} %)",
                d.mean, d.min
            ))
        })
        .collect()
}

/// Prints the paired differences of `campaign --compare` on stdout.
pub fn print_paired(paired: &PairedComparison) -> Result<()> {
    outln!("  {}", paired.heading())?;
    let label_width = 36;
    outln!(
        "  {:<label_width$}{:>16}{:>26}{:>10}",
        "difference",
        "mean ± sd",
        "p5 / p50 / p95",
        "max |Δ|"
    )?;
    for q in &paired.differences {
        match (q.difference, q.largest_abs) {
            (Some(d), Some(largest)) => outln!(
                "  {:<label_width$}{:>16}{:>26}{:>10}",
                q.name,
                format!("{:+.2} ± {:.2}", d.mean, d.standard_deviation),
                format!("{:+.2} / {:+.2} / {:+.2}", d.p5, d.p50, d.p95),
                format!("{largest:.2}")
            )?,
            _ => outln!("  {:<label_width$}{:>16}", q.name, "–")?,
        }
    }
    Ok(())
}

/// A probability in words: percent down to 0.01 %, else in powers of ten.
fn probability(p: f64) -> String {
    if p >= 1e-4 {
        format!("{:.2} %", 100.0 * p)
    } else {
        format!("{p:.2e}")
    }
}

/// "1 event", "2 events".
fn events(count: u64) -> String {
    if count == 1 {
        "1 event".to_owned()
    } else {
        format!("{count} events")
    }
}

/// The failures seen at most [`RARE_COUNT`] times, per controller: controller, failure,
/// runs with it, runs, and its 95 % upper bound.
pub fn rare_event_rows(summary: &CampaignSummary) -> Vec<Vec<String>> {
    let mut rows = Vec::new();
    for s in summary.controllers.iter().filter(|s| s.runs > 0) {
        for (name, p) in proportions(s) {
            if FAILURES.contains(&name) && p.count <= RARE_COUNT {
                rows.push(vec![
                    s.controller.clone(),
                    name.to_owned(),
                    p.count.to_string(),
                    s.runs.to_string(),
                    format!("p < {}", probability(p.upper_bound_95)),
                ]);
            }
        }
    }
    rows
}

/// The runs it takes to show the target rate, for 0 to 3 events.
fn runs_needed(summary: &CampaignSummary) -> String {
    summary
        .rare_event_target
        .runs_needed
        .iter()
        .map(|n| match n.runs {
            Some(runs) => format!("{runs} runs if {}", events(n.events)),
            None => format!("beyond 2^62 runs if {}", events(n.events)),
        })
        .collect::<Vec<_>>()
        .join(", ")
}

/// The rare-event part of the terminal report: a table of the failures seen at most
/// [`RARE_COUNT`] times with their 95 % upper bound, then the runs it takes to show the
/// target rate.
pub fn rare_event_lines(summary: &CampaignSummary) -> Vec<String> {
    let mut lines = vec![format!(
        "rare failures (seen at most {RARE_COUNT} times; trap, bolter and wave-off are safe): {} % upper bound of the probability",
        100.0 * UPPER_BOUND_CONFIDENCE
    )];
    let rows = rare_event_rows(summary);
    let controller_width = rows.iter().map(|r| r[0].chars().count()).max().unwrap_or(0);
    for row in rows {
        lines.push(format!(
            "  {:<controller_width$}  {:<13}{:>5} in {:<6}{}",
            row[0], row[1], row[2], row[3], row[4]
        ));
    }
    let target = &summary.rare_event_target;
    lines.push(format!(
        "to show p < {:e} at {} %: {} (with none, the n with (1 − p)^n ≤ {:.2}: about 3/p, the rule of three)",
        target.rate,
        100.0 * target.confidence,
        runs_needed(summary),
        1.0 - target.confidence,
    ));
    lines
}

/// The 3-D campaign's lateral statistics in `report.html`: the limits' shares with their
/// 95 % Wilson intervals, and the spread of each quantity.
fn lineup_section(section: &mut html::Section, lateral: &deckland::monte_carlo::LateralStatistics) {
    let share = |name: String, p: &Proportion| {
        vec![
            name,
            p.count.to_string(),
            format!("{} %", html::number(100.0 * p.rate, 1)),
            format!(
                "[{}, {}] %",
                html::number(100.0 * p.ci95_low, 1),
                html::number(100.0 * p.ci95_high, 1)
            ),
        ]
    };
    let spread = |name: &str, d: &Option<Distribution>| -> Vec<String> {
        let mut row = vec![name.to_string()];
        match d {
            Some(d) => {
                row.push(html::signed_number(d.mean, 2));
                row.push(html::number(d.standard_deviation, 2));
                row.extend([d.min, d.p5, d.p50, d.p95, d.max].map(|v| html::signed_number(v, 2)));
            }
            None => row.extend(std::iter::repeat_n("—".to_string(), 7)),
        }
        row
    };
    section
        .paragraph(format!(
            "Over the {} touchdowns of every controller; the limits are those of \
             docs/model.md §10.8.",
            lateral.touchdowns
        ))
        .table(
            &["criterion", "runs", "share", "95 % Wilson interval"],
            vec![
                share(
                    format!("off centre (beyond {} m)", lateral.max_off_centre_m),
                    &lateral.off_centre,
                ),
                share(
                    "lineup at the ramp within ±0.5°".to_string(),
                    &lateral.ramp_lineup_within_half_degree,
                ),
                share(
                    format!("drift beyond {} m/s", lateral.max_drift_rate_mps),
                    &lateral.drift_beyond_limit,
                ),
                share(
                    format!("bank beyond {}°", lateral.max_bank_deg),
                    &lateral.bank_beyond_limit,
                ),
            ],
        )
        .table(
            &["quantity", "mean", "sd", "min", "p5", "p50", "p95", "max"],
            vec![
                spread(
                    "offset from the centreline (m, right +)",
                    &lateral.lateral_offset_m,
                ),
                spread("drift across it (m/s, right +)", &lateral.drift_rate_mps),
                spread("bank (deg, right wing down +)", &lateral.bank_deg),
                spread(
                    "heading to the centreline (deg)",
                    &lateral.heading_to_centreline_deg,
                ),
                spread("lineup at the ramp (deg)", &lateral.ramp_lineup_error_deg),
            ],
        );
}

/// The 3-D campaign's lateral statistics, every controller's touchdowns together.
fn print_lateral(lateral: &deckland::monte_carlo::LateralStatistics) -> Result<()> {
    let rate = |p: &Proportion| {
        format!(
            "{}, {:.1} % [{:.1}, {:.1}]",
            p.count,
            100.0 * p.rate,
            100.0 * p.ci95_low,
            100.0 * p.ci95_high
        )
    };
    outln!("  3-D approach, {} touchdowns:", lateral.touchdowns)?;
    outln!(
        "    off centre (> {} m)            {}",
        lateral.max_off_centre_m,
        rate(&lateral.off_centre)
    )?;
    let spread = |name: &str, d: &Option<Distribution>| -> Result<()> {
        match d {
            Some(d) => outln!(
                "    {name:<32}mean {:+.2}, sd {:.2}, min {:+.2}, max {:+.2}",
                d.mean,
                d.standard_deviation,
                d.min,
                d.max
            )?,
            None => outln!("    {name:<32}–")?,
        }
        Ok(())
    };
    spread("lateral offset (m)", &lateral.lateral_offset_m)?;
    spread("drift rate (m/s)", &lateral.drift_rate_mps)?;
    spread("bank (deg)", &lateral.bank_deg)?;
    spread(
        "heading to centreline (deg)",
        &lateral.heading_to_centreline_deg,
    )?;
    spread("lineup at the ramp (deg)", &lateral.ramp_lineup_error_deg)?;
    outln!(
        "    ramp lineup within ±0.5°       {}",
        rate(&lateral.ramp_lineup_within_half_degree)
    )?;
    outln!(
        "    drift beyond {} m/s            {}",
        lateral.max_drift_rate_mps,
        rate(&lateral.drift_beyond_limit)
    )?;
    outln!(
        "    bank beyond {}°                  {}",
        lateral.max_bank_deg,
        rate(&lateral.bank_beyond_limit)
    )?;
    Ok(())
}
