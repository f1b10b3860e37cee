//! Issue 45, item 1: each approach keeps what the forecast gave at its commit point
//! (`RunSummary::commit_forecast`): the probabilities of a ramp strike, a hard landing
//! and, on the 3-D approach, an off-centre touchdown, at the first step with the time to
//! go at or below `decision_time_to_go_s`, the approach not waving off by then.
//!
//! The ramp strike's and the hard landing's are checked against a recomputation, step by
//! step, from the run's state (the hook where the guidance computer sees it, from the
//! longitudinal state and the hook's geometry), the glide path, its anchor and the deck
//! forecast held over the step (`Simulation::next_step_inputs`, which changes nothing of
//! the run), with Φ by quadrature: the recorded time series (`approach.csv`) alone cannot
//! give them, since it holds neither the forecast ramp height, the ramp's and the landing
//! point's predicted climb rates nor their σ, and its hook (the 6-DOF's, with its whole
//! attitude) differs a little from the one the guidance computer reads (2.5·10⁻⁴ of the probability in the
//! paper's sea). The off-centre probability is checked for presence and range only: the
//! lineup prediction it rests on (the lineup loop's response, the ship's lateral
//! measurement, the floor's σ) is internal to the lateral guidance and in no signal.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::control::{CommitForecast, RampStrikeModel};
use deckland::recording::SummaryRecorder;
use deckland::scenario::Scenario;
use deckland::simulation::{OuterLoops, Recorder, RunSummary, Simulation, Stop};

struct Nothing;
impl Recorder for Nothing {}

/// Φ(x) by Simpson's rule over [x − 12, x] of the normal density (for x ≤ 0; by symmetry
/// above), 24 000 intervals: relative error far below 10⁻⁹, independent of the library's
/// fit of erfc.
fn normal_cdf(x: f64) -> f64 {
    if x > 0.0 {
        return 1.0 - normal_cdf(-x);
    }
    let n = 24_000;
    let (a, h) = (x - 12.0, 12.0 / f64::from(n));
    let density = |t: f64| (-0.5 * t * t).exp() / (2.0 * std::f64::consts::PI).sqrt();
    let inner: f64 = (1..n)
        .map(|k| density(a + f64::from(k) * h) * if k % 2 == 1 { 4.0 } else { 2.0 })
        .sum();
    h / 3.0 * (density(a) + inner + density(x))
}

