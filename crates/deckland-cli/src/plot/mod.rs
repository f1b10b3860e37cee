//! Plots for every command: a figure of one or more stacked panels, each with a title,
//! axis labels and any of named line series, scatter series, point markers, histograms,
//! horizontal and vertical reference lines — or a bar chart by category, with intervals —
//! rendered to PNG and SVG.
//!
//! What a reviewer expects of a figure is built in:
//! - the legend never covers data: it goes where nothing is drawn, or beside the axes
//!   (in a column shared by all panels, so their axes stay aligned) — see [`legend`];
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

mod legend;
mod ticks;

use std::ops::Range;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use anyhow::{anyhow, Result};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

pub use legend::MarkerShape;
use legend::{draw_marker, Legend, Occupancy, PixelRect, Sample};
use ticks::{AxisLabels, X_LABELS, Y_LABELS};

use crate::output::OutputDir;

/// The bundled font (DejaVu Sans subset, see `assets/fonts/README.md`).
pub(crate) const FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans-subset.ttf");
/// The family name the bundled font is registered under: a generic family, so that an SVG
/// opened elsewhere falls back to the reader's own sans-serif font.
pub(crate) const FONT_FAMILY: &str = "sans-serif";

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

/// Colours and dash patterns (dash, gap in px) of horizontal reference lines, in the
/// order their names first appear: distinct from each other and from the data.
const REFERENCE_STYLES: [(RGBColor, (u32, u32)); 4] = [
    (RGBColor(80, 80, 80), (8, 5)),
    (RGBColor(170, 30, 30), (3, 3)),
    (RGBColor(110, 50, 160), (12, 4)),
    (RGBColor(0, 90, 50), (2, 6)),
];

/// Colours of point markers, in the order they are added.
const MARKER_COLOURS: [RGBColor; 4] = [
    RGBColor(0, 0, 0),
    RGBColor(200, 30, 30),
    RGBColor(110, 50, 160),
    RGBColor(0, 110, 60),
];

/// Colour of the ship's deck in pictures of the landing.
pub(crate) const DECK_COLOUR: RGBColor = RGBColor(60, 60, 60);

/// Colour of vertical reference lines and their labels.
const VERTICAL_LINE_COLOUR: RGBColor = RGBColor(90, 90, 90);

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

/// The finite points of `points`.
fn finite(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite())
        .collect()
}

