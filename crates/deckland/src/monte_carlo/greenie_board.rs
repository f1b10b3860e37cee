//! The greenie board: how the landing signal officer graded a controller's passes
//! (docs/model.md §11) — the grades, the mean points, the wires caught and the most
//! common deviations — built from a campaign's rows, so a campaign merged from its
//! shards has the board of the campaign flown whole.

use serde::Serialize;

use super::row::RunRow;
use crate::metrics::lso_grade::{parse_comment, Call, Grade, Window};
use crate::simulation::Outcome;

/// The wire a pass aims for: on a four-wire deck the US Navy's target is the 3-wire
/// (the hook touches down between the 2- and the 3-wire; the 1-wire is short, the
/// 4-wire long).
pub const TARGET_WIRE: u8 = 3;

/// How many of the most frequent deviations the board lists.
pub const TOP_DEVIATIONS: usize = 5;

/// One grade on the board.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GradeCount {
    /// The grade's name (`ok`, `fair`, `bolter`, `no_grade`, `own_wave_off`, `cut`).
    pub grade: &'static str,
    /// The LSO's shorthand (`OK`, `(OK)`, `B`, `--`, `OWO`, `C`).
    pub shorthand: &'static str,
    /// Passes with the grade.
    pub count: u64,
    /// Fraction of the graded passes (0–1; 0 when none was graded).
    pub share: f64,
}

/// One deviation (a call in a window, whatever its severity) and how often it was called.
/// `summary.json` holds its shorthand, count and share (the shorthand names the window
/// and the call, and keeps the document's keys those of every campaign, also of one
/// with no deviation).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct DeviationCount {
    /// The window it was called in.
    #[serde(skip)]
    pub window: Window,
    /// The call.
    #[serde(skip)]
    pub call: Call,
    /// Call and window in the LSO's shorthand (`LOIC`).
    pub shorthand: String,
    /// Graded passes with this call in this window.
    pub count: u64,
    /// Fraction of the graded passes (0–1).
    pub share: f64,
}

/// The greenie board of one controller's passes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GreenieBoard {
    /// Passes with a grade (every flown approach).
    pub graded: u64,
    /// Every grade in the board's order (OK, fair, bolter, no grade, own wave-off, cut).
    pub grades: Vec<GradeCount>,
    /// Mean points of the graded passes (`None` when none was graded).
    pub mean_points: Option<f64>,
    /// Traps per wire (wires 1–4, from aft).
    pub traps_per_wire: [u64; 4],
    /// The target wire ([`TARGET_WIRE`]).
    pub target_wire: u8,
    /// Fraction of the traps on the target wire (`None` without a trap).
    pub target_wire_share: Option<f64>,
    /// The [`TOP_DEVIATIONS`] most frequent deviations, most frequent first (ties in
    /// flight order of the window, then the call's).
    pub top_deviations: Vec<DeviationCount>,
}

impl GreenieBoard {
    /// The board of `rows` (one controller's).
    pub fn of_rows(rows: &[RunRow]) -> Self {
        let graded: Vec<&RunRow> = rows.iter().filter(|r| r.lso_grade.is_some()).collect();
        let passes = graded.len() as u64;
        let share = |count: u64| {
            if passes == 0 {
                0.0
            } else {
                count as f64 / passes as f64
            }
        };
        let grades = Grade::ALL
            .into_iter()
            .map(|grade| {
                let count = graded
                    .iter()
                    .filter(|r| r.lso_grade.as_deref() == Some(grade.name()))
                    .count() as u64;
                GradeCount {
                    grade: grade.name(),
                    shorthand: grade.shorthand(),
                    count,
                    share: share(count),
                }
            })
            .collect();
        let points: Vec<f64> = graded.iter().filter_map(|r| r.lso_points).collect();
        let mean_points =
            (!points.is_empty()).then(|| points.iter().sum::<f64>() / points.len() as f64);
        let mut traps_per_wire = [0; 4];
        for row in rows.iter().filter(|r| r.outcome == Outcome::Trap.name()) {
            if let Some(wire) = row.wire.filter(|w| (1..=4).contains(w)) {
                traps_per_wire[usize::from(wire - 1)] += 1;
            }
        }
        let traps: u64 = traps_per_wire.iter().sum();
        let on_target = traps_per_wire[usize::from(TARGET_WIRE - 1)];
        Self {
            graded: passes,
            grades,
            mean_points,
            traps_per_wire,
            target_wire: TARGET_WIRE,
            target_wire_share: (traps > 0).then(|| on_target as f64 / traps as f64),
            top_deviations: top_deviations(&graded, share),
        }
    }
}

