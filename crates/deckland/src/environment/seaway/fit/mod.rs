//! The time-domain (Markov) model of each motion, fitted to its encounter spectrum
//! (docs/model.md §12, "Time domain").
//!
//! **Target.** For a motion with amplitude per unit wave amplitude H(ω, μ) (module `hull`),
//! its one-sided spectrum over the encounter frequency is
//! Φ(ω_e) = Σ_j w_j Σ_branches |H(ω, μ_j)|²·S(ω)/|dω_e/dω| (m²·s/rad or rad²·s/rad), the
//! directions μ_j and weights w_j of the spreading ([`SeawayParameters::directions`]),
//! sampled at the midpoints of 4000 cells over (0, ω_e(3 rad/s, head seas)]. Its variance
//! is the midpoint sum; an independent check integrates |H|²·S over the wave frequency
//! instead (a test).
//!
//! **Model and method: a sum of band-pass resonant sections**, each a damped oscillator
//! squared, H_k(s) = g_k·ω_k²·s/(s² + 2ζ_kω_k s + ω_k²)², driven by its own unit-intensity
//! white noise, the sections independent, so the model's spectrum is the sum
//! Σ g_k²|H_k(iω)|²/π (one-sided, unit intensity E[w(t)w(s)] = δ(t − s)). Why this form:
//! - every section is stable and its spectrum is a wave-like band (rising as ω² from zero
//!   frequency, a peak near ω_k, falling as ω⁻⁶), so any fit is a valid spectral density,
//!   and the fit is linear in the weights g_k² once the poles are chosen: a non-negative
//!   least-squares fit of the spectrum's shape, searched exhaustively over a grid of
//!   centres and damping ratios for one or two sections (4 or 8 states). A log-magnitude
//!   fit of a general rational function is nonlinear, may return unstable or
//!   non-minimum-phase factors, and needs an optimiser this crate does not have;
//! - each section has relative degree 3 (C·B = 0, C·A·B = 0), so the motion, its rate and
//!   its acceleration (C·A²·x) all have finite variance, which the issue asks of the deck;
//!   only the jerk sees the white noise. Relative degree 2 would not do: then ÿ = C A² x +
//!   (C A B) w has white noise in it and infinite variance, the fault of the paper's pitch
//!   filter 0.773·s²/D(s) (docs/model.md §12);
//! - the two sections separate a narrow roll resonance from the broad wave-frequency part
//!   of roll, and the heave and pitch peaks need no more.
//!
//! The fit minimises the squared spectral error on 300 points spanning the target's energy
//! (its 0.2–99.8 % quantiles, widened by 1.5 each way); the weights are then scaled so that
//! the model's stationary variance (Lyapunov equation, `environment::lyapunov`) equals the
//! target's. [`FitReport`] gives the variance ratio and the shape error
//! ∫|Φ_model − Φ|dω_e / ∫Φ dω_e (0 for a perfect fit, at most 2).

use nalgebra::{DMatrix, DVector};

use super::spectrum::encounter_branches;
use super::{HullParameters, SeawayError, SeawayParameters, WaveSpectrum};
use crate::environment::lyapunov::stationary_covariance;

/// Wave frequency (rad/s) above which the target spectrum is not sampled: a 317-m hull
/// does not answer waves shorter than about 7 m.
const WAVE_FREQUENCY_CUTOFF_RADPS: f64 = 3.0;
/// Cells of the target's encounter-frequency grid.
const TARGET_CELLS: usize = 4000;
/// Points of the least-squares fit.
const FIT_POINTS: usize = 300;
/// Candidate centre frequencies of the sections.
const CANDIDATE_CENTRES: usize = 24;
/// Candidate damping ratios of the sections.
const CANDIDATE_DAMPING: [f64; 9] = [0.04, 0.06, 0.09, 0.13, 0.18, 0.25, 0.35, 0.5, 0.7];

