//! `airspeed`: the true airspeed and the angle of attack.

use deckland::simulation::Signals;

use super::{series, TIME};
use crate::plot::{Figure, Panel};

/// The true airspeed and the angle of attack.
pub(super) fn figure(samples: &[Signals], title: &str) -> Figure {
    Figure::new()
        .title(format!("Airspeed and angle of attack — {title}"))
        .panel(
            Panel::new("True airspeed", TIME, "airspeed (m/s)")
                .series("airspeed", series(samples, |s| s.airspeed_mps)),
        )
        .panel(
            Panel::new("Angle of attack", TIME, "angle of attack α (deg)")
                .series("α", series(samples, |s| s.alpha_rad.to_degrees())),
        )
}