/// The most frequent (window, call) pairs of the comments of `graded`, with `share`.
fn top_deviations(graded: &[&RunRow], share: impl Fn(u64) -> f64) -> Vec<DeviationCount> {
    // (window, call) → count, in order of first appearance; sorted below.
    let mut counts: Vec<((Window, Call), u64)> = Vec::new();
    for row in graded {
        let deviations = row
            .lso_comment
            .as_deref()
            .and_then(|c| parse_comment(c).ok())
            .unwrap_or_default();
        let mut seen: Vec<(Window, Call)> = Vec::new();
        for deviation in deviations {
            let key = (deviation.window, deviation.call);
            if seen.contains(&key) {
                continue;
            }
            seen.push(key);
            match counts.iter_mut().find(|(k, _)| *k == key) {
                Some((_, count)) => *count += 1,
                None => counts.push((key, 1)),
            }
        }
    }
    counts.sort_by_key(|((window, call), count)| {
        (std::cmp::Reverse(*count), *window as u8, *call as u8)
    });
    counts
        .into_iter()
        .take(TOP_DEVIATIONS)
        .map(|((window, call), count)| DeviationCount {
            window,
            call,
            shorthand: format!("{}{}", call.shorthand(), window.shorthand()),
            count,
            share: share(count),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A row with `outcome`, `wire` and the grade `grade` (name, points) and `comment`.
    fn row(
        outcome: &'static str,
        wire: Option<u8>,
        grade: Option<(&str, f64)>,
        comment: Option<&str>,
    ) -> RunRow<'static> {
        RunRow {
            wire,
            lso_grade: grade.map(|g| g.0.to_owned()),
            lso_points: grade.map(|g| g.1),
            lso_comment: comment.map(str::to_owned),
            ..RunRow::unmeasured(0, "O-PD", outcome)
        }
    }

    #[test]
    fn the_board_counts_grades_points_wires_and_deviations() {
        let rows = [
            row("trap", Some(3), Some(("ok", 4.0)), None),
            row("trap", Some(3), Some(("fair", 3.0)), Some("(H)X HIM")),
            row("trap", Some(2), Some(("ok", 4.0)), Some("(LUL)X (H)IM")),
            row("bolter", None, Some(("bolter", 2.5)), Some("HIC _H_AR")),
            row(
                "wave_off",
                None,
                Some(("own_wave_off", 2.0)),
                Some("_LO_IC"),
            ),
            row("invalid", None, None, None),
        ];
        let board = GreenieBoard::of_rows(&rows);
        // Five graded passes: OK 2, fair 1, bolter 1, no grade 0, own wave-off 1, cut 0.
        assert_eq!(board.graded, 5);
        let grades: Vec<(&str, u64, f64)> = board
            .grades
            .iter()
            .map(|g| (g.grade, g.count, g.share))
            .collect();
        assert_eq!(
            grades,
            [
                ("ok", 2, 0.4),
                ("fair", 1, 0.2),
                ("bolter", 1, 0.2),
                ("no_grade", 0, 0.0),
                ("own_wave_off", 1, 0.2),
                ("cut", 0, 0.0),
            ]
        );
        // (4 + 3 + 4 + 2.5 + 2) / 5 = 3.1.
        let mean = board.mean_points.expect("graded passes");
        assert!((mean - 3.1).abs() < 1e-12, "{mean}");
        // Three traps: one on the 2-wire, two on the target 3-wire.
        assert_eq!(board.traps_per_wire, [0, 1, 2, 0]);
        assert_eq!(board.target_wire, 3);
        let target = board.target_wire_share.expect("traps");
        assert!((target - 2.0 / 3.0).abs() < 1e-12, "{target}");
        // H in the middle twice; then once each, in flight order of the window then of
        // the call; HAR (the sixth) left out.
        let top: Vec<(&str, u64, f64)> = board
            .top_deviations
            .iter()
            .map(|d| (d.shorthand.as_str(), d.count, d.share))
            .collect();
        assert_eq!(
            top,
            [
                ("HIM", 2, 0.4),
                ("HX", 1, 0.2),
                ("LULX", 1, 0.2),
                ("HIC", 1, 0.2),
                ("LOIC", 1, 0.2),
            ]
        );
        assert_eq!(board.top_deviations[0].window, Window::Middle);
        assert_eq!(board.top_deviations[0].call, Call::High);
    }

    #[test]
    fn a_board_without_grades_has_no_mean_and_no_target_share() {
        let board = GreenieBoard::of_rows(&[row("invalid", None, None, None)]);
        assert_eq!(board.graded, 0);
        assert_eq!(board.mean_points, None);
        assert_eq!(board.target_wire_share, None);
        assert!(board.top_deviations.is_empty());
    }
}
