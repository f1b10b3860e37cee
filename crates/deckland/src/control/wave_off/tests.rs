//! Tests of the wave-off decision (kept apart so that wave_off.rs stays short).
use super::heavy_sea::stationary_ramp_height_sigma_m;
use super::*;

fn calm() -> WaveOffInputs {
    WaveOffInputs {
        time_to_go_s: 4.0,
        glide_path_error_m: 0.0,
        glide_path_error_rate_mps: 0.0,
        // 3.5° path over a level deck: 60·tan 3.5° = 3.67 m over a ramp at 20 m.
        path_height_at_ramp_m: 23.67,
        hook_climb_rate_mps: -3.7,
        mean_landing_point_height_m: 20.0,
        ramp_clearance_sigma_m: 0.5,
        ramp_clearance_gain_m: 0.0,
        // The closed loop keeps the hook's sink of 3.7 m/s to touchdown.
        closed_loop_hook_sink_rate_mps: 3.7,
        forecast: DeckForecast::still(20.0, 20.0),
    }
}

#[test]
fn a_nominal_approach_on_a_level_deck_goes_on() {
    assert_eq!(WaveOffParameters::default().decide(&calm()), None);
}

#[test]
fn each_criterion_calls_the_wave_off_with_its_value() {
    // The fixed clearance limit in place of the ramp-strike probability.
    let p = WaveOffParameters {
        min_ramp_clearance_m: 1.5,
        max_ramp_strike_probability: 0.0,
        ..WaveOffParameters::default()
    };
    // The hook 2.8 m low: clearance 3.67 − 2.8 = 0.87 m < 1 m.
    let low = WaveOffInputs {
        glide_path_error_m: 2.8,
        ..calm()
    };
    let d = p.decide(&low).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::RampClearance);
    assert!((d.value - 0.87).abs() < 1e-9);
    // The deck rising at 3.5 m/s into a hook sinking at 3.7 m/s: 7.2 m/s > 7.
    let mut rising = calm();
    rising.forecast.landing_point_climb_rate_mps = 3.5;
    let d = p.decide(&rising).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::TouchdownSinkRate);
    assert!((d.value - 7.2).abs() < 1e-9);
    // 3.5 m high: clearance is fine, the error is not.
    let high = WaveOffInputs {
        glide_path_error_m: -3.5,
        ..calm()
    };
    assert_eq!(
        p.decide(&high).map(|d| d.criterion),
        Some(WaveOffCriterion::GlidePathError)
    );
    // Drifting high at 4.5 m/s.
    let drifting = WaveOffInputs {
        glide_path_error_m: -0.5,
        glide_path_error_rate_mps: -4.5,
        ..calm()
    };
    assert_eq!(
        p.decide(&drifting).map(|d| d.criterion),
        Some(WaveOffCriterion::GlidePathErrorRate)
    );
    // Bow up 4°: the deck pitch limit (the ramp drops, so clearance is fine).
    let mut pitched = calm();
    pitched.forecast.pitch_rad = 4.0_f64.to_radians();
    assert_eq!(
        p.decide(&pitched).map(|d| d.criterion),
        Some(WaveOffCriterion::DeckPitch)
    );
    let mut heaved = calm();
    heaved.forecast.landing_point_height_m = 14.0;
    heaved.forecast.ramp_height_m = 14.0;
    assert_eq!(
        p.decide(&heaved).map(|d| d.criterion),
        Some(WaveOffCriterion::LandingPointDisplacement)
    );
}