/// One of the three motions the seaway model fits.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Motion {
    /// Heave of the centre of gravity (m, positive up).
    Heave,
    /// Pitch (rad, positive bow-up).
    Pitch,
    /// Roll (rad, positive starboard side down).
    Roll,
}

impl Motion {
    /// The three motions in order.
    pub const ALL: [Motion; 3] = [Motion::Heave, Motion::Pitch, Motion::Roll];

    /// The motion's name ("heave", "pitch", "roll").
    pub fn name(self) -> &'static str {
        match self {
            Motion::Heave => "heave",
            Motion::Pitch => "pitch",
            Motion::Roll => "roll",
        }
    }

    /// This motion's amplitude per unit wave amplitude (m/m or rad/m) at ω and μ.
    fn amplitude(self, hull: &HullParameters, omega_radps: f64, heading_rad: f64) -> f64 {
        let amplitudes = hull.amplitudes(omega_radps, heading_rad);
        match self {
            Motion::Heave => amplitudes.heave,
            Motion::Pitch => amplitudes.pitch,
            Motion::Roll => amplitudes.roll,
        }
    }
}

/// A motion's target spectrum over the encounter frequency (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct MotionTarget {
    /// The motion.
    pub motion: Motion,
    /// Width of each cell (rad/s).
    pub cell_width_radps: f64,
    /// Encounter frequencies at the cells' midpoints (rad/s).
    pub encounter_radps: Vec<f64>,
    /// One-sided spectral density there (m²·s/rad for heave, rad²·s/rad for pitch and roll).
    pub density: Vec<f64>,
}

impl MotionTarget {
    /// The target's variance, the midpoint sum Σ Φ·Δω_e (m² or rad²).
    pub fn variance(&self) -> f64 {
        self.density.iter().sum::<f64>() * self.cell_width_radps
    }

    /// The density at ω_e (rad/s) by linear interpolation between midpoints (0 outside).
    pub fn interpolate(&self, omega_e: f64) -> f64 {
        let position = omega_e / self.cell_width_radps - 0.5;
        if position < 0.0 || position >= (self.density.len() - 1) as f64 {
            return 0.0;
        }
        let index = position.floor() as usize;
        let fraction = position - index as f64;
        self.density[index] * (1.0 - fraction) + self.density[index + 1] * fraction
    }

    /// The encounter frequency below which a share `fraction` of the variance lies (rad/s).
    fn quantile(&self, fraction: f64) -> f64 {
        let total: f64 = self.density.iter().sum();
        let mut cumulative = 0.0;
        for (omega_e, density) in self.encounter_radps.iter().zip(&self.density) {
            cumulative += density;
            if cumulative >= fraction * total {
                return *omega_e;
            }
        }
        *self.encounter_radps.last().unwrap_or(&0.0)
    }
}

/// The target spectrum |H|²·S_e of `motion` for these (validated) parameters (module docs).
pub fn motion_target(
    parameters: &SeawayParameters,
    motion: Motion,
) -> Result<MotionTarget, SeawayError> {
    parameters.validate()?;
    let spectrum: WaveSpectrum = parameters.wave_spectrum()?;
    let hull = &parameters.hull;
    let speed = hull.speed_mps;
    let upper =
        super::encounter_frequency(WAVE_FREQUENCY_CUTOFF_RADPS, speed, std::f64::consts::PI);
    let width = upper / TARGET_CELLS as f64;
    let directions = parameters.directions();
    let encounter_radps: Vec<f64> = (0..TARGET_CELLS)
        .map(|i| width * (i as f64 + 0.5))
        .collect();
    let density = encounter_radps
        .iter()
        .map(|&omega_e| {
            directions
                .iter()
                .map(|&(heading, weight)| {
                    encounter_branches(omega_e, speed, heading)
                        .iter()
                        .filter(|b| b.jacobian > 1e-6)
                        .map(|b| {
                            let omega = b.wave_frequency_radps;
                            motion.amplitude(hull, omega, heading).powi(2) * spectrum.density(omega)
                                / b.jacobian
                        })
                        .sum::<f64>()
                        * weight
                })
                .sum()
        })
        .collect();
    Ok(MotionTarget {
        motion,
        cell_width_radps: width,
        encounter_radps,
        density,
    })
}

