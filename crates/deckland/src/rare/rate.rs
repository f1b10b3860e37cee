//! The rate of a catastrophe per approach of a scenario, by splitting (`deckland rare`,
//! Python's `deckland.rare`): [`estimate_rate`]; with the repetitions flown elsewhere
//! (Dask's workers), [`estimate_rate_batched`] and [`fly_repetition`].

use serde::Serialize;

use std::sync::Arc;

use super::flight::{ApproachFlight, FlightError};
use super::ramp_calibration::RampCalibration;
use super::score::{EventThresholds, RareEvent};
use super::splitting::{
    estimate_batched, repetition_seed, run, AmsError, Budget, Estimate, EventParticle, Run,
    Settings,
};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::recording::SummaryRecorder;
use crate::scenario::Scenario;
use crate::simulation::Simulation;

/// Steps between two stored copies of a flight (0.1 s at the 1-ms step): a branch replays
/// at most this many steps, and a flight of 30 s keeps about 300 copies. Against a copy a
/// second, a tenth of the replay at ten times the copies: at 10⁻⁶ in the paper's set (a
/// batch of 8 repetitions in flight) about a tenth more levels for the same steps, and a
/// peak memory of 1.5 GB against 0.3 GB (docs/rare-events.md).
pub const CHECKPOINT_EVERY_STEPS: usize = 100;

/// At most this many flights that reached the event are kept for replay.
pub const MAX_EVENT_FLIGHTS: usize = 20;

/// What to estimate and how far to go.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct RareRequest {
    /// The event.
    pub event: RareEvent,
    /// Its threshold (the campaign's when `None`): a ramp clearance below it (m), a
    /// touchdown sink rate (m/s) or offset (m) above it.
    pub threshold: Option<f64>,
    /// Seed of the splitting (its choices and every branch's noise).
    pub seed: u64,
    /// Stop once the estimate's relative standard error is at most this (checked from
    /// 32 repetitions on).
    pub target_rel_error: f64,
    /// Stop once this many approaches' worth of steps is spent.
    pub max_runs: u64,
    /// Particles per repetition.
    pub particles: usize,
    /// Flights that calibrate the ramp's score before splitting ([`RampCalibration`]:
    /// the first of the campaign with `seed`); 0, the plain score.
    pub calibration_runs: u64,
}

impl RareRequest {
    /// `event` with the defaults: the campaign's threshold, 10 % relative error, at most
    /// 100 000 approaches' worth, 100 particles.
    pub fn new(event: RareEvent, seed: u64) -> Self {
        Self {
            event,
            threshold: None,
            seed,
            target_rel_error: 0.1,
            max_runs: 100_000,
            particles: 100,
            calibration_runs: 0,
        }
    }

    /// Checks the numbers; the error names the option and its value.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "rare";
        check_ranges!(SECTION, self, {
            target_rel_error: Bounds::positive_up_to(1.0),
        });
        Bounds::closed(1.0, 1e9).check(SECTION, "max_runs", self.max_runs as f64)?;
        Bounds::closed(4.0, 100_000.0).check(SECTION, "particles", self.particles as f64)?;
        Bounds::closed(0.0, 100_000.0).check(
            SECTION,
            "calibration_runs",
            self.calibration_runs as f64,
        )?;
        if self.calibration_runs > 0 && !self.event.reads_ramp() {
            return Err(ParameterError::new(
                SECTION,
                "calibration_runs",
                self.calibration_runs,
                format!(
                    "0: only the ramp's score is calibrated (`ramp_strike`, `lost`), not `{}`",
                    self.event.name()
                ),
            ));
        }
        if let Some(threshold) = self.threshold {
            let bounds = match self.event {
                RareEvent::RampStrike => Bounds::closed(-30.0, 30.0),
                RareEvent::HardLanding | RareEvent::OffCentre => Bounds::positive_up_to(30.0),
                RareEvent::Divergence | RareEvent::Lost => {
                    return Err(ParameterError::new(
                        SECTION,
                        "threshold",
                        threshold,
                        format!("no threshold: the event `{}` has none", self.event.name()),
                    ))
                }
            };
            bounds.check(SECTION, "threshold", threshold)?;
        }
        Ok(())
    }
}

