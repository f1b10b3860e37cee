//! How well the deck's motion can be forecast: the landing point's height and vertical
//! velocity predicted T seconds ahead by the Kalman estimator on the sensed ship motion
//! and by the oracle (the ship's true state), against what then happens, over a long
//! simulated record of the ship alone (docs/model.md §3.5, §12).

use std::collections::VecDeque;

use crate::environment::{
    ShipMotion, ShipMotionEstimate, ShipMotionForecast, ShipMotionPropagator, ShipMotionSimulator,
};
use crate::estimation::DeckMotionEstimator;
use crate::random::{stream_names, RandomStreams};
use crate::sensors::{ShipMotionSensingParameters, ShipMotionSensor};

/// Integration step of the ship (s).
const STEP_S: f64 = 0.01;
/// Spacing of the forecasts compared (s).
const EVERY_S: f64 = 0.2;
/// Time the estimator runs before the first forecast is scored (s).
const SETTLE_S: f64 = 100.0;

/// One horizon's root-mean-square forecast errors of the deck point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ForecastError {
    /// The horizon T (s).
    pub horizon_s: f64,
    /// The estimator's height error (m).
    pub estimator_height_m: f64,
    /// The estimator's vertical-velocity error (m/s).
    pub estimator_climb_rate_mps: f64,
    /// The oracle's height error (m).
    pub oracle_height_m: f64,
    /// The oracle's vertical-velocity error (m/s).
    pub oracle_climb_rate_mps: f64,
}

/// The RMS of the deck point's height (m) and vertical velocity (m/s) over the record,
/// with the forecast errors at each horizon.
#[derive(Debug, Clone, PartialEq)]
pub struct ForecastStudy {
    /// RMS height of the deck point (m).
    pub height_rms_m: f64,
    /// RMS vertical velocity of the deck point (m/s).
    pub climb_rate_rms_mps: f64,
    /// The errors per horizon, in the order asked.
    pub errors: Vec<ForecastError>,
}

/// A forecast waiting for its time: due time, horizon index, and the estimator's and the
/// oracle's forecast height (m) and climb rate (m/s).
type Pending = (f64, usize, [f64; 4]);

/// The deck point's height (m) and climb rate (m/s) `lever_arm_m` aft of the pitch centre.
fn deck_point(
    lever_arm_m: f64,
    heave: f64,
    heave_rate: f64,
    pitch: f64,
    pitch_rate: f64,
) -> [f64; 2] {
    [
        heave - lever_arm_m * pitch.sin(),
        heave_rate - lever_arm_m * pitch.cos() * pitch_rate,
    ]
}

/// The forecasts waiting for their time and the squared errors of those scored.
struct Scores {
    pending: VecDeque<Pending>,
    sums: Vec<[f64; 4]>,
    counts: Vec<f64>,
}

impl Scores {
    fn new(horizons: usize) -> Self {
        Self {
            pending: VecDeque::new(),
            sums: vec![[0.0; 4]; horizons],
            counts: vec![0.0; horizons],
        }
    }

    /// Scores every forecast due by `t` against the truth (`height`, `rate`).
    fn score_due(&mut self, t: f64, [height, rate]: [f64; 2]) {
        while let Some(&(due, h, forecast)) = self.pending.front() {
            if due > t + 1e-9 {
                break;
            }
            self.pending.pop_front();
            for (sum, (value, truth)) in self.sums[h]
                .iter_mut()
                .zip(forecast.iter().zip([height, rate, height, rate]))
            {
                *sum += (value - truth).powi(2);
            }
            self.counts[h] += 1.0;
        }
    }

    /// The RMS errors per horizon.
    fn errors(&self, horizons_s: &[f64]) -> Vec<ForecastError> {
        horizons_s
            .iter()
            .enumerate()
            .map(|(h, &horizon_s)| {
                let rms = |i: usize| (self.sums[h][i] / self.counts[h].max(1.0)).sqrt();
                ForecastError {
                    horizon_s,
                    estimator_height_m: rms(0),
                    estimator_climb_rate_mps: rms(1),
                    oracle_height_m: rms(2),
                    oracle_climb_rate_mps: rms(3),
                }
            })
            .collect()
    }
}

/// Flies `ship` for `seconds` (s) from `seed`, sensed with `sensing`, and scores the
/// forecasts of the point `lever_arm_m` aft of the pitch centre at each of `horizons_s`
/// (module docs).
pub fn forecast_study(
    ship: ShipMotion,
    sensing: ShipMotionSensingParameters,
    lever_arm_m: f64,
    horizons_s: &[f64],
    seconds: f64,
    seed: u64,
) -> Result<ForecastStudy, crate::parameters::ParameterError> {
    let streams = RandomStreams::new(seed);
    let longest = horizons_s.iter().copied().fold(0.0, f64::max);
    let predictor = ShipMotionPropagator::new(&ship, longest + sensing.latency_s + 1.0);
    let mut ship = ShipMotionSimulator::with_model(ship, &streams, 0.0);
    let mut sensor = ShipMotionSensor::new(sensing, &streams)?;
    let mut estimator = DeckMotionEstimator::converged(
        ship.model(),
        &sensing,
        ship.state(),
        &mut streams.stream(stream_names::SHIP_ESTIMATE_START),
    );
    let point = |m: ShipMotionForecast| {
        deck_point(
            lever_arm_m,
            m.heave_m,
            m.heave_rate_mps,
            m.pitch_rad,
            m.pitch_rate_radps,
        )
    };
    let mut scores = Scores::new(horizons_s.len());
    let (mut squares, mut samples) = ([0.0_f64; 2], 0.0_f64);
    let every = (EVERY_S / STEP_S).round() as u64;
    for k in 0..(seconds / STEP_S) as u64 {
        let t = k as f64 * STEP_S;
        let truth = ship.outputs();
        let now = deck_point(
            lever_arm_m,
            truth.heave_m,
            truth.heave_rate_mps,
            truth.pitch_rad,
            truth.pitch_rate_radps,
        );
        scores.score_due(t, now);
        sensor.sample(t, &truth);
        while let Some(measurement) = sensor.receive(t) {
            estimator.update(&measurement);
        }
        if t > SETTLE_S && k % every == 0 {
            squares = [squares[0] + now[0] * now[0], squares[1] + now[1] * now[1]];
            samples += 1.0;
            let estimate = estimator.estimate();
            let age_s = t - estimator.time_s();
            let known = ShipMotionEstimate {
                mean: *ship.state(),
                ..ShipMotionEstimate::default()
            };
            for (h, &horizon) in horizons_s.iter().enumerate() {
                let [ah, ar] =
                    point(predictor.forecast_mean(ship.model(), &estimate, age_s + horizon));
                let [oh, or] = point(predictor.forecast_mean(ship.model(), &known, horizon));
                scores.pending.push_back((t + horizon, h, [ah, ar, oh, or]));
            }
            scores
                .pending
                .make_contiguous()
                .sort_by(|a, b| a.0.total_cmp(&b.0));
        }
        ship.step(STEP_S);
    }
    Ok(ForecastStudy {
        height_rms_m: (squares[0] / samples.max(1.0)).sqrt(),
        climb_rate_rms_mps: (squares[1] / samples.max(1.0)).sqrt(),
        errors: scores.errors(horizons_s),
    })
}