/// The probabilities by hand. Clearance 3.67 − 2.5 = 1.17 m with σ_c = 0.5 m:
/// Φ(−2.34) = 0.964 % (normal table) — above a 0.5 % limit, below 1 %. The deck
/// rising at 2.9 m/s into a hook sinking at 3.7 m/s: 6.6 m/s against 7.6 m/s, with
/// σ_s = √(0.75² + 1²) = 1.25 m/s: Φ(−0.8) = 21.19 %.
#[test]
fn the_probabilities_call_the_wave_off_with_their_value_in_percent() {
    let p = WaveOffParameters {
        max_ramp_strike_probability: 0.005,
        max_hard_landing_probability: 0.1,
        touchdown_sink_rate_sigma_mps: 1.0,
        ..WaveOffParameters::default()
    };
    let low = WaveOffInputs {
        glide_path_error_m: 2.5,
        ..calm()
    };
    let d = p.decide(&low).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::RampStrikeProbability);
    assert!((d.value - 0.964).abs() < 0.001, "{}", d.value);
    assert_eq!(d.limit, 0.5);
    let relaxed = WaveOffParameters {
        max_ramp_strike_probability: 0.01,
        ..p
    };
    assert_eq!(relaxed.decide(&low), None);
    let mut rising = calm();
    rising.forecast.landing_point_climb_rate_mps = 2.9;
    rising.forecast.landing_point_climb_rate_sigma_mps = 0.75;
    let d = p.decide(&rising).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::HardLandingProbability);
    assert!((d.value - 21.19).abs() < 0.01, "{}", d.value);
    assert_eq!(WaveOffParameters::default().decide(&rising), None);
}

/// The hard-landing probability on each model's sink, by hand: the hook sinking at
/// 3.7 m/s now and, as the guidance flies it, at 5.6 m/s at touchdown, into a deck
/// rising at 1.0 m/s (known: σ_ḣL = 0) with σ_sink = 1 m/s. `forecast`: 4.7 m/s,
/// Φ(−2.9) = 0.001866; `closed_loop`: 6.6 m/s, Φ(−1.0) = 0.158655 (normal table).
#[test]
fn the_hard_landing_probability_is_taken_on_its_models_sink() {
    let mut inputs = calm();
    inputs.closed_loop_hook_sink_rate_mps = 5.6;
    inputs.forecast.landing_point_climb_rate_mps = 1.0;
    let p = |hard_landing_model| {
        WaveOffParameters {
            hard_landing_model,
            touchdown_sink_rate_sigma_mps: 1.0,
            ..WaveOffParameters::default()
        }
        .commit_forecast(&inputs)
        .hard_landing_probability
    };
    assert!((p(HardLandingModel::Forecast) - 0.001866).abs() < 1e-6);
    assert!((p(HardLandingModel::ClosedLoop) - 0.158655).abs() < 1e-6);
    // A file that names neither key keeps the probability as it first came.
    let none = WaveOffParameters::named_by_none();
    assert_eq!(none.hard_landing_model, HardLandingModel::Forecast);
    assert_eq!(none.touchdown_sink_rate_sigma_mps, 1.0);
    assert_eq!(
        WaveOffParameters::paper().hard_landing_model,
        HardLandingModel::Forecast
    );
}

#[test]
fn outside_the_window_or_disabled_nothing_is_decided() {
    let low = WaveOffInputs {
        glide_path_error_m: 2.9,
        ..calm()
    };
    let p = WaveOffParameters {
        min_ramp_clearance_m: 1.5,
        ..WaveOffParameters::default()
    };
    for time_to_go_s in [6.0, 1.0] {
        assert_eq!(
            p.decide(&WaveOffInputs {
                time_to_go_s,
                ..low
            }),
            None
        );
    }
    assert_eq!(WaveOffParameters::paper().decide(&low), None);
}

#[test]
fn a_decision_point_after_the_window_is_refused_by_name() {
    let error = WaveOffParameters {
        decision_time_to_go_s: 5.0,
        ..WaveOffParameters::default()
    }
    .validate()
    .unwrap_err();
    assert_eq!(error.path, "control.wave_off.decision_time_to_go_s");
}

#[test]
fn the_late_abort_keys_outside_their_range_are_refused_by_name() {
    for (parameters, key) in [
        (
            WaveOffParameters {
                late_abort_ramp_strike_probability: 1.0,
                ..WaveOffParameters::default()
            },
            "control.wave_off.late_abort_ramp_strike_probability",
        ),
        (
            WaveOffParameters {
                late_abort_touchdown_sink_rate_mps: -1.0,
                ..WaveOffParameters::default()
            },
            "control.wave_off.late_abort_touchdown_sink_rate_mps",
        ),
        (
            WaveOffParameters {
                late_abort_rate_per_s: 0.0,
                ..WaveOffParameters::default()
            },
            "control.wave_off.late_abort_rate_per_s",
        ),
    ] {
        assert_eq!(parameters.validate().unwrap_err().path, key);
    }
}

