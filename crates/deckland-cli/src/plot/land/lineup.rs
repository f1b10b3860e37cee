//! `plan_view` and `cross_track`: the lineup of a 3-D approach (docs/model.md §10.8).
//!
//! Both are drawn only for a plant with lateral states (the 6-DOF aircraft); a 3-DOF
//! approach has no lineup to show.

use std::ops::Range;

use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::lateral::touchdown::MAX_OFF_CENTRE_M;
use deckland::simulation::{SignalId, Signals};

use super::ship_outline::ShipAxes;
use super::{series, Shown, TIME};
use crate::plot::{Figure, MarkerShape, Panel, DECK_COLOUR, SHIP_COLOUR};

/// Length of the approach the plan view shows (m).
const PLAN_VIEW_M: f64 = 1000.0;
/// Distance aft of the ramp where the plan view's close-up starts (m).
const CLOSE_UP_AFT_OF_RAMP_M: f64 = 190.0;
/// Dash pattern of the centreline abeam the hook (px).
const CENTRELINE_DASH: (u32, u32) = (6, 3);

/// The landing area's centreline at one instant, in the horizontal plane: the aim point
/// (earth x, y; m) and the centreline's heading from the final bearing (rad, right).
#[derive(Debug, Clone, Copy)]
struct Centreline {
    aim: (f64, f64),
    heading_rad: f64,
}

impl Centreline {
    /// The centreline of a 3-D approach's sample.
    fn of(s: &Signals) -> Option<Self> {
        Some(Self {
            aim: (s.aim_point.x_m, s.get(SignalId::AimY)?),
            heading_rad: s.get(SignalId::CentrelineHeading)?,
        })
    }

    /// The point `s_m` metres forward of the aim point along it.
    fn point(&self, s_m: f64) -> (f64, f64) {
        let (sin, cos) = self.heading_rad.sin_cos();
        (self.aim.0 + s_m * cos, self.aim.1 + s_m * sin)
    }

    /// Its y abeam earth x `x_m` (extended aft of the ramp, where the aircraft lines up).
    fn y_at(&self, x_m: f64) -> f64 {
        self.aim.1 + (x_m - self.aim.0) * self.heading_rad.tan()
    }
}

/// The hook's horizontal earth position (m), if the plant has lateral states.
fn hook(s: &Signals) -> Option<(f64, f64)> {
    Some((s.hook_x_m, s.hook_y_m?))
}

/// The sample nearest `time_s`.
fn sample_at(samples: &[Signals], time_s: f64) -> Option<&Signals> {
    samples.iter().min_by(|a, b| {
        (a.time_s - time_s)
            .abs()
            .total_cmp(&(b.time_s - time_s).abs())
    })
}

/// The lineup figures of `run`, each with its file stem; none unless it flew the 3-D
/// approach (a 3-DOF run, or a 6-DOF run in the longitudinal environment, has no
/// centreline to line up on).
pub(super) fn figures(
    run: &ApproachRun,
    scenario: &Scenario,
    title: &str,
) -> Vec<(&'static str, Figure)> {
    if run.samples.iter().all(|s| Centreline::of(s).is_none()) {
        return Vec::new();
    }
    vec![
        ("plan_view", plan_view(run, scenario, title)),
        ("cross_track", cross_track(run, title)),
    ]
}

/// What the plan view draws, relative to the aim point at the moment that decided the
/// outcome (y negated, drawn down the page).
struct PlanLayers {
    moment_s: f64,
    track: Vec<(f64, f64)>,
    centreline: Vec<(f64, f64)>,
    landing_area: Vec<(f64, f64)>,
    wires: Vec<(f64, f64)>,
    ramp: (f64, f64),
    touchdown: Option<(f64, f64)>,
}

