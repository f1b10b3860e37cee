//! Legends that never cover data: what a panel drew is marked on a grid of its plotting
//! area, and the legend goes where the grid is empty (a corner first), or beside the axes
//! when no such place exists. Each entry's sample is drawn with the style of its line,
//! marker or patch: colour, width and dash pattern.

use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

use super::style::{figure_width, font_px, px, pxu, TEXT_SIZE};
use super::FONT_FAMILY;

/// A point in backend pixels.
pub(crate) type Pixel = (i32, i32);

// Lengths in design pixels (`style::px`), but for the occupancy grid's cell.
/// Height of one legend line.
const LINE_HEIGHT: i32 = 19;
/// Width of an entry's sample.
const SAMPLE_WIDTH: i32 = 30;
/// Widest line of a note before it is wrapped.
const NOTE_WIDTH: i32 = 300;
/// Padding inside the legend box.
const PADDING: i32 = 7;
/// Distance kept between the legend and anything drawn, and the axes.
const CLEARANCE: i32 = 4;
/// Side of a cell of the occupancy grid (layout px).
const CELL: i32 = 2;

/// A rectangle in backend pixels, `right` and `bottom` excluded.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) struct PixelRect {
    pub(crate) left: i32,
    pub(crate) top: i32,
    pub(crate) right: i32,
    pub(crate) bottom: i32,
}

impl PixelRect {
    /// The rectangle with opposite corners `a` and `b` (in any order).
    pub(crate) fn spanning(a: Pixel, b: Pixel) -> Self {
        Self {
            left: a.0.min(b.0),
            top: a.1.min(b.1),
            right: a.0.max(b.0),
            bottom: a.1.max(b.1),
        }
    }

    /// The rectangle at `top_left` of `size`.
    pub(crate) fn at(top_left: Pixel, (width, height): (i32, i32)) -> Self {
        Self {
            left: top_left.0,
            top: top_left.1,
            right: top_left.0 + width,
            bottom: top_left.1 + height,
        }
    }

    /// Whether `self` and `other` share a pixel.
    pub(crate) fn overlaps(&self, other: &PixelRect) -> bool {
        self.left < other.right
            && other.left < self.right
            && self.top < other.bottom
            && other.top < self.bottom
    }

    fn width(&self) -> i32 {
        self.right - self.left
    }

    fn height(&self) -> i32 {
        self.bottom - self.top
    }
}

/// Which cells of a plotting area hold something drawn.
pub(crate) struct Occupancy {
    area: PixelRect,
    columns: usize,
    rows: usize,
    cells: Vec<bool>,
}

impl Occupancy {
    /// An empty grid over `area`.
    pub(crate) fn new(area: PixelRect) -> Self {
        let columns = (area.width().max(1) / CELL + 1) as usize;
        let rows = (area.height().max(1) / CELL + 1) as usize;
        Self {
            area,
            columns,
            rows,
            cells: vec![false; columns * rows],
        }
    }

    /// Marks the pixels of `rect` (clipped to the area).
    pub(crate) fn mark_rect(&mut self, rect: PixelRect) {
        let ((c0, c1), (r0, r1)) = self.cells_of(rect);
        for r in r0..r1 {
            for c in c0..c1 {
                self.cells[r as usize * self.columns + c as usize] = true;
            }
        }
    }

    /// The cells `rect` covers, clipped to the area: (first column, column past the
    /// last), (first row, row past the last).
    fn cells_of(&self, rect: PixelRect) -> ((i32, i32), (i32, i32)) {
        let column = |x: i32| ((x - self.area.left).div_euclid(CELL)).clamp(0, self.columns as i32);
        let row = |y: i32| ((y - self.area.top).div_euclid(CELL)).clamp(0, self.rows as i32);
        (
            (column(rect.left), column(rect.right + CELL - 1)),
            (row(rect.top), row(rect.bottom + CELL - 1)),
        )
    }

    /// Marks a disc of `radius` px about `centre` (as its bounding square).
    pub(crate) fn mark_point(&mut self, centre: Pixel, radius: i32) {
        self.mark_rect(PixelRect {
            left: centre.0 - radius,
            top: centre.1 - radius,
            right: centre.0 + radius + 1,
            bottom: centre.1 + radius + 1,
        });
    }

