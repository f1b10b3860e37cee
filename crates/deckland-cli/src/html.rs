//! `report.html`: one self-contained page per run folder, to open offline and share as
//! one file. It holds headings, paragraphs, tables, the plots inline as SVG and verbatim
//! text (the scenario flown); no scripts and no external address. The plots' text and the
//! page's use the bundled font, embedded as a `data:` URI, so the page renders the same on
//! a machine without fonts.
//!
//! Every value reaches the page through [`number`] or [`Report`]'s escaping: a non-finite
//! number is written "—", never "NaN" or "inf".

use std::fmt::Write as _;

use crate::plot::FONT_BYTES;

/// The family name the embedded font gets in the page's style sheet.
const EMBEDDED_FAMILY: &str = "deckland-sans";

/// `value` with `decimals` decimals, "—" when it is not finite.
pub fn number(value: f64, decimals: usize) -> String {
    if value.is_finite() {
        format!("{value:.decimals$}")
    } else {
        "—".to_string()
    }
}

/// `value` with its sign and `decimals` decimals, "—" when it is not finite.
pub fn signed_number(value: f64, decimals: usize) -> String {
    if value.is_finite() {
        format!("{value:+.decimals$}")
    } else {
        "—".to_string()
    }
}

/// `value` as in [`number`], or "—" when absent.
pub fn optional(value: Option<f64>, decimals: usize) -> String {
    value.map_or_else(|| "—".to_string(), |v| number(v, decimals))
}

/// Escapes text for HTML.
pub fn escape(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            _ => out.push(c),
        }
    }
    out
}

/// Escapes text and renders the two inline marks the reports use: `**bold**` and
/// `` `code` ``.
pub fn inline_markdown(text: &str) -> String {
    let escaped = escape(text);
    let mut out = String::with_capacity(escaped.len());
    let mut bold = false;
    let mut code = false;
    let mut rest = escaped.as_str();
    while let Some(c) = rest.chars().next() {
        if !code && rest.starts_with("**") {
            out.push_str(if bold { "</strong>" } else { "<strong>" });
            bold = !bold;
            rest = &rest[2..];
        } else if c == '`' {
            out.push_str(if code { "</code>" } else { "<code>" });
            code = !code;
            rest = &rest[1..];
        } else {
            out.push(c);
            rest = &rest[c.len_utf8()..];
        }
    }
    if code {
        out.push_str("</code>");
    }
    if bold {
        out.push_str("</strong>");
    }
    out
}

/// Standard base64 (RFC 4648) of `bytes`.
fn base64(bytes: &[u8]) -> String {
    const ALPHABET: &[u8; 64] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    let mut out = String::with_capacity(bytes.len().div_ceil(3) * 4);
    for chunk in bytes.chunks(3) {
        let b = [
            chunk[0],
            chunk.get(1).copied().unwrap_or(0),
            chunk.get(2).copied().unwrap_or(0),
        ];
        let n = (u32::from(b[0]) << 16) | (u32::from(b[1]) << 8) | u32::from(b[2]);
        for i in 0..4 {
            if i <= chunk.len() {
                out.push(char::from(ALPHABET[((n >> (18 - 6 * i)) & 63) as usize]));
            } else {
                out.push('=');
            }
        }
    }
    out
}

/// One piece of a section.
#[derive(Debug, Clone)]
enum Block {
    /// A paragraph of text (inline marks rendered).
    Paragraph(String),
    /// A table: header cells and rows of cells (inline marks rendered).
    Table {
        header: Vec<String>,
        rows: Vec<Vec<String>>,
    },
    /// A plot: its SVG document and caption.
    Figure { svg: String, caption: String },
    /// Verbatim text, such as a TOML or JSON file.
    Verbatim { name: String, text: String },
    /// HTML the caller built and escaped (a coloured table).
    Html(String),
}

/// A section: a heading and its blocks.
#[derive(Debug, Clone)]
pub struct Section {
    heading: String,
    blocks: Vec<Block>,
}

impl Section {
    /// Adds a paragraph (`**bold**` and `` `code` `` are rendered).
    pub fn paragraph(&mut self, text: impl Into<String>) -> &mut Self {
        self.blocks.push(Block::Paragraph(text.into()));
        self
    }

    /// Adds a table.
    pub fn table(&mut self, header: &[&str], rows: Vec<Vec<String>>) -> &mut Self {
        self.blocks.push(Block::Table {
            header: header.iter().map(|h| (*h).to_string()).collect(),
            rows,
        });
        self
    }

