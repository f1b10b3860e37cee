//! The calibration at the commit point (issue 45, item 1) in the terminal and in
//! `report.html`: per controller and criterion (ramp strike, hard landing, off-centre
//! touchdown), the events the forecast's probabilities at the commit point predicted
//! (their sum, with the central 95 % interval of the count they imply) against the events
//! the runs had, and the reliability bins (predicted against observed, on a log scale of
//! the probability, with the observed rate's exact 95 % interval). The numbers are the
//! library's ([`deckland::monte_carlo::Calibration`], `calibration` in `summary.json`).

use crate::html;
use anyhow::Result;
use deckland::monte_carlo::{
    CampaignStatistics, ClearanceError, CriterionCalibration, ReliabilityBin,
};

/// The criteria of a controller's calibration that have runs, with their names.
fn criteria(s: &CampaignStatistics) -> Vec<(&'static str, &CriterionCalibration)> {
    let c = &s.calibration;
    [
        ("ramp strike", c.ramp_strike.as_ref()),
        ("hard landing", c.hard_landing.as_ref()),
        ("off-centre touchdown", c.off_centre.as_ref()),
    ]
    .into_iter()
    .filter_map(|(name, calibration)| Some((name, calibration?)))
    .collect()
}

/// An expected number of events: one decimal from 0.1, else in powers of ten.
fn expected(x: f64) -> String {
    if x == 0.0 {
        "0".to_owned()
    } else if x >= 0.095 {
        format!("{x:.1}")
    } else {
        format!("{x:.1e}")
    }
}

/// A probability or rate: 0, or two significant figures in powers of ten.
fn rate(p: f64) -> String {
    if p == 0.0 {
        "0".to_owned()
    } else {
        format!("{p:.1e}")
    }
}

/// A bin's range of probabilities, `[1e-4, 1e-3)` (the last closed at 1).
fn bin_range(bin: &ReliabilityBin) -> String {
    let edge = |p: f64| {
        if p == 0.0 || p == 1.0 {
            format!("{p}")
        } else {
            format!("{p:e}")
        }
    };
    let close = if bin.p_high == 1.0 { ']' } else { ')' };
    format!("[{}, {}{close}", edge(bin.p_low), edge(bin.p_high))
}

/// "ramp strike: predicted 3.2 (95 %: 0–7), observed 9 (2.8 × predicted): not calibrated".
pub fn criterion_line(name: &str, c: &CriterionCalibration) -> String {
    let factor = match c.observed_to_expected {
        Some(ratio) if c.observed_events > 0 => format!(" ({ratio:.2} × predicted)"),
        _ => String::new(),
    };
    format!(
        "{name}: predicted {} (95 %: {}–{}), observed {}{factor}: {}",
        expected(c.expected_events),
        c.interval_95.low,
        c.interval_95.high,
        c.observed_events,
        if c.calibrated {
            "calibrated"
        } else {
            "not calibrated"
        }
    )
}

/// "ramp clearance flown against predicted, z = (flown − c)/σ_c over 2000 runs: mean
/// +0.18 (95 %: +0.14 to +0.22), SD 0.83 (0.81–0.86): σ_c too wide, the ramp-strike
/// probability pessimistic".
pub fn clearance_line(e: &ClearanceError) -> String {
    let verdict = if e.calibrated {
        "calibrated"
    } else if e.sd_ci95_high < 1.0 {
        "σ_c too wide, the ramp-strike probability pessimistic"
    } else if e.sd_ci95_low > 1.0 {
        "σ_c too narrow, the ramp-strike probability optimistic"
    } else if e.mean_ci95_low > 0.0 {
        "the hook crosses higher than predicted, the ramp-strike probability pessimistic"
    } else {
        "the hook crosses lower than predicted, the ramp-strike probability optimistic"
    };
    format!(
        "ramp clearance flown against predicted, z = (flown − c)/σ_c over {} runs: mean {:+.2} \
         (95 %: {:+.2} to {:+.2}), SD {:.2} ({:.2}–{:.2}): {verdict}",
        e.runs, e.mean, e.mean_ci95_low, e.mean_ci95_high, e.sd, e.sd_ci95_low, e.sd_ci95_high
    )
}

