//! The reproduction of the paper (Kistyarev & Wang): every study behind `deckland
//! reproduce`'s report, each a function that flies what the paper flew and returns what
//! was measured, with the records its figures are drawn from.
//!
//! - [`study_linear_model`]: trim (Table 3), the linear model and its modes (Eq. 14),
//!   the paper's printed A against itself, the O-PD gains (§4.2.2);
//! - [`study_open_loop`]: the nonlinear airframe against its linear model after a
//!   throttle step (Fig. 6);
//! - [`study_environment`]: the ship motion and the wind (Fig. 7, 8), with the peaks of
//!   many seeds;
//! - [`study_ideal_pitch_step`], [`study_adverse_pitch_step`]: the pitch steps of
//!   Fig. 10–12, and the adverse step over seeds with and without sensor noise;
//! - [`study_sink_rate`]: the commanded sink rate as the paper's step and ramped in
//!   (Fig. 13);
//! - [`study_approach`]: the approach of Fig. 14, 15, and approaches with the paper's
//!   sink-rate and guidance gains;
//! - [`study_boarding`]: the boarding rate over seeds (not in the paper).
//!
//! [`Reproduction::fly`] runs them all in that order. The paper's own values are data in
//! [`paper`]. Every run flies the paper's hardware set ([`HARDWARE`]).

mod approach;
mod environment;
mod linear_model;
pub mod paper;
mod pitch_step;
mod sink_rate;

pub use approach::{
    paper_gains_scenario, study_approach, study_boarding, ApproachStudy, BoardingStudy,
};
pub use environment::{study_environment, EnvironmentStudy};
pub use linear_model::{
    open_loop_agreement, study_linear_model, study_open_loop, LinearModelStudy, OpenLoopStudy,
};
pub use pitch_step::{
    last_second_tracking_rms_deg, study_adverse_pitch_step, study_ideal_pitch_step,
    AdversePitchStepStudy, PitchStepSeeds,
};
pub use sink_rate::{study_sink_rate, SinkRateStudy};

use super::{Conditions, ExperimentError};
use crate::analysis::{OpenLoopError, TrimError};
use crate::control::pitch::{ObserverPdParameters, PidParameters, PitchControllerParameters};
use crate::parameters::ParameterError;
use crate::scenario::{HardwareSet, Scenario};
use crate::simulation::SetupError;

/// The hardware every run of the reproduction flies: the paper's.
pub const HARDWARE: HardwareSet = HardwareSet::Paper;
/// The throttle step of Fig. 6: 1 % of the total maximum thrust (about 1.4 kN). The paper
/// does not give its size; small enough for the linear model to hold.
pub const THROTTLE_STEP: f64 = 0.01;
/// Pitch step of Fig. 10–12 (deg); the paper does not give its size.
pub const PITCH_STEP_DEG: f64 = 2.0;
/// Length of the pitch-step runs (s), as `deckland step`'s default.
pub const PITCH_STEP_SECONDS: f64 = 6.0;
/// The paper's commanded sink rate (m/s, Fig. 13).
pub const SINK_RATE_MPS: f64 = 10.0;
/// Ramp of the sink-rate command that this plant can follow (s).
pub const SINK_RAMP_S: f64 = 5.0;
/// Seed of the single adverse runs.
pub const SEED: u64 = 1;
/// Distance aft of the ship's pitch centre where Fig. 8 samples the wind (m).
pub const WIND_DISTANCE_AFT_M: f64 = 400.0;
/// Integration step of the open-loop throttle step (s).
const OPEN_LOOP_TIME_STEP_S: f64 = 0.001;
/// Sample interval of the open-loop throttle step (s).
const OPEN_LOOP_SAMPLE_INTERVAL_S: f64 = 0.05;

/// Lengths of the runs: the full reproduction or a quick one.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ReproductionLengths {
    /// Open-loop throttle step (s).
    pub open_loop_s: f64,
    /// Environment record (s).
    pub environment_s: f64,
    /// Sink-rate runs (s).
    pub sink_s: f64,
    /// Seeds of the boarding statistics (1..=N).
    pub boarding_seeds: u64,
    /// Seeds of the adverse pitch-step studies (1..=N).
    pub study_seeds: u64,
    /// Seeds of the environment records whose median peaks are given (1..=N).
    pub peak_seeds: u64,
}

impl ReproductionLengths {
    /// The full reproduction: one-minute records, 50 seeds of boarding statistics.
    pub fn full() -> Self {
        Self {
            open_loop_s: 60.0,
            environment_s: 60.0,
            sink_s: 20.0,
            boarding_seeds: 50,
            study_seeds: 5,
            peak_seeds: 20,
        }
    }

