//! Plots for every command: a figure of one or more stacked panels, each with a title,
//! axis labels and any of named line series, scatter series, point markers, histograms,
//! horizontal and vertical reference lines — or a bar chart by category, with intervals —
//! laid out for the width it is printed at and written as SVG, PNG and, on request, PDF.
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
//! Size ([`options`]): a figure is `--figure-width-mm` wide when printed (default IEEE's
//! one column, 88.9 mm) and its small text — tick labels, legends — is `--font-pt` at that
//! width (default 8 pt); axis labels are 16/14 and titles up to 23/14 of it. The drawing
//! code's lengths are design pixels, those of 14 px small text; the figure is laid out
//! at its output resolution, `style::px` scaling every length.
//!
//! Files ([`render`]): plotters draws the SVG; resvg rasterises it to the PNG
//! (`--figure-dpi`, default 300, the resolution written into the file) and svg2pdf
//! converts it to the PDF (`--pdf`), both with the same font, so every file has the same
//! layout and the text is shaped and kerned (rustybuzz).
//!
//! Text uses a bundled subset of DejaVu Sans (`assets/fonts`, Bitstream Vera licence):
//! plotters measures it through its `ab_glyph` backend, resvg and svg2pdf render it, so
//! plots render on machines with no system fonts, and the PDF embeds it. The SVG files
//! name only the generic family `sans-serif`, never a font file or an external address.
//!
//! Layout: the figures, one module each — [`land`] (the approach's seven figures),
//! [`step`], [`sink`], [`campaign`] — over the shared drawing code: [`Panel`] (`panel`:
//! content and data ranges; `draw`: axes, series and legend; `bars`: bar charts), [`Figure`] (`figure`:
//! stacking, layout and files; `render`: PNG and PDF from the SVG), `options` (size and
//! files), `style` (palette, font, scale), `legend` and `ticks`.

mod bars;
pub(crate) mod campaign;
mod draw;
mod figure;
pub(crate) mod land;
mod legend;
pub(crate) mod options;
mod panel;
mod render;
pub(crate) mod sink;
pub(crate) mod step;
mod style;

#[cfg(test)]
mod size_tests;
#[cfg(test)]
pub(crate) mod tests;
mod ticks;

pub use figure::Figure;
pub use legend::{MarkerShape, MarkerStyle};
pub use options::FigureArgs;
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
