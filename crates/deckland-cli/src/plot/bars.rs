//! Drawing a bar chart: categories along x, the groups side by side in each, every bar
//! with its interval and its label above; on a linear axis from zero, or on a log axis
//! (`Panel::log_y`) from its floor. A zero value draws no bar, only its label.

use std::ops::Range;

use anyhow::Result;
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::draw::{failed, Canvas};
use super::legend::{Legend, Occupancy, PixelRect, Sample};
use super::panel::Panel;
use super::style::*;
use super::ticks;

/// Colour of the intervals.
const INTERVAL_COLOUR: RGBColor = RGBColor(0, 0, 0);
/// Colour of an interval that reaches below a log axis' floor (that of a zero count): a
/// thin grey line, which no reader takes for a bar.
const OPEN_INTERVAL_COLOUR: RGBColor = RGBColor(140, 140, 140);
/// Colour of a log axis' grid lines between the powers of ten.
const MINOR_GRID_COLOUR: RGBColor = RGBColor(242, 242, 242);

/// How values map onto a bar chart's y axis: as they are, or as their decimal logarithm
/// above a floor.
#[derive(Debug, Clone, Copy)]
pub(super) struct ValueAxis {
    /// The floor's exponent on a log axis; `None` for a linear axis.
    floor: Option<f64>,
}

impl ValueAxis {
    /// The axis of `panel`'s bars and their range in axis units (with room for labels).
    pub(super) fn of(panel: &Panel) -> (Self, Range<f64>) {
        let ends = panel.bars.iter().flat_map(|b| {
            let intervals = b.intervals.iter().flat_map(|i| [i.0, i.1]);
            b.values.iter().copied().chain(intervals)
        });
        let ends: Vec<f64> = ends.filter(|v| v.is_finite() && *v > 0.0).collect();
        let highest = ends.iter().copied().fold(0.0_f64, f64::max);
        if !panel.log_y {
            let top = if highest > 0.0 { highest * 1.15 } else { 1.0 };
            return (Self { floor: None }, 0.0..top);
        }
        let lowest = ends.iter().copied().fold(f64::INFINITY, f64::min);
        if !lowest.is_finite() {
            return (Self { floor: Some(0.0) }, 0.0..1.0);
        }
        // The power of ten below half the smallest end: its bar is at least 0.3 decades tall.
        let floor = (0.5 * lowest).log10().floor();
        let top = highest.log10() + 0.3;
        (Self { floor: Some(floor) }, floor..top.max(floor + 1.0))
    }

    /// The bottom of the bars.
    fn base(&self) -> f64 {
        self.floor.unwrap_or(0.0)
    }

    /// `value` in axis units; `None` where it is not drawn (not finite, or not above
    /// the floor of a log axis).
    fn at(&self, value: f64) -> Option<f64> {
        match self.floor {
            _ if !value.is_finite() => None,
            None => Some(value),
            Some(floor) => (value > 0.0).then(|| value.log10()).filter(|v| *v > floor),
        }
    }
}

impl Panel {
    /// Draws the panel as a bar chart: categories along x, the groups side by side, each
    /// bar with its interval and its label above.
    pub(super) fn draw_bar_chart<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(Legend, Occupancy, PixelRect)>
    where
        DB::ErrorType: 'static,
    {
        let (axis, y_range) = ValueAxis::of(self);
        let x_range = -0.5..(self.categories.len() as f64 - 0.5);
        let chart = self.axes(area, x_range.clone(), y_range.clone(), true)?;
        let mut canvas = Canvas::new(area, chart, (x_range, y_range), self.notes.clone());
        if axis.floor.is_some() {
            draw_minor_grid(&mut canvas)?;
        }
        for (index, group) in self.bars.iter().enumerate() {
            let colour = PALETTE[index % PALETTE.len()];
            for (category, &value) in group.values.iter().enumerate() {
                let bar = Bar {
                    left: category as f64 - 0.4 + self.group_width() * index as f64,
                    value,
                    interval: group.intervals.get(category).copied(),
                    label: group.labels.get(category).cloned(),
                };
                self.draw_bar(&mut canvas, axis, colour, bar)?;
            }
            let sample = Sample::Patch {
                colour,
                opacity: 1.0,
            };
            canvas.legend.push(&group.name, sample);
        }
        if self.bars.iter().any(|b| !b.intervals.is_empty()) {
            let sample = Sample::Interval {
                colour: INTERVAL_COLOUR,
            };
            canvas.legend.push(&self.interval_name, sample);
        }
        Ok(canvas.finish())
    }

    /// The width of one group's bar in a category (x units).
    fn group_width(&self) -> f64 {
        0.8 / self.bars.len().max(1) as f64
    }

