//! One campaign run as a flat row: the columns of the CLI's `runs.csv` and of the
//! Python package's campaign table, defined once. A row reads back from `runs.csv`
//! exactly (`Deserialize`: numbers are written in their shortest round-trip form), which
//! is what lets shards be merged into the campaign they are part of.

use std::borrow::Cow;

use serde::{Deserialize, Serialize};

use super::campaign::RunRecord;

/// One run of a campaign under one controller, flattened (outcome, wire, touchdown, ramp
/// clearance, glide-path error, the actuators' activity, the dispersions drawn, the failure reason). Fields that
/// a run did not produce (no touchdown, a failed setup) are `None`.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct RunRow<'a> {
    /// Index of the run (from 0).
    pub run_index: u64,
    /// The controller's label (`?` if the record names no known controller).
    pub controller: Cow<'a, str>,
    /// The run's seed.
    pub seed: u64,
    /// The outcome's name, `invalid` or `panicked`.
    pub outcome: Cow<'a, str>,
    /// Wire caught (1–4).
    pub wire: Option<u8>,
    /// Touchdown point from the aim point (m, positive forward).
    pub touchdown_distance_m: Option<f64>,
    /// Touchdown sink rate relative to the deck (m/s).
    pub touchdown_sink_rate_mps: Option<f64>,
    /// Pitch attitude at touchdown (deg).
    pub touchdown_pitch_deg: Option<f64>,
    /// Airspeed at touchdown (m/s).
    pub touchdown_airspeed_mps: Option<f64>,
    /// Hook height above the ramp as it crossed it (m).
    pub ramp_clearance_m: Option<f64>,
    /// RMS glide-path error over the approach (m).
    pub glide_path_error_rms_m: Option<f64>,
    /// Largest absolute glide-path error (m).
    pub glide_path_error_max_m: Option<f64>,
    /// Simulated time at the end (s).
    pub end_time_s: Option<f64>,
    /// RMS elevator rate (deg/s).
    pub elevator_rate_rms_degps: Option<f64>,
    /// Share of the run with the elevator at its rate limit (%).
    pub time_on_rate_limit_pct: Option<f64>,
    /// Share of the run with the elevator on a travel stop (%).
    pub time_on_stops_pct: Option<f64>,
    /// Total elevator travel Σ|Δδe| (deg).
    pub elevator_travel_deg: Option<f64>,
    /// RMS rate of the total thrust (kN/s).
    pub thrust_rate_rms_knps: Option<f64>,
    /// Dispersion of the start height above the glide path (m).
    pub start_height_offset_dispersion_m: f64,
    /// Dispersion of the approach airspeed (m/s).
    pub airspeed_dispersion_mps: f64,
    /// Factor on the ship's heave and pitch RMS (–).
    pub sea_state_scale: f64,
    /// Dispersion of the wind over deck (m/s).
    pub wind_over_deck_dispersion_mps: f64,
    /// Why the run did not trap, in words.
    pub reason: Option<String>,
}

impl<'a> RunRow<'a> {
    /// The row of `record`, its controller named from `labels`
    /// ([`super::CampaignResult::controller_labels`]).
    pub fn new(record: &RunRecord, labels: &'a [String]) -> Self {
        Self::with_controller(
            record,
            labels.get(record.controller).map_or("?", String::as_str),
        )
    }

    /// The row of `record`, its controller labelled `controller`.
    pub fn with_controller(record: &RunRecord, controller: &'a str) -> Self {
        let summary = record.result.as_ref().ok();
        let touchdown = summary.and_then(|s| s.touchdown);
        Self {
            run_index: record.run_index,
            controller: Cow::Borrowed(controller),
            seed: record.seed,
            outcome: Cow::Borrowed(record.outcome_name()),
            wire: summary.and_then(|s| s.wire),
            touchdown_distance_m: touchdown.map(|t| t.distance_from_aim_m),
            touchdown_sink_rate_mps: touchdown.map(|t| t.sink_rate_mps),
            touchdown_pitch_deg: touchdown.map(|t| t.pitch_deg),
            touchdown_airspeed_mps: touchdown.map(|t| t.airspeed_mps),
            ramp_clearance_m: summary.and_then(|s| s.ramp_clearance_m),
            glide_path_error_rms_m: summary.and_then(|s| s.glide_path_error_rms_m),
            glide_path_error_max_m: summary.and_then(|s| s.glide_path_error_max_m),
            end_time_s: summary.map(|s| s.end_time_s),
            elevator_rate_rms_degps: summary.map(|s| s.actuator.elevator_rate_rms_degps),
            time_on_rate_limit_pct: summary.map(|s| s.actuator.time_on_rate_limit_pct),
            time_on_stops_pct: summary.map(|s| s.actuator.time_on_stops_pct),
            elevator_travel_deg: summary.map(|s| s.actuator.elevator_travel_deg),
            thrust_rate_rms_knps: summary.map(|s| s.actuator.thrust_rate_rms_knps),
            start_height_offset_dispersion_m: record.dispersion.start_height_offset_m,
            airspeed_dispersion_mps: record.dispersion.airspeed_error_mps,
            sea_state_scale: record.dispersion.sea_state_scale,
            wind_over_deck_dispersion_mps: record.dispersion.wind_over_deck_error_mps,
            reason: record.failure_reason(),
        }
    }

    /// Whether the run flew (its scenario could be set up): only a flown run has an end
    /// time.
    pub fn flown(&self) -> bool {
        self.end_time_s.is_some()
    }
}
