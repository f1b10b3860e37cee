//! Tests of a figure's size on paper (issue 46, item 4): the PNG's pixels and resolution,
//! the text's size at the printed width, the PDF, and text set evenly and kerned.

use super::figure::*;
use super::options::FigureOptions;
use super::panel::*;
use super::render;
use super::tests::{attribute, number, register, svg_elements};

/// DejaVu Sans's capital H is 1493 font units high of 2048 per em.
const CAP_HEIGHT_EM: f64 = 1493.0 / 2048.0;

/// A figure with a title, two panels, a legend and a vertical line's label.
fn sample_figure() -> Figure {
    let wave: Vec<(f64, f64)> = (0..200)
        .map(|i| (f64::from(i) * 0.1, (f64::from(i) * 0.1).sin()))
        .collect();
    Figure::new()
        .title("Final approach — O-PD, adverse, seed 1: trap on wire 3")
        .panel(
            Panel::new("Pitch", "time (s)", "pitch angle θ (deg)")
                .series("θ", wave.clone())
                .dashed_series("command", wave.iter().map(|(t, y)| (*t, 0.9 * y)).collect())
                .vertical_line("touchdown", 12.0),
        )
        .panel(Panel::new("Elevator", "time (s)", "elevator (deg)").series("δe", wave))
}

/// Width and height of a PNG, from its header.
fn png_size(png: &[u8]) -> (u32, u32) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n", "not a PNG");
    let word = |at: usize| u32::from_be_bytes(png[at..at + 4].try_into().expect("4 bytes"));
    (word(16), word(20))
}

/// The pixels per metre of a PNG's `pHYs` chunk (x, y), if it has one in metres.
fn png_pixels_per_metre(png: &[u8]) -> Option<(u32, u32)> {
    let mut at = 8;
    while at + 8 <= png.len() {
        let length = u32::from_be_bytes(png[at..at + 4].try_into().ok()?) as usize;
        let kind = &png[at + 4..at + 8];
        let data = png.get(at + 8..at + 8 + length)?;
        if kind == b"pHYs" && data.len() == 9 && data[8] == 1 {
            let word = |i: usize| u32::from_be_bytes(data[i..i + 4].try_into().expect("4"));
            return Some((word(0), word(4)));
        }
        at += 12 + length;
    }
    None
}

/// The root element's width in millimetres and its view box's width in layout px.
fn printed_width(svg: &str) -> (f64, f64) {
    let root = svg_elements(svg, "svg")[0];
    let mm = attribute(root, "width")
        .and_then(|w| w.strip_suffix("mm"))
        .and_then(|w| w.parse().ok())
        .expect("a width in mm");
    let view_box: Vec<f64> = attribute(root, "viewBox")
        .expect("a view box")
        .split_whitespace()
        .filter_map(|v| v.parse().ok())
        .collect();
    (mm, view_box[2])
}

/// The font sizes (layout px) of the SVG's text elements that hold `text`.
fn font_sizes_of(svg: &str, text: &str) -> Vec<f64> {
    svg_elements(svg, "text")
        .into_iter()
        .filter(|e| {
            e.split_once('>')
                .is_some_and(|(_, inner)| inner.trim() == text)
        })
        .filter_map(|e| number(e, "font-size"))
        .collect()
}

/// Points per layout pixel of a printed figure's SVG.
fn points_per_pixel(svg: &str) -> f64 {
    let (mm, pixels) = printed_width(svg);
    mm / 25.4 * 72.0 / pixels
}

/// The text's em in points: plotters' SVG writes the em as `font-size`.
fn em_points(svg: &str, text: &str) -> f64 {
    let sizes = font_sizes_of(svg, text);
    assert!(!sizes.is_empty(), "no text {text:?}");
    sizes[0] * points_per_pixel(svg)
}

fn options(width_mm: f64, font_pt: f64, dpi: u32) -> FigureOptions {
    FigureOptions {
        width_mm,
        font_pt,
        dpi,
        pdf: true,
    }
}

