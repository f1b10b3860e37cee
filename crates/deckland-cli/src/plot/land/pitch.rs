//! `pitch`: the pitch attitude and its command on approach (cf. paper Fig. 15).

use deckland::simulation::{SignalId, Signals};

use super::{series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The pitch attitude and its command on approach (cf. paper Fig. 15).
pub(super) fn figure(samples: &[Signals], title: &str) -> Figure {
    Figure::new()
        .title(format!(
            "Pitch angle on approach (cf. paper Fig. 15) — {title}"
        ))
        .panel(
            Panel::new("Pitch attitude and command", TIME, "pitch θ (deg)")
                .series(
                    "pitch command",
                    series(samples, SignalId::ThetaRef, Shown::Degrees),
                )
                .series("pitch θ", series(samples, SignalId::Theta, Shown::Degrees)),
        )
}
