//! `wind`: the total wind at the aircraft in earth axes: along and across the approach
//! (the lateral component only on the 3-D approach) and vertical.

use deckland::simulation::{SignalId, Signals};

use deckland::scenario::Scenario;

use super::{mark_wake_onset, series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The total wind at the aircraft in earth axes: x and z, and y on the 3-D approach
/// (whose plant records it).
pub(super) fn figure(samples: &[Signals], scenario: &Scenario, title: &str) -> Figure {
    let mut panel = Panel::new(
        "Total wind in earth axes (mean, turbulence and air wake)",
        TIME,
        "wind (m/s)",
    )
    .series(
        "x (positive forward; headwind negative)",
        series(samples, SignalId::WindX, Shown::AsRegistered),
    )
    .series(
        "z (positive down)",
        series(samples, SignalId::WindZ, Shown::AsRegistered),
    );
    // After x and z, so that they keep their colours in the figures of both approaches.
    let lateral = series(samples, SignalId::WindY, Shown::AsRegistered);
    if !lateral.is_empty() {
        panel = panel.series("y (positive right: wind from the left)", lateral);
    }
    Figure::new()
        .title(format!("Wind at the aircraft — {title}"))
        .panel(mark_wake_onset(panel, samples, scenario))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::plot::palette;
    use crate::plot::tests::{hex, register, svg_elements, svg_text};

    /// Samples over 10 s with the wind along x and z, and, on the 3-D approach, across.
    fn samples(lateral: bool) -> Vec<Signals> {
        (0..=100)
            .map(|i| {
                let mut s = Signals {
                    time_s: f64::from(i) * 0.1,
                    ..Signals::default()
                };
                s.wind.x_mps = -2.0;
                s.wind.z_mps = 0.5;
                s.lateral.wind_y_mps = lateral.then_some(5.0 + 0.01 * f64::from(i));
                s
            })
            .collect()
    }

    /// Issue 46, 2: the wind figure of a 3-D approach draws the lateral wind beside the
    /// longitudinal components (a third line, in the palette's third colour, named in the
    /// legend); a longitudinal approach, which has none, draws x and z only.
    #[test]
    fn the_wind_figure_has_a_lateral_series_on_the_3d_approach_only() {
        register();
        let scenario = Scenario::default();
        let lines_of = |svg: &str, index: usize| {
            let stroke = format!("stroke=\"{}\"", hex(palette(index)));
            svg_elements(svg, "polyline")
                .into_iter()
                .filter(|e| e.contains(&stroke))
                .count()
        };
        let three_d = figure(&samples(true), &scenario, "3-D")
            .render_svg()
            .unwrap();
        assert!(svg_text(&three_d).contains("y (positive right: wind from the left)"));
        // The series and its legend sample.
        assert!(lines_of(&three_d, 2) >= 2, "no lateral series drawn");
        let longitudinal = figure(&samples(false), &scenario, "3-DOF")
            .render_svg()
            .unwrap();
        assert!(!svg_text(&longitudinal).contains("y (positive right"));
        assert_eq!(lines_of(&longitudinal, 2), 0);
        assert!(lines_of(&longitudinal, 0) >= 1 && lines_of(&longitudinal, 1) >= 1);
    }
}