#[test]
fn the_png_is_the_printed_width_at_its_resolution_and_says_so() {
    register();
    for (width_mm, dpi) in [(88.9, 300), (182.0, 300), (90.0, 600), (88.9, 150)] {
        let files = sample_figure()
            .render_files(&options(width_mm, 8.0, dpi))
            .expect("renders");
        let (width, height) = png_size(&files.png);
        let expected = width_mm / 25.4 * f64::from(dpi);
        assert!(
            (f64::from(width) - expected).abs() <= 1.0,
            "{width_mm} mm at {dpi} dpi: {width} px, expected {expected:.1}"
        );
        let per_metre = (f64::from(dpi) / 0.0254).round() as u32;
        assert_eq!(
            png_pixels_per_metre(&files.png),
            Some((per_metre, per_metre))
        );
        // The SVG's printed size is the PNG's at that resolution.
        let (mm, _) = printed_width(&files.svg);
        assert!((mm - width_mm).abs() < 25.4 / 300.0, "{mm} mm");
        assert!(height > width / 3, "{width} × {height}");
    }
}

#[test]
fn the_small_text_is_font_pt_when_printed_at_the_width() {
    register();
    for (width_mm, font_pt, dpi) in [(88.9, 8.0, 300), (182.0, 9.0, 300), (60.0, 6.0, 600)] {
        let svg = sample_figure()
            .render_svg_with(&options(width_mm, font_pt, dpi))
            .expect("renders");
        // A legend entry, a vertical line's label and a tick label: the small text.
        for text in ["command", "touchdown", "0"] {
            let em = em_points(&svg, text);
            assert!(
                (em - font_pt).abs() < 0.01,
                "{text:?} is {em:.3} pt at {width_mm} mm, expected {font_pt}"
            );
        }
        // Axis labels and titles are larger, never smaller.
        let axis = em_points(&svg, "time (s)");
        assert!((axis - font_pt * 16.0 / 14.0).abs() < 0.01, "{axis} pt");
        for element in svg_elements(&svg, "text") {
            let size = number(element, "font-size").expect("a size") * points_per_pixel(&svg);
            assert!(size >= font_pt - 0.01, "{size} pt: {element}");
        }
    }
}

/// The glyphs come out as large as the SVG says: the capital H of the small text,
/// rasterised as the PNG is, is DejaVu Sans's cap height of an em of `--font-pt` at
/// `--figure-dpi`: 8 pt at 300 dpi is an em of 33.3 px, an H of 24.3 px.
#[test]
fn the_rendered_capital_is_the_cap_height_of_font_pt() {
    register();
    let options = FigureOptions::default();
    let svg = sample_figure().render_svg_with(&options).expect("renders");
    let size = font_sizes_of(&svg, "command")[0];
    let (mm, pixels) = printed_width(&svg);
    let lone_h = format!(
        "<svg width=\"{mm}mm\" height=\"{h}mm\" viewBox=\"0 0 {pixels} 200\" \
         xmlns=\"http://www.w3.org/2000/svg\"><text x=\"20\" y=\"150\" \
         font-family=\"sans-serif\" font-size=\"{size}\">HHHH</text></svg>",
        h = 200.0 / pixels * mm
    );
    let tree = render::parse(&lone_h, 300.0).expect("parses");
    let png = render::png(&tree, 1.0, 300).expect("renders");
    let image = image::load_from_memory(&png).expect("decodes").to_luma8();
    let inked_rows: Vec<u32> = (0..image.height())
        .filter(|&y| (0..image.width()).any(|x| image.get_pixel(x, y).0[0] < 128))
        .collect();
    let cap = f64::from(inked_rows.last().expect("ink") - inked_rows[0] + 1);
    let em = options.font_pt / 72.0 * f64::from(options.dpi);
    let expected = CAP_HEIGHT_EM * em;
    assert!(
        (cap - expected).abs() <= 1.5,
        "a capital H {cap} px high, expected {expected:.1} px (an em of {em:.1} px)"
    );
}

