//! Rate saturation of the elevator in a closed loop: when it starts, and whether the
//! rate limit can sustain an oscillation (a limit cycle, the mechanism of rate-limit
//! pilot-induced oscillations), by the describing function of a rate limiter.
//!
//! A rate limiter y' = R·sign(x − y) (slewing at ±R whenever the output lags its input)
//! driven by x = A·sin ωt saturates when A·ω > R. With the overdrive κ = A·ω/R its
//! describing function (the fundamental of the output over the input) is
//!
//! ```text
//! N(κ) = 1                                               κ ≤ 1
//! N(κ) = (4/(πκ))·exp(−j·acos(π/(2κ)))                   κ ≥ √(1 + π²/4) = 1.862
//! ```
//!
//! In the second range the output is a triangle wave of amplitude πR/(2ω) that turns
//! where it meets the input (fundamental 8/π² of the triangle's amplitude, lagging the
//! input by acos(π/(2κ))); between 1 and 1.862 the output follows the input part of the
//! period, and N is computed here from one simulated period. The closed form is the
//! classical one (e.g. D. Klyde & D. Mitchell, "A PIO case study — lessons learned
//! through analysis", AIAA 2005-5811; H. Duda, "Prediction of pilot-in-the-loop
//! oscillations due to rate saturation", JGCD 20(3), 1997); the unit tests check it
//! against the simulated limiter.
//!
//! In a loop with linear part L(jω) (cut at the rate limiter's input, negative feedback)
//! a limit cycle is predicted where 1 + N(κ)·L(jω) = 0: |N(κ)|·|L(jω)| = 1 and
//! ∠N(κ) + ∠L(jω) = −180°. Since ∠N lies in (−90°, 0], only frequencies where L's phase
//! is between −180° and −90° with |L| ≥ 1 can host one; its amplitude at the limiter's
//! input is A = κ·R/ω.

use nalgebra::Complex;
use std::f64::consts::PI;
use std::sync::OnceLock;

/// Overdrive above which a rate limiter's output is a pure triangle wave: √(1 + π²/4).
pub const TRIANGLE_OVERDRIVE: f64 = 1.862_096_958_062_676;

/// Describing function N(κ) of a rate limiter for the overdrive κ = A·ω/R (module docs).
pub fn rate_limiter_describing_function(overdrive: f64) -> Complex<f64> {
    if overdrive <= 1.0 {
        Complex::new(1.0, 0.0)
    } else if overdrive >= TRIANGLE_OVERDRIVE {
        Complex::from_polar(4.0 / (PI * overdrive), -(PI / (2.0 * overdrive)).acos())
    } else {
        simulated_describing_function(overdrive, 20_000)
    }
}

/// N(κ) from a simulated rate limiter (amplitude 1, frequency 1, rate limit 1/κ) with
/// `steps_per_period` steps, after 30 periods for the start-up to die out: the output's
/// first Fourier coefficient over the 31st period divided by the input's.
pub fn simulated_describing_function(overdrive: f64, steps_per_period: usize) -> Complex<f64> {
    simulated_after(overdrive, steps_per_period, 30)
}

/// N(κ) from a simulated rate limiter over the period after `warm_up` periods. Below the
/// triangle range (κ < 1.862) the output meets the input in every period, and its only
/// memory is its own value, so it is periodic from the first meeting on: three periods
/// of warm-up give the 30-period value (unit test), at a tenth of the cost.
fn simulated_after(overdrive: f64, steps_per_period: usize, warm_up: usize) -> Complex<f64> {
    let rate = 1.0 / overdrive;
    let dt = 2.0 * PI / steps_per_period as f64;
    let mut output = 0.0;
    let (mut in_phase, mut quadrature) = (0.0, 0.0);
    for k in 1..=(warm_up + 1) * steps_per_period {
        let t = k as f64 * dt;
        let input = t.sin();
        output += (input - output).clamp(-rate * dt, rate * dt);
        if k > warm_up * steps_per_period {
            in_phase += output * t.sin() * dt;
            quadrature += output * t.cos() * dt;
        }
    }
    // Fundamental b·sin + a·cos = |N|·sin(t + ∠N): N = (b + j·a)/π per unit amplitude.
    Complex::new(in_phase / PI, quadrature / PI)
}

/// A limit cycle predicted by the describing function.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PredictedLimitCycle {
    /// Frequency (rad/s).
    pub frequency_radps: f64,
    /// Overdrive κ = A·ω/R.
    pub overdrive: f64,
    /// Amplitude at the rate limiter's input A = κ·R/ω (input's unit).
    pub amplitude: f64,
}

/// Warm-up periods of the table's simulated points (below the triangle range).
const TABLE_WARM_UP_PERIODS: usize = 3;

/// One point of the tabulated describing function.
#[derive(Debug, Clone, Copy)]
struct TablePoint {
    overdrive: f64,
    magnitude: f64,
    phase_rad: f64,
}

