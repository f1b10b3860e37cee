//! `step_bank` (or `step_sideslip`) and `step_surfaces`: the lateral step.

use deckland::experiments::{
    LateralAxis, LateralSample, LateralStep, LATERAL_SETTLING_BAND_FRACTION,
};

use super::joined_labels;
use crate::commands::common::Conditions;
use crate::commands::step::flight::LateralRun;
use crate::plot::{Figure, Panel};

fn series(samples: &[LateralSample], value: impl Fn(&LateralSample) -> f64) -> Vec<(f64, f64)> {
    samples.iter().map(|s| (s.time_s, value(s))).collect()
}

/// The stepped angle with the other channel's angle, and the aileron and rudder.
pub(crate) fn lateral_figures(
    runs: &[LateralRun],
    step: &LateralStep,
    conditions: Conditions,
) -> Vec<(&'static str, Figure)> {
    let controllers = joined_labels(runs.iter().map(|r| r.choice));
    let conditions_text = match conditions {
        Conditions::Ideal => "no noise or turbulence".to_string(),
        Conditions::Adverse => format!("lateral turbulence and sensor noise, seed {}", step.seed),
    };
    type Pick = fn(&LateralSample) -> f64;
    let (stem, name, angle, command, other_name, other): (&str, &str, Pick, Pick, &str, Pick) =
        match step.axis {
            LateralAxis::Roll => (
                "step_bank",
                "bank φ",
                |s| s.bank_deg,
                |s| s.bank_command_deg,
                "sideslip β",
                |s| s.sideslip_deg,
            ),
            LateralAxis::Yaw => (
                "step_sideslip",
                "sideslip β",
                |s| s.sideslip_deg,
                |s| s.sideslip_command_deg,
                "bank φ",
                |s| s.bank_deg,
            ),
        };
    let mut panel = Panel::new(
        format!(
            "{name} command of {:+}° (jerk-limited) with {controllers}, {conditions_text}",
            step.step_deg
        ),
        "time (s)",
        format!("{name} (deg)"),
    );
    for (index, run) in runs.iter().enumerate() {
        let settled = match (run.result.settled, run.result.settling_time_s) {
            (true, Some(t)) => format!("settled (±5 %) in {t:.3} s"),
            _ => "not settled (±5 %)".to_owned(),
        };
        panel = panel
            .styled_series(
                format!("{name}, {}", run.choice.label()),
                series(&run.samples, angle),
                None,
                (index > 0).then_some((10, 6)),
            )
            .styled_series(
                format!("{other_name}, {}", run.choice.label()),
                series(&run.samples, other),
                None,
                Some((2, 4)),
            )
            .note(format!("{}: {settled}", run.choice.label()));
    }
    if let Some(run) = runs.first() {
        panel = panel.styled_series("command", series(&run.samples, command), None, Some((3, 3)));
        let target = run.samples.first().map_or(0.0, command) + step.step_deg;
        let band = LATERAL_SETTLING_BAND_FRACTION * step.step_deg.abs();
        panel = panel
            .reference_line("target ± 5 % of the step", target + band)
            .reference_line("target ± 5 % of the step", target - band);
    }
    let mut surfaces = Panel::new(
        format!(
            "Aileron and rudder during the {:+}° step with {controllers}",
            step.step_deg
        ),
        "time (s)",
        "surface (deg; aileron right wing down, rudder trailing edge left)",
    );
    for (index, run) in runs.iter().enumerate() {
        let dash = (index > 0).then_some((10, 6));
        surfaces = surfaces
            .styled_series(
                format!("δa, {}", run.choice.label()),
                series(&run.samples, |s| s.aileron_deg),
                None,
                dash,
            )
            .styled_series(
                format!("δr, {}", run.choice.label()),
                series(&run.samples, |s| s.rudder_deg),
                None,
                dash,
            );
    }
    vec![
        (stem, Figure::new().panel(panel)),
        ("step_surfaces", Figure::new().panel(surfaces)),
    ]
}
