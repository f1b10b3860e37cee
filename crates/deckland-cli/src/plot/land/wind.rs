//! `wind`: the total wind at the aircraft in earth axes.

use deckland::simulation::Signals;

use super::{series, TIME};
use crate::plot::{Figure, Panel};

/// The total wind at the aircraft in earth axes.
pub(super) fn figure(samples: &[Signals], title: &str) -> Figure {
    Figure::new()
        .title(format!("Wind at the aircraft — {title}"))
        .panel(
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
        )
}
