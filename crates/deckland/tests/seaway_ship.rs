//! The carrier in a seaway as the loop flies it (docs/model.md §12): the `seaway` ship
//! model's heave and pitch against the hull's response spectrum, its forecast against the
//! paper's filter ship, and the scenario keys it refuses.

use deckland::analysis::forecast_study;
use deckland::environment::seaway::{motion_target, Motion, SeawayParameters};
use deckland::environment::{
    ship_motion, ShipModelKind, ShipMotionParameters, ShipMotionSimulator,
};
use deckland::random::RandomStreams;
use deckland::scenario::{load_scenario, ScenarioError};
use deckland::sensors::ShipMotionSensingParameters;

/// The ship of the `seaway` model in sea state `sea_state` (the table's H_s and T_p, head
/// seas, cos² spreading, 15 kn).
fn seaway_ship(sea_state: u8) -> (ShipMotionParameters, SeawayParameters) {
    let ship = ShipMotionParameters {
        model: ShipModelKind::Seaway,
        ..ShipMotionParameters::default()
    };
    let mut seaway = SeawayParameters::sea_state(sea_state).expect("in the table");
    // The hull steams at the ship's speed (the model sets it from forward_speed_mps).
    seaway.hull.speed_mps = ship.forward_speed_mps;
    (ship, seaway)
}

/// The motion target: over 16 seeds, the RMS of heave and pitch that the loop's
/// ship integrates (RK4, 10 ms, noise held over the step) is within 5 % of
/// √∫|H|²S dω_e, the hull's response to the wave spectrum integrated over the encounter
/// frequency (`motion_target`, computed from the spectrum and the closed-form transfer
/// functions, not from the fitted filters), in sea states 4 and 6.
#[test]
fn simulated_heave_and_pitch_rms_match_the_response_spectrum_over_16_seeds() {
    for sea_state in [4, 6] {
        let (ship, seaway) = seaway_ship(sea_state);
        let model = ship_motion(&ship, &seaway).expect("the seaway fits");
        let target = |motion| {
            motion_target(&seaway, motion)
                .expect("valid")
                .variance()
                .sqrt()
        };
        let (heave_target, pitch_target) = (target(Motion::Heave), target(Motion::Pitch));
        let (mut heave, mut pitch, mut n) = (0.0, 0.0, 0.0);
        for seed in 1..=16 {
            let mut simulator =
                ShipMotionSimulator::with_model(model.clone(), &RandomStreams::new(seed), 0.0);
            for k in 0..100_000 {
                if k % 10 == 0 {
                    let outputs = simulator.outputs();
                    heave += outputs.heave_m.powi(2);
                    pitch += outputs.pitch_rad.powi(2);
                    n += 1.0;
                }
                simulator.step(0.01);
            }
        }
        let (heave, pitch) = ((heave / n).sqrt(), (pitch / n).sqrt());
        assert!(
            (heave / heave_target - 1.0).abs() < 0.05,
            "sea state {sea_state}: heave RMS {heave} m against {heave_target} m"
        );
        assert!(
            (pitch / pitch_target - 1.0).abs() < 0.05,
            "sea state {sea_state}: pitch RMS {pitch} rad against {pitch_target} rad"
        );
    }
}

/// The forecast target: in sea state 5 the Kalman estimator's forecast of the
/// landing point's vertical velocity 2.5 s ahead errs by at most 35 % of that velocity's
/// RMS. The paper's filter ship, whose deck acceleration is white noise, leaves about
/// 73 % (the figure the issue measured with the project's deck-floor study): the test
/// checks the contrast, not only the bound.
#[test]
fn the_seaways_landing_point_is_forecast_2_5_s_ahead_and_the_papers_is_not() {
    let sensing = ShipMotionSensingParameters::default();
    let (ship, seaway) = seaway_ship(5);
    let study = |ship| {
        let study = forecast_study(ship, sensing, 81.0, &[2.5], 2000.0, 11).expect("valid");
        study.errors[0].estimator_climb_rate_mps / study.climb_rate_rms_mps
    };
    let seaway_error = study(ship_motion(&ship, &seaway).expect("fits"));
    let paper = ShipMotionParameters {
        model: ShipModelKind::Filters,
        ..ShipMotionParameters::default()
    };
    let paper_error = study(ship_motion(&paper, &seaway).expect("valid"));
    assert!(seaway_error <= 0.35, "sea state 5: {seaway_error}");
    assert!(
        (0.6..0.85).contains(&paper_error),
        "the paper's sea: {paper_error}"
    );
}