/// The darkness of each column (px) of `text` set at `size` px (with the text element's
/// further `attributes`) and rasterised as the figures' PNGs are, at 300 dpi.
fn ink_columns(text: &str, size: f64, attributes: &str) -> Vec<f64> {
    let svg = format!(
        "<svg width=\"100mm\" height=\"10mm\" viewBox=\"0 0 1181 118\" \
         xmlns=\"http://www.w3.org/2000/svg\"><text x=\"10.3\" y=\"80\" \
         font-family=\"sans-serif\" font-size=\"{size}\" {attributes}>{text}</text></svg>"
    );
    let tree = render::parse(&svg, 300.0).expect("parses");
    let image = image::load_from_memory(&render::png(&tree, 1.0, 300).expect("renders"))
        .expect("decodes")
        .to_luma8();
    (0..image.width())
        .map(|x| {
            (0..image.height())
                .map(|y| f64::from(255 - image.get_pixel(x, y).0[0]))
                .sum()
        })
        .collect()
}

/// The darkness-weighted centre (px) of each run of inked columns.
fn glyph_centres(ink: &[f64]) -> Vec<f64> {
    let mut centres = Vec::new();
    let mut run: Vec<(f64, f64)> = Vec::new();
    for (x, darkness) in ink.iter().enumerate() {
        if *darkness > 0.0 {
            run.push((x as f64, *darkness));
        } else if !run.is_empty() {
            let total: f64 = run.iter().map(|(_, d)| d).sum();
            centres.push(run.iter().map(|(x, d)| x * d).sum::<f64>() / total);
            run.clear();
        }
    }
    centres
}

/// The columns (px) from the first inked to the last.
fn ink_width(ink: &[f64]) -> usize {
    let first = ink.iter().position(|d| *d > 0.0).expect("ink");
    let last = ink.iter().rposition(|d| *d > 0.0).expect("ink");
    last - first + 1
}

/// The defect of the old PNGs (plotters' bitmap text: pen positions truncated to whole
/// pixels, side bearings dropped): letters stood unevenly apart. Ten l's of a size whose
/// advance is not a whole number of pixels now stand exactly one advance apart.
#[test]
fn letters_stand_evenly_apart() {
    register();
    // 23.7 px: an advance of 6.57 px, which whole-pixel placement would round unevenly.
    let centres = glyph_centres(&ink_columns("llllllllll", 23.7, ""));
    assert_eq!(centres.len(), 10, "{centres:?}");
    let gaps: Vec<f64> = centres.windows(2).map(|w| w[1] - w[0]).collect();
    let mean = gaps.iter().sum::<f64>() / gaps.len() as f64;
    for gap in &gaps {
        assert!((gap - mean).abs() < 0.2, "gaps {gaps:?}");
    }
}

/// The bundled font's kerning (in its GPOS table, which plotters' bitmap text never read)
/// is applied: DejaVu Sans sets "AV" and "VA" 131/2048 em closer and "AA" 57/2048 em
/// wider ("VV" as it is), so the same ten letters are (9 × 131 + 4 × 57 − 131) / 2048 em
/// shorter as AVAVAVAVAV than as AAAAAVVVVV; unkerned they would be as long.
#[test]
fn pairs_are_kerned() {
    register();
    let alternating = ink_width(&ink_columns("AVAVAVAVAV", 40.0, ""));
    let grouped = ink_width(&ink_columns("AAAAAVVVVV", 40.0, ""));
    // 1276/2048 em at 40 px: 24.9 px.
    let expected = (9.0 * 131.0 + 4.0 * 57.0 - 131.0) / 2048.0 * 40.0;
    let shorter = grouped as f64 - alternating as f64;
    assert!(
        (shorter - expected).abs() < 2.0,
        "AVAVAVAVAV is {alternating} px wide, AAAAAVVVVV {grouped} px: {shorter} px shorter, \
         expected {expected:.1}"
    );
}

