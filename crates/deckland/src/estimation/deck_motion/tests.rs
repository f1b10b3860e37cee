//! Tests of the deck-motion estimator (`deck_motion.rs`).

use super::*;
use crate::environment::{ShipMotionParameters, ShipMotionPropagator, ShipMotionSimulator};
use crate::random::RandomStreams;
use crate::sensors::ShipMotionSensor;

/// Steady-state a-posteriori covariances of the two channels at 50 Hz with the
/// default sensing, in the paper's sea (heave 2 m, pitch 1.5° RMS), diagonal only, in
/// filter units. Computed independently with `scipy.linalg.solve_discrete_are` on
/// the same model (`tests/reference/deck_motion_kalman.py`, which prints them).
const HEAVE_POSTERIOR_DIAGONAL: [f64; 4] =
    [3.3473845e-05, 1.7568108e-04, 2.3447115e-03, 1.8105740e-02];
const PITCH_POSTERIOR_DIAGONAL: [f64; 4] =
    [1.2119720e-03, 3.3924175e-07, 1.3916212e-08, 2.0238543e-07];

fn converged() -> DeckMotionEstimator {
    let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
    let mut estimator = DeckMotionEstimator::new(&ship, &ShipMotionSensingParameters::default());
    // 1000 s of measurements with arbitrary values (the covariance does not depend on
    // them): the pitch filter's z₁, the double integral of pitch, is observed only
    // through the dynamics and its variance settles slowly (within 1e-4 after about
    // 50 000 updates; the plain Riccati recursion in numpy does the same).
    for k in 1..=50_000 {
        estimator.update(&ShipMotionMeasurement {
            time_s: f64::from(k) * 0.02,
            ..ShipMotionMeasurement::default()
        });
    }
    estimator
}

#[test]
fn steady_state_covariance_matches_an_independent_riccati_solution() {
    let estimate = converged().estimate();
    for (name, covariance, reference) in [
        ("heave", estimate.heave_covariance, HEAVE_POSTERIOR_DIAGONAL),
        ("pitch", estimate.pitch_covariance, PITCH_POSTERIOR_DIAGONAL),
    ] {
        for i in 0..4 {
            let relative = covariance[i][i] / reference[i] - 1.0;
            assert!(
                relative.abs() < 1e-4,
                "{name} P[{i}][{i}] = {:e}, Riccati {:e}",
                covariance[i][i],
                reference[i]
            );
        }
    }
}

/// The doubling solution of the Riccati equation, taken one measurement update further
/// to the posterior, against scipy's `solve_discrete_are` (the same constants): to
/// the constants' eight digits, where the plain recursion gets to 1e-4 in 50 000
/// updates.
#[test]
fn the_doubling_solution_is_scipys_riccati_solution() {
    let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
    let filter = DeckMotionEstimator::new(&ship, &ShipMotionSensingParameters::default());
    for (name, channel, reference) in [
        ("heave", &filter.heave, HEAVE_POSTERIOR_DIAGONAL),
        ("pitch", &filter.pitch, PITCH_POSTERIOR_DIAGONAL),
    ] {
        let step = Transition::new(0.02, &channel.companion, &channel.stationary);
        let mut posterior = channel.clone();
        posterior.covariance = channel.steady_state_prior(&step).unwrap();
        posterior.update(Vector2::zeros());
        for (i, expected) in reference.iter().enumerate() {
            let relative = posterior.covariance[(i, i)] / expected - 1.0;
            assert!(
                relative.abs() < 2e-7,
                "{name} P[{i}][{i}] = {:e}, scipy {expected:e}",
                posterior.covariance[(i, i)],
            );
        }
    }
}

