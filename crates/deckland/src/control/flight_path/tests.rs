//! Tests of the flight-path generator (kept apart so that flight_path.rs stays short).
use super::*;
use crate::control::DeckMotionFilter;

fn deck(aim_h: f64, aim_h_rate: f64) -> DeckReference {
    DeckReference {
        mean_aim: EarthPoint {
            x_m: 0.0,
            h_m: 20.0,
            ..Default::default()
        },
        mean_aim_velocity: EarthVelocity {
            x_mps: 0.0,
            h_mps: 0.0,
            ..Default::default()
        },
        aim: EarthPoint {
            x_m: 0.0,
            h_m: aim_h,
            ..Default::default()
        },
        aim_velocity: EarthVelocity {
            x_mps: 0.0,
            h_mps: aim_h_rate,
            ..Default::default()
        },
        forecast: None,
        unfiltered_aim_h_m: None,
        aim_acceleration_mps2: 0.0,
    }
}

#[test]
fn far_out_the_path_is_anchored_on_the_mean_deck() {
    let generator = FlightPathGenerator::new(FlightPathParameters::default()).unwrap();
    let r = generator.reference(-1000.0, 60.0, &deck(23.0, 1.0));
    // By hand: 20 + 1000·tan 3.5° = 81.16 m; climb −60·tan 3.5° = −3.670 m/s.
    assert!((r.height_m - (20.0 + 1000.0 * 3.5f64.to_radians().tan())).abs() < 1e-9);
    assert!((r.climb_rate_mps + 60.0 * 3.5f64.to_radians().tan()).abs() < 1e-12);
    assert_eq!(r.compensation_weight, 0.0);
    assert!((r.time_to_go_s - 1000.0 / 60.0).abs() < 1e-12);
}

#[test]
fn close_in_the_path_follows_the_predicted_moving_deck() {
    let generator = FlightPathGenerator::new(FlightPathParameters {
        deck_motion_predictor: DeckPredictorKind::FilterLead,
        ..Default::default()
    })
    .unwrap();
    // 5 s to go: fully compensated. Anchor = 23 + 1.0 s · 1 m/s = 24 m.
    let r = generator.reference(-300.0, 60.0, &deck(23.0, 1.0));
    assert_eq!(r.compensation_weight, 1.0);
    assert!((r.height_m - (24.0 + 300.0 * generator.tan_slope())).abs() < 1e-9);
    assert!((r.climb_rate_mps - (1.0 - 60.0 * generator.tan_slope())).abs() < 1e-12);
}

#[test]
fn blend_is_continuous_and_compensation_can_be_switched_off() {
    let generator = FlightPathGenerator::new(FlightPathParameters::default()).unwrap();
    // 11 s to go: half way through the 2 s blend.
    let r = generator.reference(-660.0, 60.0, &deck(24.0, 0.0));
    assert!((r.compensation_weight - 0.5).abs() < 1e-12);
    assert!((r.height_m - (22.0 + 660.0 * generator.tan_slope())).abs() < 1e-9);
    let off = FlightPathGenerator::new(FlightPathParameters {
        deck_motion_compensation: false,
        ..Default::default()
    })
    .unwrap();
    let r = off.reference(-100.0, 60.0, &deck(24.0, 1.0));
    assert_eq!(r.compensation_weight, 0.0);
    assert!((r.height_m - (20.0 + 100.0 * generator.tan_slope())).abs() < 1e-9);
}

#[test]
fn deck_filter_passes_slow_motion_and_settles_on_a_constant() {
    use crate::integration::{rk4_step, OdeSystem};
    struct Alone(DeckMotionFilter, f64);
    impl OdeSystem<2> for Alone {
        fn derivative(&self, t: f64, x: &[f64; 2]) -> [f64; 2] {
            self.0.derivative(*x, (self.1 * t).sin())
        }
    }
    // Input sin(0.1 t): a critically damped filter at 1 rad/s has gain
    // 1/(1 + 0.1²) = 0.990 there (|1/(1 + s)²| at s = 0.1i).
    let system = Alone(DeckMotionFilter::new(1.0), 0.1);
    let mut x = [0.0, 0.1];
    let mut peak: f64 = 0.0;
    for k in 0..200_000 {
        x = rk4_step(&system, k as f64 * 1e-3, &x, 1e-3);
        if k > 100_000 {
            peak = peak.max(x[0].abs());
        }
    }
    assert!((peak - 1.0 / 1.01).abs() < 2e-3, "{peak}");
}

/// The smooth blend w = 3s² − 2s³: at s = ¼ it is 0.15625 (by hand), and the reference's
/// rate has no step where the blend starts and ends (ẇ = 6s(1 − s)/T_blend is 0
/// there), unlike the linear blend, whose rate steps by offset/T_blend.
#[test]
fn the_smooth_blend_starts_and_ends_without_a_step_in_rate() {
    let smooth = FlightPathGenerator::new(FlightPathParameters::default()).unwrap();
    let linear = FlightPathGenerator::new(FlightPathParameters {
        compensation_blend: CompensationBlend::Linear,
        ..Default::default()
    })
    .unwrap();
    // 11.5 s to go at 60 m/s: a quarter of the 2-s blend from 12 s.
    let r = smooth.reference(-690.0, 60.0, &deck(24.0, 0.0));
    assert!((r.compensation_weight - 0.15625).abs() < 1e-12);
    let climb = |g: &FlightPathGenerator, time_to_go: f64| {
        g.reference(-60.0 * time_to_go, 60.0, &deck(24.0, 0.0))
            .climb_rate_mps
    };
    let glide = -60.0 * smooth.tan_slope();
    for edge in [12.0, 10.0] {
        for side in [-1e-6, 1e-6] {
            assert!((climb(&smooth, edge + side) - glide).abs() < 1e-4);
        }
    }
    // The linear blend's rate steps by (24 − 20)/2 = 2 m/s at its start.
    assert!((climb(&linear, 12.0 - 1e-6) - glide - 2.0).abs() < 1e-4);
    assert!((climb(&linear, 12.0 + 1e-6) - glide).abs() < 1e-9);
}

#[test]
fn invalid_slope_is_named() {
    let error = FlightPathGenerator::new(FlightPathParameters {
        glide_slope_deg: -3.0,
        ..Default::default()
    })
    .unwrap_err();
    assert!(error.to_string().contains("glide_slope_deg"));
}