    /// Draws one bar (none for zero), its interval and its label above both.
    fn draw_bar<DB: DrawingBackend>(
        &self,
        canvas: &mut Canvas<DB>,
        axis: ValueAxis,
        colour: RGBColor,
        bar: Bar,
    ) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let width = self.group_width();
        let centre = bar.left + width / 2.0;
        let mut label_at = axis.base();
        if let Some(top) = axis.at(bar.value).filter(|top| *top != axis.base()) {
            let corners = [(bar.left, axis.base()), (bar.left + width, top)];
            let rectangle = Rectangle::new(corners, colour.filled());
            canvas
                .chart
                .draw_series(std::iter::once(rectangle))
                .map_err(failed)?;
            canvas.occupancy.mark_rect(PixelRect::spanning(
                canvas.chart.backend_coord(&corners[0]),
                canvas.chart.backend_coord(&corners[1]),
            ));
            label_at = top;
        }
        if let Some(interval) = bar.interval {
            if let Some(high) = draw_interval(canvas, axis, centre, width, interval)? {
                label_at = label_at.max(high);
            }
        }
        let label = bar.label.unwrap_or_else(|| {
            let decimals = if bar.value.fract() == 0.0 { 0 } else { 1 };
            match bar.value.is_finite() {
                true => ticks::format_tick(bar.value, decimals),
                false => "—".to_string(),
            }
        });
        draw_label(canvas, (centre, label_at), label)
    }
}

/// One bar of a group: its left edge (x units), value, interval and label.
struct Bar {
    left: f64,
    value: f64,
    interval: Option<(f64, f64)>,
    label: Option<String>,
}

/// Draws the interval `(low, high)` of the bar centred on `centre`, `width` wide: a
/// whisker with caps; where it reaches below a log axis' floor, thin and grey, without
/// the lower cap.
/// Returns its top in axis units, `None` when it is not drawn.
fn draw_interval<DB: DrawingBackend>(
    canvas: &mut Canvas<DB>,
    axis: ValueAxis,
    centre: f64,
    width: f64,
    (low, high): (f64, f64),
) -> Result<Option<f64>>
where
    DB::ErrorType: 'static,
{
    if !low.is_finite() {
        return Ok(None);
    }
    let Some(top) = axis.at(high) else {
        return Ok(None);
    };
    let bottom = axis.at(low);
    let half_cap = width * 0.18;
    let foot = bottom.unwrap_or(axis.base());
    let mut paths = vec![
        vec![(centre, foot), (centre, top)],
        vec![(centre - half_cap, top), (centre + half_cap, top)],
    ];
    let style = match bottom {
        Some(bottom) => {
            paths.push(vec![
                (centre - half_cap, bottom),
                (centre + half_cap, bottom),
            ]);
            INTERVAL_COLOUR.stroke_width(pxu(2))
        }
        None => OPEN_INTERVAL_COLOUR.stroke_width(pxu(1)),
    };
    for path in paths {
        let pixels: Vec<_> = path.iter().map(|p| canvas.chart.backend_coord(p)).collect();
        canvas.occupancy.mark_path(&pixels, px(2));
        canvas
            .chart
            .draw_series(std::iter::once(PathElement::new(path, style)))
            .map_err(failed)?;
    }
    Ok(Some(top))
}

/// Writes `label` centred above `anchor` (data units).
fn draw_label<DB: DrawingBackend>(
    canvas: &mut Canvas<DB>,
    anchor: (f64, f64),
    label: String,
) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let text_style = (FONT_FAMILY, font_px(f64::from(TEXT_SIZE)))
        .into_font()
        .color(&RGBColor(40, 40, 40))
        .pos(Pos::new(HPos::Center, VPos::Bottom));
    let pixel = canvas.chart.backend_coord(&anchor);
    let (w, h) = canvas
        .area
        .estimate_text_size(&label, &text_style)
        .map_err(failed)?;
    let (w, h) = (i32::try_from(w).unwrap_or(0), i32::try_from(h).unwrap_or(0));
    canvas.occupancy.mark_rect(PixelRect::at(
        (pixel.0 - w / 2 - px(2), pixel.1 - px(4) - h),
        (w + px(4), h + px(4)),
    ));
    let at = canvas.area_pixel(anchor);
    canvas
        .area
        .draw(&Text::new(label, (at.0, at.1 - px(4)), text_style))
        .map_err(failed)?;
    Ok(())
}

/// Draws a log axis' light grid lines at 2 to 9 times each power of ten.
fn draw_minor_grid<DB: DrawingBackend>(canvas: &mut Canvas<DB>) -> Result<()>
where
    DB::ErrorType: 'static,
{
    let (x, y) = (canvas.x_range.clone(), canvas.y_range.clone());
    let decades = y.start.floor() as i32..=y.end.ceil() as i32;
    let heights = decades.flat_map(|k| (2..10).map(move |m| f64::from(k) + f64::from(m).log10()));
    for h in heights.filter(|h| y.contains(h)) {
        let style = MINOR_GRID_COLOUR.stroke_width(pxu(1));
        let path = PathElement::new(vec![(x.start, h), (x.end, h)], style);
        canvas
            .chart
            .draw_series(std::iter::once(path))
            .map_err(failed)?;
    }
    Ok(())
}
