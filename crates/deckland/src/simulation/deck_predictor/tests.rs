//! Tests of the deck predictors' shared geometry (`deck_predictor/mod.rs`).

use super::raise::{raise_share, ramp_clearance_sigma_m};
use super::*;
use crate::control::FlightPathParameters;

fn forecast(landing_point_height_m: f64, ramp_height_m: f64) -> DeckForecast {
    DeckForecast::still(landing_point_height_m, ramp_height_m)
}

/// The default path with a fixed 2.5-m margin (no risk-aware clearance).
fn fixed_margin() -> FlightPathParameters {
    FlightPathParameters {
        ramp_clearance_margin_m: 2.5,
        ramp_strike_probability_limit: 0.0,
        ..FlightPathParameters::default()
    }
}

/// The risk-aware clearance by hand (the default: p = 10⁻⁴, z = Φ⁻¹(1 − 10⁻⁴) = 3.7190
/// from the normal table; σ_h = 0.3 m, σ_t = 0.1 s; recovery r = 1.16 m; floor 2.0 m,
/// cap 4.0 m). The ramp forecast 2 m above the landing point with σ_r = 1 m, rising at
/// 2 m/s: σ_c = √(1 + 0.09 + 0.04) = 1.0630 m, clearance 3.7190·1.0630 − 1.16 = 2.7934 m,
/// anchor 24 + 2.7934 − 3.6698 = 23.1236 m. Known exactly (σ_r = 0), σ_c = √0.13 = 0.3606 m
/// gives 0.18 m, under the 2-m floor: anchor 24 + 2 − 3.6698 = 22.3302 m. With σ_r = 2 m
/// the clearance, 6.40 m, is capped at 4 m: anchor 24.3302 m.
#[test]
fn the_risk_aware_clearance_grows_with_the_forecasts_sigma_and_the_ramps_motion() {
    let deck = DeckGeometry::default();
    let parameters = FlightPathParameters::default();
    assert_eq!(parameters.ramp_strike_probability_limit, 1e-4);
    assert_eq!(parameters.ramp_recovery_m, 1.16);
    let generator = FlightPathGenerator::new(parameters).unwrap();
    assert!((generator.ramp_clearance_z() - 3.7190).abs() < 1e-4);
    let uncertain = DeckForecast {
        ramp_height_sigma_m: 1.0,
        ramp_climb_rate_mps: 2.0,
        ..forecast(22.0, 24.0)
    };
    assert!((ramp_clearance_sigma_m(&parameters, &uncertain) - 1.13_f64.sqrt()).abs() < 1e-12);
    let raised = ramp_aware_anchor(&parameters, &generator, &deck, &uncertain);
    assert!((raised - 23.1236).abs() < 1e-3, "{raised}");
    let known = DeckForecast {
        ramp_height_sigma_m: 0.0,
        ..uncertain
    };
    let floor = ramp_aware_anchor(&parameters, &generator, &deck, &known);
    assert!((floor - 22.3302).abs() < 1e-4, "{floor}");
    let very_uncertain = DeckForecast {
        ramp_height_sigma_m: 2.0,
        ..uncertain
    };
    let capped = ramp_aware_anchor(&parameters, &generator, &deck, &very_uncertain);
    assert!((capped - 24.3302).abs() < 1e-4, "{capped}");
}

/// The recovery credit r lowers the clearance by exactly r between the floor and the cap,
/// and r = 0 gives z·σ_c: with the uncertain forecast above, 3.9534 m over the ramp.
#[test]
fn the_recovery_credit_lowers_the_clearance_by_itself() {
    let deck = DeckGeometry::default();
    let uncertain = DeckForecast {
        ramp_height_sigma_m: 1.0,
        ramp_climb_rate_mps: 2.0,
        ..forecast(22.0, 24.0)
    };
    let anchor = |recovery_m: f64| {
        let parameters = FlightPathParameters {
            ramp_recovery_m: recovery_m,
            ..FlightPathParameters::default()
        };
        let generator = FlightPathGenerator::new(parameters).unwrap();
        ramp_aware_anchor(&parameters, &generator, &deck, &uncertain)
    };
    let rise_to_ramp_m = 60.0 * 3.5_f64.to_radians().tan();
    assert!((anchor(0.0) - (24.0 + 3.9534 - rise_to_ramp_m)).abs() < 1e-3);
    assert!((anchor(0.0) - anchor(0.5) - 0.5).abs() < 1e-12);
    assert!((anchor(0.0) - anchor(1.9) - 1.9).abs() < 1e-12);
    // Past z·σ_c − floor (1.9534 m), the floor holds.
    assert_eq!(anchor(2.5), anchor(3.0));
}

