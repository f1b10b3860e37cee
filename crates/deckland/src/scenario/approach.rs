//! The `[approach]` section: where and how fast an approach starts, and whether a 6-DOF
//! aircraft flies it in three dimensions.

use crate::parameters::{check_ranges, Bounds, ParameterError};
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
    /// 3-D approach: natural frequency of the lineup guidance in close (rad/s), (0, 2],
    /// blended in from its 0.4 rad/s far out with the deck-motion compensation
    /// (docs/model.md §10.2); 0.8, tuned on crosswind campaigns
    /// (docs/three-d-approach.md).
    pub lineup_close_frequency_radps: f64,
    /// 3-D approach: the station of the landing centreline the lineup compensation aims
    /// the hook at in close, aft of the aim point (m), [0, 200]: its forecast position
    /// when the hook crosses it (docs/model.md §10.3); 60, the ramp, where the landing
    /// signal officer grades lineup (shared model §10.8); 0, the aim point at touchdown.
    pub lineup_station_aft_m: f64,
    /// 3-D approach: the time to go at which the yaw law starts to hold the crab heading
    /// instead of zero sideslip (s), [0, 60]; 0: never (docs/model.md §10.2). 12, with
    /// the deck-motion compensation (an assumption, docs/three-d-approach.md).
    pub heading_hold_time_to_go_s: f64,
    /// 3-D approach: the time over which the heading hold blends in (s), (0, 30]; 2.
    pub heading_hold_blend_s: f64,
}

/// Whether `value` holds (serde's `skip_serializing_if` of a key true by default).
fn is_true(value: &bool) -> bool {
    *value
}

impl ApproachParameters {
    /// Checks the start range (200–10000 m), airspeed (40–150 m/s), height offset
    /// (±50 m) and the 3-D approach's lineup and heading-hold keys (their ranges above).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "approach";
        check_ranges!(SECTION, self, {
            start_range_m: Bounds::closed(200.0, 10_000.0),
            airspeed_mps: Bounds::closed(40.0, 150.0),
            start_height_offset_m: Bounds::closed(-50.0, 50.0),
            lineup_close_frequency_radps: Bounds::closed(0.0, 2.0).exclusive_min(),
            lineup_station_aft_m: Bounds::closed(0.0, 200.0),
            heading_hold_time_to_go_s: Bounds::closed(0.0, 60.0),
            heading_hold_blend_s: Bounds::closed(0.0, 30.0).exclusive_min(),
        });
        Ok(())
    }
}

impl Default for ApproachParameters {
    fn default() -> Self {
        Self {
            start_range_m: 1500.0,
            airspeed_mps: 69.1,
            start_height_offset_m: 0.0,
            three_dimensional: true,
            lineup_close_frequency_radps: 0.8,
            lineup_station_aft_m: 60.0,
            heading_hold_time_to_go_s: 12.0,
            heading_hold_blend_s: 2.0,
        }
    }
}