/// The take-over's blend time: 0 (a step) and 2 s are accepted, −0.1 s and 2.5 s are
/// refused by name with their value.
#[test]
fn the_climb_blend_time_outside_its_range_is_refused_by_name() {
    for blend_s in [0.0, 0.4, 2.0] {
        let p = WaveOffParameters {
            climb_blend_s: blend_s,
            ..WaveOffParameters::default()
        };
        assert!(p.validate().is_ok(), "{blend_s}");
    }
    for blend_s in [-0.1, 2.5, f64::NAN] {
        let error = WaveOffParameters {
            climb_blend_s: blend_s,
            ..WaveOffParameters::default()
        }
        .validate()
        .unwrap_err();
        assert_eq!(error.path, "control.wave_off.climb_blend_s");
        assert_eq!(error.value, format!("{blend_s}"));
    }
}

/// The sea state by hand (docs/model.md §3.1's seas, ramp 81 + 60 = 141 m aft of the pitch
/// centre): √(1² + (141·0.75°)²) = √(1 + 1.8457²) = 2.0992 m (moderate), √(2² +
/// 3.6914²) = 4.1984 m (the paper's), √(3² + 6.1523²) = 6.8448 m (heavy); 0 with the
/// ship steady.
#[test]
fn the_stationary_ramp_sigma_matches_a_hand_calculation() {
    use crate::environment::{DeckGeometry, ShipMotionParameters};
    let deck = DeckGeometry::default();
    for (heave_m, pitch_deg, sigma_m) in [
        (1.0, 0.75, 2.099_18),
        (2.0, 1.5, 4.198_36),
        (3.0, 2.5, 6.844_75),
    ] {
        let ship = ShipMotionParameters {
            heave_rms_m: heave_m,
            pitch_rms_deg: pitch_deg,
            ..ShipMotionParameters::default()
        };
        let got = stationary_ramp_height_sigma_m(&ship, &deck);
        assert!((got - sigma_m).abs() < 1e-5, "{got} against {sigma_m}");
    }
    let steady = ShipMotionParameters {
        enabled: false,
        ..ShipMotionParameters::default()
    };
    assert_eq!(stationary_ramp_height_sigma_m(&steady, &deck), 0.0);
}

/// Heavy-sea limits 10 % (wave-off) and 5 % (late abort) against 20 % and 20 %, from
/// σ 4.5 m to 5.5 m: at 4.2 m (the paper's sea) the parameters are the same; at 5.0 m
/// half way, 15 % and 12.5 %; from 5.5 m the heavy limits. A criterion that is off
/// stays off, and without heavy-sea limits nothing changes in any sea.
#[test]
fn the_heavy_sea_limits_move_in_linearly_with_the_sea_state() {
    let p = WaveOffParameters {
        heavy_sea_ramp_strike_probability: 0.1,
        heavy_sea_late_abort_ramp_strike_probability: 0.05,
        heavy_sea_ramp_sigma_start_m: 4.5,
        heavy_sea_ramp_sigma_full_m: 5.5,
        ..WaveOffParameters::default()
    };
    assert_eq!(p.for_sea(4.2), p);
    assert_eq!(p.for_sea(4.5), p);
    let half = p.for_sea(5.0);
    assert!((half.max_ramp_strike_probability - 0.15).abs() < 1e-12);
    assert!((half.late_abort_ramp_strike_probability - 0.125).abs() < 1e-12);
    for sigma_m in [5.5, 6.84, 20.0] {
        let heavy = p.for_sea(sigma_m);
        assert_eq!(heavy.max_ramp_strike_probability, 0.1);
        assert_eq!(heavy.late_abort_ramp_strike_probability, 0.05);
        assert_eq!(
            heavy.max_touchdown_sink_rate_mps,
            p.max_touchdown_sink_rate_mps
        );
    }
    let off = WaveOffParameters {
        max_ramp_strike_probability: 0.0,
        ..p
    };
    assert_eq!(off.for_sea(6.84).max_ramp_strike_probability, 0.0);
    let ordinary = WaveOffParameters {
        heavy_sea_ramp_strike_probability: 0.0,
        heavy_sea_late_abort_ramp_strike_probability: 0.0,
        ..WaveOffParameters::default()
    };
    assert_eq!(ordinary.for_sea(6.84), ordinary);
    let step = WaveOffParameters {
        heavy_sea_ramp_sigma_start_m: 5.0,
        heavy_sea_ramp_sigma_full_m: 5.0,
        ..p
    };
    assert_eq!(step.for_sea(5.0), step);
    assert_eq!(step.for_sea(5.0 + 1e-9).max_ramp_strike_probability, 0.1);
}

