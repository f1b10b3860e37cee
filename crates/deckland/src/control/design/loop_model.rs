//! A reduced linear model of an axis's attitude loop for design: plant (rate damping M_q
//! and control power M_δ; pitch θ, q, δe — roll φ, p, δa — yaw), surface actuator, the
//! angle-measurement noise and any law in its linear limit ([`LinearLaw`])
//! (docs/model.md §2.6, §3.3, §4, §5). Written below in the pitch axis's symbols.
//!
//! ```text
//! plant:     θ̇ = q,  q̇ = M_q·q + M_δ·δ + M_α·α      (M_q = ∂q̇/∂q, M_δ = ∂q̇/∂δe)
//!            α̇ = Z_α·α + q + Z_δ·δ                 (optional short-period coupling)
//! actuator:  δ̈ = ω_a²(u − δ) − 2ζ_a·ω_a·δ̇          (second order, no limits)
//! sensor:    y = θ + n
//! law:       ẋ_c = A_c·x_c + B_c·[r, y, q, δ],  u = C_c·x_c + D_c·[r, y, q, δ]
//! ```
//!
//! The laws give their own A_c, B_c, C_c, D_c: the O-PD with its augmented observer in its
//! linear limit (`observer_pd::linear_observer_pd`), the PID (`pid::linear_pid`), a
//! user's law through [`crate::control::AxisLaw::linear_law`].
//!
//! The angle of attack is optional ([`AngleOfAttackCoupling`]). Without it an observer's
//! model is exact, its estimates follow the plant whatever ε, and the O-PD's loop gain is
//! the ideal PD's; with it the observer must estimate M_α·Δα as a disturbance, which is
//! what makes ε matter for the margins (at the approach trim M_α = −0.26 s⁻²,
//! Z_α = −0.53 s⁻¹). The model answers the questions the design needs quickly and in
//! closed form — loop gain cut at the surface command (the cut of
//! `analysis::cascade_margins`), closed-loop transfer functions from the command and from
//! the sensor noise — and the full nonlinear linearisation stays the check
//! (docs/stabilator-design.md compares them). All quantities are deviations from trim, in
//! rad, rad/s, s.

use nalgebra::{Complex, SMatrix, SVector};

use super::plant::{AngleOfAttackCoupling, AxisPlantDerivatives, LinearActuator};
use crate::control::LinearLaw;

/// Which signal a closed-loop transfer function ends at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopOutput {
    /// True angle deviation (pitch θ, bank φ; rad).
    Angle,
    /// Surface position δ (rad).
    Surface,
    /// Surface rate δ̇ (rad/s).
    SurfaceRate,
}

/// Which signal a closed-loop transfer function starts at.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopInput {
    /// Angle command r (rad).
    Command,
    /// Angle-measurement error n (rad).
    SensorNoise,
}

/// Stability margins of a loop gain sampled on a frequency grid.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Margins {
    /// First gain crossover (rad/s).
    pub crossover_radps: Option<f64>,
    /// Phase margin there (deg).
    pub phase_margin_deg: Option<f64>,
    /// Smallest gain margin over the phase crossovers with |L| < 1 (dB); `None` if the
    /// phase never reaches −180° there (infinite gain margin).
    pub gain_margin_db: Option<f64>,
    /// Frequency of that gain margin (rad/s).
    pub phase_crossover_radps: Option<f64>,
}

/// The reduced loop of one axis: `x' = A x + B u + G w`, `u_c = C x + H w`, with the states
/// `[θ, q, δ, δ̇, c1, c2, c3, α]` (c: the controller's states) and `w = [r, n]`.
#[derive(Debug, Clone, PartialEq)]
pub struct AxisLoopModel {
    a: Matrix,
    b: Vector,
    g: SMatrix<f64, N, 2>,
    c: Vector,
    h: [f64; 2],
    /// A + B·Cᵀ: the loop closed (computed once).
    closed: Matrix,
}

const N: usize = 8;
/// Index of the law's first state.
const CONTROLLER: usize = 4;
type Matrix = SMatrix<f64, N, N>;
type Vector = SVector<f64, N>;

