//! The approach of Fig. 14, 15, approaches with the paper's sink-rate and guidance gains,
//! and the boarding rate over seeds.

use super::paper::{PAPER_GUIDANCE_GAINS, PAPER_SINK_GAINS};
use super::{paper_scenario, seeds, PaperPitchLaw, ReproductionError, SEED};
use crate::experiments::{fly_approach, fly_seeds, ApproachRun, Conditions, OutcomeCounts};
use crate::metrics::root_mean_square;
use crate::monte_carlo::Proportion;
use crate::scenario::Scenario;
use crate::simulation::RunSummary;

/// The approach in adverse conditions with seed [`SEED`], and the paper's gains flown.
#[derive(Debug, Clone)]
pub struct ApproachStudy {
    /// The scenario flown: the paper's, adverse, O-PD, seed [`SEED`].
    pub scenario: Scenario,
    /// The approach, recorded.
    pub run: ApproachRun,
    /// RMS of θ − θ_ref over the whole approach (deg).
    pub pitch_tracking_rms_deg: f64,
    /// The approach with the paper's sink-rate and guidance gains (§4.4, §4.5): ideal,
    /// then adverse with seed [`SEED`].
    pub paper_gains: [RunSummary; 2],
}

/// The paper's scenario in `conditions` with the paper's sink-rate and guidance gains.
pub fn paper_gains_scenario(conditions: Conditions) -> Scenario {
    let mut scenario = paper_scenario(conditions, SEED, PaperPitchLaw::ObserverPd);
    (
        scenario.control.sink_rate.proportional_rad_per_mps,
        scenario.control.sink_rate.integral_rad_per_m,
    ) = PAPER_SINK_GAINS;
    (
        scenario.control.guidance.proportional_per_s,
        scenario.control.guidance.integral_per_s2,
        scenario.control.guidance.derivative,
    ) = PAPER_GUIDANCE_GAINS;
    scenario
}

/// Flies the approach of Fig. 14, 15 and, without recording them, the approaches with the
/// paper's gains.
pub fn study_approach() -> Result<ApproachStudy, ReproductionError> {
    let scenario = paper_scenario(Conditions::Adverse, SEED, PaperPitchLaw::ObserverPd);
    let run = fly_approach(&scenario).map_err(ReproductionError::experiment("the approach"))?;
    let pitch_tracking_rms_deg = root_mean_square(
        run.samples
            .iter()
            .map(|s| (s.theta_rad - s.theta_ref_rad).to_degrees()),
    );
    let fly_paper_gains = |conditions: Conditions| {
        fly_approach(&paper_gains_scenario(conditions))
            .map(|run| run.summary)
            .map_err(ReproductionError::experiment(format!(
                "the {} approach with the paper's gains",
                conditions.name()
            )))
    };
    Ok(ApproachStudy {
        paper_gains: [
            fly_paper_gains(Conditions::Ideal)?,
            fly_paper_gains(Conditions::Adverse)?,
        ],
        scenario,
        run,
        pitch_tracking_rms_deg,
    })
}

/// The boarding rate of the adverse approach over seeds 1..=N.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoardingStudy {
    /// The runs' outcomes.
    pub counts: OutcomeCounts,
    /// The traps as a rate with its 95 % Wilson score interval.
    pub boarding_rate: Proportion,
}

/// Flies the approach of [`study_approach`] with seeds 1..=`boarding_seeds` (summaries
/// only, in parallel) and counts the traps.
pub fn study_boarding(boarding_seeds: u64) -> Result<BoardingStudy, ReproductionError> {
    let base = paper_scenario(Conditions::Adverse, SEED, PaperPitchLaw::ObserverPd);
    let summaries =
        fly_seeds(&base, &seeds(boarding_seeds)).map_err(|source| ReproductionError::Seeds {
            what: "the boarding statistics",
            source,
        })?;
    let counts = OutcomeCounts::of(&summaries);
    let runs = u64::try_from(counts.runs).unwrap_or(0);
    let traps = u64::try_from(counts.trap).unwrap_or(0);
    Ok(BoardingStudy {
        counts,
        boarding_rate: Proportion::new(traps, runs),
    })
}
