//! The figures of one approach (`land`, `run`, and `reproduce`'s approach), one module
//! each: `approach` (the final approach in metres around the deck), `altitude` (the whole
//! approach), `glide_path_error` (paper Fig. 14), `pitch` (Fig. 15), `controls`,
//! `airspeed` and `wind`.

mod airspeed;
mod altitude;
mod approach;
mod controls;
mod glide_path_error;
mod pitch;
mod wind;

use deckland::environment::STEADY_WAKE_EXTENT_M;
use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::Signals;

use crate::commands::land::outcome_text;
use crate::plot::{Figure, Panel};

/// The x axis of the figures over time.
const TIME: &str = "time (s)";

/// Points (time, value) of one signal.
pub(super) fn series(samples: &[Signals], value: impl Fn(&Signals) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time_s, value(s))).collect()
}

/// Points (time, value) of a signal where it applies.
pub(super) fn series_where_applicable(
    samples: &[Signals],
    value: impl Fn(&Signals) -> Option<f64>,
) -> Vec<(f64, f64)> {
    samples
        .iter()
        .filter_map(|s| value(s).map(|v| (s.time_s, v)))
        .collect()
}

/// When the air wake reaches the aircraft: the first time its centre of gravity is within
/// the wake's extent aft of the ship's pitch centre (s), if the wake blows at all.
pub(super) fn wake_onset(samples: &[Signals], scenario: &Scenario) -> Option<(f64, f64)> {
    let wind = &scenario.environment.wind;
    if !(wind.steady_wake || wind.periodic_wake) {
        return None;
    }
    let extent_m = wind.wake_extent_m.unwrap_or(STEADY_WAKE_EXTENT_M);
    samples
        .iter()
        .find(|s| s.ship.distance_aft_of_pitch_centre_m(s.x_m) < extent_m)
        .map(|s| (s.time_s, extent_m))
}

/// `panel` with the air wake's onset marked (a vertical line at its time), if the wake
/// reaches the aircraft in `samples`.
pub(super) fn mark_wake_onset(panel: Panel, samples: &[Signals], scenario: &Scenario) -> Panel {
    match wake_onset(samples, scenario) {
        Some((time_s, extent_m)) => {
            panel.vertical_line(format!("air wake from {extent_m:.0} m aft"), time_s)
        }
        None => panel,
    }
}

/// The approach's figures, each with its file stem. `flown` names the controller, the
/// conditions and the seed.
pub(crate) fn figures(
    run: &ApproachRun,
    scenario: &Scenario,
    flown: &str,
) -> Vec<(&'static str, Figure)> {
    let samples = &run.samples;
    let title = format!("{flown}: {}", outcome_text(&run.summary));
    vec![
        ("approach", approach::figure(run, scenario, flown)),
        ("altitude", altitude::figure(samples, &title)),
        (
            "glide_path_error",
            glide_path_error::figure(samples, &title),
        ),
        ("pitch", pitch::figure(samples, &title)),
        ("controls", controls::figure(samples, scenario, &title)),
        ("airspeed", airspeed::figure(samples, scenario, &title)),
        ("wind", wind::figure(samples, scenario, &title)),
    ]
}
