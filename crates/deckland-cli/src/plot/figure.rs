//! A figure: panels stacked top to bottom under a title, laid out for its printed size
//! and written as SVG, as PNG rasterised from that SVG, and as PDF (`render`).

use std::path::PathBuf;

use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use super::options::{self, FigureOptions};
use super::panel::{Outside, OutsideLegend, Panel};
use super::render;
use super::style::*;
use crate::output::OutputDir;

/// The least resolution a figure is laid out at (layout px per inch): plotters places
/// everything on whole pixels, so a PNG of fewer dpi is scaled down from this layout and
/// the SVG and PDF keep its precision.
const MIN_LAYOUT_DPI: f64 = 300.0;
/// Design pixels of a panel that are not data: its title, the margins and the x axis's
/// labels (vertically); the y axis's labels and the margins (horizontally).
const PANEL_CHROME: (f64, f64) = (96.0, 100.0);
/// The least height of a panel's data (design px) when a narrow figure is laid out.
const MIN_DATA_HEIGHT: f64 = 130.0;
/// A legend wider than this share of the figure goes under its panel rather than in a
/// column beside the axes, which would leave the data too little room.
const MAX_COLUMN_SHARE: f64 = 0.4;

/// A figure: an optional overall title above panels stacked top to bottom.
#[derive(Debug, Clone)]
pub struct Figure {
    pub(super) title: Option<String>,
    pub(super) panels: Vec<Panel>,
    /// Width in design pixels (those of 14 px small text).
    pub(super) width_px: u32,
    /// Height of each panel at that width (design px).
    pub(super) panel_height_px: u32,
}

/// A figure's geometry in layout pixels, and the page it is printed on.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Layout {
    /// Layout pixels per design pixel.
    pub(super) scale: f64,
    /// Width (layout px).
    pub(super) width: u32,
    /// Height of each panel without a legend under it (layout px).
    pub(super) panel_height: u32,
    /// Layout pixels per inch, for a figure printed at a size; `None` for one drawn in
    /// design pixels (the unit tests' figures).
    pub(super) dpi: Option<f64>,
}

/// Where the legends go that find no free place inside their axes.
#[derive(Debug, Clone, PartialEq)]
enum LegendPlace {
    /// Each inside its axes (or none is shown).
    Inside,
    /// In a column this wide (layout px) beside every panel, which then holds every
    /// panel's legend.
    Column(i32),
    /// Under their panels, in strips this high (layout px, 0 under a panel whose legend
    /// is inside its axes).
    Below(Vec<i32>),
}

impl Figure {
    /// An empty figure 1000 design px wide, 420 design px per panel.
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

    /// Sets the height of each panel (design px, at the design width of 1000 px).
    pub fn panel_height(mut self, pixels: u32) -> Self {
        self.panel_height_px = pixels;
        self
    }

    /// The figure in design pixels, 1000 px wide: what the unit tests measure.
    #[cfg(test)]
    pub(super) fn design_layout(&self) -> Layout {
        Layout {
            scale: 1.0,
            width: self.width_px,
            panel_height: self.panel_height_px,
            dpi: None,
        }
    }

