//! Drawing a panel: its axes, then its lines, scatter, markers, histograms and reference
//! lines, or its bar chart (`bars`), and its legend where nothing is drawn.

use std::ops::Range;

use anyhow::{anyhow, Result};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::legend::{draw_marker, Legend, MarkerShape, MarkerStyle, Occupancy, PixelRect, Sample};
use super::panel::{Outside, OutsideLegend, Panel};
use super::style::*;
use super::ticks::{self, AxisLabels, X_LABELS, Y_LABELS};

/// Design pixels of a plotting area's width per label asked for on its x axis, and of its
/// height per label on its y axis: a narrow figure asks for fewer, so that its labels
/// stand apart.
const LABEL_SPACING: (i32, i32) = (55, 22);

/// A panel's chart: data coordinates to pixels.
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// How a panel's text around its axes is set ([`Panel::chrome`]); lengths in layout px.
pub(super) struct Chrome {
    /// Around the panel.
    pub(super) margin: i32,
    /// The title's lines and font size.
    pub(super) caption: (Vec<String>, f64),
    /// Above and below the title.
    pub(super) caption_padding: i32,
    /// The height the title takes, with its padding.
    pub(super) caption_band: i32,
    /// The x axis's label: lines and font size.
    pub(super) x_label: (Vec<String>, f64),
    /// The y axis's label: lines and font size.
    pub(super) y_label: (Vec<String>, f64),
    /// Height of the x axis's label area.
    pub(super) x_area: i32,
    /// Width of the y axis's label area.
    pub(super) y_area: i32,
    /// A bar chart's categories are turned to read upwards.
    pub(super) turned_categories: bool,
}

impl Chrome {
    /// The height beyond what one line of each label and of the title takes.
    pub(super) fn extra_height(&self) -> i32 {
        extra_lines(&self.caption) + self.x_area - px(48)
    }
}

/// The height of the lines of `text` (lines, font size) after its first.
fn extra_lines((lines, size): &(Vec<String>, f64)) -> i32 {
    lines_before(lines.len().saturating_sub(1)) * line_height(*size)
}

/// `count` as a number of lines.
fn lines_before(count: usize) -> i32 {
    i32::try_from(count).unwrap_or(0)
}

/// The error of a failed drawing call.
pub(super) fn failed<E: std::error::Error + Send + Sync>(
    e: DrawingAreaErrorKind<E>,
) -> anyhow::Error {
    anyhow!("plot drawing failed: {e}")
}

/// What the layers of a panel draw on and record: the area and its chart, the plotting
/// area's pixels, what was drawn where, the legend, and the axes' ranges.
pub(super) struct Canvas<'a, DB: DrawingBackend> {
    pub(super) area: &'a DrawingArea<DB, Shift>,
    pub(super) chart: Chart<'a, DB>,
    pub(super) plot: PixelRect,
    pub(super) occupancy: Occupancy,
    pub(super) legend: Legend,
    pub(super) x_range: Range<f64>,
    pub(super) y_range: Range<f64>,
}

impl<'a, DB: DrawingBackend> Canvas<'a, DB> {
    /// The canvas of `chart` on `area` over the ranges, with `notes` atop its legend.
    pub(super) fn new(
        area: &'a DrawingArea<DB, Shift>,
        chart: Chart<'a, DB>,
        (x_range, y_range): (Range<f64>, Range<f64>),
        notes: Vec<String>,
    ) -> Self {
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let plot = PixelRect {
            left: xs.start,
            top: ys.start,
            right: xs.end,
            bottom: ys.end,
        };
        Self {
            area,
            chart,
            plot,
            occupancy: Occupancy::new(plot),
            legend: Legend {
                notes,
                entries: Vec::new(),
            },
            x_range,
            y_range,
        }
    }

    /// The pixel of a data point, relative to the area (for elements drawn on it).
    pub(super) fn area_pixel(&self, point: (f64, f64)) -> (i32, i32) {
        let pixel = self.chart.backend_coord(&point);
        let base = self.area.get_base_pixel();
        (pixel.0 - base.0, pixel.1 - base.1)
    }

    /// Whether a data point lies within the axes.
    fn contains(&self, (x, y): (f64, f64)) -> bool {
        let within = |r: &Range<f64>, v: f64| v >= r.start.min(r.end) && v <= r.start.max(r.end);
        within(&self.x_range, x) && within(&self.y_range, y)
    }

