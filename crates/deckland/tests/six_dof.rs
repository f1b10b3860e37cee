//! The 6-DOF F/A-18 (docs/six-dof.md): its data, its reduction to the 3-DOF model,
//! its trim and its lateral modes against an independent textbook matrix.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, LateralDerivatives, OpenLoopSixDof, SixDofAircraft,
    SixDofCommands, SixDofState, SixDofTrimError, SixDofTrimRequest,
};
use deckland::aircraft::{
    aerodynamic_coefficients, linearize, trim, Aircraft, AircraftCommands, AircraftState,
    OpenLoopAircraft, TrimRequest, Wind,
};
use deckland::integration::{rk4_step, OdeSystem};
use nalgebra::SMatrix;
use proptest::prelude::*;

/// Whether `value` agrees with `listed` (printed to three decimals, three significant
/// figures for all but C_nβ and C_nδr) to within one unit of its last printed digit.
fn agrees_to_the_printed_figures(value: f64, listed: f64) -> bool {
    (value - listed).abs() <= 1e-3
}

/// docs/six-dof.md lists the lateral derivatives at α = 7.1°. Two evaluate half a unit
/// away from the printed third figure: C_lβ = −0.10847 (listed −0.109) and
/// C_Yβ = −0.70447 (listed −0.705); every one is within one unit of it.
#[test]
fn lateral_coefficients_at_the_approach_alpha_match_the_model_list() {
    let d = LateralDerivatives::at(7.1f64.to_radians());
    let listed = [
        ("C_lβ", d.roll_beta, -0.109),
        ("C_nβ", d.yaw_beta, 0.087),
        ("C_Yβ", d.side_beta, -0.705),
        ("C_lp", d.roll_p, -0.325),
        ("C_nr", d.yaw_r, -0.449),
        ("C_lδa", d.roll_aileron, 0.132),
        ("C_nδr", d.yaw_rudder, -0.073),
    ];
    for (name, value, expected) in listed {
        assert!(
            agrees_to_the_printed_figures(value, expected),
            "{name} = {value:.5}, docs/six-dof.md lists {expected}"
        );
    }
}

fn approach_trim() -> deckland::aircraft::TrimPoint {
    trim(&Aircraft::default(), &TrimRequest::default()).expect("the approach trims")
}

/// A longitudinal wind history: a 10 m/s headwind with gusts, and a vertical gust.
fn gusty_wind(t: f64) -> Wind {
    Wind {
        x_mps: -10.0 + 3.0 * (0.7 * t).sin() + 1.5 * (2.3 * t + 0.4).sin(),
        z_mps: 1.2 * (1.1 * t).sin() - 0.6 * (3.1 * t).cos(),
        ..Default::default()
    }
}