    /// The figure laid out for `options`: `width_mm` wide at the layout's resolution,
    /// its small text `font_pt` (an em of `font_pt` / 72 in, plotters' size being 1.24
    /// em), each panel's data as tall as at the design width in proportion to its width,
    /// but at least [`MIN_DATA_HEIGHT`], and every panel taller by the most that any
    /// panel's text around its axes takes beyond one line each (wrapped titles and axis
    /// labels, turned categories).
    pub(super) fn printed_layout(&self, options: &FigureOptions) -> Result<Layout> {
        register_bundled_font()?;
        let dpi = f64::from(options.dpi).max(MIN_LAYOUT_DPI);
        let small_text = options.font_pt / 72.0 * dpi * 1.24;
        let scale = small_text / f64::from(TEXT_SIZE);
        let width = (options.width_mm / 25.4 * dpi).round().max(1.0);
        let (chrome_x, chrome_y) = PANEL_CHROME;
        let design_data_width = f64::from(self.width_px) - chrome_x;
        let data_width = width / scale - chrome_x;
        let design_data_height = f64::from(self.panel_height_px) - chrome_y;
        let data_height = (design_data_height * data_width / design_data_width)
            .max(MIN_DATA_HEIGHT.min(design_data_height));
        let width = width as u32;
        let panel_height = ((chrome_y + data_height) * scale).round() as u32;
        let _scale = ScaleGuard::set(scale, width as i32);
        let mut scratch = String::new();
        let area = SVGBackend::with_string(&mut scratch, (width, panel_height)).into_drawing_area();
        let extra = self
            .panels
            .iter()
            .map(|panel| panel.chrome(&area).extra_height())
            .max()
            .unwrap_or(0);
        Ok(Layout {
            scale,
            width,
            panel_height: panel_height + u32::try_from(extra).unwrap_or(0),
            dpi: Some(dpi),
        })
    }

    /// The title's lines and font size (layout px): one line at the largest size from
    /// 23 design px down to 17 that fits the width, else wrapped at 17.
    fn title_lines<DB: DrawingBackend>(
        &self,
        area: &DrawingArea<DB, Shift>,
        title: &str,
    ) -> (Vec<String>, f64) {
        let width = area.dim_in_pixel().0.saturating_sub(pxu(24));
        fitted_lines(area, title, (23, 17), width)
    }

    /// The height (layout px) of the title's lines beyond the first.
    fn title_extra_height(&self, layout: &Layout) -> u32 {
        let Some(title) = &self.title else { return 0 };
        let mut scratch = String::new();
        let area = SVGBackend::with_string(&mut scratch, (layout.width, 100)).into_drawing_area();
        let _scale = ScaleGuard::set(layout.scale, layout.width as i32);
        let (lines, size) = self.title_lines(&area, title);
        u32::try_from(lines.len().saturating_sub(1)).unwrap_or(0)
            * u32::try_from(line_height(size)).unwrap_or(0)
    }

    /// Overall size (layout px) with the legends `place`d.
    fn size(&self, layout: &Layout, place: &LegendPlace) -> (u32, u32) {
        let title = if self.title.is_some() {
            (40.0 * layout.scale).round() as u32 + self.title_extra_height(layout)
        } else {
            0
        };
        let rows = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        let below: i32 = match place {
            LegendPlace::Below(strips) => strips.iter().sum(),
            _ => 0,
        };
        (
            layout.width,
            title + rows * layout.panel_height + u32::try_from(below).unwrap_or(0),
        )
    }

