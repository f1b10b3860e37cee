//! Small-perturbation linearisation about a trim point in the paper's Eq. (14) form.
//!
//! ẋ = A x + B u with x = (ΔV_T, Δθ, Δα, Δq) and u = (Δδe, ΔδT): the elevator in rad and
//! the throttle as a fraction of the *total* maximum thrust of both engines. The airframe
//! is linearised alone (actuator and engine dynamics excluded, as in the paper), in still
//! air, by central differences of the nonlinear equations of motion.

use super::central_difference::jacobian;
use super::trim::TrimPoint;
use super::{Aircraft, AirframeInputs, Wind};
use nalgebra::{Complex, SMatrix, SVector};

/// Names of the linear model's states, in order.
pub const STATE_NAMES: [&str; 4] = ["airspeed", "pitch_angle", "angle_of_attack", "pitch_rate"];
/// Units of the linear model's states, in order.
pub const STATE_UNITS: [&str; 4] = ["m/s", "rad", "rad", "rad/s"];
/// Names of the linear model's inputs, in order.
pub const INPUT_NAMES: [&str; 2] = ["elevator", "throttle"];
/// Units of the linear model's inputs, in order (throttle: fraction of 2·T_max).
pub const INPUT_UNITS: [&str; 2] = ["rad", "1"];

/// A linear model ẋ = A x + B u about a trim point.
#[derive(Debug, Clone, PartialEq)]
pub struct LinearModel {
    /// State matrix A (4×4), states as in [`STATE_NAMES`].
    pub a: SMatrix<f64, 4, 4>,
    /// Input matrix B (4×2), inputs as in [`INPUT_NAMES`].
    pub b: SMatrix<f64, 4, 2>,
    /// The trim point linearised about.
    pub trim: TrimPoint,
}

impl LinearModel {
    /// Eigenvalues of A (1/s), in the order nalgebra's Schur decomposition returns them.
    pub fn eigenvalues(&self) -> Vec<Complex<f64>> {
        self.a.complex_eigenvalues().iter().copied().collect()
    }

    /// Pitch damping ∂q̇/∂q (1/s), element A[q, q].
    pub fn pitch_damping_per_s(&self) -> f64 {
        self.a[(3, 3)]
    }

    /// Elevator effectiveness ∂q̇/∂δe (1/s²), element B[q, δe].
    pub fn elevator_effectiveness_per_s2(&self) -> f64 {
        self.b[(3, 0)]
    }

    /// Pitch stiffness ∂q̇/∂α (1/s²), element A[q, α].
    pub fn pitch_stiffness_per_s2(&self) -> f64 {
        self.a[(3, 2)]
    }
}

/// Nonlinear airframe rates (V̇, θ̇, α̇, q̇) at state (V, θ, α, q) and inputs (δe, δT).
fn rates(aircraft: &Aircraft, x: &SVector<f64, 4>, u: &SVector<f64, 2>) -> SVector<f64, 4> {
    let (v, theta, alpha, q) = (x[0], x[1], x[2], x[3]);
    let (ub, wb) = (v * alpha.cos(), v * alpha.sin());
    let inputs = AirframeInputs {
        elevator_rad: u[0],
        thrust_n: u[1] * aircraft.engines().max_total_thrust_n(),
    };
    let (u_dot, w_dot, q_dot) =
        aircraft.airframe_accelerations(ub, wb, q, theta, &inputs, &Wind::default());
    SVector::<f64, 4>::new(
        (ub * u_dot + wb * w_dot) / v,
        q,
        (ub * w_dot - wb * u_dot) / (v * v),
        q_dot,
    )
}

/// Linearises `aircraft` about `trim` by central differences.
pub fn linearize(aircraft: &Aircraft, trim: &TrimPoint) -> LinearModel {
    let x0 = SVector::<f64, 4>::new(trim.speed_mps, trim.theta_rad, trim.alpha_rad, 0.0);
    let u0 = SVector::<f64, 2>::new(trim.elevator_rad, trim.throttle);
    const STATE_STEPS: [f64; 4] = [1e-4, 1e-6, 1e-6, 1e-6];
    const INPUT_STEPS: [f64; 2] = [1e-6, 1e-6];
    let a = jacobian(&x0, &STATE_STEPS, |x| rates(aircraft, x, &u0));
    let b = jacobian(&u0, &INPUT_STEPS, |u| rates(aircraft, &x0, u));
    LinearModel { a, b, trim: *trim }
}
