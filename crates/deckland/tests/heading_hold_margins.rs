//! The yaw law's heading hold in close (docs/model.md §10.2, docs/lateral-control.md):
//! the designed yaw O-PD, reading (1 − w)·β + w·(ψ_c − ψ) in place of β, keeps issue 26's
//! 45° and 6 dB on both channels of the full lateral model, and a stable closed loop.
//!
//! The sweep here is written out apart from `full_lateral_margins` (which has no heading
//! state): the lateral airframe (β, p, r, φ) with the heading ψ̇ = r·cos φ*/cos θ*, both
//! actuators, the laws' linear forms and the 80 Hz computer's delay on each command. At
//! w = 0 it is the sideslip loop, and its margins are checked against
//! `full_lateral_margins` to pin the sweep itself.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::six_dof::linearize_six_dof;
use deckland::control::design::loop_model::{log_grid, margins_of, Margins};
use deckland::control::design::LinearActuator;
use deckland::control::lateral::design::{
    channel_hardware, cross_closed_loop_gains, full_lateral_margins, FLIGHT_COMPUTER_DELAY_S,
};
use deckland::control::lateral::LateralChannel;
use deckland::control::LinearLaw;
use deckland::experiments::LateralSetup;
use nalgebra::{Complex, SMatrix};

/// Plant and actuator states: β, p, r, φ, ψ, δa, δ̇a, δr, δ̇r.
const STATES: usize = 9;
/// Rows of the measurement matrix: φ, p, δa (roll law); the yaw law's angle, −r, δr.
const MEASUREMENTS: usize = 6;

struct Loop {
    a: SMatrix<f64, STATES, STATES>,
    b: SMatrix<f64, STATES, 2>,
    m: SMatrix<f64, MEASUREMENTS, STATES>,
    roll: LinearLaw,
    yaw: LinearLaw,
}

/// The loop with the heading hold's weight `weight` in the yaw law's angle.
fn heading_loop(weight: f64) -> (Loop, Margins, Margins) {
    let setup = LateralSetup::approach().unwrap();
    let model = linearize_six_dof(&setup.aircraft, &setup.trim);
    let actuator = |channel| {
        let hardware = channel_hardware(&setup.aircraft, &model, channel);
        LinearActuator {
            natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
            damping_ratio: hardware.actuator.damping_ratio,
        }
    };
    let (aileron, rudder) = (
        actuator(LateralChannel::Roll),
        actuator(LateralChannel::Yaw),
    );
    let (roll_law, yaw_law) = setup.registered_laws("observer_pd").unwrap();
    let (roll, yaw) = (
        roll_law.linear_law().unwrap(),
        yaw_law.linear_law().unwrap(),
    );
    let (a4, b4) = (model.lateral_a(), model.lateral_b());
    let mut a = SMatrix::<f64, STATES, STATES>::zeros();
    let mut b = SMatrix::<f64, STATES, 2>::zeros();
    for i in 0..4 {
        for j in 0..4 {
            a[(i, j)] = a4[(i, j)];
        }
        a[(i, 5)] = b4[(i, 0)];
        a[(i, 7)] = b4[(i, 1)];
    }
    // ψ̇ = (q·sin φ + r·cos φ)/cos θ, linearised at the wings-level trim.
    a[(4, 2)] = setup.trim.phi_rad.cos() / setup.trim.theta_rad.cos();
    for (k, actuator) in [(5, aileron), (7, rudder)] {
        let (w, z) = (actuator.natural_frequency_radps, actuator.damping_ratio);
        a[(k, k + 1)] = 1.0;
        a[(k + 1, k)] = -w * w;
        a[(k + 1, k + 1)] = -2.0 * z * w;
        b[(k + 1, (k - 5) / 2)] = w * w;
    }
    let mut m = SMatrix::<f64, MEASUREMENTS, STATES>::zeros();
    m[(0, 3)] = 1.0;
    m[(1, 1)] = 1.0;
    m[(2, 5)] = 1.0;
    // The yaw law's angle: (1 − w)·β + w·(ψ_c − ψ).
    m[(3, 0)] = 1.0 - weight;
    m[(3, 4)] = -weight;
    m[(4, 2)] = -1.0;
    m[(5, 7)] = 1.0;
    let sweep = Loop { a, b, m, roll, yaw };
    let (roll_margins, yaw_margins) = sweep.margins();
    // The reference sweep of the sideslip loop, for the check at w = 0.
    let reference = full_lateral_margins(
        &model,
        aileron,
        rudder,
        &sweep.roll,
        &sweep.yaw,
        FLIGHT_COMPUTER_DELAY_S,
    );
    if weight == 0.0 {
        let close = |x: Option<f64>, y: Option<f64>| match (x, y) {
            (Some(x), Some(y)) => (x - y).abs() < 1e-6,
            (None, None) => true,
            _ => false,
        };
        for (mine, theirs) in [(roll_margins, reference.roll), (yaw_margins, reference.yaw)] {
            assert!(
                close(mine.phase_margin_deg, theirs.phase_margin_deg)
                    && close(mine.gain_margin_db, theirs.gain_margin_db),
                "{mine:?} against {theirs:?}"
            );
        }
    }
    (sweep, roll_margins, yaw_margins)
}