/// The converged start draws the estimate so that truth and estimate are jointly what
/// a long-running filter gives: over 4000 seeds the error z − ẑ has the steady-state
/// prior covariance (diagonal within 10 %, the sampling error of a variance over 4000
/// draws being 2.2 %) and is uncorrelated with the estimate (|ρ| < 0.1), which is the
/// orthogonality of a Kalman filter's error to its estimate.
#[test]
fn the_converged_start_has_the_steady_state_error() {
    let ship = ShipMotion::new(ShipMotionParameters::default()).unwrap();
    let sensing = ShipMotionSensingParameters::default();
    let n = 4000;
    let (mut errors, mut estimates) = (Vec::new(), Vec::new());
    let mut prior = None;
    for seed in 0..n {
        let streams = RandomStreams::new(seed);
        let truth = ship.stationary_initial_state(
            &mut streams.stream("test_heave"),
            &mut streams.stream("test_pitch"),
        );
        let filter = DeckMotionEstimator::converged(
            &ship,
            &sensing,
            &truth,
            &mut streams.stream("test_start"),
        );
        prior.get_or_insert(filter.pitch.covariance);
        let estimate = filter.estimate().mean;
        errors.push(std::array::from_fn::<f64, 4, _>(|i| {
            truth.pitch_filter[i] - estimate.pitch_filter[i]
        }));
        estimates.push(estimate.pitch_filter);
    }
    let prior = prior.unwrap();
    let mean = |v: &[[f64; 4]], i: usize| v.iter().map(|x| x[i]).sum::<f64>() / f64::from(n as u32);
    for i in 0..4 {
        let (me, mz) = (mean(&errors, i), mean(&estimates, i));
        let var_e = errors.iter().map(|x| (x[i] - me).powi(2)).sum::<f64>() / f64::from(n as u32);
        let var_z =
            estimates.iter().map(|x| (x[i] - mz).powi(2)).sum::<f64>() / f64::from(n as u32);
        let cov = errors
            .iter()
            .zip(&estimates)
            .map(|(e, z)| (e[i] - me) * (z[i] - mz))
            .sum::<f64>()
            / f64::from(n as u32);
        assert!(
            (var_e / prior[(i, i)] - 1.0).abs() < 0.1,
            "pitch z{}: error variance {var_e:e}, prior {:e}",
            i + 1,
            prior[(i, i)]
        );
        let rho = cov / (var_e * var_z).sqrt();
        assert!(rho.abs() < 0.1, "pitch z{}: correlation {rho}", i + 1);
    }
}

/// The filter's claimed error covariance must be its actual error: fly the ship for a
/// long time, measure it with the sensor, and compare the empirical mean square of
/// (estimate − truth) with the filter's own P, at the measurement times.
#[test]
fn actual_estimation_error_matches_the_filters_covariance() {
    let parameters = ShipMotionParameters::default();
    let sensing = ShipMotionSensingParameters {
        latency_s: 0.0,
        ..ShipMotionSensingParameters::default()
    };
    let streams = RandomStreams::new(5);
    let mut ship = ShipMotionSimulator::new(parameters, &streams, 0.0).unwrap();
    let mut sensor = ShipMotionSensor::new(sensing, &streams).unwrap();
    let mut estimator = DeckMotionEstimator::new(ship.model(), &sensing);
    let predictor = ShipMotionPropagator::new(ship.model(), 5.0);
    let dt = 0.002;
    // Errors of the heave (m) and pitch (rad) estimates, and of their 2-s predictions.
    let (mut heave, mut pitch, mut claimed_heave, mut claimed_pitch, mut n) =
        (0.0, 0.0, 0.0, 0.0, 0.0);
    let mut predictions = std::collections::VecDeque::new();
    let (mut predicted_error, mut predicted_claim, mut m) = (0.0, 0.0, 0.0);
    for k in 0..1_000_000_u32 {
        let t = f64::from(k) * dt;
        let truth = ship.outputs();
        while let Some((due, heave_predicted, claim)) = predictions.front().copied() {
            if due > t + 1e-9 {
                break;
            }
            predictions.pop_front();
            let error: f64 = heave_predicted - truth.heave_m;
            predicted_error += error * error;
            predicted_claim += claim;
            m += 1.0;
        }
        sensor.sample(t, &truth);
        while let Some(measurement) = sensor.receive(t) {
            estimator.update(&measurement);
            if t > 100.0 {
                let estimate = estimator.estimate();
                let now = predictor.forecast(ship.model(), &estimate, 0.0);
                heave += (now.heave_m - truth.heave_m).powi(2);
                pitch += (now.pitch_rad - truth.pitch_rad).powi(2);
                claimed_heave += now.heave_variance_m2;
                claimed_pitch += now.pitch_variance_rad2;
                n += 1.0;
                if k % 100 == 0 {
                    let ahead = predictor.forecast(ship.model(), &estimate, 2.0);
                    predictions.push_back((t + 2.0, ahead.heave_m, ahead.heave_variance_m2));
                }
            }
        }
        ship.step(dt);
    }
    // About 95 000 strongly correlated samples (the heave error's correlation time is
    // a few samples); the variance ratios are known to a few per cent.
    for (name, actual, claimed) in [
        ("heave", heave / n, claimed_heave / n),
        ("pitch", pitch / n, claimed_pitch / n),
        (
            "2-s heave prediction",
            predicted_error / m,
            predicted_claim / m,
        ),
    ] {
        assert!(
            (actual / claimed - 1.0).abs() < 0.1,
            "{name}: actual mean square {actual:e}, filter's variance {claimed:e}"
        );
    }
}