/// On a level deck the path already clears the ramp by 60·tan 3.5° = 3.6698 m > 2.5 m:
/// the anchor stays on the landing point. With the ramp 2 m higher than the landing
/// point (the ship bow down about 1.9°), the anchor rises to
/// ramp + 2.5 − 3.6698 = landing point + 0.8302 m.
#[test]
fn the_ramp_aware_anchor_rises_only_when_the_ramp_would_come_too_close() {
    let deck = DeckGeometry::default();
    let parameters = fixed_margin();
    let generator = FlightPathGenerator::new(parameters).unwrap();
    let rise = 60.0 * 3.5_f64.to_radians().tan();
    let level = ramp_aware_anchor(&parameters, &generator, &deck, &forecast(20.0, 20.0));
    assert_eq!(level, 20.0);
    let pitched = ramp_aware_anchor(&parameters, &generator, &deck, &forecast(22.0, 24.0));
    assert!((pitched - (24.0 + 2.5 - rise)).abs() < 1e-12, "{pitched}");
    assert!((pitched - 22.0 - 0.8302).abs() < 1e-4, "{pitched}");
    let unaware = FlightPathParameters {
        ramp_aware: false,
        ..parameters
    };
    assert_eq!(
        ramp_aware_anchor(&unaware, &generator, &deck, &forecast(22.0, 24.0)),
        22.0
    );
}

/// With `descend_after_ramp`, the path of a raised anchor (the ramp 2 m above the
/// landing point: raise r = 2 + 2.5 − 60·tan 3.5° = 0.8302 m) still crosses the ramp
/// 2.5 m above it, then reaches the landing point itself. By hand, for a 60-m/s closure
/// (u = 1 − d/60 rises at 1 per s) and the 0.25-s blend (b = 0.25, plateau
/// g_max = 1/(1 − b) = 4/3): at the ramp (d = 60 m) the path stands
/// LP + 0.8302 + 3.6698 = ramp + 2.5; half-way (d = 30 m, u = ½, on the plateau: shed
/// 4/3·(½ − ⅛) = ½) LP + 0.4151 + 1.8349 = LP + 2.25, the share falling at 4/3 per s; in
/// the middle of the first blend (d = 52.5 m, x = ½) the shed is
/// g_max·b·(x³ − x⁴/2) = 4/3·¼·(3/32) = 1/32 and its rate g_max·(3x² − 2x³) = 2/3 per s;
/// at the aim point LP. The share's rate is 0 at both ends (no step in the command).
/// A 0-s blend sheds linearly (½ and 1 per s half-way). Without the descent the raise
/// is kept all the way (touchdown r/tan 3.5° = 13.6 m long).
#[test]
fn the_path_sheds_its_raise_smoothly_between_the_ramp_and_the_aim_point() {
    let deck = DeckGeometry::default();
    let parameters = fixed_margin();
    assert!(parameters.ramp_aware && parameters.descend_after_ramp);
    assert_eq!(parameters.descent_blend_s, 0.25);
    let generator = FlightPathGenerator::new(parameters).unwrap();
    let tan = generator.tan_slope();
    let raised = ramp_aware_anchor(&parameters, &generator, &deck, &forecast(22.0, 24.0));
    let raise = raised - 22.0;
    let path_at = |d: f64| {
        let (share, _) = raise_share(&parameters, &deck, d, 60.0);
        22.0 + share * raise + d * tan
    };
    assert!((path_at(60.0) - 26.5).abs() < 1e-12, "{}", path_at(60.0));
    assert!((path_at(120.0) - (26.5 + 60.0 * tan)).abs() < 1e-12);
    assert!((path_at(30.0) - 24.25).abs() < 1e-12, "{}", path_at(30.0));
    assert_eq!(path_at(0.0), 22.0);
    assert_eq!(path_at(-5.0), 22.0 - 5.0 * tan);
    let close =
        |(a, b): (f64, f64), (c, d): (f64, f64)| (a - c).abs() < 1e-12 && (b - d).abs() < 1e-12;
    assert!(close(
        raise_share(&parameters, &deck, 30.0, 60.0),
        (0.5, -4.0 / 3.0)
    ));
    let first_blend = raise_share(&parameters, &deck, 52.5, 60.0);
    assert!(
        close(first_blend, (1.0 - 1.0 / 32.0, -2.0 / 3.0)),
        "{first_blend:?}"
    );
    assert_eq!(raise_share(&parameters, &deck, 90.0, 60.0), (1.0, 0.0));
    for d in [59.999, 0.001] {
        let (_, rate) = raise_share(&parameters, &deck, d, 60.0);
        assert!(rate.abs() < 1e-3, "{d}: {rate}");
    }
    let linear = FlightPathParameters {
        descent_blend_s: 0.0,
        ..parameters
    };
    assert!(close(raise_share(&linear, &deck, 30.0, 60.0), (0.5, -1.0)));
    let keep = FlightPathParameters {
        descend_after_ramp: false,
        ..parameters
    };
    assert_eq!(raise_share(&keep, &deck, 30.0, 60.0), (1.0, 0.0));
    assert!((raise / tan - 13.57).abs() < 0.01, "{}", raise / tan);
}

