//! The O-PD's design procedure for the real stabilator: gains, observer bandwidth and
//! fed-back attitude chosen from the elevator's rate and travel, the sensor noise and the
//! loop margins with the actuator in the loop (docs/stabilator-design.md; docs/model.md
//! §2.6, §3.3, §4–5). It uses the law-agnostic design code ([`crate::control::design`])
//! on the O-PD's linear form ([`super::linear_observer_pd`]).
//!
//! The paper's rule (Eq. 31–34) picks K_P, K_D from a settling time alone and ignores the
//! elevator. Here the structure stays the paper's — augmented observer, PD on the
//! attitude error, cancellation of the estimated disturbance (Eq. 30–36) — and three
//! things are designed for the hardware:
//!
//! 1. **Command shaping**, [`design_command`] (its criterion is in the design module's
//!    docs).
//! 2. **Feedback.** The error dynamics' settling time T_2% (ζ = 1), the observer's ε and
//!    the attitude fed back (measured or estimated) are searched on a grid; a candidate
//!    is admissible when, on the reduced linear loop with the actuator
//!    ([`assess_loop`]), the phase and gain margins at the elevator command meet their
//!    targets, the closed loop θ/θ_ref lags the outer (sink-rate) loop's crossover by no
//!    more than the allowed phase, and the elevator rate driven by the sensor noise (its
//!    white part and its sinusoid) stays within a fraction of the rate limit, and the
//!    describing function of the rate limit predicts no limit cycle below a multiple of
//!    the travel to the nearer stop (the smallest such cycle is the excitation threshold
//!    of a rate-limit oscillation; the default multiple 3 separates the gains that
//!    diverged in adverse approaches from those that did not,
//!    docs/stabilator-design.md). Among the admissible candidates the fastest error
//!    dynamics (smallest T_2%) win, then the least noise-driven elevator rate.
//! 3. **Refusal.** When no candidate is admissible the error names the requirement that
//!    failed for the candidate closest to meeting all of them.

use super::{ObserverPdGains, ObserverPdParameters, PitchFeedback};
use crate::control::design::command_shaping::JerkLimitedStep;
use crate::control::LinearLaw;
use crate::control::design::{
    assess_loop, check_request, design_command, nearer_stop_travel_rad, shortfalls,
    LoopAssessment, DesignError, DesignRequest, AxisHardware, AxisPlantDerivatives,
    SensorNoise,
};
use crate::estimation::ObserverParameters;

#[cfg(test)]
mod tests;

/// The O-PD in its linear limit about trim (docs/model.md §4–5 with the observer's
/// α1 → 1, the same k1, k2, k3, ε), as the design code's [`LinearLaw`]: states x1, x2, x3,
///
/// ```text
/// e = x1 − y;  ẋ1 = x2 − β1·e;  ẋ2 = x3 + M_q·x2 + M_δ·δ − β2·e;  ẋ3 = −β3·e
/// u = (K_P·(r − θ_fb) − K_D·x2 − x3)/M_δ,  θ_fb = y or x1
/// β1 = k3/ε, β2 = k2/ε², β3 = k1/ε³
/// ```
pub fn linear_observer_pd(
    gains: &ObserverPdGains,
    observer: &ObserverParameters,
    feedback: PitchFeedback,
    plant: AxisPlantDerivatives,
) -> LinearLaw {
    let (mq, md) = (plant.rate_damping_per_s, plant.control_power_per_s2);
    let eps = observer.epsilon;
    let betas = [
        observer.k3 / eps,
        observer.k2 / (eps * eps),
        observer.k1 / (eps * eps * eps),
    ];
    let (kp, kd) = (gains.proportional_per_s2, gains.derivative_per_s);
    // Each observer state sees −β·(x1 − y); the estimate's rate x2 also sees M_q·x2 + M_δ·δ.
    let mut input_matrix = [[0.0; LinearLaw::INPUTS]; LinearLaw::MAX_STATES];
    for (row, beta) in input_matrix.iter_mut().zip(betas) {
        row[LinearLaw::MEASURED_ANGLE] = beta;
    }
    input_matrix[1][LinearLaw::SURFACE] = md;
    let mut output_inputs = [0.0; LinearLaw::INPUTS];
    output_inputs[LinearLaw::COMMAND] = kp / md;
    let mut output_states = [0.0, -kd / md, -1.0 / md];
    match feedback {
        PitchFeedback::Measured => output_inputs[LinearLaw::MEASURED_ANGLE] = -kp / md,
        PitchFeedback::ObserverEstimate => output_states[0] = -kp / md,
    }
    LinearLaw {
        state_matrix: [
            [-betas[0], 1.0, 0.0],
            [-betas[1], mq, 1.0],
            [-betas[2], 0.0, 0.0],
        ],
        input_matrix,
        output_states,
        output_inputs,
    }
}

