//! Tests across the environment: reference variances, wake formulas, determinism and
//! parameter validation.

use super::*;
use crate::random::RandomStreams;

#[test]
fn lyapunov_variances_match_model_md() {
    // docs/model.md §3.1: 43.62 m² (heave) and 0.4858 (pitch) for unit-intensity noise;
    // numpy's solve of the vectorised equation gives 43.6226 and 0.485764.
    let heave = heave_unit_intensity_variance();
    let pitch = pitch_unit_intensity_variance();
    assert!((heave - 43.6226).abs() < 1e-3, "heave {heave}");
    assert!((pitch - 0.485_764).abs() < 1e-5, "pitch {pitch}");
}

#[test]
fn noise_intensity_gives_the_configured_rms() {
    let model = ShipMotion::new(ShipMotionParameters::default()).expect("valid");
    let heave_variance = model.heave_noise_intensity() * 43.6226;
    let pitch_variance = model.pitch_noise_intensity() * 0.485_764;
    assert!((heave_variance.sqrt() - 2.0).abs() < 1e-4);
    assert!((pitch_variance.sqrt() - 1.5_f64.to_radians()).abs() < 1e-7);
}

#[test]
fn state_array_round_trips() {
    let array = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0];
    assert_eq!(ShipMotionState::from_array(&array).to_array(), array);
}

#[test]
fn filter_rates_are_derivatives_of_the_outputs() {
    // With the noise held at zero, the derivative of heave must equal the heave rate
    // output, and likewise for pitch (controllable canonical form, no feed-through).
    let model = ShipMotion::new(ShipMotionParameters::default()).expect("valid");
    let state = ShipMotionState::from_array(&[0.3, -0.2, 0.1, 0.05, -0.4, 0.2, 0.7, -0.1]);
    let derivative = model.derivative(&state, ShipNoise::default());
    let outputs = model.outputs(&state);
    assert!(
        (HEAVE_FILTER_GAIN * derivative.heave_filter[0] - outputs.heave_rate_mps).abs() < 1e-15
    );
    assert!(
        (PITCH_FILTER_GAIN * derivative.pitch_filter[2] - outputs.pitch_rate_radps).abs() < 1e-15
    );
}

/// Asserts the wake's (x, z) components are `expected` (m/s) within 10⁻¹², naming the
/// point `at` on failure.
fn assert_wake_is(wake: Wind, expected: (f64, f64), at: &str) {
    assert!(
        (wake.x_mps - expected.0).abs() < 1e-12,
        "wake x at {at}: {}",
        wake.x_mps
    );
    assert!(
        (wake.z_mps - expected.1).abs() < 1e-12,
        "wake z at {at}: {}",
        wake.z_mps
    );
}

#[test]
fn steady_wake_matches_eq_21_22_by_hand() {
    // u2 = 0.002·X (0 < X < 914), w2 = −1 + 0.0013·X (X < 914), else 0.
    let cases = [
        (400.0, 0.002 * 400.0, -1.0 + 0.0013 * 400.0), // 0.8, −0.48
        (81.0, 0.002 * 81.0, -1.0 + 0.0013 * 81.0),    // 0.162, −0.8947
        (0.0, 0.0, -1.0),
        (-50.0, 0.0, -1.0 - 0.0013 * 50.0),
        (913.9, 0.002 * 913.9, -1.0 + 0.0013 * 913.9),
        (914.0, 0.0, 0.0),
        (1000.0, 0.0, 0.0),
    ];
    for (x, u2, w2) in cases {
        assert_wake_is(steady_wake(x), (u2, w2), &format!("X = {x}"));
    }
    assert!((steady_wake(400.0).x_mps - 0.8).abs() < 1e-12);
}

