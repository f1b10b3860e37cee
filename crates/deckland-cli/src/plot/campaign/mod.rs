//! The figures of a campaign: `touchdown_dispersion`, `touchdown_histograms` and
//! `outcomes`; a 3-D campaign also `touchdown_plan`, its touchdowns on the deck from above.
//! The touchdowns are marked by outcome and controller (`touchdowns`).

mod touchdowns;

#[cfg(test)]
mod tests;

use deckland::environment::DeckGeometry;

use crate::commands::campaign::folder::{proportions, CampaignFolder};
use crate::plot::{signed, BarGroup, Figure, Panel};
use touchdowns::{mark_outcomes, Touchdown};

/// The outcome categories of `outcomes`, in the order of [`proportions`].
const CATEGORIES: [&str; 8] = [
    "trap",
    "bolter",
    "wave-off",
    "ramp strike",
    "hard landing",
    "diverged",
    "timeout",
    "invalid",
];

/// The plots of a campaign, each with its file stem.
pub(crate) fn figures(folder: &CampaignFolder) -> Vec<(&'static str, Figure)> {
    let (scenario, title) = (folder.scenario, &folder.title);
    let statistics = &folder.report.summary.controllers;
    let labels: Vec<&str> = statistics.iter().map(|s| s.controller.as_str()).collect();
    let runs: Vec<Touchdown> = folder
        .table
        .rows
        .iter()
        .map(|r| Touchdown {
            controller: r.controller.as_ref(),
            outcome: r.outcome.as_ref(),
            point: r.touchdown_distance_m.zip(r.touchdown_sink_rate_mps),
        })
        .collect();
    let dispersion = dispersion(
        &labels,
        &runs,
        &scenario.environment.deck,
        scenario.outcome.hard_landing_sink_rate_mps,
    );
    let groups = statistics.iter().map(|s| {
        let classes = proportions(s);
        BarGroup {
            name: format!("{} ({} runs)", s.controller, s.runs),
            values: classes.iter().map(|(_, p)| 100.0 * p.rate).collect(),
            intervals: classes
                .iter()
                .map(|(_, p)| (100.0 * p.ci95_low, 100.0 * p.ci95_high))
                .collect(),
            labels: classes.iter().map(|(_, p)| p.count.to_string()).collect(),
        }
    });
    let mut figures = vec![
        (
            "touchdown_dispersion",
            Figure::new()
                .title(format!("Touchdown dispersion — {title}"))
                .panel(dispersion),
        ),
        ("touchdown_histograms", histograms(&labels, &runs, title)),
        (
            "outcomes",
            Figure::new()
                .title(format!("Outcomes — {title}"))
                .panel(outcomes(groups.collect())),
        ),
    ];
    if let Some(plan) = touchdown_plan(folder, &labels) {
        figures.push(("touchdown_plan", plan));
    }
    figures
}

/// The touchdown point along the deck against the sink rate, marked by outcome and
/// controller, with the wires, the ramp when a touchdown lies near it and the
/// hard-landing limit `hard_landing_mps` when near the data.
pub(crate) fn dispersion(
    labels: &[&str],
    runs: &[Touchdown],
    deck: &DeckGeometry,
    hard_landing_mps: f64,
) -> Panel {
    let mut panel = Panel::new(
        "Touchdown point along the deck and sink rate relative to the deck",
        "touchdown along the deck from the aim point (m, positive forward)",
        "sink rate at touchdown (m/s)",
    );
    // The axis spans the touchdowns and the wires; the ramp only when a touchdown lies
    // near it, else half of the axis would be empty.
    let ramp_m = -deck.ramp_aft_of_aim_point_m;
    let (mut low, mut high) = (deck.wire_positions_m[0], deck.wire_positions_m[3]);
    for (x, _) in runs.iter().filter_map(|r| r.point) {
        (low, high) = (low.min(x), high.max(x));
    }
    let margin = 0.05 * (high - low).max(1.0);
    if low - margin <= ramp_m + 10.0 {
        panel = panel.vertical_line("ramp", ramp_m);
        low = low.min(ramp_m);
    } else {
        panel = panel.note(format!(
            "the ramp, at {} m, is left of the axis: no touchdown near it",
            signed(ramp_m)
        ));
    }
    panel = panel.x_limits((low - margin)..(high + margin));
    for (index, wire) in deck.wire_positions_m.iter().enumerate() {
        panel = panel.vertical_line(format!("wire {}", index + 1), *wire);
    }
    panel = panel.limit_line(
        format!("hard-landing limit {hard_landing_mps} m/s"),
        hard_landing_mps,
    );
    mark_outcomes(panel, labels, runs)
}