/// The descent after the ramp's cap: a 3-m raise shed over the 60-m segment at a 60-m/s
/// closure with the 0.25-s blend peaks at g_max·closure/d_R·raise = (4/3)·1·3 = 4 m/s
/// of extra sink (by hand); capped at 2 m/s, half of the raise is shed, so mid-segment
/// the path keeps 0.75 of it (0.5 uncapped) and sinks (2/3)·3 = 2 m/s faster, no more;
/// a raise the cap allows is shed as before, bit for bit.
#[test]
fn the_descent_after_the_ramp_adds_no_more_sink_than_its_cap() {
    let deck = DeckGeometry::default();
    let capped = FlightPathParameters {
        max_descent_after_ramp_sink_mps: 2.0,
        ..FlightPathParameters::default()
    };
    let (share, rate) = capped_raise_share(&capped, &deck, 30.0, 60.0, 3.0);
    assert!((share - 0.75).abs() < 1e-12, "{share}");
    assert!((rate * 3.0 + 2.0).abs() < 1e-12, "{rate}");
    for range_m in [59.0, 45.0, 30.0, 5.0, 0.5] {
        let (_, rate) = capped_raise_share(&capped, &deck, range_m, 60.0, 3.0);
        assert!(-rate * 3.0 <= 2.0 + 1e-12, "{range_m}: {rate}");
        assert_eq!(
            capped_raise_share(&capped, &deck, range_m, 60.0, 1.0),
            raise_share(&capped, &deck, range_m, 60.0),
            "{range_m}"
        );
    }
    let error = FlightPathParameters {
        max_descent_after_ramp_sink_mps: 0.0,
        ..FlightPathParameters::default()
    }
    .validate()
    .unwrap_err()
    .to_string();
    assert!(error.contains("max_descent_after_ramp_sink_mps"), "{error}");
}

/// The 3-D approach's forecast takes the ship's predicted pitch's sine and cosine by
/// series: the same deck heights and climb rates as the library's to within a few
/// rounding errors of the heights (about 20 m, so 10⁻¹¹ m), over ship states drawn from
/// the paper's sea (scaled up to three times its σ) and horizons across the window.
#[test]
fn the_series_forecast_is_the_librarys_within_rounding() {
    use crate::environment::{ShipMotionParameters, ShipMotionState};
    let ship = ShipMotion::new(ShipMotionParameters::default()).expect("valid");
    let deck = DeckGeometry::default();
    let predictor = ShipMotionPropagator::new(&ship, 12.0);
    let streams = RandomStreams::new(5);
    let (mut heave, mut pitch) = (
        streams.stream(stream_names::SHIP_HEAVE),
        streams.stream(stream_names::SHIP_PITCH),
    );
    let mut largest_pitch = 0.0_f64;
    for draw in 0..200 {
        let state = ship.stationary_initial_state(&mut heave, &mut pitch);
        let scale = 1.0 + (draw % 3) as f64;
        let estimate = ShipMotionEstimate {
            mean: ShipMotionState {
                heave_filter: state.heave_filter.map(|z| scale * z),
                pitch_filter: state.pitch_filter.map(|z| scale * z),
            },
            heave_covariance: [[0.0; 4]; 4],
            pitch_covariance: [[0.0; 4]; 4],
        };
        let time_to_go_s = 0.05 * draw as f64;
        let forecast = |series| {
            forecast_deck(
                &predictor,
                &ship,
                &estimate,
                0.02,
                time_to_go_s,
                9.0,
                &deck,
                None,
                series,
            )
        };
        let (library, series) = (forecast(false), forecast(true));
        largest_pitch = largest_pitch.max(library.pitch_rad.abs());
        for (a, b) in [
            (library.ramp_height_m, series.ramp_height_m),
            (
                library.landing_point_height_m,
                series.landing_point_height_m,
            ),
            (library.ramp_climb_rate_mps, series.ramp_climb_rate_mps),
            (
                library.landing_point_climb_rate_mps,
                series.landing_point_climb_rate_mps,
            ),
        ] {
            assert!((a - b).abs() <= 1e-11, "{a} against {b} (draw {draw})");
        }
        assert_eq!(library.pitch_rad, series.pitch_rad);
    }
    // The draws reach pitch angles where the series' terms beyond x³ count.
    assert!(largest_pitch > 0.02, "{largest_pitch}");
}