    /// Shorter records and fewer seeds (for tests): every study keeps its shape, some
    /// numbers change.
    pub fn quick() -> Self {
        Self {
            open_loop_s: 20.0,
            environment_s: 20.0,
            sink_s: 16.0,
            boarding_seeds: 3,
            study_seeds: 2,
            peak_seeds: 3,
        }
    }
}

/// Seeds 1..=`count`.
fn seeds(count: u64) -> Vec<u64> {
    (1..=count).collect()
}

/// The paper's two pitch laws.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PaperPitchLaw {
    /// The observer-based PD with the paper's design (Eq. 30–36).
    ObserverPd,
    /// The PID with the paper's gains (Eq. 37).
    Pid,
}

impl PaperPitchLaw {
    /// The law's parameters as the paper gives them.
    pub fn parameters(self) -> PitchControllerParameters {
        match self {
            Self::ObserverPd => {
                PitchControllerParameters::ObserverPd(ObserverPdParameters::paper())
            }
            Self::Pid => PitchControllerParameters::Pid(PidParameters::paper()),
        }
    }
}

/// The paper's scenario in `conditions` with `seed`, flying `law`.
pub fn paper_scenario(conditions: Conditions, seed: u64, law: PaperPitchLaw) -> Scenario {
    let mut scenario = conditions.apply(HARDWARE.scenario(), seed);
    scenario.control.pitch = law.parameters();
    scenario
}