/// N tabulated once on a logarithmic κ grid from 1 to 10⁴ (601 points; simulated below
/// the triangle range, closed form above): its phase falls monotonically from 0 to −90°
/// (checked by a unit test), so a phase is found by bisection.
fn describing_function_table() -> &'static [TablePoint] {
    static TABLE: OnceLock<Vec<TablePoint>> = OnceLock::new();
    TABLE.get_or_init(|| {
        (0..=600)
            .map(|k| {
                let overdrive = 10f64.powf(4.0 * k as f64 / 600.0);
                let n = if overdrive < TRIANGLE_OVERDRIVE {
                    simulated_after(overdrive, 4000, TABLE_WARM_UP_PERIODS)
                } else {
                    rate_limiter_describing_function(overdrive)
                };
                TablePoint {
                    overdrive,
                    magnitude: n.norm(),
                    phase_rad: n.arg(),
                }
            })
            .collect()
    })
}

/// The overdrive κ at which ∠N(κ) = `phase_rad` and |N(κ)| there, interpolated in the
/// table; `None` outside the table's phases.
fn overdrive_at_phase(table: &[TablePoint], phase_rad: f64) -> Option<(f64, f64)> {
    // Phases fall along the table: the first point at or below the phase ends the bracket.
    let k = table.partition_point(|p| p.phase_rad > phase_rad);
    if k == 0 || k >= table.len() {
        return None;
    }
    let (a, b) = (table[k - 1], table[k]);
    let span = b.phase_rad - a.phase_rad;
    let f = if span.abs() < 1e-15 {
        0.0
    } else {
        (phase_rad - a.phase_rad) / span
    };
    Some((
        a.overdrive + f * (b.overdrive - a.overdrive),
        a.magnitude + f * (b.magnitude - a.magnitude),
    ))
}

/// The limit cycles that a rate limit `rate_limit` (input's unit per s) can sustain in a
/// loop with linear part `loop_gain(ω)` (cut at the limiter's input, negative feedback),
/// searched on `omegas` (rad/s, increasing), smallest amplitude first. Empty: none
/// predicted at any amplitude on the grid.
pub fn rate_limit_cycles(
    loop_gain: impl Fn(f64) -> Complex<f64>,
    rate_limit: f64,
    omegas: &[f64],
) -> Vec<PredictedLimitCycle> {
    let response: Vec<Complex<f64>> = omegas.iter().map(|&w| loop_gain(w)).collect();
    rate_limit_cycles_sampled(omegas, &response, rate_limit)
}

/// [`rate_limit_cycles`] of a loop gain already sampled: `response[k]` = L(j·`omegas[k]`).
pub fn rate_limit_cycles_sampled(
    omegas: &[f64],
    response: &[Complex<f64>],
    rate_limit: f64,
) -> Vec<PredictedLimitCycle> {
    let table = describing_function_table();
    // For each ω: the κ whose phase makes 1 + N·L real-axis aligned, and the magnitude
    // mismatch |N(κ)|·|L| − 1 there.
    let residual = |l: Complex<f64>| -> Option<(f64, f64)> {
        let needed_phase = (-1.0 / l).arg(); // ∠N must equal this, in (−π/2, 0].
        if !(needed_phase <= 0.0 && needed_phase > -0.5 * PI) {
            return None;
        }
        let (overdrive, magnitude) = overdrive_at_phase(table, needed_phase)?;
        Some((overdrive, magnitude * l.norm() - 1.0))
    };
    let mut cycles = Vec::new();
    let mut previous: Option<(f64, f64, f64)> = None;
    for (&omega, &l) in omegas.iter().zip(response) {
        let current = residual(l).map(|(k, r)| (omega, k, r));
        if let (Some((w0, k0, r0)), Some((w1, k1, r1))) = (previous, current) {
            if r0.signum() != r1.signum() {
                let f = r0 / (r0 - r1);
                let frequency_radps = w0 + f * (w1 - w0);
                let overdrive = k0 + f * (k1 - k0);
                if overdrive > 1.0 {
                    cycles.push(PredictedLimitCycle {
                        frequency_radps,
                        overdrive,
                        amplitude: overdrive * rate_limit / frequency_radps,
                    });
                }
            }
        }
        previous = current;
    }
    cycles.sort_by(|a, b| a.amplitude.total_cmp(&b.amplitude));
    cycles
}