/// The histograms of the touchdowns' sink rate and point, the controllers' bars side by
/// side in each bin.
fn histograms(labels: &[&str], runs: &[Touchdown], title: &str) -> Figure {
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
    for label in labels {
        let points: Vec<(f64, f64)> = runs
            .iter()
            .filter(|r| r.controller == *label)
            .filter_map(|r| r.point)
            .collect();
        sink = sink.histogram(
            label.to_string(),
            points.iter().map(|p| p.1).collect(),
            bins,
        );
        distance = distance.histogram(
            label.to_string(),
            points.iter().map(|p| p.0).collect(),
            bins,
        );
    }
    Figure::new()
        .title(format!("Touchdown histograms — {title}"))
        .panel(sink)
        .panel(distance)
}

/// The share of runs of each outcome, a group of bars per controller, on a log axis so
/// that a failure in 10 000 runs shows beside the traps; a zero count has no bar.
pub(crate) fn outcomes(groups: Vec<BarGroup>) -> Panel {
    let mut panel = Panel::new(
        "Share of runs by outcome, log scale, with 95 % Wilson score intervals (bar labels: runs)",
        "outcome",
        "share of runs (%, log scale)",
    )
    .categories(CATEGORIES.iter().map(|c| (*c).to_owned()).collect())
    .log_y()
    .interval_name("95 % Wilson score interval")
    .note("no bar: no run of that outcome; its interval (grey) runs up from 0");
    for group in groups {
        panel = panel.bar_group(group);
    }
    panel
}

/// A 3-D campaign's touchdowns on the deck seen from above: along the landing area's
/// centreline from the aim point against the hook's offset from it, marked by outcome and
/// controller, with the wires, the centreline and the off-centre limit (when near the
/// data), the offset to the right drawn down the page as seen from above
/// (`Panel::y_downward`); `None` for a 3-DOF campaign.
fn touchdown_plan(folder: &CampaignFolder, labels: &[&str]) -> Option<Figure> {
    let lateral = folder.table.lateral_rows()?;
    let statistics = folder.report.lateral.as_ref()?;
    let deck = &folder.scenario.environment.deck;
    let limit_m = statistics.max_off_centre_m;
    let mut panel = Panel::new(
        "Touchdown points on the landing area, from above",
        "touchdown along the centreline from the aim point (m, positive forward)",
        "offset from the centreline (m, right of it, down)",
    )
    .y_downward();
    let runs: Vec<Touchdown> = folder
        .table
        .rows
        .iter()
        .zip(lateral)
        .map(|(row, values)| Touchdown {
            controller: row.controller.as_ref(),
            outcome: row.outcome.as_ref(),
            point: row
                .touchdown_distance_m
                .zip(values.touchdown.0)
                .map(|(x, offset)| (x, -offset)),
        })
        .collect();
    let (mut low, mut high) = (deck.wire_positions_m[0], deck.wire_positions_m[3]);
    for (x, _) in runs.iter().filter_map(|r| r.point) {
        (low, high) = (low.min(x), high.max(x));
    }
    let margin = 0.05 * (high - low).max(1.0);
    let limit = format!("off-centre limit ±{limit_m} m");
    panel = panel
        .x_limits((low - margin)..(high + margin))
        .reference_line("centreline", 0.0)
        .limit_line(limit.clone(), limit_m)
        .limit_line(limit, -limit_m);
    for (index, wire) in deck.wire_positions_m.iter().enumerate() {
        panel = panel.vertical_line(format!("wire {}", index + 1), *wire);
    }
    Some(
        Figure::new()
            .title(format!("Touchdown plan — {}", folder.title))
            .panel(mark_outcomes(panel, labels, &runs)),
    )
}