    /// Marks the segment from `a` to `b`, `radius` px either side.
    pub(crate) fn mark_segment(&mut self, a: Pixel, b: Pixel, radius: i32) {
        let (dx, dy) = ((b.0 - a.0) as f64, (b.1 - a.1) as f64);
        let length = dx.hypot(dy);
        if !length.is_finite() {
            return;
        }
        let steps = (length / f64::from(CELL)).ceil().max(1.0) as i32;
        for i in 0..=steps {
            let t = f64::from(i) / f64::from(steps);
            let point = (a.0 + (dx * t).round() as i32, a.1 + (dy * t).round() as i32);
            self.mark_point(point, radius);
        }
    }

    /// Marks a polyline.
    pub(crate) fn mark_path(&mut self, pixels: &[Pixel], radius: i32) {
        match pixels {
            [single] => self.mark_point(*single, radius),
            _ => {
                for pair in pixels.windows(2) {
                    self.mark_segment(pair[0], pair[1], radius);
                }
            }
        }
    }

    /// Whether any cell of `rect` is marked.
    fn is_free(&self, rect: PixelRect, table: &[u32]) -> bool {
        let ((c0, c1), (r0, r1)) = self.cells_of(rect);
        let (c0, c1, r0, r1) = (c0 as usize, c1 as usize, r0 as usize, r1 as usize);
        let stride = self.columns + 1;
        let at = |r: usize, c: usize| table[r * stride + c];
        at(r1, c1) + at(r0, c0) - at(r0, c1) - at(r1, c0) == 0
    }

    /// The summed-area table of the marked cells ((rows + 1) × (columns + 1)).
    fn summed(&self) -> Vec<u32> {
        let stride = self.columns + 1;
        let mut table = vec![0_u32; (self.rows + 1) * stride];
        for r in 0..self.rows {
            for c in 0..self.columns {
                let cell = u32::from(self.cells[r * self.columns + c]);
                table[(r + 1) * stride + c + 1] =
                    cell + table[r * stride + c + 1] + table[(r + 1) * stride + c]
                        - table[r * stride + c];
            }
        }
        table
    }

    /// The top-left corner of a free place of `size` inside the area, keeping clear of
    /// the axes: a corner or the middle of the top or bottom edge if one is free (upper
    /// right first), else the free place nearest to a corner; `None` when nothing is free.
    pub(crate) fn free_place(&self, size: (i32, i32)) -> Option<Pixel> {
        let area = self.area;
        let (width, height) = size;
        let clearance = px(CLEARANCE);
        let left = area.left + clearance;
        let right = area.right - clearance - width;
        let top = area.top + clearance;
        let bottom = area.bottom - clearance - height;
        if right < left || bottom < top {
            return None;
        }
        let table = self.summed();
        let free = |x: i32, y: i32| {
            self.is_free(
                PixelRect {
                    left: x - clearance,
                    top: y - clearance,
                    right: x + width + clearance,
                    bottom: y + height + clearance,
                },
                &table,
            )
        };
        let middle = (left + right) / 2;
        let preferred = [
            (right, top),
            (left, top),
            (right, bottom),
            (left, bottom),
            (middle, top),
            (middle, bottom),
        ];
        if let Some(&place) = preferred.iter().find(|(x, y)| free(*x, *y)) {
            return Some(place);
        }
        let corners = [(right, top), (left, top), (right, bottom), (left, bottom)];
        let mut best: Option<(i64, Pixel)> = None;
        for y in (top..=bottom).step_by(4) {
            for x in (left..=right).step_by(4) {
                if !free(x, y) {
                    continue;
                }
                let distance = corners
                    .iter()
                    .map(|(cx, cy)| {
                        let (dx, dy) = (i64::from(x - cx), i64::from(y - cy));
                        dx * dx + dy * dy
                    })
                    .min()
                    .unwrap_or(0);
                if best.is_none_or(|(d, _)| distance < d) {
                    best = Some((distance, (x, y)));
                }
            }
        }
        best.map(|(_, place)| place)
    }
}

/// The shape of a point marker.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum MarkerShape {
    /// A circle.
    Circle,
    /// A triangle, point up.
    Triangle,
    /// A square.
    Square,
    /// A diamond (a square on its corner).
    Diamond,
    /// A triangle, point down.
    TriangleDown,
    /// A diagonal cross (×): lines only, the same filled or hollow.
    Cross,
}

/// How a point marker is drawn: its shape, colour and opacity, its size (the radius of a
/// circle, px), and whether it is filled or only outlined (hollow: what lies under it
/// shows through).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MarkerStyle {
    /// The shape.
    pub shape: MarkerShape,
    /// The colour of its fill, or of its outline when hollow.
    pub colour: RGBColor,
    /// Opacity, 0–1.
    pub opacity: f64,
    /// Size (px): the radius of a circle; the other shapes are as large to the eye.
    pub size: u32,
    /// Filled, or only outlined.
    pub filled: bool,
}

