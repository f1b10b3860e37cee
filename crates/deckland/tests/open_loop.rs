//! Open-loop behaviour of the nonlinear plant: trim holds, the linear model predicts
//! small steps, and a steady uniform wind changes only the ground speed.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::{Aircraft, AircraftCommands, AircraftState, OpenLoopAircraft, Wind};
use deckland::analysis::{open_loop_step_responses, trim, InputStep, TrimPoint, TrimRequest};
use deckland::integration::rk4_step;

const DT: f64 = 1e-3;

fn level_trim(aircraft: &Aircraft) -> TrimPoint {
    trim(aircraft, &TrimRequest::default()).unwrap()
}

fn fly(system: &OpenLoopAircraft, start: AircraftState, seconds: f64) -> AircraftState {
    let mut x = start.to_array();
    for k in 0..(seconds / DT).round() as usize {
        x = rk4_step(system, k as f64 * DT, &x, DT);
    }
    AircraftState::from_array(&x)
}

#[test]
fn trimmed_aircraft_flown_open_loop_stays_at_trim() {
    let aircraft = Aircraft::default();
    let point = level_trim(&aircraft);
    let start = point.state(0.0, 100.0, &Wind::default());
    let commands = AircraftCommands {
        elevator_rad: point.elevator_rad,
        thrust_n: point.thrust_n,
    };
    let derivative = aircraft.derivative(&start, &commands, &Wind::default());
    for (name, value) in [
        ("u̇", derivative.u_mps),
        ("ẇ", derivative.w_mps),
        ("q̇", derivative.q_radps),
        ("ḣ", derivative.h_m),
        ("Ṫ", derivative.engine_thrust_n[0]),
        ("δ̇e", derivative.elevator_rad),
        ("δ̈e", derivative.elevator_rate_radps),
    ] {
        assert!(value.abs() < 1e-9, "{name} = {value}");
    }
    let system = OpenLoopAircraft {
        aircraft,
        commands,
        wind: Wind::default(),
    };
    let end = fly(&system, start, 20.0);
    let air = aircraft.state_air_data(&end, &Wind::default());
    assert!((air.airspeed_mps - 69.1).abs() < 1e-6);
    assert!((end.theta_rad - point.theta_rad).abs() < 1e-8);
    assert!((end.h_m - 100.0).abs() < 1e-6);
    assert!((end.x_m - 69.1 * 20.0).abs() < 1e-4);
}

/// Flies the nonlinear airframe and the linear model for `seconds` after an input step
/// `delta` (elevator rad, throttle fraction) and returns the worst state error relative
/// to that state's largest excursion.
fn linear_prediction_error(delta: [f64; 2], seconds: f64) -> [f64; 4] {
    let aircraft = Aircraft::default();
    let point = level_trim(&aircraft);
    let step = InputStep {
        elevator_rad: delta[0],
        throttle: delta[1],
    };
    let (_, samples) = open_loop_step_responses(&aircraft, &point, step, seconds, DT, DT).unwrap();
    let mut max_error = [0.0_f64; 4];
    let mut max_excursion = [0.0_f64; 4];
    for sample in &samples {
        for i in 0..4 {
            max_error[i] = max_error[i].max((sample.nonlinear[i] - sample.linear[i]).abs());
            max_excursion[i] = max_excursion[i].max(sample.nonlinear[i].abs());
        }
    }
    std::array::from_fn(|i| max_error[i] / max_excursion[i])
}

#[test]
fn linear_model_predicts_small_elevator_step() {
    // The pitch stiffness is low (∂q̇/∂α = −0.26 s⁻² against ∂q̇/∂δe ≈ −1.9 s⁻²), so even
    // 0.1° of elevator moves α by about 0.7°: "small" must be small here.
    let relative = linear_prediction_error([0.1f64.to_radians(), 0.0], 5.0);
    for (i, e) in relative.iter().enumerate() {
        assert!(*e < 0.08, "state {i}: relative error {e}");
    }
    // What remains is the nonlinearity, which is second order: halving the step halves
    // the relative error. An error in the Jacobian would not shrink this way.
    let half = linear_prediction_error([0.05f64.to_radians(), 0.0], 5.0);
    for i in 0..4 {
        assert!(
            half[i] < 0.6 * relative[i],
            "state {i}: {} vs {}",
            half[i],
            relative[i]
        );
    }
}

#[test]
fn linear_model_predicts_small_throttle_step() {
    // 1 % of the total maximum thrust, about 1.4 kN.
    let relative = linear_prediction_error([0.0, 0.01], 5.0);
    for (i, e) in relative.iter().enumerate() {
        assert!(*e < 0.01, "state {i}: relative error {e}");
    }
}

#[test]
fn linear_model_fails_for_a_large_step_showing_the_test_can_fail() {
    // A 1° elevator step drives α about 7° from trim: the linear prediction degrades.
    let relative = linear_prediction_error([1f64.to_radians(), 0.0], 5.0);
    assert!(relative.iter().any(|e| *e > 0.08), "{relative:?}");
}

#[test]
fn steady_headwind_changes_only_ground_speed() {
    let aircraft = Aircraft::default();
    let point = level_trim(&aircraft);
    let headwind = Wind {
        x_mps: -10.0,
        z_mps: 0.0,
        ..Default::default()
    };
    let start = point.state(0.0, 100.0, &headwind);
    let commands = AircraftCommands {
        elevator_rad: point.elevator_rad,
        thrust_n: point.thrust_n,
    };
    let system = OpenLoopAircraft {
        aircraft,
        commands,
        wind: headwind,
    };
    let end = fly(&system, start, 20.0);
    let air = aircraft.state_air_data(&end, &headwind);
    assert!(
        (air.airspeed_mps - 69.1).abs() < 1e-6,
        "airspeed {}",
        air.airspeed_mps
    );
    assert!((air.alpha_rad - point.alpha_rad).abs() < 1e-9);
    assert!((end.theta_rad - point.theta_rad).abs() < 1e-8);
    assert!((end.h_m - 100.0).abs() < 1e-6);
    let (ground_speed, climb) = end.earth_velocity_mps();
    assert!(
        (ground_speed - 59.1).abs() < 1e-6,
        "ground speed {ground_speed}"
    );
    assert!(climb.abs() < 1e-6);
    assert!((end.x_m - 59.1 * 20.0).abs() < 1e-4);
}
