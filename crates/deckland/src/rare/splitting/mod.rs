//! Generalised adaptive multilevel splitting (AMS) for the probability that
//! the running maximum of a trajectory's score reaches a threshold.
//!
//! The algorithm is the generalised AMS of C.-E. Bréhier, M. Gazeau,
//! L. Goudenège, T. Lelièvre & M. Rousset, "Unbiasedness of some
//! generalized adaptive multilevel splitting algorithms", Annals of Applied
//! Probability 26 (2016): at each iteration every particle whose maximum is
//! at or below the level is killed (ties included), and each is replaced by
//! a copy of a random survivor branched at the first step at which the
//! survivor's running maximum exceeds the level. Its estimator is unbiased
//! for any number of particles, also in discrete time where scores tie.
//!
//! [`run`] is one AMS run; [`estimate`] combines independent runs into an
//! estimate with a 95 % confidence interval.

use rand::{Rng, RngCore, SeedableRng};
use rand_chacha::ChaCha8Rng;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

/// One random trajectory that can be copied at any step and continued with fresh noise.
pub trait Trajectory: Clone + Send + Sync {
    /// Advances one step; returns the score after the step and whether the trajectory has ended (it stops on its own: landed, waved off, diverged, time up).
    fn advance(&mut self) -> Advance;
    /// Replaces the stream of every random input by a fresh one derived from `key`; the same state and key give the same continuation, bit for bit.
    fn reseed(&mut self, key: u64);
    /// The score at the current time.
    fn score(&self) -> f64;
}

/// What one step of a [`Trajectory`] returns.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Advance {
    /// The score after the step.
    pub score: f64,
    /// Whether the trajectory has ended on its own.
    pub ended: bool,
}

/// Settings of one AMS run.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Settings {
    /// Number of particles N (≥ 2); the relative variance of one run falls
    /// like 1/N. Default 100.
    pub particles: usize,
    /// Minimum number k of particles killed per iteration (1 ≤ k < N): the
    /// level is the k-th smallest maximum. Default 10 (N/10): on the
    /// Ornstein–Uhlenbeck case at p ≈ 1e-7 and 1e-4 (4000–6000 runs of
    /// N = 100 each), relative variance × steps was the same for k = 1 to
    /// 50 within the ±10 % noise of the measurement, while k = 10 needs
    /// 7–8 times fewer iterations than k = 1 (84 against 719 at 1e-4) and
    /// lets the ≥ 10 branches of an iteration run in parallel. k = 1 gives the lowest variance
    /// per run at a fixed N (Bréhier et al. 2016), not per step simulated.
    pub killed_per_iteration: usize,
    /// Steps between two stored copies of a particle (≥ 1), in steps; a
    /// branch replays at most this many steps. Default 10.
    pub checkpoint_every: usize,
    /// Guard on the number of iterations of one run. Default 100 000.
    pub max_iterations: u64,
    /// The rare event is "the running maximum of the score ≥ threshold", in
    /// units of the score.
    pub threshold: f64,
}

impl Settings {
    /// Default settings for the event "score ≥ `threshold`".
    pub fn new(threshold: f64) -> Self {
        Self {
            particles: 100,
            killed_per_iteration: 10,
            checkpoint_every: 10,
            max_iterations: 100_000,
            threshold,
        }
    }

    /// Checks every field; the error names the field and its value.
    pub fn validate(&self) -> Result<(), AmsError> {
        if self.particles < 2 {
            return Err(AmsError::TooFewParticles(self.particles));
        }
        if self.killed_per_iteration == 0 || self.killed_per_iteration >= self.particles {
            return Err(AmsError::KilledOutOfRange {
                killed: self.killed_per_iteration,
                particles: self.particles,
            });
        }
        if !self.threshold.is_finite() {
            return Err(AmsError::NonFiniteThreshold(self.threshold));
        }
        if self.checkpoint_every == 0 {
            return Err(AmsError::ZeroCheckpointInterval);
        }
        if self.max_iterations == 0 {
            return Err(AmsError::ZeroMaxIterations);
        }
        Ok(())
    }
}

