//! Tests of the splitting: determinism, ties, replays, budgets and bad input.
use super::estimate::student_t_quantile;
use super::*;
use crate::rare::ornstein_uhlenbeck::{OuParams, OuTrajectory, B_1E4, B_1E7};

/// A ±1 random walk of `steps` steps: integer scores, so many ties.
#[derive(Clone)]
struct Walk {
    position: i32,
    left: u32,
    rng: ChaCha8Rng,
}

impl Trajectory for Walk {
    fn advance(&mut self) -> Advance {
        self.position += if self.rng.random::<bool>() { 1 } else { -1 };
        self.left -= 1;
        Advance {
            score: f64::from(self.position),
            ended: self.left == 0,
        }
    }
    fn reseed(&mut self, key: u64) {
        self.rng = ChaCha8Rng::seed_from_u64(key);
    }
    fn score(&self) -> f64 {
        f64::from(self.position)
    }
}

fn ou_start() -> OuTrajectory {
    OuTrajectory::new(&OuParams::reference(), 0)
}

/// Exact `P(max_{j≤n} S_j ≥ b) = P(S_n ≥ b) + P(S_n > b)` for the ±1
/// walk (b ≥ 1): the reflection principle (W. Feller, "An Introduction to Probability
/// Theory and Its Applications", vol. 1, 3rd ed., 1968, §III.7).
fn walk_reflection(steps: u32, b: i32) -> f64 {
    let mut choose = 1.0; // C(steps, ups), ups from 0 up
    let mut total = 0.0;
    for ups in 0..=steps {
        let end = 2 * ups as i32 - steps as i32;
        total += choose * (f64::from(u8::from(end >= b)) + f64::from(u8::from(end > b)));
        choose *= f64::from(steps - ups) / f64::from(ups + 1);
    }
    total / 2f64.powi(steps as i32)
}

#[test]
fn unbiased_with_ties() {
    let start = Walk {
        position: 0,
        left: 40,
        rng: ChaCha8Rng::seed_from_u64(0),
    };
    let truth = walk_reflection(40, 22);
    assert!((1e-4..1e-3).contains(&truth), "P = {truth:e}");
    for killed in [1, 3] {
        let settings = Settings {
            particles: 10,
            killed_per_iteration: killed,
            ..Settings::new(22.0)
        };
        let e = estimate(&start, &settings, 5, None, 4000, u64::MAX).expect("valid");
        let error = e.relative_standard_error.expect("two repetitions") * e.probability;
        let z = (e.probability - truth) / error;
        assert!(
            z.abs() <= 3.0,
            "k = {killed}: {:e} vs {truth:e}, z = {z:.2}",
            e.probability
        );
    }
}

#[test]
fn levels_rise_and_ties_are_killed_together() {
    let start = Walk {
        position: 0,
        left: 40,
        rng: ChaCha8Rng::seed_from_u64(0),
    };
    let settings = Settings {
        particles: 20,
        killed_per_iteration: 1,
        ..Settings::new(16.0)
    };
    let run = run(&start, &settings, 3, u64::MAX).expect("valid");
    assert!(
        run.levels.windows(2).all(|w| w[0] < w[1]),
        "{:?}",
        run.levels
    );
    assert!(run.killed.iter().any(|&k| k > 1), "integer scores must tie");
    assert_eq!(run.iterations as usize, run.levels.len());
    assert_eq!(
        run.trajectories,
        20 + run.killed.iter().sum::<usize>() as u64
    );
}

#[test]
fn checkpoint_spacing_does_not_change_the_run() {
    let start = ou_start();
    let runs: Vec<Run> = [1, 7, 10_000]
        .into_iter()
        .map(|checkpoint_every| {
            let settings = Settings {
                checkpoint_every,
                ..Settings::new(B_1E4)
            };
            run(&start, &settings, 11, u64::MAX).expect("valid")
        })
        .collect();
    for other in &runs[1..] {
        assert_eq!(other.estimate, runs[0].estimate);
        assert_eq!(other.levels, runs[0].levels);
        assert_eq!(other.events, runs[0].events);
    }
    // Replays cost steps: sparser checkpoints replay more.
    assert!(runs[0].steps < runs[1].steps && runs[1].steps < runs[2].steps);
}