/// The anchor filter's free response (`anchor_free_response`: the move, and the rate the
/// closed-loop hard-landing sink reads) is what its exact step (`AnchorShaping`'s
/// critically damped filter, a target held) gives: 1 m below its target at rest, the
/// anchor rises 1 − (1 + 1.5)·e^(−1.5) = 0.44217 m in 1.5 s at ω = 1 rad/s and moves at
/// ω²·T·e^(−ωT) = 0.33470 m/s then (by hand); the same from a 10-µs integration of
/// ä = ω²(target − a) − 2ω·ȧ from a moving start; no move and the rate now over no time.
#[test]
fn the_anchor_moves_by_its_filters_free_response() {
    let (moved, rate) = anchor_free_response(19.0, 0.0, 20.0, 1.0, 1.5);
    assert!((moved - 0.442_17).abs() < 1e-5, "{moved}");
    assert!((rate - 0.334_695).abs() < 1e-6, "{rate}");
    let (omega, horizon_s) = (1.3_f64, 1.4_f64);
    let (mut a, mut a_rate, target) = (21.0_f64, -0.7_f64, 20.2);
    let dt = 1e-5_f64;
    for _ in 0..(horizon_s / dt).round() as usize {
        let acceleration = omega * omega * (target - a) - 2.0 * omega * a_rate;
        a += a_rate * dt + 0.5 * acceleration * dt * dt;
        a_rate += acceleration * dt;
    }
    let (moved, rate) = anchor_free_response(21.0, -0.7, 20.2, omega, horizon_s);
    assert!(
        (moved - (a - 21.0)).abs() < 1e-4,
        "{moved} against {}",
        a - 21.0
    );
    assert!((rate - a_rate).abs() < 1e-4, "{rate} against {a_rate}");
    assert_eq!(
        anchor_free_response(21.0, -0.7, 20.2, omega, 0.0),
        (0.0, -0.7)
    );
}

/// The path's response to the ramp's later updates (`ramp_update_response_m2`):
/// ∫₀ᵀ g dσ² and ∫₀ᵀ g² dσ² for a variance growing linearly, σ²(τ) = τ, against a fine
/// midpoint sum of the same integrals (g = 1 − (1 + ωτ)·e^(−ωτ)): within 1 % at 8
/// intervals; by hand, ∫₀ᵀ g dτ = T − 2/ω + (2/ω + T)·e^(−ωT) = 0.2810 at ω = 1, T = 1.5;
/// the variance the path follows, 2w·∫g − w²·∫g², never more than the whole variance
/// for w in [0, 1]; nothing for a variance that does not grow, nor for a crossing now.
#[test]
fn the_path_follows_the_ramps_later_updates_by_its_filters_step_response() {
    let (omega, horizon_s) = (1.0, 1.5);
    let g = |tau: f64| 1.0 - (1.0 + omega * tau) * (-omega * tau).exp();
    let n = 100_000;
    let fine = |power: i32| -> f64 {
        (0..n)
            .map(|k| {
                let tau = (f64::from(k) + 0.5) * horizon_s / f64::from(n);
                g(tau).powi(power) * horizon_s / f64::from(n)
            })
            .sum()
    };
    let [first, second] = ramp_update_response_m2(|tau| tau, horizon_s, anchor_filter_share(omega));
    let by_hand = horizon_s - 2.0 + (2.0 + horizon_s) * (-horizon_s).exp();
    let (fine_g, fine_g2) = (fine(1), fine(2));
    assert!(
        (fine_g - by_hand).abs() < 1e-9,
        "{fine_g} against {by_hand}"
    );
    assert!(
        (first / fine_g - 1.0).abs() < 0.01,
        "{first} against {fine_g}"
    );
    assert!(
        (second / fine_g2 - 1.0).abs() < 0.01,
        "{second} against {fine_g2}"
    );
    for w in [0.0, 0.3, 1.0] {
        let followed = 2.0 * w * first - w * w * second;
        assert!((0.0..horizon_s).contains(&followed), "{w}: {followed}");
    }
    assert_eq!(
        ramp_update_response_m2(|_| 2.0, horizon_s, anchor_filter_share(omega)),
        [0.0; 2]
    );
    assert_eq!(
        ramp_update_response_m2(|tau| tau, 0.0, anchor_filter_share(omega)),
        [0.0; 2]
    );
}

