//! `controls`: the elevator against its stops, and the thrust commanded and delivered.

use deckland::scenario::Scenario;

use deckland::simulation::{SignalId, Signals};

use super::{series, Shown, TIME};
use crate::plot::{Figure, Panel};

/// The elevator against its stops, and the thrust commanded and delivered.
pub(super) fn figure(samples: &[Signals], scenario: &Scenario, title: &str) -> Figure {
    let actuator = scenario.aircraft.elevator_actuator;
    Figure::new()
        .title(format!("Controls — {title}"))
        .panel(
            Panel::new(
                "Elevator (positive trailing edge down)",
                TIME,
                "elevator δe (deg)",
            )
            .series(
                "elevator",
                series(samples, SignalId::Elevator, Shown::Degrees),
            )
            .surface_stops(actuator.min_deflection_deg, actuator.max_deflection_deg),
        )
        .panel(
            Panel::new("Thrust, both engines", TIME, "thrust (kN)")
                .series(
                    "command",
                    series(samples, SignalId::ThrustCommand, Shown::Thousandths),
                )
                .series(
                    "actual",
                    series(samples, SignalId::Thrust, Shown::Thousandths),
                ),
        )
}