/// Heavy-sea limits of 5 % for the wave-off and the late abort, as set for the paper's
/// sea (2.0 m, 1.5°) and for the heavy sea's ship (3.0 m, 2.5°) on the default deck: the
/// pair the heavy-sea tests here and in `late_abort.rs` compare.
pub(in crate::control) fn heavy_sea_limits_by_ship() -> (WaveOffParameters, WaveOffParameters) {
    use crate::environment::{DeckGeometry, ShipMotionParameters};
    let p = WaveOffParameters {
        heavy_sea_ramp_strike_probability: 0.05,
        heavy_sea_late_abort_ramp_strike_probability: 0.05,
        ..WaveOffParameters::default()
    };
    let deck = DeckGeometry::default();
    let papers = ShipMotionParameters::default();
    let heavy = ShipMotionParameters {
        heave_rms_m: 3.0,
        pitch_rms_deg: 2.5,
        ..papers
    };
    (p.for_ship(&papers, &deck), p.for_ship(&heavy, &deck))
}

/// The effect: the hook 2.0 m low on a 0.5-m σ_c, a predicted clearance of 1.67 m (as
/// in `the_probabilities_call_the_wave_off_with_their_value_in_percent`), Φ(−1.67/σ)
/// with σ = 1.2 m: Φ(−1.392) = 8.20 % (normal table). Below the ordinary 20 %, the paper's
/// sea goes on; with a heavy-sea limit of 5 % the heavy sea's ship (3.0 m, 2.5°) waves
/// off on it (its late abort: `late_abort.rs`).
#[test]
fn a_heavy_sea_waves_off_where_the_papers_sea_goes_on() {
    let (papers, heavy) = heavy_sea_limits_by_ship();
    let inputs = WaveOffInputs {
        glide_path_error_m: 2.0,
        ramp_clearance_sigma_m: 1.2,
        ..calm()
    };
    assert_eq!(papers.decide(&inputs), None);
    let d = heavy.decide(&inputs).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::RampStrikeProbability);
    assert!((d.value - 8.20).abs() < 0.01, "{}", d.value);
    assert_eq!(d.limit, 5.0);
}

/// Each heavy-sea key and the α floor's lead outside their ranges are refused by name
/// and value.
#[test]
fn the_heavy_sea_keys_outside_their_range_are_refused_by_name() {
    let p = WaveOffParameters::default();
    for (parameters, key, value) in [
        (
            WaveOffParameters {
                heavy_sea_ramp_strike_probability: 1.0,
                ..p
            },
            "control.wave_off.heavy_sea_ramp_strike_probability",
            "1.0",
        ),
        (
            WaveOffParameters {
                heavy_sea_late_abort_ramp_strike_probability: -0.1,
                ..p
            },
            "control.wave_off.heavy_sea_late_abort_ramp_strike_probability",
            "-0.1",
        ),
        (
            WaveOffParameters {
                heavy_sea_ramp_sigma_start_m: 51.0,
                ..p
            },
            "control.wave_off.heavy_sea_ramp_sigma_start_m",
            "51.0",
        ),
        (
            WaveOffParameters {
                heavy_sea_ramp_sigma_full_m: 4.0,
                ..p
            },
            "control.wave_off.heavy_sea_ramp_sigma_full_m",
            "4.0",
        ),
        (
            WaveOffParameters {
                max_commit_ramp_strike_probability: 1.5,
                ..p
            },
            "control.wave_off.max_commit_ramp_strike_probability",
            "1.5",
        ),
        (
            WaveOffParameters {
                commit_gate_ramp_sigma_start_m: -1.0,
                ..p
            },
            "control.wave_off.commit_gate_ramp_sigma_start_m",
            "-1.0",
        ),
        (
            WaveOffParameters {
                commit_gate_ramp_sigma_full_m: 3.0,
                ..p
            },
            "control.wave_off.commit_gate_ramp_sigma_full_m",
            "3.0",
        ),
        (
            WaveOffParameters {
                alpha_lead_s: 2.5,
                ..p
            },
            "control.wave_off.alpha_lead_s",
            "2.5",
        ),
    ] {
        let error = parameters.validate().unwrap_err();
        assert_eq!(error.path, key);
        assert_eq!(error.value, value);
    }
}

