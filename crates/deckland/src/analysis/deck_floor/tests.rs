use super::*;
use crate::environment::{ShipMotionParameters, PITCH_FILTER_GAIN, SHAPING_FILTER_DENOMINATOR};
use crate::random::RandomStreams;

/// The landing point's and the ramp's lever arms aft of the pitch centre (m,
/// docs/model.md §2.7: 81 m, and the ramp 60 m aft of the landing point).
const LANDING_POINT_M: f64 = 81.0;
const RAMP_M: f64 = 141.0;

fn papers_sea() -> ShipMotion {
    ShipMotion::new(ShipMotionParameters::default()).expect("the default sea")
}

/// The paper's sea from tests/reference/deck_motion_floor.py, which integrates the
/// covariance built up by the noise as a matrix ODE with RK4 (the library takes
/// P∞ − e^{Ah}P∞e^{Aᵀh}): (horizon, lever arm, height σ, velocity σ).
#[test]
fn the_floor_matches_an_independent_integration() {
    let ship = papers_sea();
    for (horizon, arm, height, velocity) in [
        (0.5, LANDING_POINT_M, 0.32644, 1.03787),
        (0.5, RAMP_M, 0.56824, 1.80660),
        (1.4, LANDING_POINT_M, 0.78427, 1.08018),
        (1.4, RAMP_M, 1.36398, 1.87621),
        (2.5, LANDING_POINT_M, 0.91722, 1.22161),
        (2.5, RAMP_M, 1.57166, 2.10591),
    ] {
        let floor = deck_point_floor(&ship, arm, horizon);
        assert!(
            (floor.height_sigma_m / height - 1.0).abs() < 2e-4,
            "{horizon} s, {arm} m: height σ {} against {height}",
            floor.height_sigma_m
        );
        assert!(
            (floor.climb_rate_sigma_mps / velocity - 1.0).abs() < 2e-4,
            "{horizon} s, {arm} m: velocity σ {} against {velocity}",
            floor.climb_rate_sigma_mps
        );
    }
    let (height, velocity) = deck_point_stationary_sigma(&ship, LANDING_POINT_M);
    assert!((height - 2.91493).abs() < 1e-4 && (velocity - 1.66192).abs() < 1e-4);
    let (height, velocity) = deck_point_stationary_sigma(&ship, RAMP_M);
    assert!((height - 4.19836).abs() < 1e-4 && (velocity - 2.68647).abs() < 1e-4);
}

/// Over a short horizon h the pitch rate's unforeseen variance is q·(h − d₃h² +
/// (2d₃² − d₂)h³/3 + O(h⁴)) (the filter's impulse response to the pitch rate is
/// 1 − d₃τ + (d₃² − d₂)τ²/2 + …, squared and integrated), and heave's rate adds O(h⁵): the
/// velocity's σ grows as √h, the signature of a white pitch acceleration.
#[test]
fn the_velocity_floor_grows_as_the_root_of_the_horizon() {
    let ship = papers_sea();
    let [_, _, d2, d3] = SHAPING_FILTER_DENOMINATOR;
    for h in [0.02, 0.04] {
        let series = h - d3 * h * h + (2.0 * d3 * d3 - d2) * h.powi(3) / 3.0;
        let expected = RAMP_M * PITCH_FILTER_GAIN * (ship.pitch_noise_intensity() * series).sqrt();
        let floor = deck_point_floor(&ship, RAMP_M, h);
        assert!(
            (floor.climb_rate_sigma_mps / expected - 1.0).abs() < 1e-4,
            "{h} s: {} against {expected}",
            floor.climb_rate_sigma_mps
        );
    }
}

/// The stationary height σ is √(heave² + (r·pitch)²) from the configured RMS alone, and
/// the floor tends to the stationary σ as the horizon grows.
#[test]
fn the_floor_tends_to_the_stationary_motion() {
    let parameters = ShipMotionParameters {
        heave_rms_m: 1.0,
        pitch_rms_deg: 0.75,
        ..ShipMotionParameters::default()
    };
    let ship = ShipMotion::new(parameters).unwrap();
    let (height, velocity) = deck_point_stationary_sigma(&ship, RAMP_M);
    let expected = (1.0_f64 + (RAMP_M * 0.75_f64.to_radians()).powi(2)).sqrt();
    assert!(
        (height - expected).abs() < 1e-9,
        "{height} against {expected}"
    );
    let far = deck_point_floor(&ship, RAMP_M, 400.0);
    assert!((far.height_sigma_m - height).abs() < 1e-6);
    assert!((far.climb_rate_sigma_mps - velocity).abs() < 1e-6);
    let still = ShipMotion::new(ShipMotionParameters {
        enabled: false,
        ..parameters
    })
    .unwrap();
    assert_eq!(deck_point_stationary_sigma(&still, RAMP_M), (0.0, 0.0));
}

