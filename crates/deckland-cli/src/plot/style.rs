//! The figures' look: palette, reference-line styles, marker colours, the bundled font,
//! and small helpers shared by the drawing code.

use std::sync::OnceLock;

use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::prelude::*;

/// The bundled font (DejaVu Sans subset, see `assets/fonts/README.md`).
pub(crate) const FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");
/// The family name the bundled font is registered under: a generic family, so that an SVG
/// opened elsewhere falls back to the reader's own sans-serif font.
pub(crate) const FONT_FAMILY: &str = "sans-serif";

/// Line colours, in the order series are drawn (colour-blind-safe palette of Okabe & Ito).
pub(super) const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];

/// The palette's colour for the series at `index` (repeating).
pub(crate) fn palette(index: usize) -> RGBColor {
    PALETTE[index % PALETTE.len()]
}

/// Colours and dash patterns (dash, gap in px) of horizontal reference lines, in the
/// order their names first appear: distinct from each other and from the data.
pub(super) const REFERENCE_STYLES: [(RGBColor, (u32, u32)); 4] = [
    (RGBColor(80, 80, 80), (8, 5)),
    (RGBColor(170, 30, 30), (3, 3)),
    (RGBColor(110, 50, 160), (12, 4)),
    (RGBColor(0, 90, 50), (2, 6)),
];

/// Colours of point markers, in the order they are added.
pub(super) const MARKER_COLOURS: [RGBColor; 4] = [
    RGBColor(0, 0, 0),
    RGBColor(200, 30, 30),
    RGBColor(110, 50, 160),
    RGBColor(0, 110, 60),
];

/// Colour of the ship's deck in pictures of the landing.
pub(crate) const DECK_COLOUR: RGBColor = RGBColor(60, 60, 60);
/// The ship's flight-deck outline in the plan view: a light grey under the deck's lines.
pub(crate) const SHIP_COLOUR: RGBColor = RGBColor(150, 150, 150);

/// Colour of vertical reference lines and their labels.
pub(super) const VERTICAL_LINE_COLOUR: RGBColor = RGBColor(90, 90, 90);

/// Registers the bundled font once per process.
pub(super) fn register_bundled_font() -> Result<()> {
    static REGISTERED: OnceLock<bool> = OnceLock::new();
    let ok = *REGISTERED.get_or_init(|| {
        [FontStyle::Normal, FontStyle::Bold]
            .into_iter()
            .all(|style| plotters::style::register_font(FONT_FAMILY, style, FONT_BYTES).is_ok())
    });
    if ok {
        Ok(())
    } else {
        Err(anyhow!("the bundled plot font could not be loaded"))
    }
}

/// Whether a line, in pixels, turns back on itself vertically at more than a tenth of its
/// points: plotters polygonises lines wider than 1 px and such lines then break up, so
/// they are drawn 1 px wide.
pub(super) fn is_jagged(pixels: &[(i32, i32)]) -> bool {
    let mut steps = pixels
        .windows(2)
        .map(|w| w[1].1 - w[0].1)
        .filter(|dy| *dy != 0);
    let Some(mut previous) = steps.next() else {
        return false;
    };
    let mut reversals = 0;
    for step in steps {
        if step.signum() != previous.signum() {
            reversals += 1;
        }
        previous = step;
    }
    reversals * 10 > pixels.len()
}

/// The finite points of `points`.
pub(super) fn finite(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect()
}

/// The largest font size from `preferred` down to 11 px at which `text` fits `width` px.
pub(super) fn fitted_font_size<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    preferred: u32,
    width: u32,
) -> u32 {
    (11..=preferred)
        .rev()
        .find(|&size| {
            area.estimate_text_size(text, &TextStyle::from((FONT_FAMILY, size).into_font()))
                .is_ok_and(|(w, _)| w <= width)
        })
        .unwrap_or(11)
}
