//! Plots for every command: a figure of one or more stacked panels, each with a title,
//! axis labels and any of named line series, scatter series, point markers, histograms,
//! horizontal and vertical reference lines — or a bar chart by category, with intervals —
//! rendered to PNG and SVG.
//!
//! What a reviewer expects of a figure is built in:
//! - the legend never covers data: it goes where nothing is drawn, or beside the axes
//!   (in a column shared by all panels, so their axes stay aligned, which then holds
//!   every panel's legend, so that none stands beside an empty column) — see [`legend`];
//! - the axes span the data: a limit far from it is named in a note
//!   ([`Panel::limit_line`]) rather than stretching the axis;
//! - points of several series are told apart by shape and by fill (filled or hollow),
//!   not by colour alone ([`MarkerStyle`]); a bar chart may take a log axis for rare
//!   counts, and draws no bar for a zero;
//! - each legend entry is drawn with its line's colour, width and dash pattern, and
//!   distinct reference lines have distinct colours and dashes;
//! - each axis writes its ticks with one precision, counts as integers, never "-0"
//!   (see [`ticks`]);
//! - several histograms on one panel are drawn side by side within each bin, never
//!   blended;
//! - nothing non-finite is drawn or written.
//!
//! Text uses a bundled subset of DejaVu Sans (`assets/fonts`, Bitstream Vera licence)
//! registered with plotters' `ab_glyph` backend, so plots render on machines with no
//! system fonts. The SVG files name only the generic family `sans-serif`, never a font
//! file or an external address.
//!
//! Layout: the figures, one module each — [`land`] (the approach's seven figures),
//! [`step`], [`sink`], [`campaign`] — over the shared drawing code: [`Panel`] (`panel`:
//! content and data ranges; `draw`: axes, series and legend; `bars`: bar charts), [`Figure`] (`figure`:
//! stacking and PNG/SVG files), `style` (palette, font), `legend` and `ticks`.

mod bars;
pub(crate) mod campaign;
mod draw;
mod figure;
pub(crate) mod land;
mod legend;
mod panel;
pub(crate) mod sink;
pub(crate) mod step;
mod style;

#[cfg(test)]
pub(crate) mod tests;
mod ticks;

pub use figure::Figure;
pub use legend::{MarkerShape, MarkerStyle};
pub use panel::{BarGroup, Panel};
pub(crate) use style::{palette, DECK_COLOUR, FONT_BYTES, FONT_FAMILY, SHIP_COLOUR};

/// `value` with its sign, a true minus for negative values: "+10", "−25".
pub(crate) fn signed(value: f64) -> String {
    if value < 0.0 {
        format!("\u{2212}{}", -value)
    } else {
        format!("+{value}")
    }
}