/// One band-pass section H(s) = g·ω₀²·s/(s² + 2ζω₀s + ω₀²)² (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ResonantSection {
    /// Centre (natural) frequency ω₀ (rad/s).
    pub centre_frequency_radps: f64,
    /// Damping ratio ζ of each of the two oscillator factors.
    pub damping_ratio: f64,
    /// Gain g (output units per unit-intensity noise, e.g. m·s^{1/2}).
    pub gain: f64,
}

impl ResonantSection {
    /// The one-sided output spectrum |H(iω)|²/π of unit-intensity white noise at ω (rad/s).
    pub fn spectral_density(&self, omega_radps: f64) -> f64 {
        let w0 = self.centre_frequency_radps;
        let real = w0 * w0 - omega_radps * omega_radps;
        let imaginary = 2.0 * self.damping_ratio * w0 * omega_radps;
        let magnitude2 = (real * real + imaginary * imaginary).powi(2);
        (self.gain * w0 * w0 * omega_radps).powi(2) / magnitude2 / std::f64::consts::PI
    }

    /// Coefficients (d₀, d₁, d₂, d₃) of (s² + 2ζω₀s + ω₀²)² = s⁴ + d₃s³ + d₂s² + d₁s + d₀.
    pub fn denominator(&self) -> [f64; 4] {
        let (w0, zeta) = (self.centre_frequency_radps, self.damping_ratio);
        [
            w0.powi(4),
            4.0 * zeta * w0.powi(3),
            2.0 * w0 * w0 + 4.0 * zeta * zeta * w0 * w0,
            4.0 * zeta * w0,
        ]
    }
}

/// A linear model ẋ = A x + B w, y = C x, w unit-intensity white noise (one per section).
#[derive(Debug, Clone, PartialEq)]
pub struct MarkovModel {
    sections: Vec<ResonantSection>,
    a: DMatrix<f64>,
    b: DMatrix<f64>,
    c: DMatrix<f64>,
}

/// The exact discretisation of a [`MarkovModel`] over one step: x_{k+1} = Φ x_k + L n_k,
/// n_k ~ N(0, I).
#[derive(Debug, Clone, PartialEq)]
pub struct ExactDiscretisation {
    /// The transition Φ = e^{A·dt}.
    pub transition: DMatrix<f64>,
    /// A factor L of the step's noise covariance Q_d = P − Φ P Φᵀ = L Lᵀ.
    pub noise_factor: DMatrix<f64>,
    /// A factor of the stationary covariance P, to start a run in steady state.
    pub stationary_factor: DMatrix<f64>,
}

impl MarkovModel {
    /// The model of these sections, each in controllable canonical form, block-diagonal:
    /// section k's states (z, ż, z̈, z⃛) with z = w_k/D_k(s), output g_k·ω_k²·ż.
    pub fn from_sections(sections: Vec<ResonantSection>) -> Self {
        let n = 4 * sections.len();
        let mut a = DMatrix::zeros(n, n);
        let mut b = DMatrix::zeros(n, sections.len());
        let mut c = DMatrix::zeros(1, n);
        for (k, section) in sections.iter().enumerate() {
            let offset = 4 * k;
            for i in 0..3 {
                a[(offset + i, offset + i + 1)] = 1.0;
            }
            for (j, d) in section.denominator().iter().enumerate() {
                a[(offset + 3, offset + j)] = -d;
            }
            b[(offset + 3, k)] = 1.0;
            c[(0, offset + 1)] = section.gain * section.centre_frequency_radps.powi(2);
        }
        Self { sections, a, b, c }
    }

