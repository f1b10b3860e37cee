//! The figures of a campaign: `touchdown_dispersion`, `touchdown_histograms` and
//! `outcomes`; a 3-D campaign also `touchdown_plan`, its touchdowns on the deck from above.

use crate::commands::campaign::folder::{proportions, CampaignFolder};
use crate::plot::{BarGroup, Figure, Panel};

/// The plots of a campaign, each with its file stem.
pub(crate) fn figures(folder: &CampaignFolder) -> Vec<(&'static str, Figure)> {
    let (scenario, title) = (folder.scenario, &folder.title);
    let deck = &scenario.environment.deck;
    let statistics = &folder.report.summary.controllers;
    let labels: Vec<&str> = statistics.iter().map(|s| s.controller.as_str()).collect();
    let touchdowns = |label: &str| -> Vec<(f64, f64)> {
        folder
            .rows
            .iter()
            .filter(|r| r.controller == label)
            .filter_map(|r| r.touchdown_distance_m.zip(r.touchdown_sink_rate_mps))
            .collect()
    };
    let mut dispersion = Panel::new(
        "Touchdown point along the deck and sink rate relative to the deck",
        "touchdown along the deck from the aim point (m, positive forward)",
        "sink rate at touchdown (m/s)",
    );
    for label in &labels {
        let points = touchdowns(label);
        dispersion = dispersion.scatter(format!("{label} ({} touchdowns)", points.len()), points);
    }
    // The axis spans the touchdowns and the wires; the ramp only when a touchdown lies
    // near it, else half of the axis would be empty.
    let ramp_m = -deck.ramp_aft_of_aim_point_m;
    let (mut low, mut high) = (deck.wire_positions_m[0], deck.wire_positions_m[3]);
    for (x, _) in labels.iter().flat_map(|label| touchdowns(label)) {
        (low, high) = (low.min(x), high.max(x));
    }
    let margin = 0.05 * (high - low).max(1.0);
    if low - margin <= ramp_m + 10.0 {
        dispersion = dispersion.vertical_line("ramp", ramp_m);
        low = low.min(ramp_m);
    } else {
        dispersion = dispersion.note(format!(
            "the ramp, at {} m, is left of the axis: no touchdown near it",
            ramp_m
        ));
    }
    dispersion = dispersion.x_limits((low - margin)..(high + margin));
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
    for label in &labels {
        let points = touchdowns(label);
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
    for s in statistics {
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
    let mut figures = vec![
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
    ];
    if let Some(plan) = touchdown_plan(folder, &labels) {
        figures.push(("touchdown_plan", plan));
    }
    figures
}

/// A 3-D campaign's touchdowns on the deck seen from above: along the landing area's
/// centreline from the aim point against the hook's offset from it, with the wires, the
/// centreline and the off-centre limit, the offset to the right drawn down the page as seen
/// from above (`Panel::y_downward`); `None` for a 3-DOF campaign.
fn touchdown_plan(folder: &CampaignFolder, labels: &[&str]) -> Option<Figure> {
    let lateral = folder.lateral_rows.as_ref()?;
    let statistics = folder.report.lateral.as_ref()?;
    let deck = &folder.scenario.environment.deck;
    let limit_m = statistics.max_off_centre_m;
    let mut panel = Panel::new(
        "Touchdown points on the landing area, from above",
        "touchdown along the centreline from the aim point (m, positive forward)",
        "offset from the centreline (m, right of it, down)",
    )
    .y_downward();
    let (mut low, mut high) = (deck.wire_positions_m[0], deck.wire_positions_m[3]);
    for label in labels {
        let points: Vec<(f64, f64)> = folder
            .rows
            .iter()
            .zip(lateral)
            .filter(|(row, _)| row.controller == *label)
            .filter_map(|(row, values)| row.touchdown_distance_m.zip(values.touchdown.0))
            .map(|(x, offset)| (x, -offset))
            .collect();
        for (x, _) in &points {
            (low, high) = (low.min(*x), high.max(*x));
        }
        panel = panel.scatter(format!("{label} ({} touchdowns)", points.len()), points);
    }
    let margin = 0.05 * (high - low).max(1.0);
    panel = panel
        .x_limits((low - margin)..(high + margin))
        .reference_line("centreline", 0.0)
        .reference_line(format!("off-centre limit ±{limit_m} m"), limit_m)
        .reference_line(format!("off-centre limit ±{limit_m} m"), -limit_m);
    for (index, wire) in deck.wire_positions_m.iter().enumerate() {
        panel = panel.vertical_line(format!("wire {}", index + 1), *wire);
    }
    Some(
        Figure::new()
            .title(format!("Touchdown plan — {}", folder.title))
            .panel(panel),
    )
}
