//! The commanded sink rate of Fig. 13: the paper's step, and the same command ramped in.

use super::{paper_scenario, PaperPitchLaw, ReproductionError, SEED, SINK_RAMP_S, SINK_RATE_MPS};
use crate::experiments::{fly_sink_rate, Conditions, SinkRateRun, SinkRateTracking};

/// The sink-rate command flown as a step and ramped in, O-PD, ideal conditions.
#[derive(Debug, Clone)]
pub struct SinkRateStudy {
    /// The paper's step of [`SINK_RATE_MPS`].
    pub step: SinkRateRun,
    /// The command ramped in over [`SINK_RAMP_S`].
    pub ramp: SinkRateRun,
}

impl SinkRateStudy {
    /// The command of [`SINK_RATE_MPS`] ramped in over `ramp_s`, `seconds` of flight.
    pub fn tracking(ramp_s: f64, seconds: f64) -> SinkRateTracking {
        SinkRateTracking {
            sink_rate_mps: SINK_RATE_MPS,
            ramp_s,
            seconds,
        }
    }
}

/// Flies the command as a step and ramped in over [`SINK_RAMP_S`], each `seconds` long,
/// with the paper's O-PD in ideal conditions (seed [`SEED`]).
pub fn study_sink_rate(seconds: f64) -> Result<SinkRateStudy, ReproductionError> {
    let scenario = paper_scenario(Conditions::Ideal, SEED, PaperPitchLaw::ObserverPd);
    let fly = |ramp_s: f64| {
        fly_sink_rate(&scenario, &SinkRateStudy::tracking(ramp_s, seconds)).map_err(
            ReproductionError::experiment(format!("the sink-rate command ramped over {ramp_s} s")),
        )
    };
    Ok(SinkRateStudy {
        step: fly(0.0)?,
        ramp: fly(SINK_RAMP_S)?,
    })
}
