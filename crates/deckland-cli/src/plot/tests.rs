//! Unit tests of the plotting code.

use super::figure::*;
use super::panel::*;
use super::style::*;
use super::*;

/// Registers the bundled font (for tests that measure text).
pub(crate) fn register() {
    register_bundled_font().expect("the bundled font registers");
}

#[test]
fn bundled_font_registers() {
    assert!(register_bundled_font().is_ok());
}

#[test]
fn ranges_are_padded_and_never_empty() {
    let flat = Panel::new("t", "x", "y").series("a", vec![(0.0, 2.0), (1.0, 2.0)]);
    let (x, y) = flat.ranges();
    assert_eq!(x, 0.0..1.0);
    assert!(y.start < 2.0 && y.end > 2.0);
    let empty = Panel::new("t", "x", "y");
    assert_eq!(empty.ranges().0, -1.0..1.0);
}

#[test]
fn histogram_bins_share_the_range_and_count_every_value() {
    let panel = Panel::new("t", "x", "count")
        .histogram("a", vec![0.0, 1.0, 2.0, 3.0], 3)
        .histogram("b", vec![3.0, 3.0, f64::NAN], 3);
    let bins = panel.bins().expect("values");
    assert_eq!(bins, (0.0, 1.0, 3));
    assert_eq!(Panel::bin_counts(&[0.0, 1.0, 2.0, 3.0], bins), [1, 1, 2]);
    assert_eq!(Panel::bin_counts(&[3.0, 3.0, f64::NAN], bins), [0, 0, 2]);
    let (x, y) = panel.ranges();
    assert_eq!(x, 0.0..3.0);
    assert!(
        y.start == 0.0 && y.end > 2.0,
        "a count axis starts at zero: {y:?}"
    );
}

#[test]
fn scatter_histogram_and_bar_panels_render() {
    let figure = Figure::new()
        .panel(
            Panel::new("Scatter", "distance (m)", "sink rate (m/s)")
                .scatter("runs", vec![(-3.0, 3.5), (2.0, 4.0), (f64::NAN, 1.0)])
                .vertical_line("wire 1", -18.0)
                .reference_line("limit", 7.6),
        )
        .panel(
            Panel::new("Histogram", "sink rate (m/s)", "runs").histogram(
                "O-PD",
                vec![3.0, 3.5, 4.0, 4.2],
                5,
            ),
        )
        .panel(
            Panel::new("Outcomes", "outcome", "runs")
                .categories(vec!["trap".into(), "bolter".into()])
                .bar_group(BarGroup {
                    name: "O-PD".into(),
                    values: vec![90.0, 10.0],
                    intervals: vec![(80.0, 95.0), (5.0, 20.0)],
                    labels: vec!["9".into(), "1".into()],
                })
                .bar_group(BarGroup {
                    name: "PID".into(),
                    values: vec![70.0, 30.0],
                    ..BarGroup::default()
                })
                .interval_name("95 % interval"),
        );
    let svg = figure.render_svg().expect("renders");
    for text in ["wire 1", "Histogram", "trap", "bolter", "PID"] {
        assert!(svg.contains(text), "{text}");
    }
}

#[test]
fn nothing_non_finite_reaches_the_svg() {
    let figure = Figure::new()
        .panel(
            Panel::new("Lines", "time (s)", "value (m)")
                .series("a", vec![(0.0, f64::NAN), (1.0, f64::INFINITY), (2.0, 1.0)])
                .dashed_series("b", vec![(f64::NAN, 0.0)])
                .reference_line("limit", f64::NAN)
                .vertical_line("wire", f64::INFINITY)
                .marker("touchdown", (f64::NAN, 1.0), MarkerShape::Circle)
                .note("nothing finite here"),
        )
        .panel(Panel::new("Histogram", "x (m)", "runs").histogram(
            "h",
            vec![f64::NAN, f64::NEG_INFINITY],
            5,
        ))
        .panel(
            Panel::new("Bars", "outcome", "share (%)")
                .categories(vec!["trap".into()])
                .bar_group(BarGroup {
                    name: "O-PD".into(),
                    values: vec![f64::NAN],
                    intervals: vec![(f64::NAN, f64::INFINITY)],
                    labels: Vec::new(),
                }),
        );
    let svg = figure.render_svg().expect("renders");
    for word in ["NaN", "inf", "Infinity"] {
        assert!(
            !svg.split(|c: char| !c.is_ascii_alphanumeric())
                .any(|w| w == word),
            "{word} in the SVG"
        );
    }
}

