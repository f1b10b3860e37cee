//! Validation of trim, linearisation and modes against the paper (Table 3, Eq. 14) and
//! the values docs/model.md §2.3 records for this model, with eigenvalues cross-checked by an
//! independent computation (characteristic polynomial + Durand–Kerner root finding).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::aircraft::{AerodynamicConfiguration, Aircraft};
use deckland::analysis::{identify_modes, linearize, trim, ModeKind, TrimError, TrimRequest};
use nalgebra::{Complex, SMatrix};

fn level(speed: f64) -> TrimRequest {
    TrimRequest {
        speed_mps: speed,
        flight_path_angle_rad: 0.0,
    }
}

/// Paper Table 3: V* = 69.1 m/s, α* = θ* = 7.1°, γ* = 0.
#[test]
fn default_trim_reproduces_paper_table_3() {
    let point = trim(&Aircraft::default(), &level(69.1)).unwrap();
    assert!(
        (point.alpha_rad.to_degrees() - 7.1).abs() < 0.01,
        "α {}",
        point.alpha_rad.to_degrees()
    );
    assert!((point.theta_rad.to_degrees() - 7.1).abs() < 0.01);
    assert!(point.residuals.max_abs() < 1e-9, "{:?}", point.residuals);
    // docs/model.md §2.3: δe ≈ −8.2°, T ≈ 26 kN.
    assert!(
        (point.elevator_rad.to_degrees() + 8.2).abs() < 0.1,
        "δe {}",
        point.elevator_rad.to_degrees()
    );
    assert!(
        (point.thrust_n - 26_000.0).abs() < 1_000.0,
        "T {}",
        point.thrust_n
    );
}

/// docs/model.md §2.3: the clean data trims at α ≈ 16° at 69.1 m/s.
#[test]
fn clean_configuration_trims_near_16_degrees() {
    let aircraft = Aircraft::with_configuration(AerodynamicConfiguration::CLEAN);
    let point = trim(&aircraft, &level(69.1)).unwrap();
    assert!(
        (point.alpha_rad.to_degrees() - 16.0).abs() < 0.5,
        "α {}",
        point.alpha_rad.to_degrees()
    );
}

/// Independent check of the trim: recompute lift and weight balance by hand.
/// At trim with γ = 0: L + T sin α = m g and T cos α = D.
#[test]
fn trim_balances_forces_by_hand() {
    let aircraft = Aircraft::default();
    let point = trim(&aircraft, &level(69.1)).unwrap();
    let c = deckland::aircraft::aerodynamic_coefficients(
        point.alpha_rad,
        point.elevator_rad,
        0.0,
        aircraft.configuration(),
    );
    let qs = 0.5 * 1.33 * 69.1 * 69.1 * 37.16;
    let (lift, drag) = (qs * c.lift, qs * c.drag);
    assert!((lift + point.thrust_n * point.alpha_rad.sin() - 15_000.0 * 9.75).abs() < 1e-4);
    assert!((point.thrust_n * point.alpha_rad.cos() - drag).abs() < 1e-4);
    assert!(c.moment.abs() < 1e-12);
}

#[test]
fn glide_slope_trim_has_theta_equal_alpha_plus_gamma() {
    let gamma = -3.5f64.to_radians();
    let point = trim(
        &Aircraft::default(),
        &TrimRequest {
            speed_mps: 69.1,
            flight_path_angle_rad: gamma,
        },
    )
    .unwrap();
    assert!((point.theta_rad - point.alpha_rad - gamma).abs() < 1e-15);
    // Descending needs less thrust than level flight, but still positive (docs/model.md §2.3).
    let level_thrust = trim(&Aircraft::default(), &level(69.1)).unwrap().thrust_n;
    assert!(point.thrust_n > 0.0 && point.thrust_n < level_thrust);
}