/// "p in [1e-4, 1e-3): 1234 runs, mean p 3.1e-4, observed 2 (rate 1.6e-3, 95 %:
/// 2.0e-4–5.8e-3)", for a bin with runs.
fn bin_line(bin: &ReliabilityBin) -> Option<String> {
    Some(format!(
        "p in {}: {} run{}, mean p {}, observed {} (rate {}, 95 %: {}–{})",
        bin_range(bin),
        bin.runs,
        if bin.runs == 1 { "" } else { "s" },
        rate(bin.mean_predicted?),
        bin.observed_events,
        rate(bin.observed_rate?),
        rate(bin.ci95_low),
        rate(bin.ci95_high)
    ))
}

/// The terminal's lines: per controller whose runs reached the commit point, how many
/// did, then each criterion's line and its bins with runs.
pub fn lines(stats: &[CampaignStatistics]) -> Vec<String> {
    let mut lines = Vec::new();
    for s in stats.iter().filter(|s| s.calibration.runs_at_commit > 0) {
        let c = &s.calibration;
        let whose = if stats.len() > 1 {
            format!("{}: ", s.controller)
        } else {
            String::new()
        };
        lines.push(format!(
            "calibration at the commit point ({whose}{} runs reached it, {} waved off after it): events the forecast predicted against those flown",
            c.runs_at_commit, c.waved_off_after_commit
        ));
        for (name, criterion) in criteria(s) {
            lines.push(format!("  {}", criterion_line(name, criterion)));
            lines.extend(
                criterion
                    .bins
                    .iter()
                    .filter_map(bin_line)
                    .map(|l| format!("    {l}")),
            );
        }
        if let Some(error) = &c.ramp_clearance_error {
            lines.push(format!("  {}", clearance_line(error)));
        }
    }
    lines
}

/// Prints [`lines`].
pub fn print(stats: &[CampaignStatistics]) -> Result<()> {
    for line in lines(stats) {
        outln!("  {line}")?;
    }
    Ok(())
}

/// Whether any controller's runs reached the commit point (the page has the section).
pub fn any(stats: &[CampaignStatistics]) -> bool {
    stats.iter().any(|s| s.calibration.runs_at_commit > 0)
}

/// The calibration section of `report.html`: the counts, then the reliability bins.
pub fn html_section(section: &mut html::Section, stats: &[CampaignStatistics]) {
    let mut counts = Vec::new();
    let mut bins = Vec::new();
    for s in stats {
        for (name, c) in criteria(s) {
            counts.push(vec![
                s.controller.clone(),
                name.to_owned(),
                c.runs.to_string(),
                expected(c.expected_events),
                format!("{}–{}", c.interval_95.low, c.interval_95.high),
                c.observed_events.to_string(),
                c.observed_to_expected
                    .map_or_else(|| "—".to_owned(), |r| html::number(r, 2)),
                if c.calibrated { "yes" } else { "no" }.to_owned(),
            ]);
            for bin in c.bins.iter().filter(|b| b.runs > 0) {
                bins.push(vec![
                    s.controller.clone(),
                    name.to_owned(),
                    bin_range(bin),
                    bin.runs.to_string(),
                    bin.mean_predicted.map_or_else(String::new, rate),
                    bin.observed_events.to_string(),
                    format!("{}–{}", rate(bin.ci95_low), rate(bin.ci95_high)),
                ]);
            }
        }
    }
    let method = stats
        .first()
        .map_or("", |s| s.calibration.method)
        .to_owned();
    section
        .paragraph(format!(
            "The probabilities the forecast gave at each run's commit point \
             (`commit_*_probability` in `runs.csv`) against what the runs did: {method}. \
             A ramp strike is the outcome `ramp_strike`, a hard landing `hard_landing`, an \
             off-centre touchdown the `off_centre` column."
        ))
        .table(
            &[
                "controller",
                "event",
                "runs at the commit point",
                "predicted events",
                "95 % interval of the count",
                "observed events",
                "observed / predicted",
                "calibrated",
            ],
            counts,
        )
        .table(
            &[
                "controller",
                "event",
                "predicted probability",
                "runs",
                "mean predicted",
                "observed events",
                "95 % interval of the observed rate",
            ],
            bins,
        );
    for s in stats {
        if let Some(error) = &s.calibration.ramp_clearance_error {
            section.paragraph(format!("{}: {}.", s.controller, clearance_line(error)));
        }
    }
}