fn relative_difference(a: f64, b: f64, scale: f64) -> f64 {
    (a - b).abs() / b.abs().max(scale)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// With v = p = r = φ = ψ = y = 0, no lateral wind and δa = δr = 0, the 6-DOF
    /// derivative is the 3-DOF derivative, and the lateral rates are zero.
    #[test]
    fn derivative_reduces_to_the_longitudinal_model(
        u in 30.0..110.0_f64, w in -8.0..25.0_f64, q in -0.5..0.5_f64,
        theta in -0.4..0.5_f64, x in -3000.0..100.0_f64, h in 0.0..500.0_f64,
        thrust_1 in 0.0..71_172.0_f64, thrust_2 in 0.0..71_172.0_f64,
        elevator in -0.43..0.17_f64, elevator_rate in -0.6..0.6_f64,
        elevator_command in -0.5..0.3_f64, thrust_command in 0.0..150_000.0_f64,
        wind_x in -25.0..10.0_f64, wind_z in -6.0..6.0_f64,
        aileron_command in -0.5..0.5_f64, rudder_command in -0.6..0.6_f64,
    ) {
        let longitudinal = Aircraft::default();
        let six = SixDofAircraft::default();
        let state = AircraftState {
            u_mps: u, w_mps: w, q_radps: q, theta_rad: theta, x_m: x, h_m: h,
            engine_thrust_n: [thrust_1, thrust_2],
            elevator_rad: elevator, elevator_rate_radps: elevator_rate,
        };
        let wind = Wind { x_mps: wind_x, z_mps: wind_z, ..Default::default() };
        let expected = longitudinal.derivative(
            &state,
            &AircraftCommands { elevator_rad: elevator_command, thrust_n: thrust_command },
            &wind,
        );
        // The lateral commands move only the lateral actuators' states (held at rest
        // at neutral here), never the airframe.
        let commands = SixDofCommands {
            elevator_rad: elevator_command,
            thrust_n: thrust_command,
            aileron_rad: aileron_command,
            rudder_rad: rudder_command,
        };
        let derivative = six.derivative(
            &SixDofState::from_longitudinal(&state), &commands, &wind);
        let got = derivative.longitudinal().to_array();
        let scales = [1.0, 1.0, 0.01, 0.01, 1.0, 1.0, 1.0, 1.0, 0.01, 0.01];
        for (i, (a, b)) in got.iter().zip(expected.to_array()).enumerate() {
            prop_assert!(relative_difference(*a, b, scales[i] * 1e-6) <= 1e-9,
                "{}: {a} vs {b}", AircraftState::NAMES[i]);
        }
        for lateral in [derivative.v_mps, derivative.p_radps, derivative.r_radps,
                        derivative.phi_rad, derivative.psi_rad, derivative.y_m,
                        derivative.aileron_rad, derivative.rudder_rad] {
            prop_assert!(lateral == 0.0, "{derivative:?}");
        }
    }
}

/// An open-loop plant whose held wind can be replaced.
trait HeldWind: Copy {
    /// The same plant and commands in `wind`.
    fn in_wind(self, wind: Wind) -> Self;
}

impl HeldWind for OpenLoopAircraft {
    fn in_wind(self, wind: Wind) -> Self {
        Self { wind, ..self }
    }
}

impl HeldWind for OpenLoopSixDof {
    fn in_wind(self, wind: Wind) -> Self {
        Self { wind, ..self }
    }
}

/// The open-loop plant `P` flown through [`gusty_wind`] instead of its held wind.
struct Gusty<P>(P);

impl<const N: usize, P: OdeSystem<N> + HeldWind> OdeSystem<N> for Gusty<P> {
    fn derivative(&self, t: f64, x: &[f64; N]) -> [f64; N] {
        self.0.in_wind(gusty_wind(t)).derivative(t, x)
    }
    fn constrain(&self, x: &mut [f64; N]) {
        self.0.constrain(x);
    }
}

/// Both models flown 20 s by RK4 (10 ms steps) from the approach trim, with a 2° nose-up
/// elevator command, more thrust and a gusty longitudinal wind, agree to 1e-9.
#[test]
fn rk4_trajectories_agree_in_a_longitudinal_wind_history() {
    let point = approach_trim();
    let start = point.state(-1500.0, 100.0, &gusty_wind(0.0));
    let longitudinal = Gusty(OpenLoopAircraft {
        aircraft: Aircraft::default(),
        commands: AircraftCommands {
            elevator_rad: point.elevator_rad - 2f64.to_radians(),
            thrust_n: point.thrust_n * 1.3,
        },
        wind: Wind::default(),
    });
    let six = Gusty(OpenLoopSixDof {
        aircraft: SixDofAircraft::default(),
        commands: SixDofCommands {
            elevator_rad: longitudinal.0.commands.elevator_rad,
            thrust_n: longitudinal.0.commands.thrust_n,
            ..SixDofCommands::default()
        },
        wind: Wind::default(),
    });
    let dt = 0.01;
    let mut x3 = start.to_array();
    let mut x6 = SixDofState::from_longitudinal(&start).to_array();
    let scales = [70.0, 10.0, 0.1, 0.1, 1500.0, 100.0, 1e4, 1e4, 0.1, 0.1];
    let mut worst: f64 = 0.0;
    for k in 0..2000 {
        let t = k as f64 * dt;
        x3 = rk4_step(&longitudinal, t, &x3, dt);
        x6 = rk4_step(&six, t, &x6, dt);
        let reduced = SixDofState::from_array(&x6).longitudinal().to_array();
        for i in 0..AircraftState::DIMENSION {
            worst = worst.max(relative_difference(reduced[i], x3[i], scales[i]));
        }
    }
    let end = AircraftState::from_array(&x3);
    // The run goes somewhere: with more thrust and nose-up elevator it climbs 100 m.
    assert!(end.h_m > 150.0 && end.u_mps < 60.0, "{end:?}");
    assert!(worst <= 1e-9, "largest relative difference {worst:e}");
    let lateral = SixDofState::from_array(&x6);
    assert_eq!(
        [
            lateral.v_mps,
            lateral.p_radps,
            lateral.r_radps,
            lateral.phi_rad,
            lateral.psi_rad,
            lateral.y_m
        ],
        [0.0; 6]
    );
}

