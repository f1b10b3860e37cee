//! `wind`: the total wind at the aircraft in earth axes.

use deckland::simulation::{SignalId, Signals};

use deckland::scenario::Scenario;

use super::{mark_wake_onset, series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The total wind at the aircraft in earth axes.
pub(super) fn figure(samples: &[Signals], scenario: &Scenario, title: &str) -> Figure {
    let mark = |panel: Panel| mark_wake_onset(panel, samples, scenario);
    Figure::new()
        .title(format!("Wind at the aircraft — {title}"))
        .panel(mark(
            Panel::new(
                "Total wind in earth axes (mean, turbulence and air wake)",
                TIME,
                "wind (m/s)",
            )
            .series(
                "x (positive forward; headwind negative)",
                series(samples, SignalId::WindX, Shown::AsRegistered),
            )
            .series(
                "z (positive down)",
                series(samples, SignalId::WindZ, Shown::AsRegistered),
            ),
        ))
}