#[test]
fn periodic_wake_matches_eq_23_25_by_hand() {
    // θ_s = 0.05 rad, V_wd = 10 m/s, ω_p = 1.25 rad/s; values cross-checked in Python:
    // (t, X) = (0, 400): C = −0.7201824913, u3 = −0.8125098866, w3 = −2.0525201001;
    // (3.7, 81): u3 = −0.9402385098, w3 = −2.1637502480; (10, 1000): u3 = 1.1135246785,
    // w3 = 3.2668530161; (1, 0): u3 = −1.0896894453, w3 = −2.4444384855.
    let parameters = WindParameters::default();
    let cases = [
        (0.0, 400.0, -0.812_509_886_6, -2.052_520_100_1),
        (3.7, 81.0, -0.940_238_509_8, -2.163_750_248_0),
        (10.0, 1000.0, 1.113_524_678_5, 3.266_853_016_1),
        (1.0, 0.0, -1.089_689_445_3, -2.444_438_485_5),
    ];
    for (t, x, u3_python, w3_python) in cases {
        let c = (1.25 * (2.28 * t + x / (0.85 * 10.0)) + 0.1_f64).cos();
        let u3 = 0.05 * 10.0 * (2.22 + 0.000_091 * x) * c;
        let w3 = 0.05 * 10.0 * (4.98 + 0.0018 * x) * c;
        assert!((u3 - u3_python).abs() < 1e-9 && (w3 - w3_python).abs() < 1e-9);
        assert_wake_is(
            periodic_wake(t, x, &parameters),
            (u3, w3),
            &format!("t = {t}, X = {x}"),
        );
    }
}

#[test]
fn mean_wind_is_a_headwind_of_wind_over_deck_less_ship_speed() {
    assert_eq!(
        mean_wind(10.0, 0.0),
        Wind {
            x_mps: -10.0,
            z_mps: 0.0,
            ..Default::default()
        }
    );
    assert_eq!(
        mean_wind(15.0, 10.0),
        Wind {
            x_mps: -5.0,
            z_mps: 0.0,
            ..Default::default()
        }
    );
}

#[test]
fn wind_model_sums_switched_components() {
    let streams = RandomStreams::new(2);
    let parameters = WindParameters {
        turbulence: false,
        ..WindParameters::default()
    };
    let wind = WindModel::new(parameters, 0.0, &streams).expect("valid");
    let total = wind.wind(0.0, 400.0);
    // −10 (mean) + 0.8 (u2) − 0.8125098866 (u3); −0.48 (w2) − 2.0525201001 (w3).
    assert!((total.x_mps - (-10.0 + 0.8 - 0.812_509_886_6)).abs() < 1e-9);
    assert!((total.z_mps - (-0.48 - 2.052_520_100_1)).abs() < 1e-9);

    let calm = WindParameters {
        mean_wind: false,
        turbulence: false,
        steady_wake: false,
        periodic_wake: false,
        ..WindParameters::default()
    };
    let still = WindModel::new(calm, 0.0, &streams).expect("valid");
    assert_eq!(still.wind(5.0, 400.0), Wind::default());
}

#[test]
fn turbulence_is_reproducible_for_a_seed() {
    let run = |seed: u64| {
        let mut wind = WindModel::new(WindParameters::default(), 0.0, &RandomStreams::new(seed))
            .expect("valid");
        (0..200)
            .map(|_| {
                wind.advance(0.01, 69.1);
                wind.components(0.0, 400.0).turbulence
            })
            .collect::<Vec<_>>()
    };
    assert_eq!(run(1), run(1));
    assert_ne!(run(1), run(2));
}

#[test]
fn bad_parameters_are_rejected_by_the_constructors_too() {
    let ship = ShipMotionParameters {
        heave_rms_m: -2.0,
        ..ShipMotionParameters::default()
    };
    assert!(ShipMotion::new(ship).is_err());
    let wind = WindParameters {
        turbulence_scale_m: 0.0,
        ..WindParameters::default()
    };
    assert!(WindModel::new(wind, 0.0, &RandomStreams::new(1)).is_err());
}