/// The PDF is one page of the printed size with the text as text: the font embedded as
/// a TrueType program (vector outlines) and shown with text operators, not drawn as
/// paths or pixels.
#[test]
fn the_pdf_is_vector_with_the_font_embedded() {
    register();
    let files = sample_figure()
        .render_files(&options(88.9, 8.0, 300))
        .expect("renders");
    let pdf = files.pdf.expect("asked for");
    assert!(pdf.starts_with(b"%PDF-1."), "not a PDF");
    assert!(
        pdf.trim_ascii_end().ends_with(b"%%EOF"),
        "the PDF has no end"
    );
    let text = String::from_utf8_lossy(&pdf);
    for part in ["/FontFile2", "/CIDFontType2", "/ToUnicode", "DejaVuSans"] {
        assert!(text.contains(part), "no {part} in the PDF");
    }
    assert!(!text.contains("/Subtype /Image"), "the PDF holds an image");
    // The page: 88.9 mm = 252 pt wide.
    let media = text
        .split("/MediaBox [")
        .nth(1)
        .and_then(|rest| rest.split(']').next())
        .expect("a media box");
    let corners: Vec<f64> = media
        .split_whitespace()
        .filter_map(|v| v.parse().ok())
        .collect();
    assert!((corners[2] - 252.0).abs() < 0.3, "a page {media} pt");
    // The page's content shows text: BT … Tj/TJ … ET, in its (deflated) streams.
    let shown = streams(&pdf).iter().any(|content| {
        let content = String::from_utf8_lossy(content);
        content.contains("BT") && (content.contains("Tj") || content.contains("TJ"))
    });
    assert!(shown, "no text operators in the PDF's content");
}

/// One figure gives one PDF, byte for byte: svg2pdf writes a resources dictionary in a
/// `HashMap`'s order, random in every map, which the figure's writer puts in order (a
/// figure with several resources of a kind came out differently from one conversion to
/// the next before).
#[test]
fn the_pdf_of_a_figure_is_the_same_every_time() {
    register();
    let values: Vec<f64> = (0..300).map(|i| (f64::from(i) * 0.37).sin()).collect();
    let figure = sample_figure().panel(
        Panel::new("Touchdowns", "sink rate (m/s)", "runs")
            .histogram("O-PD", values.clone(), 12)
            .histogram("PID", values.iter().map(|v| v * 0.8).collect(), 12),
    );
    let render = || {
        figure
            .clone()
            .render_files(&options(88.9, 8.0, 300))
            .expect("renders")
            .pdf
            .expect("asked for")
    };
    let first = render();
    let text = String::from_utf8_lossy(&first);
    let entries = text
        .lines()
        .filter(|l| {
            let l = l.trim_start();
            (l.starts_with("/xo") || l.starts_with("/gs")) && l.ends_with(" 0 R")
        })
        .count();
    assert!(
        entries >= 3,
        "the sample has {entries} resource entries: too few to test order"
    );
    for _ in 0..8 {
        assert!(render() == first, "two conversions of one figure differ");
    }
}

/// The inflated content of the PDF's Flate streams.
fn streams(pdf: &[u8]) -> Vec<Vec<u8>> {
    let mut out = Vec::new();
    let mut rest = pdf;
    while let Some(start) = find(rest, b"stream\n").or_else(|| find(rest, b"stream\r\n")) {
        let body = &rest[start..];
        let body = body
            .strip_prefix(b"stream\r\n")
            .or_else(|| body.strip_prefix(b"stream\n"))
            .unwrap_or(body);
        let Some(end) = find(body, b"endstream") else {
            break;
        };
        if let Ok(inflated) = miniz_oxide::inflate::decompress_to_vec_zlib(&body[..end]) {
            out.push(inflated);
        }
        rest = &body[end..];
    }
    out
}

fn find(haystack: &[u8], needle: &[u8]) -> Option<usize> {
    haystack.windows(needle.len()).position(|w| w == needle)
}

/// A narrow figure's long title and axis labels are wrapped, not set smaller, and its
/// legend goes under the axes rather than into a column that would squeeze them.
#[test]
fn a_one_column_figure_wraps_its_labels_and_keeps_its_text_size() {
    register();
    let svg = sample_figure()
        .render_svg_with(&FigureOptions::default())
        .expect("renders");
    let title = "Final approach — O-PD, adverse, seed 1: trap on wire 3";
    let texts: Vec<String> = svg_elements(&svg, "text")
        .into_iter()
        .filter_map(|e| e.split_once('>').map(|(_, inner)| inner.trim().to_owned()))
        .collect();
    assert!(
        !texts.iter().any(|t| t == title),
        "the title is on one line"
    );
    let joined = texts.join(" ");
    assert!(
        joined.contains(title),
        "the title's lines make the title: {texts:?}"
    );
}