    /// The sections.
    pub fn sections(&self) -> &[ResonantSection] {
        &self.sections
    }

    /// The state matrix A.
    pub fn a(&self) -> &DMatrix<f64> {
        &self.a
    }

    /// The noise input matrix B (one column per unit-intensity noise).
    pub fn b(&self) -> &DMatrix<f64> {
        &self.b
    }

    /// The output row C (y = C x).
    pub fn c(&self) -> &DMatrix<f64> {
        &self.c
    }

    /// The number of states.
    pub fn state_dimension(&self) -> usize {
        self.a.nrows()
    }

    /// The output's one-sided spectrum Σ g_k²|H_k(iω)|²/π at ω (rad/s).
    pub fn spectral_density(&self, omega_radps: f64) -> f64 {
        self.sections
            .iter()
            .map(|s| s.spectral_density(omega_radps))
            .sum()
    }

    /// The stationary state covariance P (A P + P Aᵀ + B Bᵀ = 0); `None` if A is unstable.
    pub fn stationary_covariance(&self) -> Option<DMatrix<f64>> {
        stationary_covariance(&self.a, &self.b)
    }

    /// The rows reading the output, its rate and its acceleration from the state: C, C A and
    /// C A² (exact, since C B = C A B = 0: no noise feeds through to the acceleration).
    pub fn output_rows(&self) -> [DMatrix<f64>; 3] {
        let rate_row = &self.c * &self.a;
        let acceleration_row = &rate_row * &self.a;
        [self.c.clone(), rate_row, acceleration_row]
    }

    /// Stationary variances of the output, its rate (C A x) and its acceleration (C A² x),
    /// finite because C B = C A B = 0; `None` if A is unstable.
    pub fn variances(&self) -> Option<[f64; 3]> {
        let p = self.stationary_covariance()?;
        let quadratic = |row: &DMatrix<f64>| (row * &p * row.transpose())[(0, 0)];
        Some(self.output_rows().map(|row| quadratic(&row)))
    }

    /// The exact discretisation over `dt_s` seconds (dt > 0), by the matrix exponential and
    /// Q_d = P − Φ P Φᵀ, factored by a symmetric eigendecomposition (rounding clipped).
    pub fn discretise(&self, dt_s: f64) -> Option<ExactDiscretisation> {
        let p = self.stationary_covariance()?;
        let transition = (&self.a * dt_s).exp();
        let q = &p - &transition * &p * transition.transpose();
        Some(ExactDiscretisation {
            noise_factor: symmetric_factor(&q),
            stationary_factor: symmetric_factor(&p),
            transition,
        })
    }
}

/// L with L Lᵀ = M for a symmetric positive semi-definite M: V·diag(√max(λ, 0)).
fn symmetric_factor(m: &DMatrix<f64>) -> DMatrix<f64> {
    let symmetric = (m + m.transpose()) * 0.5;
    let eigen = symmetric.symmetric_eigen();
    let roots = DVector::from_iterator(
        eigen.eigenvalues.len(),
        eigen.eigenvalues.iter().map(|l| l.max(0.0).sqrt()),
    );
    &eigen.eigenvectors * DMatrix::from_diagonal(&roots)
}

/// How well one motion's model fits its target (module docs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FitReport {
    /// The motion.
    pub motion: Motion,
    /// The target's variance ∫Φ dω_e (m² or rad²).
    pub target_variance: f64,
    /// The model's stationary variance from the Lyapunov equation (m² or rad²).
    pub model_variance: f64,
    /// model_variance / target_variance.
    pub variance_ratio: f64,
    /// The least-squares fit's variance over the target's, before the variance is matched.
    pub least_squares_variance_ratio: f64,
    /// ∫|Φ_model − Φ|dω_e / ∫Φ dω_e after the variance is matched (0 perfect, ≤ 2).
    pub shape_error: f64,
    /// The model's acceleration variance (m²/s⁴ or rad²/s⁴), finite by construction.
    pub acceleration_variance: f64,
}

