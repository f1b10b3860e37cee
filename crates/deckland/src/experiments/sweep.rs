//! One scenario over many seeds: the runs in parallel, the results in seed order.

use rayon::prelude::*;
use serde::Serialize;

use crate::recording::SummaryRecorder;
use crate::scenario::Scenario;
use crate::simulation::{Outcome, RunSummary, SetupError, Simulation};

/// Flies `base` once per seed (summary only) on rayon's pool; the results come in the
/// order of `seeds` and do not depend on the number of threads (each run depends only on
/// its seed).
pub fn fly_seeds(base: &Scenario, seeds: &[u64]) -> Result<Vec<RunSummary>, SetupError> {
    seeds
        .par_iter()
        .map(|&seed| {
            let scenario = Scenario { seed, ..*base };
            Ok(Simulation::new(&scenario)?.run(&mut SummaryRecorder))
        })
        .collect()
}

/// How many runs ended in each outcome.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize)]
pub struct OutcomeCounts {
    /// Runs counted.
    pub runs: usize,
    /// Traps.
    pub trap: usize,
    /// Bolters.
    pub bolter: usize,
    /// Ramp strikes.
    pub ramp_strike: usize,
    /// Hard landings.
    pub hard_landing: usize,
    /// Wave-offs (safe, not failures).
    pub wave_off: usize,
    /// Divergences.
    pub diverged: usize,
    /// Timeouts.
    pub timeout: usize,
}

impl OutcomeCounts {
    /// Counts the outcomes of `summaries`.
    pub fn of(summaries: &[RunSummary]) -> Self {
        let mut counts = Self {
            runs: summaries.len(),
            ..Self::default()
        };
        for summary in summaries {
            match summary.outcome {
                Outcome::Trap => counts.trap += 1,
                Outcome::Bolter => counts.bolter += 1,
                Outcome::RampStrike => counts.ramp_strike += 1,
                Outcome::HardLanding => counts.hard_landing += 1,
                Outcome::WaveOff => counts.wave_off += 1,
                Outcome::Diverged => counts.diverged += 1,
                Outcome::Timeout => counts.timeout += 1,
                Outcome::Completed => {}
            }
        }
        counts
    }

    /// The share of traps (0–1); 0 with no runs.
    pub fn boarding_rate(&self) -> f64 {
        if self.runs == 0 {
            0.0
        } else {
            self.trap as f64 / self.runs as f64
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn summary(outcome: Outcome) -> RunSummary {
        RunSummary {
            outcome,
            wire: None,
            reason: None,
            end_time_s: 0.0,
            steps: 0,
            touchdown: None,
            ramp_clearance_m: None,
            glide_path_error_rms_m: None,
            glide_path_error_max_m: None,
            actuator: Default::default(),
            deck_within_recovery_limits_pct: 100.0,
            commit_forecast: None,
            trap_sheet: None,
            lso_grade: None,
        }
    }

    #[test]
    fn outcomes_are_counted_and_the_boarding_rate_is_the_trap_share() {
        let summaries = [
            summary(Outcome::Trap),
            summary(Outcome::Trap),
            summary(Outcome::Bolter),
            summary(Outcome::RampStrike),
        ];
        let counts = OutcomeCounts::of(&summaries);
        assert_eq!((counts.trap, counts.bolter, counts.ramp_strike), (2, 1, 1));
        assert_eq!(counts.boarding_rate(), 0.5);
        assert_eq!(OutcomeCounts::default().boarding_rate(), 0.0);
    }
}