#[test]
fn unreachable_trims_name_the_limit() {
    let aircraft = Aircraft::default();
    // Far too slow: no lift solution in the polynomials' range.
    let slow = trim(&aircraft, &level(35.0)).unwrap_err();
    assert!(
        matches!(
            slow,
            TrimError::AlphaOutOfRange { .. } | TrimError::NoConvergence { .. }
        ),
        "{slow}"
    );
    // Steep dive: thrust would have to be negative.
    let dive = trim(
        &aircraft,
        &TrimRequest {
            speed_mps: 69.1,
            flight_path_angle_rad: -20f64.to_radians(),
        },
    )
    .unwrap_err();
    match dive {
        TrimError::ThrustLimit {
            limit_name,
            required_n,
            ..
        } => {
            assert_eq!(limit_name, "lower");
            assert!(required_n < 0.0);
        }
        other => panic!("expected a thrust limit, got {other}"),
    }
    // Fast steep climb with gear and flaps down: drag ≥ q̄·S·0.164 ≈ 91 kN plus
    // m·g·sin 25° ≈ 62 kN exceeds 2·71172 N.
    let climb = trim(
        &aircraft,
        &TrimRequest {
            speed_mps: 150.0,
            flight_path_angle_rad: 25f64.to_radians(),
        },
    )
    .unwrap_err();
    assert!(
        matches!(
            climb,
            TrimError::ThrustLimit {
                limit_name: "upper",
                ..
            }
        ),
        "{climb}"
    );
    assert!(climb.to_string().contains("thrust"));
    // Invalid requests name the field.
    let nan = trim(&aircraft, &level(f64::NAN)).unwrap_err();
    assert!(nan.to_string().contains("speed_mps"), "{nan}");
}

#[test]
fn elevator_limit_is_reported_with_its_excess() {
    // A nose-down moment increment of −0.35 needs about 0.35/0.9 rad ≈ 22° more
    // trailing-edge-up elevator than the −8.2° of the default trim: beyond −25°.
    let mut config = AerodynamicConfiguration::LANDING;
    config.moment_coefficient_increment = -0.35;
    let aircraft = Aircraft::with_configuration(config);
    let error = trim(&aircraft, &level(69.1)).unwrap_err();
    match error {
        TrimError::ElevatorLimit {
            limit_name,
            exceeded_by_deg,
            required_deg,
            ..
        } => {
            assert_eq!(limit_name, "lower");
            assert!((required_deg + 25.0 + exceeded_by_deg).abs() < 1e-9);
        }
        other => panic!("expected an elevator limit, got {other}"),
    }
}

/// Eigenvalues via the characteristic polynomial (Faddeev–LeVerrier) and Durand–Kerner
/// iteration: a computation independent of nalgebra's Schur decomposition.
fn eigenvalues_by_polynomial(a: &SMatrix<f64, 4, 4>) -> Vec<Complex<f64>> {
    let n = 4;
    let mut coefficients = vec![1.0];
    let mut m = SMatrix::<f64, 4, 4>::zeros();
    let identity = SMatrix::<f64, 4, 4>::identity();
    for k in 1..=n {
        m = a * m + identity * coefficients[k - 1];
        let c = -(a * m).trace() / k as f64;
        coefficients.push(c);
    }
    let poly = |z: Complex<f64>| {
        coefficients
            .iter()
            .fold(Complex::new(0.0, 0.0), |acc, &c| acc * z + c)
    };
    let mut roots: Vec<Complex<f64>> = (0..n)
        .map(|k| Complex::new(0.4, 0.9).powu(k as u32))
        .collect();
    for _ in 0..500 {
        for i in 0..n {
            let mut denominator = Complex::new(1.0, 0.0);
            for j in 0..n {
                if i != j {
                    denominator *= roots[i] - roots[j];
                }
            }
            let correction = poly(roots[i]) / denominator;
            roots[i] -= correction;
        }
    }
    roots
}

