//! Line plots for every command: a figure of one or more stacked panels, each with named
//! line series, a title, axis labels and optional horizontal reference lines, rendered to
//! PNG and SVG.
//!
//! Text uses a bundled subset of DejaVu Sans (`assets/fonts`, Bitstream Vera licence)
//! registered with plotters' `ab_glyph` backend, so plots render on machines with no
//! system fonts.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::output::OutputDir;

/// The bundled font (DejaVu Sans subset, see `assets/fonts/README.md`).
const FONT_BYTES: &[u8] = include_bytes!("../assets/fonts/DejaVuSans-subset.ttf");
/// The family name the bundled font is registered under.
const FONT_FAMILY: &str = "sans-serif";

/// Line colours, in the order series are drawn (colour-blind-safe palette of Okabe & Ito).
const PALETTE: [RGBColor; 7] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
];

/// Registers the bundled font once per process.
fn register_bundled_font() -> Result<()> {
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
fn is_jagged(pixels: &[(i32, i32)]) -> bool {
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

/// One named line: (x, y) points in data units.
#[derive(Debug, Clone)]
pub struct Series {
    /// Legend entry.
    pub name: String,
    /// The points; non-finite points are skipped.
    pub points: Vec<(f64, f64)>,
}

impl Series {
    /// A series called `name` through `points`.
    pub fn new(name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        Self {
            name: name.into(),
            points,
        }
    }
}

/// A horizontal reference line at `y` with a legend entry.
#[derive(Debug, Clone)]
pub struct ReferenceLine {
    /// Legend entry.
    pub name: String,
    /// Height in data units.
    pub y: f64,
}

/// One panel: axes with title, labels (with units), series and reference lines.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    title: String,
    x_label: String,
    y_label: String,
    series: Vec<Series>,
    reference_lines: Vec<ReferenceLine>,
}

impl Panel {
    /// An empty panel with a title and axis labels (say the units: "time (s)").
    pub fn new(
        title: impl Into<String>,
        x_label: impl Into<String>,
        y_label: impl Into<String>,
    ) -> Self {
        Self {
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            ..Self::default()
        }
    }

    /// Adds a line series.
    pub fn series(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.series.push(Series::new(name, points));
        self
    }

    /// Adds a dashed horizontal reference line at `y`.
    pub fn reference_line(mut self, name: impl Into<String>, y: f64) -> Self {
        self.reference_lines.push(ReferenceLine {
            name: name.into(),
            y,
        });
        self
    }

    /// Data ranges, padded by 5 % and never empty.
    fn ranges(&self) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
        let points = self.series.iter().flat_map(|s| s.points.iter().copied());
        let finite = points.filter(|(x, y)| x.is_finite() && y.is_finite());
        let (mut x_min, mut x_max, mut y_min, mut y_max) = (
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::INFINITY,
            f64::NEG_INFINITY,
        );
        for (x, y) in finite {
            (x_min, x_max) = (x_min.min(x), x_max.max(x));
            (y_min, y_max) = (y_min.min(y), y_max.max(y));
        }
        for line in self.reference_lines.iter().filter(|l| l.y.is_finite()) {
            (y_min, y_max) = (y_min.min(line.y), y_max.max(line.y));
        }
        let pad = |min: f64, max: f64, fraction: f64| {
            if !(min.is_finite() && max.is_finite()) {
                -1.0..1.0
            } else if max - min <= f64::EPSILON * max.abs().max(1.0) {
                (min - 1.0)..(max + 1.0)
            } else {
                let margin = fraction * (max - min);
                (min - margin)..(max + margin)
            }
        };
        (pad(x_min, x_max, 0.0), pad(y_min, y_max, 0.08))
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let (x_range, y_range) = self.ranges();
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, (FONT_FAMILY, 20))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x_range.clone(), y_range)
            .map_err(error)?;
        chart
            .configure_mesh()
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style((FONT_FAMILY, 14))
            .axis_desc_style((FONT_FAMILY, 16))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(error)?;
        for (index, series) in self.series.iter().enumerate() {
            let colour = PALETTE[index % PALETTE.len()];
            let finite: Vec<(f64, f64)> = series
                .points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite())
                .collect();
            let pixels: Vec<(i32, i32)> = finite.iter().map(|p| chart.backend_coord(p)).collect();
            let width = if is_jagged(&pixels) { 1 } else { 2 };
            chart
                .draw_series(LineSeries::new(finite, colour.stroke_width(width)))
                .map_err(error)?
                .label(series.name.as_str())
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 24, y)], colour.stroke_width(2))
                });
        }
        for line in &self.reference_lines {
            let style = RGBColor(90, 90, 90).stroke_width(1);
            let ends = [(x_range.start, line.y), (x_range.end, line.y)];
            chart
                .draw_series(DashedLineSeries::new(ends, 8, 5, style))
                .map_err(error)?
                .label(line.name.as_str())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
        }
        if self.series.len() + self.reference_lines.len() > 1 {
            chart
                .configure_series_labels()
                .label_font((FONT_FAMILY, 14))
                .background_style(WHITE.mix(0.85))
                .border_style(RGBColor(160, 160, 160))
                .position(SeriesLabelPosition::UpperRight)
                .draw()
                .map_err(error)?;
        }
        Ok(())
    }
}