/// Invalid input, or no result at all.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum AmsError {
    /// `particles` below 2.
    #[error("particles = {0}: at least 2 particles are needed")]
    TooFewParticles(usize),
    /// `killed_per_iteration` is 0 or not below `particles`.
    #[error(
        "killed_per_iteration = {killed}: must be at least 1 and below particles = {particles}"
    )]
    KilledOutOfRange {
        /// The value given.
        killed: usize,
        /// The number of particles.
        particles: usize,
    },
    /// `threshold` is NaN or infinite.
    #[error("threshold = {0}: must be finite")]
    NonFiniteThreshold(f64),
    /// `checkpoint_every` is 0.
    #[error("checkpoint_every = 0: must be at least 1 step")]
    ZeroCheckpointInterval,
    /// `max_iterations` is 0.
    #[error("max_iterations = 0: must be at least 1")]
    ZeroMaxIterations,
    /// The step budget is 0.
    #[error("max_steps = 0: the step budget must be at least 1 step")]
    ZeroStepBudget,
    /// `max_repetitions` is 0.
    #[error("max_repetitions = 0: must be at least 1")]
    ZeroRepetitions,
    /// `target_rel_error` is not a finite positive number.
    #[error("target_rel_error = {0}: must be finite and positive")]
    BadTarget(f64),
    /// A batch of repetitions flown elsewhere (a cluster's workers,
    /// [`estimate_batched`]) did not come back.
    #[error("a batch of repetitions failed: {0}")]
    Batch(String),
    /// Every repetition of [`estimate`] stopped early: there is no estimate.
    #[error("no repetition completed: {0}")]
    NoCompleteRepetition(PartialReason),
}

/// Why a run stopped before its end.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub enum PartialReason {
    /// The step budget (in steps) was spent.
    StepBudget {
        /// The budget, in steps.
        budget: u64,
    },
    /// `max_iterations` iterations were done.
    MaxIterations {
        /// The limit.
        limit: u64,
    },
}

impl std::fmt::Display for PartialReason {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::StepBudget { budget } => write!(f, "step budget of {budget} steps spent"),
            Self::MaxIterations { limit } => write!(f, "max_iterations = {limit} reached"),
        }
    }
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub enum Outcome {
    /// The level reached the threshold: the estimate is final.
    Converged,
    /// No particle passed level `level` (every maximum ≤ level): the
    /// estimate is 0, which is a valid outcome of the unbiased estimator.
    Extinct {
        /// The level that no particle passed.
        level: f64,
    },
    /// Stopped early: there is no estimate.
    Partial(PartialReason),
}

impl std::fmt::Display for Outcome {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Self::Converged => write!(f, "converged"),
            Self::Extinct { level } => write!(f, "extinct: no particle passed level {level}"),
            Self::Partial(reason) => write!(f, "partial: {reason}"),
        }
    }
}

/// A reseed on the way from the start state: advance to `step`, then
/// `reseed(key)`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct Branch {
    /// Steps from the start state.
    pub step: usize,
    /// The key given to [`Trajectory::reseed`].
    pub key: u64,
}

/// A final particle that reached the event, with what [`refly`] needs to
/// fly it again from the start state.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct EventParticle {
    /// Index among the final particles.
    pub index: usize,
    /// Its running maximum (≥ threshold).
    pub max: f64,
    /// Its genealogy: the reseeds from the start state, first `(0, key₀)`.
    pub lineage: Vec<Branch>,
}

/// The result of one AMS run.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Run {
    /// `Π_q (1 − K_q/N) · #{max ≥ threshold}/N`; `None` when partial.
    pub estimate: Option<f64>,
    /// How the run ended.
    pub outcome: Outcome,
    /// Number of iterations that killed particles.
    pub iterations: u64,
    /// Level `Z_q` of each iteration, in units of the score.
    pub levels: Vec<f64>,
    /// Number `K_q` of particles killed at each iteration.
    pub killed: Vec<usize>,
    /// Steps simulated, replays included.
    pub steps: u64,
    /// Trajectories started: N initial ones and one per branch.
    pub trajectories: u64,
    /// Final particles with maximum ≥ threshold.
    pub reached: usize,
    /// Those particles, each with its lineage for [`refly`].
    pub events: Vec<EventParticle>,
}

/// One particle: its own segment of trajectory and its inherited history.
struct Particle<T> {
    /// States at steps `offset`, `offset + c`, … (`[0]` is the branch state,
    /// already reseeded).
    checkpoints: Vec<T>,
    /// Step of the branch state, counted from the start state.
    offset: usize,
    /// Running maximum after each step from the start state (index 0: start).
    history: Vec<f64>,
    /// Final running maximum.
    max: f64,
    /// Reseeds from the start state.
    lineage: Vec<Branch>,
}

/// What simulation needs from the settings.
#[derive(Clone, Copy)]
struct Context {
    threshold: f64,
    checkpoint_every: usize,
}