    /// The legend, what was drawn where, and the plotting area.
    pub(super) fn finish(self) -> (Legend, Occupancy, PixelRect) {
        (self.legend, self.occupancy, self.plot)
    }
}

/// `x` and `y` widened about their centres so that a unit spans as many pixels on both
/// axes of a plotting area of `(width, height)` pixels.
pub(super) fn equal_aspect_ranges(
    x: Range<f64>,
    y: Range<f64>,
    (width, height): (i32, i32),
) -> (Range<f64>, Range<f64>) {
    let (w, h) = (f64::from(width.max(1)), f64::from(height.max(1)));
    let (x_span, y_span) = (x.end - x.start, y.end - y.start);
    let widen = |r: &Range<f64>, span: f64| {
        let centre = 0.5 * (r.start + r.end);
        (centre - 0.5 * span)..(centre + 0.5 * span)
    };
    if x_span / w >= y_span / h {
        (x.clone(), widen(&y, x_span / w * h))
    } else {
        (widen(&x, y_span / h * w), y)
    }
}

impl Panel {
    /// The plotting area's size (px) that this panel's axes leave on an area of `dims`
    /// pixels: laid out once on a scratch SVG, as [`Panel::axes`] lays it out.
    fn plotting_size(&self, dims: (u32, u32)) -> Result<(i32, i32)> {
        let mut scratch = String::new();
        let area = SVGBackend::with_string(&mut scratch, dims).into_drawing_area();
        let chart = self.axes(&area, 0.0..1.0, 0.0..1.0, false)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        Ok((xs.end - xs.start, ys.end - ys.start))
    }

    /// How the panel's text around its axes is set on `area`: the title and the axis
    /// labels on as many lines as they need to fit, the categories of a bar chart turned
    /// when they do not fit side by side, and the label areas that leaves.
    pub(super) fn chrome<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Chrome {
        let (width, height) = area.dim_in_pixel();
        let (width, height) = (
            i32::try_from(width).unwrap_or(0),
            i32::try_from(height).unwrap_or(0),
        );
        let margin = px(12);
        // The title, as plotters' caption: centred, half its height above and below (at
        // most 5 px), inside the margin.
        let caption_width = u32::try_from(width - px(30)).unwrap_or(0);
        let caption = fitted_lines(area, &self.title, (19, 15), caption_width);
        let caption_style = TextStyle::from((FONT_FAMILY, caption.1).into_font());
        let caption_height = text_height(area, &caption_style);
        let padding = (caption_height / 2).min(px(5));
        let caption_band = 2 * padding + caption_height + extra_lines(&caption);
        // Categories too wide for their share of the axis are turned to read upwards.
        let small = TextStyle::from((FONT_FAMILY, font_px(f64::from(TEXT_SIZE))).into_font());
        let widest_category = self
            .categories
            .iter()
            .filter_map(|name| area.estimate_text_size(name, &small).ok())
            .map(|(w, _)| i32::try_from(w).unwrap_or(0))
            .max()
            .unwrap_or(0);
        let mut turned = 0;
        // The axis labels, wrapped to the plotting area's sides: laid out twice, since the
        // extra lines of each shorten the other's side.
        let (mut x_area, mut y_area) = (px(48), px(72));
        let mut x_label = (Vec::new(), 0.0);
        let mut y_label = (Vec::new(), 0.0);
        for _ in 0..2 {
            let plot_width = width - 2 * margin - y_area;
            let plot_height = height - 2 * margin - caption_band - x_area;
            let share = plot_width / i32::try_from(self.categories.len().max(1)).unwrap_or(1);
            turned = if widest_category > share - px(8) {
                (widest_category - text_height(area, &small)).max(0)
            } else {
                0
            };
            x_label = fitted_lines(
                area,
                &self.x_label,
                (16, TEXT_SIZE),
                u32::try_from(plot_width).unwrap_or(0),
            );
            y_label = fitted_lines(
                area,
                &self.y_label,
                (16, TEXT_SIZE),
                u32::try_from(plot_height).unwrap_or(0),
            );
            x_area = px(48) + turned + extra_lines(&x_label);
            y_area = px(72) + extra_lines(&y_label);
        }
        Chrome {
            margin,
            caption,
            caption_padding: padding,
            caption_band,
            x_label,
            y_label,
            x_area,
            y_area,
            turned_categories: turned > 0,
        }
    }