/// At β = 0 in still air the 6-DOF trim is the 3-DOF trim, wings level.
#[test]
fn symmetric_trim_is_the_longitudinal_trim() {
    let expected = approach_trim();
    let point = trim_six_dof(&SixDofAircraft::default(), &SixDofTrimRequest::default()).unwrap();
    assert!((point.alpha_rad - expected.alpha_rad).abs() < 1e-9);
    assert!((point.elevator_rad - expected.elevator_rad).abs() < 1e-9);
    assert!((point.thrust_n - expected.thrust_n).abs() < 1e-5);
    for lateral in [
        point.phi_rad,
        point.psi_rad,
        point.aileron_rad,
        point.rudder_rad,
    ] {
        assert!(lateral.abs() < 1e-9, "{point:?}");
    }
}

/// The trimmed state is an equilibrium: every rate of the full nonlinear model is zero
/// but the position's, and the ground track is along the final bearing (ẏ = 0).
fn assert_steady_on_the_bearing(aircraft: &SixDofAircraft, request: &SixDofTrimRequest) {
    let point = trim_six_dof(aircraft, request).unwrap();
    let state = point.state(-1000.0, 0.0, 80.0);
    let commands = SixDofCommands {
        elevator_rad: point.elevator_rad,
        thrust_n: point.thrust_n,
        aileron_rad: point.aileron_rad,
        rudder_rad: point.rudder_rad,
    };
    let rate = aircraft.derivative(&state, &commands, &request.wind);
    let array = rate.to_array();
    for (i, value) in array.iter().enumerate() {
        if ["x_m", "h_m"].contains(&SixDofState::NAMES[i]) {
            continue;
        }
        assert!(
            value.abs() < 1e-8,
            "{} rate {value:e}",
            SixDofState::NAMES[i]
        );
    }
    // Still air gives the requested air path; ḣ = V sin γ + ... in still air.
    let ground_speed_x = rate.x_m;
    assert!(ground_speed_x > 0.0);
}

/// β = 5° with the relative wind from the right: right rudder (trailing edge left, to
/// hold the nose against C_nβ > 0), right aileron (against C_lβ < 0) and a bank into the
/// wind (φ > 0) to balance the side force; and the state is an equilibrium.
#[test]
fn steady_sideslip_trim_needs_rudder_aileron_and_bank_into_the_wind() {
    let aircraft = SixDofAircraft::default();
    let request = SixDofTrimRequest {
        sideslip_rad: 5f64.to_radians(),
        ..SixDofTrimRequest::default()
    };
    let point = trim_six_dof(&aircraft, &request).unwrap();
    assert!(point.rudder_rad > 0.0 && point.aileron_rad > 0.0 && point.phi_rad > 0.0);
    // Mirror image: the opposite sideslip gives the opposite controls.
    let mirror = trim_six_dof(
        &aircraft,
        &SixDofTrimRequest {
            sideslip_rad: -5f64.to_radians(),
            ..request
        },
    )
    .unwrap();
    assert!((mirror.rudder_rad + point.rudder_rad).abs() < 1e-9);
    assert!((mirror.aileron_rad + point.aileron_rad).abs() < 1e-9);
    assert!((mirror.phi_rad + point.phi_rad).abs() < 1e-9);
    assert_steady_on_the_bearing(&aircraft, &request);
}

