//! Small-perturbation linearisation of the 6-DOF aircraft about a trim point, and the
//! lateral-directional modes (docs/six-dof.md).
//!
//! The airframe alone (actuator and engine dynamics excluded, as in the longitudinal
//! linearisation), in still air, by central differences of the nonlinear equations in
//! the states (V_T, α, β, p, q, r, φ, θ) and inputs (δe, δT, δa, δr). The heading ψ and
//! the position do not feed back and are left out. The lateral set is the block
//! (β, p, r, φ; δa, δr); the longitudinal set is the block (V_T, θ, α, q; δe, δT) in the
//! order and units of `crate::aircraft::linearize`.

use super::dynamics::{SixDofAircraft, SixDofInputs};
use super::kinematics::euler_rates;
use super::trim::SixDofTrimPoint;
use crate::aircraft::central_difference::jacobian;
use crate::environment::Wind;
use nalgebra::{Complex, SMatrix, SVector};

/// Names of the lateral states, in order.
pub const LATERAL_STATE_NAMES: [&str; 4] = ["sideslip", "roll_rate", "yaw_rate", "bank_angle"];
/// Units of the lateral states, in order.
pub const LATERAL_STATE_UNITS: [&str; 4] = ["rad", "rad/s", "rad/s", "rad"];
/// Names of the lateral inputs, in order.
pub const LATERAL_INPUT_NAMES: [&str; 2] = ["aileron", "rudder"];
/// Units of the lateral inputs, in order.
pub const LATERAL_INPUT_UNITS: [&str; 2] = ["rad", "rad"];

const FULL_STATES: usize = 8;
const FULL_INPUTS: usize = 4;
const LATERAL_STATES: [usize; 4] = [2, 3, 5, 6];
const LATERAL_INPUTS: [usize; 2] = [2, 3];
const LONGITUDINAL_STATES: [usize; 4] = [0, 7, 1, 4];
const LONGITUDINAL_INPUTS: [usize; 2] = [0, 1];

/// The linear model ẋ = A x + B u of the 6-DOF airframe about a trim point.
#[derive(Debug, Clone, PartialEq)]
pub struct SixDofLinearModel {
    /// Full A (8×8), states (V_T, α, β, p, q, r, φ, θ) in m/s, rad, rad/s.
    pub a: SMatrix<f64, 8, 8>,
    /// Full B (8×4), inputs (δe rad, δT fraction of 2·T_max, δa rad, δr rad).
    pub b: SMatrix<f64, 8, 4>,
    /// The trim point linearised about.
    pub trim: SixDofTrimPoint,
}

impl SixDofLinearModel {
    /// The lateral A (4×4), states as in [`LATERAL_STATE_NAMES`].
    pub fn lateral_a(&self) -> SMatrix<f64, 4, 4> {
        SMatrix::from_fn(|i, j| self.a[(LATERAL_STATES[i], LATERAL_STATES[j])])
    }

    /// The lateral B (4×2), inputs as in [`LATERAL_INPUT_NAMES`].
    pub fn lateral_b(&self) -> SMatrix<f64, 4, 2> {
        SMatrix::from_fn(|i, j| self.b[(LATERAL_STATES[i], LATERAL_INPUTS[j])])
    }

    /// The longitudinal A (4×4), states (V_T, θ, α, q) as `crate::aircraft::STATE_NAMES`.
    pub fn longitudinal_a(&self) -> SMatrix<f64, 4, 4> {
        SMatrix::from_fn(|i, j| self.a[(LONGITUDINAL_STATES[i], LONGITUDINAL_STATES[j])])
    }

    /// The longitudinal B (4×2), inputs (δe, δT) as `crate::aircraft::INPUT_NAMES`.
    pub fn longitudinal_b(&self) -> SMatrix<f64, 4, 2> {
        SMatrix::from_fn(|i, j| self.b[(LONGITUDINAL_STATES[i], LONGITUDINAL_INPUTS[j])])
    }

    /// The lateral modes of [`SixDofLinearModel::lateral_a`]; `None` when its
    /// eigenvalues are not one oscillatory pair and two real roots.
    pub fn lateral_modes(&self) -> Option<LateralModes> {
        LateralModes::of(&self.lateral_a())
    }
}

/// The Dutch roll: the oscillatory lateral pair λ = −ζω_n ± iω_n√(1 − ζ²).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DutchRoll {
    /// The eigenvalue with positive imaginary part (1/s).
    pub eigenvalue: Complex<f64>,
    /// Natural frequency ω_n = |λ| (rad/s).
    pub natural_frequency_radps: f64,
    /// Damping ratio ζ = −Re λ/|λ| (–); negative when unstable.
    pub damping_ratio: f64,
}

/// A real (aperiodic) mode λ.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RealMode {
    /// The eigenvalue λ (1/s).
    pub eigenvalue_per_s: f64,
    /// Time constant τ = −1/λ (s); negative when the mode diverges.
    pub time_constant_s: f64,
    /// Time to half amplitude (stable) or to double amplitude (unstable), ln 2/|λ| (s).
    pub time_to_half_or_double_s: f64,
    /// Whether λ < 0.
    pub stable: bool,
}

