//! The campaign: its specification, the parallel loop and its result.

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use rayon::prelude::*;

use super::record::{RunFailure, RunRecord};
use super::row::RunRow;
use super::seeds::run_seed;
use super::shard::Shard;
use super::statistics::CampaignStatistics;
use crate::control::pitch::PitchControllerParameters;
use crate::random::RandomStreams;
use crate::recording::SummaryRecorder;
use crate::scenario::{DispersionSample, Mission, Scenario};
use crate::simulation::{PitchLawFactory, Simulation};

/// A user's own pitch law for a campaign: built once per run, after that run's trim.
#[derive(Clone)]
pub struct SharedPitchLaw(pub Arc<PitchLawFactory>);

impl std::fmt::Debug for SharedPitchLaw {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("SharedPitchLaw(user's own pitch law)")
    }
}

impl PartialEq for SharedPitchLaw {
    /// The same factory (the same allocation).
    fn eq(&self, other: &Self) -> bool {
        Arc::ptr_eq(&self.0, &other.0)
    }
}

/// A pitch controller a campaign flies, with its label for tables and files.
#[derive(Debug, Clone, PartialEq)]
pub struct ControllerVariant {
    /// Label, e.g. `O-PD`.
    pub label: String,
    /// The controller and its tuning, as the scenario names it.
    pub pitch: PitchControllerParameters,
    /// A user's own law flying instead of `pitch` (see `examples/custom_pitch_law.rs`).
    pub custom_law: Option<SharedPitchLaw>,
}

impl ControllerVariant {
    /// A registered pitch law with its label.
    pub fn registered(pitch: PitchControllerParameters) -> Self {
        Self {
            label: pitch.label().to_owned(),
            pitch,
            custom_law: None,
        }
    }

    /// A user's own pitch law, built by `factory` for each run, labelled `label`.
    pub fn custom(label: impl Into<String>, factory: Arc<PitchLawFactory>) -> Self {
        Self {
            label: label.into(),
            pitch: PitchControllerParameters::default(),
            custom_law: Some(SharedPitchLaw(factory)),
        }
    }
}

/// The label of a pitch controller, e.g. `O-PD`.
pub fn controller_label(pitch: &PitchControllerParameters) -> &'static str {
    pitch.label()
}

/// What a campaign flies: `runs` approaches of `scenario` (with its dispersions), each
/// under every controller of `controllers`, run `i` with seed [`run_seed`]`(seed, i)` —
/// all of them, or those of one [`Shard`].
#[derive(Debug, Clone, PartialEq)]
pub struct CampaignSpec {
    /// The nominal scenario; its `seed` is replaced per run, its `dispersion` applied.
    pub scenario: Scenario,
    /// Number of approaches per controller.
    pub runs: u64,
    /// The campaign seed.
    pub seed: u64,
    /// The controllers; the same seeds and dispersions fly under each.
    pub controllers: Vec<ControllerVariant>,
    /// The part of the campaign to fly ([`Shard::WHOLE`] for all of it).
    pub shard: Shard,
}

impl CampaignSpec {
    /// `runs` approaches of `scenario` under its own pitch controller, campaign seed `seed`.
    pub fn new(scenario: Scenario, runs: u64, seed: u64) -> Self {
        let pitch = scenario.control.pitch;
        Self {
            scenario,
            runs,
            seed,
            controllers: vec![ControllerVariant::registered(pitch)],
            shard: Shard::WHOLE,
        }
    }

    /// Only the runs of `shard` of this campaign.
    pub fn sharded(self, shard: Shard) -> Self {
        Self { shard, ..self }
    }

    /// The same campaign under the compared laws
    /// ([`PitchControllerParameters::COMPARISON`]: O-PD and PID, in that order): the
    /// scenario's own law keeps its tuning, each other takes its tuning for the scenario's
    /// hardware set. A scenario flying a law outside the comparison flies it first.
    pub fn comparing_pitch_controllers(mut self) -> Self {
        let own = self.scenario.control.pitch;
        let tuning = self.scenario.hardware.law_tuning();
        let compared = PitchControllerParameters::COMPARISON
            .into_iter()
            .filter_map(|name| {
                if name == own.type_name() {
                    Some(own)
                } else {
                    PitchControllerParameters::registered(name, tuning)
                }
            });
        let outside = !PitchControllerParameters::COMPARISON.contains(&own.type_name());
        self.controllers = outside
            .then_some(own)
            .into_iter()
            .chain(compared)
            .map(ControllerVariant::registered)
            .collect();
        self
    }

    /// The scenario run `run_index` flies under controller `controller` (before
    /// validation), with its seed and dispersion draw.
    pub fn run_scenario(&self, run_index: u64, controller: usize) -> (Scenario, DispersionSample) {
        let seed = run_seed(self.seed, run_index);
        let mut scenario = Scenario {
            seed,
            ..self.scenario
        };
        if let Some(variant) = self.controllers.get(controller) {
            scenario.control.pitch = variant.pitch;
        }
        let draw = scenario.dispersion.sample(&RandomStreams::new(seed));
        (draw.apply(&scenario), draw)
    }
}