/// A 5 m/s crosswind from the left (W_y = +5 m/s) on a 3° glide path: β = 0, wings
/// level, heading ψ = −asin(W_y/(V cos γ)) into the wind, and the track on the bearing.
#[test]
fn crab_in_a_steady_crosswind_heads_into_the_wind() {
    let aircraft = SixDofAircraft::default();
    let gamma = -3f64.to_radians();
    let request = SixDofTrimRequest {
        longitudinal: TrimRequest {
            speed_mps: 69.1,
            flight_path_angle_rad: gamma,
        },
        sideslip_rad: 0.0,
        wind: Wind {
            x_mps: -12.0,
            y_mps: 5.0,
            z_mps: 0.0,
        },
    };
    let point = trim_six_dof(&aircraft, &request).unwrap();
    let expected = -(5.0 / (69.1 * gamma.cos())).asin();
    assert!((point.psi_rad - expected).abs() < 1e-9, "{point:?}");
    assert!(point.phi_rad.abs() < 1e-9 && point.rudder_rad.abs() < 1e-9);
    assert_steady_on_the_bearing(&aircraft, &request);
}

#[test]
fn unreachable_sideslip_names_the_surface_and_the_excess() {
    let aircraft = SixDofAircraft::default();
    let error = trim_six_dof(
        &aircraft,
        &SixDofTrimRequest {
            sideslip_rad: 25f64.to_radians(),
            ..SixDofTrimRequest::default()
        },
    )
    .unwrap_err();
    let SixDofTrimError::SurfaceLimit {
        surface,
        required_deg,
        limit_deg,
        exceeded_by_deg,
    } = error.clone()
    else {
        panic!("expected a surface limit, got {error}");
    };
    assert_eq!(surface, "rudder");
    assert!((limit_deg - 30.0).abs() < 1e-9);
    assert!((exceeded_by_deg - (required_deg - 30.0)).abs() < 1e-9 && exceeded_by_deg > 0.0);
    let message = error.to_string();
    assert!(
        message.contains("rudder") && message.contains("by"),
        "{message}"
    );

    let error = trim_six_dof(
        &aircraft,
        &SixDofTrimRequest {
            sideslip_rad: 0.9,
            ..SixDofTrimRequest::default()
        },
    )
    .unwrap_err();
    assert!(error.to_string().contains("sideslip_rad"), "{error}");
    let error = trim_six_dof(
        &aircraft,
        &SixDofTrimRequest {
            wind: Wind {
                y_mps: 80.0,
                ..Wind::default()
            },
            ..SixDofTrimRequest::default()
        },
    )
    .unwrap_err();
    assert!(error.to_string().contains("wind.y_mps"), "{error}");
}

