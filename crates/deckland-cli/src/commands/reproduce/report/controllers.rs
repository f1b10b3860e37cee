//! The controllers' section (paper §4): the gains, designed or as given.

use deckland::control::pitch::{ObserverPdParameters, PidParameters};
use deckland::experiments::reproduction::paper::{PAPER_A, PAPER_GUIDANCE_GAINS};
use deckland::experiments::reproduction::SEED;
use deckland::scenario::Scenario;

use super::{row, stated, Findings, Section};

/// Paper §4: the gains.
pub(super) fn controllers(f: &Findings) -> Section {
    let opd = ObserverPdParameters::paper();
    let pid = PidParameters::paper();
    let scenario = Scenario::paper();
    let speed = scenario.control.speed;
    let sink = scenario.control.sink_rate;
    let guidance = scenario.control.guidance;
    let observer = opd.observer;
    let ended = |summary: &deckland::simulation::RunSummary| match &summary.reason {
        Some(reason) => format!("{} ({reason})", summary.outcome.name()),
        None => summary.outcome.name().to_string(),
    };
    let study = &f.reproduction.linear_model;
    let [paper_ideal, paper_adverse] = &f.reproduction.approach.paper_gains;
    let paper_gains_result = format!(
        "{} in ideal conditions, {} in adverse conditions (seed {SEED})",
        ended(paper_ideal),
        ended(paper_adverse)
    );
    Section {
        title: "Controllers (paper §4)",
        rows: vec![
            row(
                "O-PD design T_2% (s), ζ",
                stated("opd_design"),
                format!("{}, {:.4}", opd.settling_time_s, opd.damping_ratio),
                "used as given",
            ),
            row(
                "O-PD K_Pθ (1/s²)",
                stated("opd_kp"),
                format!("{:.2}", study.gains.proportional_per_s2),
                "K_P = ω_n², ω_n = 4/(T_2%·ζ)",
            ),
            row(
                "O-PD K_Dθ (1/s)",
                stated("opd_kd"),
                format!("{:.4}", study.gains.derivative_per_s),
                format!(
                    "K_D = 2ζω_n + ∂q̇/∂q with ours {:.3} /s (paper {}); Eq. 31/33 print the \
                     sign of ∂q̇/∂q the other way, the paper's number follows from this form",
                    study.model.pitch_damping_per_s(),
                    PAPER_A[3][3]
                ),
            ),
            row(
                "PID K_Pθ2, K_Iθ, K_Dθ2",
                stated("pid_gains"),
                format!(
                    "{}, {}, {}",
                    pid.proportional_per_s2, pid.integral_per_s3, pid.derivative_per_s
                ),
                "used as given, with anti-windup (the paper says nothing of saturation)",
            ),
            row(
                "velocity loop K_PV, K_IV, K_DV",
                stated("speed_gains"),
                format!(
                    "{:.3}, {:.4}, 0",
                    speed.proportional_per_s(),
                    speed.integral_per_s2()
                ),
                format!(
                    "designed from Eq. 41 for ω = {} rad/s, ζ = {} (engine lag {} s)",
                    speed.natural_frequency_radps,
                    speed.damping_ratio,
                    scenario.aircraft.engines.time_constant_s
                ),
            ),
            row(
                "sink-rate loop K_Ps, K_Is",
                stated("sink_gains"),
                format!(
                    "{}, {}",
                    sink.proportional_rad_per_mps, sink.integral_rad_per_m
                ),
                format!(
                    "**different by design**: an approach flown here with the paper's \
                     sink-rate and guidance gains ends {paper_gains_result}. Ours are chosen \
                     for bandwidth separation and boarding rate (docs/landing-design.md); the \
                     paper's set stays selectable"
                ),
            ),
            row(
                "guidance K_Pz, K_Iz, K_Dz",
                stated("guidance_gains"),
                format!(
                    "{}, {}, {}",
                    guidance.proportional_per_s, guidance.integral_per_s2, guidance.derivative
                ),
                format!(
                    "**different by design**: K_Pz = {} /s commands the sink-rate loop faster \
                     than its flight path follows ({:.1} s lag, below); see the row above",
                    PAPER_GUIDANCE_GAINS.0,
                    study.flight_path_lag_s()
                ),
            ),
            row(
                "observer k1, k2, k3, α1, ε",
                stated("observer"),
                format!(
                    "{}, {}, {}, {}, {}",
                    observer.k1, observer.k2, observer.k3, observer.alpha1, observer.epsilon
                ),
                "values chosen here (docs/model.md §4, docs/observer-bandwidth.md)",
            ),
        ],
    }
}