    /// Draws the figure with its legends `place`d; returns, for each panel, the size
    /// (layout px, with its spacing) of its legend where it is drawn outside its axes
    /// (in a column or under them) or found no free place inside.
    fn draw<DB: DrawingBackend>(
        &self,
        root: DrawingArea<DB, Shift>,
        layout: &Layout,
        place: &LegendPlace,
    ) -> Result<Vec<OutsideLegend>>
    where
        DB::ErrorType: 'static,
    {
        let _scale = ScaleGuard::set(layout.scale, layout.width as i32);
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        root.fill(&WHITE).map_err(error)?;
        let body = match &self.title {
            Some(title) => self.draw_title(&root, title)?,
            None => root.clone(),
        };
        let rows = self.panels.len().max(1);
        let areas = match place {
            LegendPlace::Below(strips) => {
                let heights: Vec<i32> = (0..rows)
                    .map(|i| layout.panel_height as i32 + strips.get(i).copied().unwrap_or(0))
                    .collect();
                let total: i32 = heights.iter().sum();
                let body_height = i32::try_from(body.dim_in_pixel().1).unwrap_or(0);
                let mut breaks = Vec::new();
                let mut sum = 0;
                for height in &heights[..rows - 1] {
                    sum += height;
                    breaks.push(
                        (f64::from(sum) * f64::from(body_height) / f64::from(total.max(1))).round()
                            as i32,
                    );
                }
                body.split_by_breakpoints(Vec::<i32>::new(), breaks)
            }
            _ => body.split_evenly((rows, 1)),
        };
        let mut outside = Vec::new();
        for (index, (area, panel)) in areas.iter().zip(&self.panels).enumerate() {
            let legend = match place {
                LegendPlace::Inside => panel.draw(area, Outside::Nowhere)?,
                LegendPlace::Column(column) => {
                    let width = i32::try_from(area.dim_in_pixel().0).unwrap_or(0);
                    let (axes, legend) = area.split_horizontally(width - column);
                    panel.draw(&axes, Outside::Column(&legend))?
                }
                LegendPlace::Below(strips) => {
                    let strip = strips.get(index).copied().unwrap_or(0);
                    let height = i32::try_from(area.dim_in_pixel().1).unwrap_or(0);
                    let (axes, under) = area.split_vertically(height - strip);
                    panel.draw(&axes, Outside::Below(&under))?
                }
            };
            outside.push(legend);
        }
        root.present().map_err(error)?;
        Ok(outside)
    }

    /// Draws the title centred at the top of `root`, wrapped if it does not fit at the
    /// small text's size; returns the area under it.
    fn draw_title<DB: DrawingBackend>(
        &self,
        root: &DrawingArea<DB, Shift>,
        title: &str,
    ) -> Result<DrawingArea<DB, Shift>>
    where
        DB::ErrorType: 'static,
    {
        let error = |e: DrawingAreaErrorKind<DB::ErrorType>| anyhow!("plot drawing failed: {e}");
        let (lines, size) = self.title_lines(root, title);
        let style =
            TextStyle::from((FONT_FAMILY, size).into_font()).pos(Pos::new(HPos::Center, VPos::Top));
        let (_, text_height) = root.estimate_text_size(title, &style).map_err(error)?;
        let text_height = i32::try_from(text_height).unwrap_or(0);
        let step = line_height(size);
        // As plotters' `titled`: half the text's height above and below, at most 5 px.
        let padding = (text_height / 2).min(px(5));
        let centre = i32::try_from(root.dim_in_pixel().0 / 2).unwrap_or(0);
        let mut top = padding;
        for (index, line) in lines.iter().enumerate() {
            if index > 0 {
                top += step;
            }
            root.draw(&Text::new(line.clone(), (centre, top), style.clone()))
                .map_err(error)?;
        }
        let height = i32::try_from(root.dim_in_pixel().1).unwrap_or(0);
        Ok(root
            .split_vertically((top + padding + text_height).min(height))
            .1)
    }

    /// Where the legends go: inside their axes where they find room; else in a column
    /// beside the axes, as wide as the widest legend (found by drawing to scratch SVGs,
    /// again with the column, since it then holds every legend); or, when that column
    /// would take more than [`MAX_COLUMN_SHARE`] of the width, under their panels.
    fn legend_place(&self, layout: &Layout) -> Result<LegendPlace> {
        let scratch_draw = |place: &LegendPlace| -> Result<Vec<OutsideLegend>> {
            let mut scratch = String::new();
            let size = self.size(layout, place);
            self.draw(
                SVGBackend::with_string(&mut scratch, size).into_drawing_area(),
                layout,
                place,
            )
        };
        let widest = |legends: &[OutsideLegend]| {
            legends
                .iter()
                .map(|legend| legend.map_or(0, |(w, _)| w))
                .max()
                .unwrap_or(0)
        };
        let inside = scratch_draw(&LegendPlace::Inside)?;
        let mut column = widest(&inside);
        if column == 0 {
            return Ok(LegendPlace::Inside);
        }
        if f64::from(column) > MAX_COLUMN_SHARE * f64::from(layout.width) {
            let strips = inside
                .iter()
                .map(|legend| legend.map_or(0, |(_, h)| h))
                .collect();
            return Ok(LegendPlace::Below(strips));
        }
        for _ in 0..2 {
            let in_column = widest(&scratch_draw(&LegendPlace::Column(column))?);
            if in_column <= column {
                break;
            }
            column = in_column;
        }
        Ok(LegendPlace::Column(column))
    }