/// Amplitude of a sinusoidal input at `omega` (rad/s) at which the rate limiter starts to
/// saturate, when the input reaches the limiter through a gain `gain_to_limiter`
/// (limiter input per unit of that input at `omega`): R/(ω·|gain|).
pub fn saturation_onset_amplitude(rate_limit: f64, omega: f64, gain_to_limiter: f64) -> f64 {
    rate_limit / (omega * gain_to_limiter.abs())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Below the triangle range three warm-up periods give the same describing function
    /// as thirty: the limiter's output is periodic from its first meeting with the input.
    #[test]
    fn three_warm_up_periods_suffice_below_the_triangle_range() {
        for overdrive in [1.01, 1.2, 1.5, 1.8, 1.86] {
            let short = simulated_after(overdrive, 4000, TABLE_WARM_UP_PERIODS);
            let long = simulated_describing_function(overdrive, 4000);
            assert!(
                (short - long).norm() < 1e-9,
                "κ {overdrive}: {short} vs {long}"
            );
        }
    }

    /// The bisection in `overdrive_at_phase` needs the table's phase to fall
    /// monotonically (the rate limiter lags more the harder it is driven).
    #[test]
    fn tabulated_phase_falls_monotonically() {
        let table = describing_function_table();
        for pair in table.windows(2) {
            assert!(
                pair[1].phase_rad <= pair[0].phase_rad,
                "κ {} → {}: {} → {}",
                pair[0].overdrive,
                pair[1].overdrive,
                pair[0].phase_rad,
                pair[1].phase_rad
            );
        }
        assert!(table[0].phase_rad.abs() < 1e-9);
        assert!(table[table.len() - 1].phase_rad < -0.49 * PI);
    }

    /// At and beyond √(1 + π²/4) the simulated limiter's fundamental matches the closed
    /// form (4/(πκ))·e^{−j·acos(π/(2κ))}: at κ = 2, |N| = 2/π = 0.63662 and
    /// ∠N = −acos(π/4) = −38.24°; at κ = 10, 0.12732 and −80.96°.
    #[test]
    fn closed_form_matches_the_simulated_limiter() {
        for (overdrive, magnitude, phase_deg) in [
            (2.0, std::f64::consts::FRAC_2_PI, -38.24),
            (10.0, 0.127_32, -80.96),
        ] {
            let closed = rate_limiter_describing_function(overdrive);
            let simulated = simulated_describing_function(overdrive, 40_000);
            assert!((closed.norm() - magnitude).abs() < 1e-4, "{closed}");
            assert!(
                (closed.arg().to_degrees() - phase_deg).abs() < 0.01,
                "{closed}"
            );
            assert!(
                (closed - simulated).norm() < 2e-4,
                "{closed} vs {simulated}"
            );
        }
    }

    /// Below the onset the limiter is transparent; between onset and the triangle regime
    /// the describing function is continuous with the closed form at κ = 1.862.
    #[test]
    fn describing_function_is_continuous_from_onset_to_triangle() {
        assert_eq!(
            rate_limiter_describing_function(0.5),
            Complex::new(1.0, 0.0)
        );
        let near_onset = rate_limiter_describing_function(1.0001);
        assert!((near_onset - 1.0).norm() < 1e-2, "{near_onset}");
        let below = simulated_describing_function(TRIANGLE_OVERDRIVE - 1e-6, 40_000);
        let above = rate_limiter_describing_function(TRIANGLE_OVERDRIVE);
        assert!((below - above).norm() < 2e-4, "{below} vs {above}");
        // Magnitude falls and lag grows monotonically with the overdrive.
        let mut last = rate_limiter_describing_function(1.0);
        for k in 1..40 {
            let n = rate_limiter_describing_function(1.0 + 0.05 * k as f64);
            assert!(n.norm() <= last.norm() + 1e-9 && n.arg() <= last.arg() + 1e-9);
            last = n;
        }
    }

    /// A double integrator with PD control and a rate limit, L(s) = (K_P + K_D s)/s²:
    /// the lag of the limiter meets the loop's phase where |N|·|L| = 1, which the
    /// describing function predicts; the prediction satisfies 1 + N·L = 0.
    #[test]
    fn predicts_the_pd_double_integrator_limit_cycle() {
        let (kp, kd, rate) = (25.0, 10.0, 0.7);
        let loop_gain = |w: f64| {
            let s = Complex::new(0.0, w);
            (kp + kd * s) / (s * s)
        };
        let omegas: Vec<f64> = (0..2000)
            .map(|k| 10f64.powf(-1.0 + 3.0 * k as f64 / 2000.0))
            .collect();
        let cycles = rate_limit_cycles(loop_gain, rate, &omegas);
        assert!(!cycles.is_empty());
        for cycle in cycles {
            let n = rate_limiter_describing_function(cycle.overdrive);
            let characteristic = 1.0 + n * loop_gain(cycle.frequency_radps);
            assert!(characteristic.norm() < 0.02, "{cycle:?}: {characteristic}");
            assert!(
                (cycle.amplitude - cycle.overdrive * rate / cycle.frequency_radps).abs() < 1e-12
            );
        }
    }

    #[test]
    fn onset_amplitude_is_rate_over_frequency() {
        assert!((saturation_onset_amplitude(0.7, 2.0, 0.5) - 0.7).abs() < 1e-15);
    }
}