#[test]
fn refly_reproduces_the_event_flights() {
    let start = ou_start();
    let settings = Settings::new(B_1E4);
    let run = run(&start, &settings, 21, u64::MAX).expect("valid");
    assert_eq!(run.outcome, Outcome::Converged);
    assert!(run.reached > 0 && run.reached == run.events.len());
    for event in &run.events {
        let mut max = f64::NEG_INFINITY;
        let mut steps = 0;
        let end = refly(&start, &event.lineage, settings.threshold, |s| {
            max = max.max(s.score());
            steps += 1;
        });
        assert_eq!(max.to_bits(), event.max.to_bits());
        assert!(end.score() >= settings.threshold);
        assert_eq!(steps, end.step() + 1, "observed the start and every step");
    }
}

#[test]
fn student_t_quantiles_match_references() {
    // ν = 1 and 2 have closed forms; ν = 5, 10, 30 from mpmath 1.3 at
    // 50 digits (they agree with the 3-decimal tables of the NIST/SEMATECH
    // e-Handbook of Statistical Methods, 2012, §1.3.6.7.2).
    let one = (0.475 * std::f64::consts::PI).tan();
    let two = 0.95 / (2.0 * 0.975 * 0.025_f64).sqrt();
    let cases = [
        (1.0, one),
        (2.0, two),
        (5.0, 2.5705818356363155),
        (10.0, 2.228138851986275),
        (30.0, 2.042272456301238),
    ];
    for (dof, want) in cases {
        let got = student_t_quantile(0.975, dof);
        assert!(
            ((got - want) / want).abs() < 1e-10,
            "ν = {dof}: {got} vs {want}"
        );
    }
    assert!((student_t_quantile(0.975, 1e6) - 1.959966).abs() < 1e-5);
}

#[test]
fn repetition_seeds_follow_splitmix64() {
    // First outputs of SplitMix64 from state 0 (S. Vigna's reference
    // implementation, splitmix64.c, 2015).
    assert_eq!(repetition_seed(0, 0), 0xE220_A839_7B1D_CDAF);
    assert_eq!(repetition_seed(0, 1), 0x6E78_9E6A_A1B9_65F4);
    assert_eq!(repetition_seed(0, 2), 0x06C4_5D18_8009_454F);
}

#[test]
fn same_seed_same_estimate_on_any_thread_count() {
    let start = ou_start();
    let settings = Settings::new(B_1E4);
    let on = |threads: usize, seed: u64| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("thread pool")
            .install(|| estimate(&start, &settings, seed, Some(0.1), 200, u64::MAX))
            .expect("valid")
    };
    let one = on(1, 9);
    let two = on(2, 9);
    assert_eq!(one, two);
    assert_eq!(one.probability.to_bits(), two.probability.to_bits());
    assert_eq!(format!("{one:?}"), format!("{:?}", on(2, 9)));
    let other = on(2, 10);
    assert_ne!(one.probability, other.probability);
    assert_ne!(one.steps, other.steps);
}