/// One motion's fitted model with its report.
#[derive(Debug, Clone, PartialEq)]
pub struct MotionModel {
    /// The state-space model.
    pub model: MarkovModel,
    /// The fit's report.
    pub report: FitReport,
}

/// Heave, pitch and roll models of the carrier in one seaway (module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct SeawayModel {
    /// The parameters fitted.
    pub parameters: SeawayParameters,
    /// Heave of the centre of gravity (m).
    pub heave: MotionModel,
    /// Pitch (rad).
    pub pitch: MotionModel,
    /// Roll (rad).
    pub roll: MotionModel,
}

impl SeawayModel {
    /// Fits heave, pitch and roll for these parameters; refuses invalid parameters and a
    /// motion with no energy, naming the key or motion.
    pub fn fit(parameters: &SeawayParameters) -> Result<Self, SeawayError> {
        Self::fit_with(parameters, 2)
    }

    /// As [`SeawayModel::fit`] with one section per motion (4 states each): the ship that
    /// a landing simulation flies, whose Kalman estimator and forecast use the same
    /// 4-state canonical filters as the paper's ship (docs/model.md §12).
    pub fn fit_single_section(parameters: &SeawayParameters) -> Result<Self, SeawayError> {
        Self::fit_with(parameters, 1)
    }

    /// One motion's model with at most `max_sections` sections (1 or 2); refuses a motion
    /// with no energy ([`SeawayError::NoEnergy`]).
    pub fn fit_motion(
        parameters: &SeawayParameters,
        motion: Motion,
        max_sections: usize,
    ) -> Result<MotionModel, SeawayError> {
        fit_motion(
            &motion_target(parameters, motion)?,
            parameters,
            max_sections,
        )
    }

    fn fit_with(parameters: &SeawayParameters, max_sections: usize) -> Result<Self, SeawayError> {
        let fit = |motion| {
            fit_motion(
                &motion_target(parameters, motion)?,
                parameters,
                max_sections,
            )
        };
        Ok(Self {
            parameters: *parameters,
            heave: fit(Motion::Heave)?,
            pitch: fit(Motion::Pitch)?,
            roll: fit(Motion::Roll)?,
        })
    }

    /// The three fit reports: heave, pitch, roll.
    pub fn reports(&self) -> [FitReport; 3] {
        [self.heave.report, self.pitch.report, self.roll.report]
    }
}

/// Fits one motion's target (module docs).
fn fit_motion(
    target: &MotionTarget,
    parameters: &SeawayParameters,
    max_sections: usize,
) -> Result<MotionModel, SeawayError> {
    let motion = target.motion;
    let target_variance = target.variance();
    if target_variance.is_nan() || target_variance <= 1e-16 {
        return Err(SeawayError::NoEnergy {
            motion: motion.name(),
            wave_heading_deg: parameters.wave_heading_deg,
            variance: target_variance,
        });
    }
    let failed = |reason: &str| SeawayError::FitFailed {
        motion: motion.name(),
        reason: reason.to_owned(),
    };
    let sections =
        least_squares_sections(target, max_sections).ok_or_else(|| failed("no candidate fits"))?;
    let least_squares = MarkovModel::from_sections(sections.clone());
    let [ls_variance, ..] = least_squares
        .variances()
        .ok_or_else(|| failed("unstable"))?;
    let scale = (target_variance / ls_variance).sqrt();
    let scaled = sections
        .into_iter()
        .map(|s| ResonantSection {
            gain: s.gain * scale,
            ..s
        })
        .collect();
    let model = MarkovModel::from_sections(scaled);
    let [model_variance, _, acceleration_variance] =
        model.variances().ok_or_else(|| failed("unstable"))?;
    let error: f64 = target
        .encounter_radps
        .iter()
        .zip(&target.density)
        .map(|(&w, &d)| (model.spectral_density(w) - d).abs())
        .sum::<f64>()
        * target.cell_width_radps;
    let report = FitReport {
        motion,
        target_variance,
        model_variance,
        variance_ratio: model_variance / target_variance,
        least_squares_variance_ratio: ls_variance / target_variance,
        shape_error: error / target_variance,
        acceleration_variance,
    };
    Ok(MotionModel { model, report })
}