/// Runs `state` (whose running maximum so far is `history`) until it ends
/// or reaches the threshold. Returns the particle and the steps taken.
fn grow<T: Trajectory>(
    mut state: T,
    mut history: Vec<f64>,
    mut max: f64,
    lineage: Vec<Branch>,
    terminal: bool,
    ctx: Context,
) -> (Particle<T>, u64) {
    let offset = history.len().saturating_sub(1);
    let mut checkpoints = vec![state.clone()];
    let mut taken = 0usize;
    let mut done = terminal || max >= ctx.threshold;
    while !done {
        if taken > 0 && taken.is_multiple_of(ctx.checkpoint_every) {
            checkpoints.push(state.clone());
        }
        let step = state.advance();
        taken += 1;
        max = max.max(step.score);
        history.push(max);
        done = step.ended || max >= ctx.threshold;
    }
    let particle = Particle {
        checkpoints,
        offset,
        history,
        max,
        lineage,
    };
    (particle, taken as u64)
}

/// A child of `parent` branched at the first step whose running maximum
/// exceeds `level`, reseeded with `key` and run to its end. Returns the child
/// and the steps taken (replay included).
fn branch<T: Trajectory>(
    parent: &Particle<T>,
    level: f64,
    key: u64,
    ctx: Context,
) -> (Particle<T>, u64) {
    let last = parent.history.len() - 1;
    // The history is non-decreasing; the inherited part lies at or below
    // earlier, lower levels, so the branch step is in the parent's own part.
    let at = parent
        .history
        .partition_point(|&m| m <= level)
        .clamp(parent.offset, last);
    let from = ((at - parent.offset) / ctx.checkpoint_every).min(parent.checkpoints.len() - 1);
    let mut state = parent.checkpoints[from].clone();
    let replay = at - parent.offset - from * ctx.checkpoint_every;
    for _ in 0..replay {
        state.advance();
    }
    state.reseed(key);
    let mut lineage = parent.lineage.clone();
    lineage.push(Branch { step: at, key });
    let mut history = Vec::with_capacity(parent.history.capacity());
    history.extend_from_slice(&parent.history[..=at]);
    // Branched at the parent's last step: it ended or was absorbed there.
    let (child, grown) = grow(state, history, parent.history[at], lineage, at == last, ctx);
    (child, grown + replay as u64)
}

/// Maps in parallel when there is more than one item, keeping the order.
fn par_map<I: Sync, O: Send>(items: &[I], f: impl Fn(&I) -> O + Sync + Send) -> Vec<O> {
    if items.len() > 1 {
        items.par_iter().map(f).collect()
    } else {
        items.iter().map(f).collect()
    }
}

/// The state of one run between iterations.
struct Swarm<T> {
    particles: Vec<Particle<T>>,
    rng: ChaCha8Rng,
    ctx: Context,
    weight: f64,
    levels: Vec<f64>,
    killed: Vec<usize>,
    steps: u64,
    trajectories: u64,
    /// Reused buffer for the maxima.
    scratch: Vec<f64>,
}

impl<T: Trajectory> Swarm<T> {
    /// N particles from `start`, each reseeded with its own key and run.
    fn new(start: &T, settings: &Settings, seed: u64) -> Self {
        let ctx = Context {
            threshold: settings.threshold,
            checkpoint_every: settings.checkpoint_every,
        };
        let mut rng = ChaCha8Rng::seed_from_u64(seed);
        let keys: Vec<u64> = (0..settings.particles).map(|_| rng.next_u64()).collect();
        let max = f64::NEG_INFINITY.max(start.score());
        let grown = par_map(&keys, |&key| {
            let mut state = start.clone();
            state.reseed(key);
            grow(
                state,
                vec![max],
                max,
                vec![Branch { step: 0, key }],
                false,
                ctx,
            )
        });
        let steps = grown.iter().map(|(_, s)| s).sum();
        Self {
            particles: grown.into_iter().map(|(p, _)| p).collect(),
            rng,
            ctx,
            weight: 1.0,
            levels: Vec::new(),
            killed: Vec::new(),
            steps,
            trajectories: keys.len() as u64,
            scratch: Vec::with_capacity(keys.len()),
        }
    }

    /// The k-th smallest maximum.
    fn level(&mut self, k: usize) -> f64 {
        self.scratch.clear();
        self.scratch.extend(self.particles.iter().map(|p| p.max));
        let (_, level, _) = self.scratch.select_nth_unstable_by(k - 1, f64::total_cmp);
        *level
    }

