//! The figures of one approach (`land`, `run`, and `reproduce`'s approach), one module
//! each: `approach` (the final approach in metres around the deck), `altitude` (the whole
//! approach), `glide_path_error` (paper Fig. 14), `pitch` (Fig. 15), `controls`,
//! `airspeed` and `wind`; for a 3-D approach also `plan_view` and `cross_track` (`lineup`).

mod airspeed;
mod altitude;
mod approach;
mod controls;
mod glide_path_error;
mod lineup;
mod pitch;
mod ship_outline;
mod wind;

use deckland::environment::STEADY_WAKE_EXTENT_M;
use deckland::experiments::ApproachRun;
use deckland::scenario::Scenario;
use deckland::simulation::{SignalId, Signals};

use crate::commands::outcome::outcome_text;
use crate::plot::{Figure, Panel};

/// The x axis of the figures over time.
const TIME: &str = "time (s)";

/// The unit a plotted series shows its registered signal in.
#[derive(Debug, Clone, Copy)]
pub(super) enum Shown {
    /// The signal's own SI unit (`simulation::SIGNALS`).
    AsRegistered,
    /// An angle (rad) in degrees.
    Degrees,
    /// A thousandth: newtons in kilonewtons.
    Thousandths,
}

/// Points (time, value) of the registered signal `signal` where it applies (an optional
/// signal, such as the glide path's height, only where it has a value).
pub(super) fn series(samples: &[Signals], signal: SignalId, shown: Shown) -> Vec<(f64, f64)> {
    samples
        .iter()
        .filter_map(|s| {
            let value = s.get(signal)?;
            let value = match shown {
                Shown::AsRegistered => value,
                Shown::Degrees => value.to_degrees(),
                Shown::Thousandths => value / 1000.0,
            };
            Some((s.time_s, value))
        })
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
        .find(|s| s.distance_aft_m < extent_m)
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
    let mut figures = vec![
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
    ];
    figures.extend(lineup::figures(run, scenario, &title));
    figures
}
