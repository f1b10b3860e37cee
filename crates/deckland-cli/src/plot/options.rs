//! The size of the figures on paper and their files: `--figure-width-mm`, `--font-pt`,
//! `--figure-dpi` and `--pdf`, shared by every command that writes figures.
//!
//! A figure is laid out for its printed width: its small text (tick labels, legends, line
//! labels) is `--font-pt` when the figure is printed `--figure-width-mm` wide, its axis
//! labels and titles larger (never smaller). The defaults are a journal's: IEEE's
//! one-column width, 3.5 in = 88.9 mm (IEEE Author Center, "Size Requirements for
//! Graphics"; Elsevier's is 90 mm), and 8 pt text: IEEE's guidelines for author-supplied
//! graphics set callouts in 8 pt, and Elsevier's "Artwork sizing" asks for lettering of
//! 7 pt at the printed size (IEEE's current page suggests type of about 9–10 pt:
//! `--font-pt 9`). The PNG is 300 dpi, IEEE's standard for colour and grayscale images
//! (IEEE Author Center, "Resolution and Size"): 1050 px across one column.

use std::sync::RwLock;

use anyhow::{bail, Result};

/// IEEE's one-column width (mm): 3.5 in.
pub const DEFAULT_WIDTH_MM: f64 = 88.9;
/// The small text's size (pt) at the figure's width.
pub const DEFAULT_FONT_PT: f64 = 8.0;
/// Pixels per inch of the PNG.
pub const DEFAULT_DPI: u32 = 300;

/// Narrowest and widest figure (mm).
pub const WIDTH_MM_RANGE: (f64, f64) = (30.0, 500.0);
/// Smallest and largest text (pt).
pub const FONT_PT_RANGE: (f64, f64) = (4.0, 36.0);
/// Lowest and highest PNG resolution (dpi).
pub const DPI_RANGE: (u32, u32) = (72, 1200);
/// The least width of a figure in ems of its small text: narrower, the axes and their
/// labels leave no room for the data (88.9 mm holds 8 pt text 31.5 times).
pub const MIN_WIDTH_EMS: f64 = 20.0;
/// The most pixels a PNG may have (a 400 MB image in memory).
pub const MAX_PNG_PIXELS: u64 = 100_000_000;

/// How every figure of a command is sized and which files it is written to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FigureOptions {
    /// Printed width (mm).
    pub width_mm: f64,
    /// Size of the small text (pt) at that width.
    pub font_pt: f64,
    /// Pixels per inch of the PNG.
    pub dpi: u32,
    /// Also write `<stem>.pdf`.
    pub pdf: bool,
}

impl Default for FigureOptions {
    fn default() -> Self {
        Self {
            width_mm: DEFAULT_WIDTH_MM,
            font_pt: DEFAULT_FONT_PT,
            dpi: DEFAULT_DPI,
            pdf: false,
        }
    }
}

impl FigureOptions {
    /// The options, checked together: the figure must hold [`MIN_WIDTH_EMS`] of its text.
    pub fn checked(self) -> Result<Self> {
        let ems = self.width_mm / 25.4 * 72.0 / self.font_pt;
        if ems < MIN_WIDTH_EMS {
            let largest = self.width_mm / 25.4 * 72.0 / MIN_WIDTH_EMS;
            bail!(
                "--font-pt {} is too large for --figure-width-mm {}: a figure is at least \
                 {MIN_WIDTH_EMS} times as wide as its text is high (at most {:.1} pt at \
                 {} mm)",
                self.font_pt,
                self.width_mm,
                (largest * 10.0).floor() / 10.0,
                self.width_mm
            );
        }
        Ok(self)
    }
}