    /// The chart's axes, title and grid on `area` (see [`Panel::chrome`]).
    pub(super) fn axes<'a, DB: DrawingBackend + 'a>(
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
        let chrome = self.chrome(area);
        let margin = chrome.margin;
        let (width, height) = area.dim_in_pixel();
        let (width, height) = (
            i32::try_from(width).unwrap_or(0),
            i32::try_from(height).unwrap_or(0),
        );
        let mut chart = ChartBuilder::on(area)
            .margin_top(margin + chrome.caption_band)
            .margin_bottom(margin)
            .margin_left(margin)
            .margin_right(margin)
            .x_label_area_size(chrome.x_area)
            .y_label_area_size(chrome.y_area)
            .build_cartesian_2d(x_range.clone(), y_range.clone())
            .map_err(error)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let base = area.get_base_pixel();
        let (caption, caption_size) = &chrome.caption;
        let caption_style = TextStyle::from((FONT_FAMILY, *caption_size).into_font())
            .pos(Pos::new(HPos::Center, VPos::Top));
        for (index, line) in caption.iter().enumerate() {
            let down = lines_before(index) * line_height(*caption_size);
            let at = (width / 2, margin + chrome.caption_padding + down);
            area.draw(&Text::new(line.clone(), at, caption_style.clone()))
                .map_err(error)?;
        }
        // As plotters' axis descriptions: the x label's last line on the bottom of its
        // area, centred under the plotting area; the y label turned, its first line on
        // the left of its area, centred beside the plotting area.
        let (x_lines, x_size) = &chrome.x_label;
        let style = TextStyle::from((FONT_FAMILY, *x_size).into_font())
            .pos(Pos::new(HPos::Center, VPos::Bottom));
        let centre = (xs.start + xs.end) / 2 - base.0;
        for (index, line) in x_lines.iter().enumerate() {
            let up = lines_before(x_lines.len() - 1 - index) * line_height(*x_size);
            let at = (centre, height - margin - up);
            area.draw(&Text::new(line.clone(), at, style.clone()))
                .map_err(error)?;
        }
        let (y_lines, y_size) = &chrome.y_label;
        let style = TextStyle::from((FONT_FAMILY, *y_size).into_font())
            .transform(FontTransform::Rotate270)
            .pos(Pos::new(HPos::Center, VPos::Top));
        let middle = (ys.start + ys.end) / 2 - base.1;
        for (index, line) in y_lines.iter().enumerate() {
            let at = (margin + lines_before(index) * line_height(*y_size), middle);
            area.draw(&Text::new(line.clone(), at, style.clone()))
                .map_err(error)?;
        }
        // Turned categories: reading upwards, each ending under its tick.
        if categories && chrome.turned_categories {
            let style = TextStyle::from((FONT_FAMILY, font_px(f64::from(TEXT_SIZE))).into_font())
                .transform(FontTransform::Rotate270)
                .pos(Pos::new(HPos::Right, VPos::Center));
            for (index, name) in self.categories.iter().enumerate() {
                let x = chart.backend_coord(&(index as f64, y_range.start)).0 - base.0;
                let at = (x, ys.end - base.1 + px(10));
                area.draw(&Text::new(name.clone(), at, style.clone()))
                    .map_err(error)?;
            }
        }
        let labels = |pixels: i32, spacing: i32, most: usize| {
            let fit = f64::from(pixels) / f64::from(px(spacing));
            (fit.floor().max(0.0) as usize).clamp(2, most)
        };
        let x_labels = AxisLabels::new(
            &x_range,
            labels(xs.end - xs.start, LABEL_SPACING.0, X_LABELS),
            false,
        );
        // A log axis labels the whole powers of ten (its values are their exponents).
        let log = self.log_y;
        let y_labels = AxisLabels::new(
            &y_range,
            labels(ys.end - ys.start, LABEL_SPACING.1, Y_LABELS),
            self.integer_y || log,
        );
        let names = if chrome.turned_categories {
            Vec::new()
        } else {
            self.categories.clone()
        };
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
        let downward = self.y_downward;
        // + 0.0 turns −0 into 0: the axis never labels "−0".
        let y_format = move |y: &f64| match y_labels.format(if downward { -*y + 0.0 } else { *y }) {
            label if log && !label.is_empty() => ticks::power_of_ten(y.round()),
            label => label,
        };
        let mut mesh = chart.configure_mesh();
        if categories {
            mesh.disable_x_mesh().x_labels(self.categories.len().max(1));
        } else {
            mesh.x_labels(x_labels.count);
        }
        mesh.y_labels(y_labels.count)
            .x_label_formatter(&x_format)
            .y_label_formatter(&y_format)
            // A font, not a (family, size) pair, which plotters would round to whole px.
            .label_style((FONT_FAMILY, font_px(f64::from(TEXT_SIZE))).into_font())
            .set_all_tick_mark_size(px(5))
            .axis_style(BLACK.stroke_width(pxu(1)))
            .max_light_lines(if log { 0 } else { 4 })
            .light_line_style(RGBColor(242, 242, 242).stroke_width(pxu(1)))
            .bold_line_style(RGBColor(218, 218, 218).stroke_width(pxu(1)))
            .draw()
            .map_err(error)?;
        Ok(chart)
    }

