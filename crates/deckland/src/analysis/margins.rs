//! Stability margins of the landing cascade, loop by loop, on the linearised closed loop
//! (docs/model.md §5: "checked on the linearised cascade with gain and phase margins").
//!
//! The closed loop of the approach is linearised numerically (central differences) at the
//! start of an ideal-conditions approach, with one loop cut at a time
//! ([`LoopBreak`]): x' = A x + B u, y = C x + D u, u the value injected at the cut and y
//! the value the loop computes there. The loop transfer function is
//! L(s) = −(C (sI − A)⁻¹ B + D) (negative feedback), evaluated on a logarithmic grid of
//! frequencies. Reported per loop:
//!
//! - the bandwidth: the first gain crossover (|L| falling through 1), and the phase margin
//!   180° + ∠L there;
//! - the gain margin: −20 log₁₀|L| at the phase crossovers (∠L = −180° mod 360°) where
//!   |L| < 1, the smallest (how much the loop gain may grow);
//! - the modulus margin: min over ω of |1 + L(jω)|, the distance of the Nyquist curve from
//!   −1, which also covers loops with several crossovers (a resonance); it guarantees a
//!   gain margin of at least 1/(1 − m) and a phase margin of at least 2 asin(m/2);
//! - the largest real part of the closed loop's eigenvalues (the cut closed again,
//!   A + B C/(1 − D)), an independent check of stability.
//!
//! The finite-time observer's |e|^α terms have no derivative at e = 0, so the analysis
//! replaces the O-PD observer by its linear limit (α1 → 1, same k1, k2, k3, ε): the
//! linear extended-state observer of the same bandwidth. A flight-control computer that
//! holds its commands over frames of T seconds enters as the zero-order hold's delay
//! T/2 (a factor e^(−jωT/2) on every loop, each of which passes through one held
//! command); the closed-loop eigenvalues leave it out.

use crate::aircraft::PlantModel;
use crate::control::pitch::PitchControllerParameters;
use crate::scenario::Scenario;
use crate::simulation::{ClosedLoop, HeldInputs, LoopBreak, LoopCut, SetupError, Simulation};
use nalgebra::{Complex, DMatrix, DVector};

/// Margins of one loop of the cascade.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoopMargins {
    /// Where the loop was cut.
    pub loop_break: LoopBreak,
    /// First gain-crossover frequency (rad/s): the loop's bandwidth.
    pub crossover_radps: Option<f64>,
    /// Phase margin at that crossover (deg).
    pub phase_margin_deg: Option<f64>,
    /// Phase-crossover frequency of the smallest gain margin (rad/s).
    pub phase_crossover_radps: Option<f64>,
    /// Smallest gain margin (dB) over phase crossovers with |L| < 1; `None` when there is
    /// none.
    pub gain_margin_db: Option<f64>,
    /// Modulus margin min |1 + L(jω)| (–).
    pub modulus_margin: f64,
    /// Frequency of the modulus margin (rad/s).
    pub modulus_margin_radps: f64,
    /// Largest real part of the closed loop's eigenvalues (1/s), ignoring the
    /// position-like states with a zero eigenvalue; negative means stable.
    pub closed_loop_max_real_part: f64,
}

/// The linearised cascade with one loop cut.
struct CutLoop {
    a: DMatrix<f64>,
    b: DVector<f64>,
    c: DVector<f64>,
    d: f64,
}

fn linearise(
    system: &ClosedLoop,
    held: &HeldInputs,
    x0: &[f64],
    cut: LoopBreak,
    u0: f64,
) -> CutLoop {
    let n = x0.len();
    let mut rate = vec![0.0; n];
    let mut evaluate = |x: &[f64], u: f64| {
        let taps = LoopCut::new(cut, u);
        system.evaluate(0.0, x, held, &taps, &mut rate);
        (rate.clone(), taps.computed())
    };
    let mut a = DMatrix::zeros(n, n);
    let mut c = DVector::zeros(n);
    for j in 0..n {
        let h = 1e-6 * x0[j].abs().max(1.0);
        let (mut plus, mut minus) = (x0.to_vec(), x0.to_vec());
        plus[j] += h;
        minus[j] -= h;
        let (fp, yp) = evaluate(&plus, u0);
        let (fm, ym) = evaluate(&minus, u0);
        for i in 0..n {
            a[(i, j)] = (fp[i] - fm[i]) / (2.0 * h);
        }
        c[j] = (yp - ym) / (2.0 * h);
    }
    let h = 1e-6 * u0.abs().max(1.0);
    let (fp, yp) = evaluate(x0, u0 + h);
    let (fm, ym) = evaluate(x0, u0 - h);
    let b = DVector::from_iterator(n, (0..n).map(|i| (fp[i] - fm[i]) / (2.0 * h)));
    CutLoop {
        a,
        b,
        c,
        d: (yp - ym) / (2.0 * h),
    }
}

