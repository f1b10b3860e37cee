//! `approach`: the final approach in metres around the deck.

use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::{Event, SignalId, Signals};

use crate::commands::outcome::outcome_text;
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
/// Dash pattern of the deck under the hook (px).
const DECK_UNDER_HOOK_DASH: (u32, u32) = (4, 3);

/// The final approach in metres around the deck: the hook, the glide path and the
/// landing point against the hook's distance along the deck from the aim point, heights
/// above the deck's mean height; the deck under the hook as it moved, the deck and its
/// four wires at the moment that decided the outcome (touchdown, the pass over the last
/// wire, or the end of the run), the ramp as the hook crossed it and the touchdown
/// point. Two panels: the last 1000 m, and a close-up from 190 m aft of the ramp over
/// the deck, which shares the upper panel's legend.
pub(crate) fn figure(run: &ApproachRun, scenario: &Scenario, flown: &str) -> Figure {
    let deck = &scenario.environment.deck;
    let samples = &run.samples;
    let mean_deck_m = deck.deck_height_m;
    let ramp_m = -deck.ramp_aft_of_aim_point_m;
    let along = |s: &Signals| deck.distance_along_deck(&s.ship, s.hook_x_m);
    // The deck's height under the hook at the sample's instant, over the deck only.
    let deck_under_hook = |s: &Signals| {
        let s_m = along(s);
        (s_m >= ramp_m).then(|| deck.point_along_deck(&s.ship, s_m).h_m)
    };
    // Points (distance along the deck, height above the mean deck) where the signal
    // applies and the hook is at or forward of `from_m`.
    let curve = |from_m: f64, value: &dyn Fn(&Signals) -> Option<f64>| -> Vec<(f64, f64)> {
        samples
            .iter()
            .filter_map(|s| value(s).map(|v| (along(s), v - mean_deck_m)))
            .filter(|(x, _)| *x >= from_m)
            .collect()
    };
    // The glide path where it lies above the deck under the hook: below it, it is an aim
    // point, not a path to fly.
    let path_above_deck = |s: &Signals| {
        s.get(SignalId::PathHeight)
            .filter(|path| deck_under_hook(s).is_none_or(|deck| *path >= deck))
    };
    let outcome = outcome_text(&run.summary);
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
    let passed_last_wire_s = run.events.iter().find_map(|event| match event {
        Event::PassedLastWire { time_s, .. } => Some(*time_s),
        _ => None,
    });
    // The deck at the moment that decided the outcome, ramp to bow side.
    let (deck_time_s, deck_moment) = match (touchdown, passed_last_wire_s) {
        (Some((t, _)), _) => (t.time_s, "at touchdown"),
        (None, Some(time_s)) => (time_s, "as the hook passed the last wire"),
        (None, None) => (run.summary.end_time_s, "at the end of the run"),
    };
    let deck_sample = samples.iter().min_by(|a, b| {
        (a.time_s - deck_time_s)
            .abs()
            .total_cmp(&(b.time_s - deck_time_s).abs())
    });
    let last_wire_m = deck.wire_positions_m[3];
    let forward_end_m =
        touchdown.map_or(last_wire_m, |(t, _)| t.distance_from_aim_m.max(last_wire_m)) + 20.0;
    let deck_height = |s_m: f64| {
        deck_sample.map(|sample| deck.point_along_deck(&sample.ship, s_m).h_m - mean_deck_m)
    };
    let deck_line: Vec<(f64, f64)> = [ramp_m, forward_end_m]
        .iter()
        .filter_map(|&s_m| deck_height(s_m).map(|h| (s_m, h)))
        .collect();
    let wires: Vec<(f64, f64)> = deck
        .wire_positions_m
        .iter()
        .filter_map(|&s_m| deck_height(s_m).map(|h| (s_m, h)))
        .collect();
    let deck_name = match deck_sample {
        Some(sample) => format!("deck {deck_moment} (t = {:.2} s)", sample.time_s),
        None => format!("deck {deck_moment}"),
    };
    let panel = |title: String, from_m: f64| {
        let mut panel = Panel::new(
            title,
            "hook distance along the deck from the aim point (m, positive forward)",
            "height above the mean deck (m)",
        )
        .x_limits(from_m..forward_end_m)
        .series("hook", curve(from_m, &|s| s.get(SignalId::HookHeight)))
        .dashed_series("glide path", curve(from_m, &path_above_deck))
        .series(
            "landing point",
            curve(from_m, &|s| s.get(SignalId::AimHeight)),
        )
        .styled_series(
            "deck under the hook, as it moved",
            curve(from_m, &deck_under_hook),
            Some(DECK_COLOUR),
            Some(DECK_UNDER_HOOK_DASH),
        )
        .coloured_series(deck_name.clone(), deck_line.clone(), DECK_COLOUR)
        .scatter("wires 1–4 on that deck (−18, −6, +6, +18 m)", wires.clone());
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
        panel
    };
    let close_up_m = ramp_m - CLOSE_UP_AFT_OF_RAMP_M;
    Figure::new()
        .title(format!("Final approach — {flown}: {outcome}"))
        .panel(panel(
            format!("The last {FINAL_APPROACH_M:.0} m"),
            -FINAL_APPROACH_M,
        ))
        .panel(
            panel(
                format!(
                    "Over the deck: {CLOSE_UP_AFT_OF_RAMP_M:.0} m aft of the ramp to the wires \
                     (legend above)"
                ),
                close_up_m,
            )
            .shared_legend(),
        )
        .panel_height(440)
}