impl RealMode {
    fn new(lambda: f64) -> Self {
        Self {
            eigenvalue_per_s: lambda,
            time_constant_s: -1.0 / lambda,
            time_to_half_or_double_s: std::f64::consts::LN_2 / lambda.abs(),
            stable: lambda < 0.0,
        }
    }
}

/// The three lateral-directional modes.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralModes {
    /// The Dutch roll.
    pub dutch_roll: DutchRoll,
    /// Roll subsidence: the real root of larger magnitude.
    pub roll_subsidence: RealMode,
    /// Spiral: the real root of smaller magnitude.
    pub spiral: RealMode,
}

impl LateralModes {
    /// The modes of a lateral A (β, p, r, φ); `None` unless its eigenvalues are one
    /// complex pair and two real roots.
    pub fn of(a: &SMatrix<f64, 4, 4>) -> Option<Self> {
        let eigenvalues = a.complex_eigenvalues();
        let scale = eigenvalues.iter().map(|l| l.norm()).fold(0.0, f64::max);
        let imaginary_floor = 1e-9 * scale.max(1e-12);
        let pair: Vec<Complex<f64>> = eigenvalues
            .iter()
            .copied()
            .filter(|l| l.im > imaginary_floor)
            .collect();
        let mut real: Vec<f64> = eigenvalues
            .iter()
            .filter(|l| l.im.abs() <= imaginary_floor)
            .map(|l| l.re)
            .collect();
        if pair.len() != 1 || real.len() != 2 {
            return None;
        }
        real.sort_by(|x, y| y.abs().total_cmp(&x.abs()));
        let lambda = pair[0];
        let omega = lambda.norm();
        Some(Self {
            dutch_roll: DutchRoll {
                eigenvalue: lambda,
                natural_frequency_radps: omega,
                damping_ratio: -lambda.re / omega,
            },
            roll_subsidence: RealMode::new(real[0]),
            spiral: RealMode::new(real[1]),
        })
    }
}

/// Nonlinear rates of (V_T, α, β, p, q, r, φ, θ) for inputs (δe, δT, δa, δr), still air,
/// ψ = 0.
fn rates(
    aircraft: &SixDofAircraft,
    x: &SVector<f64, FULL_STATES>,
    u: &SVector<f64, FULL_INPUTS>,
) -> SVector<f64, FULL_STATES> {
    let (v, alpha, beta) = (x[0], x[1], x[2]);
    let (sin_a, cos_a) = alpha.sin_cos();
    let (sin_b, cos_b) = beta.sin_cos();
    let velocity = [v * cos_a * cos_b, v * sin_b, v * sin_a * cos_b];
    let body_rates = [x[3], x[4], x[5]];
    let euler = [x[6], x[7], 0.0];
    let inputs = SixDofInputs {
        elevator_rad: u[0],
        thrust_n: u[1] * aircraft.longitudinal().engines().max_total_thrust_n(),
        aileron_rad: u[2],
        rudder_rad: u[3],
    };
    let body = aircraft.body_rates(velocity, body_rates, euler, &inputs, &Wind::default());
    let [ub, vb, wb] = velocity;
    let [u_dot, v_dot, w_dot] = body.velocity;
    let in_plane_squared = ub * ub + wb * wb;
    let v_rate = (ub * u_dot + vb * v_dot + wb * w_dot) / v;
    let alpha_rate = (ub * w_dot - wb * u_dot) / in_plane_squared;
    let beta_rate = (v * v_dot - vb * v_rate) / (v * in_plane_squared.sqrt());
    let [phi_rate, theta_rate, _] = euler_rates(body_rates, euler);
    SVector::from([
        v_rate,
        alpha_rate,
        beta_rate,
        body.angular[0],
        body.angular[1],
        body.angular[2],
        phi_rate,
        theta_rate,
    ])
}

/// Linearises `aircraft` about `trim` by central differences.
pub fn linearize_six_dof(aircraft: &SixDofAircraft, trim: &SixDofTrimPoint) -> SixDofLinearModel {
    let x0 = SVector::<f64, FULL_STATES>::from([
        trim.speed_mps,
        trim.alpha_rad,
        trim.sideslip_rad,
        0.0,
        0.0,
        0.0,
        trim.phi_rad,
        trim.theta_rad,
    ]);
    let u0 = SVector::<f64, FULL_INPUTS>::from([
        trim.elevator_rad,
        trim.throttle,
        trim.aileron_rad,
        trim.rudder_rad,
    ]);
    const STATE_STEPS: [f64; FULL_STATES] = [1e-4, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6];
    const INPUT_STEP: f64 = 1e-6;
    let a = jacobian(&x0, &STATE_STEPS, |x| rates(aircraft, x, &u0));
    let b = jacobian(&u0, &[INPUT_STEP; FULL_INPUTS], |u| rates(aircraft, &x0, u));
    SixDofLinearModel { a, b, trim: *trim }
}