/// The commit point's probabilities of a ramp strike and a hard landing, worked out
/// afresh at the first step whose time to go (the glide path's, for the hook of the
/// longitudinal state) is at or below the decision point's, before any wave-off: the
/// predicted clearance from the path's height at the mean ramp, the hook's error to it
/// and the forecast ramp, its σ from the forecast's and the flight path's σ; the
/// predicted sink rate relative to the deck; then the clearance and its σ. Also the
/// summary of the run, flown step by step to the end.
#[allow(clippy::type_complexity)]
fn recomputed(scenario: &Scenario) -> (Option<(f64, f64, f64, f64)>, RunSummary) {
    let mut simulation = Simulation::new(scenario).unwrap();
    let wave_off = scenario.control.wave_off;
    let mut found = None;
    loop {
        let held = simulation.next_step_inputs();
        let system = simulation.system();
        let OuterLoops::Approach { flight_path, .. } = system.outer_loops() else {
            panic!("an approach");
        };
        // The hook as the guidance computer sees it: the longitudinal state's.
        let aircraft = system.aircraft_state(simulation.state());
        let (hook_x_m, hook_h_m) = scenario.aircraft.hook.position(&aircraft);
        let (hook_x_rate_mps, hook_climb_rate_mps) = scenario.aircraft.hook.velocity(&aircraft);
        let deck = held.deck.unwrap();
        let path = flight_path.reference(hook_x_m, hook_x_rate_mps, &deck);
        let committed = path.time_to_go_s <= wave_off.decision_time_to_go_s;
        if found.is_none() && committed && simulation.wave_off_decision().is_none() {
            let parameters = flight_path.parameters();
            let forecast = deck.forecast.unwrap();
            let ramp_x_m = deck.mean_aim.x_m - system.deck().ramp_aft_of_aim_point_m;
            let path_at_ramp_m = path.height_m - (ramp_x_m - hook_x_m) * flight_path.tan_slope();
            let clearance_m = path_at_ramp_m - (path.height_m - hook_h_m) - forecast.ramp_height_m;
            // The closed loop (docs/model.md §9): the anchor filter's free response over
            // the time to the crossing, towards the anchor it is given now.
            let closure_mps = hook_x_rate_mps - deck.mean_aim_velocity.x_mps;
            let ramp_time_s =
                (path.time_to_go_s - system.deck().ramp_aft_of_aim_point_m / closure_mps).max(0.0);
            let target_m = deck.unfiltered_aim_h_m.unwrap();
            let omega = parameters.anchor_filter_frequency_radps;
            let e0 = deck.aim.h_m - target_m;
            let moved_m = -e0
                + (e0 + (deck.aim_velocity.h_mps + omega * e0) * ramp_time_s)
                    * (-omega * ramp_time_s).exp();
            let closed_loop = wave_off.ramp_strike_model.is_closed_loop();
            // With direct lift (`closed_loop_lift`): the hook flies to the path on the
            // unfiltered anchor, leaving its loop's free response at the crossing.
            let sea_sigma_m = scenario
                .environment
                .resolved_ship()
                .unwrap()
                .deck_point_height_rms_m(system.deck().landing_point_aft_of_pitch_centre_m);
            let aircraft = &scenario.aircraft.parameters;
            let q_pa = 0.5 * aircraft.air_density_kg_m3 * scenario.approach.airspeed_mps.powi(2);
            let lift = (scenario.control.direct_lift)
                .for_sea(sea_sigma_m)
                .lift_loop(q_pa * aircraft.wing_area_m2 / aircraft.mass_kg)
                .unwrap();
            let clearance_m = match wave_off.ramp_strike_model {
                RampStrikeModel::ClosedLoopLift => {
                    let w = path.compensation_weight;
                    let error_m = path.height_m - hook_h_m + w * (target_m - deck.aim.h_m);
                    let rate_mps = path.climb_rate_mps - hook_climb_rate_mps;
                    clearance_m + error_m - lift.free_response(error_m, rate_mps, ramp_time_s)
                }
                _ if closed_loop => clearance_m + path.compensation_weight * moved_m,
                _ => clearance_m,
            };
            // What the path follows of the ramp's later forecast updates, on the ramp
            // floor only: 2w·∫g dσ² − w²·∫g² dσ².
            let [first, second] = forecast.ramp_update_response_m2;
            let w = path.compensation_weight;
            let followed = 2.0 * w * first - w * w * second;
            assert!(followed >= 0.0 && followed <= forecast.ramp_height_sigma_m.powi(2));
            // Off the floor, the anchor model's: what the path follows of the landing
            // point's updates, 2w·∫g dC − w²·∫g² dσ_L², at most σ_r².
            let [cross, landing] = forecast.landing_point_update_response_m2;
            let anchor = wave_off.ramp_strike_model.follows_landing_point();
            let followed = if closed_loop && target_m > forecast.landing_point_height_m {
                followed
            } else if anchor {
                (2.0 * w * cross - w * w * landing).min(forecast.ramp_height_sigma_m.powi(2))
            } else {
                0.0
            };
            let timing = forecast.ramp_climb_rate_mps * parameters.ramp_crossing_time_sigma_s;
            let sigma_c = (forecast.ramp_height_sigma_m.powi(2) - followed
                + parameters.hook_height_sigma_m.powi(2)
                + timing * timing)
                .sqrt();
            let sink = -hook_climb_rate_mps + forecast.landing_point_climb_rate_mps;
            let sigma_sink = forecast
                .landing_point_climb_rate_sigma_mps
                .hypot(wave_off.touchdown_sink_rate_sigma_mps);
            found = Some((
                normal_cdf(-clearance_m / sigma_c),
                normal_cdf((sink - wave_off.hard_landing_sink_rate_mps) / sigma_sink),
                clearance_m,
                sigma_c,
            ));
        }
        if matches!(simulation.step(&mut Nothing), Stop::Ended(_)) {
            return (found, simulation.summary().unwrap().clone());
        }
    }
}

/// `got` and `want` agree to a millionth of their size (the library's Φ is good to
/// 1.2·10⁻⁷ of its value).
fn assert_close(what: &str, got: f64, want: f64) {
    assert!(
        (got - want).abs() <= 1e-6 * want.abs() + 1e-300,
        "{what}: {got:e} against {want:e} recomputed"
    );
}

/// The paper's sea on the 3-DOF approach at `seed`, and its flight's summary.
fn papers_sea_3dof(seed: u64) -> (Scenario, RunSummary) {
    let scenario = Scenario {
        seed,
        ..Scenario::papers_sea().longitudinal()
    };
    let summary = Simulation::new(&scenario)
        .unwrap()
        .run(&mut SummaryRecorder);
    (scenario, summary)
}

fn in_unit_interval(p: f64) -> bool {
    (0.0..=1.0).contains(&p)
}