impl RareRequest {
    /// The splitting's settings: `particles`, a tenth of them dropped at each level
    /// (at least one), a stored copy every [`CHECKPOINT_EVERY_STEPS`], the event at 0.
    pub fn settings(&self) -> Settings {
        Settings {
            particles: self.particles,
            killed_per_iteration: (self.particles / 10).max(1),
            checkpoint_every: CHECKPOINT_EVERY_STEPS,
            ..Settings::new(0.0)
        }
    }

    /// Checks the request and sets up the approach it starts from, with the thresholds
    /// it flies (the scenario's, `threshold` moving the event's): everything that can be
    /// refused before any flying.
    /// With `calibration_runs`, the calibration's flights are flown here.
    pub fn start(
        &self,
        scenario: &Scenario,
    ) -> Result<(ApproachFlight, EventThresholds), RareError> {
        let (flight, thresholds) = self.start_plain(scenario)?;
        let calibration = self.ramp_calibration(scenario)?;
        Ok((flight.with_ramp_calibration(calibration), thresholds))
    }

    /// As [`RareRequest::start`], with the plain score (nothing flown): every check
    /// that can refuse the request before any flying.
    pub fn start_plain(
        &self,
        scenario: &Scenario,
    ) -> Result<(ApproachFlight, EventThresholds), RareError> {
        self.validate()?;
        let thresholds = match self.threshold {
            Some(value) => EventThresholds::of(scenario).with(self.event, value),
            None => EventThresholds::of(scenario),
        };
        Ok((
            ApproachFlight::new(scenario, self.event, thresholds)?,
            thresholds,
        ))
    }

    /// The ramp score's calibration, flown from the first `calibration_runs` runs of the
    /// campaign with `seed`; `None` when 0.
    pub fn ramp_calibration(
        &self,
        scenario: &Scenario,
    ) -> Result<Option<Arc<RampCalibration>>, RareError> {
        if self.calibration_runs == 0 {
            return Ok(None);
        }
        RampCalibration::fly(scenario, self.seed, self.calibration_runs)
            .map(|calibration| Some(Arc::new(calibration)))
            .ok_or(RareError::Calibration {
                runs: self.calibration_runs,
            })
    }
}

/// Why no rate could be estimated.
#[derive(Debug, thiserror::Error)]
pub enum RareError {
    /// A request value is out of range.
    #[error(transparent)]
    Request(#[from] ParameterError),
    /// The scenario cannot be flown or scored.
    #[error(transparent)]
    Flight(#[from] FlightError),
    /// Fewer than two of the calibration's flights crossed the ramp.
    #[error(
        "fewer than 2 of the {runs} calibration flights (`calibration_runs`) crossed the \
         ramp: the ramp's score cannot be calibrated"
    )]
    Calibration {
        /// The flights flown.
        runs: u64,
    },
    /// Splitting could not give an estimate.
    #[error(transparent)]
    Splitting(#[from] AmsError),
}

/// The estimate with what it cost and the flights that reached the event.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RareResult {
    /// The request.
    pub request: RareRequest,
    /// The thresholds flown.
    pub thresholds: EventThresholds,
    /// The probability per approach, its 95 % interval and the work done.
    pub estimate: Estimate,
    /// Steps of one whole approach (the scenario's seed, flown without splitting): the
    /// unit of the costs below.
    pub approach_steps: u64,
    /// The steps spent, in approaches.
    pub approaches_spent: f64,
    /// The approaches a plain campaign would need for the same relative standard error,
    /// (1 − p)/(p·ε²); `None` without a positive estimate and an error.
    pub brute_force_approaches: Option<f64>,
    /// Approaches spent over those of the plain campaign.
    pub cost_factor: Option<f64>,
    /// Each repetition's levels, in the score's units (0 is the event), in order.
    pub levels: Vec<Vec<f64>>,
    /// Flights that reached the event (at most [`MAX_EVENT_FLIGHTS`]): the repetition
    /// and the particle, with the branches to fly it again ([`replay_event_flight`]).
    pub event_flights: Vec<(u64, EventParticle)>,
}