impl PlanLayers {
    /// One panel of the plan view over `window` along x. The flight deck is drawn in the
    /// close-up only; the overview lists it (no points) so that both panels draw the same
    /// series in the same colours under one legend.
    fn panel(&self, heading: String, window: Range<f64>, deck_outline: Vec<(f64, f64)>) -> Panel {
        let in_view = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
            points
                .iter()
                .copied()
                .filter(|(x, _)| *x >= window.start)
                .collect()
        };
        let mut panel = Panel::new(
            heading,
            "earth x along the final bearing from the aim point (m)",
            "earth y from the aim point (m, right of the bearing, down)",
        )
        .y_downward()
        .x_limits(window.clone())
        .series("hook", in_view(&self.track))
        .styled_series(
            "landing centreline abeam the hook, as it moved",
            in_view(&self.centreline),
            Some(DECK_COLOUR),
            Some(CENTRELINE_DASH),
        )
        .coloured_series(
            format!("landing area's centreline at t = {:.2} s", self.moment_s),
            self.landing_area.clone(),
            DECK_COLOUR,
        )
        .coloured_series(
            "flight deck then, to scale (Nimitz, 333 × 77 m)",
            deck_outline,
            SHIP_COLOUR,
        )
        .scatter("wires 1–4 on the centreline", self.wires.clone())
        .marker("ramp", self.ramp, MarkerShape::Triangle);
        if let Some(point) = self.touchdown {
            panel = panel.marker("touchdown", point, MarkerShape::Circle);
        }
        panel
    }
}

/// The approach from above: the hook's track and the landing area's centreline abeam it
/// as the deck moved, in earth axes with the origin at the aim point at the moment that
/// decided the outcome (touchdown, or the end of the run); the angled landing area from
/// the ramp to past the last wire at that moment, and the touchdown point. Two panels:
/// the last 1000 m, and a close-up from 190 m aft of the ramp to the bow with the ship's
/// flight deck drawn to scale at that moment (`ship_outline`) and the ramp.
fn plan_view(run: &ApproachRun, scenario: &Scenario, title: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let moment_s = run
        .summary
        .touchdown
        .map_or(run.summary.end_time_s, |t| t.time_s);
    let Some((moment, line)) =
        sample_at(samples, moment_s).and_then(|s| Some((s, Centreline::of(s)?)))
    else {
        return Figure::new().title(format!("Plan view — {title}"));
    };
    let origin = line.aim;
    // Seen from above with x along the final bearing to the right, y (to the right of the
    // bearing) points down the page: every y is drawn negated (`Panel::y_downward`).
    let relative = |(x, y): (f64, f64)| (x - origin.0, origin.1 - y);
    let track: Vec<(f64, f64)> = samples.iter().filter_map(hook).map(relative).collect();
    let centreline: Vec<(f64, f64)> = samples
        .iter()
        .filter_map(|s| {
            let (x, _) = hook(s)?;
            Some(relative((x, Centreline::of(s)?.y_at(x))))
        })
        .collect();
    // The landing area at the moment: its centreline from the ramp to 20 m past the
    // last wire, and the wires' crossings of it.
    let ramp_s = -deck.ramp_aft_of_aim_point_m;
    let forward_s = deck.wire_positions_m[3] + 20.0;
    let landing_area: Vec<(f64, f64)> = [ramp_s, forward_s]
        .iter()
        .map(|&s_m| relative(line.point(s_m)))
        .collect();
    let wires: Vec<(f64, f64)> = deck
        .wire_positions_m
        .iter()
        .map(|&s_m| relative(line.point(s_m)))
        .collect();
    // The flight deck at the moment, to scale, and the ramp on its stern.
    let axes = ShipAxes::new(line.aim, line.heading_rad, deck);
    let outline: Vec<(f64, f64)> = axes.outline().into_iter().map(relative).collect();
    let bow_m = outline.iter().map(|p| p.0).fold(f64::MIN, f64::max);
    let ramp = relative(line.point(ramp_s));
    let touchdown = run
        .summary
        .touchdown
        .and_then(|t| sample_at(samples, t.time_s))
        .and_then(hook)
        .map(relative);
    let layers = PlanLayers {
        moment_s: moment.time_s,
        track,
        centreline,
        landing_area,
        wires,
        ramp,
        touchdown,
    };
    Figure::new()
        .title(format!("Plan view — {title}"))
        .panel(layers.panel(
            format!("The last {PLAN_VIEW_M:.0} m"),
            -PLAN_VIEW_M..(forward_s + 10.0),
            Vec::new(),
        ))
        .panel(
            layers
                .panel(
                    format!(
                        "Over the deck, to scale: {CLOSE_UP_AFT_OF_RAMP_M:.0} m aft of the ramp to the bow (legend above)"
                    ),
                    (ramp_s - CLOSE_UP_AFT_OF_RAMP_M)..(bow_m + 10.0),
                    outline,
                )
                .equal_aspect()
                .shared_legend(),
        )
        .panel_height(400)
}