/// The paper's sea (`scenarios/paper-adverse.toml`'s filter ship) on the realistic
/// default (the 3-D approach, the wave-off on): every run that reached the commit point
/// has probabilities in [0, 1], its off-centre probability too, and its ramp strike's
/// and hard landing's are the recomputed ones; flown step by step with the inputs drawn
/// early, the run is the one flown straight through.
#[test]
fn in_the_papers_sea_the_commit_forecast_is_the_recomputed_one() {
    let mut reached = 0;
    let models = [
        RampStrikeModel::ClosedLoopLift,
        RampStrikeModel::ClosedLoopAnchor,
        RampStrikeModel::ClosedLoop,
        RampStrikeModel::Forecast,
    ];
    for (seed, model) in (1..=5).flat_map(|seed| models.map(|model| (seed, model))) {
        let mut scenario = Scenario {
            seed,
            ..Scenario::papers_sea()
        };
        scenario.control.wave_off.ramp_strike_model = model;
        let (recomputed, summary) = recomputed(&scenario);
        let straight = Simulation::new(&scenario)
            .unwrap()
            .run(&mut SummaryRecorder);
        assert_eq!(
            summary, straight,
            "seed {seed}: drawing early changed the run"
        );
        match (summary.commit_forecast, recomputed) {
            (None, None) => {}
            (Some(forecast), Some((ramp, hard, clearance_m, sigma_m))) => {
                reached += 1;
                let CommitForecast {
                    ramp_strike_probability,
                    hard_landing_probability,
                    off_centre_probability,
                    ramp_clearance_m,
                    ramp_clearance_sigma_m,
                } = forecast;
                let off_centre = off_centre_probability.expect("a 3-D approach's");
                for p in [
                    ramp_strike_probability,
                    hard_landing_probability,
                    off_centre,
                ] {
                    assert!(in_unit_interval(p), "seed {seed}: {forecast:?}");
                }
                assert_close(&format!("seed {seed} ramp"), ramp_strike_probability, ramp);
                assert_close(&format!("seed {seed} hard"), hard_landing_probability, hard);
                assert_close(&format!("seed {seed} c"), ramp_clearance_m, clearance_m);
                assert_close(&format!("seed {seed} σ_c"), ramp_clearance_sigma_m, sigma_m);
            }
            other => panic!("seed {seed}: recorded and recomputed disagree: {other:?}"),
        }
    }
    assert!(
        reached >= 3,
        "only {reached} of 10 flights reached the commit point"
    );
}

/// A longitudinal approach (the 3-DOF aircraft) has no off-centre probability; a
/// scenario without the wave-off (the paper's set) none at all; and an approach that
/// waves off before the commit point (a ramp-strike limit of 10⁻³⁰⁰, which any forecast
/// exceeds as the window opens) never reaches it.
#[test]
fn only_an_approach_that_reaches_the_commit_point_with_a_forecast_has_one() {
    let longitudinal: Vec<CommitForecast> = (1..=6)
        .filter_map(|seed| papers_sea_3dof(seed).1.commit_forecast)
        .collect();
    assert!(
        !longitudinal.is_empty(),
        "no 3-DOF run reached the commit point"
    );
    for forecast in longitudinal {
        assert_eq!(forecast.off_centre_probability, None);
        assert!(in_unit_interval(forecast.ramp_strike_probability));
        assert!(in_unit_interval(forecast.hard_landing_probability));
    }
    let path = format!(
        "{}/../../scenarios/paper-adverse.toml",
        env!("CARGO_MANIFEST_DIR")
    );
    let paper = deckland::scenario::load_scenario(&std::fs::read_to_string(path).unwrap(), "paper")
        .unwrap();
    assert!(!paper.control.wave_off.enabled);
    let summary = Simulation::new(&paper).unwrap().run(&mut SummaryRecorder);
    assert_eq!(summary.commit_forecast, None);
    let mut early = Scenario {
        seed: 2,
        ..Scenario::papers_sea()
    };
    early.control.wave_off.max_ramp_strike_probability = 1e-300;
    let summary = Simulation::new(&early).unwrap().run(&mut SummaryRecorder);
    assert_eq!(summary.outcome.name(), "wave_off", "{:?}", summary.reason);
    assert_eq!(summary.commit_forecast, None);
}

/// The commit gate (`control.wave_off.max_commit_ramp_strike_probability`, docs/model.md
/// §9) acts at the commit point on the probability recorded there, and only above its
/// limit: in the paper's sea (4.20 m, beyond the gate's band, so the limit holds in
/// full), an approach committed at probability p with the gate off flies the same to the
/// bit with the gate at 1.001·p, and waves off on the ramp-strike probability at the
/// commit point, with no commit forecast, with the gate at 0.999·p.
#[test]
fn the_commit_gate_waves_off_exactly_above_its_limit() {
    let mut gated = 0;
    for seed in 1..=6 {
        let (scenario, free) = papers_sea_3dof(seed);
        let Some(committed) = free.commit_forecast else {
            continue;
        };
        let p = committed.ramp_strike_probability;
        let with_gate = |limit: f64| {
            let mut gate = scenario;
            gate.control.wave_off.max_commit_ramp_strike_probability = limit;
            Simulation::new(&gate).unwrap().run(&mut SummaryRecorder)
        };
        let above = with_gate(1.001 * p);
        assert_eq!(above.commit_forecast, free.commit_forecast, "seed {seed}");
        assert_eq!(above.outcome.name(), free.outcome.name(), "seed {seed}");
        assert_eq!(above.end_time_s, free.end_time_s, "seed {seed}");
        assert_eq!(above.touchdown, free.touchdown, "seed {seed}");
        let below = with_gate(0.999 * p);
        assert_eq!(below.outcome.name(), "wave_off", "seed {seed}");
        assert_eq!(below.commit_forecast, None, "seed {seed}");
        let reason = below.reason.unwrap_or_default();
        assert!(
            reason.contains("ramp_strike_probability"),
            "seed {seed}: {reason}"
        );
        gated += 1;
    }
    assert!(
        gated >= 2,
        "only {gated} of 6 runs reached the commit point"
    );
}