/// Estimates the probability per approach of `request.event` in `scenario` by adaptive
/// multilevel splitting, calling `progress` with each repetition's run.
pub fn estimate_rate(
    scenario: &Scenario,
    request: &RareRequest,
    progress: impl FnMut(u64, &Run),
) -> Result<RareResult, RareError> {
    let (start, _) = request.start(scenario)?;
    let settings = request.settings();
    let run_batch = |repetitions: std::ops::Range<u64>, share: u64| {
        use rayon::prelude::*;
        repetitions
            .into_par_iter()
            .map(|r| run(&start, &settings, repetition_seed(request.seed, r), share))
            .collect()
    };
    estimate_rate_batched(scenario, request, run_batch, progress)
}

/// Repetition `repetition` of the estimate of `request` in `scenario`, flown on at most
/// `share` steps: what [`estimate_rate`] flies for it, to the bit, wherever it is flown
/// (a cluster's worker gets the scenario and the request, not the flight).
pub fn fly_repetition(
    scenario: &Scenario,
    request: &RareRequest,
    repetition: u64,
    share: u64,
) -> Result<Run, RareError> {
    let (start, _) = request.start(scenario)?;
    let settings = request.settings();
    Ok(run(
        &start,
        &settings,
        repetition_seed(request.seed, repetition),
        share,
    )?)
}

/// As [`estimate_rate`], with each batch of repetitions flown by
/// `run_batch(repetitions, share)` ([`fly_repetition`] for each, in order): the same
/// result to the bit.
pub fn estimate_rate_batched(
    scenario: &Scenario,
    request: &RareRequest,
    run_batch: impl FnMut(std::ops::Range<u64>, u64) -> Vec<Result<Run, AmsError>>,
    mut progress: impl FnMut(u64, &Run),
) -> Result<RareResult, RareError> {
    let (_, thresholds) = request.start_plain(scenario)?;
    request.settings().validate()?;
    let approach_steps = Simulation::new(scenario)
        .map_err(FlightError::from)?
        .run(&mut SummaryRecorder)
        .steps
        .max(1);
    let budget = Budget {
        target_rel_error: Some(request.target_rel_error),
        max_repetitions: u64::MAX,
        max_steps: request.max_runs.saturating_mul(approach_steps),
    };
    let mut levels = Vec::new();
    let mut event_flights = Vec::new();
    let estimate = estimate_batched(budget, run_batch, |r, run| {
        levels.push(run.levels.clone());
        for particle in &run.events {
            if event_flights.len() < MAX_EVENT_FLIGHTS {
                event_flights.push((r, particle.clone()));
            }
        }
        progress(r, run);
    })?;
    let approaches_spent = estimate.steps as f64 / approach_steps as f64;
    let p = estimate.probability;
    let brute_force_approaches = estimate
        .relative_standard_error
        .filter(|e| *e > 0.0 && p > 0.0)
        .map(|e| (1.0 - p) / (p * e * e));
    Ok(RareResult {
        request: *request,
        thresholds,
        approach_steps,
        approaches_spent,
        cost_factor: brute_force_approaches.map(|n| approaches_spent / n),
        brute_force_approaches,
        estimate,
        levels,
        event_flights,
    })
}

/// Flies again, recorded, the flight of `particle` from `scenario`'s start as the
/// estimate flew it: the same flight, bit for bit.
pub fn replay_event_flight(
    scenario: &Scenario,
    thresholds: EventThresholds,
    event: RareEvent,
    particle: &EventParticle,
) -> Result<Option<crate::experiments::ApproachRun>, FlightError> {
    let start = ApproachFlight::new(scenario, event, thresholds)?.recorded();
    let flight = super::splitting::refly(&start, &particle.lineage, 0.0, |_| {});
    Ok(flight.into_run())
}