/// `calm()` at `time_to_go_s` with the deck forecast pitched `pitch_deg` and the landing
/// point moving at `climb_rate_mps`.
fn deck_moving(time_to_go_s: f64, pitch_deg: f64, climb_rate_mps: f64) -> WaveOffInputs {
    let mut inputs = calm();
    inputs.time_to_go_s = time_to_go_s;
    inputs.forecast.pitch_rad = pitch_deg.to_radians();
    inputs.forecast.landing_point_climb_rate_mps = climb_rate_mps;
    inputs
}

/// The recovery limits are the summary's numbers: 35 ft and 8 ft in metres, the lens's
/// angles.
#[test]
fn the_recovery_limits_are_35_ft_8_ft_in_4_s_and_the_lens_angles() {
    const FOOT_M: f64 = 0.3048;
    let limits = RecoveryLimits::default();
    assert!((limits.total_deck_motion_m - 35.0 * FOOT_M).abs() < 1e-12);
    assert!((limits.deck_motion_in_window_m - 8.0 * FOOT_M).abs() < 1e-12);
    assert_eq!(
        (limits.lens_pitch_limit_deg, limits.lens_roll_limit_deg),
        (1.62, 8.19)
    );
}

/// Far out, a deck forecast pitched beyond the lens's 1.62° fouls the deck; inside the
/// limits, in the wave-off window (where the ordinary criteria decide), before the check
/// starts, or with the check off, it does not.
#[test]
fn a_deck_beyond_the_lens_fouls_the_deck_only_far_out() {
    let on = WaveOffParameters {
        recovery: RecoveryLimits {
            foul_deck_time_to_go_s: 10.0,
            ..RecoveryLimits::default()
        },
        ..WaveOffParameters::default()
    };
    let decision = on
        .decide_foul_deck(&deck_moving(8.0, 2.0, 0.0))
        .expect("foul deck");
    assert_eq!(decision.criterion, WaveOffCriterion::FoulDeckMotion);
    assert!((decision.value - 100.0 * 2.0 / 1.62).abs() < 1e-9);
    assert_eq!(on.decide_foul_deck(&deck_moving(8.0, 1.5, 0.0)), None);
    assert_eq!(on.decide_foul_deck(&deck_moving(3.0, 2.0, 0.0)), None);
    assert_eq!(on.decide_foul_deck(&deck_moving(11.0, 2.0, 0.0)), None);
    let off = WaveOffParameters {
        recovery: RecoveryLimits::named_by_none(),
        ..on
    };
    assert_eq!(off.decide_foul_deck(&deck_moving(8.0, 2.0, 0.0)), None);
    // 0.7 m/s over 4 s is 2.8 m, beyond 8 ft.
    let moving = on
        .decide_foul_deck(&deck_moving(8.0, 0.0, -0.7))
        .expect("foul deck");
    assert!((moving.value - 100.0 * 2.8 / 2.4384).abs() < 1e-9);
}