    /// Adds a plot from its SVG document.
    pub fn figure(&mut self, svg: &str, caption: impl Into<String>) -> &mut Self {
        self.blocks.push(Block::Figure {
            svg: svg.to_string(),
            caption: caption.into(),
        });
        self
    }

    /// Adds HTML as it is: the caller escapes any text in it.
    pub fn html(&mut self, html: impl Into<String>) -> &mut Self {
        self.blocks.push(Block::Html(html.into()));
        self
    }

    /// Adds a file's text, shown verbatim under its name.
    pub fn verbatim(&mut self, name: impl Into<String>, text: impl Into<String>) -> &mut Self {
        self.blocks.push(Block::Verbatim {
            name: name.into(),
            text: text.into(),
        });
        self
    }
}

/// The page's body text size (pt): the browser's default 16 px.
const BODY_TEXT_PT: f64 = 12.0;

/// How wide a figure is shown on the page (mm): its printed width scaled so that its
/// small text (`--font-pt` when printed) is the page's body text — a one-column figure
/// (88.9 mm, 8 pt) 133 mm wide, not stretched over the page with its text three times
/// the body's (the page is at most 1100 px, and a figure never wider than it).
fn figure_width_on_page_mm(options: crate::plot::options::FigureOptions) -> f64 {
    options.width_mm * BODY_TEXT_PT / options.font_pt
}

/// A self-contained HTML report.
#[derive(Debug, Clone)]
pub struct Report {
    title: String,
    sections: Vec<Section>,
}