impl MarkerStyle {
    /// A filled marker of `shape` in `colour`, `size` px, opaque.
    pub fn filled(shape: MarkerShape, colour: RGBColor, size: u32) -> Self {
        Self {
            shape,
            colour,
            opacity: 1.0,
            size,
            filled: true,
        }
    }

    /// The same marker with `opacity`.
    pub fn opacity(self, opacity: f64) -> Self {
        Self { opacity, ..self }
    }

    /// The same marker, outlined only.
    pub fn hollow(self) -> Self {
        Self {
            filled: false,
            ..self
        }
    }
}

/// How an entry's sample is drawn: exactly as the thing it names.
#[derive(Debug, Clone, Copy)]
pub(crate) enum Sample {
    /// A line of `width` px, dashed `(dash, gap)` px or solid.
    Line {
        colour: RGBColor,
        width: u32,
        dash: Option<(u32, u32)>,
    },
    /// A point marker.
    Marker(MarkerStyle),
    /// A filled patch (histogram or bar), with an outline of the same colour.
    Patch { colour: RGBColor, opacity: f64 },
    /// An error bar with caps.
    Interval { colour: RGBColor },
}

/// One legend entry.
#[derive(Debug, Clone)]
pub(crate) struct Entry {
    pub(crate) sample: Sample,
    pub(crate) label: String,
}

/// A panel's legend: optional note lines (such as the outcome) above the entries.
#[derive(Debug, Clone, Default)]
pub(crate) struct Legend {
    pub(crate) notes: Vec<String>,
    pub(crate) entries: Vec<Entry>,
}

fn text_style() -> TextStyle<'static> {
    (FONT_FAMILY, font_px(f64::from(TEXT_SIZE)))
        .into_font()
        .color(&BLACK)
}

fn note_style() -> TextStyle<'static> {
    (FONT_FAMILY, font_px(f64::from(TEXT_SIZE)))
        .into_font()
        .style(FontStyle::Bold)
        .color(&BLACK)
}

impl Legend {
    /// Whether the panel shows a legend: notes, or more than one entry (a lone line is
    /// named by the panel's title).
    pub(crate) fn is_shown(&self) -> bool {
        !self.notes.is_empty() || self.entries.len() > 1
    }

    /// Adds an entry unless one with the same label is there already (two lines of one
    /// band share one entry).
    pub(crate) fn push(&mut self, label: &str, sample: Sample) {
        if !label.is_empty() && !self.entries.iter().any(|e| e.label == label) {
            self.entries.push(Entry {
                sample,
                label: label.to_string(),
            });
        }
    }

    /// The notes wrapped at word boundaries into lines of at most [`NOTE_WIDTH`] (and
    /// no wider than the figure leaves within the legend's box).
    fn note_lines<DB: DrawingBackend>(&self, area: &DrawingArea<DB, Shift>) -> Vec<String> {
        let widest = figure_width().map_or(px(NOTE_WIDTH), |figure| {
            px(NOTE_WIDTH).min(figure - px(2 * PADDING + 16))
        });
        let widest = u32::try_from(widest).unwrap_or(0);
        let fits = |text: &str| {
            area.estimate_text_size(text, &note_style())
                .is_ok_and(|(w, _)| w <= widest)
        };
        let mut lines = Vec::new();
        for note in &self.notes {
            let note_start = lines.len();
            // A short token (a unit, "=") stays with the word before it: "2.008 s".
            let mut words: Vec<String> = Vec::new();
            for word in note.split_whitespace() {
                match words.last_mut() {
                    Some(last) if word.chars().count() <= 2 => {
                        last.push(' ');
                        last.push_str(word);
                    }
                    _ => words.push(word.to_string()),
                }
            }
            lines.extend(super::style::fill_lines(words, fits));
            // No lone word on a note's last line.
            super::style::no_lone_last_word(&mut lines[note_start..], fits);
        }
        lines
    }