/// The largest font size from `preferred` down to 11 px at which `text` fits `width` px.
fn fitted_font_size<DB: DrawingBackend>(
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

/// One named line: (x, y) points in data units.
#[derive(Debug, Clone)]
struct Line {
    name: String,
    points: Vec<(f64, f64)>,
    dashed: bool,
    colour: Option<RGBColor>,
}

/// A named set of points drawn as dots.
#[derive(Debug, Clone)]
struct Scatter {
    name: String,
    points: Vec<(f64, f64)>,
}

/// One named point drawn as a marker.
#[derive(Debug, Clone)]
struct Marker {
    name: String,
    point: (f64, f64),
    shape: MarkerShape,
}

/// A horizontal reference line at `y`; lines of the same name share a style and an entry.
#[derive(Debug, Clone)]
struct ReferenceLine {
    name: String,
    y: f64,
}

/// A vertical reference line at `x`, labelled at the top of the axes.
#[derive(Debug, Clone)]
struct VerticalLine {
    name: String,
    x: f64,
}

/// A named set of values drawn as a histogram (counts per bin).
#[derive(Debug, Clone)]
struct Histogram {
    name: String,
    values: Vec<f64>,
}

/// One group of bars of a bar chart: one value per category, with an optional interval
/// (drawn as an error bar) and a label above each bar.
#[derive(Debug, Clone, Default)]
pub struct BarGroup {
    /// Legend entry.
    pub name: String,
    /// One value per category, in the chart's category order.
    pub values: Vec<f64>,
    /// One (low, high) interval per category, or none.
    pub intervals: Vec<(f64, f64)>,
    /// One label per category written above its bar, or none (then the value).
    pub labels: Vec<String>,
}

/// One panel: axes with title, labels (with units), line and scatter series, markers,
/// histograms and reference lines; or, with categories, a bar chart.
#[derive(Debug, Clone, Default)]
pub struct Panel {
    title: String,
    x_label: String,
    y_label: String,
    lines: Vec<Line>,
    scatter: Vec<Scatter>,
    markers: Vec<Marker>,
    histograms: Vec<Histogram>,
    histogram_bins: usize,
    reference_lines: Vec<ReferenceLine>,
    vertical_lines: Vec<VerticalLine>,
    categories: Vec<String>,
    bars: Vec<BarGroup>,
    interval_name: String,
    notes: Vec<String>,
    integer_y: bool,
    x_limits: Option<Range<f64>>,
}

/// Where a panel's legend went: `Some(width)` when it needs the column beside the axes.
type OutsideLegend = Option<i32>;

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

    /// Adds a solid line series.
    pub fn series(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.lines.push(Line {
            name: name.into(),
            points,
            dashed: false,
            colour: None,
        });
        self
    }

    /// Adds a dashed line series (for references that vary, such as a command).
    pub fn dashed_series(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.lines.push(Line {
            name: name.into(),
            points,
            dashed: true,
            colour: None,
        });
        self
    }

    /// Adds a solid line series in a colour of its own (for a physical object, such as
    /// the deck, rather than one series among others).
    pub fn coloured_series(
        mut self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        colour: RGBColor,
    ) -> Self {
        self.lines.push(Line {
            name: name.into(),
            points,
            dashed: false,
            colour: Some(colour),
        });
        self
    }

    /// Adds a dashed horizontal reference line at `y`; lines given the same name share a
    /// style and one legend entry (the two edges of a band).
    pub fn reference_line(mut self, name: impl Into<String>, y: f64) -> Self {
        self.reference_lines.push(ReferenceLine {
            name: name.into(),
            y,
        });
        self
    }

    /// Adds a series drawn as points (no line).
    pub fn scatter(mut self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.scatter.push(Scatter {
            name: name.into(),
            points,
        });
        self
    }

    /// Adds one named point drawn as a marker of `shape`.
    pub fn marker(
        mut self,
        name: impl Into<String>,
        point: (f64, f64),
        shape: MarkerShape,
    ) -> Self {
        self.markers.push(Marker {
            name: name.into(),
            point,
            shape,
        });
        self
    }

    /// Adds a dashed vertical reference line at `x`, labelled with its name at the top.
    pub fn vertical_line(mut self, name: impl Into<String>, x: f64) -> Self {
        self.vertical_lines.push(VerticalLine {
            name: name.into(),
            x,
        });
        self
    }

    /// Adds a histogram of `values`; every histogram of a panel shares the same `bins`
    /// equal bins over the range of all their values (the last call's `bins` counts), and
    /// several are drawn side by side within each bin. The y axis counts, in integers.
    pub fn histogram(mut self, name: impl Into<String>, values: Vec<f64>, bins: usize) -> Self {
        self.histograms.push(Histogram {
            name: name.into(),
            values,
        });
        self.histogram_bins = bins.max(1);
        self.integer_y = true;
        self
    }

    /// Makes the panel a bar chart over `categories` (x axis); add groups with
    /// [`Panel::bar_group`].
    pub fn categories(mut self, categories: Vec<String>) -> Self {
        self.categories = categories;
        self
    }

    /// Adds a group of bars with their intervals and labels.
    pub fn bar_group(mut self, group: BarGroup) -> Self {
        self.bars.push(group);
        self
    }

    /// Names the bars' intervals in the legend ("95 % Wilson score interval").
    pub fn interval_name(mut self, name: impl Into<String>) -> Self {
        self.interval_name = name.into();
        self
    }

    /// Writes `text` in bold at the top of the legend (the outcome of a run).
    pub fn note(mut self, text: impl Into<String>) -> Self {
        self.notes.push(text.into());
        self
    }

    /// Fixes the x axis to `range` instead of the data's.
    pub fn x_limits(mut self, range: Range<f64>) -> Self {
        self.x_limits = Some(range);
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

    /// Data ranges, padded and never empty; a count axis starts at zero.
    fn ranges(&self) -> (Range<f64>, Range<f64>) {
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
        let limits = self.x_limits.clone();
        let in_window = |x: f64| limits.as_ref().is_none_or(|r| x >= r.start && x <= r.end);
        let points = self
            .lines
            .iter()
            .flat_map(|s| s.points.iter().copied())
            .chain(self.scatter.iter().flat_map(|s| s.points.iter().copied()))
            .chain(self.markers.iter().map(|m| m.point))
            .chain(extra);
        let finite = points.filter(|(x, y)| x.is_finite() && y.is_finite() && in_window(*x));
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
        let x_fraction =
            if self.scatter.is_empty() && self.vertical_lines.is_empty() && self.markers.is_empty()
            {
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
        let x = match &self.x_limits {
            Some(r) if r.start.is_finite() && r.end.is_finite() && r.end > r.start => r.clone(),
            _ => pad(x_min, x_max, x_fraction),
        };
        let y = if self.histograms.is_empty() {
            pad(y_min, y_max, 0.08)
        } else {
            0.0..(y_max.max(1.0) * 1.08)
        };
        (x, y)
    }

    /// The chart's axes, title and grid on `area`.
    fn axes<'a, DB: DrawingBackend + 'a>(
        &self,
        area: &'a DrawingArea<DB, Shift>,
        x_range: Range<f64>,
        y_range: Range<f64>,
        categories: bool,
    ) -> Result<ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let width = area.dim_in_pixel().0.saturating_sub(30);
        let caption_size = fitted_font_size(area, &self.title, 19, width);
        let mut chart = ChartBuilder::on(area)
            .caption(&self.title, (FONT_FAMILY, caption_size))
            .margin(12)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d(x_range.clone(), y_range.clone())
            .map_err(error)?;
        let x_labels = AxisLabels::new(&x_range, X_LABELS, false);
        let y_labels = AxisLabels::new(&y_range, Y_LABELS, self.integer_y);
        let names = self.categories.clone();
        let x_format = move |x: &f64| {
            if categories {
                let nearest = x.round();
                if (x - nearest).abs() < 1e-6 && nearest >= 0.0 {
                    names.get(nearest as usize).cloned().unwrap_or_default()
                } else {
                    String::new()
                }
            } else {
                x_labels.format(*x)
            }
        };
        let y_format = |y: &f64| y_labels.format(*y);
        let mut mesh = chart.configure_mesh();
        if categories {
            mesh.disable_x_mesh().x_labels(self.categories.len().max(1));
        } else {
            mesh.x_labels(x_labels.count);
        }
        mesh.y_labels(y_labels.count)
            .x_label_formatter(&x_format)
            .y_label_formatter(&y_format)
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style((FONT_FAMILY, 14))
            .axis_desc_style((FONT_FAMILY, 16))
            .max_light_lines(4)
            .light_line_style(RGBColor(242, 242, 242))
            .bold_line_style(RGBColor(218, 218, 218))
            .draw()
            .map_err(error)?;
        Ok(chart)
    }

    /// Draws the panel on `area`; its legend goes inside if a free place exists, else
    /// into `column` (if given). Returns the width the legend needs beside the axes when
    /// it found no free place.
    fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        column: Option<&DrawingArea<DB, Shift>>,
    ) -> Result<OutsideLegend>
    where
        DB::ErrorType: 'static,
    {
        let (legend, occupancy, plot) = if self.categories.is_empty() {
            self.draw_xy(area)?
        } else {
            self.draw_bar_chart(area)?
        };
        if !legend.is_shown() {
            return Ok(None);
        }
        let size = legend.size(area)?;
        if let Some(place) = occupancy.free_place(size) {
            legend.draw(area, place, size)?;
            return Ok(None);
        }
        if let Some(column) = column {
            let base = column.get_base_pixel();
            legend.draw(column, (base.0 + 4, plot.top), size)?;
        }
        Ok(Some(size.0 + 12))
    }

    /// Draws lines, histograms, points and reference lines; returns the legend, what was
    /// drawn where, and the plotting area.
    fn draw_xy<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(Legend, Occupancy, PixelRect)>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let (x_range, y_range) = self.ranges();
        let mut chart = self.axes(area, x_range.clone(), y_range.clone(), false)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let plot = PixelRect {
            left: xs.start,
            top: ys.start,
            right: xs.end,
            bottom: ys.end,
        };
        let mut occupancy = Occupancy::new(plot);
        let mut legend = Legend {
            notes: self.notes.clone(),
            entries: Vec::new(),
        };
        let mut histogram_entries = Vec::new();
        if let Some(bins) = self.bins() {
            let (start, width, _) = bins;
            let groups = self.histograms.len();
            let opacity = if groups > 1 { 0.85 } else { 0.6 };
            let sub_width = width / groups as f64;
            for (index, histogram) in self.histograms.iter().enumerate() {
                let colour = PALETTE[index % PALETTE.len()];
                let counts = Self::bin_counts(&histogram.values, bins);
                let boxes: Vec<[(f64, f64); 2]> = counts
                    .into_iter()
                    .enumerate()
                    .filter(|(_, count)| *count > 0)
                    .map(|(bin, count)| {
                        let left = start + width * bin as f64 + sub_width * index as f64;
                        [(left, 0.0), (left + sub_width, count as f64)]
                    })
                    .collect();
                for corners in &boxes {
                    let (a, b) = (
                        chart.backend_coord(&corners[0]),
                        chart.backend_coord(&corners[1]),
                    );
                    occupancy.mark_rect(PixelRect {
                        left: a.0.min(b.0),
                        top: a.1.min(b.1),
                        right: a.0.max(b.0),
                        bottom: a.1.max(b.1),
                    });
                }
                chart
                    .draw_series(
                        boxes
                            .iter()
                            .map(|c| Rectangle::new(*c, colour.mix(opacity).filled())),
                    )
                    .map_err(error)?;
                chart
                    .draw_series(
                        boxes
                            .iter()
                            .map(|c| Rectangle::new(*c, colour.stroke_width(1))),
                    )
                    .map_err(error)?;
                histogram_entries.push((histogram.name.clone(), Sample::Patch { colour, opacity }));
            }
        }
        for (index, line) in self.lines.iter().enumerate() {
            let colour = line.colour.unwrap_or(PALETTE[index % PALETTE.len()]);
            let points = finite(&line.points);
            let pixels: Vec<(i32, i32)> = points.iter().map(|p| chart.backend_coord(p)).collect();
            let width = if !line.dashed && is_jagged(&pixels) {
                1
            } else {
                2
            };
            let style = colour.stroke_width(width);
            let dash = line.dashed.then_some((10, 6));
            match dash {
                Some((dash, gap)) => chart
                    .draw_series(DashedLineSeries::new(points, dash, gap, style))
                    .map_err(error)?,
                None => chart
                    .draw_series(LineSeries::new(points, style))
                    .map_err(error)?,
            };
            occupancy.mark_path(&pixels, 2);
            legend.push(
                &line.name,
                Sample::Line {
                    colour,
                    width,
                    dash,
                },
            );
        }
        for (name, sample) in histogram_entries {
            legend.push(&name, sample);
        }
        let mut reference_names: Vec<&str> = Vec::new();
        for line in self.reference_lines.iter().filter(|l| l.y.is_finite()) {
            let index = match reference_names.iter().position(|n| *n == line.name) {
                Some(index) => index,
                None => {
                    reference_names.push(&line.name);
                    reference_names.len() - 1
                }
            };
            let (colour, (dash, gap)) = REFERENCE_STYLES[index % REFERENCE_STYLES.len()];
            let style = colour.stroke_width(1);
            let ends = [(x_range.start, line.y), (x_range.end, line.y)];
            let pixels = ends.map(|p| chart.backend_coord(&p));
            chart
                .draw_series(DashedLineSeries::new(ends, dash, gap, style))
                .map_err(error)?;
            occupancy.mark_path(&pixels, 1);
            legend.push(
                &line.name,
                Sample::Line {
                    colour,
                    width: 1,
                    dash: Some((dash, gap)),
                },
            );
        }
        let label_style = (FONT_FAMILY, 13).into_font().color(&VERTICAL_LINE_COLOUR);
        for line in self.vertical_lines.iter().filter(|l| l.x.is_finite()) {
            let style = VERTICAL_LINE_COLOUR.stroke_width(1);
            let ends = [(line.x, y_range.start), (line.x, y_range.end)];
            let pixels = ends.map(|p| chart.backend_coord(&p));
            chart
                .draw_series(DashedLineSeries::new(ends, 6, 4, style))
                .map_err(error)?;
            occupancy.mark_path(&pixels, 1);
            let (w, h) = area
                .estimate_text_size(&line.name, &label_style)
                .map_err(error)?;
            let top = chart.backend_coord(&(line.x, y_range.end));
            occupancy.mark_rect(PixelRect::at(
                (top.0 + 2, top.1 + 2),
                (
                    i32::try_from(w).unwrap_or(0) + 4,
                    i32::try_from(h).unwrap_or(0) + 4,
                ),
            ));
            let base = area.get_base_pixel();
            area.draw(&Text::new(
                line.name.clone(),
                (top.0 + 4 - base.0, top.1 + 4 - base.1),
                label_style.clone(),
            ))
            .map_err(error)?;
        }
        let offset = self.lines.len();
        for (index, series) in self.scatter.iter().enumerate() {
            let colour = PALETTE[(offset + index) % PALETTE.len()];
            let points = finite(&series.points);
            for point in &points {
                occupancy.mark_point(chart.backend_coord(point), 4);
            }
            chart
                .draw_series(
                    points
                        .into_iter()
                        .map(move |p| Circle::new(p, 3, colour.mix(0.7).filled())),
                )
                .map_err(error)?;
            legend.push(
                &series.name,
                Sample::Marker {
                    colour,
                    opacity: 0.7,
                    shape: MarkerShape::Circle,
                    size: 3,
                },
            );
        }
        let base = area.get_base_pixel();
        for (index, marker) in self.markers.iter().enumerate() {
            let (x, y) = marker.point;
            if !(x.is_finite() && y.is_finite()) {
                continue;
            }
            let colour = MARKER_COLOURS[index % MARKER_COLOURS.len()];
            let pixel = chart.backend_coord(&marker.point);
            occupancy.mark_point(pixel, 8);
            draw_marker(
                area,
                (pixel.0 - base.0, pixel.1 - base.1),
                marker.shape,
                colour.mix(1.0),
                6,
            )
            .map_err(error)?;
            legend.push(
                &marker.name,
                Sample::Marker {
                    colour,
                    opacity: 1.0,
                    shape: marker.shape,
                    size: 6,
                },
            );
        }
        Ok((legend, occupancy, plot))
    }

    /// Draws the panel as a bar chart: categories along x, the groups side by side, each
    /// bar with its interval and its label above.
    fn draw_bar_chart<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(Legend, Occupancy, PixelRect)>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let categories = self.categories.len();
        let highest = self
            .bars
            .iter()
            .flat_map(|b| {
                b.values
                    .iter()
                    .copied()
                    .chain(b.intervals.iter().map(|i| i.1))
            })
            .filter(|v| v.is_finite())
            .fold(0.0_f64, f64::max);
        let top = if highest > 0.0 { highest * 1.15 } else { 1.0 };
        let x_range = -0.5..(categories as f64 - 0.5);
        let mut chart = self.axes(area, x_range, 0.0..top, true)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let plot = PixelRect {
            left: xs.start,
            top: ys.start,
            right: xs.end,
            bottom: ys.end,
        };
        let mut occupancy = Occupancy::new(plot);
        let mut legend = Legend {
            notes: self.notes.clone(),
            entries: Vec::new(),
        };
        let groups = self.bars.len().max(1);
        let group_width = 0.8 / groups as f64;
        let base = area.get_base_pixel();
        let text_style = (FONT_FAMILY, 13)
            .into_font()
            .color(&RGBColor(40, 40, 40))
            .pos(Pos::new(HPos::Center, VPos::Bottom));
        let interval_colour = RGBColor(0, 0, 0);
        for (index, group) in self.bars.iter().enumerate() {
            let colour = PALETTE[index % PALETTE.len()];
            for (category, &value) in group.values.iter().enumerate() {
                let left = category as f64 - 0.4 + group_width * index as f64;
                let centre = left + group_width / 2.0;
                let height = if value.is_finite() { value } else { 0.0 };
                let corners = [(left, 0.0), (left + group_width, height)];
                chart
                    .draw_series(std::iter::once(Rectangle::new(corners, colour.filled())))
                    .map_err(error)?;
                let (a, b) = (
                    chart.backend_coord(&corners[0]),
                    chart.backend_coord(&corners[1]),
                );
                occupancy.mark_rect(PixelRect {
                    left: a.0.min(b.0),
                    top: a.1.min(b.1),
                    right: a.0.max(b.0),
                    bottom: a.1.max(b.1),
                });
                let mut label_at = height;
                if let Some(&(low, high)) = group.intervals.get(category) {
                    if low.is_finite() && high.is_finite() {
                        let half_cap = group_width * 0.18;
                        let style = interval_colour.stroke_width(2);
                        for path in [
                            vec![(centre, low), (centre, high)],
                            vec![(centre - half_cap, low), (centre + half_cap, low)],
                            vec![(centre - half_cap, high), (centre + half_cap, high)],
                        ] {
                            let pixels: Vec<_> =
                                path.iter().map(|p| chart.backend_coord(p)).collect();
                            occupancy.mark_path(&pixels, 2);
                            chart
                                .draw_series(std::iter::once(PathElement::new(path, style)))
                                .map_err(error)?;
                        }
                        label_at = label_at.max(high);
                    }
                }
                let label = group.labels.get(category).cloned().unwrap_or_else(|| {
                    if value.is_finite() {
                        ticks::format_tick(value, if value.fract() == 0.0 { 0 } else { 1 })
                    } else {
                        "—".to_string()
                    }
                });
                let anchor = chart.backend_coord(&(centre, label_at));
                let (w, h) = area
                    .estimate_text_size(&label, &text_style)
                    .map_err(error)?;
                let (w, h) = (i32::try_from(w).unwrap_or(0), i32::try_from(h).unwrap_or(0));
                occupancy.mark_rect(PixelRect::at(
                    (anchor.0 - w / 2 - 2, anchor.1 - 4 - h),
                    (w + 4, h + 4),
                ));
                area.draw(&Text::new(
                    label,
                    (anchor.0 - base.0, anchor.1 - 4 - base.1),
                    text_style.clone(),
                ))
                .map_err(error)?;
            }
            legend.push(
                &group.name,
                Sample::Patch {
                    colour,
                    opacity: 1.0,
                },
            );
        }
        if self.bars.iter().any(|b| !b.intervals.is_empty()) {
            legend.push(
                &self.interval_name,
                Sample::Interval {
                    colour: interval_colour,
                },
            );
        }
        Ok((legend, occupancy, plot))
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

    /// Sets the height of each panel (px).
    pub fn panel_height(mut self, pixels: u32) -> Self {
        self.panel_height_px = pixels;
        self
    }

    /// Overall size in pixels (width, height).
    fn size(&self) -> (u32, u32) {
        let title = if self.title.is_some() { 40 } else { 0 };
        let rows = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        (self.width_px, title + rows * self.panel_height_px)
    }

    /// Draws the figure with a legend column `column` px wide beside every panel (0 for
    /// none); returns the widest legend that found no free place inside its axes.
    fn draw<DB: DrawingBackend>(&self, root: DrawingArea<DB, Shift>, column: i32) -> Result<i32>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        root.fill(&WHITE).map_err(error)?;
        let body = match &self.title {
            Some(title) => {
                let width = self.width_px.saturating_sub(24);
                let size = fitted_font_size(&root, title, 23, width);
                root.titled(title, (FONT_FAMILY, size)).map_err(error)?
            }
            None => root.clone(),
        };
        let areas = body.split_evenly((self.panels.len().max(1), 1));
        let mut widest = 0;
        for (area, panel) in areas.iter().zip(&self.panels) {
            let outside = if column > 0 {
                let width = i32::try_from(area.dim_in_pixel().0).unwrap_or(0);
                let (axes, legend) = area.split_horizontally(width - column);
                panel.draw(&axes, Some(&legend))?
            } else {
                panel.draw(area, None)?
            };
            widest = widest.max(outside.unwrap_or(0));
        }
        root.present().map_err(error)?;
        Ok(widest)
    }

    /// The width of the legend column: 0 when every legend finds a free place inside its
    /// axes, else the widest of those that do not (found by drawing to a scratch SVG,
    /// again with the column, since narrower axes may push out another legend).
    fn legend_column(&self) -> Result<i32> {
        let mut column = 0;
        for _ in 0..3 {
            let mut scratch = String::new();
            let widest = self.draw(
                SVGBackend::with_string(&mut scratch, self.size()).into_drawing_area(),
                column,
            )?;
            if widest <= column {
                break;
            }
            column = widest;
        }
        Ok(column)
    }

    /// Renders the figure as PNG to `path` (the extension selects the format).
    pub fn render_png(&self, path: &Path) -> Result<()> {
        register_bundled_font()?;
        let column = self.legend_column()?;
        self.draw(
            BitMapBackend::new(path, self.size()).into_drawing_area(),
            column,
        )?;
        Ok(())
    }

    /// Renders the figure as an SVG document.
    pub fn render_svg(&self) -> Result<String> {
        register_bundled_font()?;
        let column = self.legend_column()?;
        let mut svg = String::new();
        self.draw(
            SVGBackend::with_string(&mut svg, self.size()).into_drawing_area(),
            column,
        )?;
        Ok(svg)
    }

    /// Writes `<stem>.png` and `<stem>.svg` atomically into `output`; returns both paths.
    pub fn save(&self, output: &OutputDir, stem: &str) -> Result<[PathBuf; 2]> {
        Ok(self.save_with_svg(output, stem)?.0)
    }

    /// As [`Figure::save`], also returning the SVG document (for `report.html`).
    pub fn save_with_svg(&self, output: &OutputDir, stem: &str) -> Result<([PathBuf; 2], String)> {
        let png = output.write_with(&format!("{stem}.png"), |path| self.render_png(path))?;
        let document = self.render_svg()?;
        let svg = output.write_bytes(&format!("{stem}.svg"), document.as_bytes())?;
        Ok(([png, svg], document))
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
        assert!(
            y.start == 0.0 && y.end > 2.0,
            "a count axis starts at zero: {y:?}"
        );
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
                    .bar_group(BarGroup {
                        name: "O-PD".into(),
                        values: vec![90.0, 10.0],
                        intervals: vec![(80.0, 95.0), (5.0, 20.0)],
                        labels: vec!["9".into(), "1".into()],
                    })
                    .bar_group(BarGroup {
                        name: "PID".into(),
                        values: vec![70.0, 30.0],
                        ..BarGroup::default()
                    })
                    .interval_name("95 % interval"),
            );
        let svg = figure.render_svg().expect("renders");
        for text in ["wire 1", "Histogram", "trap", "bolter", "PID"] {
            assert!(svg.contains(text), "{text}");
        }
    }

    #[test]
    fn nothing_non_finite_reaches_the_svg() {
        let figure = Figure::new()
            .panel(
                Panel::new("Lines", "time (s)", "value (m)")
                    .series("a", vec![(0.0, f64::NAN), (1.0, f64::INFINITY), (2.0, 1.0)])
                    .dashed_series("b", vec![(f64::NAN, 0.0)])
                    .reference_line("limit", f64::NAN)
                    .vertical_line("wire", f64::INFINITY)
                    .marker("touchdown", (f64::NAN, 1.0), MarkerShape::Circle)
                    .note("nothing finite here"),
            )
            .panel(Panel::new("Histogram", "x (m)", "runs").histogram(
                "h",
                vec![f64::NAN, f64::NEG_INFINITY],
                5,
            ))
            .panel(
                Panel::new("Bars", "outcome", "share (%)")
                    .categories(vec!["trap".into()])
                    .bar_group(BarGroup {
                        name: "O-PD".into(),
                        values: vec![f64::NAN],
                        intervals: vec![(f64::NAN, f64::INFINITY)],
                        labels: Vec::new(),
                    }),
            );
        let svg = figure.render_svg().expect("renders");
        for word in ["NaN", "inf", "Infinity"] {
            assert!(
                !svg.split(|c: char| !c.is_ascii_alphanumeric())
                    .any(|w| w == word),
                "{word} in the SVG"
            );
        }
    }

    #[test]
    fn svg_text_names_only_the_generic_font_family() {
        let svg = Figure::new()
            .title("t")
            .panel(Panel::new("p", "x (s)", "y (m)").series("a", vec![(0.0, 0.0), (1.0, 1.0)]))
            .render_svg()
            .expect("renders");
        let families: Vec<&str> = svg
            .split("font-family=\"")
            .skip(1)
            .filter_map(|rest| rest.split('"').next())
            .collect();
        assert!(!families.is_empty());
        assert!(families.iter().all(|f| *f == FONT_FAMILY), "{families:?}");
        assert!(!svg.contains("url(") && !svg.contains("@font-face"));
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