/// Why a campaign could not start.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum CampaignError {
    /// Zero runs, or no controller.
    #[error("a campaign needs at least one run and one controller (got {runs} runs, {controllers} controllers)")]
    Empty {
        /// Runs asked for.
        runs: u64,
        /// Controllers given.
        controllers: usize,
    },
    /// More runs than this machine can count (runs × controllers overflows `usize`).
    #[error("{runs} runs under {controllers} controllers are more than this machine can index")]
    TooManyRuns {
        /// Runs asked for.
        runs: u64,
        /// Controllers given.
        controllers: usize,
    },
    /// The scenario's mission is not an approach.
    #[error("a campaign flies approaches: set `mission.kind = \"approach\"`")]
    NotAnApproach,
    /// A shard beyond the runs: shard K/M holds no run when K ≥ N.
    #[error("shard {shard} of a campaign of {runs} runs holds no run: use at most {runs} shards")]
    EmptyShard {
        /// The shard.
        shard: Shard,
        /// Runs of the whole campaign.
        runs: u64,
    },
    /// The nominal scenario itself is invalid.
    #[error("the nominal scenario is invalid: {0}")]
    InvalidScenario(#[from] crate::parameters::ParameterError),
    /// The thread pool could not be built (e.g. 0 threads).
    #[error("cannot start {threads} worker threads: {message}")]
    ThreadPool {
        /// Threads asked for.
        threads: usize,
        /// The reason.
        message: String,
    },
}

/// What a campaign produced.
#[derive(Debug, Clone, PartialEq)]
pub struct CampaignResult {
    /// Every finished run, sorted by run index then controller.
    pub records: Vec<RunRecord>,
    /// Approaches asked for, per controller, in the whole campaign (all shards).
    pub requested_runs: u64,
    /// The part of the campaign flown.
    pub shard: Shard,
    /// The controllers' labels, in [`RunRecord::controller`] order.
    pub controller_labels: Vec<String>,
    /// Whether the campaign (or shard) was stopped before every run finished; the records
    /// then hold exactly the runs that finished (not necessarily the first ones).
    pub partial: bool,
}

impl CampaignResult {
    /// The statistics of each controller, in order.
    pub fn statistics(&self) -> Vec<CampaignStatistics> {
        self.controller_labels
            .iter()
            .enumerate()
            .map(|(index, label)| CampaignStatistics::of(&self.records, index, label))
            .collect()
    }

    /// The records as rows of `runs.csv`, in order, each controller named from
    /// [`Self::controller_labels`].
    pub fn rows(&self) -> Vec<RunRow<'_>> {
        self.records
            .iter()
            .map(|r| RunRow::new(r, &self.controller_labels))
            .collect()
    }
}

/// Flies one run; never panics (a panic inside the simulation becomes a record).
fn fly(spec: &CampaignSpec, run_index: u64, controller: usize) -> RunRecord {
    let (scenario, dispersion) = spec.run_scenario(run_index, controller);
    let custom_law = spec
        .controllers
        .get(controller)
        .and_then(|variant| variant.custom_law.as_ref());
    let result = catch_unwind(AssertUnwindSafe(|| {
        let simulation = match custom_law {
            Some(law) => Simulation::with_pitch_law(&scenario, &*law.0),
            None => Simulation::new(&scenario),
        };
        simulation.map(|simulation| simulation.run(&mut SummaryRecorder))
    }))
    .map_err(|payload| {
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| (*s).to_owned())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_owned());
        RunFailure::Panicked(message)
    })
    .and_then(|flown| flown.map_err(RunFailure::from));
    RunRecord {
        run_index,
        controller,
        seed: scenario.seed,
        dispersion,
        result,
    }
}

