//! The carrier's motion spectra in sea states 3–6 (docs/model.md §12, docs/seaway-results.md
//! "Motion"): for heave, pitch and roll, the response spectrum |H(ω_e)|²·S(ω_e) the fit aims
//! at, the fitted model's spectrum, and (heave and pitch) a Welch periodogram of the ship
//! the landing loop flies, stepped on its own.
//!
//! The seaway is the scenarios' (`scenarios/sea-state-N.toml`): the sea-state table's H_s
//! and T_p, Pierson–Moskowitz, head seas, cos² spreading, the hull at the ship's default
//! 7.7 m/s (15 kn), as `SeawayShip` builds it.
//!
//! - `target`: [`motion_target`] (4000 cells), interpolated linearly between its midpoints;
//! - `fit`: the one-section model the loop flies ([`SeawayModel::fit_single_section`], whose
//!   heave and pitch are the loop's shaping filters); roll's is fitted the same way, though
//!   the loop drives the roll filter of docs/model.md §3.7 at the seaway's roll RMS instead;
//! - `simulated`: heave and pitch of [`ShipMotionSimulator`] (RK4, held noise, 0.01 s),
//!   sampled every 0.25 s, Welch (Hann, 256-s segments, half overlap); empty for roll.
//!
//! Units: heave m²·s/rad, pitch and roll deg²·s/rad, one-sided (∫₀^∞ Φ dω_e = variance).
//! Stdout is the CSV; stderr the variance checks.
//!
//! `cargo run --release -p deckland --example seaway_spectra [SECONDS] | python3
//! docs/images/seaway_spectra.py > docs/images/seaway_spectra.svg` (default 40 000 s of
//! simulated ship per sea, seed 7).

use std::f64::consts::PI;

use deckland::environment::seaway::{motion_target, Motion, SeawayModel, SeawayParameters};
use deckland::environment::{ship_motion, ShipMotionParameters, ShipMotionSimulator};
use deckland::random::RandomStreams;

/// Encounter-frequency grid of the CSV (rad/s): `GRID_POINTS` points, ends included.
const GRID_LOW_RADPS: f64 = 0.05;
const GRID_HIGH_RADPS: f64 = 2.0;
const GRID_POINTS: usize = 200;
/// The simulated ship: step, sampling interval, Welch segment length (samples) and seed.
const STEP_S: f64 = 0.01;
const STEPS_PER_SAMPLE: usize = 25;
const SEGMENT: usize = 1024;
const SEED: u64 = 7;

fn main() {
    let seconds: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(40_000.0);
    let grid: Vec<f64> = (0..GRID_POINTS)
        .map(|i| {
            GRID_LOW_RADPS
                + (GRID_HIGH_RADPS - GRID_LOW_RADPS) * i as f64 / (GRID_POINTS - 1) as f64
        })
        .collect();
    println!("sea_state,motion,omega_e_radps,target,fit,simulated");
    eprintln!(
        "variance checks: target = Σ Φ Δω_e over motion_target's cells; fit = ∫₀^60 Φ_fit dω_e \
         (Simpson) against the model's Lyapunov variance; window = share of the target's \
         variance in [{GRID_LOW_RADPS}, {GRID_HIGH_RADPS}] rad/s; simulated = sample variance \
         of {seconds} s and ∫ Welch over the window against ∫ target there"
    );
    for sea_state in [3, 4, 5, 6] {
        let ship = ShipMotionParameters::default();
        let mut seaway = SeawayParameters::sea_state(sea_state).expect("in the table");
        seaway.hull.speed_mps = ship.forward_speed_mps;
        let model = SeawayModel::fit_single_section(&seaway).expect("the table's seas fit");
        let simulated = simulate(&ship, &seaway, seconds);
        for (motion, fitted) in [
            (Motion::Heave, &model.heave),
            (Motion::Pitch, &model.pitch),
            (Motion::Roll, &model.roll),
        ] {
            let target = motion_target(&seaway, motion).expect("valid");
            // Output units: m for heave, deg for pitch and roll.
            let unit2 = match motion {
                Motion::Heave => 1.0,
                Motion::Pitch | Motion::Roll => (180.0 / PI).powi(2),
            };
            let record = match motion {
                Motion::Heave => Some(&simulated.0),
                Motion::Pitch => Some(&simulated.1),
                Motion::Roll => None,
            };
            let periodogram =
                record.map(|record| welch(record, STEP_S * STEPS_PER_SAMPLE as f64, &grid));
            for (i, &omega_e) in grid.iter().enumerate() {
                let simulated = periodogram
                    .as_ref()
                    .map(|p| format!("{:.6e}", p[i] * unit2))
                    .unwrap_or_default();
                println!(
                    "{sea_state},{},{omega_e:.5},{:.6e},{:.6e},{simulated}",
                    motion.name(),
                    target.interpolate(omega_e) * unit2,
                    fitted.model.spectral_density(omega_e) * unit2,
                );
            }
            let report = fitted.report;
            let fit_integral = simpson(|w| fitted.model.spectral_density(w), 0.0, 60.0, 600_000);
            let window =
                |f: &dyn Fn(f64) -> f64| simpson(f, GRID_LOW_RADPS, GRID_HIGH_RADPS, 20_000);
            let target_window = window(&|w| target.interpolate(w));
            eprintln!(
                "SS{sea_state} {:5}: RMS {:.4} {}; target {:.5e}, fit ∫ {:.5e} / Lyapunov \
                 {:.5e} = {:.5}, / target = {:.5}; window holds {:.2} % of the target; \
                 shape error {:.3}",
                motion.name(),
                (report.target_variance * unit2).sqrt(),
                if motion == Motion::Heave { "m" } else { "deg" },
                target.variance(),
                fit_integral,
                report.model_variance,
                fit_integral / report.model_variance,
                fit_integral / target.variance(),
                100.0 * target_window / target.variance(),
                report.shape_error,
            );
            assert!(
                (fit_integral / report.model_variance - 1.0).abs() < 0.01,
                "the fit's spectrum does not integrate to its variance"
            );
            if let (Some(p), Some(record)) = (&periodogram, record) {
                let sample = record.iter().map(|x| x * x).sum::<f64>() / record.len() as f64;
                let welch_window: f64 = p
                    .windows(2)
                    .zip(grid.windows(2))
                    .map(|(p, w)| 0.5 * (p[0] + p[1]) * (w[1] - w[0]))
                    .sum();
                eprintln!(
                    "          simulated: variance {:.5e} / target {:.4}; ∫ Welch over the \
                     window / ∫ target there {:.4}",
                    sample,
                    sample / target.variance(),
                    welch_window / target_window,
                );
            }
        }
    }
}