/// The hook's lateral offset from the landing area's moving centreline over time, with
/// the off-centre limit (or a note naming it, when it lies far beyond the offsets flown),
/// and the bank (commanded and flown), heading and sideslip that
/// correct it.
fn cross_track(run: &ApproachRun, title: &str) -> Figure {
    let samples = &run.samples;
    let mut lineup = Panel::new(
        "Hook's offset from the landing area's centreline, as it moved",
        TIME,
        "offset (m, positive right)",
    )
    .series(
        "hook offset",
        series(samples, SignalId::CrossTrack, Shown::AsRegistered),
    )
    .reference_line("on the centreline", 0.0)
    .limit_line(
        format!("off-centre limit ±{MAX_OFF_CENTRE_M} m"),
        MAX_OFF_CENTRE_M,
    )
    .limit_line(
        format!("off-centre limit ±{MAX_OFF_CENTRE_M} m"),
        -MAX_OFF_CENTRE_M,
    );
    if let Some(t) = run.summary.touchdown {
        lineup = lineup.vertical_line("touchdown", t.time_s);
    }
    Figure::new()
        .title(format!("Lineup — {title}"))
        .panel(lineup)
        .panel(
            Panel::new("Bank, heading and sideslip", TIME, "angle (deg)")
                .dashed_series(
                    "bank command",
                    series(samples, SignalId::BankCommand, Shown::Degrees),
                )
                .series(
                    "bank φ (right wing down +)",
                    series(samples, SignalId::Bank, Shown::Degrees),
                )
                .series(
                    "heading ψ from the final bearing (nose right +)",
                    series(samples, SignalId::Heading, Shown::Degrees),
                )
                .series(
                    "sideslip β (wind from the right +)",
                    series(samples, SignalId::Sideslip, Shown::Degrees),
                ),
        )
}

#[cfg(test)]
mod tests {
    use super::*;
    use deckland::experiments::fly_approach;

    /// The points of an SVG element's `points="x,y x,y …"` attribute.
    fn points(element: &str) -> Vec<(f64, f64)> {
        let Some(start) = element.find("points=\"") else {
            return Vec::new();
        };
        let rest = &element[start + 8..];
        rest[..rest.find('"').unwrap_or(rest.len())]
            .split_whitespace()
            .filter_map(|pair| {
                let (x, y) = pair.split_once(',')?;
                Some((x.parse().ok()?, y.parse().ok()?))
            })
            .collect()
    }