/// Flies the campaign on `threads` worker threads. `progress` is called (from the
/// workers) after each run with its record; `stop`, when set, makes the workers start
/// no further run, and the result is then [`CampaignResult::partial`].
///
/// Only the runs of the spec's [`CampaignSpec::shard`] are flown. The records are sorted
/// by run index and controller, and each depends only on its seed, so the result is
/// identical for any `threads`, and the shards of a campaign together are the campaign.
pub fn run_campaign(
    spec: &CampaignSpec,
    threads: usize,
    progress: &(dyn Fn(&RunRecord) + Sync),
    stop: &AtomicBool,
) -> Result<CampaignResult, CampaignError> {
    let variants = spec.controllers.len();
    if spec.runs == 0 || variants == 0 {
        return Err(CampaignError::Empty {
            runs: spec.runs,
            controllers: variants,
        });
    }
    if !matches!(spec.scenario.mission, Mission::Approach) {
        return Err(CampaignError::NotAnApproach);
    }
    spec.scenario.validate()?;
    spec.scenario.dispersion.validate()?;
    let pool_error = |message: String| CampaignError::ThreadPool { threads, message };
    if threads == 0 {
        return Err(pool_error("at least one thread is needed".to_owned()));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|index| format!("deckland-campaign-{index}"))
        .build()
        .map_err(|e| pool_error(e.to_string()))?;
    let shard = spec.shard;
    let shard_runs = shard.runs_of(spec.runs);
    if shard_runs == 0 {
        return Err(CampaignError::EmptyShard {
            shard,
            runs: spec.runs,
        });
    }
    let total = usize::try_from(shard_runs)
        .ok()
        .and_then(|runs| runs.checked_mul(variants))
        .ok_or(CampaignError::TooManyRuns {
            runs: spec.runs,
            controllers: variants,
        })?;
    // An indexed collect writes each slot in place (no per-item lists); one run per task
    // lets idle workers steal single runs, whose lengths differ.
    let slots: Vec<Option<RunRecord>> = pool.install(|| {
        (0..total)
            .into_par_iter()
            .with_max_len(1)
            .map(|item| {
                if stop.load(Ordering::Relaxed) {
                    return None;
                }
                let run_index = shard.run_index((item / variants) as u64);
                let record = fly(spec, run_index, item % variants);
                progress(&record);
                Some(record)
            })
            .collect()
    });
    let mut records: Vec<RunRecord> = slots.into_iter().flatten().collect();
    records.sort_by_key(|r| (r.run_index, r.controller));
    let partial = records.len() < total;
    Ok(CampaignResult {
        records,
        requested_runs: spec.runs,
        shard,
        controller_labels: spec.controllers.iter().map(|c| c.label.clone()).collect(),
        partial,
    })
}

#[cfg(test)]
mod tests {
    use std::sync::atomic::AtomicBool;

    use super::*;
    use crate::control::pitch::{ObserverPdParameters, PidParameters};
    use crate::scenario::load_scenario;

    /// The law that the test build registers with one file and one registry line
    /// (`control/pitch/proportional.rs`) is named in a scenario file, tuned by the paper's
    /// set by name, and flown by a campaign first, then the compared O-PD and PID.
    #[test]
    fn a_law_registered_with_one_line_flies_in_a_comparison() {
        let text = "[control.pitch]\ntype = \"proportional\"\nderivative_per_s = 5.0\n";
        let scenario = load_scenario(text, "pd.toml").expect("a valid scenario");
        assert_eq!(scenario.control.pitch.label(), "PD");
        let paper = load_scenario(
            "hardware = \"paper\"\n[control.pitch]\ntype = \"proportional\"\n",
            "pd-paper.toml",
        )
        .expect("a valid scenario");
        assert_eq!(paper.control.pitch.type_name(), "proportional");

        let spec = CampaignSpec::new(scenario, 2, 11).comparing_pitch_controllers();
        let labels: Vec<&str> = spec.controllers.iter().map(|c| c.label.as_str()).collect();
        assert_eq!(labels, ["PD", "O-PD", "PID"]);
        assert_eq!(spec.controllers[0].pitch, scenario.control.pitch);
        let result = run_campaign(&spec, 1, &|_| {}, &AtomicBool::new(false)).expect("valid");
        assert_eq!(result.records.len(), 6);
        for record in result.records.iter().filter(|r| r.controller == 0) {
            // It holds the glide path down to the deck.
            let summary = record.result.as_ref().expect("the law flies");
            let clearance = summary.ramp_clearance_m.expect("reaches the ramp");
            let error = summary.glide_path_error_rms_m.expect("on the path");
            assert!(clearance > 0.0 && error < 1.0, "{summary:?}");
        }
    }

    /// The comparison keeps the scenario's own law and tunes the other for its hardware
    /// set, by name.
    #[test]
    fn a_comparison_keeps_the_own_law_and_tunes_the_other_for_the_set() {
        let mut scenario = Scenario::paper();
        let own = PidParameters {
            anti_windup: false,
            ..PidParameters::paper()
        };
        scenario.control.pitch = PitchControllerParameters::Pid(own);
        let spec = CampaignSpec::new(scenario, 1, 1).comparing_pitch_controllers();
        let laws: Vec<_> = spec.controllers.iter().map(|c| c.pitch).collect();
        assert_eq!(
            laws,
            [
                PitchControllerParameters::ObserverPd(ObserverPdParameters::paper()),
                PitchControllerParameters::Pid(own),
            ]
        );
        let realistic = CampaignSpec::new(Scenario::default(), 1, 1).comparing_pitch_controllers();
        let laws: Vec<_> = realistic.controllers.iter().map(|c| c.pitch).collect();
        assert_eq!(
            laws,
            [
                PitchControllerParameters::default(),
                PitchControllerParameters::Pid(PidParameters::default()),
            ]
        );
    }
}