    /// Width and height of the legend box (px).
    pub(crate) fn size<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
    ) -> Result<(i32, i32)> {
        let width_of = |text: &str, style: &TextStyle| -> Result<i32> {
            let (w, _) = area
                .estimate_text_size(text, style)
                .map_err(|e| anyhow!("cannot measure the legend text: {e}"))?;
            Ok(i32::try_from(w).unwrap_or(i32::MAX / 4))
        };
        let notes = self.note_lines(area);
        let mut width = 0;
        for note in &notes {
            width = width.max(width_of(note, &note_style())?);
        }
        for entry in &self.entries {
            width = width.max(px(SAMPLE_WIDTH + 6) + width_of(&entry.label, &text_style())?);
        }
        let lines = i32::try_from(notes.len() + self.entries.len()).unwrap_or(0);
        Ok((
            width + 2 * px(PADDING),
            lines * px(LINE_HEIGHT) + 2 * px(PADDING) - px(4),
        ))
    }

    /// Draws the legend with its top-left corner at `top_left` (backend pixels).
    pub(crate) fn draw<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        top_left: Pixel,
        size: (i32, i32),
    ) -> Result<()>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("legend drawing failed: {e}");
        let base = area.get_base_pixel();
        let at = |x: i32, y: i32| (x - base.0, y - base.1);
        let (x0, y0) = top_left;
        area.draw(&Rectangle::new(
            [at(x0, y0), at(x0 + size.0, y0 + size.1)],
            WHITE.filled(),
        ))
        .map_err(error)?;
        area.draw(&Rectangle::new(
            [at(x0, y0), at(x0 + size.0, y0 + size.1)],
            RGBColor(170, 170, 170).stroke_width(pxu(1)),
        ))
        .map_err(error)?;
        let (padding, line_height) = (px(PADDING), px(LINE_HEIGHT));
        let mut y = y0 + padding;
        for note in &self.note_lines(area) {
            area.draw(&Text::new(note.clone(), at(x0 + padding, y), note_style()))
                .map_err(error)?;
            y += line_height;
        }
        for entry in &self.entries {
            let left = x0 + padding;
            let middle = y + line_height / 2 - px(2);
            draw_sample(area, entry.sample, at(left, middle)).map_err(error)?;
            area.draw(&Text::new(
                entry.label.clone(),
                at(left + px(SAMPLE_WIDTH + 6), y),
                text_style(),
            ))
            .map_err(error)?;
            y += line_height;
        }
        Ok(())
    }
}

/// Draws an entry's sample with its left end at `start` (area-relative pixels, at the
/// middle of the entry's line).
fn draw_sample<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    sample: Sample,
    start: Pixel,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let (left, middle) = start;
    let right = left + px(SAMPLE_WIDTH);
    match sample {
        Sample::Line {
            colour,
            width,
            dash,
        } => {
            let style = colour.stroke_width(pxu(width));
            let ends = vec![(left, middle), (right, middle)];
            match dash {
                Some((dash, gap)) => {
                    area.draw(&DashedPathElement::new(ends, pxu(dash), pxu(gap), style))
                }
                None => area.draw(&PathElement::new(ends, style)),
            }
        }
        Sample::Marker(style) => draw_marker(area, ((left + right) / 2, middle), style),
        Sample::Patch { colour, opacity } => {
            let corners = [
                (left + px(3), middle - px(6)),
                (right - px(3), middle + px(6)),
            ];
            area.draw(&Rectangle::new(corners, colour.mix(opacity).filled()))?;
            area.draw(&Rectangle::new(corners, colour.stroke_width(pxu(1))))
        }
        Sample::Interval { colour } => {
            let x = (left + right) / 2;
            let style = colour.stroke_width(pxu(2));
            let (half, cap) = (px(7), px(5));
            for path in [
                vec![(x, middle - half), (x, middle + half)],
                vec![(x - cap, middle - half), (x + cap, middle - half)],
                vec![(x - cap, middle + half), (x + cap, middle + half)],
            ] {
                area.draw(&PathElement::new(path, style))?;
            }
            Ok(())
        }
    }
}

/// The corners of a marker's polygon of `shape` and size `s` centred on (x, y); none for
/// a circle or a cross.
fn marker_polygon(shape: MarkerShape, (x, y): Pixel, s: i32) -> Vec<Pixel> {
    match shape {
        MarkerShape::Triangle => vec![(x, y - s), (x - s, y + s * 3 / 4), (x + s, y + s * 3 / 4)],
        MarkerShape::TriangleDown => {
            vec![(x, y + s), (x + s, y - s * 3 / 4), (x - s, y - s * 3 / 4)]
        }
        // As large as the circle to the eye: a side of 1.8 s, a half diagonal of 1.25 s.
        MarkerShape::Square => {
            let h = (s * 9 / 10).max(1);
            vec![
                (x - h, y - h),
                (x + h, y - h),
                (x + h, y + h),
                (x - h, y + h),
            ]
        }
        MarkerShape::Diamond => {
            let d = (s * 5 / 4).max(1);
            vec![(x, y - d), (x + d, y), (x, y + d), (x - d, y)]
        }
        MarkerShape::Circle | MarkerShape::Cross => Vec::new(),
    }
}