/// tests/reference/deck_motion_floor.py finds the same rule with a trapezoidal integral
/// on a fine grid: the paper's sea's landing point (stationary σ 1.66192 m/s), decided at
/// 0.5 s and 2.5 s (σ 1.03787 and 1.22161 m/s), 0.1 % of hard landings.
#[test]
fn the_decision_bound_matches_an_independent_computation() {
    for (unforeseen, margin, without, threshold, fraction) in [
        (1.03787, 3.8, 0.011112, 1.5086, 0.12256),
        (1.03787, 4.2, 0.005749, 2.0769, 0.05479),
        (1.03787, 4.6, 0.002821, 2.7844, 0.01597),
        (1.22161, 3.8, 0.011112, 0.8571, 0.22344),
        (1.22161, 4.2, 0.005749, 1.3699, 0.11204),
        (1.22161, 4.6, 0.002821, 2.0221, 0.03636),
    ] {
        let bound = hard_landing_decision_bound(1.66192, unforeseen, margin, 0.001).unwrap();
        assert!(
            (bound.rate_without_decision - without).abs() < 2e-6,
            "{bound:?}"
        );
        assert!((bound.threshold_mps - threshold).abs() < 2e-3, "{bound:?}");
        assert!(
            (bound.wave_off_fraction - fraction).abs() < 2e-4,
            "{bound:?}"
        );
    }
}

/// The rule's threshold, applied to 10⁶ draws of (forecast, unforeseen rest), lets through
/// the rate of hard landings it was found for and waves off the share it claims.
#[test]
fn the_rule_keeps_the_rate_it_was_found_for() {
    let (s, u, margin, rate) = (1.66192, 1.22161, 4.2, 0.001);
    let bound = hard_landing_decision_bound(s, u, margin, rate).unwrap();
    let forecast_sigma = (s * s - u * u).sqrt();
    let streams = RandomStreams::new(17);
    let (mut forecasts, mut rest) = (streams.stream("forecast"), streams.stream("rest"));
    let n = 1_000_000;
    let (mut hard, mut waved) = (0_u32, 0_u32);
    for _ in 0..n {
        let f = forecast_sigma * forecasts.standard_normal();
        if f > bound.threshold_mps {
            waved += 1;
        } else if f + u * rest.standard_normal() > margin {
            hard += 1;
        }
    }
    // Binomial standard errors: 3.2e-5 for the 0.1 %, 3.2e-4 for the 11 %.
    let hard_rate = f64::from(hard) / f64::from(n);
    let waved_rate = f64::from(waved) / f64::from(n);
    assert!((hard_rate - rate).abs() < 1.3e-4, "{hard_rate}");
    assert!(
        (waved_rate - bound.wave_off_fraction).abs() < 1.3e-3,
        "{waved_rate} against {bound:?}"
    );
}

#[test]
fn the_decision_bound_refuses_what_it_cannot_answer_and_needs_none_below_the_rate() {
    assert!(hard_landing_decision_bound(1.0, 1.2, 3.0, 0.001).is_none());
    assert!(hard_landing_decision_bound(1.0, 0.5, 3.0, 0.0).is_none());
    assert!(hard_landing_decision_bound(0.0, 0.0, 3.0, 0.01).is_none());
    assert!(hard_landing_decision_bound(1.0, 0.5, f64::NAN, 0.01).is_none());
    // P(v > 4σ) = 3.2e-5 is below 0.1 %: nothing to wave off.
    let bound = hard_landing_decision_bound(1.0, 0.5, 4.0, 0.001).unwrap();
    assert_eq!(bound.wave_off_fraction, 0.0);
    assert!((bound.rate_without_decision - 3.167e-5).abs() < 1e-7);
}

/// z = 3.719 for 10⁻⁴ (Abramowitz & Stegun, Table 26.1): 3.719·1.364 − 1.2 = 3.873 m.
#[test]
fn the_ramp_clearance_is_the_quantile_less_the_recovery() {
    let clearance = ramp_clearance_for_strike_rate(1.364, 1.2, 1e-4);
    assert!(
        (clearance - (3.719_016 * 1.364 - 1.2)).abs() < 1e-4,
        "{clearance}"
    );
}

/// The sea state by hand: 1.0 m of heave and 0.75° of pitch 81 m aft give
/// √(1 + (81·0.0130900)²) = √2.12422 = 1.45747 m, 2.0 m and 1.5° give 2.91494 m (the
/// ship model's own stationary σ of the landing point, 1.46 and 2.91 m, worked out
/// from its covariance independently of this formula, agree).
#[test]
fn a_deck_points_stationary_sigma_is_that_of_heave_and_pitch() {
    let sea = |heave_rms_m, pitch_rms_deg| ShipMotionParameters {
        heave_rms_m,
        pitch_rms_deg,
        ..ShipMotionParameters::default()
    };
    let moderate = sea(1.0, 0.75).deck_point_height_rms_m(81.0);
    assert!((moderate - 1.45747).abs() < 1e-5, "{moderate}");
    let paper = sea(2.0, 1.5).deck_point_height_rms_m(81.0);
    assert!((paper - 2.91494).abs() < 1e-5, "{paper}");
    for (heave, pitch) in [(1.0, 0.75), (2.0, 1.5), (3.0, 2.5)] {
        let ship = ShipMotion::new(sea(heave, pitch)).unwrap();
        for arm in [LANDING_POINT_M, RAMP_M] {
            let from_covariance = deck_point_stationary_sigma(&ship, arm).0;
            let formula = sea(heave, pitch).deck_point_height_rms_m(arm);
            assert!((from_covariance - formula).abs() < 1e-9 * formula);
        }
    }
}

