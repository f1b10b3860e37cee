//! A panel's content: its series, markers, histograms, reference lines and bars, the
//! builder that adds them, and the data ranges they span.

use std::ops::Range;

use plotters::coord::Shift;
use plotters::prelude::*;

use super::legend::{MarkerShape, MarkerStyle};

/// How far beyond the data a limit line may lie and still widen the axis to show it: a
/// fraction of the data's span (`Panel::limit_line`).
pub(super) const LIMIT_REACH: f64 = 0.25;

/// One named line: (x, y) points in data units.
#[derive(Debug, Clone)]
pub(super) struct Line {
    pub(super) name: String,
    pub(super) points: Vec<(f64, f64)>,
    pub(super) dashed: bool,
    pub(super) colour: Option<RGBColor>,
    /// Dash and gap (px) when dashed; `None` for the default (10, 6).
    pub(super) pattern: Option<(u32, u32)>,
}

/// A named set of points drawn as dots, or as markers of a style of their own.
#[derive(Debug, Clone)]
pub(super) struct Scatter {
    pub(super) name: String,
    pub(super) points: Vec<(f64, f64)>,
    pub(super) style: Option<MarkerStyle>,
}

/// One named point drawn as a marker.
#[derive(Debug, Clone)]
pub(super) struct Marker {
    pub(super) name: String,
    pub(super) point: (f64, f64),
    pub(super) shape: MarkerShape,
}

/// A horizontal reference line at `y`; lines of the same name share a style and an entry.
/// A limit widens the axis only when it lies near the data; else a note names it.
#[derive(Debug, Clone)]
pub(super) struct ReferenceLine {
    pub(super) name: String,
    pub(super) y: f64,
    pub(super) limit: bool,
}

/// A vertical reference line at `x`, labelled at the top of the axes.
#[derive(Debug, Clone)]
pub(super) struct VerticalLine {
    pub(super) name: String,
    pub(super) x: f64,
}

/// A named set of values drawn as a histogram (counts per bin).
#[derive(Debug, Clone)]
pub(super) struct Histogram {
    pub(super) name: String,
    pub(super) values: Vec<f64>,
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
    pub(super) title: String,
    pub(super) x_label: String,
    pub(super) y_label: String,
    pub(super) lines: Vec<Line>,
    pub(super) scatter: Vec<Scatter>,
    /// Legend entries for markers drawn by the styled scatter series (their key).
    pub(super) keys: Vec<(String, MarkerStyle)>,
    pub(super) markers: Vec<Marker>,
    pub(super) histograms: Vec<Histogram>,
    pub(super) histogram_bins: usize,
    pub(super) reference_lines: Vec<ReferenceLine>,
    pub(super) vertical_lines: Vec<VerticalLine>,
    pub(super) categories: Vec<String>,
    pub(super) bars: Vec<BarGroup>,
    pub(super) interval_name: String,
    pub(super) notes: Vec<String>,
    pub(super) integer_y: bool,
    /// A bar chart's y axis is logarithmic (`Panel::log_y`).
    pub(super) log_y: bool,
    pub(super) x_limits: Option<Range<f64>>,
    /// The legend is that of another panel of the figure: none is drawn here.
    pub(super) shared_legend: bool,
    /// A metre on the x axis is as long as a metre on the y axis (a map, to scale).
    pub(super) equal_aspect: bool,
    /// The y values are given negated so that y grows downward; the labels say the
    /// values themselves (a map seen from above with y to the right of x).
    pub(super) y_downward: bool,
}

/// Where a panel's legend went: `Some((width, height))` (layout px, with the spacing it
/// needs there) when it is drawn outside the axes or found no free place inside them.
pub(super) type OutsideLegend = Option<(i32, i32)>;