impl Loop {
    /// The margins at the aileron and at the rudder command, the other loop closed.
    fn margins(&self) -> (Margins, Margins) {
        let omegas = log_grid(0.01, 200.0, 600);
        let (mut roll, mut yaw) = (Vec::new(), Vec::new());
        for &w in &omegas {
            let s = Complex::new(0.0, w);
            let mut resolvent = self.a.map(|v| Complex::from(-v));
            for i in 0..STATES {
                resolvent[(i, i)] += s;
            }
            let g = self.m.map(Complex::from)
                * resolvent.try_inverse().unwrap()
                * self.b.map(Complex::from);
            let delay = Complex::from_polar(1.0, -w * FLIGHT_COMPUTER_DELAY_S);
            let (ka, kr) = (
                self.roll.measurement_response(s),
                self.yaw.measurement_response(s),
            );
            let (roll_gain, yaw_gain) = cross_closed_loop_gains(&g, &ka, &kr, delay);
            roll.push(roll_gain);
            yaw.push(yaw_gain);
        }
        (margins_of(&omegas, &roll), margins_of(&omegas, &yaw))
    }

    /// The largest real part of the closed loop's eigenvalues, without the delay.
    fn closed_loop_max_real_part(&self) -> f64 {
        const L: usize = LinearLaw::MAX_STATES;
        const N: usize = STATES + 2 * L;
        let mut closed = SMatrix::<f64, N, N>::zeros();
        for i in 0..STATES {
            for j in 0..STATES {
                closed[(i, j)] = self.a[(i, j)];
            }
        }
        let inputs = [
            LinearLaw::MEASURED_ANGLE,
            LinearLaw::RATE,
            LinearLaw::SURFACE,
        ];
        for (channel, law) in [&self.roll, &self.yaw].into_iter().enumerate() {
            let offset = STATES + channel * L;
            let mut row = [0.0; N];
            for (k, &input) in inputs.iter().enumerate() {
                for (j, entry) in row.iter_mut().enumerate().take(STATES) {
                    *entry += law.output_inputs[input] * self.m[(3 * channel + k, j)];
                }
            }
            for i in 0..L {
                row[offset + i] = law.output_states[i];
                for j in 0..L {
                    closed[(offset + i, offset + j)] = law.state_matrix[i][j];
                }
                for (k, &input) in inputs.iter().enumerate() {
                    for j in 0..STATES {
                        closed[(offset + i, j)] +=
                            law.input_matrix[i][input] * self.m[(3 * channel + k, j)];
                    }
                }
            }
            for i in 0..STATES {
                for (j, value) in row.iter().enumerate() {
                    closed[(i, j)] += self.b[(i, channel)] * value;
                }
            }
        }
        closed
            .complex_eigenvalues()
            .iter()
            .map(|l| l.re)
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

#[test]
fn the_heading_hold_keeps_45_degrees_and_6_db_and_a_stable_loop_through_its_blend() {
    for weight in [0.0, 0.5, 1.0] {
        let (sweep, roll, yaw) = heading_loop(weight);
        for (channel, m) in [("roll", roll), ("yaw", yaw)] {
            let pm = m.phase_margin_deg.expect("a crossover");
            let gm = m.gain_margin_db.unwrap_or(f64::INFINITY);
            println!(
                "w = {weight}: {channel}: PM {pm:.1}° at {:?} rad/s, GM {gm:.1} dB",
                m.crossover_radps
            );
            assert!(pm >= 45.0 && gm >= 6.0, "w = {weight}, {channel}: {m:?}");
        }
        let slowest = sweep.closed_loop_max_real_part();
        println!("w = {weight}: slowest closed-loop eigenvalue real part {slowest:.3} /s");
        // Without the hold the heading is a free integrator of r (an eigenvalue at 0).
        if weight > 0.0 {
            assert!(slowest < 0.0, "w = {weight}: {slowest}");
        }
    }
}
