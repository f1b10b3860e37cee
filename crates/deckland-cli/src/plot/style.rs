//! The figures' look: palette, reference-line styles, marker colours, the bundled font,
//! and small helpers shared by the drawing code.

use std::cell::Cell;
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

thread_local! {
    /// Layout pixels per design pixel of the figure being drawn on this thread (see
    /// [`px`]); 1 outside [`Figure`](super::Figure)'s drawing.
    static SCALE: Cell<f64> = const { Cell::new(1.0) };
    /// Width (layout px) of the figure being drawn on this thread; 0 outside its drawing.
    static FIGURE_WIDTH: Cell<i32> = const { Cell::new(0) };
}

/// Every length of the drawing code (font sizes, margins, line widths, dash patterns,
/// marker sizes, the legend's spacing) is written in *design pixels*: those of a figure
/// whose small text (tick labels, legends) is 14 px. A figure is laid out at its output
/// resolution, where that text is `--font-pt` at `--figure-dpi`: plotters places
/// everything on whole pixels, and a figure laid out coarser than it is printed shows
/// the steps. [`Figure`](super::Figure) sets the scale for the time it draws; this is
/// `design` design pixels in layout pixels, rounded (at least 1 for a positive length).
pub(super) fn px(design: i32) -> i32 {
    let scaled = (f64::from(design) * scale()).round() as i32;
    if design > 0 {
        scaled.max(1)
    } else {
        scaled
    }
}

/// [`px`] of an unsigned length (a line width, a marker's size).
pub(super) fn pxu(design: u32) -> u32 {
    u32::try_from(px(i32::try_from(design).unwrap_or(i32::MAX / 4))).unwrap_or(0)
}

/// A font size (plotters' size, 1.24 em) of `design` design pixels in layout pixels,
/// not rounded: text takes any size.
pub(super) fn font_px(design: f64) -> f64 {
    design * scale()
}

/// The scale set for this thread's drawing.
pub(super) fn scale() -> f64 {
    SCALE.with(Cell::get)
}

/// The width (layout px) of the figure being drawn, `None` outside a figure's drawing.
pub(super) fn figure_width() -> Option<i32> {
    Some(FIGURE_WIDTH.with(Cell::get)).filter(|w| *w > 0)
}

/// Sets the scale and width of this thread's drawing until dropped, then restores the
/// previous ones.
pub(super) struct ScaleGuard {
    previous: (f64, i32),
}

impl ScaleGuard {
    /// Draws at `scale` layout pixels per design pixel, a figure `width` layout px wide,
    /// until the guard is dropped.
    pub(super) fn set(scale: f64, width: i32) -> Self {
        let previous = (
            SCALE.with(|cell| cell.replace(scale)),
            FIGURE_WIDTH.with(|cell| cell.replace(width)),
        );
        Self { previous }
    }
}

impl Drop for ScaleGuard {
    fn drop(&mut self) {
        SCALE.with(|cell| cell.set(self.previous.0));
        FIGURE_WIDTH.with(|cell| cell.set(self.previous.1));
    }
}

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

/// The finite points of `points`.
pub(super) fn finite(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect()
}

/// The size of the small text (tick labels, legends, line labels) in design pixels:
/// `--font-pt` is its size.
pub(super) const TEXT_SIZE: u32 = 14;

/// `text` set to fit `width` (layout px): on one line at the largest size from
/// `preferred` down to `smallest` (design px) at which it fits, else wrapped at word
/// boundaries at `smallest`. Returns the lines and the size (layout px).
pub(super) fn fitted_lines<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    text: &str,
    (preferred, smallest): (u32, u32),
    width: u32,
) -> (Vec<String>, f64) {
    let fits = |text: &str, size: f64| {
        area.estimate_text_size(text, &TextStyle::from((FONT_FAMILY, size).into_font()))
            .is_ok_and(|(w, _)| w <= width)
    };
    let one_line = (smallest..=preferred.max(smallest))
        .rev()
        .map(|size| font_px(f64::from(size)))
        .find(|&size| fits(text, size));
    match one_line {
        Some(size) => (vec![text.to_owned()], size),
        None => {
            let size = font_px(f64::from(smallest));
            (wrap(text, |line| fits(line, size)), size)
        }
    }
}

/// The distance (layout px) between the baselines of lines of text of plotters' `size`
/// (1.24 em): 1.2 em.
pub(super) fn line_height(size: f64) -> i32 {
    (size / 1.24 * 1.2).round() as i32
}

/// The height (layout px) plotters gives a line of text in `style`.
pub(super) fn text_height<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    style: &TextStyle,
) -> i32 {
    area.estimate_text_size("Hg", style)
        .map_or(0, |(_, h)| i32::try_from(h).unwrap_or(0))
}

/// `text` wrapped at word boundaries into lines that `fits` (a word longer than a line
/// stands alone); a last line of one word takes the word before it along when both fit.
pub(super) fn wrap(text: &str, fits: impl Fn(&str) -> bool) -> Vec<String> {
    let mut lines = fill_lines(text.split_whitespace(), &fits);
    if lines.is_empty() {
        lines.push(String::new());
    }
    no_lone_last_word(&mut lines, &fits);
    lines
}

/// `words` filled in order into lines that `fits`, one space apart (a word longer than a
/// line stands alone); no line for no words.
pub(super) fn fill_lines<S: AsRef<str>>(
    words: impl IntoIterator<Item = S>,
    fits: impl Fn(&str) -> bool,
) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in words {
        let word = word.as_ref();
        let candidate = if line.is_empty() {
            word.to_owned()
        } else {
            format!("{line} {word}")
        };
        if line.is_empty() || fits(&candidate) {
            line = candidate;
        } else {
            lines.push(std::mem::replace(&mut line, word.to_owned()));
        }
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// No lone word on the last of `lines`: takes the line before's last word down when the
/// two still `fit` ("… 0.3 m above the / deck" → "… 0.3 m above / the deck").
pub(super) fn no_lone_last_word(lines: &mut [String], fits: impl Fn(&str) -> bool) {
    if let [.., previous, last] = lines {
        if !last.contains(' ') {
            if let Some((rest, word)) = previous.rsplit_once(' ') {
                let joined = format!("{word} {last}");
                if fits(&joined) {
                    *last = joined;
                    previous.truncate(rest.len());
                }
            }
        }
    }
}