impl AxisLoopModel {
    /// Builds the model (docs/model.md §4–5 in their linear limit).
    pub fn new(
        plant: AxisPlantDerivatives,
        coupling: Option<AngleOfAttackCoupling>,
        actuator: LinearActuator,
        law: &LinearLaw,
    ) -> Self {
        let (mq, md) = (plant.rate_damping_per_s, plant.control_power_per_s2);
        let (wa, za) = (actuator.natural_frequency_radps, actuator.damping_ratio);
        let mut a = Matrix::zeros();
        let mut b = Vector::zeros();
        let mut g = SMatrix::<f64, N, 2>::zeros();
        let mut c = Vector::zeros();
        a[(0, 1)] = 1.0;
        a[(1, 1)] = mq;
        a[(1, 2)] = md;
        a[(2, 3)] = 1.0;
        a[(3, 2)] = -wa * wa;
        a[(3, 3)] = -2.0 * za * wa;
        b[3] = wa * wa;
        match coupling {
            Some(c) => {
                a[(7, 7)] = c.dalphadot_dalpha_per_s;
                a[(7, 1)] = 1.0;
                a[(7, 2)] = c.dalphadot_delevator_per_s;
                a[(1, 7)] = c.dqdot_dalpha_per_s2;
            }
            // A decoupled, stable placeholder: α never reaches the pitch dynamics.
            None => a[(7, 7)] = -1.0,
        }
        // The law's states are rows and columns 4, 5, 6; it sees the command r and the
        // sensor error n through G and H, θ (in y = θ + n), q and δ through A and C.
        for i in 0..LinearLaw::MAX_STATES {
            let row = CONTROLLER + i;
            for j in 0..LinearLaw::MAX_STATES {
                a[(row, CONTROLLER + j)] = law.state_matrix[i][j];
            }
            let input = law.input_matrix[i];
            g[(row, 0)] = input[LinearLaw::COMMAND];
            a[(row, 0)] = input[LinearLaw::MEASURED_ANGLE];
            g[(row, 1)] = input[LinearLaw::MEASURED_ANGLE];
            a[(row, 1)] = input[LinearLaw::RATE];
            a[(row, 2)] = input[LinearLaw::SURFACE];
            c[row] = law.output_states[i];
        }
        let direct = law.output_inputs;
        let h = [
            direct[LinearLaw::COMMAND],
            direct[LinearLaw::MEASURED_ANGLE],
        ];
        c[0] = direct[LinearLaw::MEASURED_ANGLE];
        c[1] = direct[LinearLaw::RATE];
        c[2] = direct[LinearLaw::SURFACE];
        let closed = a + b * c.transpose();
        Self {
            a,
            b,
            g,
            c,
            h,
            closed,
        }
    }

    /// Loop gain L(jω) = −C (jωI − A)⁻¹ B with the loop cut at the surface command
    /// (negative-feedback convention, as in `analysis::cascade_margins`).
    pub fn loop_gain(&self, omega_radps: f64) -> Complex<f64> {
        let x = solve(&self.a, &self.b, omega_radps);
        -dot(&self.c, &x)
    }

    /// Closed-loop transfer function from `input` to `output` at jω.
    pub fn closed_loop(
        &self,
        input: LoopInput,
        output: LoopOutput,
        omega_radps: f64,
    ) -> Complex<f64> {
        let column = match input {
            LoopInput::Command => 0,
            LoopInput::SensorNoise => 1,
        };
        let forcing = Vector::from_fn(|i, _| self.g[(i, column)] + self.b[i] * self.h[column]);
        let x = solve(&self.closed, &forcing, omega_radps);
        match output {
            LoopOutput::Angle => x[0],
            LoopOutput::Surface => x[2],
            LoopOutput::SurfaceRate => x[3],
        }
    }

