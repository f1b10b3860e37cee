//! Plots for every command: a figure of one or more stacked panels, each with a title,
//! axis labels and any of named line series, scatter series, histograms, horizontal and
//! vertical reference lines — or a bar chart of counts by category — rendered to PNG and
//! SVG.
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

/// A vertical reference line at `x` with a legend entry.
#[derive(Debug, Clone)]
pub struct VerticalLine {
    /// Legend entry.
    pub name: String,
    /// Position in data units.
    pub x: f64,
}

/// A named set of values drawn as a histogram (counts per bin).
#[derive(Debug, Clone)]
pub struct Histogram {
    /// Legend entry.
    pub name: String,
    /// The values; non-finite values are skipped.
    pub values: Vec<f64>,
}

/// One group of bars of a bar chart: one value per category.
#[derive(Debug, Clone)]
pub struct Bars {
    /// Legend entry.
    pub name: String,
    /// One value per category, in the chart's category order.
    pub values: Vec<f64>,
}

/// One panel: axes with title, labels (with units), line and scatter series,
/// histograms and reference lines; or, with categories, a bar chart.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    title: String,
    x_label: String,
    y_label: String,
    series: Vec<Series>,
    scatter: Vec<Series>,
    histograms: Vec<Histogram>,
    histogram_bins: usize,
    reference_lines: Vec<ReferenceLine>,
    vertical_lines: Vec<VerticalLine>,
    categories: Vec<String>,
    bars: Vec<Bars>,
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

    /// Adds a series drawn as points (no line).
    pub fn scatter(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.scatter.push(Series::new(name, points));
        self
    }

    /// Adds a dashed vertical reference line at `x`.
    pub fn vertical_line(mut self, name: impl Into<String>, x: f64) -> Self {
        self.vertical_lines.push(VerticalLine {
            name: name.into(),
            x,
        });
        self
    }

    /// Adds a histogram of `values`; every histogram of a panel shares the same `bins`
    /// equal bins over the range of all their values (the last call's `bins` counts).
    pub fn histogram(mut self, name: impl Into<String>, values: Vec<f64>, bins: usize) -> Self {
        self.histograms.push(Histogram {
            name: name.into(),
            values,
        });
        self.histogram_bins = bins.max(1);
        self
    }

    /// Makes the panel a bar chart over `categories` (x axis); add groups with
    /// [`Panel::bars`].
    pub fn categories(mut self, categories: Vec<String>) -> Self {
        self.categories = categories;
        self
    }

    /// Adds a group of bars, one value per category, drawn side by side with the others.
    pub fn bars(mut self, name: impl Into<String>, values: Vec<f64>) -> Self {
        self.bars.push(Bars {
            name: name.into(),
            values,
        });
        self
    }

    /// The shared bins of the panel's histograms: (first edge, width, count), or `None`
    /// without finite values.
    fn bins(&self) -> Option<(f64, f64, usize)> {
        let values = self
            .histograms
            .iter()
            .flat_map(|h| h.values.iter().copied());
        let (min, max) = values
            .filter(|v| v.is_finite())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        if !(min.is_finite() && max.is_finite()) {
            return None;
        }
        let count = self.histogram_bins.max(1);
        let span = if max > min { max - min } else { 1.0 };
        let start = if max > min { min } else { min - 0.5 };
        Some((start, span / count as f64, count))
    }

    /// Counts of `values` in the bins `(start, width, count)`; the top edge is in the
    /// last bin.
    fn bin_counts(values: &[f64], (start, width, count): (f64, f64, usize)) -> Vec<u64> {
        let mut counts = vec![0; count];
        for v in values.iter().filter(|v| v.is_finite()) {
            let index = (((v - start) / width).floor().max(0.0) as usize).min(count - 1);
            counts[index] += 1;
        }
        counts
    }

    /// Data ranges, padded by 5 % and never empty.
    fn ranges(&self) -> (std::ops::Range<f64>, std::ops::Range<f64>) {
        let mut extra: Vec<(f64, f64)> = Vec::new();
        if let Some(bins) = self.bins() {
            let (start, width, count) = bins;
            let highest = self
                .histograms
                .iter()
                .flat_map(|h| Self::bin_counts(&h.values, bins))
                .max()
                .unwrap_or(0);
            extra.push((start, 0.0));
            extra.push((start + width * count as f64, highest as f64));
        }
        let points = self
            .series
            .iter()
            .chain(&self.scatter)
            .flat_map(|s| s.points.iter().copied())
            .chain(extra);
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
        for line in self.vertical_lines.iter().filter(|l| l.x.is_finite()) {
            (x_min, x_max) = (x_min.min(line.x), x_max.max(line.x));
        }
        let x_fraction = if self.scatter.is_empty() && self.vertical_lines.is_empty() {
            0.0
        } else {
            0.04
        };
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
        (pad(x_min, x_max, x_fraction), pad(y_min, y_max, 0.08))
    }

    fn draw<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        if !self.categories.is_empty() {
            return self.draw_bar_chart(area);
        }
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let (x_range, y_range) = self.ranges();
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, (FONT_FAMILY, 20))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x_range.clone(), y_range.clone())
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
        if let Some(bins) = self.bins() {
            let (start, width, _) = bins;
            for (index, histogram) in self.histograms.iter().enumerate() {
                let colour = PALETTE[index % PALETTE.len()];
                let fill = colour.mix(if self.histograms.len() > 1 {
                    0.45
                } else {
                    0.75
                });
                let counts = Self::bin_counts(&histogram.values, bins);
                let rectangles = counts.into_iter().enumerate().map(move |(bin, count)| {
                    let left = start + width * bin as f64;
                    Rectangle::new([(left, 0.0), (left + width, count as f64)], fill.filled())
                });
                chart
                    .draw_series(rectangles)
                    .map_err(error)?
                    .label(histogram.name.as_str())
                    .legend(move |(x, y)| {
                        Rectangle::new([(x, y - 5), (x + 24, y + 5)], fill.filled())
                    });
            }
        }
        let offset = self.series.len();
        for (index, series) in self.scatter.iter().enumerate() {
            let colour = PALETTE[(offset + index) % PALETTE.len()];
            let finite = series
                .points
                .iter()
                .copied()
                .filter(|(x, y)| x.is_finite() && y.is_finite());
            chart
                .draw_series(finite.map(move |p| Circle::new(p, 3, colour.mix(0.7).filled())))
                .map_err(error)?
                .label(series.name.as_str())
                .legend(move |(x, y)| Circle::new((x + 12, y), 4, colour.filled()));
        }
        for line in &self.vertical_lines {
            let style = RGBColor(90, 90, 90).stroke_width(1);
            let ends = [(line.x, y_range.start), (line.x, y_range.end)];
            chart
                .draw_series(DashedLineSeries::new(ends, 6, 4, style))
                .map_err(error)?;
            let label_style = (FONT_FAMILY, 13).into_font().color(&RGBColor(60, 60, 60));
            chart
                .draw_series(std::iter::once(Text::new(
                    line.name.clone(),
                    (line.x, y_range.end),
                    label_style,
                )))
                .map_err(error)?;
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
        if self.series.len()
            + self.scatter.len()
            + self.histograms.len()
            + self.reference_lines.len()
            > 1
        {
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

    /// Draws the panel as a bar chart: categories along x, the groups side by side.
    fn draw_bar_chart<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let categories = self.categories.len();
        let highest = self
            .bars
            .iter()
            .flat_map(|b| b.values.iter().copied())
            .filter(|v| v.is_finite())
            .fold(0.0_f64, f64::max);
        let top = if highest > 0.0 { highest * 1.12 } else { 1.0 };
        let x_range = -0.5..(categories as f64 - 0.5);
        let names = self.categories.clone();
        let label = move |x: &f64| {
            let nearest = x.round();
            if (x - nearest).abs() < 1e-6 && nearest >= 0.0 {
                names.get(nearest as usize).cloned().unwrap_or_default()
            } else {
                String::new()
            }
        };
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, (FONT_FAMILY, 20))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x_range, 0.0..top)
            .map_err(error)?;
        chart
            .configure_mesh()
            .disable_x_mesh()
            .x_labels(categories.max(1))
            .x_label_formatter(&label)
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style((FONT_FAMILY, 14))
            .axis_desc_style((FONT_FAMILY, 16))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()
            .map_err(error)?;
        let groups = self.bars.len().max(1);
        let group_width = 0.8 / groups as f64;
        for (index, bars) in self.bars.iter().enumerate() {
            let colour = PALETTE[index % PALETTE.len()];
            let rectangles = bars
                .values
                .iter()
                .enumerate()
                .map(move |(category, &value)| {
                    let left = category as f64 - 0.4 + group_width * index as f64;
                    let height = if value.is_finite() { value } else { 0.0 };
                    Rectangle::new([(left, 0.0), (left + group_width, height)], colour.filled())
                });
            chart
                .draw_series(rectangles)
                .map_err(error)?
                .label(bars.name.as_str())
                .legend(move |(x, y)| {
                    Rectangle::new([(x, y - 5), (x + 24, y + 5)], colour.filled())
                });
            let text_style = (FONT_FAMILY, 13).into_font().color(&RGBColor(40, 40, 40));
            let values = bars
                .values
                .iter()
                .enumerate()
                .map(move |(category, &value)| {
                    let centre = category as f64 - 0.4 + group_width * (index as f64 + 0.35);
                    Text::new(
                        format!("{value}"),
                        (centre, value + top * 0.05),
                        text_style.clone(),
                    )
                });
            chart.draw_series(values).map_err(error)?;
        }
        if self.bars.len() > 1 {
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
    fn histogram_bins_share_the_range_and_count_every_value() {
        let panel = Panel::new("t", "x", "count")
            .histogram("a", vec![0.0, 1.0, 2.0, 3.0], 3)
            .histogram("b", vec![3.0, 3.0, f64::NAN], 3);
        let bins = panel.bins().expect("values");
        assert_eq!(bins, (0.0, 1.0, 3));
        assert_eq!(Panel::bin_counts(&[0.0, 1.0, 2.0, 3.0], bins), [1, 1, 2]);
        assert_eq!(Panel::bin_counts(&[3.0, 3.0, f64::NAN], bins), [0, 0, 2]);
        let (x, y) = panel.ranges();
        assert_eq!(x, 0.0..3.0);
        assert!(y.start < 0.0 && y.end > 2.0);
    }

    #[test]
    fn scatter_histogram_and_bar_panels_render() {
        let figure = Figure::new()
            .panel(
                Panel::new("Scatter", "distance (m)", "sink rate (m/s)")
                    .scatter("runs", vec![(-3.0, 3.5), (2.0, 4.0), (f64::NAN, 1.0)])
                    .vertical_line("wire 1", -18.0)
                    .reference_line("limit", 7.6),
            )
            .panel(
                Panel::new("Histogram", "sink rate (m/s)", "runs").histogram(
                    "O-PD",
                    vec![3.0, 3.5, 4.0, 4.2],
                    5,
                ),
            )
            .panel(
                Panel::new("Outcomes", "outcome", "runs")
                    .categories(vec!["trap".into(), "bolter".into()])
                    .bars("O-PD", vec![9.0, 1.0])
                    .bars("PID", vec![7.0, 3.0]),
            );
        let svg = figure.render_svg().expect("renders");
        for text in ["wire 1", "Histogram", "trap", "bolter", "PID"] {
            assert!(svg.contains(text), "{text}");
        }
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