/// Where a panel's legend goes when it is not inside its axes.
pub(super) enum Outside<'a, DB: DrawingBackend> {
    /// Nowhere: it is drawn only where it finds a free place inside.
    Nowhere,
    /// Into a column beside the figure's axes, even when it would fit inside.
    Column(&'a DrawingArea<DB, Shift>),
    /// Under the axes when it finds no free place inside.
    Below(&'a DrawingArea<DB, Shift>),
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

    /// Adds a solid line series.
    pub fn series(self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.line(name, points, false, None, None)
    }

    /// Adds a dashed line series (for references that vary, such as a command).
    pub fn dashed_series(self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.line(name, points, true, None, None)
    }

    /// Adds a solid line series in a colour of its own (for a physical object, such as
    /// the deck, rather than one series among others).
    pub fn coloured_series(
        self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        colour: RGBColor,
    ) -> Self {
        self.line(name, points, false, Some(colour), None)
    }

    /// Adds a line series with its own colour (else the palette's) and dash pattern
    /// (dash, gap in px; else solid): to tell apart lines that may lie on each other.
    pub fn styled_series(
        self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        colour: Option<RGBColor>,
        pattern: Option<(u32, u32)>,
    ) -> Self {
        self.line(name, points, pattern.is_some(), colour, pattern)
    }

    /// Adds a line series: dashed or solid, in `colour` (else the palette's), with a dash
    /// `pattern` (else the default dash).
    fn line(
        mut self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        dashed: bool,
        colour: Option<RGBColor>,
        pattern: Option<(u32, u32)>,
    ) -> Self {
        self.lines.push(Line {
            name: name.into(),
            points,
            dashed,
            colour,
            pattern,
        });
        self
    }

    /// Adds a dashed horizontal reference line at `y`; lines given the same name share a
    /// style and one legend entry (the two edges of a band).
    pub fn reference_line(self, name: impl Into<String>, y: f64) -> Self {
        self.horizontal_line(name, y, false)
    }

    /// Adds a horizontal line at `y`: a limit ([`Panel::limit_line`]) or a reference.
    fn horizontal_line(mut self, name: impl Into<String>, y: f64, limit: bool) -> Self {
        self.reference_lines.push(ReferenceLine {
            name: name.into(),
            y,
            limit,
        });
        self
    }

    /// Adds the lower and upper stops of a surface at `min_deg` and `max_deg` as
    /// reference lines named with their signed angles ("lower stop −25°").
    pub fn surface_stops(self, min_deg: f64, max_deg: f64) -> Self {
        self.reference_line(format!("lower stop {}°", super::signed(min_deg)), min_deg)
            .reference_line(format!("upper stop {}°", super::signed(max_deg)), max_deg)
    }

    /// Adds a limit: a reference line at `y` drawn when it lies within [`LIMIT_REACH`] of
    /// the data's span beyond the data, so that the axis spans the data; a limit farther
    /// away is named in a note instead ("… above the axis"). Say its value in `name`.
    pub fn limit_line(self, name: impl Into<String>, y: f64) -> Self {
        self.horizontal_line(name, y, true)
    }

    /// Adds a series drawn as points (no line).
    pub fn scatter(self, name: impl Into<String>, points: Vec<(f64, f64)>) -> Self {
        self.markers(name, points, None)
    }

    /// Adds a series drawn as markers of `style`, in the order added (the last on top);
    /// an empty `name` gives no legend entry (see [`Panel::legend_entry`]).
    pub fn styled_scatter(
        self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: MarkerStyle,
    ) -> Self {
        self.markers(name, points, Some(style))
    }

    /// Adds a series drawn as markers of `style` (else the palette's default marker).
    fn markers(
        mut self,
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        style: Option<MarkerStyle>,
    ) -> Self {
        self.scatter.push(Scatter {
            name: name.into(),
            points,
            style,
        });
        self
    }

    /// Adds a legend entry for a marker of `style` that names no series of its own: the
    /// key to markers whose shape says one thing and colour another.
    pub fn legend_entry(mut self, name: impl Into<String>, style: MarkerStyle) -> Self {
        self.keys.push((name.into(), style));
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

    /// Draws a bar chart's y axis on a logarithmic scale, so that shares of 1 in 10 000
    /// stand beside shares near 100 %: every bar rises from the axis' floor, the power of
    /// ten below half the smallest positive value or interval end; a zero value draws no
    /// bar, and an interval that reaches zero is thin and grey, without a lower cap.
    pub fn log_y(mut self) -> Self {
        self.log_y = true;
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

    /// Draws no legend: the entries are those of another panel of the same figure, which
    /// says so (its title, or the figure's).
    pub fn shared_legend(mut self) -> Self {
        self.shared_legend = true;
        self
    }

    /// Draws the axes to one scale, as a map: the y range (or, when the data need more,
    /// the x range) widens about its centre until a unit is as many pixels on both.
    pub fn equal_aspect(mut self) -> Self {
        self.equal_aspect = true;
        self
    }

    /// Draws y growing downward, as a map from above with y to the right of x: the
    /// caller gives every y negated (−y) and the axis labels the values themselves.
    pub fn y_downward(mut self) -> Self {
        self.y_downward = true;
        self
    }

    /// Fixes the x axis to `range` instead of the data's.
    pub fn x_limits(mut self, range: Range<f64>) -> Self {
        self.x_limits = Some(range);
        self
    }

    /// The shared bins of the panel's histograms: (first edge, width, count), or `None`
    /// without finite values.
    pub(super) fn bins(&self) -> Option<(f64, f64, usize)> {
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
    pub(super) fn bin_counts(values: &[f64], (start, width, count): (f64, f64, usize)) -> Vec<u64> {
        let mut counts = vec![0; count];
        for v in values.iter().filter(|v| v.is_finite()) {
            let index = (((v - start) / width).floor().max(0.0) as usize).min(count - 1);
            counts[index] += 1;
        }
        counts
    }

    /// What the axes must span, (x min, x max, y min, y max), infinite when nothing
    /// finite is drawn: the data in the x window, the reference lines, the limits near
    /// the data and the vertical lines.
    fn extent(&self) -> (f64, f64, f64, f64) {
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
        let lines = self.reference_lines.iter().filter(|l| l.y.is_finite());
        for line in lines.clone().filter(|l| !l.limit) {
            (y_min, y_max) = (y_min.min(line.y), y_max.max(line.y));
        }
        // A limit near the data widens the axis to show it; a far one is left out.
        let reach = LIMIT_REACH * (y_max - y_min);
        let (data_min, data_max) = (y_min, y_max);
        for line in lines.filter(|l| l.limit) {
            if !(data_min.is_finite() && data_max.is_finite())
                || (line.y >= data_min - reach && line.y <= data_max + reach)
            {
                (y_min, y_max) = (y_min.min(line.y), y_max.max(line.y));
            }
        }
        for line in self.vertical_lines.iter().filter(|l| l.x.is_finite()) {
            (x_min, x_max) = (x_min.min(line.x), x_max.max(line.x));
        }
        (x_min, x_max, y_min, y_max)
    }

    /// Data ranges, padded and never empty; a count axis starts at zero.
    pub(super) fn ranges(&self) -> (Range<f64>, Range<f64>) {
        let (x_min, x_max, y_min, y_max) = self.extent();
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
}