    /// Draws the panel on `area`; its legend goes into a column beside the axes if given
    /// one, else inside where a free place exists, else under the axes if given a place
    /// there. Returns the size the legend needs outside the axes (with its spacing) when
    /// it is in the column or found no free place.
    pub(super) fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        outside: Outside<'_, DB>,
    ) -> Result<OutsideLegend>
    where
        DB::ErrorType: 'static,
    {
        let (legend, occupancy, plot) = if self.categories.is_empty() {
            self.draw_xy(area)?
        } else {
            self.draw_bar_chart(area)?
        };
        if !legend.is_shown() || self.shared_legend {
            return Ok(None);
        }
        let size = legend.size(area)?;
        match outside {
            // With a legend column beside the figure, every legend goes there: beside the
            // panel whose legend fits inside its axes, the column would stay empty.
            Outside::Column(column) => {
                let base = column.get_base_pixel();
                legend.draw(column, (base.0 + px(4), plot.top), size)?;
            }
            Outside::Nowhere | Outside::Below(_) => {
                if let Some(place) = occupancy.free_place(size) {
                    legend.draw(area, place, size)?;
                    return Ok(None);
                }
                // Under the axes, from their left edge, within the strip.
                if let Outside::Below(strip) = outside {
                    let base = strip.get_base_pixel();
                    let right = base.0 + i32::try_from(strip.dim_in_pixel().0).unwrap_or(0);
                    let left = plot.left.min(right - px(4) - size.0).max(base.0 + px(4));
                    legend.draw(strip, (left, base.1 + px(2)), size)?;
                }
            }
        }
        Ok(Some((size.0 + px(12), size.1 + px(8))))
    }

    /// Draws lines, histograms, points and reference lines; returns the legend, what was
    /// drawn where, and the plotting area.
    pub(super) fn draw_xy<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(Legend, Occupancy, PixelRect)>
    where
        DB::ErrorType: 'static,
    {
        let (x_range, y_range) = self.ranges();
        let ranges = if self.equal_aspect {
            let size = self.plotting_size(area.dim_in_pixel())?;
            equal_aspect_ranges(x_range, y_range, size)
        } else {
            (x_range, y_range)
        };
        let chart = self.axes(area, ranges.0.clone(), ranges.1.clone(), false)?;
        let mut canvas = Canvas::new(area, chart, ranges, self.notes.clone());
        let histogram_entries = self.draw_histograms(&mut canvas)?;
        self.draw_lines(&mut canvas)?;
        for (name, sample) in histogram_entries {
            canvas.legend.push(&name, sample);
        }
        self.draw_reference_lines(&mut canvas)?;
        self.draw_vertical_lines(&mut canvas)?;
        self.draw_scatter(&mut canvas)?;
        self.draw_markers(&mut canvas)?;
        Ok(canvas.finish())
    }

    /// Draws the histograms side by side within each bin; returns their legend entries.
    fn draw_histograms<DB: DrawingBackend>(
        &self,
        canvas: &mut Canvas<DB>,
    ) -> Result<Vec<(String, Sample)>>
    where
        DB::ErrorType: 'static,
    {
        let mut entries = Vec::new();
        let Some(bins) = self.bins() else {
            return Ok(entries);
        };
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
                canvas.occupancy.mark_rect(PixelRect::spanning(
                    canvas.chart.backend_coord(&corners[0]),
                    canvas.chart.backend_coord(&corners[1]),
                ));
            }
            let fill = colour.mix(opacity).filled();
            let chart = &mut canvas.chart;
            chart
                .draw_series(boxes.iter().map(|c| Rectangle::new(*c, fill)))
                .map_err(failed)?;
            chart
                .draw_series(
                    boxes
                        .iter()
                        .map(|c| Rectangle::new(*c, colour.stroke_width(pxu(1)))),
                )
                .map_err(failed)?;
            entries.push((histogram.name.clone(), Sample::Patch { colour, opacity }));
        }
        Ok(entries)
    }

    /// Draws the line series, solid or dashed, 2 px wide.
    fn draw_lines<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        for (index, line) in self.lines.iter().enumerate() {
            let colour = line.colour.unwrap_or(PALETTE[index % PALETTE.len()]);
            let points = finite(&line.points);
            let chart = &mut canvas.chart;
            let pixels: Vec<(i32, i32)> = points.iter().map(|p| chart.backend_coord(p)).collect();
            // Widths and dashes in design pixels (the legend's sample draws them alike).
            let width = 2;
            let dash = line.dashed.then_some(line.pattern.unwrap_or((10, 6)));
            match dash {
                Some((dash, gap)) => {
                    let style = colour.stroke_width(pxu(width));
                    let series = DashedLineSeries::new(points, pxu(dash), pxu(gap), style);
                    chart.draw_series(series).map_err(failed)?;
                }
                None => {
                    let series = LineSeries::new(points, colour.stroke_width(pxu(width)));
                    chart.draw_series(series).map_err(failed)?;
                }
            }
            canvas.occupancy.mark_path(&pixels, px(2));
            let sample = Sample::Line {
                colour,
                width,
                dash,
            };
            canvas.legend.push(&line.name, sample);
        }
        Ok(())
    }

    /// Draws the horizontal reference lines within the axes, each name in its own style;
    /// a limit beyond the axes is named in a note.
    fn draw_reference_lines<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let mut names: Vec<&str> = Vec::new();
        let mut beyond: Vec<(&str, f64)> = Vec::new();
        for line in self.reference_lines.iter().filter(|l| l.y.is_finite()) {
            let index = names
                .iter()
                .position(|n| *n == line.name)
                .unwrap_or_else(|| {
                    names.push(&line.name);
                    names.len() - 1
                });
            let x_range = canvas.x_range.clone();
            if !canvas.contains((x_range.start, line.y)) {
                beyond.extend(line.limit.then_some((line.name.as_str(), line.y)));
                continue;
            }
            let (colour, (dash, gap)) = REFERENCE_STYLES[index % REFERENCE_STYLES.len()];
            let ends = [(x_range.start, line.y), (x_range.end, line.y)];
            let pixels = ends.map(|p| canvas.chart.backend_coord(&p));
            let style = colour.stroke_width(pxu(1));
            let series = DashedLineSeries::new(ends, pxu(dash), pxu(gap), style);
            canvas.chart.draw_series(series).map_err(failed)?;
            canvas.occupancy.mark_path(&pixels, px(1));
            let sample = Sample::Line {
                colour,
                width: 1,
                dash: Some((dash, gap)),
            };
            canvas.legend.push(&line.name, sample);
        }
        let y_range = canvas.y_range.clone();
        for name in names {
            let sides: Vec<bool> = beyond
                .iter()
                .filter(|(n, _)| *n == name)
                .map(|(_, y)| *y > y_range.end)
                .collect();
            let side = match (sides.contains(&true), sides.contains(&false)) {
                (false, false) => continue,
                (true, false) => "above",
                (false, true) => "below",
                (true, true) => "above and below",
            };
            canvas.legend.notes.push(format!("{name}: {side} the axis"));
        }
        Ok(())
    }

    /// Draws the vertical reference lines, each labelled at the top of the axes (a label
    /// that would overlap one before it a line lower).
    fn draw_vertical_lines<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let label_style = (FONT_FAMILY, font_px(f64::from(TEXT_SIZE)))
            .into_font()
            .color(&VERTICAL_LINE_COLOUR);
        let (area, y_range, plot) = (canvas.area, canvas.y_range.clone(), canvas.plot);
        let mut labels: Vec<PixelRect> = Vec::new();
        for line in self.vertical_lines.iter().filter(|l| l.x.is_finite()) {
            let style = VERTICAL_LINE_COLOUR.stroke_width(pxu(1));
            let ends = [(line.x, y_range.start), (line.x, y_range.end)];
            let pixels = ends.map(|p| canvas.chart.backend_coord(&p));
            canvas
                .chart
                .draw_series(DashedLineSeries::new(ends, pxu(2), pxu(3), style))
                .map_err(failed)?;
            canvas.occupancy.mark_path(&pixels, px(1));
            let (w, h) = area
                .estimate_text_size(&line.name, &label_style)
                .map_err(failed)?;
            let (w, h) = (i32::try_from(w).unwrap_or(0), i32::try_from(h).unwrap_or(0));
            let top = canvas.chart.backend_coord(&(line.x, y_range.end));
            // The label right of the line, or left of it where it would leave the axes.
            let left = if top.0 + px(4) + w > plot.right {
                top.0 - px(4) - w
            } else {
                top.0 + px(4)
            };
            let mut rect = PixelRect::at((left - px(2), top.1 + px(2)), (w + px(4), h + px(4)));
            while labels.iter().any(|other| other.overlaps(&rect)) {
                rect = PixelRect::at((rect.left, rect.bottom), (w + px(4), h + px(4)));
            }
            labels.push(rect);
            canvas.occupancy.mark_rect(rect);
            let base = area.get_base_pixel();
            let at = (left - base.0, rect.top + px(2) - base.1);
            area.draw(&Text::new(line.name.clone(), at, label_style.clone()))
                .map_err(failed)?;
        }
        Ok(())
    }

    /// Draws the scatter series, in the order added: as dots in the palette's colours
    /// after the lines', or as markers of their own style (those within the axes); then
    /// the keys' legend entries.
    fn draw_scatter<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let offset = self.lines.len();
        for (index, series) in self.scatter.iter().enumerate() {
            let points = finite(&series.points);
            let style = match series.style {
                Some(style) => style,
                None => {
                    let colour = PALETTE[(offset + index) % PALETTE.len()];
                    MarkerStyle::filled(MarkerShape::Circle, colour, 3).opacity(0.7)
                }
            };
            let radius = px(i32::try_from(style.size).unwrap_or(3) + 1);
            for point in &points {
                let pixel = canvas.chart.backend_coord(point);
                canvas.occupancy.mark_point(pixel, radius);
            }
            if series.style.is_some() {
                for point in points.into_iter().filter(|p| canvas.contains(*p)) {
                    draw_marker(canvas.area, canvas.area_pixel(point), style).map_err(failed)?;
                }
            } else {
                let fill = style.colour.mix(style.opacity).filled();
                canvas
                    .chart
                    .draw_series(
                        points
                            .into_iter()
                            .map(move |p| Circle::new(p, pxu(3), fill)),
                    )
                    .map_err(failed)?;
            }
            canvas.legend.push(&series.name, Sample::Marker(style));
        }
        for (name, style) in &self.keys {
            canvas.legend.push(name, Sample::Marker(*style));
        }
        Ok(())
    }

    /// Draws the named point markers.
    fn draw_markers<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        for (index, marker) in self.markers.iter().enumerate() {
            let (x, y) = marker.point;
            if !(x.is_finite() && y.is_finite()) {
                continue;
            }
            let colour = MARKER_COLOURS[index % MARKER_COLOURS.len()];
            let style = MarkerStyle::filled(marker.shape, colour, 6);
            let pixel = canvas.chart.backend_coord(&marker.point);
            canvas.occupancy.mark_point(pixel, px(8));
            draw_marker(canvas.area, canvas.area_pixel(marker.point), style).map_err(failed)?;
            canvas.legend.push(&marker.name, Sample::Marker(style));
        }
        Ok(())
    }
}