    /// Largest real part of the closed loop's eigenvalues (1/s); negative means stable.
    pub fn closed_loop_max_real_part(&self) -> f64 {
        self.closed
            .complex_eigenvalues()
            .iter()
            .map(|l| l.re)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Margins of [`AxisLoopModel::loop_gain`] on `omegas` (rad/s, increasing).
    pub fn margins(&self, omegas: &[f64]) -> Margins {
        let gains: Vec<Complex<f64>> = omegas.iter().map(|&w| self.loop_gain(w)).collect();
        margins_of(omegas, &gains)
    }

    /// RMS (output's unit) of `output` driven by white sensor noise of standard deviation
    /// `sigma_rad` drawn every `sample_interval_s` and held (two-sided density
    /// σ²·T_s/(2π)·sinc²(ωT_s/2) per rad/s): √((σ²T_s/π)·∫₀^∞ |H(jω)|² sinc²(ωT_s/2) dω),
    /// integrated by the trapezoidal rule on a logarithmic grid to 100× the Nyquist
    /// frequency.
    pub fn white_noise_rms(
        &self,
        output: LoopOutput,
        sigma_rad: f64,
        sample_interval_s: f64,
    ) -> f64 {
        let nyquist = std::f64::consts::PI / sample_interval_s;
        let grid = log_grid(1e-3, 100.0 * nyquist, 4000);
        let density = |w: f64| {
            let x = 0.5 * w * sample_interval_s;
            let sinc = if x.abs() < 1e-12 { 1.0 } else { x.sin() / x };
            self.closed_loop(LoopInput::SensorNoise, output, w)
                .norm_sqr()
                * sinc
                * sinc
        };
        let mut integral = 0.0;
        let mut previous = (grid[0], density(grid[0]));
        for &w in &grid[1..] {
            let value = density(w);
            integral += 0.5 * (value + previous.1) * (w - previous.0);
            previous = (w, value);
        }
        (sigma_rad * sigma_rad * sample_interval_s / std::f64::consts::PI * integral).sqrt()
    }
}

/// `n` logarithmically spaced frequencies from `low` to `high` (rad/s).
pub fn log_grid(low: f64, high: f64, n: usize) -> Vec<f64> {
    let (a, b) = (low.ln(), high.ln());
    (0..n)
        .map(|k| (a + (b - a) * k as f64 / (n - 1) as f64).exp())
        .collect()
}

/// (jωI − A)⁻¹ b, or zero where jωI − A is singular.
fn solve(a: &Matrix, b: &Vector, omega: f64) -> SVector<Complex<f64>, N> {
    let mut m = SMatrix::<Complex<f64>, N, N>::from_fn(|i, j| Complex::new(-a[(i, j)], 0.0));
    for i in 0..N {
        m[(i, i)] += Complex::new(0.0, omega);
    }
    m.lu()
        .solve(&b.map(|v| Complex::new(v, 0.0)))
        .unwrap_or_else(SVector::zeros)
}

fn dot(c: &Vector, x: &SVector<Complex<f64>, N>) -> Complex<f64> {
    c.iter().zip(x.iter()).map(|(&c, &x)| x * c).sum()
}

/// Phase and gain margins of a loop gain sampled at increasing frequencies: the first
/// crossing of |L| = 1 from above, and the smallest −20 log|L| where the unwrapped phase
/// crosses −180° + k·360° with |L| < 1.
pub fn margins_of(omegas: &[f64], gains: &[Complex<f64>]) -> Margins {
    let mut phases = Vec::with_capacity(gains.len());
    let mut offset = 0.0;
    let mut previous = gains[0].arg().to_degrees();
    for (k, g) in gains.iter().enumerate() {
        let raw = g.arg().to_degrees();
        if k > 0 {
            if raw - previous > 180.0 {
                offset -= 360.0;
            } else if raw - previous < -180.0 {
                offset += 360.0;
            }
        }
        previous = raw;
        phases.push(raw + offset);
    }
    let db: Vec<f64> = gains.iter().map(|g| 20.0 * g.norm().log10()).collect();
    let mut margins = Margins {
        crossover_radps: None,
        phase_margin_deg: None,
        gain_margin_db: None,
        phase_crossover_radps: None,
    };
    let at = |k: usize, f: f64| (omegas[k].ln() + f * (omegas[k + 1].ln() - omegas[k].ln())).exp();
    for k in 0..omegas.len() - 1 {
        if db[k] >= 0.0 && db[k + 1] < 0.0 && margins.crossover_radps.is_none() {
            let f = db[k] / (db[k] - db[k + 1]);
            let phase = phases[k] + f * (phases[k + 1] - phases[k]);
            let pm = (phase + 180.0).rem_euclid(360.0);
            margins.phase_margin_deg = Some(if pm > 180.0 { pm - 360.0 } else { pm });
            margins.crossover_radps = Some(at(k, f));
        }
        let (n0, n1) = (
            ((phases[k] + 180.0) / 360.0).floor(),
            ((phases[k + 1] + 180.0) / 360.0).floor(),
        );
        if n0 != n1 {
            let level = -180.0 + 360.0 * n0.max(n1);
            let f = (level - phases[k]) / (phases[k + 1] - phases[k]);
            let gm = -(db[k] + f * (db[k + 1] - db[k]));
            if gm > 0.0 && margins.gain_margin_db.is_none_or(|m| gm < m) {
                margins.gain_margin_db = Some(gm);
                margins.phase_crossover_radps = Some(at(k, f));
            }
        }
    }
    margins
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::control::design::tests::{ACTUATOR, PLANT};

    /// A law without states, the ideal PD u = (K_P·(r − y) − K_D·q)/M_δ, gives
    /// L(s) = (K_P + K_D s)·A(s)/(s(s − M_q)), A the actuator. At ω = 10 rad/s with
    /// K_P = 16, K_D = 7.81: L = (16 + 78.1j)·A(10j)/(10j·(10j + 0.1891)), by hand.
    #[test]
    fn a_law_given_as_data_closes_the_loop_it_describes() {
        let (kp, kd, md) = (16.0, 7.81, PLANT.control_power_per_s2);
        let mut law = LinearLaw::without_states();
        law.output_inputs = [kp / md, -kp / md, -kd / md, 0.0];
        let model = AxisLoopModel::new(PLANT, None, ACTUATOR, &law);
        let s = Complex::new(0.0, 10.0);
        let wa2 = 30.74 * 30.74;
        let actuator = wa2 / (s * s + 2.0 * 0.509 * 30.74 * s + wa2);
        let expected = (kp + kd * s) * actuator / (s * (s + 0.1891));
        let got = model.loop_gain(10.0);
        assert!(
            (got - expected).norm() < 1e-9 * expected.norm(),
            "{got} vs {expected}"
        );
        assert!(model.closed_loop_max_real_part() < 0.0);
        let t = model.closed_loop(LoopInput::Command, LoopOutput::Angle, 1e-3);
        assert!((t - 1.0).norm() < 1e-2, "{t}");
    }

    /// White noise straight to the output (H = 1 at all frequencies is not available, so
    /// check the integral on its own): a held white sequence of σ² has variance σ², and
    /// through the sinc² weighting ∫₀^∞ sinc²(ωT/2)dω = π/T.
    #[test]
    fn held_white_noise_integral_is_normalised() {
        let t = 1e-3;
        let grid = log_grid(1e-3, 100.0 * std::f64::consts::PI / t, 4000);
        let mut integral = 0.0;
        for w in grid.windows(2) {
            let f = |w: f64| {
                let x = 0.5 * w * t;
                (x.sin() / x).powi(2)
            };
            integral += 0.5 * (f(w[0]) + f(w[1])) * (w[1] - w[0]);
        }
        // The tail beyond 100× Nyquist holds about 2/(π·100) of the total.
        let ratio = integral / (std::f64::consts::PI / t);
        assert!((ratio - 1.0).abs() < 0.01, "{ratio}");
    }

    /// Textbook loop L = 4/(s + 1)³: gain margin 20·log10(2) dB at √3 rad/s.
    #[test]
    fn margins_of_a_third_order_loop() {
        let omegas = log_grid(0.01, 100.0, 2001);
        let gains: Vec<Complex<f64>> = omegas
            .iter()
            .map(|&w| Complex::new(4.0, 0.0) / Complex::new(1.0, w).powi(3))
            .collect();
        let m = margins_of(&omegas, &gains);
        assert!((m.gain_margin_db.expect("gm") - 6.0206).abs() < 0.01);
        assert!((m.phase_crossover_radps.expect("w") - 3f64.sqrt()).abs() < 1e-3);
    }
}
