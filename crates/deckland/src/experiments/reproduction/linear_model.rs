//! Trim, the linear model and its modes (paper Table 3, Eq. 14), the O-PD gains
//! (§4.2.2), and the open-loop throttle step of Fig. 6.

use nalgebra::SMatrix;

use super::paper::{PAPER_A, PAPER_B};
use super::{ReproductionError, OPEN_LOOP_SAMPLE_INTERVAL_S, OPEN_LOOP_TIME_STEP_S, THROTTLE_STEP};
use crate::aircraft::{AerodynamicConfiguration, Aircraft};
use crate::analysis::{
    identify_modes, linearize, open_loop_step_responses, trim, InputStep, LinearModel, Mode,
    ModeKind, OpenLoopSample, TrimPoint, TrimRequest,
};
use crate::control::pitch::{ObserverPdGains, ObserverPdParameters};

/// The landing aircraft trimmed and linearised, the clean data's trim, the paper's
/// printed A analysed, and the O-PD gains designed from the linear model.
#[derive(Debug, Clone)]
pub struct LinearModelStudy {
    /// The default (landing configuration) aircraft.
    pub aircraft: Aircraft,
    /// Its level trim at the paper's speed.
    pub trim: TrimPoint,
    /// Its linear model about the trim (paper Eq. 14 form).
    pub model: LinearModel,
    /// The modes of the linear model.
    pub modes: Vec<Mode>,
    /// The trim of the clean (no-flap) data the paper says it uses, or why there is none.
    pub clean_trim: Result<TrimPoint, String>,
    /// The modes of the paper's printed A.
    pub paper_a_modes: Vec<Mode>,
    /// The O-PD gains of the paper's design (settling time, damping) with this model's
    /// pitch damping.
    pub gains: ObserverPdGains,
}

/// Trims and linearises the landing aircraft, trims the clean data, finds the modes of
/// the paper's printed A and designs the O-PD gains.
pub fn study_linear_model() -> Result<LinearModelStudy, ReproductionError> {
    let aircraft = Aircraft::default();
    let trim_point = trim(&aircraft, &TrimRequest::default()).map_err(ReproductionError::Trim)?;
    let model = linearize(&aircraft, &trim_point);
    let modes = identify_modes(&model.eigenvalues());
    let clean_trim = trim(
        &Aircraft::with_configuration(AerodynamicConfiguration::CLEAN),
        &TrimRequest::default(),
    )
    .map_err(|e| e.to_string());
    let paper_a = SMatrix::<f64, 4, 4>::from_fn(|i, j| PAPER_A[i][j]);
    let paper_a_modes = identify_modes(
        &paper_a
            .complex_eigenvalues()
            .iter()
            .copied()
            .collect::<Vec<_>>(),
    );
    let opd = ObserverPdParameters::paper();
    let gains = ObserverPdGains::design(
        opd.settling_time_s,
        opd.damping_ratio,
        model.pitch_damping_per_s(),
    )
    .map_err(ReproductionError::GainDesign)?;
    Ok(LinearModelStudy {
        aircraft,
        trim: trim_point,
        model,
        modes,
        clean_trim,
        paper_a_modes,
        gains,
    })
}

/// The mode of `kind` among `modes`.
fn mode(modes: &[Mode], kind: ModeKind) -> Option<&Mode> {
    modes.iter().find(|m| m.kind == kind)
}

/// |λ − λ_ref| / |λ_ref| of two modes' eigenvalues; NaN when either is missing.
fn relative_distance(mode: Option<&Mode>, reference: Option<&Mode>) -> f64 {
    match (mode, reference) {
        (Some(x), Some(y)) => (x.eigenvalue - y.eigenvalue).norm() / y.eigenvalue.norm(),
        _ => f64::NAN,
    }
}

impl LinearModelStudy {
    /// The lag of the flight path behind pitch (s): 1/|∂α̇/∂α| of the linear model.
    pub fn flight_path_lag_s(&self) -> f64 {
        1.0 / self.model.a[(2, 2)].abs()
    }

    /// The linear model's mode of `kind`.
    pub fn mode(&self, kind: ModeKind) -> Option<&Mode> {
        mode(&self.modes, kind)
    }

    /// The paper's printed A's mode of `kind`.
    pub fn paper_a_mode(&self, kind: ModeKind) -> Option<&Mode> {
        mode(&self.paper_a_modes, kind)
    }

    /// How far the linear model's eigenvalue of `kind` lies from the paper's printed A's,
    /// relative to the latter's magnitude (NaN when either lacks the mode).
    pub fn distance_from_paper_a(&self, kind: ModeKind) -> f64 {
        relative_distance(self.mode(kind), self.paper_a_mode(kind))
    }

    /// The smallest and largest |B_ours / B_paper| over the δe column's entries that the
    /// paper prints as nonzero: how many times the data's elevator effectiveness exceeds
    /// the paper's.
    pub fn elevator_column_ratio_range(&self) -> (f64, f64) {
        (0..4)
            .filter(|&i| PAPER_B[i][0] != 0.0)
            .map(|i| (self.model.b[(i, 0)] / PAPER_B[i][0]).abs())
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(low, high), r| {
                (low.min(r), high.max(r))
            })
    }
}

