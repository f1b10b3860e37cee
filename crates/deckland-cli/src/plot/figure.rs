//! A figure: panels stacked top to bottom under a title, rendered to PNG and SVG.

use std::path::{Path, PathBuf};

use anyhow::{anyhow, Result};
use plotters::coord::Shift;
use plotters::prelude::*;

use super::panel::Panel;
use super::style::*;
use crate::output::OutputDir;

/// A figure: an optional overall title above panels stacked top to bottom.
#[derive(Debug, Clone)]
pub struct Figure {
    pub(super) title: Option<String>,
    pub(super) panels: Vec<Panel>,
    pub(super) width_px: u32,
    pub(super) panel_height_px: u32,
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
    /// none), which then holds every panel's legend; returns the widest legend drawn in
    /// the column, or, without one, the widest that found no free place inside its axes.
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
    /// axes, else the widest legend of the figure, since the column then holds them all
    /// (found by drawing to a scratch SVG, again with the column).
    pub(super) fn legend_column(&self) -> Result<i32> {
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
