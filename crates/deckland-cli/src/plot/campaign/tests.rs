//! Tests of the campaign's figures, read back from their SVG (issue 46, 1 and 4).

use deckland::environment::DeckGeometry;

use super::touchdowns::Touchdown;
use super::*;
use crate::plot::palette;
use crate::plot::tests::{attribute, hex, number, register, svg_elements, svg_text};

fn run<'a>(controller: &'a str, outcome: &'a str, point: Option<(f64, f64)>) -> Touchdown<'a> {
    Touchdown {
        controller,
        outcome,
        point,
    }
}

/// The dispersion figure of `runs` as SVG.
fn dispersion_svg(labels: &[&str], runs: &[Touchdown]) -> String {
    register();
    let panel = dispersion(labels, runs, &DeckGeometry::default(), 7.6);
    Figure::new().panel(panel).render_svg().expect("renders")
}

/// The corners of a `polygon` or `polyline` element.
fn corners(element: &str) -> Vec<(f64, f64)> {
    attribute(element, "points")
        .unwrap_or_default()
        .split_whitespace()
        .filter_map(|pair| {
            let (x, y) = pair.split_once(',')?;
            Some((x.parse().ok()?, y.parse().ok()?))
        })
        .collect()
}

/// The legend names each outcome that has a point, with its count, and no other; the
/// runs without a touchdown are counted in a note.
#[test]
fn the_dispersion_legend_names_each_outcome_present() {
    let runs = [
        run("O-PD", "trap", Some((0.0, 3.0))),
        run("O-PD", "trap", Some((5.0, 3.5))),
        run("O-PD", "bolter", Some((19.0, 2.5))),
        run("O-PD", "bolter", None),
        run("O-PD", "hard_landing", Some((-2.0, 8.1))),
        run("O-PD", "ramp_strike", None),
    ];
    let text = svg_text(&dispersion_svg(&["O-PD"], &runs));
    for entry in [
        "O-PD (4 touchdowns)",
        "trap (2)",
        "bolter (1)",
        "hard landing (1)",
    ] {
        assert!(text.contains(entry), "{entry} missing: {text}");
    }
    assert!(!text.contains("wave-off") && !text.contains("ramp strike ("));
    assert!(
        text.contains("not drawn, no touchdown: 1 bolter, 1 ramp strike"),
        "{text}"
    );
}

/// Each outcome is drawn with its own shape in the controller's colour: traps as
/// circles, bolters as triangles, hard landings as squares, ramp strikes as diamonds.
#[test]
fn each_outcome_has_its_own_marker_shape() {
    let runs = [
        run("O-PD", "trap", Some((0.0, 3.0))),
        run("O-PD", "bolter", Some((19.0, 2.5))),
        run("O-PD", "hard_landing", Some((-2.0, 8.1))),
        run("O-PD", "ramp_strike", Some((-10.0, 6.0))),
    ];
    let svg = dispersion_svg(&["O-PD"], &runs);
    let fill = format!("fill=\"{}\"", hex(palette(0)));
    let polygons: Vec<Vec<(f64, f64)>> = svg_elements(&svg, "polygon")
        .into_iter()
        .filter(|e| e.contains(&fill))
        .map(corners)
        .collect();
    let circles = svg_elements(&svg, "circle")
        .into_iter()
        .filter(|e| e.contains(&fill))
        .count();
    // The trap's circle and the legend's controller entry.
    assert_eq!(circles, 2, "{svg}");
    let triangles = polygons.iter().filter(|p| p.len() == 3).count();
    let squares = polygons
        .iter()
        .filter(|p| p.len() == 4 && p[0].1 == p[1].1)
        .count();
    let diamonds = polygons
        .iter()
        .filter(|p| p.len() == 4 && p[0].0 == p[2].0)
        .count();
    assert_eq!((triangles, squares, diamonds), (1, 1, 1), "{polygons:?}");
}

/// With `--compare`, the controllers' points differ in fill, not only in colour: the
/// first's filled and translucent, the second's hollow and drawn after them, so that at
/// the same touchdown both show.
#[test]
fn paired_controllers_are_filled_and_hollow_and_neither_hides_the_other() {
    let points = [(0.0, 3.0), (4.0, 3.4), (-6.0, 2.2)];
    let runs: Vec<Touchdown> = ["O-PD", "PID"]
        .iter()
        .flat_map(|c| points.iter().map(move |p| run(c, "trap", Some(*p))))
        .collect();
    let svg = dispersion_svg(&["O-PD", "PID"], &runs);
    let circles = svg_elements(&svg, "circle");
    let (first, second) = (hex(palette(0)), hex(palette(1)));
    let position = |colour: &str, filled: bool| -> Vec<(usize, f64, f64)> {
        circles
            .iter()
            .enumerate()
            .filter(|(_, e)| match filled {
                true => attribute(e, "fill") == Some(colour),
                false => {
                    attribute(e, "fill") == Some("none") && attribute(e, "stroke") == Some(colour)
                }
            })
            .filter_map(|(i, e)| Some((i, number(e, "cx")?, number(e, "cy")?)))
            .collect()
    };
    let filled = position(&first, true);
    let hollow = position(&second, false);
    assert!(
        position(&second, true).is_empty(),
        "the second controller is hollow"
    );
    assert!(
        position(&first, false).is_empty(),
        "the first controller is filled"
    );
    // Three points each, and the legend's entry each.
    assert_eq!((filled.len(), hollow.len()), (4, 4), "{svg}");
    for (index, x, y) in &filled[..3] {
        let over = hollow
            .iter()
            .find(|(_, hx, hy)| hx == x && hy == y)
            .expect("the same touchdown");
        assert!(
            over.0 > *index,
            "the hollow marker is drawn over the filled one"
        );
    }
    let opacity = circles
        .iter()
        .find(|e| attribute(e, "fill") == Some(first.as_str()))
        .and_then(|e| number(e, "opacity"))
        .unwrap_or(1.0);
    assert!(opacity < 1.0, "the filled markers are translucent");
}

/// The outcomes chart of a campaign draws no bar for a zero count and a readable one for
/// a count of 1 in 10 000.
#[test]
fn the_outcomes_chart_has_a_log_axis_and_no_bar_for_a_zero_count() {
    register();
    let mut values = vec![0.0; 8];
    let mut intervals = vec![(0.0, 0.038); 8];
    let mut labels = vec!["0".to_owned(); 8];
    (values[0], intervals[0], labels[0]) = (99.98, (99.95, 99.99), "9998".into());
    (values[3], intervals[3], labels[3]) = (0.01, (0.0018, 0.057), "1".into());
    (values[4], intervals[4], labels[4]) = (0.01, (0.0018, 0.057), "1".into());
    let group = BarGroup {
        name: "O-PD (10000 runs)".into(),
        values,
        intervals,
        labels,
    };
    let svg = Figure::new()
        .panel(outcomes(vec![group]))
        .render_svg()
        .expect("renders");
    let fill = format!("fill=\"{}\"", hex(palette(0)));
    let mut heights: Vec<f64> = svg_elements(&svg, "rect")
        .into_iter()
        .filter(|e| e.contains(&fill))
        .filter_map(|e| number(e, "height"))
        .collect();
    // Three bars and the legend's patch (12 px).
    assert_eq!(heights.len(), 4, "{heights:?}");
    heights.sort_by(f64::total_cmp);
    assert!(heights[1] >= 20.0, "1 in 10 000 is {} px tall", heights[1]);
}
