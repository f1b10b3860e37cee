//! Ship roll, yaw and sway (docs/model.md §3.7; issue 27 target "the roll, yaw and sway
//! RMS over 16 seeds match the parameters within 5 %, checked against the filters'
//! Lyapunov variance").
//!
//! The reference variances are computed here independently of the library: the roll
//! filter's from the textbook closed form of a second-order system driven by white
//! noise, 1/(4ζω³), and the 1/D(s) filter's by integrating its power spectrum
//! |1/D(jω)|² numerically (σ² = (1/π)∫₀^∞ |G(jω)|² dω for unit intensity), not by the
//! Lyapunov solver under test.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::environment::{
    LateralShipMotion, LateralShipMotionState, LateralShipStreams, ShipMotionParameters,
    ROLL_FILTER_DAMPING_RATIO, ROLL_FILTER_NATURAL_FREQUENCY_RADPS, SHAPING_FILTER_DENOMINATOR,
};
use deckland::random::RandomStreams;

/// Stationary variance of a second-order filter 1/(s² + 2ζωs + ω²) under unit-intensity
/// white noise: 1/(4ζω³) (e.g. Newland, *Random Vibrations*, Eq. 7.22 for the
/// displacement of a damped oscillator).
fn roll_reference_variance() -> f64 {
    let (omega, zeta) = (
        ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
        ROLL_FILTER_DAMPING_RATIO,
    );
    1.0 / (4.0 * zeta * omega.powi(3))
}

/// Stationary variance of 1/D(s) under unit-intensity white noise, (1/π)∫₀^∞ |1/D(jω)|² dω,
/// by Simpson's rule on [0, 200] rad/s (the tail beyond falls as ω⁻⁸ and adds < 1e-15).
fn canonical_reference_variance() -> f64 {
    let [d0, d1, d2, d3] = SHAPING_FILTER_DENOMINATOR;
    let power = |w: f64| {
        // D(jω) = ω⁴ − d₂ω² + d₀ + j(−d₃ω³ + d₁ω).
        let re = w.powi(4) - d2 * w * w + d0;
        let im = -d3 * w.powi(3) + d1 * w;
        1.0 / (re * re + im * im)
    };
    let (upper, intervals) = (200.0, 2_000_000);
    let h = upper / f64::from(intervals);
    let mut sum = power(0.0) + power(upper);
    for k in 1..intervals {
        let weight = if k % 2 == 1 { 4.0 } else { 2.0 };
        sum += weight * power(f64::from(k) * h);
    }
    sum * h / 3.0 / std::f64::consts::PI
}

#[test]
fn the_spectral_variance_of_one_over_d_agrees_with_model_md() {
    // docs/model.md §3.1: heave 1.21²·σ² = 43.62 m² (numpy: 43.6226).
    let variance = canonical_reference_variance();
    assert!(
        (1.21_f64.powi(2) * variance - 43.6226).abs() < 1e-3,
        "{variance}"
    );
}

#[test]
fn noise_intensities_give_the_configured_rms_by_the_reference_variances() {
    let parameters = ShipMotionParameters::default();
    let model = LateralShipMotion::new(&parameters).unwrap();
    let [roll_q, yaw_q, sway_q] = model.noise_intensities();
    let roll = (roll_q * roll_reference_variance()).sqrt().to_degrees();
    let yaw = (yaw_q * canonical_reference_variance()).sqrt().to_degrees();
    let sway = (sway_q * canonical_reference_variance()).sqrt();
    assert!(
        (roll / parameters.roll_rms_deg - 1.0).abs() < 1e-6,
        "{roll}"
    );
    assert!((yaw / parameters.yaw_rms_deg - 1.0).abs() < 1e-6, "{yaw}");
    assert!((sway / parameters.sway_rms_m - 1.0).abs() < 1e-6, "{sway}");
}

/// One RK4 step of the filters under noise held over the step (as the closed loop
/// integrates the heave and pitch filters).
fn rk4_step(
    model: &LateralShipMotion,
    state: &LateralShipMotionState,
    noise: deckland::environment::LateralShipNoise,
    dt: f64,
) -> LateralShipMotionState {
    let x = state.to_array();
    let f = |x: &[f64; 10]| {
        model
            .derivative(&LateralShipMotionState::from_array(x), noise)
            .to_array()
    };
    let add = |x: &[f64; 10], k: &[f64; 10], a: f64| -> [f64; 10] {
        std::array::from_fn(|i| x[i] + a * k[i])
    };
    let k1 = f(&x);
    let k2 = f(&add(&x, &k1, dt / 2.0));
    let k3 = f(&add(&x, &k2, dt / 2.0));
    let k4 = f(&add(&x, &k3, dt));
    LateralShipMotionState::from_array(&std::array::from_fn(|i| {
        x[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i])
    }))
}

