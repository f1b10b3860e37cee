//! The pitch steps of Fig. 10–12 with both of the paper's laws, and the adverse step over
//! seeds: with the pitch sensor's noise off for the O-PD, as flown for the PID.

use super::{
    paper_scenario, seeds, PaperPitchLaw, ReproductionError, PITCH_STEP_DEG, PITCH_STEP_SECONDS,
    SEED,
};
use crate::experiments::{fly_pitch_step, Conditions, PitchStep, PitchStepResponse, PitchStepRun};
use crate::metrics::{median, root_mean_square};
use crate::simulation::Signals;

/// The step of Fig. 10–12.
fn step() -> PitchStep {
    PitchStep::new(PITCH_STEP_DEG, PITCH_STEP_SECONDS)
}

/// Flies the step in `conditions` with `seed` and `law`, the sensor noise off if
/// `noiseless`.
fn fly(
    conditions: Conditions,
    seed: u64,
    law: PaperPitchLaw,
    noiseless: bool,
) -> Result<PitchStepRun, ReproductionError> {
    let mut scenario = paper_scenario(conditions, seed, law);
    if noiseless {
        scenario.environment.pitch_noise.enabled = false;
    }
    fly_pitch_step(&scenario, &step()).map_err(ReproductionError::experiment(format!(
        "the {} {} step of seed {seed}",
        conditions.name(),
        scenario.control.pitch.label()
    )))
}

/// Both laws' step: O-PD, then PID.
fn both(conditions: Conditions) -> Result<[PitchStepRun; 2], ReproductionError> {
    Ok([
        fly(conditions, SEED, PaperPitchLaw::ObserverPd, false)?,
        fly(conditions, SEED, PaperPitchLaw::Pid, false)?,
    ])
}

/// The ideal step of Fig. 10 (seed [`SEED`]): O-PD, then PID.
pub fn study_ideal_pitch_step() -> Result<[PitchStepRun; 2], ReproductionError> {
    both(Conditions::Ideal)
}

/// One law's adverse step over seeds 1..=N.
#[derive(Debug, Clone, PartialEq)]
pub struct PitchStepSeeds {
    /// The response of each seed, in seed order.
    pub responses: Vec<PitchStepResponse>,
    /// How many settled.
    pub settled: usize,
    /// The median settling time of those that settled (s; NaN when none did).
    pub median_settling_s: f64,
}

impl PitchStepSeeds {
    /// Counts the settled `responses` and takes the median of their settling times.
    pub fn of(responses: Vec<PitchStepResponse>) -> Self {
        let times: Vec<f64> = responses
            .iter()
            .filter(|r| r.settled)
            .filter_map(|r| r.settling_time_s)
            .collect();
        Self {
            settled: times.len(),
            median_settling_s: median(times),
            responses,
        }
    }
}

/// The adverse step of Fig. 11, 12 and what lies behind the report's notes on it.
#[derive(Debug, Clone)]
pub struct AdversePitchStepStudy {
    /// The step with seed [`SEED`]: O-PD, then PID.
    pub runs: [PitchStepRun; 2],
    /// RMS of θ − θ_ref over the last second of the O-PD's run (deg).
    pub observer_pd_tracking_rms_deg: f64,
    /// The O-PD without the pitch sensor's noise, seeds 1..=N.
    pub observer_pd_noiseless: PitchStepSeeds,
    /// The PID, seeds 1..=N.
    pub pid_seeds: PitchStepSeeds,
}

/// RMS of θ − θ_ref over the last second of a record (deg).
pub fn last_second_tracking_rms_deg(samples: &[Signals]) -> f64 {
    let end_s = samples.last().map_or(0.0, |s| s.time_s);
    root_mean_square(
        samples
            .iter()
            .filter(|s| s.time_s >= end_s - 1.0)
            .map(|s| (s.theta_rad - s.theta_ref_rad).to_degrees()),
    )
}

/// The adverse step with both laws (seed [`SEED`]), and over seeds 1..=`study_seeds` the
/// O-PD without sensor noise and the PID as flown.
pub fn study_adverse_pitch_step(
    study_seeds: u64,
) -> Result<AdversePitchStepStudy, ReproductionError> {
    let runs = both(Conditions::Adverse)?;
    let over_seeds = |law, noiseless| -> Result<PitchStepSeeds, ReproductionError> {
        let responses = seeds(study_seeds)
            .into_iter()
            .map(|seed| Ok(fly(Conditions::Adverse, seed, law, noiseless)?.response))
            .collect::<Result<Vec<_>, ReproductionError>>()?;
        Ok(PitchStepSeeds::of(responses))
    };
    Ok(AdversePitchStepStudy {
        observer_pd_tracking_rms_deg: last_second_tracking_rms_deg(&runs[0].samples),
        observer_pd_noiseless: over_seeds(PaperPitchLaw::ObserverPd, true)?,
        pid_seeds: over_seeds(PaperPitchLaw::Pid, false)?,
        runs,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tracking_rms_takes_only_the_last_second() {
        // θ − θ_ref is 5° before the last second and a square wave of ±1° in it: the RMS
        // of the last second is 1°.
        let samples: Vec<Signals> = (0..=300)
            .map(|i| {
                let time_s = f64::from(i) * 0.01;
                let error_deg: f64 = if time_s < 1.995 {
                    5.0
                } else if i % 2 == 0 {
                    1.0
                } else {
                    -1.0
                };
                Signals {
                    time_s,
                    theta_rad: error_deg.to_radians(),
                    theta_ref_rad: 0.0,
                    ..Signals::default()
                }
            })
            .collect();
        let rms = last_second_tracking_rms_deg(&samples);
        assert!((rms - 1.0).abs() < 1e-12, "{rms}");
    }
}