/// The lateral matrices of the textbook small-perturbation form, built by hand from the
/// dimensional stability derivatives: body axes about a wings-level trim with α₀, θ₀
/// and primed moment derivatives for I_xz (Stevens & Lewis, *Aircraft Control and
/// Simulation*, 2nd ed., §2.6 lateral-directional small-perturbation equations; the same
/// form as McRuer, Ashkenas & Graham, *Aircraft Dynamics and Automatic Control*, Ch. 4):
///
/// ```text
/// β̇ = (Y_β/V) β + sin α₀ p − cos α₀ r + (g cos θ₀/V) φ + (Y_δ/V) δ
/// ṗ = L'_β β + L'_p p + L'_r r + L'_δ δ
/// ṙ = N'_β β + N'_p p + N'_r r + N'_δ δ
/// φ̇ = p + tan θ₀ r
/// L' = (I_z L + I_xz N)/Γ,  N' = (I_xz L + I_x N)/Γ,  Γ = I_x I_z − I_xz²
/// ```
///
/// with Y_x = q̄S C_Yx/m, L_x = q̄S b C_lx, N_x = q̄S (b C_nx − d c̄ C_Yx) (the CG d·c̄
/// ahead of the data's reference point), and the rate derivatives × b/(2V).
fn textbook_lateral(
    aircraft: &SixDofAircraft,
    speed: f64,
    alpha: f64,
    theta: f64,
) -> (SMatrix<f64, 4, 4>, SMatrix<f64, 4, 2>) {
    let p = aircraft.longitudinal().parameters();
    let lateral = aircraft.lateral();
    let cg = aircraft
        .longitudinal()
        .configuration()
        .cg_ahead_of_reference_chords
        * p.mean_chord_m;
    let d = LateralDerivatives::at(alpha);
    let qs = 0.5 * p.air_density_kg_m3 * speed * speed * p.wing_area_m2;
    let b = lateral.span_m;
    let rate = b / (2.0 * speed);
    let side = |c: f64| qs * c / p.mass_kg;
    let roll = |c: f64| qs * b * c;
    let yaw = |c: f64, c_side: f64| qs * (b * c - cg * c_side);
    let (ix, iz, ixz) = (
        lateral.roll_inertia_kg_m2,
        lateral.yaw_inertia_kg_m2,
        lateral.product_of_inertia_xz_kg_m2,
    );
    let gamma = ix * iz - ixz * ixz;
    let primed = |l: f64, n: f64| ((iz * l + ixz * n) / gamma, (ixz * l + ix * n) / gamma);
    let (l_beta, n_beta) = primed(roll(d.roll_beta), yaw(d.yaw_beta, d.side_beta));
    let (l_p, n_p) = primed(roll(d.roll_p) * rate, yaw(d.yaw_p, 0.0) * rate);
    let (l_r, n_r) = primed(roll(d.roll_r) * rate, yaw(d.yaw_r, 0.0) * rate);
    let (l_a, n_a) = primed(roll(d.roll_aileron), yaw(d.yaw_aileron, d.side_aileron));
    let (l_rudder, n_rudder) = primed(roll(d.roll_rudder), yaw(d.yaw_rudder, d.side_rudder));
    let g = p.gravity_mps2;
    #[rustfmt::skip]
    let a = SMatrix::<f64, 4, 4>::new(
        side(d.side_beta) / speed, alpha.sin(), -alpha.cos(), g * theta.cos() / speed,
        l_beta, l_p, l_r, 0.0,
        n_beta, n_p, n_r, 0.0,
        0.0, 1.0, theta.tan(), 0.0,
    );
    #[rustfmt::skip]
    let input = SMatrix::<f64, 4, 2>::new(
        side(d.side_aileron) / speed, side(d.side_rudder) / speed,
        l_a, l_rudder,
        n_a, n_rudder,
        0.0, 0.0,
    );
    (a, input)
}

