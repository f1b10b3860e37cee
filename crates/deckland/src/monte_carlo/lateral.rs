//! A 3-D approach campaign's lateral outcomes (docs/model.md §10.4; shared model §10.8):
//! the columns a 3-D campaign adds to `runs.csv`, and their statistics — off-centre
//! touchdowns with their Wilson interval, the lateral touchdown scatter, the share of
//! passes within ±0.5° of lineup at the ramp, and the drift and bank at touchdown
//! against their limits. A 3-DOF campaign has none of them.

use serde::Serialize;

use super::record::RunRecord;
use super::statistics::{Distribution, Proportion};
use crate::simulation::lateral::touchdown::{
    MAX_OFF_CENTRE_M, MAX_TOUCHDOWN_BANK_DEG, MAX_TOUCHDOWN_DRIFT_MPS,
};
use crate::simulation::lateral::LateralTouchdown;

/// The lineup error at the ramp a landing signal officer accepts in close (deg): about
/// ±0.5° (shared model §10.8).
pub const RAMP_LINEUP_PASS_DEG: f64 = 0.5;

/// The columns a 3-D campaign adds to `runs.csv`, after the others.
pub const LATERAL_RUN_COLUMNS: [&str; 6] = [
    "touchdown_lateral_offset_m",
    "touchdown_drift_rate_mps",
    "touchdown_bank_deg",
    "touchdown_heading_to_centreline_deg",
    "ramp_lineup_error_deg",
    "off_centre",
];

/// One run's values of [`LATERAL_RUN_COLUMNS`] (empty where it did not touch down).
pub type LateralRunValues = (
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<bool>,
);

/// The lateral outcome of `record`, if it is a 3-D approach that touched down.
pub fn lateral_touchdown(record: &RunRecord) -> Option<LateralTouchdown> {
    record.result.as_ref().ok()?.touchdown?.lateral
}

/// The values of [`LATERAL_RUN_COLUMNS`] for `record`.
pub fn lateral_run_values(record: &RunRecord) -> LateralRunValues {
    let lateral = lateral_touchdown(record);
    (
        lateral.map(|l| l.offset_m),
        lateral.map(|l| l.drift_rate_mps),
        lateral.map(|l| l.bank_deg),
        lateral.map(|l| l.heading_to_centreline_deg),
        lateral.and_then(|l| l.ramp_lineup_error_deg),
        lateral.map(|l| l.off_centre),
    )
}

/// The lateral statistics of a 3-D campaign's touchdowns.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LateralStatistics {
    /// Touchdowns with a lateral outcome.
    pub touchdowns: u64,
    /// Off-centre touchdowns (beyond `max_off_centre_m`), a share of the touchdowns.
    pub off_centre: Proportion,
    /// The off-centre limit (m).
    pub max_off_centre_m: f64,
    /// Lateral offset of the hook from the centreline at touchdown (m).
    pub lateral_offset_m: Option<Distribution>,
    /// Drift across the centreline relative to the deck at touchdown (m/s).
    pub drift_rate_mps: Option<Distribution>,
    /// Bank at touchdown (deg).
    pub bank_deg: Option<Distribution>,
    /// Heading to the centreline at touchdown (deg).
    pub heading_to_centreline_deg: Option<Distribution>,
    /// Lineup error at the ramp (deg).
    pub ramp_lineup_error_deg: Option<Distribution>,
    /// Passes within ±[`RAMP_LINEUP_PASS_DEG`] at the ramp, a share of those that
    /// crossed it.
    pub ramp_lineup_within_half_degree: Proportion,
    /// Touchdowns with |drift| beyond the limit.
    pub drift_beyond_limit: Proportion,
    /// The drift limit at touchdown (m/s).
    pub max_drift_rate_mps: f64,
    /// Touchdowns with |bank| beyond the limit.
    pub bank_beyond_limit: Proportion,
    /// The bank limit at touchdown (deg).
    pub max_bank_deg: f64,
}

impl LateralStatistics {
    /// The statistics of `records`' lateral touchdowns; `None` when none has one (a
    /// 3-DOF campaign).
    pub fn of(records: &[RunRecord]) -> Option<Self> {
        let touchdowns: Vec<LateralTouchdown> =
            records.iter().filter_map(lateral_touchdown).collect();
        if touchdowns.is_empty() {
            return None;
        }
        let n = touchdowns.len() as u64;
        let count = |test: &dyn Fn(&LateralTouchdown) -> bool| {
            touchdowns.iter().filter(|t| test(t)).count() as u64
        };
        let ramp: Vec<f64> = touchdowns
            .iter()
            .filter_map(|t| t.ramp_lineup_error_deg)
            .collect();
        let within = ramp
            .iter()
            .filter(|e| e.abs() <= RAMP_LINEUP_PASS_DEG)
            .count() as u64;
        Some(Self {
            touchdowns: n,
            off_centre: Proportion::new(count(&|t| t.off_centre), n),
            max_off_centre_m: MAX_OFF_CENTRE_M,
            lateral_offset_m: Distribution::of(touchdowns.iter().map(|t| t.offset_m)),
            drift_rate_mps: Distribution::of(touchdowns.iter().map(|t| t.drift_rate_mps)),
            bank_deg: Distribution::of(touchdowns.iter().map(|t| t.bank_deg)),
            heading_to_centreline_deg: Distribution::of(
                touchdowns.iter().map(|t| t.heading_to_centreline_deg),
            ),
            ramp_lineup_error_deg: Distribution::of(ramp.iter().copied()),
            ramp_lineup_within_half_degree: Proportion::new(within, ramp.len() as u64),
            drift_beyond_limit: Proportion::new(
                count(&|t| t.drift_rate_mps.abs() > MAX_TOUCHDOWN_DRIFT_MPS),
                n,
            ),
            max_drift_rate_mps: MAX_TOUCHDOWN_DRIFT_MPS,
            bank_beyond_limit: Proportion::new(
                count(&|t| t.bank_deg.abs() > MAX_TOUCHDOWN_BANK_DEG),
                n,
            ),
            max_bank_deg: MAX_TOUCHDOWN_BANK_DEG,
        })
    }
}
