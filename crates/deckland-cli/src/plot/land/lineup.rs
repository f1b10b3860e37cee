//! `plan_view` and `cross_track`: the lineup of a 3-D approach (docs/model.md §10.8).
//!
//! Both are drawn only for a plant with lateral states (the 6-DOF aircraft); a 3-DOF
//! approach has no lineup to show.

use deckland::environment::{DeckGeometry, EarthPoint};
use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::Signals;

use super::TIME;
use crate::plot::{Figure, MarkerShape, Panel, DECK_COLOUR};

/// Length of the approach the plan view shows (m).
const PLAN_VIEW_M: f64 = 1000.0;
/// Distance aft of the ramp where the plan view's close-up starts (m).
const CLOSE_UP_AFT_OF_RAMP_M: f64 = 190.0;
/// Dash pattern of the centreline abeam the hook (px).
const CENTRELINE_DASH: (u32, u32) = (6, 3);

/// The hook's earth position at a sample, if the plant has lateral states.
fn hook(s: &Signals) -> Option<EarthPoint> {
    Some(EarthPoint {
        x_m: s.hook_x_m,
        y_m: s.hook_y_m?,
        h_m: s.hook_h_m,
    })
}

/// The y of the landing area's centreline, at the sample's instant, abeam earth x `x_m`
/// (the centreline extended aft of the ramp, where the aircraft lines up on it).
fn centreline_y_at(deck: &DeckGeometry, s: &Signals, x_m: f64) -> f64 {
    let line = deck.landing_centreline(&s.ship);
    let slope = if line.direction.x.abs() > f64::EPSILON {
        line.direction.y / line.direction.x
    } else {
        0.0
    };
    line.point.y_m + (x_m - line.point.x_m) * slope
}

/// The sample nearest `time_s`.
fn sample_at(samples: &[Signals], time_s: f64) -> Option<&Signals> {
    samples.iter().min_by(|a, b| {
        (a.time_s - time_s)
            .abs()
            .total_cmp(&(b.time_s - time_s).abs())
    })
}

/// The lineup figures of `run`, each with its file stem; none for a longitudinal plant.
pub(super) fn figures(
    run: &ApproachRun,
    scenario: &Scenario,
    title: &str,
) -> Vec<(&'static str, Figure)> {
    if run.samples.iter().all(|s| s.hook_y_m.is_none()) {
        return Vec::new();
    }
    vec![
        ("plan_view", plan_view(run, scenario, title)),
        ("cross_track", cross_track(run, scenario, title)),
    ]
}

/// The approach from above: the hook's track and the landing area's centreline abeam it
/// as the deck moved, in earth axes with the origin at the aim point at the moment that
/// decided the outcome (touchdown, or the end of the run); the angled landing area from
/// the ramp to past the last wire at that moment, and the touchdown point. Two panels:
/// the last 1000 m, and a close-up from 190 m aft of the ramp.
fn plan_view(run: &ApproachRun, scenario: &Scenario, title: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let moment_s = run
        .summary
        .touchdown
        .map_or(run.summary.end_time_s, |t| t.time_s);
    let Some(moment) = sample_at(samples, moment_s) else {
        return Figure::new().title(format!("Plan view — {title}"));
    };
    let origin = deck.aim_point_3d(&moment.ship);
    let relative = |p: EarthPoint| (p.x_m - origin.x_m, p.y_m - origin.y_m);
    let track: Vec<(f64, f64)> = samples.iter().filter_map(hook).map(relative).collect();
    let centreline: Vec<(f64, f64)> = samples
        .iter()
        .filter_map(|s| {
            let h = hook(s)?;
            Some((
                h.x_m - origin.x_m,
                centreline_y_at(deck, s, h.x_m) - origin.y_m,
            ))
        })
        .collect();
    // The landing area at the moment: its centreline from the ramp to 20 m past the
    // last wire, and the wires' crossings of it.
    let ramp_s = -deck.ramp_aft_of_aim_point_m;
    let forward_s = deck.wire_positions_m[3] + 20.0;
    let landing_area: Vec<(f64, f64)> = [ramp_s, forward_s]
        .iter()
        .map(|&s_m| relative(deck.point_on_landing_centreline(&moment.ship, s_m)))
        .collect();
    let wires: Vec<(f64, f64)> = deck
        .wires_3d(&moment.ship)
        .into_iter()
        .map(relative)
        .collect();
    let touchdown = run
        .summary
        .touchdown
        .and_then(|t| sample_at(samples, t.time_s))
        .and_then(hook)
        .map(relative);
    let panel = |heading: String, from_m: f64| {
        let in_view = |points: &[(f64, f64)]| -> Vec<(f64, f64)> {
            points
                .iter()
                .copied()
                .filter(|(x, _)| *x >= from_m)
                .collect()
        };
        let mut panel = Panel::new(
            heading,
            "earth x along the final bearing from the aim point (m)",
            "earth y from the aim point (m, positive right)",
        )
        .x_limits(from_m..forward_s + 10.0)
        .series("hook", in_view(&track))
        .styled_series(
            "landing centreline abeam the hook, as it moved",
            in_view(&centreline),
            Some(DECK_COLOUR),
            Some(CENTRELINE_DASH),
        )
        .coloured_series(
            format!("landing area's centreline at t = {:.2} s", moment.time_s),
            landing_area.clone(),
            DECK_COLOUR,
        )
        .scatter("wires 1–4 on the centreline", wires.clone());
        if let Some(point) = touchdown {
            panel = panel.marker("touchdown", point, MarkerShape::Circle);
        }
        panel
    };
    Figure::new()
        .title(format!("Plan view — {title}"))
        .panel(panel(format!("The last {PLAN_VIEW_M:.0} m"), -PLAN_VIEW_M))
        .panel(
            panel(
                format!(
                    "Over the deck: {CLOSE_UP_AFT_OF_RAMP_M:.0} m aft of the ramp (legend above)"
                ),
                ramp_s - CLOSE_UP_AFT_OF_RAMP_M,
            )
            .shared_legend(),
        )
        .panel_height(400)
}

/// The hook's lateral offset from the landing area's moving centreline over time, and
/// the bank and heading that correct it.
fn cross_track(run: &ApproachRun, scenario: &Scenario, title: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let offset: Vec<(f64, f64)> = samples
        .iter()
        .filter_map(|s| {
            let h = hook(s)?;
            Some((
                s.time_s,
                deck.offset_right_of_landing_centreline(&s.ship, &h),
            ))
        })
        .collect();
    let degrees = |value: fn(&Signals) -> Option<f64>| -> Vec<(f64, f64)> {
        samples
            .iter()
            .filter_map(|s| value(s).map(|v| (s.time_s, v.to_degrees())))
            .collect()
    };
    let mut lineup = Panel::new(
        "Hook's offset from the landing area's centreline, as it moved",
        TIME,
        "offset (m, positive right)",
    )
    .series("hook offset", offset)
    .reference_line("on the centreline", 0.0);
    if let Some(t) = run.summary.touchdown {
        lineup = lineup.vertical_line("touchdown", t.time_s);
    }
    Figure::new()
        .title(format!("Lineup — {title}"))
        .panel(lineup)
        .panel(
            Panel::new("Bank and heading", TIME, "angle (deg)")
                .series("bank φ (right wing down +)", degrees(|s| s.phi_rad))
                .series(
                    "heading ψ from the final bearing (nose right +)",
                    degrees(|s| s.psi_rad),
                )
                .series(
                    "sideslip β (wind from the right +)",
                    degrees(|s| s.beta_rad),
                ),
        )
}
