//! Drawing a panel: its axes, then its lines, scatter, markers, histograms and reference
//! lines, or its bar chart, and its legend where nothing is drawn.

use std::ops::Range;

use anyhow::{anyhow, Result};
use plotters::coord::types::RangedCoordf64;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::legend::{draw_marker, Legend, MarkerShape, Occupancy, PixelRect, Sample};
use super::panel::{OutsideLegend, Panel};
use super::style::*;
use super::ticks::{self, AxisLabels, X_LABELS, Y_LABELS};

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
        let downward = self.y_downward;
        // + 0.0 turns −0 into 0: the axis never labels "−0".
        let y_format = move |y: &f64| y_labels.format(if downward { -*y + 0.0 } else { *y });
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
    pub(super) fn draw_xy<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(Legend, Occupancy, PixelRect)>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let (x_range, y_range) = self.ranges();
        let (x_range, y_range) = if self.equal_aspect {
            let size = self.plotting_size(area.dim_in_pixel())?;
            equal_aspect_ranges(x_range, y_range, size)
        } else {
            (x_range, y_range)
        };
        let mut chart = self.axes(area, x_range.clone(), y_range.clone(), false)?;
        let (xs, ys) = chart.plotting_area().get_pixel_range();
        let plot = PixelRect {
            left: xs.start,
            top: ys.start,
            right: xs.end,
            bottom: ys.end,
        };
        let mut occupancy = Occupancy::new(plot);
        // One pixel in data units.
        let pixel_x = (x_range.end - x_range.start) / f64::from((xs.end - xs.start).max(1));
        let pixel_y = (y_range.end - y_range.start) / f64::from((ys.end - ys.start).max(1));
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
                    occupancy.mark_rect(PixelRect::spanning(
                        chart.backend_coord(&corners[0]),
                        chart.backend_coord(&corners[1]),
                    ));
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
            // A jagged line is drawn 1 px wide three times, offset by one pixel right and
            // down, so that it looks as heavy as the others (2 px) without breaking up.
            let jagged = !line.dashed && is_jagged(&pixels);
            let width = 2;
            let dash = line.dashed.then_some(line.pattern.unwrap_or((10, 6)));
            match dash {
                Some((dash, gap)) => chart
                    .draw_series(DashedLineSeries::new(
                        points,
                        dash,
                        gap,
                        colour.stroke_width(width),
                    ))
                    .map(|_| ())
                    .map_err(error)?,
                None if jagged => {
                    for (dx, dy) in [(0.0, 0.0), (pixel_x, 0.0), (0.0, -pixel_y)] {
                        let shifted = points.iter().map(|(x, y)| (x + dx, y + dy));
                        chart
                            .draw_series(LineSeries::new(shifted, colour.stroke_width(1)))
                            .map_err(error)?;
                    }
                }
                None => chart
                    .draw_series(LineSeries::new(points, colour.stroke_width(width)))
                    .map(|_| ())
                    .map_err(error)?,
            }
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
                .draw_series(DashedLineSeries::new(ends, 2, 3, style))
                .map_err(error)?;
            occupancy.mark_path(&pixels, 1);
            let (w, h) = area
                .estimate_text_size(&line.name, &label_style)
                .map_err(error)?;
            let (w, h) = (i32::try_from(w).unwrap_or(0), i32::try_from(h).unwrap_or(0));
            let top = chart.backend_coord(&(line.x, y_range.end));
            // The label right of the line, or left of it where it would leave the axes.
            let left = if top.0 + 4 + w > plot.right {
                top.0 - 4 - w
            } else {
                top.0 + 4
            };
            occupancy.mark_rect(PixelRect::at((left - 2, top.1 + 2), (w + 4, h + 4)));
            let base = area.get_base_pixel();
            area.draw(&Text::new(
                line.name.clone(),
                (left - base.0, top.1 + 4 - base.1),
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
    pub(super) fn draw_bar_chart<DB: DrawingBackend>(
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
                occupancy.mark_rect(PixelRect::spanning(
                    chart.backend_coord(&corners[0]),
                    chart.backend_coord(&corners[1]),
                ));
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
