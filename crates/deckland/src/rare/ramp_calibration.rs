//! The ramp score's calibration (`deckland rare --calibrate-score RUNS`): how far the
//! score's forecast of the hook's clearance over the ramp misses, by how long before the
//! crossing it is made, over a scenario's first flights ([`RampCalibration::of`] and
//! [`RampCalibration::fly`] in `super::ramp_forecast`, which flies them).

use serde::Serialize;

/// The ramp forecast's misses by how far before the crossing it is made: the mean and
/// the spread (SD) of the clearance flown less the forecast ĉ, over a scenario's first
/// flights, in bins of [`RampCalibration::BIN_S`]. The calibrated ramp score forecasts
/// ĉ + mean and divides by the spread: the forecast then carries what the guidance does
/// between now and the ramp (the path's raise and its shed past the ramp, docs/model.md
/// §5.7), which the plain forecast does not, and its σ is the sea's own, not one fitted
/// in the paper's sea (docs/rare-events.md).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RampCalibration {
    /// Mean miss in each bin, from τ = 0 (m).
    pub mean_miss_m: Vec<f64>,
    /// SD of the miss in each bin (m).
    pub spread_m: Vec<f64>,
    /// The flights that crossed the ramp and were counted.
    pub flights: usize,
}

impl RampCalibration {
    /// The width of a bin of τ, the time before the crossing (s).
    pub const BIN_S: f64 = 0.1;

    /// The smallest spread the calibrated score divides by (m), there and at the
    /// crossing: a bin of flights that all missed alike would otherwise make it 0.
    pub const MIN_SPREAD_M: f64 = 0.01;

    /// The time constant of the first-order lag through which the calibrated score
    /// passes its forecast margin (s). Calibrated, the forecast's misses are nearly
    /// independent from one tenth of a second to the next, and the running maximum of an
    /// unlagged score marks their peaks: copies branched there fly on below them, tie and
    /// go extinct (8 of 8 repetitions in sea state 5 at 2.81 m with 300 particles,
    /// measured without the lag; docs/rare-events.md). Over 1 s the peaks average out.
    pub const LAG_S: f64 = 1.0;

    /// The mean miss and its spread `ahead_s` before the crossing (m): the bin's, or the
    /// last bin's beyond it.
    pub fn at(&self, ahead_s: f64) -> (f64, f64) {
        let last = self.mean_miss_m.len().saturating_sub(1);
        let bin = ((ahead_s.max(0.0) / Self::BIN_S) as usize).min(last);
        (self.mean_miss_m[bin], self.spread_m[bin])
    }

    /// The spread at the crossing (m): the first bin's.
    pub fn spread_now_m(&self) -> f64 {
        self.spread_m[0]
    }
}
