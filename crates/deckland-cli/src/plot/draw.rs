//! Drawing a panel: its axes, then its lines, scatter, markers, histograms and reference
//! lines, or its bar chart (`bars`), and its legend where nothing is drawn.

use std::ops::Range;

use anyhow::{anyhow, Result};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;

use super::legend::{draw_marker, Legend, MarkerShape, MarkerStyle, Occupancy, PixelRect, Sample};
use super::panel::{OutsideLegend, Panel};
use super::style::*;
use super::ticks::{self, AxisLabels, X_LABELS, Y_LABELS};

/// A panel's chart: data coordinates to pixels.
pub(super) type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

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

    /// The chart's axes, title and grid on `area`.
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
        // A log axis labels the whole powers of ten (its values are their exponents).
        let log = self.log_y;
        let y_labels = AxisLabels::new(&y_range, Y_LABELS, self.integer_y || log);
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
            .x_desc(&self.x_label)
            .y_desc(&self.y_label)
            .label_style((FONT_FAMILY, 14))
            .axis_desc_style((FONT_FAMILY, 16))
            .max_light_lines(if log { 0 } else { 4 })
            .light_line_style(RGBColor(242, 242, 242))
            .bold_line_style(RGBColor(218, 218, 218))
            .draw()
            .map_err(error)?;
        Ok(chart)
    }

    /// Draws the panel on `area`; its legend goes into `column` if given, else inside if a
    /// free place exists. Returns the width the legend needs beside the axes when it is
    /// in the column or found no free place.
    pub(super) fn draw<DB: DrawingBackend>(
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
        if !legend.is_shown() || self.shared_legend {
            return Ok(None);
        }
        let size = legend.size(area)?;
        // With a legend column beside the figure, every legend goes there: beside the
        // panel whose legend fits inside its axes, the column would stay empty.
        if let Some(column) = column {
            let base = column.get_base_pixel();
            legend.draw(column, (base.0 + 4, plot.top), size)?;
        } else if let Some(place) = occupancy.free_place(size) {
            legend.draw(area, place, size)?;
            return Ok(None);
        }
        Ok(Some(size.0 + 12))
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
                        .map(|c| Rectangle::new(*c, colour.stroke_width(1))),
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
        let (xs, ys) = canvas.chart.plotting_area().get_pixel_range();
        let (x_range, y_range) = (&canvas.x_range, &canvas.y_range);
        // One pixel in data units.
        let pixel_x = (x_range.end - x_range.start) / f64::from((xs.end - xs.start).max(1));
        let pixel_y = (y_range.end - y_range.start) / f64::from((ys.end - ys.start).max(1));
        for (index, line) in self.lines.iter().enumerate() {
            let colour = line.colour.unwrap_or(PALETTE[index % PALETTE.len()]);
            let points = finite(&line.points);
            let chart = &mut canvas.chart;
            let pixels: Vec<(i32, i32)> = points.iter().map(|p| chart.backend_coord(p)).collect();
            // A jagged line is drawn 1 px wide three times, offset by one pixel right and
            // down, so that it looks as heavy as the others (2 px) without breaking up.
            let jagged = !line.dashed && is_jagged(&pixels);
            let width = 2;
            let dash = line.dashed.then_some(line.pattern.unwrap_or((10, 6)));
            match dash {
                Some((dash, gap)) => {
                    let style = colour.stroke_width(width);
                    let series = DashedLineSeries::new(points, dash, gap, style);
                    chart.draw_series(series).map_err(failed)?;
                }
                None if jagged => {
                    for (dx, dy) in [(0.0, 0.0), (pixel_x, 0.0), (0.0, -pixel_y)] {
                        let shifted = points.iter().map(|(x, y)| (x + dx, y + dy));
                        chart
                            .draw_series(LineSeries::new(shifted, colour.stroke_width(1)))
                            .map_err(failed)?;
                    }
                }
                None => {
                    let series = LineSeries::new(points, colour.stroke_width(width));
                    chart.draw_series(series).map_err(failed)?;
                }
            }
            canvas.occupancy.mark_path(&pixels, 2);
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
            let series = DashedLineSeries::new(ends, dash, gap, colour.stroke_width(1));
            canvas.chart.draw_series(series).map_err(failed)?;
            canvas.occupancy.mark_path(&pixels, 1);
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

    /// Draws the vertical reference lines, each labelled at the top of the axes.
    fn draw_vertical_lines<DB: DrawingBackend>(&self, canvas: &mut Canvas<DB>) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let label_style = (FONT_FAMILY, 13).into_font().color(&VERTICAL_LINE_COLOUR);
        let (area, y_range, plot) = (canvas.area, canvas.y_range.clone(), canvas.plot);
        for line in self.vertical_lines.iter().filter(|l| l.x.is_finite()) {
            let style = VERTICAL_LINE_COLOUR.stroke_width(1);
            let ends = [(line.x, y_range.start), (line.x, y_range.end)];
            let pixels = ends.map(|p| canvas.chart.backend_coord(&p));
            canvas
                .chart
                .draw_series(DashedLineSeries::new(ends, 2, 3, style))
                .map_err(failed)?;
            canvas.occupancy.mark_path(&pixels, 1);
            let (w, h) = area
                .estimate_text_size(&line.name, &label_style)
                .map_err(failed)?;
            let (w, h) = (i32::try_from(w).unwrap_or(0), i32::try_from(h).unwrap_or(0));
            let top = canvas.chart.backend_coord(&(line.x, y_range.end));
            // The label right of the line, or left of it where it would leave the axes.
            let left = if top.0 + 4 + w > plot.right {
                top.0 - 4 - w
            } else {
                top.0 + 4
            };
            canvas
                .occupancy
                .mark_rect(PixelRect::at((left - 2, top.1 + 2), (w + 4, h + 4)));
            let base = area.get_base_pixel();
            let at = (left - base.0, top.1 + 4 - base.1);
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
            let radius = i32::try_from(style.size).unwrap_or(3) + 1;
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
                    .draw_series(points.into_iter().map(move |p| Circle::new(p, 3, fill)))
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
            canvas.occupancy.mark_point(pixel, 8);
            draw_marker(canvas.area, canvas.area_pixel(marker.point), style).map_err(failed)?;
            canvas.legend.push(&marker.name, Sample::Marker(style));
        }
        Ok(())
    }
}
