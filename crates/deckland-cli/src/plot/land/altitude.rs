//! `altitude`: the hook height over the whole approach, against the glide path and the landing point on the deck.

use deckland::simulation::{SignalId, Signals};

use super::{series, Shown, TIME};
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
            .series(
                "hook",
                series(samples, SignalId::HookHeight, Shown::AsRegistered),
            )
            .dashed_series(
                "glide path (hook reference)",
                series(samples, SignalId::PathHeight, Shown::AsRegistered),
            )
            .series(
                "landing point on the deck",
                series(samples, SignalId::AimHeight, Shown::AsRegistered),
            ),
        )
}
