//! `approach`: the final approach in metres around the deck.

use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::{Event, Signals};

use crate::commands::land::outcome_text;
use crate::plot::{Figure, MarkerShape, Panel, DECK_COLOUR};

/// The hook height at `time_s`, interpolated between the recorded samples.
fn hook_height_at(samples: &[Signals], time_s: f64) -> Option<f64> {
    let after = samples.iter().position(|s| s.time_s >= time_s)?;
    let b = &samples[after];
    let Some(a) = after.checked_sub(1).map(|i| &samples[i]) else {
        return Some(b.hook_h_m);
    };
    let span = b.time_s - a.time_s;
    let fraction = if span > 0.0 {
        (time_s - a.time_s) / span
    } else {
        1.0
    };
    Some(a.hook_h_m + fraction * (b.hook_h_m - a.hook_h_m))
}

/// Length of the final approach shown in the upper panel of `approach` (m).
const FINAL_APPROACH_M: f64 = 1000.0;
/// Distance aft of the ramp where the close-up over the deck starts (m).
const CLOSE_UP_AFT_OF_RAMP_M: f64 = 190.0;

/// The final approach in metres around the deck: the hook, the glide path and the
/// landing point against the hook's distance along the deck from the aim point, heights
/// above the deck's mean height; the ramp as the hook crossed it, the wires, the deck at
/// touchdown and the touchdown point, with the outcome written on it. Two panels: the
/// last 1000 m, and a close-up from 190 m aft of the ramp over the deck.
pub(crate) fn figure(run: &ApproachRun, scenario: &Scenario, flown: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let mean_deck_m = deck.deck_height_m;
    let along = |s: &Signals| deck.distance_along_deck(&s.ship, s.hook_x_m);
    // Points (distance along the deck, height above the mean deck) where the signal
    // applies and the hook is at or forward of `from_m`.
    let curve = |from_m: f64, value: &dyn Fn(&Signals) -> Option<f64>| -> Vec<(f64, f64)> {
        samples
            .iter()
            .filter_map(|s| value(s).map(|v| (along(s), v - mean_deck_m)))
            .filter(|(x, _)| *x >= from_m)
            .collect()
    };
    let outcome = outcome_text(&run.summary);
    let ramp_m = -deck.ramp_aft_of_aim_point_m;
    let ramp_crossing = run.events.iter().find_map(|event| match event {
        Event::RampCrossing {
            time_s,
            clearance_m,
        } => hook_height_at(samples, *time_s)
            .map(|hook| (hook - clearance_m - mean_deck_m, *clearance_m)),
        _ => None,
    });
    let touchdown = run
        .summary
        .touchdown
        .and_then(|t| hook_height_at(samples, t.time_s).map(|hook| (t, hook - mean_deck_m)));
    // The deck as it stood at touchdown (or at the end of the run), ramp to bow side.
    let deck_time_s = touchdown.map_or(run.summary.end_time_s, |(t, _)| t.time_s);
    let deck_pose = samples
        .iter()
        .min_by(|a, b| {
            (a.time_s - deck_time_s)
                .abs()
                .total_cmp(&(b.time_s - deck_time_s).abs())
        })
        .map(|s| s.ship);
    let last_wire_m = deck.wire_positions_m[3];
    let forward_end_m =
        touchdown.map_or(last_wire_m, |(t, _)| t.distance_from_aim_m.max(last_wire_m)) + 20.0;
    let deck_line: Vec<(f64, f64)> = deck_pose
        .map(|pose| {
            [ramp_m, forward_end_m]
                .iter()
                .map(|&s_m| (s_m, deck.point_along_deck(&pose, s_m).h_m - mean_deck_m))
                .collect()
        })
        .unwrap_or_default();
    let deck_name = if touchdown.is_some() {
        "deck at touchdown"
    } else {
        "deck at the end of the run"
    };
    let panel = |title: String, from_m: f64, close_up: bool| {
        let mut panel = Panel::new(
            title,
            "hook distance along the deck from the aim point (m, positive forward)",
            "height above the mean deck (m)",
        )
        .x_limits(from_m..forward_end_m)
        .series("hook", curve(from_m, &|s| Some(s.hook_h_m)))
        .dashed_series("glide path", curve(from_m, &|s| s.path_height_m))
        .series("landing point", curve(from_m, &|s| Some(s.aim_point.h_m)))
        .coloured_series(deck_name, deck_line.clone(), DECK_COLOUR)
        .vertical_line("ramp", ramp_m);
        if let Some((height, clearance)) = ramp_crossing {
            panel = panel.marker(
                if clearance >= 0.0 {
                    format!("ramp as crossed, {clearance:.2} m below the hook")
                } else {
                    format!("ramp as crossed, {:.2} m above the hook", -clearance)
                },
                (ramp_m, height),
                MarkerShape::Triangle,
            );
        }
        if let Some((t, height)) = touchdown {
            panel = panel.marker(
                format!(
                    "touchdown {:+.1} m, sink {:.2} m/s",
                    t.distance_from_aim_m, t.sink_rate_mps
                ),
                (t.distance_from_aim_m, height),
                MarkerShape::Circle,
            );
        }
        if close_up {
            // Wires 12 m apart are numbered only: names would run into each other.
            for (index, wire) in deck.wire_positions_m.iter().enumerate() {
                panel = panel.vertical_line(format!("{}", index + 1), *wire);
            }
            panel = panel.note(outcome.clone());
        }
        panel
    };
    let close_up_m = ramp_m - CLOSE_UP_AFT_OF_RAMP_M;
    Figure::new()
        .title(format!("Final approach — {flown}: {outcome}"))
        .panel(panel(
            format!("The last {FINAL_APPROACH_M:.0} m"),
            -FINAL_APPROACH_M,
            false,
        ))
        .panel(panel(
            format!(
                "Over the deck: {:.0} m aft of the ramp to the wires (numbered 1–4)",
                CLOSE_UP_AFT_OF_RAMP_M
            ),
            close_up_m,
            true,
        ))
        .panel_height(440)
}
