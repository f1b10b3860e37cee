//! `step_pitch` and `step_elevator`: the pitch step (paper Fig. 10–12); the lateral
//! step's figures in [`lateral`].

pub(crate) mod lateral;

use deckland::experiments::SETTLING_BAND_FRACTION;
use deckland::simulation::Signals;

use crate::commands::common::{Conditions, ControllerChoice};
use crate::commands::step::flight::{ControllerResult, ControllerRun, StepFlight};
use crate::plot::{Figure, Panel};

fn series(samples: &[Signals], value: impl Fn(&Signals) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time_s, value(s))).collect()
}

/// The labels of the controllers flown, in order, joined for a title: "O-PD and PID".
fn joined_labels(choices: impl Iterator<Item = ControllerChoice>) -> String {
    choices.map(|c| c.label()).collect::<Vec<_>>().join(" and ")
}

/// How a step response ended, in words: "settled in 1.150 s" or "not settled" (the
/// reason is in the table and the JSON document).
fn settling_text(result: &ControllerResult) -> String {
    match (result.settled, result.settling_time_s) {
        (true, Some(t)) => match result.settling_after_reference_s {
            Some(after) if result.reference_duration_s > 0.0 => format!(
                "settled (±2 %) in {t:.3} s, {} s after the reference ends",
                if after < 0.0 {
                    format!("\u{2212}{:.3}", -after)
                } else {
                    format!("+{after:.3}")
                }
            ),
            _ => format!("settled (±2 %) in {t:.3} s"),
        },
        _ => "not settled (±2 %)".to_string(),
    }
}

/// The pitch figure (paper Fig. 10/11) and the elevator figure (paper Fig. 12): the
/// controllers flown, the conditions and the seed in the title, each controller's
/// settling written on the pitch panel.
pub(crate) fn figures(runs: &[ControllerRun], flight: &StepFlight) -> Vec<(&'static str, Figure)> {
    let (conditions, seed, step_deg) = (flight.conditions, flight.seed, flight.step.step_deg);
    let controllers = joined_labels(runs.iter().map(|r| r.choice));
    let conditions_text = match conditions {
        Conditions::Ideal => "no noise or wind".to_string(),
        Conditions::Adverse => format!("noise and wind, seed {seed}"),
    };
    let paper_pitch = match conditions {
        Conditions::Ideal => "cf. paper Fig. 10",
        Conditions::Adverse => "cf. paper Fig. 11",
    };
    let trim_deg = runs
        .first()
        .and_then(|r| r.samples.first())
        .map_or(0.0, |s| s.theta_ref_rad.to_degrees());
    let target_deg = trim_deg + step_deg;
    let band_deg = SETTLING_BAND_FRACTION * step_deg.abs();
    let band_name = format!(
        "target ± {:.0} % of the step",
        SETTLING_BAND_FRACTION * 100.0
    );
    let reference_s = runs.first().map_or(0.0, |r| r.result.reference_duration_s);
    let command = if reference_s > 0.0 {
        format!("jerk-limited reference over {reference_s:.2} s")
    } else {
        "a step".to_owned()
    };
    let mut pitch = Panel::new(
        format!(
            "Pitch command of {step_deg:+}° ({command}) with {controllers}, {conditions_text} \
             ({paper_pitch})"
        ),
        "time (s)",
        "pitch angle θ (deg)",
    );
    for (index, run) in runs.iter().enumerate() {
        // The second controller dashed: on the ideal step both may lie on one curve.
        pitch = pitch
            .styled_series(
                format!("θ, {}", run.choice.label()),
                series(&run.samples, |s| s.theta_rad.to_degrees()),
                None,
                (index > 0).then_some((10, 6)),
            )
            .note(format!(
                "{}: {}",
                run.choice.label(),
                settling_text(&run.result)
            ));
    }
    if let Some(run) = runs.first() {
        pitch = pitch.styled_series(
            if reference_s > 0.0 {
                "command (jerk-limited reference)"
            } else {
                "command (step)"
            },
            series(&run.samples, |s| s.theta_ref_rad.to_degrees()),
            None,
            Some((3, 3)),
        );
    }
    pitch = pitch
        .reference_line(band_name.clone(), target_deg + band_deg)
        .reference_line(band_name, target_deg - band_deg);

    let actuator = flight
        .scenario(ControllerChoice::Opd)
        .aircraft
        .elevator_actuator;
    let mut elevator = Panel::new(
        format!(
            "Elevator during the {step_deg:+}° step with {controllers}, {conditions_text}{}",
            match conditions {
                Conditions::Ideal => "",
                Conditions::Adverse => " (cf. paper Fig. 12)",
            }
        ),
        "time (s)",
        "elevator δe (deg, trailing edge down)",
    );
    for (index, run) in runs.iter().enumerate() {
        elevator = elevator.styled_series(
            format!("δe, {}", run.choice.label()),
            series(&run.samples, |s| s.elevator_rad.to_degrees()),
            None,
            (index > 0).then_some((10, 6)),
        );
    }
    elevator = elevator.surface_stops(actuator.min_deflection_deg, actuator.max_deflection_deg);
    vec![
        ("step_pitch", Figure::new().panel(pitch)),
        ("step_elevator", Figure::new().panel(elevator)),
    ]
}
