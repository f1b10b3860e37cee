//! Wind in three dimensions (docs/model.md §3.9; shared model §10.6): the crosswind, the
//! mean wind over the angled deck, and lateral free-air turbulence.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::environment::{
    mean_wind, mean_wind_over_angled_deck, LateralTurbulence, WindModel, WindParameters,
};
use deckland::random::RandomStreams;

#[test]
fn lateral_turbulence_has_sigma_u_and_the_dryden_autocorrelation() {
    // MIL-F-8785C low altitude: σ_v = σ_u, L_v = L_u. A first-order Dryden process with
    // time constant τ = L/V has autocorrelation e^(−|lag|/τ) (the Fourier pair of its
    // spectrum 2σ²τ/(1 + (τω)²)).
    let parameters = WindParameters::default();
    let mut turbulence = LateralTurbulence::new(&parameters, &RandomStreams::new(8));
    let airspeed_mps = 69.1;
    let tau_s = parameters.turbulence_scale_m / airspeed_mps; // 0.441 s
    let dt = 0.01;
    let lag = (tau_s / dt).round() as usize;
    let steps = 1_000_000; // 10 000 s ≈ 22 700 τ
    let samples: Vec<f64> = (0..steps)
        .map(|_| {
            turbulence.advance(dt, airspeed_mps);
            turbulence.wind().y_mps
        })
        .collect();
    let n = samples.len() as f64;
    let variance = samples.iter().map(|v| v * v).sum::<f64>() / n;
    let covariance = samples
        .iter()
        .zip(&samples[lag..])
        .map(|(a, b)| a * b)
        .sum::<f64>()
        / (n - lag as f64);
    // Standard errors for T = 10 000 s: the sample variance √(2τ/T) = 0.94 %, so the RMS
    // 0.47 %; Bartlett's formula gives the lag-τ autocorrelation √((τ/T)(1 − 3e⁻²)) =
    // 0.005. Tolerances: 4 and 5 standard errors.
    let rms = variance.sqrt();
    assert!(
        (rms / parameters.turbulence_sigma_u_mps - 1.0).abs() < 0.02,
        "rms {rms}"
    );
    let expected = (-(lag as f64 * dt) / tau_s).exp();
    let correlation = covariance / variance;
    assert!(
        (correlation - expected).abs() < 0.025,
        "autocorrelation {correlation}, expected {expected}"
    );
}

#[test]
fn lateral_turbulence_leaves_the_longitudinal_draws_unchanged() {
    let parameters = WindParameters::default();
    let streams = RandomStreams::new(21);
    let mut plain = WindModel::new(parameters, 0.0, &streams).unwrap();
    let mut three_d = WindModel::new(parameters, 0.0, &streams)
        .unwrap()
        .three_dimensional(0.0, &streams);
    let mut saw_lateral = false;
    for k in 0..1000 {
        plain.advance(0.01, 69.1);
        three_d.advance(0.01, 69.1);
        let t = f64::from(k) * 0.01;
        let (a, b) = (
            plain.components(t, 500.0).turbulence,
            three_d.components(t, 500.0).turbulence,
        );
        assert_eq!((a.x_mps, a.z_mps), (b.x_mps, b.z_mps));
        assert_eq!(a.y_mps, 0.0);
        saw_lateral |= b.y_mps != 0.0;
    }
    assert!(saw_lateral);
}

#[test]
fn mean_wind_runs_down_the_angled_deck_with_the_crosswind_across_it() {
    // Straight deck, no crosswind: the 3-DOF headwind bit for bit.
    assert_eq!(
        mean_wind_over_angled_deck(10.0, 7.7, 0.0, 0.0),
        mean_wind(10.0, 7.7)
    );
    // Wind over the deck is the air's velocity relative to the ship, which moves at
    // V·(cos δ, sin δ): it must be V_wd down the landing area (−x) plus the crosswind.
    let (v_wd, v_ship, delta, cross) = (12.0, 7.7, 9.0_f64.to_radians(), 5.0);
    let wind = mean_wind_over_angled_deck(v_wd, v_ship, delta, cross);
    let over_deck_x = wind.x_mps - v_ship * delta.cos();
    let over_deck_y = wind.y_mps - v_ship * delta.sin();
    assert!((over_deck_x + v_wd).abs() < 1e-12);
    assert!((over_deck_y - cross).abs() < 1e-12);
    assert_eq!(wind.z_mps, 0.0);
}

#[test]
fn the_wind_model_adds_the_crosswind_to_the_mean_wind() {
    let parameters = WindParameters {
        crosswind_mps: -4.0,
        turbulence: false,
        steady_wake: false,
        periodic_wake: false,
        ..WindParameters::default()
    };
    let streams = RandomStreams::new(2);
    let plain = WindModel::new(parameters, 7.7, &streams).unwrap();
    assert_eq!(plain.wind(3.0, 400.0).y_mps, -4.0);
    let angled = WindModel::new(parameters, 7.7, &streams)
        .unwrap()
        .three_dimensional(9.0_f64.to_radians(), &streams);
    let y = angled.wind(3.0, 400.0).y_mps;
    assert!((y - (7.7 * 9.0_f64.to_radians().sin() - 4.0)).abs() < 1e-12);
}

#[test]
fn a_crosswind_beyond_10_mps_is_refused_by_name() {
    for value in ["10.5", "-12.0"] {
        let text = format!("[environment.wind]\ncrosswind_mps = {value}\n");
        let error = deckland::scenario::load_scenario(&text, "wind.toml").unwrap_err();
        let message = error.to_string();
        assert!(
            message.contains("environment.wind.crosswind_mps"),
            "{message}"
        );
    }
}
