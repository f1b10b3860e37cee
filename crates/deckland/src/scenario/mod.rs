//! A scenario: every parameter of one run, with the defaults of MODEL.md.
//!
//! The structure mirrors the scenario file (TOML) section by section; units are in the
//! field names. [`Scenario::validate`] checks every field before a run starts;
//! [`load_scenario`] reads a scenario file and reports a bad one by file, line and field;
//! [`DEFAULT_SCENARIO_TOML`] is the commented default file.

use crate::aircraft::{
    AerodynamicConfiguration, AircraftParameters, ConfigurationName, ElevatorActuatorParameters,
    EngineParameters, HookGeometry,
};
use crate::control::pitch::PitchControllerParameters;
use crate::control::{
    FlightPathParameters, GuidanceParameters, SinkRateControllerParameters,
    SpeedControllerParameters,
};
use crate::environment::EnvironmentParameters;
use serde::{Deserialize, Serialize};

mod dispersion;
mod file;
mod template;

pub use dispersion::{DispersionParameters, DispersionSample, DISPERSION_STREAM};
pub use file::{load_scenario, ScenarioError};
pub use template::DEFAULT_SCENARIO_TOML;

/// The aircraft section of a scenario.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct AircraftSection {
    /// Aerodynamic configuration: `landing` (default) or `clean` (MODEL.md §2.3).
    pub configuration: ConfigurationName,
    /// Mass, geometry, atmosphere (paper Table 2).
    pub parameters: AircraftParameters,
    /// Engines (MODEL.md §2.5).
    pub engines: EngineParameters,
    /// Elevator actuator (MODEL.md §2.6).
    pub elevator_actuator: ElevatorActuatorParameters,
    /// Hook point (MODEL.md §2.7).
    pub hook: HookGeometry,
}

impl AircraftSection {
    /// The aerodynamic increments of the named configuration.
    pub fn aerodynamics(&self) -> AerodynamicConfiguration {
        AerodynamicConfiguration::named(self.configuration)
    }
}

/// The controllers of the cascade (MODEL.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ControlSection {
    /// Pitch controller: O-PD (default) or PID.
    pub pitch: PitchControllerParameters,
    /// Speed (thrust) loop.
    pub speed: SpeedControllerParameters,
    /// Sink-rate (pitch command) loop.
    pub sink_rate: SinkRateControllerParameters,
    /// Guidance (climb-rate command) loop.
    pub guidance: GuidanceParameters,
    /// Glide path and deck-motion compensation.
    pub flight_path: FlightPathParameters,
}

/// The start of an approach (MODEL.md §6).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ApproachParameters {
    /// Range of the hook before the (mean) landing point at the start (m); 1500 m.
    pub start_range_m: f64,
    /// Approach airspeed, the speed loop's reference (m/s); 69.1 m/s (Table 3).
    pub airspeed_mps: f64,
    /// Start height of the hook above the glide path (m); 0.
    pub start_height_offset_m: f64,
}

impl Default for ApproachParameters {
    fn default() -> Self {
        Self {
            start_range_m: 1500.0,
            airspeed_mps: 69.1,
            start_height_offset_m: 0.0,
        }
    }
}

/// Limits that classify a landing (MODEL.md §7).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OutcomeLimits {
    /// Touchdown sink rate relative to the deck above which a landing is hard (m/s).
    pub hard_landing_sink_rate_mps: f64,
    /// Airspeed below which the run is declared diverged (m/s).
    pub min_airspeed_mps: f64,
}

impl Default for OutcomeLimits {
    fn default() -> Self {
        Self {
            hard_landing_sink_rate_mps: 7.6,
            min_airspeed_mps: 30.0,
        }
    }
}

/// What the run flies.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum Mission {
    /// The full approach and landing on the moving deck (paper §4, Fig. 14–15).
    #[default]
    Approach,
    /// A pitch-attitude step from level trim, outer loops off (paper Fig. 10–12).
    PitchStep {
        /// Step size (deg), positive nose-up.
        step_deg: f64,
        /// Time of the step after the start (s).
        step_time_s: f64,
        /// Length of the run (s).
        duration_s: f64,
        /// Distance of the aircraft aft of the ship's pitch centre at the start (m),
        /// which sets the air wake it flies through.
        start_distance_aft_m: f64,
        /// Altitude (m).
        altitude_m: f64,
    },
    /// Tracking a constant commanded sink rate from level trim (paper Fig. 13).
    SinkRate {
        /// Commanded sink rate (m/s, positive down).
        sink_rate_mps: f64,
        /// Time of the command after the start (s).
        step_time_s: f64,
        /// Time over which the command (and its pitch feed-forward) ramps from zero to its
        /// value (s); 0 is a step.
        ramp_s: f64,
        /// Length of the run (s).
        duration_s: f64,
        /// Altitude at the start (m).
        altitude_m: f64,
    },
}

impl Mission {
    /// A pitch step of `step_deg` lasting `duration_s`, with the other defaults.
    pub fn pitch_step(step_deg: f64, duration_s: f64) -> Self {
        Self::PitchStep {
            step_deg,
            step_time_s: 1.0,
            duration_s,
            start_distance_aft_m: 1000.0,
            altitude_m: 150.0,
        }
    }

    /// A sink-rate command of `sink_rate_mps` ramped in over `ramp_s` and lasting
    /// `duration_s`, with the other defaults.
    pub fn sink_rate(sink_rate_mps: f64, ramp_s: f64, duration_s: f64) -> Self {
        Self::SinkRate {
            sink_rate_mps,
            step_time_s: 1.0,
            ramp_s,
            duration_s,
            altitude_m: 600.0,
        }
    }
}

/// Every parameter of one run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scenario {
    /// Seed of every random stream (MODEL.md §3.4).
    pub seed: u64,
    /// Integration step (s); 1 ms (MODEL.md §6).
    pub time_step_s: f64,
    /// Time limit of an approach (s).
    pub max_time_s: f64,
    /// What the run flies.
    pub mission: Mission,
    /// The aircraft.
    pub aircraft: AircraftSection,
    /// Ship motion, deck geometry, wind and sensor noise.
    pub environment: EnvironmentParameters,
    /// The controllers.
    pub control: ControlSection,
    /// The start of an approach.
    pub approach: ApproachParameters,
    /// Landing classification limits.
    pub outcome: OutcomeLimits,
    /// Per-run dispersions of a Monte Carlo campaign (none by default; a single run
    /// ignores them).
    pub dispersion: DispersionParameters,
}

impl Default for Scenario {
    /// Adverse conditions (every disturbance at its default), O-PD pitch control.
    fn default() -> Self {
        Self {
            seed: 1,
            time_step_s: 0.001,
            max_time_s: 60.0,
            mission: Mission::Approach,
            aircraft: AircraftSection::default(),
            environment: EnvironmentParameters::default(),
            control: ControlSection::default(),
            approach: ApproachParameters::default(),
            outcome: OutcomeLimits::default(),
            dispersion: DispersionParameters::default(),
        }
    }
}

impl Scenario {
    /// Switches off every disturbance: no wind, no sensor noise, no deck motion.
    pub fn ideal(mut self) -> Self {
        let env = &mut self.environment;
        env.ship.enabled = false;
        env.wind.mean_wind = false;
        env.wind.turbulence = false;
        env.wind.steady_wake = false;
        env.wind.periodic_wake = false;
        env.pitch_noise.enabled = false;
        self
    }
}
