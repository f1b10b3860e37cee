//! `airspeed`: the true airspeed and the angle of attack.

use deckland::simulation::{SignalId, Signals};

use deckland::scenario::Scenario;

use super::{mark_wake_onset, series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The true airspeed and the angle of attack.
pub(super) fn figure(samples: &[Signals], scenario: &Scenario, title: &str) -> Figure {
    let mark = |panel: Panel| mark_wake_onset(panel, samples, scenario);
    Figure::new()
        .title(format!("Airspeed and angle of attack — {title}"))
        .panel(mark(
            Panel::new("True airspeed", TIME, "airspeed (m/s)").series(
                "airspeed",
                series(samples, SignalId::Airspeed, Shown::AsRegistered),
            ),
        ))
        .panel(mark(
            Panel::new("Angle of attack", TIME, "angle of attack α (deg)")
                .series("α", series(samples, SignalId::Alpha, Shown::Degrees)),
        ))
}
