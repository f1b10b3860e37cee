//! The result folders of `fly(out=...)` and `campaign(out=...)`: the files `deckland run`
//! and `deckland campaign` write — the data, the plots and `report.html` — written by the
//! command line's own code (`deckland_cli::folders`).

use std::path::PathBuf;

use deckland_cli::folders::{
    FigureOptions, FolderRequest, DPI_RANGE, FONT_PT_RANGE, WIDTH_MM_RANGE,
};
use pyo3::exceptions::{PyOSError, PyTypeError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt};

use crate::errors::{argument_error, strict_integer, value_error};

/// Where a folder goes, as given to the Python call.
pub(crate) struct Destination {
    out: PathBuf,
    force: bool,
    figures: FigureOptions,
}

impl Destination {
    /// The destination of `out` (a path or `None`: no folder), `force` and `figures` (a
    /// `deckland.Figures` or `None`: the defaults), checked before anything is flown.
    pub(crate) fn of(
        out: Option<PathBuf>,
        force: bool,
        figures: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<Option<Self>> {
        let figures = match figures {
            Some(figures) if !figures.is_none() => figure_options(figures)?,
            _ => FigureOptions::default(),
        };
        let figures = figures.checked().map_err(|error| {
            value_error(
                error
                    .to_string()
                    .replace("--font-pt", "figures.font_pt")
                    .replace("--figure-width-mm", "figures.width_mm"),
            )
        })?;
        Ok(out.map(|out| Self {
            out,
            force,
            figures,
        }))
    }

    /// Writes with `write` (the interpreter released); returns the folder's path. An error
    /// of the files is an `OSError` with the command line's words, its options named as
    /// this call's arguments.
    pub(crate) fn write(
        &self,
        py: Python<'_>,
        write: impl FnOnce(&FolderRequest) -> anyhow::Result<PathBuf> + Send,
    ) -> PyResult<String> {
        let request = FolderRequest {
            out: &self.out,
            force: self.force,
            figures: self.figures,
        };
        let written = py.detach(|| write(&request));
        written
            .map(|path| path.display().to_string())
            .map_err(|error| PyOSError::new_err(python_words(&error)))
    }
}

/// The error's chain on one line as the command line prints it, its options named as
/// the Python arguments (`out=`, `force=True`).
fn python_words(error: &anyhow::Error) -> String {
    deckland_cli::error_chain(error)
        .replace("--out ", "out=")
        .replace("with --out", "with out=")
        .replace("--force", "force=True")
}

/// The options of a `deckland.Figures`: `width_mm`, `font_pt`, `dpi`, `pdf`, each of its
/// type (a bool is not a number, nor a number a bool) and within the command line's range.
fn figure_options(figures: &Bound<'_, PyAny>) -> PyResult<FigureOptions> {
    let attribute = |name: &str| {
        figures.getattr(name).map_err(|_| {
            PyTypeError::new_err(format!(
                "`figures` = {}: expected a deckland.Figures (no attribute `{name}`)",
                figures
                    .repr()
                    .map_or_else(|_| "?".to_owned(), |r| r.to_string())
            ))
        })
    };
    let number = |name: &str, (low, high): (f64, f64)| -> PyResult<f64> {
        let value = attribute(name)?;
        let is_number = (value.is_instance_of::<PyFloat>() || value.is_instance_of::<PyInt>())
            && !value.is_instance_of::<PyBool>();
        if !is_number {
            return Err(PyTypeError::new_err(format!(
                "`figures.{name}` = {}: expected a number (an int or a float)",
                value.repr()?
            )));
        }
        let number: f64 = value.extract()?;
        if !(number.is_finite() && (low..=high).contains(&number)) {
            return Err(argument_error(
                &format!("figures.{name}"),
                number,
                format!("{low} to {high}"),
            ));
        }
        Ok(number)
    };
    let width_mm = number("width_mm", WIDTH_MM_RANGE)?;
    let font_pt = number("font_pt", FONT_PT_RANGE)?;
    let (low, high) = DPI_RANGE;
    let dpi = strict_integer("figures.dpi", &attribute("dpi")?)?;
    if !(i128::from(low)..=i128::from(high)).contains(&dpi) {
        return Err(argument_error(
            "figures.dpi",
            dpi,
            format!("{low} to {high} pixels per inch"),
        ));
    }
    let pdf = attribute("pdf")?;
    if !pdf.is_instance_of::<PyBool>() {
        return Err(PyTypeError::new_err(format!(
            "`figures.pdf` = {}: expected True or False",
            pdf.repr()?
        )));
    }
    Ok(FigureOptions {
        width_mm,
        font_pt,
        dpi: dpi as u32,
        pdf: pdf.extract()?,
    })
}
