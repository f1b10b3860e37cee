//! The campaign's touchdown points, marked by outcome and controller: each outcome has
//! its own shape (trap a circle, bolter a triangle, hard landing a square, …), each
//! controller its colour, the first filled and the second hollow, so that with `--compare`
//! neither controller's points hide the other's (the hollow ones are drawn over the
//! filled, which are translucent); the rare outcomes are drawn last, on top.

use plotters::style::RGBColor;

use crate::plot::{MarkerShape, MarkerStyle, Panel};

/// One run of the campaign as the touchdown plots see it.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Touchdown<'a> {
    /// The controller's label.
    pub(crate) controller: &'a str,
    /// The outcome's name in `runs.csv` (`trap`, `hard_landing`, …).
    pub(crate) outcome: &'a str,
    /// The point drawn, if the run has one (a ramp strike, a wave-off or a bolter that
    /// flew over the wires has no touchdown).
    pub(crate) point: Option<(f64, f64)>,
}

/// The outcomes in the order they are drawn (the rare ones last, on top), with their
/// names in the legend and their shapes; any other outcome is a cross.
const OUTCOMES: [(&str, &str, MarkerShape); 8] = [
    ("trap", "trap", MarkerShape::Circle),
    ("bolter", "bolter", MarkerShape::Triangle),
    ("wave_off", "wave-off", MarkerShape::TriangleDown),
    ("hard_landing", "hard landing", MarkerShape::Square),
    ("ramp_strike", "ramp strike", MarkerShape::Diamond),
    ("diverged", "diverged", MarkerShape::Cross),
    ("timeout", "timeout", MarkerShape::Cross),
    ("invalid", "invalid", MarkerShape::Cross),
];

/// The colour of the outcomes' shapes in the legend (the controllers' colours are theirs).
const KEY_COLOUR: RGBColor = RGBColor(80, 80, 80);

/// An outcome's place in the drawing order, its name in the legend and its shape.
fn outcome_marker(outcome: &str) -> (usize, String, MarkerShape) {
    OUTCOMES
        .iter()
        .position(|(name, _, _)| *name == outcome)
        .map_or_else(
            || {
                (
                    OUTCOMES.len(),
                    outcome.replace('_', " "),
                    MarkerShape::Cross,
                )
            },
            |index| (index, OUTCOMES[index].1.to_owned(), OUTCOMES[index].2),
        )
}

/// The marker of the controller at `index` for an outcome of `shape`: its colour; the
/// first filled and translucent (a trap's circle more than the rarer outcomes' shapes,
/// which are larger too, so that they stand out), the second hollow.
pub(crate) fn controller_style(index: usize, shape: MarkerShape) -> MarkerStyle {
    let colour = crate::plot::palette(index);
    let (size, opacity) = match shape {
        MarkerShape::Circle => (4, 0.5),
        MarkerShape::Triangle | MarkerShape::TriangleDown => (6, 0.85),
        _ => (5, 0.85),
    };
    let style = MarkerStyle::filled(shape, colour, size);
    if index % 2 == 1 {
        style.hollow().opacity(0.9)
    } else {
        style.opacity(opacity)
    }
}

/// `panel` with the runs' points, one series per outcome and controller, keyed in the
/// legend by controller (its colour and fill, with its number of points) and by outcome
/// (its shape, with its count per controller); a note counts the runs of each outcome
/// that have no point.
pub(crate) fn mark_outcomes(mut panel: Panel, controllers: &[&str], runs: &[Touchdown]) -> Panel {
    for (index, controller) in controllers.iter().enumerate() {
        let drawn = runs
            .iter()
            .filter(|r| r.controller == *controller && r.point.is_some())
            .count();
        panel = panel.legend_entry(
            format!("{controller} ({drawn} touchdowns)"),
            controller_style(index, MarkerShape::Circle),
        );
    }
    let mut outcomes: Vec<&str> = Vec::new();
    for run in runs.iter().filter(|r| r.point.is_some()) {
        if !outcomes.contains(&run.outcome) {
            outcomes.push(run.outcome);
        }
    }
    outcomes.sort_by_key(|outcome| outcome_marker(outcome).0);
    for outcome in outcomes {
        let (_, name, shape) = outcome_marker(outcome);
        let mut counts = Vec::new();
        for (index, controller) in controllers.iter().enumerate() {
            let points: Vec<(f64, f64)> = runs
                .iter()
                .filter(|r| r.controller == *controller && r.outcome == outcome)
                .filter_map(|r| r.point)
                .collect();
            counts.push(match controllers.len() {
                1 => points.len().to_string(),
                _ => format!("{controller} {}", points.len()),
            });
            panel = panel.styled_scatter("", points, controller_style(index, shape));
        }
        let key = MarkerStyle::filled(shape, KEY_COLOUR, controller_style(0, shape).size);
        panel = panel.legend_entry(format!("{name} ({})", counts.join(", ")), key);
    }
    match not_drawn(controllers, runs) {
        Some(note) => panel.note(note),
        None => panel,
    }
}

/// The note that counts the runs without a point, per controller and outcome: "not
/// drawn, no touchdown: O-PD 79 bolters, 20 ramp strikes; PID …"; `None` if every run
/// has one.
fn not_drawn(controllers: &[&str], runs: &[Touchdown]) -> Option<String> {
    let mut parts = Vec::new();
    for controller in controllers {
        let mut outcomes: Vec<(usize, String, usize)> = Vec::new();
        let missing = runs
            .iter()
            .filter(|r| r.controller == *controller && r.point.is_none());
        for run in missing {
            let (order, name, _) = outcome_marker(run.outcome);
            match outcomes.iter_mut().find(|(_, n, _)| *n == name) {
                Some(entry) => entry.2 += 1,
                None => outcomes.push((order, name, 1)),
            }
        }
        outcomes.sort();
        let list: Vec<String> = outcomes
            .iter()
            .map(|(_, name, count)| format!("{count} {}", plural(name, *count)))
            .collect();
        if !list.is_empty() {
            let who = if controllers.len() > 1 {
                format!("{controller} ")
            } else {
                String::new()
            };
            parts.push(format!("{who}{}", list.join(", ")));
        }
    }
    (!parts.is_empty()).then(|| format!("not drawn, no touchdown: {}", parts.join("; ")))
}

/// An outcome's name for `count` runs: "1 bolter", "79 bolters", "2 diverged".
fn plural(name: &str, count: usize) -> String {
    if count == 1 || matches!(name, "diverged" | "invalid") {
        name.to_owned()
    } else {
        format!("{name}s")
    }
}
