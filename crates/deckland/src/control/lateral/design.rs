//! The lateral channels' design data and their margins on the full lateral model
//! (docs/lateral-control.md).
//!
//! - [`channel_plants`]: each channel's rate damping and control power from the 6-DOF
//!   linearisation at trim (roll: L_p, L_δa; yaw, on β with β̇ ≈ −r: N_r, −N_δr);
//! - [`channel_hardware`]: the design code's [`AxisHardware`] of a channel (its actuator,
//!   the flight computer's delay), for `control::design::assess_loop` on the reduced loop;
//! - [`full_lateral_margins`]: each channel's margins with the other channel's loop
//!   closed, on the full lateral model (β, p, r, φ; δa, δr) with both actuators and the
//!   computer's delay, by a direct frequency sweep: the cross-coupling (dihedral, adverse
//!   yaw, the rudder's rolling moment) is in it.

use nalgebra::{Complex, SMatrix};

use super::LateralChannel;
use crate::aircraft::six_dof::{SixDofAircraft, SixDofLinearModel};
use crate::aircraft::ElevatorActuatorParameters;
use crate::control::design::loop_model::{log_grid, margins_of, Margins};
use crate::control::design::{ActuatorKeys, AxisHardware, AxisPlantDerivatives, LinearActuator};
use crate::control::LinearLaw;

/// Equivalent delay of the 80 Hz flight computer (s): half a frame for the hold plus one
/// frame of computing, 1.5/80 = 18.75 ms (as the pitch design models it).
pub const FLIGHT_COMPUTER_DELAY_S: f64 = 1.5 / 80.0;

/// The aileron's scenario keys.
pub const AILERON_KEYS: ActuatorKeys = ActuatorKeys {
    min_deflection: "aircraft.aileron_actuator.travel_deg",
    max_deflection: "aircraft.aileron_actuator.travel_deg",
    rate_limit: "aircraft.aileron_actuator.rate_limit_degps",
};

/// The rudder's scenario keys.
pub const RUDDER_KEYS: ActuatorKeys = ActuatorKeys {
    min_deflection: "aircraft.rudder_actuator.travel_deg",
    max_deflection: "aircraft.rudder_actuator.travel_deg",
    rate_limit: "aircraft.rudder_actuator.rate_limit_degps",
};

/// Index of β, p, r, φ in the lateral state and of δa, δr in its input.
const BETA: usize = 0;
const ROLL_RATE: usize = 1;
const YAW_RATE: usize = 2;
const BANK: usize = 3;
const AILERON: usize = 0;
const RUDDER: usize = 1;

/// The roll and yaw channels' plants from the lateral linearisation: roll (φ̈ ≈ ṗ):
/// L_p = ∂ṗ/∂p, L_δa = ∂ṗ/∂δa; yaw on β with β̇ ≈ −r (β̈ ≈ −ṙ): rate damping
/// ∂ṙ/∂r = N_r, control power −∂ṙ/∂δr = −N_δr.
pub fn channel_plants(model: &SixDofLinearModel) -> (AxisPlantDerivatives, AxisPlantDerivatives) {
    let (a, b) = (model.lateral_a(), model.lateral_b());
    (
        AxisPlantDerivatives {
            rate_damping_per_s: a[(ROLL_RATE, ROLL_RATE)],
            control_power_per_s2: b[(ROLL_RATE, AILERON)],
        },
        AxisPlantDerivatives {
            rate_damping_per_s: a[(YAW_RATE, YAW_RATE)],
            control_power_per_s2: -b[(YAW_RATE, RUDDER)],
        },
    )
}

/// The aileron's or rudder's parameters in the design code's actuator type.
pub fn channel_actuator(
    aircraft: &SixDofAircraft,
    channel: LateralChannel,
) -> ElevatorActuatorParameters {
    let actuator = match channel {
        LateralChannel::Roll => aircraft.aileron(),
        LateralChannel::Yaw => aircraft.rudder(),
    };
    *actuator.parameters()
}

/// A channel's hardware for the design code: its actuator and keys, the trim surface
/// position, its plant and the flight computer's delay (no angle-of-attack coupling).
pub fn channel_hardware(
    aircraft: &SixDofAircraft,
    model: &SixDofLinearModel,
    channel: LateralChannel,
) -> AxisHardware {
    let (roll, yaw) = channel_plants(model);
    let (plant, keys, trim) = match channel {
        LateralChannel::Roll => (roll, AILERON_KEYS, model.trim.aileron_rad),
        LateralChannel::Yaw => (yaw, RUDDER_KEYS, model.trim.rudder_rad),
    };
    AxisHardware {
        actuator: channel_actuator(aircraft, channel),
        actuator_keys: keys,
        surface_trim_rad: trim,
        plant,
        coupling: None,
        control_delay_s: FLIGHT_COMPUTER_DELAY_S,
    }
}

