//! `wind`: the total wind at the aircraft in earth axes.

use deckland::simulation::Signals;

use deckland::scenario::Scenario;

use super::{series, wake_onset, TIME};
use crate::plot::{Figure, Panel};

/// The total wind at the aircraft in earth axes.
pub(super) fn figure(samples: &[Signals], scenario: &Scenario, title: &str) -> Figure {
    let onset = wake_onset(samples, scenario);
    let mark = |panel: Panel| match onset {
        Some((time_s, extent_m)) => {
            panel.vertical_line(format!("air wake from {extent_m:.0} m aft"), time_s)
        }
        None => panel,
    };
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
                series(samples, |s| s.wind.x_mps),
            )
            .series("z (positive down)", series(samples, |s| s.wind.z_mps)),
        ))
}