#[test]
fn lateral_modes_agree_with_the_textbook_matrix() {
    let aircraft = SixDofAircraft::default();
    for gamma_deg in [0.0, -3.5] {
        let request = SixDofTrimRequest {
            longitudinal: TrimRequest {
                speed_mps: 69.1,
                flight_path_angle_rad: f64::to_radians(gamma_deg),
            },
            ..SixDofTrimRequest::default()
        };
        let point = trim_six_dof(&aircraft, &request).unwrap();
        let model = linearize_six_dof(&aircraft, &point);
        let (a, b) = textbook_lateral(&aircraft, point.speed_mps, point.alpha_rad, point.theta_rad);
        let a_error = (model.lateral_a() - a).amax();
        assert!(
            a_error < 1e-7,
            "A differs by {a_error:e}:\n{}\n{a}",
            model.lateral_a()
        );
        assert!(
            (model.lateral_b() - b).amax() < 1e-6,
            "{}\n{b}",
            model.lateral_b()
        );
        let got = model.lateral_modes().expect("Dutch roll, roll and spiral");
        let want = deckland::aircraft::six_dof::LateralModes::of(&a).unwrap();
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-6 * y.abs();
        for (figure, linearised, textbook) in [
            (
                "Dutch roll frequency",
                got.dutch_roll.natural_frequency_radps,
                want.dutch_roll.natural_frequency_radps,
            ),
            (
                "Dutch roll damping",
                got.dutch_roll.damping_ratio,
                want.dutch_roll.damping_ratio,
            ),
            (
                "roll subsidence",
                got.roll_subsidence.time_constant_s,
                want.roll_subsidence.time_constant_s,
            ),
            (
                "spiral",
                got.spiral.time_constant_s,
                want.spiral.time_constant_s,
            ),
        ] {
            assert!(
                close(linearised, textbook),
                "{figure}: {linearised} vs {textbook}"
            );
        }
        // Plausible approach figures for a fighter: a lightly damped Dutch roll near
        // 1 rad/s and a roll subsidence near 1 s.
        assert!((0.5..2.0).contains(&got.dutch_roll.natural_frequency_radps));
        assert!((0.3..2.0).contains(&got.roll_subsidence.time_constant_s));
    }
}

/// The longitudinal block of the 6-DOF linearisation is the 3-DOF one.
#[test]
fn longitudinal_block_is_the_three_dof_linearisation() {
    let point = trim_six_dof(&SixDofAircraft::default(), &SixDofTrimRequest::default()).unwrap();
    let model = linearize_six_dof(&SixDofAircraft::default(), &point);
    let expected = linearize(&Aircraft::default(), &approach_trim());
    assert!((model.longitudinal_a() - expected.a).amax() < 1e-7);
    assert!((model.longitudinal_b() - expected.b).amax() < 1e-6 * expected.b.amax());
    // And the lateral and longitudinal sets are decoupled at a wings-level trim.
    let coupling = model.a.view((2, 0), (1, 2)).amax();
    assert!(coupling < 1e-9, "{coupling:e}");
}

/// Drag's cos β factor: at β = 10° the drag the model applies is C_D·cos β, computed
/// here from the longitudinal coefficients by hand (along −x_s: the body-x force of
/// drag at β is −q̄S·C_D cos β·cos α).
#[test]
fn sideslip_factors_scale_lift_and_drag() {
    let aircraft = SixDofAircraft::default();
    let p = aircraft.longitudinal().parameters();
    let (speed, alpha, beta) = (69.1, 0.12_f64, 10f64.to_radians());
    let velocity = [
        speed * alpha.cos() * beta.cos(),
        speed * beta.sin(),
        speed * alpha.sin() * beta.cos(),
    ];
    let inputs = deckland::aircraft::six_dof::SixDofInputs::default();
    let rates = aircraft.body_rates(velocity, [0.0; 3], [0.0; 3], &inputs, &Wind::default());
    let c = aerodynamic_coefficients(alpha, 0.0, 0.0, aircraft.longitudinal().configuration());
    let qs = 0.5 * p.air_density_kg_m3 * speed * speed * p.wing_area_m2;
    let lift = qs * c.lift * (2.0 * beta / 3.0).cos();
    let drag = qs * c.drag * beta.cos();
    let u_dot = (lift * alpha.sin() - drag * alpha.cos()) / p.mass_kg;
    let w_dot = (-lift * alpha.cos() - drag * alpha.sin()) / p.mass_kg + p.gravity_mps2;
    assert!(
        (rates.velocity[0] - u_dot).abs() < 1e-10,
        "{} vs {u_dot}",
        rates.velocity[0]
    );
    assert!((rates.velocity[2] - w_dot).abs() < 1e-10);
}