#[test]
fn svg_text_names_only_the_generic_font_family() {
    let svg = Figure::new()
        .title("t")
        .panel(Panel::new("p", "x (s)", "y (m)").series("a", vec![(0.0, 0.0), (1.0, 1.0)]))
        .render_svg()
        .expect("renders");
    let families: Vec<&str> = svg
        .split("font-family=\"")
        .skip(1)
        .filter_map(|rest| rest.split('"').next())
        .collect();
    assert!(!families.is_empty());
    assert!(families.iter().all(|f| *f == FONT_FAMILY), "{families:?}");
    assert!(!svg.contains("url(") && !svg.contains("@font-face"));
}

#[test]
fn figure_renders_to_svg_with_its_text() {
    let figure = Figure::new()
        .title("Two panels")
        .panel(
            Panel::new("Upper", "time (s)", "height (m)")
                .series(
                    "sine",
                    (0..100)
                        .map(|i| (f64::from(i) * 0.1, (f64::from(i) * 0.1).sin()))
                        .collect(),
                )
                .reference_line("zero", 0.0),
        )
        .panel(
            Panel::new("Lower", "time (s)", "speed (m/s)")
                .series("line", vec![(0.0, 0.0), (1.0, 1.0)]),
        );
    let svg = figure.render_svg().expect("renders");
    assert!(
        svg.contains("Two panels") && svg.contains("height (m)") && svg.contains("speed (m/s)")
    );
}

#[test]
fn a_panel_sharing_a_legend_needs_no_legend_column() {
    // (A legend is drawn from two entries on.) A panel full of data has no free place for its legend: alone, the figure needs a
    // column beside the axes; when it shares the legend of the panel above, it needs none.
    let full: Vec<(f64, f64)> = (0..10_000)
        .map(|i| (f64::from(i % 200), f64::from(i / 200)))
        .collect();
    let (left, right): (Vec<_>, Vec<_>) = full.iter().partition(|(x, _)| *x < 100.0);
    let crowded = || {
        Panel::new("t", "x", "y")
            .scatter("left", left.clone())
            .scatter("right", right.clone())
    };
    let open = Panel::new("t", "x", "y")
        .series("rising", vec![(0.0, 0.0), (199.0, 1.0)])
        .series("falling", vec![(0.0, 1.0), (199.0, 0.9)]);
    let alone = Figure::new().panel(open.clone()).panel(crowded());
    assert!(alone.legend_column().unwrap() > 0);
    let shared = Figure::new().panel(open).panel(crowded().shared_legend());
    assert_eq!(shared.legend_column().unwrap(), 0);
}

/// The SVG elements `<tag …>` of `svg`, each up to its next `<`.
pub(crate) fn svg_elements<'a>(svg: &'a str, tag: &str) -> Vec<&'a str> {
    svg.split('<')
        .filter(|e| {
            e.strip_prefix(tag)
                .is_some_and(|rest| rest.starts_with(' '))
        })
        .collect()
}

/// The value of the attribute `name` of an SVG element.
pub(crate) fn attribute<'a>(element: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let rest = &element[element.find(&key)? + key.len()..];
    Some(&rest[..rest.find('"')?])
}

/// The value of the numeric attribute `name` of an SVG element.
pub(crate) fn number(element: &str, name: &str) -> Option<f64> {
    attribute(element, name)?.parse().ok()
}

/// The SVG colour of `colour` ("#0072B2").
pub(crate) fn hex(colour: plotters::style::RGBColor) -> String {
    format!("#{:02X}{:02X}{:02X}", colour.0, colour.1, colour.2)
}

/// Every text of `svg` in document order, joined by spaces (a wrapped note reads whole).
pub(crate) fn svg_text(svg: &str) -> String {
    svg_elements(svg, "text")
        .iter()
        .filter_map(|e| e.split_once('>').map(|(_, text)| text.trim()))
        .collect::<Vec<_>>()
        .join(" ")
}

/// The x of the text element that reads `text`.
pub(crate) fn text_x(svg: &str, text: &str) -> Option<f64> {
    svg_elements(svg, "text")
        .into_iter()
        .find(|e| e.split_once('>').is_some_and(|(_, t)| t.trim() == text))
        .and_then(|e| number(e, "x"))
}

/// A series over 25 s between −3.9 and 3.5 (a hook's offset, m).
fn offsets() -> Vec<(f64, f64)> {
    (0..=100)
        .map(|i| f64::from(i) * 0.25)
        .map(|t| (t, 3.7 * (0.5 * t).sin() - 0.2))
        .collect()
}