/// The best one or (`max_sections` ≥ 2) two sections by non-negative least squares over
/// the candidate grid.
fn least_squares_sections(
    target: &MotionTarget,
    max_sections: usize,
) -> Option<Vec<ResonantSection>> {
    let (low, high) = (target.quantile(0.002) / 1.5, target.quantile(0.998) * 1.5);
    let points: Vec<f64> = (0..FIT_POINTS)
        .map(|i| low + (high - low) * (i as f64 + 0.5) / FIT_POINTS as f64)
        .collect();
    let values: Vec<f64> = points.iter().map(|&w| target.interpolate(w)).collect();
    let (centre_low, centre_high) = (target.quantile(0.01), target.quantile(0.99));
    let mut candidates = Vec::new();
    for i in 0..CANDIDATE_CENTRES {
        let fraction = i as f64 / (CANDIDATE_CENTRES - 1) as f64;
        let centre = centre_low * (centre_high / centre_low).powf(fraction);
        for &damping_ratio in &CANDIDATE_DAMPING {
            candidates.push(ResonantSection {
                centre_frequency_radps: centre,
                damping_ratio,
                gain: 1.0,
            });
        }
    }
    let basis: Vec<Vec<f64>> = candidates
        .iter()
        .map(|s| points.iter().map(|&w| s.spectral_density(w)).collect())
        .collect();
    let dot = |x: &[f64], y: &[f64]| x.iter().zip(y).map(|(a, b)| a * b).sum::<f64>();
    let gram_diagonal: Vec<f64> = basis.iter().map(|b| dot(b, b)).collect();
    let projections: Vec<f64> = basis.iter().map(|b| dot(b, &values)).collect();
    // Residual ‖t − Σ wᵢbᵢ‖² = ‖t‖² − Σ wᵢ(bᵢ·t) at the least-squares weights; maximise the
    // explained part Σ wᵢ(bᵢ·t) over single sections and pairs with positive weights.
    let mut best: Option<(f64, Vec<(usize, f64)>)> = None;
    let mut consider = |explained: f64, choice: Vec<(usize, f64)>| {
        if best.as_ref().is_none_or(|(e, _)| explained > *e) {
            best = Some((explained, choice));
        }
    };
    for i in 0..candidates.len() {
        if projections[i] > 0.0 && gram_diagonal[i] > 0.0 {
            let weight = projections[i] / gram_diagonal[i];
            consider(weight * projections[i], vec![(i, weight)]);
        }
        let pairs = if max_sections >= 2 {
            i + 1
        } else {
            candidates.len()
        };
        for j in pairs..candidates.len() {
            let g_ij = dot(&basis[i], &basis[j]);
            let determinant = gram_diagonal[i] * gram_diagonal[j] - g_ij * g_ij;
            if determinant <= 1e-9 * gram_diagonal[i] * gram_diagonal[j] {
                continue;
            }
            let w_i = (gram_diagonal[j] * projections[i] - g_ij * projections[j]) / determinant;
            let w_j = (gram_diagonal[i] * projections[j] - g_ij * projections[i]) / determinant;
            if w_i > 0.0 && w_j > 0.0 {
                consider(
                    w_i * projections[i] + w_j * projections[j],
                    vec![(i, w_i), (j, w_j)],
                );
            }
        }
    }
    let (_, choice) = best?;
    Some(
        choice
            .into_iter()
            .map(|(i, weight)| ResonantSection {
                gain: weight.sqrt(),
                ..candidates[i]
            })
            .collect(),
    )
}

#[cfg(test)]
mod tests;