impl CutLoop {
    /// Largest real part of the eigenvalues of A + B C/(1 − D), skipping eigenvalues
    /// within 1e-7 of zero (position and unused filter states).
    fn closed_loop_max_real_part(&self) -> f64 {
        let closed = &self.a + &self.b * self.c.transpose() / (1.0 - self.d);
        closed
            .complex_eigenvalues()
            .iter()
            .filter(|l| l.norm() > 1e-7)
            .map(|l| l.re)
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// L(jω) = −(C (jωI − A)⁻¹ B + D).
    fn loop_gain(&self, omega: f64) -> Complex<f64> {
        let n = self.a.nrows();
        let mut m =
            DMatrix::<Complex<f64>>::from_fn(n, n, |i, j| Complex::new(-self.a[(i, j)], 0.0));
        for i in 0..n {
            m[(i, i)] += Complex::new(0.0, omega);
        }
        let b =
            DVector::<Complex<f64>>::from_iterator(n, self.b.iter().map(|&v| Complex::new(v, 0.0)));
        let x = m.lu().solve(&b).unwrap_or_else(|| DVector::zeros(n));
        let g: Complex<f64> = self
            .c
            .iter()
            .zip(x.iter())
            .map(|(&c, &x)| x * c)
            .sum::<Complex<f64>>()
            + Complex::new(self.d, 0.0);
        -g
    }
}

/// Margins from the loop gain sampled on a logarithmic frequency grid.
fn margins_from_response(cut: LoopBreak, omegas: &[f64], gains: &[Complex<f64>]) -> LoopMargins {
    // Unwrapped phase (deg) and magnitude (dB).
    let mut phases = Vec::with_capacity(gains.len());
    let mut previous = gains[0].arg().to_degrees();
    let mut offset = 0.0;
    for (k, g) in gains.iter().enumerate() {
        let raw = g.arg().to_degrees();
        if k > 0 {
            let jump = raw - previous;
            if jump > 180.0 {
                offset -= 360.0;
            } else if jump < -180.0 {
                offset += 360.0;
            }
        }
        previous = raw;
        phases.push(raw + offset);
    }
    let magnitudes_db: Vec<f64> = gains.iter().map(|g| 20.0 * g.norm().log10()).collect();
    let interpolate = |k: usize, fraction: f64, values: &[f64]| {
        values[k] + fraction * (values[k + 1] - values[k])
    };
    let log_omega = |k: usize, fraction: f64| {
        (omegas[k].ln() + fraction * (omegas[k + 1].ln() - omegas[k].ln())).exp()
    };
    let (modulus_index, modulus_margin) = gains.iter().map(|g| (g + 1.0).norm()).enumerate().fold(
        (0, f64::INFINITY),
        |best, (k, m)| if m < best.1 { (k, m) } else { best },
    );
    let mut result = LoopMargins {
        loop_break: cut,
        crossover_radps: None,
        phase_margin_deg: None,
        phase_crossover_radps: None,
        gain_margin_db: None,
        modulus_margin,
        modulus_margin_radps: omegas[modulus_index],
        closed_loop_max_real_part: f64::NAN,
    };
    for k in 0..omegas.len() - 1 {
        let (m0, m1) = (magnitudes_db[k], magnitudes_db[k + 1]);
        if m0 >= 0.0 && m1 < 0.0 && result.crossover_radps.is_none() {
            let fraction = m0 / (m0 - m1);
            let phase = interpolate(k, fraction, &phases);
            // Phase margin: distance of the phase above −180° (mod 360°).
            let margin = (phase + 180.0).rem_euclid(360.0);
            let margin = if margin > 180.0 {
                margin - 360.0
            } else {
                margin
            };
            result.phase_margin_deg = Some(margin);
            result.crossover_radps = Some(log_omega(k, fraction));
        }
        // Phase crossings of −180° + 360°·n.
        let (p0, p1) = (phases[k], phases[k + 1]);
        let n0 = ((p0 + 180.0) / 360.0).floor();
        let n1 = ((p1 + 180.0) / 360.0).floor();
        if n0 != n1 {
            let level = -180.0 + 360.0 * n0.max(n1);
            let fraction = (level - p0) / (p1 - p0);
            let margin = -interpolate(k, fraction, &magnitudes_db);
            if margin > 0.0 && result.gain_margin_db.is_none_or(|m| margin < m) {
                result.gain_margin_db = Some(margin);
                result.phase_crossover_radps = Some(log_omega(k, fraction));
            }
        }
    }
    result
}

/// The margins of the pitch, sink-rate, guidance and speed loops of `scenario`'s cascade,
/// and of its direct-lift loop when it flies one, linearised at the start of an approach
/// in ideal conditions.
///
/// The cascade is linearised on the 3-DOF aircraft whatever `scenario`'s model: wings
/// level with the lateral states at rest, the 6-DOF flies the 3-DOF's longitudinal
/// trajectory (docs/six-dof.md; the tests agree to 1e-9), while its linearisation here
/// would carry the lateral modes with their loops open (the lateral laws' margins are
/// `tests/lateral_laws.rs`'s and `tests/heading_hold_margins.rs`'s).
pub fn cascade_margins(scenario: &Scenario) -> Result<Vec<LoopMargins>, SetupError> {
    let mut linear = scenario.ideal();
    linear.aircraft.model = PlantModel::ThreeDof;
    linear.mission = crate::scenario::Mission::Approach;
    // The flight computer's zero-order hold enters as its equivalent delay of half a
    // frame: the linearisation needs the commands to follow the state continuously.
    let hold_delay_s = linear
        .control
        .flight_computer_rate_hz
        .map_or(0.0, |rate| 0.5 / rate);
    linear.control.flight_computer_rate_hz = None;
    if let PitchControllerParameters::ObserverPd(p) = &mut linear.control.pitch {
        p.observer.alpha1 = 1.0 - 1e-9;
    }
    let mut simulation = Simulation::new(&linear)?;
    let held = simulation.next_step_inputs();
    let system = simulation.system();
    let x0 = simulation.state();
    let nominal = simulation.signals();
    let omegas: Vec<f64> = (0..=1200)
        .map(|k| 10f64.powf(-3.0 + 5.0 * k as f64 / 1200.0))
        .collect();
    let mut all = Vec::new();
    let direct_lift = nominal
        .direct_lift_command
        .map(|command| (LoopBreak::DirectLiftCommand, command));
    for (cut, u0) in [
        (LoopBreak::ElevatorCommand, nominal.elevator_command_rad),
        (LoopBreak::PitchCommand, nominal.theta_ref_rad),
        // An approach always commands a climb rate.
        (
            LoopBreak::ClimbRateCommand,
            nominal.climb_rate_command_mps.unwrap_or_default(),
        ),
        (LoopBreak::ThrustCommand, nominal.thrust_command_n),
    ]
    .into_iter()
    .chain(direct_lift)
    {
        let model = linearise(system, &held, x0, cut, u0);
        let gains: Vec<Complex<f64>> = omegas
            .iter()
            .map(|&w| model.loop_gain(w) * Complex::from_polar(1.0, -w * hold_delay_s))
            .collect();
        let mut margins = margins_from_response(cut, &omegas, &gains);
        margins.closed_loop_max_real_part = model.closed_loop_max_real_part();
        all.push(margins);
    }
    Ok(all)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 2001 frequencies from 0.01 to 100 rad/s, logarithmically spaced.
    fn log_grid() -> Vec<f64> {
        (0..=2000)
            .map(|k| 10f64.powf(-2.0 + 4.0 * k as f64 / 2000.0))
            .collect()
    }

    /// The margins of the loop gain `loop_gain(ω)` over [`log_grid`].
    fn margins_of(loop_gain: impl Fn(f64) -> Complex<f64>) -> LoopMargins {
        let omegas = log_grid();
        let gains: Vec<Complex<f64>> = omegas.iter().map(|&w| loop_gain(w)).collect();
        margins_from_response(LoopBreak::PitchCommand, &omegas, &gains)
    }

    /// L(s) = K/(s(s + 1)) with K = 2: |L(jω)| = 1 at ω² = (−1 + √17)/2, ω = 1.2496;
    /// phase −90° − atan ω = −141.3°, so PM = 38.7°; the phase never reaches −180°.
    #[test]
    fn margins_of_a_textbook_loop() {
        let m = margins_of(|w| {
            let s = Complex::new(0.0, w);
            Complex::new(2.0, 0.0) / (s * (s + 1.0))
        });
        assert!((m.crossover_radps.unwrap() - 1.2496).abs() < 1e-3);
        assert!((m.phase_margin_deg.unwrap() - 38.67).abs() < 0.1);
        assert!(m.gain_margin_db.is_none());
        // |1 + L| is smallest near the crossover, and below 1 there.
        assert!(
            m.modulus_margin < 1.0 && m.modulus_margin > 0.5,
            "{}",
            m.modulus_margin
        );
    }

    /// L(s) = 4/(s + 1)³: phase −180° at ω = √3 where |L| = 4/8, GM = 6.02 dB.
    #[test]
    fn gain_margin_of_a_third_order_loop() {
        let m = margins_of(|w| {
            let p = Complex::new(1.0, w);
            Complex::new(4.0, 0.0) / (p * p * p)
        });
        assert!((m.phase_crossover_radps.unwrap() - 3f64.sqrt()).abs() < 1e-3);
        assert!((m.gain_margin_db.unwrap() - 20.0 * 2f64.log10()).abs() < 0.01);
    }
}
