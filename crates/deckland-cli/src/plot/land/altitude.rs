//! `altitude`: the hook height over the whole approach, against the glide path and the landing point on the deck.

use deckland::simulation::Signals;

use super::{series, series_where_applicable, TIME};
use crate::plot::{Figure, Panel};

/// The hook height over the whole approach, against the glide path and the landing point on the deck.
pub(super) fn figure(samples: &[Signals], title: &str) -> Figure {
    Figure::new()
        .title(format!("Whole approach — {title}"))
        .panel(
            Panel::new(
                "Hook height, glide path and the landing point on the deck",
                TIME,
                "height above mean sea level (m)",
            )
            .series("hook", series(samples, |s| s.hook_h_m))
            .dashed_series(
                "glide path (hook reference)",
                series_where_applicable(samples, |s| s.path_height_m),
            )
            .series(
                "landing point on the deck",
                series(samples, |s| s.aim_point.h_m),
            ),
        )
}