/// σ_c of the closed loop: with the anchor on the ramp floor (the path's weight w on the
/// ramp) the followed variance 2w·∫g − w²·∫g² comes off the ramp's, off the floor (w = 0)
/// nothing does: σ_r = 1 m, ∫g dσ² = 0.2 m² and ∫g² dσ² = 0.04 m² (0.36 m² followed at
/// w = 1, 0.19 m² at w = 0.5), σ_h = 0.3 m, the ramp still: √(1 − 0.36 + 0.09) = 0.8544 m
/// at w = 1, √(1 − 0.19 + 0.09) at w = 0.5, √1.09 off it; a followed variance beyond the
/// ramp's is held to it. Off the floor under the anchor models, with ∫g dC = 0.15 m² and
/// ∫g² dσ_L² = 0.05 m², the path takes 2·0.15 − 0.05 = 0.25 m² out at w = 1,
/// √(1 − 0.25 + 0.09); nothing at w = 0; a landing point uncorrelated with the ramp
/// (∫g dC = 0) adds its 0.05 m², √1.14; beyond the ramp's variance, held to it, √0.09.
#[test]
fn the_closed_loop_sigma_takes_out_what_the_path_follows_of_its_anchor() {
    let parameters = FlightPathParameters::default();
    let f = DeckForecast {
        ramp_height_sigma_m: 1.0,
        ramp_update_response_m2: [0.2, 0.04],
        landing_point_update_response_m2: [0.15, 0.05],
        ..forecast(20.0, 20.0)
    };
    let on = |f: &DeckForecast, w: f64| closed_loop_ramp_clearance_sigma_m(&parameters, f, w);
    let off = |f: &DeckForecast, w: f64| {
        landing_point_following_ramp_clearance_sigma_m(&parameters, f, w)
    };
    let with = |ramp: [f64; 2], landing: [f64; 2]| DeckForecast {
        ramp_update_response_m2: ramp,
        landing_point_update_response_m2: landing,
        ..f
    };
    // (σ_c, the σ_c² worked out above)
    let cases = [
        (on(&f, 1.0), 0.73_f64),
        (on(&f, 0.5), 0.9),
        (on(&f, 0.0), 1.09),
        (on(&with([3.0, 1.0], [0.15, 0.05]), 1.0), 0.09),
        (off(&f, 1.0), 0.84),
        (off(&with([0.2, 0.04], [0.0, 0.05]), 1.0), 1.14),
        (off(&with([0.2, 0.04], [3.0, 1.0]), 1.0), 0.09),
    ];
    for (got, want) in cases {
        assert!((got - want.sqrt()).abs() < 1e-12, "{got} against √{want}");
    }
    assert_eq!(on(&f, 0.0), ramp_clearance_sigma_m(&parameters, &f));
    assert_eq!(off(&f, 0.0), ramp_clearance_sigma_m(&parameters, &f));
}

/// The path's response to the landing point's later updates
/// (`landing_point_update_response_m2`): for a covariance C(τ) = ρ·τ and a landing
/// point's variance σ_L²(τ) = τ (both growing linearly) it is [ρ·∫₀ᵀ g dτ, ∫₀ᵀ g² dτ],
/// the ramp's moments scaled, by hand ρ·0.2810 at ω = 1, T = 1.5 (as above); a covariance
/// that falls counts (negative), a variance that falls does not.
#[test]
fn the_path_follows_the_landing_points_updates_by_their_covariance_with_the_ramps() {
    let (omega, horizon_s, rho) = (1.0, 1.5, 0.6);
    let ramp = ramp_update_response_m2(|tau| tau, horizon_s, anchor_filter_share(omega));
    let [cross, landing] = landing_point_update_response_m2(
        |tau| [rho * tau, tau],
        horizon_s,
        anchor_filter_share(omega),
    );
    assert!((cross - rho * ramp[0]).abs() < 1e-15, "{cross}");
    assert_eq!(landing, ramp[1]);
    let by_hand = horizon_s - 2.0 + (2.0 + horizon_s) * (-horizon_s).exp();
    assert!((cross / (rho * by_hand) - 1.0).abs() < 0.01, "{cross}");
    let [falling, none] =
        landing_point_update_response_m2(|tau| [-tau, -tau], horizon_s, anchor_filter_share(omega));
    assert!((falling + ramp[0]).abs() < 1e-15, "{falling}");
    assert_eq!(none, 0.0);
}