/// The two bands of the wave-off's ramp-strike decisions start in the sea where the
/// guidance's capped clearance stops holding its own ramp-strike bound, and are in full
/// where the capped path's strike probability is twice the bound. For the paper's sea
/// scaled by k (heave and pitch RMS alike, so its stationary ramp σ is 4.20·k m), the
/// ramp's floor σ_F over the 1.4 s from the commit point to the crossing gives the capped
/// path's probability (docs/model.md §5.7; m_max = 4 m, r = 1.16 m, σ_h = 0.3 m):
///
/// - the heavy-sea limits (`control.wave_off.heavy_sea_ramp_sigma_start_m`, `…_full_m`)
///   credit the recovery r, as the heavy sea's late abort at 0.5 % flies it:
///   Φ(−(m_max + r)/σ_F), 10⁻⁴ at σ_R∞ ≈ 4.27 m and 2·10⁻⁴ at ≈ 4.49 m;
/// - the commit gate (`commit_gate_ramp_sigma_start_m`, `…_full_m`) credits none, as the
///   ordinary late abort at 20 % does not fly it, and adds the hook's own scatter:
///   Φ(−m_max/√(σ_F² + σ_h²)), 10⁻⁴ at ≈ 3.18 m and 2·10⁻⁴ at ≈ 3.35 m. The paper's sea
///   (4.20 m) holds the bound only with r credited (7.7·10⁻⁵): 2.1·10⁻³ without.
#[test]
fn the_wave_off_bands_start_where_the_capped_path_stops_holding_its_bound() {
    use crate::control::{FlightPathParameters, WaveOffParameters};
    let path = FlightPathParameters::default();
    let wave_off = WaveOffParameters::default();
    // (σ_R∞, the capped path's P(strike)) in the paper's sea scaled by k, with the miss
    // distance `miss` and the hook's scatter `sigma_h`.
    let capped = |k: f64, miss: f64, sigma_h: f64| {
        let ship = ShipMotion::new(ShipMotionParameters {
            heave_rms_m: 2.0 * k,
            pitch_rms_deg: 1.5 * k,
            ..ShipMotionParameters::default()
        })
        .expect("a valid sea");
        let floor = deck_point_floor(&ship, RAMP_M, 1.4).height_sigma_m;
        let sigma_ramp = deck_point_stationary_sigma(&ship, RAMP_M).0;
        (sigma_ramp, normal_cdf(-miss / floor.hypot(sigma_h)))
    };
    // The sea (its σ_R∞) where the capped path's probability reaches `p`, by bisection on
    // k (the probability grows with k).
    let sea_at = |p: f64, miss: f64, sigma_h: f64| {
        let (mut low, mut high) = (0.5_f64, 2.0_f64);
        for _ in 0..60 {
            let k = 0.5 * (low + high);
            if capped(k, miss, sigma_h).1 > p {
                high = k;
            } else {
                low = k;
            }
        }
        capped(0.5 * (low + high), miss, sigma_h).0
    };
    let bound = path.ramp_strike_probability_limit;
    let (cap, sigma_h) = (path.max_ramp_clearance_m, path.hook_height_sigma_m);
    let credited = cap + path.ramp_recovery_m;
    for (band, miss, sigma_h) in [
        (
            (
                wave_off.heavy_sea_ramp_sigma_start_m,
                wave_off.heavy_sea_ramp_sigma_full_m,
            ),
            credited,
            0.0,
        ),
        (
            (
                wave_off.commit_gate_ramp_sigma_start_m,
                wave_off.commit_gate_ramp_sigma_full_m,
            ),
            cap,
            sigma_h,
        ),
    ] {
        let (start, full) = (
            sea_at(bound, miss, sigma_h),
            sea_at(2.0 * bound, miss, sigma_h),
        );
        assert!(
            (start - band.0).abs() < 0.05,
            "the capped path stops holding 10⁻⁴ at σ_R∞ = {start:.3} m"
        );
        assert!(
            (full - band.1).abs() < 0.05,
            "the capped path reaches 2·10⁻⁴ at σ_R∞ = {full:.3} m"
        );
    }
    // The paper's sea itself (k = 1, 4.20 m) holds the bound only with r credited.
    assert!(capped(1.0, credited, 0.0).1 < bound);
    let uncredited = capped(1.0, cap, sigma_h).1;
    assert!((1e-3..4e-3).contains(&uncredited), "{uncredited}");
}
