//! `glide_path_error`: the hook's position error to the glide path (cf. paper Fig. 14).

use deckland::simulation::{SignalId, Signals};

use super::{series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The hook's position error to the glide path (cf. paper Fig. 14).
pub(super) fn figure(samples: &[Signals], title: &str) -> Figure {
    Figure::new()
        .title(format!(
            "Position error to the glide path (cf. paper Fig. 14) — {title}"
        ))
        .panel(
            Panel::new(
                "Glide-path error: path height − hook height (positive: hook below the path)",
                TIME,
                "error (m)",
            )
            .series(
                "glide-path error",
                series(samples, SignalId::GlidePathError, Shown::AsRegistered),
            )
            .reference_line("on the path", 0.0),
        )
}