/// The options that set the figures' size and files (see the module's documentation).
#[derive(Debug, Clone, clap::Args)]
pub struct FigureArgs {
    /// Width of every figure as printed (mm), 30 to 500. The default is a journal's
    /// one-column width, IEEE's 3.5 in (Elsevier's is 90; two columns are 182 to 190).
    #[arg(long, value_name = "MM", default_value_t = DEFAULT_WIDTH_MM,
          value_parser = parse_width_mm, allow_negative_numbers = true)]
    pub figure_width_mm: f64,
    /// Size of the figures' small text (tick labels, legends) when a figure is printed at
    /// `--figure-width-mm` (pt), 4 to 36; axis labels and titles are larger.
    #[arg(long, value_name = "PT", default_value_t = DEFAULT_FONT_PT,
          value_parser = parse_font_pt, allow_negative_numbers = true)]
    pub font_pt: f64,
    /// Resolution of the PNG files (pixels per inch, written into the file), 72 to 1200:
    /// a figure's PNG is width / 25.4 × DPI pixels wide.
    #[arg(long, value_name = "DPI", default_value_t = DEFAULT_DPI,
          value_parser = parse_dpi, allow_negative_numbers = true)]
    pub figure_dpi: u32,
    /// Also write every figure as PDF, `<name>.pdf` beside its PNG and SVG: vector
    /// graphics, the text in the embedded font, the page the figure's printed size.
    #[arg(long)]
    pub pdf: bool,
}

impl FigureArgs {
    /// The checked options.
    pub fn options(&self) -> Result<FigureOptions> {
        FigureOptions {
            width_mm: self.figure_width_mm,
            font_pt: self.font_pt,
            dpi: self.figure_dpi,
            pdf: self.pdf,
        }
        .checked()
    }
}

/// A number within `(low, high)`, or "expected {what} from {low} to {high}".
fn parse_in<T>(text: &str, (low, high): (T, T), what: &str) -> Result<T, String>
where
    T: std::str::FromStr + PartialOrd + std::fmt::Display,
{
    text.trim()
        .parse::<T>()
        .ok()
        .filter(|v| *v >= low && *v <= high)
        .ok_or_else(|| format!("expected {what} from {low} to {high}"))
}

fn parse_width_mm(text: &str) -> Result<f64, String> {
    parse_in(text, WIDTH_MM_RANGE, "a width in mm")
}

fn parse_font_pt(text: &str) -> Result<f64, String> {
    parse_in(text, FONT_PT_RANGE, "a size in points")
}

fn parse_dpi(text: &str) -> Result<u32, String> {
    parse_in(text, DPI_RANGE, "a whole number of pixels per inch")
}

/// The options of the command being run; the defaults until [`set`] is called.
static CURRENT: RwLock<Option<FigureOptions>> = RwLock::new(None);

/// Sets the options every figure of this process is written with (the command line's).
pub fn set(options: FigureOptions) {
    if let Ok(mut current) = CURRENT.write() {
        *current = Some(options);
    }
}

/// The options figures are written with: those [`set`], else the defaults.
pub fn current() -> FigureOptions {
    CURRENT
        .read()
        .ok()
        .and_then(|current| *current)
        .unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bad_values_are_refused_in_words() {
        for bad in ["0", "-1", "NaN", "inf", "29.9", "500.1", "abc", ""] {
            let error = parse_width_mm(bad).expect_err(bad);
            assert!(
                error.contains("a width in mm from 30 to 500"),
                "{bad}: {error}"
            );
        }
        for bad in ["0", "-1", "NaN", "-inf", "3.9", "37", "8pt"] {
            let error = parse_font_pt(bad).expect_err(bad);
            assert!(
                error.contains("a size in points from 4 to 36"),
                "{bad}: {error}"
            );
        }
        for bad in ["0", "71", "1201", "300.5", "-300"] {
            assert!(parse_dpi(bad).is_err(), "{bad}");
        }
        assert_eq!(parse_width_mm("88.9"), Ok(88.9));
        assert_eq!(parse_font_pt("8"), Ok(8.0));
        assert_eq!(parse_dpi("600"), Ok(600));
    }

    #[test]
    fn text_too_large_for_the_width_is_refused_naming_both_options() {
        let options = FigureOptions {
            width_mm: 40.0,
            font_pt: 12.0,
            ..FigureOptions::default()
        };
        let error = options.checked().expect_err("too large").to_string();
        assert!(
            error.contains("--font-pt 12") && error.contains("--figure-width-mm 40"),
            "{error}"
        );
        assert!(FigureOptions::default().checked().is_ok());
    }
}