    /// Kills every particle with maximum ≤ `level` and branches replacements;
    /// returns `false` on extinction (nothing survives).
    fn iterate(&mut self, level: f64) -> bool {
        let n = self.particles.len();
        let (mut killed, mut survivors) = (Vec::new(), Vec::with_capacity(n));
        for (i, p) in self.particles.iter().enumerate() {
            if p.max <= level {
                killed.push(i);
            } else {
                survivors.push(i);
            }
        }
        self.levels.push(level);
        self.killed.push(killed.len());
        self.weight *= 1.0 - killed.len() as f64 / n as f64;
        if survivors.is_empty() {
            return false;
        }
        // All randomness is drawn here, in order, before any simulation.
        let plan: Vec<(usize, u64)> = killed
            .iter()
            .map(|_| {
                let parent = survivors[self.rng.random_range(0..survivors.len())];
                (parent, self.rng.next_u64())
            })
            .collect();
        let particles = &self.particles;
        let ctx = self.ctx;
        let children = par_map(&plan, |&(parent, key)| {
            branch(&particles[parent], level, key, ctx)
        });
        for (slot, (child, steps)) in killed.drain(..).zip(children) {
            self.particles[slot] = child;
            self.steps += steps;
            self.trajectories += 1;
        }
        true
    }

    /// The run's result.
    fn finish(self, outcome: Outcome) -> Run {
        let n = self.particles.len();
        let events: Vec<EventParticle> = self
            .particles
            .into_iter()
            .enumerate()
            .filter(|(_, p)| p.max >= self.ctx.threshold)
            .map(|(index, p)| EventParticle {
                index,
                max: p.max,
                lineage: p.lineage,
            })
            .collect();
        let estimate = match outcome {
            Outcome::Partial(_) => None,
            Outcome::Extinct { .. } => Some(0.0),
            Outcome::Converged => Some(self.weight * events.len() as f64 / n as f64),
        };
        Run {
            estimate,
            outcome,
            iterations: self.levels.len() as u64,
            levels: self.levels,
            killed: self.killed,
            steps: self.steps,
            trajectories: self.trajectories,
            reached: events.len(),
            events,
        }
    }
}

/// One AMS run from `start` for the event "running maximum of the score ≥
/// `settings.threshold`".
///
/// All randomness of the algorithm comes from a ChaCha8 stream seeded by
/// `seed`, so the result is bit-identical for any rayon thread count.
/// `max_steps` (in steps, replays included) is checked before each
/// iteration, so a run may exceed it by one iteration's branches; a run
/// stopped by it or by `max_iterations` has outcome [`Outcome::Partial`]
/// and no estimate.
pub fn run<T: Trajectory>(
    start: &T,
    settings: &Settings,
    seed: u64,
    max_steps: u64,
) -> Result<Run, AmsError> {
    settings.validate()?;
    if max_steps == 0 {
        return Err(AmsError::ZeroStepBudget);
    }
    let mut swarm = Swarm::new(start, settings, seed);
    let outcome = loop {
        if swarm.steps >= max_steps {
            break Outcome::Partial(PartialReason::StepBudget { budget: max_steps });
        }
        if swarm.levels.len() as u64 >= settings.max_iterations {
            break Outcome::Partial(PartialReason::MaxIterations {
                limit: settings.max_iterations,
            });
        }
        let level = swarm.level(settings.killed_per_iteration);
        if level >= settings.threshold {
            break Outcome::Converged;
        }
        if !swarm.iterate(level) {
            break Outcome::Extinct { level };
        }
    };
    Ok(swarm.finish(outcome))
}

/// Flies a particle again from `start` along its `lineage` (advance to each
/// branch step, reseed with its key) until it ends or its score reaches
/// `threshold`, calling `observe` on the start state and after every step.
/// Returns the final state.
///
/// Each segment is deterministic given its state and key, so this flight
/// is the particle's own, bit for bit, from the original start: attach a
/// recorder to `start` (or in `observe`) to record a whole event flight.
pub fn refly<T: Trajectory>(
    start: &T,
    lineage: &[Branch],
    threshold: f64,
    mut observe: impl FnMut(&T),
) -> T {
    let mut state = start.clone();
    observe(&state);
    let mut step = 0;
    let mut max = f64::NEG_INFINITY.max(state.score());
    let mut ended = false;
    let mut advance = |state: &mut T, max: &mut f64| {
        let next = state.advance();
        *max = max.max(next.score);
        observe(state);
        next.ended
    };
    for branch in lineage {
        while step < branch.step && !ended {
            ended = advance(&mut state, &mut max);
            step += 1;
        }
        state.reseed(branch.key);
    }
    while max < threshold && !ended {
        ended = advance(&mut state, &mut max);
    }
    state
}

mod estimate;

pub use estimate::{
    estimate, estimate_batched, estimate_observed, repetition_seed, Budget, Estimate, Stop,
    MIN_REPETITIONS_FOR_TARGET, REPETITIONS_PER_BATCH,
};

#[cfg(test)]
mod tests;
