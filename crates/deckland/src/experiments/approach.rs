//! One approach to the deck, recorded.

use serde::Serialize;

use super::ExperimentError;
use crate::recording::TimeSeriesRecorder;
use crate::scenario::{Mission, Scenario};
use crate::simulation::{Event, PitchLawFactory, RunSummary, Signals, Simulation};

/// How often an approach's time series is recorded (s of simulated time): every 10 ms.
pub const APPROACH_RECORD_INTERVAL_S: f64 = 0.01;

/// A flown approach: every signal each [`APPROACH_RECORD_INTERVAL_S`], the events and
/// the summary.
#[derive(Debug, Clone)]
pub struct ApproachRun {
    /// The recorded signals, in time order (the last step always included).
    pub samples: Vec<Signals>,
    /// Ramp crossing, touchdown, passing the last wire.
    pub events: Vec<Event>,
    /// How it ended and what it measured.
    pub summary: RunSummary,
}

/// Flies `scenario` as an approach (whatever its mission says) and records it.
pub fn fly_approach(scenario: &Scenario) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::new(&scenario)?)
}

/// As [`fly_approach`], with a user's own pitch law flying.
pub fn fly_approach_with_law(
    scenario: &Scenario,
    pitch_law: &PitchLawFactory,
) -> Result<ApproachRun, ExperimentError> {
    let scenario = approach_of(scenario);
    record(Simulation::with_pitch_law(&scenario, pitch_law)?)
}

fn approach_of(scenario: &Scenario) -> Scenario {
    Scenario {
        mission: Mission::Approach,
        ..*scenario
    }
}

fn record(simulation: Simulation) -> Result<ApproachRun, ExperimentError> {
    let mut recorder = TimeSeriesRecorder::every(APPROACH_RECORD_INTERVAL_S);
    let summary = simulation.run(&mut recorder);
    Ok(ApproachRun {
        samples: recorder.samples,
        events: recorder.events,
        summary,
    })
}

/// One recorded instant of an approach as a flat row (SI units, angles in degrees): the
/// columns of the CLI's `approach.csv` and of the Python package's time series.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ApproachRow {
    /// Time (s).
    pub time_s: f64,
    /// CG earth x (m).
    pub x_m: f64,
    /// CG altitude (m).
    pub altitude_m: f64,
    /// Hook height (m).
    pub hook_height_m: f64,
    /// Reference height of the hook on the glide path (m); none before the path is
    /// captured.
    pub glide_path_height_m: Option<f64>,
    /// Glide-path error h_ref − h_hook (m), positive when below the path.
    pub glide_path_error_m: f64,
    /// Height of the moving landing point (m).
    pub landing_point_height_m: f64,
    /// True airspeed (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack (deg).
    pub alpha_deg: f64,
    /// Pitch angle (deg).
    pub theta_deg: f64,
    /// Pitch command θ_ref (deg).
    pub theta_command_deg: f64,
    /// Measured pitch angle (deg).
    pub theta_measured_deg: f64,
    /// CG climb rate (m/s).
    pub climb_rate_mps: f64,
    /// Climb-rate command (m/s); none where no sink-rate loop flies.
    pub climb_rate_command_mps: Option<f64>,
    /// Elevator position (deg).
    pub elevator_deg: f64,
    /// Elevator command (deg).
    pub elevator_command_deg: f64,
    /// Total actual thrust (N).
    pub thrust_n: f64,
    /// Total thrust command (N).
    pub thrust_command_n: f64,
    /// Wind at the aircraft, x positive forward (m/s).
    pub wind_x_mps: f64,
    /// Wind at the aircraft, z positive down (m/s).
    pub wind_z_mps: f64,
    /// Distance of the CG aft of the ship's pitch centre (m).
    pub distance_aft_m: f64,
    /// Ship heave (m).
    pub ship_heave_m: f64,
    /// Ship pitch (deg).
    pub ship_pitch_deg: f64,
    /// The pitch law's disturbance estimate (rad/s²), if it has one.
    pub disturbance_estimate_radps2: Option<f64>,
}

impl From<&Signals> for ApproachRow {
    fn from(s: &Signals) -> Self {
        Self {
            time_s: s.time_s,
            x_m: s.x_m,
            altitude_m: s.h_m,
            hook_height_m: s.hook_h_m,
            glide_path_height_m: s.path_height_m,
            glide_path_error_m: s.glide_path_error_m,
            landing_point_height_m: s.aim_point.h_m,
            airspeed_mps: s.airspeed_mps,
            alpha_deg: s.alpha_rad.to_degrees(),
            theta_deg: s.theta_rad.to_degrees(),
            theta_command_deg: s.theta_ref_rad.to_degrees(),
            theta_measured_deg: s.theta_measured_rad.to_degrees(),
            climb_rate_mps: s.climb_rate_mps,
            climb_rate_command_mps: s.climb_rate_command_mps,
            elevator_deg: s.elevator_rad.to_degrees(),
            elevator_command_deg: s.elevator_command_rad.to_degrees(),
            thrust_n: s.thrust_n,
            thrust_command_n: s.thrust_command_n,
            wind_x_mps: s.wind.x_mps,
            wind_z_mps: s.wind.z_mps,
            distance_aft_m: s.distance_aft_m,
            ship_heave_m: s.ship.heave_m,
            ship_pitch_deg: s.ship.pitch_rad.to_degrees(),
            disturbance_estimate_radps2: s.disturbance_estimate_radps2,
        }
    }
}
