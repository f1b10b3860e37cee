//! The two figures of the report that no other command draws: the aerodynamic
//! coefficients (paper Fig. 4) and the open-loop throttle step (Fig. 6).

use deckland::aircraft::{
    aerodynamic_coefficients, AerodynamicConfiguration, Aircraft, ALPHA_MAX_RAD, ALPHA_MIN_RAD,
};
use deckland::analysis::OpenLoopSample;

use crate::plot::{Figure, Panel};

/// Angle-of-attack samples of Fig. 4 (deg), every 0.25° over the model's range.
fn alpha_grid_deg() -> Vec<f64> {
    let (low, high) = (ALPHA_MIN_RAD.to_degrees(), ALPHA_MAX_RAD.to_degrees());
    let count = ((high - low) / 0.25).round() as usize;
    (0..=count).map(|i| low + 0.25 * i as f64).collect()
}

/// Paper Fig. 4: C_L, C_D and C_m against α at δe = q = 0, for the clean polynomial data
/// (the paper's) and this implementation's default landing configuration.
pub(crate) fn aerodynamic_coefficients_figure() -> Figure {
    let grid = alpha_grid_deg();
    let curve = |configuration: &AerodynamicConfiguration, pick: fn(f64, f64, f64) -> f64| {
        grid.iter()
            .map(|alpha_deg| {
                let c = aerodynamic_coefficients(alpha_deg.to_radians(), 0.0, 0.0, configuration);
                (*alpha_deg, pick(c.lift, c.drag, c.moment))
            })
            .collect::<Vec<_>>()
    };
    let clean = AerodynamicConfiguration::CLEAN;
    let landing = AerodynamicConfiguration::LANDING;
    let panel = |title: &str, y_label: &str, pick: fn(f64, f64, f64) -> f64| {
        Panel::new(title, "angle of attack α (deg)", y_label)
            .series("clean data (paper)", curve(&clean, pick))
            .series(
                "landing configuration (deckland default)",
                curve(&landing, pick),
            )
    };
    Figure::new()
        .title("F/A-18 aerodynamic coefficients at δe = 0, q = 0 (cf. paper Fig. 4)")
        .panel(panel("Lift coefficient", "C_L (–)", |l, _, _| l))
        .panel(panel("Drag coefficient", "C_D (–)", |_, d, _| d))
        .panel(
            panel(
                "Pitching-moment coefficient (about the CG)",
                "C_m (–)",
                |_, _, m| m,
            )
            .reference_line("zero", 0.0),
        )
}

/// Paper Fig. 6: the nonlinear airframe against the linear model after a throttle step,
/// one panel per state (deviations from trim).
pub(crate) fn open_loop_step(
    samples: &[OpenLoopSample],
    throttle: f64,
    aircraft: &Aircraft,
) -> Figure {
    let thrust_kn = throttle * aircraft.engines().max_total_thrust_n() / 1000.0;
    let states: [(&str, &str, f64); 4] = [
        ("Airspeed", "ΔV_T (m/s)", 1.0),
        ("Pitch angle", "Δθ (deg)", 180.0 / std::f64::consts::PI),
        ("Angle of attack", "Δα (deg)", 180.0 / std::f64::consts::PI),
        ("Pitch rate", "Δq (deg/s)", 180.0 / std::f64::consts::PI),
    ];
    let mut figure = Figure::new().title(format!(
        "Throttle step +{:.0} % (+{thrust_kn:.2} kN) from trim: nonlinear and linear (cf. paper Fig. 6)",
        throttle * 100.0
    ));
    for (index, (title, label, scale)) in states.into_iter().enumerate() {
        let points = |linear: bool| {
            samples
                .iter()
                .map(|s| {
                    let x = if linear { s.linear } else { s.nonlinear };
                    (s.time_s, scale * x[index])
                })
                .collect::<Vec<_>>()
        };
        figure = figure.panel(
            Panel::new(title, "time after the step (s)", label)
                .series("nonlinear", points(false))
                .series("linear (Eq. 14 form)", points(true)),
        );
    }
    figure
}
