use super::*;
use crate::environment::{
    ShipMotionParameters, ROLL_FILTER_DAMPING_RATIO, ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
    SHAPING_FILTER_DENOMINATOR,
};

/// ∫₀^τ h(s)² ds for the impulse response h of a filter ż = f(z) + e_N·n, output z₁,
/// by classical RK4 of the free system from z(0) = e_N at 1 ms, the integral by the
/// trapezoid rule: a computation apart from the table's e^{Aτ} and Lyapunov solution.
fn impulse_energy<const N: usize>(derivative: impl Fn(&[f64; N]) -> [f64; N], tau: f64) -> f64 {
    let dt = 1e-3;
    let steps = (tau / dt).round() as usize;
    let mut z = [0.0; N];
    z[N - 1] = 1.0;
    let mut energy = 0.0;
    for _ in 0..steps {
        let before = z[0];
        let add = |z: &[f64; N], k: &[f64; N], c: f64| std::array::from_fn(|i| z[i] + c * k[i]);
        let k1 = derivative(&z);
        let k2 = derivative(&add(&z, &k1, dt / 2.0));
        let k3 = derivative(&add(&z, &k2, dt / 2.0));
        let k4 = derivative(&add(&z, &k3, dt));
        z = std::array::from_fn(|i| z[i] + dt / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
        energy += 0.5 * dt * (before * before + z[0] * z[0]);
    }
    energy
}

fn roll_energy(tau: f64) -> f64 {
    let (omega, zeta) = (
        ROLL_FILTER_NATURAL_FREQUENCY_RADPS,
        ROLL_FILTER_DAMPING_RATIO,
    );
    impulse_energy(
        |z: &[f64; 2]| [z[1], -omega * omega * z[0] - 2.0 * zeta * omega * z[1]],
        tau,
    )
}

fn canonical_energy(tau: f64) -> f64 {
    let [d0, d1, d2, d3] = SHAPING_FILTER_DENOMINATOR;
    impulse_energy(
        |z: &[f64; 4]| {
            [
                z[1],
                z[2],
                z[3],
                -d0 * z[0] - d1 * z[1] - d2 * z[2] - d3 * z[3],
            ]
        },
        tau,
    )
}

/// The paper's sea's lateral motion (the defaults), its filters, the default deck and
/// their floor.
fn default_floor() -> (
    ShipMotionParameters,
    LateralShipMotion,
    DeckGeometry,
    AimPointLateralFloor,
) {
    let parameters = ShipMotionParameters::default();
    let ship = LateralShipMotion::new(&parameters).expect("default ship");
    let deck = DeckGeometry::default();
    let floor = AimPointLateralFloor::new(&ship, &deck);
    (parameters, ship, deck, floor)
}

#[test]
fn the_aim_points_sensitivities_are_the_decks_geometry_by_hand() {
    // The aim point is 81 m aft of the pitch centre, 10 m to port of the ship's
    // centreline and 19 m above the roll axis (docs/model.md §2.7, §10.5); the ship's
    // mean heading is the deck angle, 9°. To first order: sway moves it across the
    // bearing by cos 9°; yaw about the pitch centre by cos 9°·(−81) − sin 9°·(−10) m/rad;
    // roll, starboard down, swings a point 19 m above the axis to starboard by
    // 19·cos 9° m/rad.
    let deck = DeckGeometry::default();
    let (sin, cos) = 9.0_f64.to_radians().sin_cos();
    let [roll, yaw, sway] = aim_point_sensitivities(&deck);
    assert!((sway - cos).abs() < 1e-6, "sway {sway}");
    assert!((yaw - (-81.0 * cos + 10.0 * sin)).abs() < 1e-4, "yaw {yaw}");
    assert!((roll - 19.0 * cos).abs() < 1e-4, "roll {roll}");
}

#[test]
fn the_floor_is_the_noise_still_to_come_integrated_apart() {
    // σ²(τ) = k_φ²·q_φ·∫h_φ² + (k_ψ²q_ψ + k_y²q_y)·∫h_D², the impulse responses
    // integrated step by step (above), against the table's closed form.
    let (_, ship, deck, floor) = default_floor();
    let [q_roll, q_yaw, q_sway] = ship.noise_intensities();
    let [k_roll, k_yaw, k_sway] = aim_point_sensitivities(&deck);
    for tau in [0.5, 2.0, 3.0, 4.0, 10.0] {
        let expected = (k_roll * k_roll * q_roll * roll_energy(tau)
            + (k_yaw * k_yaw * q_yaw + k_sway * k_sway * q_sway) * canonical_energy(tau))
        .sqrt();
        let sigma = floor.sigma_m(tau);
        assert!(
            (sigma - expected).abs() < 1e-5 * expected.max(1e-3),
            "τ = {tau} s: table {sigma} m, integrated {expected} m"
        );
    }
    assert_eq!(floor.sigma_m(0.0), 0.0);
}

#[test]
fn the_floor_grows_to_the_configured_motion() {
    // Far ahead nothing is foreseeable: σ is the aim point's stationary RMS, which the
    // configured RMS of roll (1°), yaw (0.3°) and sway (0.5 m) give through the
    // sensitivities, whatever the noise intensities were solved to be.
    let (parameters, _, deck, floor) = default_floor();
    let [k_roll, k_yaw, k_sway] = aim_point_sensitivities(&deck);
    let expected = ((k_roll * parameters.roll_rms_deg.to_radians()).powi(2)
        + (k_yaw * parameters.yaw_rms_deg.to_radians()).powi(2)
        + (k_sway * parameters.sway_rms_m).powi(2))
    .sqrt();
    assert!((floor.stationary_sigma_m() - expected).abs() < 1e-9 * expected);
    assert!((floor.sigma_m(1000.0) - expected).abs() < 1e-9 * expected);
    // The table reaches it from below, never passing it.
    let mut last = 0.0;
    for k in 0..1300 {
        let sigma = floor.sigma_m(0.05 * f64::from(k));
        assert!(sigma >= last - 1e-12 && sigma <= expected * (1.0 + 1e-9));
        last = sigma;
    }
    assert!(floor.sigma_m(60.0) > 0.99 * expected);
}