/// Draws one marker centred on `centre` (area-relative pixels), its size in design
/// pixels.
pub(crate) fn draw_marker<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    centre: Pixel,
    style: MarkerStyle,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let colour = style.colour.mix(style.opacity);
    let outline = colour.stroke_width(pxu(1));
    let size = pxu(style.size);
    let s = i32::try_from(size).unwrap_or(4);
    match style.shape {
        MarkerShape::Circle if style.filled => {
            area.draw(&Circle::new(centre, size, colour.filled()))
        }
        MarkerShape::Circle => area.draw(&Circle::new(centre, size, outline)),
        MarkerShape::Cross => {
            let (x, y) = centre;
            let d = (s * 4 / 5).max(1);
            let width = pxu(if style.filled { 2 } else { 1 });
            for ends in [
                [(x - d, y - d), (x + d, y + d)],
                [(x - d, y + d), (x + d, y - d)],
            ] {
                area.draw(&PathElement::new(ends, colour.stroke_width(width)))?;
            }
            Ok(())
        }
        shape => {
            let corners = marker_polygon(shape, centre, s);
            if style.filled {
                area.draw(&Polygon::new(corners, colour.filled()))
            } else {
                let mut closed = corners.clone();
                closed.extend(corners.first().copied());
                area.draw(&PathElement::new(closed, outline))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn area() -> PixelRect {
        PixelRect {
            left: 100,
            top: 50,
            right: 900,
            bottom: 350,
        }
    }

    #[test]
    fn an_empty_area_takes_the_legend_upper_right() {
        let grid = Occupancy::new(area());
        assert_eq!(
            grid.free_place((200, 80)),
            Some((900 - CLEARANCE - 200, 54))
        );
    }

    #[test]
    fn the_legend_moves_away_from_data_in_the_upper_right() {
        let mut grid = Occupancy::new(area());
        // A line across the upper right quarter.
        grid.mark_segment((500, 60), (900, 60), 2);
        grid.mark_segment((600, 50), (600, 200), 2);
        // The upper right is taken: the next corner in order of preference is upper left.
        assert_eq!(grid.free_place((200, 80)), Some((100 + CLEARANCE, 54)));
        // With the upper half full, a lower corner.
        grid.mark_rect(PixelRect::at((100, 50), (800, 150)));
        assert_eq!(
            grid.free_place((200, 80)),
            Some((696, 350 - CLEARANCE - 80))
        );
    }

    #[test]
    fn a_note_never_ends_on_a_lone_word() {
        // The outcome of seed 1 wrapped as "… 0.3 m above the" / "deck" at 300 px.
        crate::plot::tests::register();
        let mut svg = String::new();
        let area = SVGBackend::with_string(&mut svg, (800, 400)).into_drawing_area();
        let legend = Legend {
            notes: vec![
                "bolter: flew over the last wire 0.3 m above the deck".to_owned(),
                "short".to_owned(),
            ],
            entries: Vec::new(),
        };
        let lines = legend.note_lines(&area);
        assert!(lines.len() >= 3, "{lines:?}");
        let last_of_first = &lines[lines.len() - 2];
        assert!(last_of_first.contains(' '), "a lone word: {lines:?}");
        assert!(last_of_first.ends_with("deck"), "{lines:?}");
        // A one-line note stays as it is, and takes no word from the note before.
        assert_eq!(lines.last().map(String::as_str), Some("short"));
    }

    #[test]
    fn a_full_area_has_no_place() {
        let mut grid = Occupancy::new(area());
        grid.mark_rect(area());
        assert_eq!(grid.free_place((50, 20)), None);
        let small = Occupancy::new(area());
        assert_eq!(small.free_place((1000, 20)), None);
    }

    #[test]
    fn one_entry_per_label() {
        let mut legend = Legend::default();
        let sample = Sample::Line {
            colour: BLACK,
            width: 1,
            dash: Some((8, 5)),
        };
        legend.push("±2 % band", sample);
        legend.push("±2 % band", sample);
        assert_eq!(legend.entries.len(), 1);
        assert!(!legend.is_shown());
    }
}