#[test]
fn bad_settings_are_named_errors() {
    let start = ou_start();
    let bad = |change: fn(&mut Settings)| {
        let mut settings = Settings::new(3.0);
        change(&mut settings);
        settings
    };
    let out_of_range = |killed| AmsError::KilledOutOfRange {
        killed,
        particles: 100,
    };
    let cases = [
        (
            bad(|s| s.particles = 1),
            AmsError::TooFewParticles(1),
            "particles = 1",
        ),
        (
            bad(|s| s.killed_per_iteration = 100),
            out_of_range(100),
            "killed_per_iteration = 100",
        ),
        (
            bad(|s| s.killed_per_iteration = 0),
            out_of_range(0),
            "killed_per_iteration = 0",
        ),
        (
            bad(|s| s.threshold = f64::INFINITY),
            AmsError::NonFiniteThreshold(f64::INFINITY),
            "threshold = inf",
        ),
        (
            bad(|s| s.checkpoint_every = 0),
            AmsError::ZeroCheckpointInterval,
            "checkpoint_every = 0",
        ),
        (
            bad(|s| s.max_iterations = 0),
            AmsError::ZeroMaxIterations,
            "max_iterations = 0",
        ),
    ];
    for (settings, want, text) in cases {
        let got = run(&start, &settings, 1, 1000).expect_err("invalid settings");
        assert_eq!(got, want);
        assert!(got.to_string().contains(text), "{got}");
        let got = estimate(&start, &settings, 1, None, 8, 1000).err();
        assert_eq!(got, Some(want));
    }
    let nan = bad(|s| s.threshold = f64::NAN).validate();
    assert!(matches!(nan, Err(AmsError::NonFiniteThreshold(t)) if t.is_nan()));
}

#[test]
fn bad_budgets_and_targets_are_named_errors() {
    let start = ou_start();
    let settings = Settings::new(3.0);
    assert_eq!(
        run(&start, &settings, 1, 0).err(),
        Some(AmsError::ZeroStepBudget)
    );
    let zero_budget = estimate(&start, &settings, 1, None, 8, 0).err();
    assert_eq!(zero_budget, Some(AmsError::ZeroStepBudget));
    let zero_reps = estimate(&start, &settings, 1, None, 0, 1000).err();
    assert_eq!(zero_reps, Some(AmsError::ZeroRepetitions));
    for target in [0.0, -0.1, f64::INFINITY] {
        let got = estimate(&start, &settings, 1, Some(target), 8, 1000).err();
        assert_eq!(got, Some(AmsError::BadTarget(target)));
    }
}

#[test]
fn unreachable_threshold_goes_extinct_with_the_reason() {
    let start = ou_start();
    let settings = Settings::new(1e9);
    let run = run(&start, &settings, 4, u64::MAX).expect("valid");
    let Outcome::Extinct { level } = run.outcome else {
        panic!("expected extinction, got {}", run.outcome);
    };
    assert_eq!(run.estimate, Some(0.0));
    assert_eq!(run.killed.last(), Some(&settings.particles));
    assert_eq!(run.levels.last(), Some(&level));
    assert!(run.outcome.to_string().contains("no particle passed level"));
    let e = estimate(&start, &settings, 4, Some(0.1), 16, u64::MAX).expect("valid");
    assert_eq!(e.probability, 0.0);
    assert_eq!(e.extinct_repetitions, 16);
    assert_eq!(e.relative_standard_error, None);
    assert_eq!(e.stop, Stop::MaxRepetitions);
}

#[test]
fn small_budgets_give_partial_results_with_the_reason() {
    let start = ou_start();
    let settings = Settings::new(B_1E7);
    let cut = run(&start, &settings, 4, 10_000).expect("valid");
    let budget = PartialReason::StepBudget { budget: 10_000 };
    assert_eq!(cut.outcome, Outcome::Partial(budget));
    assert_eq!(cut.estimate, None);
    let capped = Settings {
        max_iterations: 3,
        ..settings.clone()
    };
    let cut = run(&start, &capped, 4, u64::MAX).expect("valid");
    let limit = PartialReason::MaxIterations { limit: 3 };
    assert_eq!((cut.outcome, cut.iterations), (Outcome::Partial(limit), 3));
    let e = estimate(&start, &settings, 4, Some(0.01), 1000, 2_000_000).expect("valid");
    assert_eq!(e.stop, Stop::StepBudget);
    assert!(!e.target_met() && e.repetitions > 0 && e.partial_repetitions > 0);
    let none = estimate(&start, &settings, 4, None, 8, 10_000).err();
    let share = PartialReason::StepBudget { budget: 1_250 };
    assert_eq!(none, Some(AmsError::NoCompleteRepetition(share)));
    let none = estimate(&start, &capped, 4, None, 8, u64::MAX).err();
    assert_eq!(none, Some(AmsError::NoCompleteRepetition(limit)));
}
