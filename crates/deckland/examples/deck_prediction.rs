//! Prediction error of the landing point's height against horizon (docs/deck-prediction.md):
//! the Kalman estimator on the sensed ship motion, the oracle (the ship's true state), and
//! the physics floor (the oracle's own error variance, from the model). In the paper's sea
//! (the default) and a moderate sea (1.0 m, 0.75° RMS).
//!
//! `cargo run --release -p deckland --example deck_prediction [SECONDS]` (default 4000 s
//! of simulated ship motion per sea; the standard error of each σ is then about 3 %).

use std::collections::VecDeque;

use deckland::environment::{
    ShipMotionEstimate, ShipMotionParameters, ShipMotionPropagator, ShipMotionSimulator,
};
use deckland::estimation::DeckMotionEstimator;
use deckland::random::{stream_names, RandomStreams};
use deckland::sensors::{ShipMotionSensingParameters, ShipMotionSensor};

/// The landing point's lever arm aft of the pitch centre (m, docs/model.md §2.7).
const LANDING_ARM_M: f64 = 81.0;
/// Horizons (s).
const HORIZONS_S: [f64; 9] = [0.1, 0.25, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0];
/// Integration step of the ship (s) and the spacing of the predictions compared (s).
const STEP_S: f64 = 0.002;
const EVERY_S: f64 = 0.1;

/// A prediction waiting for its time: due time, horizon index, estimator's and oracle's
/// predicted height (m) and the estimator's claimed variance (m²).
type Pending = (f64, usize, f64, f64, f64);

/// Root-mean-square prediction error (m) of the estimator and the oracle, the estimator's
/// claimed σ and the physics floor σ, per horizon.
fn study(parameters: ShipMotionParameters, seconds: f64, seed: u64) -> Vec<[f64; 4]> {
    let sensing = ShipMotionSensingParameters::default();
    let streams = RandomStreams::new(seed);
    let mut ship = ShipMotionSimulator::new(parameters, &streams, 0.0).expect("valid sea");
    let mut sensor = ShipMotionSensor::new(sensing, &streams).expect("valid sensing");
    // Converged at the start, as in the closed loop (docs/model.md §3.5).
    let mut estimator = DeckMotionEstimator::converged(
        ship.model(),
        &sensing,
        ship.state(),
        &mut streams.stream(stream_names::SHIP_ESTIMATE_START),
    );
    let predictor = ShipMotionPropagator::new(ship.model(), HORIZONS_S[HORIZONS_S.len() - 1] + 1.0);
    let mut pending: VecDeque<Pending> = VecDeque::new();
    let mut sums = vec![[0.0; 4]; HORIZONS_S.len()];
    let mut counts = vec![0.0; HORIZONS_S.len()];
    let every = (EVERY_S / STEP_S).round() as u64;
    let steps = (seconds / STEP_S) as u64;
    for k in 0..steps {
        let t = k as f64 * STEP_S;
        let truth = ship.outputs();
        let height = truth.heave_m - LANDING_ARM_M * truth.pitch_rad.sin();
        while let Some(&(due, h, estimated, oracle, claimed)) = pending.front() {
            if due > t + 1e-9 {
                break;
            }
            pending.pop_front();
            sums[h][0] += (estimated - height).powi(2);
            sums[h][1] += (oracle - height).powi(2);
            sums[h][2] += claimed;
            counts[h] += 1.0;
        }
        sensor.sample(t, &truth);
        while let Some(measurement) = sensor.receive(t) {
            estimator.update(&measurement);
        }
        // After 100 s of convergence, predict from now, every EVERY_S.
        if t > 100.0 && k % every == 0 {
            let estimate = estimator.estimate();
            let age_s = t - estimator.time_s();
            let known = ShipMotionEstimate {
                mean: *ship.state(),
                ..ShipMotionEstimate::default()
            };
            for (h, horizon) in HORIZONS_S.iter().enumerate() {
                let ahead = predictor.forecast(ship.model(), &estimate, age_s + horizon);
                let oracle = predictor.forecast(ship.model(), &known, *horizon);
                pending.push_back((
                    t + horizon,
                    h,
                    ahead.deck_point_height_m(LANDING_ARM_M),
                    oracle.deck_point_height_m(LANDING_ARM_M),
                    ahead.deck_point_height_sigma_m(LANDING_ARM_M).powi(2),
                ));
            }
            pending
                .make_contiguous()
                .sort_by(|a, b| a.0.total_cmp(&b.0));
        }
        ship.step(STEP_S);
    }
    HORIZONS_S
        .iter()
        .enumerate()
        .map(|(h, horizon)| {
            let known = ShipMotionEstimate::default();
            let floor = predictor
                .forecast(ship.model(), &known, *horizon)
                .deck_point_height_sigma_m(LANDING_ARM_M);
            let n = counts[h];
            [
                (sums[h][0] / n).sqrt(),
                (sums[h][1] / n).sqrt(),
                (sums[h][2] / n).sqrt(),
                floor,
            ]
        })
        .collect()
}

fn main() {
    let seconds: f64 = std::env::args()
        .nth(1)
        .and_then(|a| a.parse().ok())
        .unwrap_or(4000.0);
    let tan_slope = 3.5_f64.to_radians().tan();
    for (name, heave_rms_m, pitch_rms_deg) in [
        ("the paper's sea (default)", 2.0, 1.5),
        ("moderate sea", 1.0, 0.75),
    ] {
        let parameters = ShipMotionParameters {
            heave_rms_m,
            pitch_rms_deg,
            ..ShipMotionParameters::default()
        };
        println!(
            "\n{name}: heave {heave_rms_m} m, pitch {pitch_rms_deg}° RMS; {seconds} s simulated"
        );
        println!("| horizon (s) | estimator σ (m) | estimator's own claim (m) | oracle σ (m) | physics floor (m) | estimator / oracle | touchdown-scatter equivalent, estimator (m) |");
        println!("|---|---|---|---|---|---|---|");
        for (horizon, [estimator, oracle, claimed, floor]) in
            HORIZONS_S.iter().zip(study(parameters, seconds, 7))
        {
            println!(
                "| {horizon} | {estimator:.3} | {claimed:.3} | {oracle:.3} | {floor:.3} | {:.3} | {:.1} |",
                estimator / oracle,
                estimator / tan_slope
            );
        }
    }
}