    /// The SVG elements `<tag …>` of `svg` that hold `needle`.
    fn elements<'a>(svg: &'a str, tag: &str, needle: &str) -> Vec<&'a str> {
        svg.split('<')
            .filter(|e| e.starts_with(tag) && e.contains(needle))
            .collect()
    }

    /// The distance (px) from `p` to the segment from `a` to `b`.
    fn to_segment(p: (f64, f64), a: (f64, f64), b: (f64, f64)) -> f64 {
        let (dx, dy) = (b.0 - a.0, b.1 - a.1);
        let t = (((p.0 - a.0) * dx + (p.1 - a.1) * dy) / (dx * dx + dy * dy)).clamp(0.0, 1.0);
        (p.0 - a.0 - t * dx).hypot(p.1 - a.1 - t * dy)
    }

    /// The default approach (seed 1), flown once for the tests.
    fn default_run() -> &'static (Scenario, ApproachRun) {
        static RUN: std::sync::OnceLock<(Scenario, ApproachRun)> = std::sync::OnceLock::new();
        RUN.get_or_init(|| {
            let scenario = Scenario::default();
            let run = fly_approach(&scenario).expect("flies");
            (scenario, run)
        })
    }

    /// Issue 46, 5: the cross-track figure's offset axis spans the offsets flown; the
    /// off-centre limit, far beyond them, is named in a note rather than drawn (the default
    /// approach stays within ±4 m of the centreline, the limit is ±6.1 m); and both panels'
    /// legends stand in the column beside the axes, none inside the upper panel beside an
    /// empty column.
    #[test]
    fn cross_track_spans_the_offsets_and_names_the_far_limit() {
        use crate::plot::tests::{svg_text, text_x};
        crate::plot::tests::register();
        let (_, run) = default_run();
        let offsets: Vec<f64> = series(&run.samples, SignalId::CrossTrack, Shown::AsRegistered)
            .into_iter()
            .map(|(_, y)| y)
            .collect();
        let (low, high) = offsets
            .iter()
            .fold((f64::MAX, f64::MIN), |(l, h), y| (l.min(*y), h.max(*y)));
        let reach = crate::plot::panel::LIMIT_REACH * (high - low);
        assert!(high + reach < MAX_OFF_CENTRE_M && low - reach > -MAX_OFF_CENTRE_M);
        let svg = cross_track(run, "test").render_svg().expect("renders");
        let text = svg_text(&svg);
        let note = format!("off-centre limit ±{MAX_OFF_CENTRE_M} m: above and below the axis");
        assert!(text.contains(&note), "{text}");
        // No line in the limit's colour (the second reference line's).
        let limit = crate::plot::tests::hex(crate::plot::style::REFERENCE_STYLES[1].0);
        assert!(!svg.contains(&format!("stroke=\"{limit}\"")));
        let (upper, lower) = (text_x(&svg, "hook offset"), text_x(&svg, "bank command"));
        assert!(upper.is_some() && upper == lower, "{upper:?} {lower:?}");
    }

    /// Issue 44's target: in the rendered plan view the ramp's marker stands on the
    /// flight deck's stern edge within a pixel, and the four wires' dots are on the deck,
    /// read back from the SVG's pixels (the default approach, seed 1, traps).
    #[test]
    fn the_ramp_and_the_wires_are_on_the_drawn_deck_within_a_pixel() {
        crate::plot::tests::register();
        let (scenario, run) = default_run();
        let svg = plan_view(run, scenario, "test")
            .render_svg()
            .expect("renders");
        let grey = format!(
            "stroke=\"#{:02X}{:02X}{:02X}\"",
            SHIP_COLOUR.0, SHIP_COLOUR.1, SHIP_COLOUR.2
        );
        let outline = elements(&svg, "polyline", &grey)
            .into_iter()
            .map(points)
            .find(|p| p.len() == super::super::ship_outline::FLIGHT_DECK_OUTLINE.len())
            .expect("the flight deck is drawn");
        // The close-up's ramp marker: the lowest of the black triangles (the overview's and
        // the legend's are above it); its centre is the apex plus the half base.
        let ramp = elements(&svg, "polygon", "fill=\"#000000\"")
            .into_iter()
            .map(points)
            .filter(|p| p.len() == 3)
            .map(|p| (p[0].0, p[0].1 + 0.5 * (p[2].0 - p[1].0)))
            .max_by(|a, b| a.1.total_cmp(&b.1))
            .expect("the ramp is marked");
        let stern = to_segment(ramp, outline[0], outline[1]);
        assert!(stern <= 1.0, "the ramp is {stern} px off the stern edge");
        // The wires' dots in the close-up (below the overview's bottom edge): on the deck.
        let top = outline.iter().map(|p| p.1).fold(f64::MAX, f64::min);
        let wires: Vec<(f64, f64)> = elements(&svg, "circle", "r=\"3\"")
            .into_iter()
            .filter_map(|e| {
                let number = |key: &str| -> Option<f64> {
                    let rest = &e[e.find(key)? + key.len()..];
                    rest[..rest.find('"')?].parse().ok()
                };
                Some((number("cx=\"")?, number("cy=\"")?))
            })
            .filter(|p| p.1 > top)
            .collect();
        assert_eq!(wires.len(), 4, "{wires:?}");
        for wire in wires {
            assert!(
                super::super::ship_outline::inside_polygon(wire, &outline),
                "wire at {wire:?} px is off the deck"
            );
        }
    }
}