fn refusal(text: &str) -> String {
    match load_scenario(text, "sea.toml") {
        Err(error @ (ScenarioError::Structure { .. } | ScenarioError::OutOfRange { .. })) => {
            error.to_string()
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}

#[test]
fn a_file_naming_no_model_flies_the_filters_and_the_seaway_refuses_what_it_sets() {
    let old = load_scenario("[environment.ship]\nheave_rms_m = 1.0\n", "old.toml").expect("valid");
    assert_eq!(old.environment.ship.model, ShipModelKind::Filters);

    let written = refusal("[environment.ship]\nmodel = \"seaway\"\nheave_rms_m = 1.0\n");
    assert!(
        written.contains("environment.ship.heave_rms_m") && written.contains("line 3"),
        "{written}"
    );
    let following = refusal(
        "[environment.ship]\nmodel = \"seaway\"\n[environment.seaway]\nwave_heading_deg = 20.0\n",
    );
    assert!(
        following.contains("environment.seaway.wave_heading_deg"),
        "{following}"
    );
    let period = refusal("[environment.seaway]\npeak_period_s = 40.0\n");
    assert!(period.contains("peak_period_s"), "{period}");
    // A sea-state number from the table, alone: not 9, not beside the keys it sets.
    let numbered = load_scenario(
        "[environment.ship]\nmodel = \"seaway\"\n[environment.seaway]\nsea_state = 6\n",
        "six.toml",
    )
    .expect("valid");
    let six = SeawayParameters::sea_state(6).expect("in the table");
    assert_eq!(
        numbered
            .environment
            .seaway
            .resolved()
            .expect("in the table"),
        six
    );
    // Written out (a campaign's scenario.toml, a pickled Python scenario), it reads back.
    let written = toml::to_string(&numbered).expect("serialises");
    assert_eq!(load_scenario(&written, "written.toml"), Ok(numbered));
    let nine = refusal("[environment.seaway]\nsea_state = 9\n");
    assert!(nine.contains("environment.seaway.sea_state"), "{nine}");
    let both = refusal("[environment.seaway]\nsea_state = 5\npeak_period_s = 9.0\n");
    assert!(both.contains("environment.seaway.peak_period_s"), "{both}");
    let unknown = load_scenario("[environment.ship]\nmodel = \"swell\"\n", "s.toml")
        .expect_err("not a model");
    assert!(unknown.to_string().contains("model"), "{unknown}");
}

/// The seaway's RMS scale with H_s at a fixed spectral shape (linear waves): the model
/// memoises its fit at 1 m, so this checks the scaling against a fresh fit too.
#[test]
fn the_seaways_rms_is_linear_in_the_wave_height() {
    let (ship, seaway) = seaway_ship(5);
    let base = ship_motion(&ship, &seaway).expect("fits");
    let doubled = ship_motion(
        &ship,
        &SeawayParameters {
            significant_wave_height_m: 2.0 * seaway.significant_wave_height_m,
            ..seaway
        },
    )
    .expect("fits");
    let (b, d) = (base.parameters(), doubled.parameters());
    assert!((d.heave_rms_m / b.heave_rms_m - 2.0).abs() < 1e-12);
    assert!((d.pitch_rms_deg / b.pitch_rms_deg - 2.0).abs() < 1e-12);
    let target = motion_target(&seaway, Motion::Heave)
        .expect("valid")
        .variance()
        .sqrt();
    assert!(
        (b.heave_rms_m / target - 1.0).abs() < 1e-6,
        "{} {target}",
        b.heave_rms_m
    );
}