#[test]
fn roll_yaw_and_sway_rms_over_16_seeds_match_the_parameters_within_5_percent() {
    let parameters = ShipMotionParameters::default();
    let model = LateralShipMotion::new(&parameters).unwrap();
    let (dt, duration_s) = (0.05, 3000.0);
    let steps = (duration_s / dt) as usize;
    let mut sums = [0.0; 3];
    let mut count = 0.0;
    for seed in 1..=16 {
        let mut streams = LateralShipStreams::new(&RandomStreams::new(seed));
        let mut state = model.stationary_initial_state(&mut streams);
        for _ in 0..steps {
            let noise = model.draw_noise(&mut streams, dt);
            state = rk4_step(&model, &state, noise, dt);
            let out = model.outputs(&state);
            sums[0] += out.roll_rad.powi(2);
            sums[1] += out.yaw_rad.powi(2);
            sums[2] += out.sway_m.powi(2);
            count += 1.0;
        }
    }
    // Sampling error: a sample variance over T has relative standard error √(2·I/T),
    // I = ∫ρ²(τ)dτ over all lags ≈ 1/(2·decay rate) for a lightly damped pair: roll
    // (decay ζω = 0.031 /s) 15.9 s, 1/D(s) (0.04 /s) 12.5 s. Over 16 × 3000 s the RMS
    // then has a relative standard error of 1.3 % (roll) and 1.1 %: 5 % is about 4 of
    // them.
    let [q_roll, q_yaw, q_sway] = model.noise_intensities();
    let expected = [
        (q_roll * roll_reference_variance()).sqrt(),
        (q_yaw * canonical_reference_variance()).sqrt(),
        (q_sway * canonical_reference_variance()).sqrt(),
    ];
    let configured = [
        parameters.roll_rms_deg.to_radians(),
        parameters.yaw_rms_deg.to_radians(),
        parameters.sway_rms_m,
    ];
    for (i, name) in ["roll", "yaw", "sway"].iter().enumerate() {
        let rms = (sums[i] / count).sqrt();
        assert!(
            (rms / expected[i] - 1.0).abs() < 0.05,
            "{name}: simulated RMS {rms}, Lyapunov {}",
            expected[i]
        );
        assert!((expected[i] / configured[i] - 1.0).abs() < 1e-6, "{name}");
        eprintln!(
            "{name}: simulated RMS / configured = {:.4}",
            rms / configured[i]
        );
    }
}

#[test]
fn the_filters_start_from_their_stationary_distribution() {
    // The RMS of the initial state over 2000 seeds: relative standard error 1/√(2·2000)
    // = 1.6 %; allowed 5 %.
    let parameters = ShipMotionParameters::default();
    let model = LateralShipMotion::new(&parameters).unwrap();
    let mut sums = [0.0; 3];
    let seeds = 2000;
    for seed in 0..seeds {
        let mut streams = LateralShipStreams::new(&RandomStreams::new(seed));
        let out = model.outputs(&model.stationary_initial_state(&mut streams));
        sums[0] += out.roll_rad.to_degrees().powi(2);
        sums[1] += out.yaw_rad.to_degrees().powi(2);
        sums[2] += out.sway_m.powi(2);
    }
    let configured = [
        parameters.roll_rms_deg,
        parameters.yaw_rms_deg,
        parameters.sway_rms_m,
    ];
    for (sum, rms) in sums.iter().zip(configured) {
        let sample = (sum / seeds as f64).sqrt();
        assert!((sample / rms - 1.0).abs() < 0.05, "{sample} vs {rms}");
    }
}

#[test]
fn lateral_keys_out_of_range_are_refused_by_name() {
    for (text, key) in [
        ("[environment.ship]\nroll_rms_deg = 31.0\n", "roll_rms_deg"),
        ("[environment.ship]\nyaw_rms_deg = -0.1\n", "yaw_rms_deg"),
        ("[environment.ship]\nsway_rms_m = 25.0\n", "sway_rms_m"),
    ] {
        let error = deckland::scenario::load_scenario(text, "lateral.toml").unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains(&format!("environment.ship.{key}")),
            "{message}"
        );
    }
}