/// Composite Simpson's rule of f over [a, b] with `n` (even) intervals.
fn simpson(f: impl Fn(f64) -> f64, a: f64, b: f64, n: usize) -> f64 {
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|i| f(a + h * i as f64) * if i % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    (f(a) + f(b) + inner) * h / 3.0
}

/// Heave (m) and pitch (rad) of the ship the loop flies in this seaway, `seconds` long,
/// sampled every `STEPS_PER_SAMPLE` steps.
fn simulate(
    ship: &ShipMotionParameters,
    seaway: &SeawayParameters,
    seconds: f64,
) -> (Vec<f64>, Vec<f64>) {
    let model = ship_motion(ship, seaway).expect("the scenario's ship");
    let mut simulator = ShipMotionSimulator::with_model(model, &RandomStreams::new(SEED), 0.0);
    let samples = (seconds / (STEP_S * STEPS_PER_SAMPLE as f64)) as usize;
    let (mut heave, mut pitch) = (Vec::with_capacity(samples), Vec::with_capacity(samples));
    for _ in 0..samples {
        for _ in 0..STEPS_PER_SAMPLE {
            simulator.step(STEP_S);
        }
        let outputs = simulator.outputs();
        heave.push(outputs.heave_m);
        pitch.push(outputs.pitch_rad);
    }
    (heave, pitch)
}

/// Welch's one-sided spectral density of `record` (spacing `dt` s) at the frequencies
/// `omegas` (rad/s): Hann segments of `SEGMENT` samples, half overlapping, each less its
/// mean, Φ(ω) = dt·|Σ wₙxₙe^{−iωn·dt}|²/(π Σwₙ²) averaged (a direct DFT at each ω).
fn welch(record: &[f64], dt: f64, omegas: &[f64]) -> Vec<f64> {
    let window: Vec<f64> = (0..SEGMENT)
        .map(|n| 0.5 - 0.5 * (2.0 * PI * n as f64 / SEGMENT as f64).cos())
        .collect();
    let window_power: f64 = window.iter().map(|w| w * w).sum();
    let twiddles: Vec<Vec<(f64, f64)>> = omegas
        .iter()
        .map(|&omega| {
            (0..SEGMENT)
                .map(|n| {
                    let phase = omega * n as f64 * dt;
                    (phase.cos(), -phase.sin())
                })
                .collect()
        })
        .collect();
    let mut sums = vec![0.0; omegas.len()];
    let mut segments = 0usize;
    let mut start = 0;
    while start + SEGMENT <= record.len() {
        let segment = &record[start..start + SEGMENT];
        let mean = segment.iter().sum::<f64>() / SEGMENT as f64;
        let tapered: Vec<f64> = segment
            .iter()
            .zip(&window)
            .map(|(x, w)| (x - mean) * w)
            .collect();
        for (sum, twiddle) in sums.iter_mut().zip(&twiddles) {
            let (re, im) = tapered
                .iter()
                .zip(twiddle)
                .fold((0.0, 0.0), |(re, im), (x, (c, s))| (re + x * c, im + x * s));
            *sum += re * re + im * im;
        }
        segments += 1;
        start += SEGMENT / 2;
    }
    sums.iter()
        .map(|s| dt * s / (PI * window_power * segments.max(1) as f64))
        .collect()
}