    /// The width of the legend column of the figure in design pixels, 0 for none.
    #[cfg(test)]
    pub(super) fn legend_column(&self) -> Result<i32> {
        register_bundled_font()?;
        Ok(match self.legend_place(&self.design_layout())? {
            LegendPlace::Column(column) => column,
            _ => 0,
        })
    }

    /// The SVG document of the figure at `layout`: for a printed figure, its `width` and
    /// `height` are its printed size in millimetres over a view box in layout pixels.
    pub(super) fn document(&self, layout: &Layout) -> Result<String> {
        register_bundled_font()?;
        let place = self.legend_place(layout)?;
        let size = self.size(layout, &place);
        let mut svg = String::new();
        self.draw(
            SVGBackend::with_string(&mut svg, size).into_drawing_area(),
            layout,
            &place,
        )?;
        Ok(match layout.dpi {
            Some(dpi) => render::with_printed_size(&svg, size, dpi),
            None => svg,
        })
    }

    /// Renders the figure as an SVG document in design pixels, 1000 px wide.
    #[cfg(test)]
    pub fn render_svg(&self) -> Result<String> {
        self.document(&self.design_layout())
    }

    /// Renders the figure as an SVG document laid out for `options`.
    #[cfg(test)]
    pub fn render_svg_with(&self, options: &FigureOptions) -> Result<String> {
        self.document(&self.printed_layout(options)?)
    }

    /// The figure's files for `options`: the SVG document, the PNG rasterised from it at
    /// `options.dpi`, and the PDF when `options.pdf`.
    pub fn render_files(&self, options: &FigureOptions) -> Result<Rendered> {
        let layout = self.printed_layout(options)?;
        let svg = self.document(&layout)?;
        let dpi = layout.dpi.unwrap_or(MIN_LAYOUT_DPI);
        let tree = render::parse(&svg, dpi)?;
        let png = render::png(&tree, f64::from(options.dpi) / dpi, options.dpi)?;
        let pdf = options.pdf.then(|| render::pdf(&tree, dpi)).transpose()?;
        Ok(Rendered { svg, png, pdf })
    }

    /// Writes `<stem>.png` and `<stem>.svg` (and `<stem>.pdf` when asked for) atomically
    /// into `output`, laid out with the command's figure options; returns their paths.
    pub fn save(&self, output: &OutputDir, stem: &str) -> Result<Vec<PathBuf>> {
        Ok(self.save_with_svg(output, stem)?.0)
    }

    /// As [`Figure::save`], also returning the SVG document (for `report.html`).
    pub fn save_with_svg(&self, output: &OutputDir, stem: &str) -> Result<(Vec<PathBuf>, String)> {
        let Rendered { svg, png, pdf } = self.render_files(&options::current())?;
        let mut written = vec![output.write_bytes(&format!("{stem}.png"), &png)?];
        written.push(output.write_bytes(&format!("{stem}.svg"), svg.as_bytes())?);
        if let Some(pdf) = pdf {
            written.push(output.write_bytes(&format!("{stem}.pdf"), &pdf)?);
        }
        Ok((written, svg))
    }
}

/// A figure's files: the SVG document, the PNG and the PDF (when asked for).
#[derive(Debug, Clone)]
pub struct Rendered {
    /// The SVG document.
    pub svg: String,
    /// The PNG file's bytes.
    pub png: Vec<u8>,
    /// The PDF file's bytes.
    pub pdf: Option<Vec<u8>>,
}

impl Default for Figure {
    fn default() -> Self {
        Self::new()
    }
}
