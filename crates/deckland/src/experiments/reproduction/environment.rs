//! The ship motion and the wind of the paper's scenario (Fig. 7, 8): one record, and the
//! peaks of many seeds' records against the paper's stated maxima (§3.5).

use super::{ReproductionError, ReproductionLengths, HARDWARE, SEED, WIND_DISTANCE_AFT_M};
use crate::analysis::TrimPoint;
use crate::experiments::{record_environment, EnvironmentRecord, EnvironmentSample};
use crate::metrics::median;
use crate::scenario::EnvironmentSection;

/// The environment record of seed [`SEED`] and the peaks of seeds 1..=N.
#[derive(Debug, Clone)]
pub struct EnvironmentStudy {
    /// The paper's environment.
    pub parameters: EnvironmentSection,
    /// What was recorded (seed [`SEED`]).
    pub record: EnvironmentRecord,
    /// The record.
    pub samples: Vec<EnvironmentSample>,
    /// Peak |heave| of the record (m).
    pub heave_peak_m: f64,
    /// Peak |ship pitch| of the record (deg).
    pub ship_pitch_peak_deg: f64,
    /// Peak |landing-point height about its mean| of the record (m).
    pub landing_point_peak_m: f64,
    /// Smallest and largest x-wind of the record (m/s).
    pub wind_x_range_mps: (f64, f64),
    /// Peak |heave| of each record of seeds 1..=N (m).
    pub heave_peaks_m: Vec<f64>,
    /// Peak |ship pitch| of each record of seeds 1..=N (deg).
    pub pitch_peaks_deg: Vec<f64>,
    /// The median of [`Self::heave_peaks_m`] (m).
    pub median_heave_peak_m: f64,
    /// The median of [`Self::pitch_peaks_deg`] (deg).
    pub median_pitch_peak_deg: f64,
}

/// The largest |`value`| over `samples` (0 for none).
fn peak(samples: &[EnvironmentSample], value: fn(&EnvironmentSample) -> f64) -> f64 {
    samples
        .iter()
        .map(|s| value(s).abs())
        .fold(0.0_f64, f64::max)
}

/// Records the paper's environment for `lengths.environment_s` (the wind
/// [`WIND_DISTANCE_AFT_M`] aft, its turbulence at the speed of `trim`) with seed [`SEED`],
/// and the peaks of seeds 1..=`lengths.peak_seeds`.
pub fn study_environment(
    trim: &TrimPoint,
    lengths: &ReproductionLengths,
) -> Result<EnvironmentStudy, ReproductionError> {
    let parameters = HARDWARE.scenario().environment;
    parameters
        .validate()
        .map_err(ReproductionError::Environment)?;
    let record = EnvironmentRecord {
        seconds: lengths.environment_s,
        seed: SEED,
        distance_aft_m: WIND_DISTANCE_AFT_M,
        airspeed_mps: trim.speed_mps,
    };
    let fly = |record: &EnvironmentRecord| {
        record_environment(&parameters, record).map_err(ReproductionError::experiment(format!(
            "the environment record of seed {}",
            record.seed
        )))
    };
    let samples = fly(&record)?;
    let wind_x_range_mps = samples
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(low, high), s| {
            (low.min(s.wind_x_mps), high.max(s.wind_x_mps))
        });
    let mut heave_peaks_m = Vec::new();
    let mut pitch_peaks_deg = Vec::new();
    for seed in 1..=lengths.peak_seeds {
        let seed_samples = fly(&EnvironmentRecord { seed, ..record })?;
        heave_peaks_m.push(peak(&seed_samples, |s| s.heave_m));
        pitch_peaks_deg.push(peak(&seed_samples, |s| s.pitch_deg));
    }
    Ok(EnvironmentStudy {
        parameters,
        record,
        heave_peak_m: peak(&samples, |s| s.heave_m),
        ship_pitch_peak_deg: peak(&samples, |s| s.pitch_deg),
        landing_point_peak_m: peak(&samples, |s| s.landing_point_height_m),
        wind_x_range_mps,
        median_heave_peak_m: median(heave_peaks_m.iter().copied()),
        median_pitch_peak_deg: median(pitch_peaks_deg.iter().copied()),
        heave_peaks_m,
        pitch_peaks_deg,
        samples,
    })
}
