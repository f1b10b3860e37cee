//! The `[approach]` section: where and how fast an approach starts, and whether a 6-DOF
//! aircraft flies it in three dimensions.

use crate::parameters::{Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// The start of an approach (docs/model.md §6).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ApproachParameters {
    /// Range of the hook before the (mean) landing point at the start (m); 1500 m.
    pub start_range_m: f64,
    /// Approach airspeed, the speed loop's reference (m/s); 69.1 m/s (Table 3).
    pub airspeed_mps: f64,
    /// Start height of the hook above the glide path (m); 0.
    pub start_height_offset_m: f64,
    /// Whether a 6-DOF aircraft flies the 3-D carrier approach (docs/model.md §10.1):
    /// the angled deck on a steaming ship that rolls, yaws and sways, the 3-D wind, and
    /// lineup through the roll and yaw laws; `false` flies the 3-DOF's environment with
    /// the lateral surfaces held at trim. The 3-DOF aircraft ignores it. Default true
    /// (written out only when false, so that files written before it are unchanged).
    #[serde(skip_serializing_if = "is_true")]
    pub three_dimensional: bool,
}

/// Whether `value` holds (serde's `skip_serializing_if` of a key true by default).
fn is_true(value: &bool) -> bool {
    *value
}

impl ApproachParameters {
    /// Checks the start range (200–10000 m), airspeed (40–150 m/s) and height offset
    /// (±50 m).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "approach";
        Bounds::closed(200.0, 10_000.0).check(SECTION, "start_range_m", self.start_range_m)?;
        Bounds::closed(40.0, 150.0).check(SECTION, "airspeed_mps", self.airspeed_mps)?;
        Bounds::closed(-50.0, 50.0).check(
            SECTION,
            "start_height_offset_m",
            self.start_height_offset_m,
        )
    }
}

impl Default for ApproachParameters {
    fn default() -> Self {
        Self {
            start_range_m: 1500.0,
            airspeed_mps: 69.1,
            start_height_offset_m: 0.0,
            three_dimensional: true,
        }
    }
}
