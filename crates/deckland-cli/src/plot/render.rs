//! From a figure's SVG document to its files: the printed size written into the SVG, the
//! PNG rasterised by resvg, the PDF converted by svg2pdf.
//!
//! The SVG is the one drawing of a figure; both other files are made from it, with the
//! bundled font (`usvg` shapes text with rustybuzz, applying the font's kerning, and
//! resvg renders the glyphs' outlines at their exact positions). plotters' own bitmap
//! backend is not used: it draws each glyph from its pen position truncated to a whole
//! pixel, drops the glyph's left side bearing and kerns from the legacy `kern` table
//! only, which the bundled font (kerned in `GPOS`) does not have, so its letters stood
//! unevenly apart.

use std::sync::{Arc, OnceLock};

use anyhow::{anyhow, bail, Context, Result};
use svg2pdf::usvg;
use usvg::fontdb;

use super::options::MAX_PNG_PIXELS;
use super::style::FONT_BYTES;

/// `svg` (plotters' document, `size` layout px) with its printed size in millimetres at
/// `dpi` layout px per inch as its `width` and `height`, over its view box in layout px.
pub(super) fn with_printed_size(svg: &str, (width, height): (u32, u32), dpi: f64) -> String {
    let mm = |pixels: u32| f64::from(pixels) / dpi * 25.4;
    let from = format!("width=\"{width}\" height=\"{height}\" viewBox");
    let to = format!(
        "width=\"{:.3}mm\" height=\"{:.3}mm\" viewBox",
        mm(width),
        mm(height)
    );
    svg.replacen(&from, &to, 1)
}

/// The bundled font, the only one the SVG's text is set in, and its family's name.
fn fonts() -> &'static (Arc<fontdb::Database>, String) {
    static FONTS: OnceLock<(Arc<fontdb::Database>, String)> = OnceLock::new();
    FONTS.get_or_init(|| {
        let mut database = fontdb::Database::new();
        database.load_font_data(FONT_BYTES.to_vec());
        let family = database
            .faces()
            .next()
            .and_then(|face| face.families.first())
            .map_or_else(|| "DejaVu Sans".to_owned(), |(name, _)| name.clone());
        database.set_sans_serif_family(family.clone());
        (Arc::new(database), family)
    })
}

/// The SVG document parsed for rendering, its millimetres at `dpi` layout px per inch
/// (so that the tree is as many units wide as the view box).
pub(super) fn parse(svg: &str, dpi: f64) -> Result<usvg::Tree> {
    let (database, family) = fonts();
    let options = usvg::Options {
        dpi: dpi as f32,
        font_family: family.clone(),
        fontdb: database.clone(),
        ..usvg::Options::default()
    };
    usvg::Tree::from_str(svg, &options).context("cannot read the figure's SVG document")
}

/// The PNG of `tree` at `zoom` image pixels per layout pixel, marked `dpi` pixels per
/// inch, opaque on white.
pub(super) fn png(tree: &usvg::Tree, zoom: f64, dpi: u32) -> Result<Vec<u8>> {
    let size = tree.size();
    let width = (f64::from(size.width()) * zoom).round().max(1.0) as u32;
    let height = (f64::from(size.height()) * zoom).round().max(1.0) as u32;
    if u64::from(width) * u64::from(height) > MAX_PNG_PIXELS {
        bail!(
            "a figure of {width} × {height} pixels is too large for a PNG (at most \
             {MAX_PNG_PIXELS} pixels): lower --figure-dpi or --figure-width-mm"
        );
    }
    let mut pixmap = resvg::tiny_skia::Pixmap::new(width, height)
        .ok_or_else(|| anyhow!("cannot make a {width} × {height} image"))?;
    pixmap.fill(resvg::tiny_skia::Color::WHITE);
    let transform = resvg::tiny_skia::Transform::from_scale(
        width as f32 / size.width(),
        height as f32 / size.height(),
    );
    resvg::render(tree, transform, &mut pixmap.as_mut());
    // Premultiplied RGBA over white: each channel plus the white the alpha leaves.
    let rgb: Vec<u8> = pixmap
        .data()
        .chunks_exact(4)
        .flat_map(|p| {
            let white = 255 - p[3];
            [
                p[0].saturating_add(white),
                p[1].saturating_add(white),
                p[2].saturating_add(white),
            ]
        })
        .collect();
    let mut bytes = Vec::new();
    let mut encoder = png::Encoder::new(&mut bytes, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    // The resolution (pHYs), so that a word processor places the image at its size.
    let per_metre = (f64::from(dpi) / 0.0254).round() as u32;
    encoder.set_pixel_dims(Some(png::PixelDimensions {
        xppu: per_metre,
        yppu: per_metre,
        unit: png::Unit::Meter,
    }));
    let mut writer = encoder.write_header().context("cannot write the PNG")?;
    writer
        .write_image_data(&rgb)
        .context("cannot write the PNG")?;
    writer.finish().context("cannot write the PNG")?;
    Ok(bytes)
}

/// The PDF of `tree`: one page of the figure's printed size (its layout px at `dpi` per
/// inch), vector graphics, the text as text in the embedded subset of the bundled font.
pub(super) fn pdf(tree: &usvg::Tree, dpi: f64) -> Result<Vec<u8>> {
    let page = svg2pdf::PageOptions { dpi: dpi as f32 };
    svg2pdf::to_pdf(tree, svg2pdf::ConversionOptions::default(), page)
        .map(in_resource_order)
        .map_err(|e| anyhow!("cannot convert the figure to PDF: {e}"))
}

/// `pdf` with the entries of each resources dictionary sorted, so that one figure gives
/// one file, byte for byte. svg2pdf 0.13 names its resources in a fixed order but writes
/// a dictionary's entries in the order of a `HashMap` (a random order, different in every
/// map). The entries are lines `/xo3 14 0 R` between a line ending in `<<` and one that
/// is `>>`; they are only reordered among themselves, so every byte offset of the file
/// (its cross-reference table) stays right.
fn in_resource_order(pdf: Vec<u8>) -> Vec<u8> {
    let is_entry = |line: &[u8]| {
        let words: Vec<&[u8]> = line.trim_ascii().split(|b| *b == b' ').collect();
        matches!(words.as_slice(), [name, object, b"0", b"R"]
            if name.len() > 1 && name[0] == b'/' && name[1..].iter().all(u8::is_ascii_alphanumeric)
                && !object.is_empty() && object.iter().all(u8::is_ascii_digit))
    };
    let mut lines: Vec<&[u8]> = pdf.split_inclusive(|b| *b == b'\n').collect();
    let mut start = 0;
    while start < lines.len() {
        let opens = lines[start].trim_ascii_end().ends_with(b"<<");
        let mut end = start + 1;
        while opens && end < lines.len() && is_entry(lines[end]) {
            end += 1;
        }
        let closes = lines.get(end).is_some_and(|l| l.trim_ascii() == b">>");
        if opens && closes && end > start + 2 {
            lines[start + 1..end].sort_unstable();
        }
        start = end.max(start + 1);
    }
    lines.concat()
}