/// The page's style sheet, without the embedded font.
const STYLE: &str = "
body { font-family: deckland-sans, sans-serif; margin: 2em auto; max-width: 1100px;
       padding: 0 1em; color: #222; line-height: 1.4; }
h1 { font-size: 1.6em; } h2 { font-size: 1.3em; margin-top: 1.6em;
       border-bottom: 1px solid #ccc; }
table { border-collapse: collapse; margin: 0.6em 0; font-size: 0.92em; }
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; text-align: left;
         vertical-align: top; }
th { background: #f2f2f2; }
td.number { text-align: right; font-variant-numeric: tabular-nums; }
figure { margin: 1em 0; }
figure svg { max-width: 100%; height: auto; border: 1px solid #eee; }
figure svg text { font-family: deckland-sans, sans-serif; }
figcaption { font-size: 0.92em; color: #444; }
pre { background: #f7f7f7; border: 1px solid #ddd; padding: 0.6em; overflow-x: auto;
      font-size: 0.85em; }
code { background: #f2f2f2; padding: 0 0.2em; }
";

/// Whether a table cell holds a number (right-aligned).
fn is_numeric(cell: &str) -> bool {
    let trimmed = cell.trim_start_matches(['+', '-', '−']);
    trimmed.chars().next().is_some_and(|c| c.is_ascii_digit())
        && trimmed
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | ' ' | '%' | '/'))
}

/// The SVG element of a plotters document, without an XML prologue.
fn svg_element(svg: &str) -> &str {
    svg.find("<svg").map_or(svg, |start| &svg[start..])
}

impl Report {
    /// An empty report with a title.
    pub fn new(title: impl Into<String>) -> Self {
        Self {
            title: title.into(),
            sections: Vec::new(),
        }
    }

    /// Adds a section and returns it to fill.
    pub fn section(&mut self, heading: impl Into<String>) -> &mut Section {
        self.sections.push(Section {
            heading: heading.into(),
            blocks: Vec::new(),
        });
        let last = self.sections.len() - 1;
        &mut self.sections[last]
    }

    /// The page.
    pub fn to_html(&self) -> String {
        let mut out = String::new();
        let _ = write!(
            out,
            "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n\
             <meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n\
             <title>{}</title>\n<style>\n@font-face {{ font-family: {EMBEDDED_FAMILY}; \
             src: url(data:font/ttf;base64,{}) format(\"truetype\"); }}\n{STYLE}</style>\n\
             </head>\n<body>\n<h1>{}</h1>\n",
            escape(&self.title),
            base64(FONT_BYTES),
            escape(&self.title)
        );
        for section in &self.sections {
            let _ = writeln!(out, "<h2>{}</h2>", escape(&section.heading));
            for block in &section.blocks {
                match block {
                    Block::Paragraph(text) => {
                        let _ = writeln!(out, "<p>{}</p>", inline_markdown(text));
                    }
                    Block::Table { header, rows } => {
                        out.push_str("<table>\n<thead><tr>");
                        for cell in header {
                            let _ = write!(out, "<th>{}</th>", inline_markdown(cell));
                        }
                        out.push_str("</tr></thead>\n<tbody>\n");
                        for row in rows {
                            out.push_str("<tr>");
                            for cell in row {
                                let class = if is_numeric(cell) {
                                    " class=\"number\""
                                } else {
                                    ""
                                };
                                let _ = write!(out, "<td{class}>{}</td>", inline_markdown(cell));
                            }
                            out.push_str("</tr>\n");
                        }
                        out.push_str("</tbody>\n</table>\n");
                    }
                    Block::Figure { svg, caption } => {
                        let _ = writeln!(
                            out,
                            "<figure style=\"width: {:.1}mm; max-width: 100%\">\n{}\n\
                             <figcaption>{}</figcaption>\n</figure>",
                            figure_width_on_page_mm(crate::plot::options::current()),
                            svg_element(svg).trim_end(),
                            inline_markdown(caption)
                        );
                    }
                    Block::Html(html) => out.push_str(html),
                    Block::Verbatim { name, text } => {
                        let _ = writeln!(
                            out,
                            "<p><strong>{}</strong></p>\n<pre>{}</pre>",
                            escape(name),
                            escape(text)
                        );
                    }
                }
            }
        }
        out.push_str("</body>\n</html>\n");
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn base64_matches_rfc_4648_examples() {
        for (input, expected) in [
            ("", ""),
            ("f", "Zg=="),
            ("fo", "Zm8="),
            ("foo", "Zm9v"),
            ("foob", "Zm9vYg=="),
            ("fooba", "Zm9vYmE="),
            ("foobar", "Zm9vYmFy"),
        ] {
            assert_eq!(base64(input.as_bytes()), expected, "{input}");
        }
    }

    #[test]
    fn text_is_escaped_and_marks_rendered() {
        assert_eq!(
            inline_markdown("**large**: a < b & `x|y`"),
            "<strong>large</strong>: a &lt; b &amp; <code>x|y</code>"
        );
        assert_eq!(escape("\"<svg>\""), "&quot;&lt;svg&gt;&quot;");
    }

    #[test]
    fn non_finite_numbers_never_reach_the_page() {
        assert_eq!(number(f64::NAN, 2), "—");
        assert_eq!(signed_number(f64::INFINITY, 1), "—");
        assert_eq!(optional(None, 1), "—");
        assert_eq!(number(1.234, 2), "1.23");
        assert_eq!(signed_number(-1.25, 1), "-1.2");
    }

    /// A figure is shown with its small text at the page's body size, 12 pt (16 px): a
    /// one-column figure with 8 pt text 1.5 times its printed width, 88.9 × 1.5 =
    /// 133.35 mm (504 px), not the page's 1100 px, where its text was 26 pt.
    #[test]
    fn a_figure_is_shown_with_its_text_at_the_body_size() {
        use crate::plot::options::FigureOptions;
        let one_column = FigureOptions::default();
        assert!((figure_width_on_page_mm(one_column) - 133.35).abs() < 1e-9);
        let two_columns_at_9pt = FigureOptions {
            width_mm: 182.0,
            font_pt: 9.0,
            ..one_column
        };
        assert!((figure_width_on_page_mm(two_columns_at_9pt) - 242.666_666).abs() < 1e-3);
    }

    #[test]
    fn a_report_is_one_page_without_external_resources() {
        let mut report = Report::new("Run <1>");
        report
            .section("Summary")
            .paragraph("every number from **this** run")
            .table(
                &["quantity", "value"],
                vec![vec!["sink rate".into(), "3.92".into()]],
            )
            .figure(
                "<?xml version=\"1.0\"?>\n<svg width=\"10\" height=\"10\"></svg>",
                "a plot",
            )
            .verbatim("scenario.toml", "seed = 1\n[a]\nb = \"<c>\"\n");
        let html = report.to_html();
        assert!(html.starts_with("<!DOCTYPE html>"));
        assert!(html.contains("<h1>Run &lt;1&gt;</h1>"));
        assert!(html.contains("<td class=\"number\">3.92</td>"));
        assert!(html.contains("mm; max-width: 100%\">\n<svg width=\"10\""));
        assert!(!html.contains("<?xml"));
        assert!(html.contains("b = &quot;&lt;c&gt;&quot;"));
        assert!(html.contains("url(data:font/ttf;base64,"));
        for external in ["http:", "https:", "<script", "<link", "src=\""] {
            assert!(!html.contains(external), "{external}");
        }
    }
}