/// The designed O-PD pitch loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PitchDesign {
    /// The feedback chosen, with its assessment.
    pub feedback: FeedbackAssessment,
    /// The design step's shaped trajectory (jerk, acceleration bounds inside).
    pub command: JerkLimitedStep,
    /// Its settling time: trajectory duration plus the actuator's lag 2ζ_a/ω_a (s).
    pub command_settling_time_s: f64,
}

/// What a candidate O-PD feedback achieves on the reduced linear loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeedbackAssessment {
    /// The O-PD parameters assessed.
    pub parameters: ObserverPdParameters,
    /// K_P, K_D from them.
    pub gains: ObserverPdGains,
    /// The loop they close.
    pub assessment: LoopAssessment,
}

/// Assesses one O-PD feedback on the reduced linear loop; `None` when its gains cannot be
/// designed (a non-finite gain).
pub fn assess_feedback(
    hardware: &AxisHardware,
    noise: &SensorNoise,
    parameters: &ObserverPdParameters,
    outer_loop_crossover_radps: f64,
) -> Option<FeedbackAssessment> {
    let gains = ObserverPdGains::design(
        parameters.settling_time_s,
        parameters.damping_ratio,
        hardware.plant.rate_damping_per_s,
    )
    .ok()?;
    let law = linear_observer_pd(
        &gains,
        &parameters.observer,
        parameters.pitch_feedback,
        hardware.plant,
    );
    Some(FeedbackAssessment {
        parameters: *parameters,
        gains,
        assessment: assess_loop(hardware, noise, &law, outer_loop_crossover_radps),
    })
}

/// Error-dynamics settling times T_2% searched (s).
const SETTLING_TIMES_S: [f64; 14] = [
    0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0, 2.2, 2.5, 3.0,
];
/// Observer bandwidth parameters ε searched.
const EPSILONS: [f64; 7] = [0.05, 0.1, 0.15, 0.2, 0.3, 0.4, 0.5];

/// Designs the O-PD for `hardware` and `noise` to meet `request` (module docs).
pub fn design_observer_pd(
    hardware: &AxisHardware,
    noise: &SensorNoise,
    request: &DesignRequest,
) -> Result<PitchDesign, DesignError> {
    check_request(hardware, request)?;
    let (command, command_settling_time_s) = design_command(hardware, request)?;
    let rate_limit_radps = hardware
        .actuator
        .rate_limit_degps
        .map_or(f64::INFINITY, f64::to_radians);
    let travel_rad = nearer_stop_travel_rad(hardware);
    let mut best: Option<(f64, FeedbackAssessment)> = None;
    let mut closest: Option<(f64, FeedbackAssessment)> = None;
    for settling_time_s in SETTLING_TIMES_S {
        for epsilon in EPSILONS {
            for pitch_feedback in [PitchFeedback::ObserverEstimate, PitchFeedback::Measured] {
                let parameters = ObserverPdParameters {
                    settling_time_s,
                    damping_ratio: 1.0,
                    pitch_feedback,
                    observer: ObserverParameters {
                        epsilon,
                        ..request.observer
                    },
                };
                let Some(candidate) = assess_feedback(
                    hardware,
                    noise,
                    &parameters,
                    request.outer_loop_crossover_radps,
                ) else {
                    continue;
                };
                if candidate.assessment.closed_loop_max_real_part >= 0.0 {
                    continue;
                }
                let gaps = shortfalls(
                    &candidate.assessment,
                    request,
                    rate_limit_radps,
                    travel_rad,
                );
                let total: f64 = gaps.iter().map(|g| g.3).sum();
                if total == 0.0 {
                    // Fastest first (T_2% dominates), then quietest.
                    let score = settling_time_s * 1e3
                        + candidate.assessment.noise.surface_rate_rms_radps;
                    if best.is_none_or(|(s, _)| score < s) {
                        best = Some((score, candidate));
                    }
                } else if closest.is_none_or(|(s, _)| total < s) {
                    closest = Some((total, candidate));
                }
            }
        }
    }
    if let Some((_, feedback)) = best {
        return Ok(PitchDesign {
            feedback,
            command,
            command_settling_time_s,
        });
    }
    let Some((_, candidate)) = closest else {
        return Err(DesignError::NoFeasibleFeedback {
            limiting: "closed-loop stability",
            best: f64::NAN,
            required: 0.0,
        });
    };
    let worst = shortfalls(
        &candidate.assessment,
        request,
        rate_limit_radps,
        travel_rad,
    )
        .into_iter()
        .fold(("", 0.0, 0.0, -1.0), |w, g| if g.3 > w.3 { g } else { w });
    Err(DesignError::NoFeasibleFeedback {
        limiting: worst.0,
        best: worst.1,
        required: worst.2,
    })
}
