//! `pitch`: the pitch attitude and its command on approach (cf. paper Fig. 15).

use deckland::simulation::Signals;

use super::{series, TIME};
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
                    series(samples, |s| s.theta_ref_rad.to_degrees()),
                )
                .series("pitch θ", series(samples, |s| s.theta_rad.to_degrees())),
        )
}
