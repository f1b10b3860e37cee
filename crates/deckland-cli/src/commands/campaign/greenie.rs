//! The greenie board of a campaign (docs/model.md §11): the landing signal officer's
//! grades of each controller's passes, printed in the terminal and drawn in `report.html`
//! as the coloured board a squadron pins up.

use crate::html;
use anyhow::Result;
use deckland::monte_carlo::{CampaignStatistics, GreenieBoard};

/// Each grade's colours on the board, by its name (background; text): green OK, yellow
/// fair, orange bolter, brown no grade, blue own wave-off, red cut (the squadrons'
/// convention), white text on the dark ones.
const GRADE_COLOURS: [(&str, &str); 6] = [
    ("ok", "background:#3c9a3c;color:#fff"),
    ("fair", "background:#e8d44d"),
    ("bolter", "background:#e8902c"),
    ("no_grade", "background:#8b5a2b;color:#fff"),
    ("own_wave_off", "background:#3a6fc4;color:#fff"),
    ("cut", "background:#c83232;color:#fff"),
];

/// The grade's words on the board: its shorthand and its name in words.
fn grade_label(name: &str, shorthand: &str) -> String {
    format!("{shorthand} {}", name.replace('_', " "))
}

/// A share as a percentage with one decimal.
fn percent(share: f64) -> String {
    format!("{:.1} %", 100.0 * share)
}

/// The board's top deviations in one line: `HIM 3 (50.0 %), LOIC 2 (33.3 %)`.
fn top_deviations(board: &GreenieBoard) -> String {
    if board.top_deviations.is_empty() {
        return "none".to_owned();
    }
    board
        .top_deviations
        .iter()
        .map(|d| format!("{} {} ({})", d.shorthand, d.count, percent(d.share)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The target wire's line: `3-wire 60.0 % of traps`.
fn target_wire(board: &GreenieBoard) -> String {
    match board.target_wire_share {
        Some(share) => format!("{}-wire {} of traps", board.target_wire, percent(share)),
        None => format!("{}-wire: no trap", board.target_wire),
    }
}

/// Prints the greenie board of each controller, `label_width` and `width` wide like the
/// rest of the campaign's table.
pub fn print(stats: &[CampaignStatistics], label_width: usize, width: usize) -> Result<()> {
    outln!("  greenie board (LSO grades): count, share of graded passes")?;
    let Some(first) = stats.first() else {
        return Ok(());
    };
    for (k, grade) in first.greenie_board.grades.iter().enumerate() {
        out!(
            "  {:<label_width$}",
            grade_label(grade.grade, grade.shorthand)
        )?;
        for s in stats {
            let g = &s.greenie_board.grades[k];
            out!(
                "{:>width$}",
                format!("{:>5} {:>7}", g.count, percent(g.share))
            )?;
        }
        outln!()?;
    }
    out!("  {:<label_width$}", "mean points (of 4)")?;
    for s in stats {
        let mean = s.greenie_board.mean_points;
        out!(
            "{:>width$}",
            mean.map_or("–".to_owned(), |m| format!("{m:.2}"))
        )?;
    }
    outln!()?;
    out!("  {:<label_width$}", "target wire")?;
    for s in stats {
        out!("{:>width$}", target_wire(&s.greenie_board))?;
    }
    outln!()?;
    for s in stats {
        outln!(
            "  top deviations, {}: {}",
            s.controller,
            top_deviations(&s.greenie_board)
        )?;
    }
    Ok(())
}

/// A line under the grades of the HTML board: its label and its value for a board.
type BoardLine = (&'static str, fn(&GreenieBoard) -> String);

/// The board as an HTML table, one coloured row per grade and a column of count and
/// share per controller, then the mean points, the wires and the top deviations.
pub fn board_html(stats: &[CampaignStatistics]) -> String {
    let mut out = String::from("<table class=\"greenie\">\n<thead><tr><th>grade</th>");
    for s in stats {
        out.push_str(&format!(
            "<th>{}: passes (of {})</th><th>{}: share</th>",
            html::escape(&s.controller),
            s.greenie_board.graded,
            html::escape(&s.controller)
        ));
    }
    out.push_str("</tr></thead>\n<tbody>\n");
    let Some(first) = stats.first() else {
        return out + "</tbody>\n</table>\n";
    };
    for (k, grade) in first.greenie_board.grades.iter().enumerate() {
        let style = GRADE_COLOURS
            .iter()
            .find(|(name, _)| *name == grade.grade)
            .map_or("", |(_, style)| style);
        out.push_str(&format!(
            "<tr style=\"{style}\"><td>{}</td>",
            html::escape(&grade_label(grade.grade, grade.shorthand))
        ));
        for s in stats {
            let g = &s.greenie_board.grades[k];
            out.push_str(&format!(
                "<td class=\"number\">{}</td><td class=\"number\">{}</td>",
                g.count,
                percent(g.share)
            ));
        }
        out.push_str("</tr>\n");
    }
    let rows: [BoardLine; 4] = [
        ("mean points (of 4)", |b| {
            b.mean_points.map_or("–".to_owned(), |m| format!("{m:.2}"))
        }),
        ("traps on wires 1/2/3/4", |b| {
            let w = b.traps_per_wire;
            format!("{}/{}/{}/{}", w[0], w[1], w[2], w[3])
        }),
        ("target wire", target_wire),
        ("most common deviations", top_deviations),
    ];
    for (label, value) in rows {
        out.push_str(&format!("<tr><td>{label}</td>"));
        for s in stats {
            out.push_str(&format!(
                "<td colspan=\"2\">{}</td>",
                html::escape(&value(&s.greenie_board))
            ));
        }
        out.push_str("</tr>\n");
    }
    out + "</tbody>\n</table>\n"
}