/// Each channel's margins on the full lateral loop.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralMargins {
    /// At the aileron command, the yaw loop closed.
    pub roll: Margins,
    /// At the rudder command, the roll loop closed.
    pub yaw: Margins,
    /// Largest real part of the closed loop's eigenvalues without the delay (1/s).
    pub closed_loop_max_real_part: f64,
}

type Plant = SMatrix<f64, 8, 8>;

/// The lateral airframe with both actuators: states [β, p, r, φ, δa, δ̇a, δr, δ̇r], inputs
/// the surface commands [u_a, u_r]; and the laws' measurements
/// [φ, p, δa, β, −r, δr] as rows of the output matrix.
fn plant_with_actuators(
    model: &SixDofLinearModel,
    aileron: LinearActuator,
    rudder: LinearActuator,
) -> (Plant, SMatrix<f64, 8, 2>, SMatrix<f64, 6, 8>) {
    let (a4, b4) = (model.lateral_a(), model.lateral_b());
    let mut a = Plant::zeros();
    let mut b = SMatrix::<f64, 8, 2>::zeros();
    for i in 0..4 {
        for j in 0..4 {
            a[(i, j)] = a4[(i, j)];
        }
        a[(i, 4)] = b4[(i, AILERON)];
        a[(i, 6)] = b4[(i, RUDDER)];
    }
    for (k, actuator) in [(4, aileron), (6, rudder)] {
        let (w, z) = (actuator.natural_frequency_radps, actuator.damping_ratio);
        a[(k, k + 1)] = 1.0;
        a[(k + 1, k)] = -w * w;
        a[(k + 1, k + 1)] = -2.0 * z * w;
        b[(k + 1, (k - 4) / 2)] = w * w;
    }
    let mut m = SMatrix::<f64, 6, 8>::zeros();
    m[(0, BANK)] = 1.0;
    m[(1, ROLL_RATE)] = 1.0;
    m[(2, 4)] = 1.0;
    m[(3, BETA)] = 1.0;
    m[(4, YAW_RATE)] = -1.0;
    m[(5, 6)] = 1.0;
    (a, b, m)
}

impl LinearLaw {
    /// The law's transfer from its measurements [y, ω, δ] to its surface command at
    /// `s` = jω (command and sensor error zero).
    pub fn measurement_response(&self, s: Complex<f64>) -> [Complex<f64>; 3] {
        const N: usize = LinearLaw::MAX_STATES;
        let mut resolvent = SMatrix::<Complex<f64>, N, N>::zeros();
        for i in 0..N {
            for j in 0..N {
                resolvent[(i, j)] = Complex::from(-self.state_matrix[i][j]);
            }
            resolvent[(i, i)] += s;
        }
        let inverse = resolvent.try_inverse().unwrap_or_else(SMatrix::zeros);
        let inputs = [
            LinearLaw::MEASURED_ANGLE,
            LinearLaw::RATE,
            LinearLaw::SURFACE,
        ];
        inputs.map(|input| {
            let mut value = Complex::from(self.output_inputs[input]);
            for i in 0..N {
                for j in 0..N {
                    value += self.output_states[i] * inverse[(i, j)] * self.input_matrix[j][input];
                }
            }
            value
        })
    }
}

