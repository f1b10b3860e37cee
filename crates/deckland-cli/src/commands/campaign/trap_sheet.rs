//! A 3-D campaign's trap-sheet statistics in the terminal and in `report.html`: per
//! position of the groove (X, IM, IC, AR), the passes that flew it and, per deviation,
//! the mean, the standard deviation and the 95 % confidence interval of the mean (and in
//! the page the 2.5th–97.5th percentiles).

use crate::html;
use anyhow::Result;
use deckland::metrics::TrapSheetPosition;
use deckland::monte_carlo::{DeviationStatistics, TrapSheetStatistics, TRAP_SHEET_DEVIATIONS};

/// A position's name with its window, as a landing signal officer calls it.
fn position_name(position: TrapSheetPosition) -> &'static str {
    match position {
        TrapSheetPosition::Start => "X, the start (¾–½ nmi)",
        TrapSheetPosition::Middle => "IM, the middle (½–¼ nmi)",
        TrapSheetPosition::InClose => "IC, in close (¼–0.1 nmi)",
        TrapSheetPosition::AtRamp => "AR, at the ramp (0.1 nmi–ramp)",
    }
}

/// The deviations the terminal shows (the lineup in metres is in `summary.json` and the
/// page): the glide slope's mean and peak (m), the lineup's mean and peak (deg).
const PRINTED: [usize; 4] = [0, 1, 4, 5];

/// Prints the trap-sheet statistics, every controller's passes together.
pub fn print(sheet: &TrapSheetStatistics) -> Result<()> {
    outln!("  LSO trap sheet: mean ± sd [95 % interval of the mean], over the passes that flew each position")?;
    for position in &sheet.positions {
        outln!(
            "    {} — {} passes",
            position_name(position.position),
            position.passes
        )?;
        let deviations = position.deviations();
        for k in PRINTED {
            let name = TRAP_SHEET_DEVIATIONS[k].1;
            match deviations[k] {
                Some(d) => outln!(
                    "      {name:<52}{:+.2} ± {:.2} [{:+.2}, {:+.2}]",
                    d.mean,
                    d.standard_deviation,
                    d.mean_ci95_low,
                    d.mean_ci95_high
                )?,
                None => outln!("      {name:<52}–")?,
            }
        }
    }
    Ok(())
}

/// The trap-sheet section of `report.html`: one table, a row per position and deviation.
pub fn html_section(section: &mut html::Section, sheet: &TrapSheetStatistics) {
    let cells = |d: &Option<DeviationStatistics>| -> Vec<String> {
        match d {
            Some(d) => vec![
                d.count.to_string(),
                html::signed_number(d.mean, 2),
                html::number(d.standard_deviation, 2),
                format!(
                    "[{}, {}]",
                    html::signed_number(d.mean_ci95_low, 2),
                    html::signed_number(d.mean_ci95_high, 2)
                ),
                format!(
                    "[{}, {}]",
                    html::signed_number(d.p2_5, 2),
                    html::signed_number(d.p97_5, 2)
                ),
            ],
            None => vec!["0".to_string()]
                .into_iter()
                .chain(std::iter::repeat_n("—".to_string(), 4))
                .collect(),
        }
    };
    let mut rows = Vec::new();
    for position in &sheet.positions {
        for (k, d) in position.deviations().iter().enumerate() {
            let mut row = vec![
                position_name(position.position).to_string(),
                TRAP_SHEET_DEVIATIONS[k].1.to_string(),
            ];
            row.extend(cells(d));
            rows.push(row);
        }
    }
    section
        .paragraph(format!(
            "The glide-slope and lineup deviations a landing signal officer grades, per \
             position of the groove (docs/model.md §10.8), over every controller's passes \
             that flew the position (a wave-off before it, or a setup that failed, has \
             none). Intervals: {}.",
            sheet.intervals
        ))
        .table(
            &[
                "position",
                "deviation",
                "passes",
                "mean",
                "sd",
                "95 % interval of the mean",
                "2.5th–97.5th percentile",
            ],
            rows,
        );
}