fn assert_same_spectrum(mut left: Vec<Complex<f64>>, mut right: Vec<Complex<f64>>, tolerance: f64) {
    let key =
        |c: &Complex<f64>| (c.re * 1e6).round() as i64 * 1_000_000 + (c.im * 1e6).round() as i64;
    left.sort_by_key(key);
    right.sort_by_key(key);
    for (l, r) in left.iter().zip(&right) {
        assert!((l - r).norm() < tolerance, "{l} vs {r}");
    }
}

/// docs/model.md §8: the paper's printed Eq. (14) A matrix has eigenvalues −0.406 ± 0.447i and
/// −0.054 ± 0.161i (not the ones the paper prints).
#[test]
fn printed_paper_matrix_gives_the_eigenvalues_model_md_records() {
    let a = SMatrix::<f64, 4, 4>::from_row_slice(&[
        -0.18, -9.81, -0.274, 0.0, //
        0.0, 0.0, 0.0, 1.0, //
        -0.0041, 0.0, -0.59, 1.0, //
        0.0, 0.0, -0.26, -0.15,
    ]);
    let modes = identify_modes(&a.complex_eigenvalues().iter().copied().collect::<Vec<_>>());
    let sp = modes
        .iter()
        .find(|m| m.kind == ModeKind::ShortPeriod)
        .unwrap()
        .eigenvalue;
    let ph = modes
        .iter()
        .find(|m| m.kind == ModeKind::Phugoid)
        .unwrap()
        .eigenvalue;
    assert!((sp - Complex::new(-0.406, 0.447)).norm() < 2e-3, "{sp}");
    assert!((ph - Complex::new(-0.054, 0.161)).norm() < 2e-3, "{ph}");
    assert_same_spectrum(
        a.complex_eigenvalues().iter().copied().collect(),
        eigenvalues_by_polynomial(&a),
        1e-8,
    );
}

/// docs/model.md §2.3: short period ≈ −0.385 ± 0.478i, phugoid ≈ 0.002 ± 0.164i; ∂q̇/∂α ≈ −0.26.
#[test]
fn linear_model_modes_match_model_md() {
    let aircraft = Aircraft::default();
    let point = trim(&aircraft, &level(69.1)).unwrap();
    let model = linearize(&aircraft, &point);
    let eigenvalues = model.eigenvalues();
    assert_same_spectrum(
        eigenvalues.clone(),
        eigenvalues_by_polynomial(&model.a),
        1e-8,
    );
    let modes = identify_modes(&eigenvalues);
    let sp = modes
        .iter()
        .find(|m| m.kind == ModeKind::ShortPeriod)
        .unwrap();
    let ph = modes.iter().find(|m| m.kind == ModeKind::Phugoid).unwrap();
    assert!(
        (sp.eigenvalue - Complex::new(-0.385, 0.478)).norm() < 5e-3,
        "{}",
        sp.eigenvalue
    );
    assert!(
        (ph.eigenvalue - Complex::new(0.002, 0.164)).norm() < 5e-3,
        "{}",
        ph.eigenvalue
    );
    assert!(
        (model.pitch_stiffness_per_s2() + 0.26).abs() < 0.005,
        "{}",
        model.pitch_stiffness_per_s2()
    );
    // Paper Eq. 14 structure: θ̇ = q exactly, elevator gives nose-down moment.
    assert_eq!(
        model.a.row(1).iter().copied().collect::<Vec<_>>(),
        vec![0.0, 0.0, 0.0, 1.0]
    );
    assert!(model.elevator_effectiveness_per_s2() < 0.0);
    assert!(model.pitch_damping_per_s() < 0.0);
    // Throttle column: ∂V̇/∂δT = 2·T_max·cos α/m (by hand).
    let expected = 2.0 * 71_172.0 * point.alpha_rad.cos() / 15_000.0;
    assert!((model.b[(0, 1)] - expected).abs() < 1e-6);
}