/// Issue 46, 5: a limit far beyond the data is named in a note and left off the axis,
/// which spans the data; a limit near the data is drawn.
#[test]
fn a_limit_far_from_the_data_is_a_note_and_the_axis_spans_the_data() {
    register();
    let far = Panel::new("t", "time (s)", "offset (m)")
        .series("offset", offsets())
        .reference_line("centreline", 0.0)
        .limit_line("limit ±6.1 m", 6.1)
        .limit_line("limit ±6.1 m", -6.1);
    let (_, y) = far.ranges();
    assert!(
        y.start > -4.6 && y.end < 4.2,
        "the axis spans the data: {y:?}"
    );
    let svg = Figure::new().panel(far).render_svg().expect("renders");
    let text = svg_text(&svg);
    assert!(
        text.contains("limit ±6.1 m: above and below the axis"),
        "{text}"
    );
    let limit_colour = hex(REFERENCE_STYLES[1].0);
    assert!(
        !svg.contains(&limit_colour),
        "a limit off the axis is drawn"
    );
    let near = Panel::new("t", "time (s)", "offset (m)")
        .series("offset", offsets())
        .limit_line("limit 4 m", 4.0);
    let (_, y) = near.ranges();
    assert!(y.end > 4.0, "a limit near the data widens the axis: {y:?}");
    let svg = Figure::new().panel(near).render_svg().expect("renders");
    assert!(!svg_text(&svg).contains("the axis"));
}

/// Issue 46, 5: when one panel's legend needs the column beside the axes, every panel's
/// legend goes there, so that no panel stands beside an empty third of the figure.
#[test]
fn a_legend_column_holds_every_panels_legend() {
    register();
    let full: Vec<(f64, f64)> = (0..10_000)
        .map(|i| (f64::from(i % 200), f64::from(i / 200)))
        .collect();
    let (left, right): (Vec<_>, Vec<_>) = full.iter().partition(|(x, _)| *x < 100.0);
    let figure = Figure::new()
        .panel(
            Panel::new("open", "x", "y")
                .series("rising", vec![(0.0, 0.0), (199.0, 1.0)])
                .series("falling", vec![(0.0, 1.0), (199.0, 0.9)]),
        )
        .panel(
            Panel::new("crowded", "x", "y")
                .scatter("left", left)
                .scatter("right", right),
        );
    let column = figure.legend_column().expect("lays out");
    assert!(column > 0);
    let svg = figure.render_svg().expect("renders");
    let open = text_x(&svg, "rising").expect("the open panel's legend");
    let crowded = text_x(&svg, "left").expect("the crowded panel's legend");
    assert!(
        open > f64::from(1000 - column),
        "{open} px: inside the axes"
    );
    assert_eq!(open, crowded, "both legends in the column");
}

/// Issue 46, 3: a zero draws no bar (only its label), and on a log axis a share of 1 in
/// 10 000 is a bar as readable as the others, read back from the SVG's rectangles.
#[test]
fn a_zero_draws_no_bar_and_a_log_axis_shows_one_in_ten_thousand() {
    register();
    let colour = hex(palette(0));
    let bars = |panel: Panel| {
        let svg = Figure::new().panel(panel).render_svg().expect("renders");
        let fill = format!("fill=\"{colour}\"");
        let rects: Vec<f64> = svg_elements(&svg, "rect")
            .into_iter()
            .filter(|e| e.contains(&fill))
            .filter_map(|e| number(e, "height"))
            .collect();
        (rects, svg)
    };
    let chart = || {
        Panel::new("Outcomes", "outcome", "share (%)")
            .categories(vec!["trap".into(), "bolter".into(), "ramp strike".into()])
            .bar_group(BarGroup {
                name: "O-PD".into(),
                values: vec![99.99, 0.0, 0.01],
                intervals: vec![(99.94, 100.0), (0.0, 0.04), (0.0018, 0.057)],
                labels: vec!["9999".into(), "0".into(), "1".into()],
            })
            .interval_name("95 % interval")
    };
    for panel in [chart(), chart().log_y()] {
        let (heights, svg) = bars(panel);
        // The trap's bar, the ramp strike's and the legend's patch: none for the bolter
        // (on the linear axis the ramp strike's is less than a pixel tall).
        assert_eq!(heights.len(), 3, "{heights:?}");
        assert!(
            svg_text(&svg).split(' ').any(|word| word == "0"),
            "the zero's label"
        );
    }
    // The second tallest is the ramp strike's bar on a log axis (the legend's patch is
    // 12 px); on the linear axis it is the patch, the bar a fraction of a pixel.
    for (panel, readable) in [(chart(), false), (chart().log_y(), true)] {
        let (mut heights, _) = bars(panel);
        heights.sort_by(|a, b| b.total_cmp(a));
        assert_eq!(heights[1] >= 20.0, readable, "{heights:?}");
    }
}