/// The margins of each channel on the full lateral loop (module docs): at each frequency
/// the plant's response G(jω) from the two surface commands to the six measurements, the
/// laws' responses K(jω), the delay e^{−jωτ} on each command, H = K·G·e^{−jωτ} (2×2), and
/// with the other channel closed the loop gain at the aileron
/// L_a = −(H_aa + H_ar·H_ra/(1 − H_rr)) (and alike at the rudder), on 600 log-spaced
/// frequencies from 0.01 to 200 rad/s.
pub fn full_lateral_margins(
    model: &SixDofLinearModel,
    aileron: LinearActuator,
    rudder: LinearActuator,
    roll_law: &LinearLaw,
    yaw_law: &LinearLaw,
    delay_s: f64,
) -> LateralMargins {
    let (a, b, m) = plant_with_actuators(model, aileron, rudder);
    let omegas = log_grid(0.01, 200.0, 600);
    let mut roll = Vec::with_capacity(omegas.len());
    let mut yaw = Vec::with_capacity(omegas.len());
    for &w in &omegas {
        let s = Complex::new(0.0, w);
        let mut resolvent = a.map(|v| Complex::from(-v));
        for i in 0..8 {
            resolvent[(i, i)] += s;
        }
        let inverse = resolvent.try_inverse().unwrap_or_else(SMatrix::zeros);
        let g = m.map(Complex::from) * inverse * b.map(Complex::from);
        let delay = Complex::from_polar(1.0, -w * delay_s);
        let (ka, kr) = (
            roll_law.measurement_response(s),
            yaw_law.measurement_response(s),
        );
        let (roll_gain, yaw_gain) = cross_closed_loop_gains(&g, &ka, &kr, delay);
        roll.push(roll_gain);
        yaw.push(yaw_gain);
    }
    LateralMargins {
        roll: margins_of(&omegas, &roll),
        yaw: margins_of(&omegas, &yaw),
        closed_loop_max_real_part: closed_loop_max_real_part(&a, &b, &m, roll_law, yaw_law),
    }
}

/// The loop gains at one frequency at the aileron and at the rudder command, each with
/// the other channel closed (L_a and L_r of [`full_lateral_margins`]): from the plant's
/// response `g` from the two surface commands to the laws' six measurements
/// (φ, p, δa, β, −r, δr), the roll and yaw laws' responses `ka` and `kr` to their three
/// measurements, and the command delay's factor `delay` (e^{−jωτ}).
pub fn cross_closed_loop_gains(
    g: &SMatrix<Complex<f64>, 6, 2>,
    ka: &[Complex<f64>; 3],
    kr: &[Complex<f64>; 3],
    delay: Complex<f64>,
) -> (Complex<f64>, Complex<f64>) {
    let mut h = [[Complex::from(0.0); 2]; 2];
    for input in 0..2 {
        for k in 0..3 {
            h[0][input] += ka[k] * g[(k, input)] * delay;
            h[1][input] += kr[k] * g[(3 + k, input)] * delay;
        }
    }
    let one = Complex::from(1.0);
    (
        -(h[0][0] + h[0][1] * h[1][0] / (one - h[1][1])),
        -(h[1][1] + h[1][0] * h[0][1] / (one - h[0][0])),
    )
}

/// The closed lateral loop without the delay, in state space (8 plant and actuator
/// states, 3 per law), and the largest real part of its eigenvalues.
fn closed_loop_max_real_part(
    a: &Plant,
    b: &SMatrix<f64, 8, 2>,
    m: &SMatrix<f64, 6, 8>,
    roll_law: &LinearLaw,
    yaw_law: &LinearLaw,
) -> f64 {
    const N: usize = 8 + 2 * LinearLaw::MAX_STATES;
    let mut closed = SMatrix::<f64, N, N>::zeros();
    for i in 0..8 {
        for j in 0..8 {
            closed[(i, j)] = a[(i, j)];
        }
    }
    let inputs = [
        LinearLaw::MEASURED_ANGLE,
        LinearLaw::RATE,
        LinearLaw::SURFACE,
    ];
    for (channel, law) in [roll_law, yaw_law].into_iter().enumerate() {
        let offset = 8 + channel * LinearLaw::MAX_STATES;
        // u = C_c·x_c + D_c·(M x): the command's row over the plant's and the law's states.
        let mut row = [0.0; N];
        for (k, &input) in inputs.iter().enumerate() {
            for j in 0..8 {
                row[j] += law.output_inputs[input] * m[(3 * channel + k, j)];
            }
        }
        for i in 0..LinearLaw::MAX_STATES {
            row[offset + i] = law.output_states[i];
            for j in 0..LinearLaw::MAX_STATES {
                closed[(offset + i, offset + j)] = law.state_matrix[i][j];
            }
            for (k, &input) in inputs.iter().enumerate() {
                for j in 0..8 {
                    closed[(offset + i, j)] += law.input_matrix[i][input] * m[(3 * channel + k, j)];
                }
            }
        }
        for i in 0..8 {
            for (j, value) in row.iter().enumerate() {
                closed[(i, j)] += b[(i, channel)] * value;
            }
        }
    }
    closed
        .complex_eigenvalues()
        .iter()
        .map(|l| l.re)
        .fold(f64::NEG_INFINITY, f64::max)
}