/// A figure: an optional overall title above panels stacked top to bottom.
#[derive(Debug, Clone)]
pub struct Figure {
    title: Option<String>,
    panels: Vec<Panel>,
    width_px: u32,
    panel_height_px: u32,
}

impl Figure {
    /// An empty figure 1000 px wide, 420 px per panel.
    pub fn new() -> Self {
        Self {
            title: None,
            panels: Vec::new(),
            width_px: 1000,
            panel_height_px: 420,
        }
    }

    /// Sets a title above all panels.
    pub fn title(mut self, title: impl Into<String>) -> Self {
        self.title = Some(title.into());
        self
    }

    /// Adds a panel below the others.
    pub fn panel(mut self, panel: Panel) -> Self {
        self.panels.push(panel);
        self
    }

    /// Overall size in pixels (width, height).
    fn size(&self) -> (u32, u32) {
        let title = if self.title.is_some() { 40 } else { 0 };
        let rows = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        (self.width_px, title + rows * self.panel_height_px)
    }

    fn draw<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        root.fill(&WHITE).map_err(error)?;
        let body = match &self.title {
            Some(title) => root.titled(title, (FONT_FAMILY, 24)).map_err(error)?,
            None => root.clone(),
        };
        let areas = body.split_evenly((self.panels.len().max(1), 1));
        for (area, panel) in areas.iter().zip(&self.panels) {
            panel.draw(area)?;
        }
        root.present().map_err(error)?;
        Ok(())
    }

    /// Renders the figure as PNG to `path` (the extension selects the format).
    pub fn render_png(&self, path: &Path) -> Result<()> {
        register_bundled_font()?;
        self.draw(BitMapBackend::new(path, self.size()).into_drawing_area())
    }

    /// Renders the figure as an SVG document.
    pub fn render_svg(&self) -> Result<String> {
        register_bundled_font()?;
        let mut svg = String::new();
        self.draw(SVGBackend::with_string(&mut svg, self.size()).into_drawing_area())?;
        Ok(svg)
    }

    /// Writes `<stem>.png` and `<stem>.svg` atomically into `output`; returns both paths.
    pub fn save(&self, output: &OutputDir, stem: &str) -> Result<[PathBuf; 2]> {
        let png = output.write_with(&format!("{stem}.png"), |path| self.render_png(path))?;
        let svg = output.write_bytes(&format!("{stem}.svg"), self.render_svg()?.as_bytes())?;
        Ok([png, svg])
    }
}

impl Default for Figure {
    fn default() -> Self {
        Self::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bundled_font_registers() {
        assert!(register_bundled_font().is_ok());
    }

    #[test]
    fn jagged_lines_are_recognised() {
        let smooth: Vec<(i32, i32)> = (0..100).map(|i| (i, i / 3)).collect();
        let jagged: Vec<(i32, i32)> = (0..100).map(|i| (i / 5, (i % 2) * 3)).collect();
        assert!(!is_jagged(&smooth));
        assert!(is_jagged(&jagged));
    }

    #[test]
    fn ranges_are_padded_and_never_empty() {
        let flat = Panel::new("t", "x", "y").series("a", vec![(0.0, 2.0), (1.0, 2.0)]);
        let (x, y) = flat.ranges();
        assert_eq!(x, 0.0..1.0);
        assert!(y.start < 2.0 && y.end > 2.0);
        let empty = Panel::new("t", "x", "y");
        assert_eq!(empty.ranges().0, -1.0..1.0);
    }

    #[test]
    fn figure_renders_to_svg_with_its_text() {
        let figure = Figure::new()
            .title("Two panels")
            .panel(
                Panel::new("Upper", "time (s)", "height (m)")
                    .series(
                        "sine",
                        (0..100)
                            .map(|i| (f64::from(i) * 0.1, (f64::from(i) * 0.1).sin()))
                            .collect(),
                    )
                    .reference_line("zero", 0.0),
            )
            .panel(
                Panel::new("Lower", "time (s)", "speed (m/s)")
                    .series("line", vec![(0.0, 0.0), (1.0, 1.0)]),
            );
        let svg = figure.render_svg().expect("renders");
        assert!(
            svg.contains("Two panels") && svg.contains("height (m)") && svg.contains("speed (m/s)")
        );
    }
}