/// The `stationary` model reads the motion in the window as β·ḣ (β set for the ship
/// flown) and checks the forecast roll against the lens's 8.19°; the `linear` model, the
/// check as it first came, reads ḣ·W and no roll. At ḣ = 0.7 m/s: ḣ·4 s = 2.8 m fouls
/// the deck, β·ḣ = 3.06 s · 0.7 m/s = 2.14 m does not; a forecast roll of 9° fouls it
/// only under `stationary`, at 100·9/8.19 %.
#[test]
fn the_stationary_model_reads_beta_and_roll_and_the_linear_neither() {
    use crate::control::FoulDeckModel;
    let stationary = WaveOffParameters {
        recovery: RecoveryLimits {
            foul_deck_time_to_go_s: 10.0,
            foul_deck_model: FoulDeckModel::Stationary,
            window_motion_per_rate_s: Some(3.06),
            ..RecoveryLimits::default()
        },
        ..WaveOffParameters::default()
    };
    let linear = WaveOffParameters {
        recovery: RecoveryLimits {
            foul_deck_model: FoulDeckModel::Linear,
            window_motion_per_rate_s: None,
            ..stationary.recovery
        },
        ..stationary
    };
    let moving = deck_moving(8.0, 0.0, 0.7);
    assert_eq!(stationary.decide_foul_deck(&moving), None);
    let share = stationary.recovery.largest_share_pct(&moving);
    assert!(
        (share - 100.0 * 3.06 * 0.7 / 2.4384).abs() < 1e-9,
        "{share}"
    );
    assert!(linear.decide_foul_deck(&moving).is_some());
    let mut rolled = deck_moving(8.0, 0.0, 0.0);
    rolled.forecast.roll_rad = 9.0_f64.to_radians();
    let decision = stationary.decide_foul_deck(&rolled).expect("foul deck");
    assert!((decision.value - 100.0 * 9.0 / 8.19).abs() < 1e-9);
    assert_eq!(linear.decide_foul_deck(&rolled), None);
}

/// The commit gate's limit in a sea (`commit_gate_in_sea`): none at and below the start
/// (3.2 m; the moderate sea at 2.10 m), the limit in full from 3.35 m (the paper's sea at
/// 4.20 m, the heavy sea at 6.84 m), p^w between (half way, 3.275 m: √(7·10⁻⁴) =
/// 0.026458), and none in any sea with the gate off. `in_sea` carries it with the
/// heavy-sea limits.
#[test]
fn the_commit_gate_moves_in_with_the_sea_state() {
    let p = WaveOffParameters::default();
    assert_eq!(p.max_commit_ramp_strike_probability, 7e-4);
    assert_eq!(p.commit_gate_in_sea(2.10), 0.0);
    assert_eq!(p.commit_gate_in_sea(3.2), 0.0);
    for sigma_m in [3.35, 4.20, 6.84] {
        assert!((p.commit_gate_in_sea(sigma_m) - 7e-4).abs() < 1e-15);
    }
    let half = p.commit_gate_in_sea(3.275);
    assert!((half - 0.026_457_513).abs() < 1e-8, "{half}");
    let off = WaveOffParameters::named_by_none();
    assert_eq!(off.commit_gate_in_sea(6.84), 0.0);
    assert_eq!(p.in_sea(2.10).max_commit_ramp_strike_probability, 0.0);
    let papers = p.in_sea(4.20);
    assert!((papers.max_commit_ramp_strike_probability - 7e-4).abs() < 1e-15);
    assert_eq!(
        papers.max_ramp_strike_probability,
        p.for_sea(4.20).max_ramp_strike_probability
    );
}

/// The gate's decision at the commit point: Φ(−3.2) = 6.871·10⁻⁴ (normal table) commits
/// under 7·10⁻⁴; Φ(−3.1) = 9.676·10⁻⁴ waves off on the ramp-strike probability, its
/// value and limit in percent; with the gate off, or the wave-off off, it commits.
#[test]
fn the_commit_gate_waves_off_above_its_limit() {
    let p = WaveOffParameters::default();
    let forecast = |clearance_m: f64| CommitForecast {
        ramp_strike_probability: ramp_strike_probability(clearance_m, 1.0),
        hard_landing_probability: 0.0,
        off_centre_probability: None,
        ramp_clearance_m: clearance_m,
        ramp_clearance_sigma_m: 1.0,
    };
    assert_eq!(p.decide_commit(&forecast(3.2)), None);
    let d = p.decide_commit(&forecast(3.1)).expect("wave-off");
    assert_eq!(d.criterion, WaveOffCriterion::RampStrikeProbability);
    assert!((d.value - 0.09676).abs() < 2e-5, "{}", d.value);
    assert!((d.limit - 0.07).abs() < 1e-12);
    assert_eq!(d.predicted_ramp_clearance_m, 3.1);
    let off = WaveOffParameters {
        max_commit_ramp_strike_probability: 0.0,
        ..p
    };
    assert_eq!(off.decide_commit(&forecast(0.0)), None);
    let disabled = WaveOffParameters {
        enabled: false,
        ..p
    };
    assert_eq!(disabled.decide_commit(&forecast(0.0)), None);
}