/// The open-loop throttle step of Fig. 6: the samples of both models and how well they
/// agree.
#[derive(Debug, Clone)]
pub struct OpenLoopStudy {
    /// The throttle step (fraction of the total maximum thrust).
    pub throttle_step: f64,
    /// Length of the record (s).
    pub seconds: f64,
    /// Both models' deviations from trim over time.
    pub samples: Vec<OpenLoopSample>,
    /// Worst |nonlinear − linear| over the step relative to the largest nonlinear
    /// excursion, per state (V_T, θ, α, q).
    pub relative_error: [f64; 4],
    /// The largest nonlinear excursion from trim per state (m/s, rad, rad, rad/s).
    pub excursion: [f64; 4],
}

/// Flies [`THROTTLE_STEP`] from the trim of `linear_model` for `seconds` with the
/// nonlinear airframe and its linear model.
pub fn study_open_loop(
    linear_model: &LinearModelStudy,
    seconds: f64,
) -> Result<OpenLoopStudy, ReproductionError> {
    let step = InputStep {
        elevator_rad: 0.0,
        throttle: THROTTLE_STEP,
    };
    let (_, samples) = open_loop_step_responses(
        &linear_model.aircraft,
        &linear_model.trim,
        step,
        seconds,
        OPEN_LOOP_TIME_STEP_S,
        OPEN_LOOP_SAMPLE_INTERVAL_S,
    )
    .map_err(ReproductionError::OpenLoop)?;
    let (relative_error, excursion) = open_loop_agreement(&samples);
    Ok(OpenLoopStudy {
        throttle_step: THROTTLE_STEP,
        seconds,
        samples,
        relative_error,
        excursion,
    })
}

/// Per state, the worst |nonlinear − linear| relative to the largest |nonlinear|
/// excursion (0 where the state did not move), and that excursion.
pub fn open_loop_agreement(samples: &[OpenLoopSample]) -> ([f64; 4], [f64; 4]) {
    let mut error = [0.0_f64; 4];
    let mut excursion = [0.0_f64; 4];
    for sample in samples {
        for i in 0..4 {
            error[i] = error[i].max((sample.nonlinear[i] - sample.linear[i]).abs());
            excursion[i] = excursion[i].max(sample.nonlinear[i].abs());
        }
    }
    let relative = std::array::from_fn(|i| {
        if excursion[i] > 0.0 {
            error[i] / excursion[i]
        } else {
            0.0
        }
    });
    (relative, excursion)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample(nonlinear: [f64; 4], linear: [f64; 4]) -> OpenLoopSample {
        OpenLoopSample {
            time_s: 0.0,
            nonlinear,
            linear,
        }
    }

    #[test]
    fn agreement_is_the_worst_error_over_the_largest_excursion() {
        // State 0: excursion 2, worst error 0.5 → 25 %; state 1 never moves → 0;
        // state 2: excursion |−4|, error 1 → 25 %; state 3: the linear model is twice
        // the nonlinear one → 100 %.
        let samples = [
            sample([1.0, 0.0, -4.0, 1.0], [0.5, 0.0, -3.0, 2.0]),
            sample([2.0, 0.0, -1.0, 0.5], [2.1, 0.0, -1.0, 1.0]),
        ];
        let (relative, excursion) = open_loop_agreement(&samples);
        assert_eq!(excursion, [2.0, 0.0, 4.0, 1.0]);
        assert_eq!(relative, [0.25, 0.0, 0.25, 1.0]);
    }

    #[test]
    fn the_paper_printed_a_gives_the_eigenvalues_computed_by_hand() {
        // Independent check, not through nalgebra: the characteristic polynomial of the
        // paper's printed A (Eq. 14), by Faddeev–LeVerrier in plain Python, is
        // λ⁴ + 0.92 λ³ + 0.4805766 λ² + 0.06256149 λ + 0.01045746; its roots, by
        // Durand–Kerner iteration, are −0.406142 ± 0.446576i and −0.053858 ± 0.160619i.
        let study = match study_linear_model() {
            Ok(study) => study,
            Err(error) => panic!("{error}"),
        };
        let short = study
            .paper_a_mode(ModeKind::ShortPeriod)
            .map(|m| m.eigenvalue);
        let phugoid = study.paper_a_mode(ModeKind::Phugoid).map(|m| m.eigenvalue);
        let near = |l: Option<nalgebra::Complex<f64>>, re: f64, im: f64| {
            l.is_some_and(|l| (l.re - re).abs() < 1e-5 && (l.im - im).abs() < 1e-5)
        };
        assert!(near(short, -0.406142, 0.446576), "{short:?}");
        assert!(near(phugoid, -0.053858, 0.160619), "{phugoid:?}");
        assert!(study.flight_path_lag_s() > 0.0);
        let (low, high) = study.elevator_column_ratio_range();
        assert!(low.is_finite() && high >= low, "{low} {high}");
    }
}
