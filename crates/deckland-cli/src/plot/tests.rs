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
fn jagged_lines_are_recognised() {
    let smooth: Vec<(i32, i32)> = (0..100).map(|i| (i, i / 3)).collect();
    let jagged: Vec<(i32, i32)> = (0..100).map(|i| (i / 5, (i % 2) * 3)).collect();
    assert!(!is_jagged(&smooth));
    assert!(is_jagged(&jagged));
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