/// Why a study of the reproduction could not be flown.
#[derive(Debug, thiserror::Error)]
pub enum ReproductionError {
    /// The landing aircraft does not trim.
    #[error("cannot trim the landing aircraft: {0}")]
    Trim(#[source] TrimError),
    /// The O-PD gains cannot be designed from the linear model.
    #[error("cannot design the O-PD gains: {0}")]
    GainDesign(#[source] ParameterError),
    /// The open-loop throttle step cannot be flown.
    #[error("cannot fly the open-loop throttle step: {0}")]
    OpenLoop(#[source] OpenLoopError),
    /// The paper's environment does not validate.
    #[error("the paper's environment is not valid: {0}")]
    Environment(#[source] ParameterError),
    /// A run of a study cannot be flown.
    #[error("cannot fly {what}: {source}")]
    Experiment {
        /// Which run.
        what: String,
        /// Why.
        #[source]
        source: ExperimentError,
    },
    /// The runs over many seeds cannot be set up.
    #[error("cannot set up {what}: {source}")]
    Seeds {
        /// Which study.
        what: &'static str,
        /// Why.
        #[source]
        source: SetupError,
    },
}

impl ReproductionError {
    fn experiment(what: impl Into<String>) -> impl FnOnce(ExperimentError) -> Self {
        let what = what.into();
        move |source| Self::Experiment { what, source }
    }
}

/// Every study of the reproduction, flown with one set of lengths.
#[derive(Debug, Clone)]
pub struct Reproduction {
    /// The lengths flown.
    pub lengths: ReproductionLengths,
    /// Trim, linear model, modes and gains.
    pub linear_model: LinearModelStudy,
    /// The open-loop throttle step.
    pub open_loop: OpenLoopStudy,
    /// Ship motion and wind.
    pub environment: EnvironmentStudy,
    /// The ideal pitch step, O-PD then PID.
    pub ideal_pitch_step: [crate::experiments::PitchStepRun; 2],
    /// The adverse pitch step and its studies over seeds.
    pub adverse_pitch_step: AdversePitchStepStudy,
    /// The sink-rate command.
    pub sink_rate: SinkRateStudy,
    /// The approach and the paper's gains.
    pub approach: ApproachStudy,
    /// The boarding rate.
    pub boarding: BoardingStudy,
}

impl Reproduction {
    /// Flies every study in the order of the module's list.
    pub fn fly(lengths: ReproductionLengths) -> Result<Self, ReproductionError> {
        let linear_model = study_linear_model()?;
        let open_loop = study_open_loop(&linear_model, lengths.open_loop_s)?;
        let environment = study_environment(&linear_model.trim, &lengths)?;
        let ideal_pitch_step = study_ideal_pitch_step()?;
        let adverse_pitch_step = study_adverse_pitch_step(lengths.study_seeds)?;
        let sink_rate = study_sink_rate(lengths.sink_s)?;
        let approach = study_approach()?;
        let boarding = study_boarding(lengths.boarding_seeds)?;
        Ok(Self {
            lengths,
            linear_model,
            open_loop,
            environment,
            ideal_pitch_step,
            adverse_pitch_step,
            sink_rate,
            approach,
            boarding,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analysis::ModeKind;

    /// A quick reproduction returns every record the figures are drawn from and every
    /// number the report sets beside the paper's, consistent with how it was flown.
    #[test]
    fn a_quick_reproduction_returns_what_the_report_needs() {
        let lengths = ReproductionLengths::quick();
        let r = match Reproduction::fly(lengths) {
            Ok(r) => r,
            Err(error) => panic!("{error}"),
        };

        // Trim at the paper's speed, both longitudinal modes, both sets of modes.
        let model = &r.linear_model;
        assert!((model.trim.speed_mps - paper::value("trim_speed")).abs() < 1e-9);
        for kind in [ModeKind::ShortPeriod, ModeKind::Phugoid] {
            assert!(model.mode(kind).is_some() && model.paper_a_mode(kind).is_some());
            assert!(model.distance_from_paper_a(kind).is_finite());
        }
        assert!(model.gains.proportional_per_s2 > 0.0 && model.gains.derivative_per_s > 0.0);

        // Fig. 6: sampled every 0.05 s over the record, both ends included; the step
        // moves the airspeed, and each error is a fraction of its state's excursion.
        let open_loop = &r.open_loop;
        assert_eq!(open_loop.samples.len(), 20 * 20 + 1);
        assert!(open_loop.excursion[0] > 0.0);
        assert!(open_loop
            .relative_error
            .iter()
            .all(|e| (0.0..1.0).contains(e)));

        // Fig. 7, 8: every 10 ms over the record; seed 1 is among the peak seeds, and
        // the medians lie among the peaks.
        let environment = &r.environment;
        assert_eq!(environment.samples.len(), 20 * 100 + 1);
        assert_eq!(environment.record.seed, SEED);
        assert_eq!(environment.heave_peaks_m.len(), 3);
        assert_eq!(environment.pitch_peaks_deg.len(), 3);
        assert_eq!(environment.heave_peaks_m[0], environment.heave_peak_m);
        assert_eq!(
            environment.pitch_peaks_deg[0],
            environment.ship_pitch_peak_deg
        );
        let (low, high) = environment.wind_x_range_mps;
        assert!(low <= high);
        let within = |value: f64, values: &[f64]| {
            values.iter().any(|v| *v <= value) && values.iter().any(|v| *v >= value)
        };
        assert!(within(
            environment.median_heave_peak_m,
            &environment.heave_peaks_m
        ));
        assert!(within(
            environment.median_pitch_peak_deg,
            &environment.pitch_peaks_deg
        ));

        // Fig. 10–12: O-PD then PID, recorded; the studies over seeds count their runs.
        for runs in [&r.ideal_pitch_step, &r.adverse_pitch_step.runs] {
            assert_eq!(
                runs[0].response.controller,
                PaperPitchLaw::ObserverPd.parameters().label()
            );
            assert_eq!(
                runs[1].response.controller,
                PaperPitchLaw::Pid.parameters().label()
            );
            assert!(runs.iter().all(|run| !run.samples.is_empty()));
        }
        let adverse = &r.adverse_pitch_step;
        assert!(adverse.observer_pd_tracking_rms_deg > 0.0);
        for study in [&adverse.observer_pd_noiseless, &adverse.pid_seeds] {
            assert_eq!(study.responses.len(), 2);
            assert!(study.settled <= study.responses.len());
            assert_eq!(study.median_settling_s.is_finite(), study.settled > 0);
        }

        // Fig. 13: both runs recorded, the ramped one measured when it completed.
        let sink = &r.sink_rate;
        assert!(!sink.step.samples.is_empty() && !sink.ramp.samples.is_empty());
        assert_eq!(
            sink.ramp.metrics.is_some(),
            sink.ramp.summary.outcome == crate::simulation::Outcome::Completed
        );

        // Fig. 14, 15 and the boarding rate over 3 seeds.
        let approach = &r.approach;
        assert!(!approach.run.samples.is_empty());
        assert!(approach.pitch_tracking_rms_deg > 0.0);
        assert_eq!(approach.scenario.seed, SEED);
        assert_eq!(r.boarding.counts.runs, 3);
        assert_eq!(
            r.boarding.boarding_rate.count,
            r.boarding.counts.trap as u64
        );
        assert!(r.boarding.boarding_rate.ci95_low <= r.boarding.boarding_rate.rate);
    }

    #[test]
    fn the_paper_gains_scenario_flies_the_paper_gains() {
        let scenario = paper_gains_scenario(Conditions::Ideal);
        assert_eq!(scenario.control.sink_rate.proportional_rad_per_mps, 0.0061);
        assert_eq!(scenario.control.sink_rate.integral_rad_per_m, 0.018);
        assert_eq!(scenario.control.guidance.proportional_per_s, 1.0);
        assert_eq!(scenario.control.guidance.integral_per_s2, 0.5);
        assert_eq!(scenario.control.guidance.derivative, 0.01);
        assert_eq!(scenario.hardware, HardwareSet::Paper);
    }
}
