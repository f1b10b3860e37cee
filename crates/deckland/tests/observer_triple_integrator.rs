//! The augmented observer on the textbook system it is designed for (paper Eq. 7–10):
//! ẇ1 = w2, ẇ2 = w3 + h(t), ẇ3 = η(t), y = w1 + n(t), with the known smooth
//! disturbance w3(t) = sin t + 0.5·cos 2t (so η = cos t − sin 2t) and known input
//! h(t) = 0.3·cos 0.7t. Plant and observer are integrated together with RK4 at 1 ms
//! (docs/model.md §6); the noise sample is drawn once per step and held over its stages.
//!
//! The error bounds below are the measured maxima after the transient (printed by the
//! tests with `--nocapture`) rounded up by a factor of about two; they are not from the
//! paper, which gives no observer-only results.

use deckland::estimation::{AugmentedObserver, ObserverParameters, ObserverState};
use deckland::integration::{rk4_step, OdeSystem};
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use rand_distr::{Distribution, Normal};

const DT: f64 = 1e-3;

struct PlantAndObserver {
    observer: AugmentedObserver,
    /// Measurement noise held over the step (rad).
    noise: f64,
}

fn known_input(t: f64) -> f64 {
    0.3 * (0.7 * t).cos()
}

fn disturbance(t: f64) -> f64 {
    t.sin() + 0.5 * (2.0 * t).cos()
}

impl OdeSystem<6> for PlantAndObserver {
    fn derivative(&self, t: f64, x: &[f64; 6]) -> [f64; 6] {
        let [w1, w2, w3, x1, x2, x3] = *x;
        let h = known_input(t);
        let estimate = ObserverState { x1, x2, x3 };
        let d = self.observer.derivative(&estimate, w1 + self.noise, h);
        [w2, w3 + h, t.cos() - (2.0 * t).sin(), d.x1, d.x2, d.x3]
    }
}

/// Largest and root-mean-square estimation errors |x_i − w_i| over t ∈ [settle_s, end_s].
fn errors(epsilon: f64, noise_sigma: f64, settle_s: f64, end_s: f64) -> ([f64; 3], [f64; 3]) {
    let parameters = ObserverParameters {
        epsilon,
        ..ObserverParameters::default()
    };
    let observer = AugmentedObserver::new(parameters).expect("valid parameters");
    let mut system = PlantAndObserver {
        observer,
        noise: 0.0,
    };
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let normal = Normal::new(0.0, noise_sigma).expect("valid sigma");
    // Plant starts away from the observer's zero initial estimate.
    let mut x = [0.1, -0.2, disturbance(0.0), 0.0, 0.0, 0.0];
    let mut max = [0.0_f64; 3];
    let mut sum_of_squares = [0.0_f64; 3];
    let mut count = 0.0;
    let steps = (end_s / DT).round() as usize;
    for k in 0..steps {
        let t = k as f64 * DT;
        system.noise = normal.sample(&mut rng);
        x = rk4_step(&system, t, &x, DT);
        assert!(x.iter().all(|v| v.is_finite()), "non-finite state at {t} s");
        if t + DT >= settle_s {
            count += 1.0;
            for i in 0..3 {
                let error = x[i + 3] - x[i];
                max[i] = max[i].max(error.abs());
                sum_of_squares[i] += error * error;
            }
        }
    }
    (max, sum_of_squares.map(|s| (s / count).sqrt()))
}

/// Largest estimation errors |x_i − w_i| over t ∈ [settle_s, end_s].
fn max_errors(epsilon: f64, noise_sigma: f64, settle_s: f64, end_s: f64) -> [f64; 3] {
    errors(epsilon, noise_sigma, settle_s, end_s).0
}

#[test]
fn estimates_converge_without_noise() {
    let errors = max_errors(0.03, 0.0, 2.0, 20.0);
    println!("epsilon 0.03, no noise: {errors:?}");
    assert!(errors[0] < 1e-5, "position error {}", errors[0]);
    assert!(errors[1] < 2e-3, "rate error {}", errors[1]);
    // 0.15 is 10 % of the disturbance's amplitude (1.5).
    assert!(errors[2] < 0.15, "disturbance error {}", errors[2]);
}

#[test]
fn error_bound_shrinks_with_epsilon() {
    let errors: Vec<[f64; 3]> = [0.05, 0.03, 0.01]
        .iter()
        .map(|&epsilon| max_errors(epsilon, 0.0, 2.0, 20.0))
        .collect();
    println!("epsilon 0.05, 0.03, 0.01: {errors:?}");
    for pair in errors.windows(2) {
        for (channel, (coarse, fine)) in pair[0].iter().zip(&pair[1]).enumerate() {
            assert!(
                *fine < 0.7 * coarse,
                "channel {} did not shrink: {errors:?}",
                channel + 1
            );
        }
    }
}

#[test]
fn estimates_stay_bounded_with_measurement_noise_and_noise_grows_as_epsilon_falls() {
    // σ = 0.001, the pitch-attitude noise of docs/model.md §3.3.
    // Measured (seed 7): rms disturbance error 0.12, 0.27, 0.73 rad/s² for ε = 0.05,
    // 0.03, 0.02: the bandwidth that shrinks the lag also passes more noise.
    let mut previous_rms = 0.0;
    for epsilon in [0.05, 0.03, 0.02] {
        let (max, rms) = errors(epsilon, 1e-3, 2.0, 20.0);
        println!("epsilon {epsilon}, sigma 1e-3: max {max:?}, rms {rms:?}");
        if epsilon == 0.03 {
            assert!(max[0] < 2.5e-3, "position error {}", max[0]);
            assert!(max[1] < 0.15, "rate error {}", max[1]);
            assert!(max[2] < 2.5, "disturbance error {}", max[2]);
        }
        assert!(
            rms[2] > previous_rms,
            "noise sensitivity should grow as ε falls"
        );
        previous_rms = rms[2];
    }
}
