//! Tests of the aircraft plant (kept apart so that dynamics.rs stays short).
use super::*;

/// The wind-axis equations of docs/model.md §2.4 written out independently, still air:
/// V̇ = (T cos α − D)/m − g sin γ, α̇ = q − (T sin α + L)/(mV) + g cos γ / V.
fn wind_axis_rates(
    aircraft: &Aircraft,
    v: f64,
    alpha: f64,
    theta: f64,
    q: f64,
    de: f64,
    t: f64,
) -> (f64, f64, f64) {
    let p = aircraft.parameters();
    let q_hat = q * p.mean_chord_m / (2.0 * v);
    let c = aerodynamic_coefficients(alpha, de, q_hat, aircraft.configuration());
    let qbar_s = 0.5 * p.air_density_kg_m3 * v * v * p.wing_area_m2;
    let (lift, drag) = (qbar_s * c.lift, qbar_s * c.drag);
    let gamma = theta - alpha;
    let m = p.mass_kg;
    let g = p.gravity_mps2;
    let v_dot = (t * alpha.cos() - drag) / m - g * gamma.sin();
    let alpha_dot = q - (t * alpha.sin() + lift) / (m * v) + g * gamma.cos() / v;
    let q_dot = qbar_s * p.mean_chord_m * c.moment / p.pitch_inertia_kg_m2;
    (v_dot, alpha_dot, q_dot)
}

#[test]
fn body_axis_equations_agree_with_wind_axis_form_in_still_air() {
    let aircraft = Aircraft::default();
    let cases = [
        (69.1, 0.124, 0.124, 0.0, -0.14, 26_000.0),
        (75.0, 0.05, -0.02, 0.1, 0.02, 60_000.0),
        (55.0, 0.30, 0.20, -0.2, -0.3, 10_000.0),
    ];
    for (v, alpha, theta, q, de, t) in cases {
        let (u, w) = (v * f64::cos(alpha), v * f64::sin(alpha));
        let inputs = AirframeInputs {
            elevator_rad: de,
            thrust_n: t,
        };
        let (u_dot, w_dot, q_dot) =
            aircraft.airframe_accelerations(u, w, q, theta, &inputs, &Wind::default());
        let v_dot = (u * u_dot + w * w_dot) / v;
        let alpha_dot = (u * w_dot - w * u_dot) / (v * v);
        let (v_ref, a_ref, q_ref) = wind_axis_rates(&aircraft, v, alpha, theta, q, de, t);
        assert!((v_dot - v_ref).abs() < 1e-10, "V̇ {v_dot} vs {v_ref}");
        assert!(
            (alpha_dot - a_ref).abs() < 1e-12,
            "α̇ {alpha_dot} vs {a_ref}"
        );
        assert!((q_dot - q_ref).abs() < 1e-12);
    }
}

/// Direct lift control's increment is lift: in the wind-axis equations (Stevens &
/// Lewis Eq. 2.5-32 family) it leaves V̇ alone and lowers α̇ by q̄S·ΔC_L/(m·V_T), which
/// is computed here by hand, not by the model.
#[test]
fn a_lift_increment_turns_the_flight_path_and_leaves_the_airspeed() {
    let aircraft = Aircraft::default();
    let p = *aircraft.parameters();
    let (v, alpha, theta) = (69.1_f64, 0.124_f64, 0.063_f64);
    let state = AircraftState {
        u_mps: v * alpha.cos(),
        w_mps: v * alpha.sin(),
        theta_rad: theta,
        engine_thrust_n: [13_000.0, 13_000.0],
        elevator_rad: -0.14,
        ..Default::default()
    };
    let commands = AircraftCommands {
        elevator_rad: -0.14,
        thrust_n: 26_000.0,
    };
    let wind = Wind::default();
    let (sin_t, cos_t) = theta.sin_cos();
    let air = aircraft.air_data_trig(state.u_mps, state.w_mps, sin_t, cos_t, &wind);
    let rates = |increment: f64| {
        let d =
            aircraft.derivative_with_direct_lift(&state, &commands, &air, sin_t, cos_t, increment);
        let (u, w) = (state.u_mps, state.w_mps);
        // The rotation terms q·w and q·u vanish: q = 0.
        (
            (u * d.u_mps + w * d.w_mps) / v,
            (u * d.w_mps - w * d.u_mps) / (v * v),
        )
    };
    let (v_dot_0, alpha_dot_0) = rates(0.0);
    let (v_dot_1, alpha_dot_1) = rates(0.1);
    let qbar_s = 0.5 * p.air_density_kg_m3 * v * v * p.wing_area_m2;
    let expected = -qbar_s * 0.1 / (p.mass_kg * v);
    assert!(
        (v_dot_1 - v_dot_0).abs() < 1e-12,
        "V̇ moved by {}",
        v_dot_1 - v_dot_0
    );
    assert!(
        ((alpha_dot_1 - alpha_dot_0) - expected).abs() < 1e-12,
        "α̇ moved by {} against {expected} by hand",
        alpha_dot_1 - alpha_dot_0
    );
    // Without an increment the plant is the one every other caller flies.
    let plain = aircraft.derivative(&state, &commands, &wind);
    let zero = aircraft.derivative_with_direct_lift(&state, &commands, &air, sin_t, cos_t, 0.0);
    assert_eq!(plain, zero);
}

#[test]
fn steady_uniform_wind_acts_only_through_air_relative_velocity() {
    let aircraft = Aircraft::default();
    let inputs = AirframeInputs {
        elevator_rad: -0.1,
        thrust_n: 30_000.0,
    };
    let (theta, alpha, v) = (0.1_f64, 0.12_f64, 69.0);
    let still = aircraft.airframe_accelerations(
        v * alpha.cos(),
        v * alpha.sin(),
        0.0,
        theta,
        &inputs,
        &Wind::default(),
    );
    // The same air-relative velocity, carried by a 12 m/s headwind and 3 m/s updraft.
    let wind = Wind {
        x_mps: -12.0,
        z_mps: -3.0,
        ..Default::default()
    };
    let wind_xb = wind.x_mps * theta.cos() - wind.z_mps * theta.sin();
    let wind_zb = wind.x_mps * theta.sin() + wind.z_mps * theta.cos();
    let windy = aircraft.airframe_accelerations(
        v * alpha.cos() + wind_xb,
        v * alpha.sin() + wind_zb,
        0.0,
        theta,
        &inputs,
        &wind,
    );
    assert!((still.0 - windy.0).abs() < 1e-12);
    assert!((still.1 - windy.1).abs() < 1e-12);
    assert!((still.2 - windy.2).abs() < 1e-12);
}

#[test]
fn engines_lag_towards_half_the_total_command_each() {
    let aircraft = Aircraft::default();
    let state = AircraftState {
        u_mps: 69.0,
        engine_thrust_n: [10_000.0, 10_000.0],
        ..Default::default()
    };
    let commands = AircraftCommands {
        elevator_rad: 0.0,
        thrust_n: 50_000.0,
    };
    let d = aircraft.derivative(&state, &commands, &Wind::default());
    assert!((d.engine_thrust_n[0] - (25_000.0 - 10_000.0) / 0.625).abs() < 1e-9);
    let over = AircraftCommands {
        thrust_n: 1e9,
        ..commands
    };
    let d = aircraft.derivative(&state, &over, &Wind::default());
    assert!((d.engine_thrust_n[1] - (71_172.0 - 10_000.0) / 0.625).abs() < 1e-9);
}
