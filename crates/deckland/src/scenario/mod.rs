//! A scenario: every parameter of one run, with the defaults of docs/model.md.
//!
//! The structure mirrors the scenario file (TOML) section by section; units are in the
//! field names. Each section checks its own fields ([`crate::parameters`]: one error
//! shape, naming the dotted path, the value and the allowed range);
//! [`Scenario::validate`] checks every section before a run starts;
//! [`load_scenario`] reads a scenario file and reports a bad one by file, line and field;
//! [`DEFAULT_SCENARIO_TOML`] is the commented default file.

use crate::control::lateral::{LateralChannel, LateralLawParameters};
use crate::control::pitch::PitchControllerParameters;
use crate::control::{
    ArrivalTimingParameters, DirectLiftParameters, FlightPathParameters, GuidanceParameters,
    SinkRateControllerParameters, SpeedControllerParameters, WaveOffParameters,
};
use crate::environment::seaway::SeawayParameters;
use crate::environment::{
    resolved_ship_parameters, DeckGeometry, ShipMotion, ShipMotionParameters, WindParameters,
};
use crate::parameters::{check_ranges, Bounds, ParameterError};
use crate::sensors::{PitchNoiseParameters, ShipMotionSensingParameters};
use serde::{Deserialize, Serialize};

mod aircraft;
mod approach;
mod dispersion;
mod file;
mod hardware;
mod lateral;
mod template;
/// Refuses an O-PD's `observer` (its section `section`) that the integration step `dt`
/// does not resolve: k3·dt/ε above 0.5, named on its `epsilon`.
fn check_observer_resolved(
    observer: &crate::estimation::ObserverParameters,
    section: &str,
    dt: f64,
) -> Result<(), ParameterError> {
    if observer.k3 / observer.epsilon * dt > 0.5 {
        return Err(ParameterError::new(
            section,
            "epsilon",
            observer.epsilon,
            format_args!(
                "at least {:?} with k3 = {} and time_step_s = {dt}, so that the \
                 observer (k3/ε rad/s) is resolved by the integration step",
                observer.k3 * dt / 0.5,
                observer.k3
            ),
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests;

pub use aircraft::{AircraftDefinition, AircraftSection, FA18_DEFINITION_TOML};
pub use approach::ApproachParameters;
pub use dispersion::{DispersionParameters, DispersionSample, DISPERSION_STREAM};
pub use file::{
    load_aircraft_definition, load_scenario, load_scenario_in, read_text_file, ReadError,
    ScenarioError, MAX_AIRCRAFT_FILE_BYTES, MAX_SCENARIO_FILE_BYTES,
};
pub use hardware::HardwareSet;
pub use template::DEFAULT_SCENARIO_TOML;

/// The environment section of a scenario (docs/model.md §3; deck geometry §2.7).
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(default, deny_unknown_fields)]
pub struct EnvironmentSection {
    /// Ship heave and pitch (docs/model.md §3.1); a file with no `[environment.ship]`
    /// names no ship model ([`ShipMotionParameters::named_by_none`]).
    #[serde(default = "ShipMotionParameters::named_by_none")]
    pub ship: ShipMotionParameters,
    /// The seaway of the `seaway` ship model (docs/model.md §12): read only when
    /// `ship.model = "seaway"`.
    pub seaway: SeawayParameters,
    /// Deck geometry (docs/model.md §2.7).
    pub deck: DeckGeometry,
    /// Wind and air wake (docs/model.md §3.2).
    pub wind: WindParameters,
    /// Pitch-attitude measurement noise (docs/model.md §3.3).
    pub pitch_noise: PitchNoiseParameters,
    /// The ship's motion as its inertial navigation measures it and the data link
    /// delivers it to the aircraft (docs/model.md §3.5).
    pub ship_sensing: ShipMotionSensingParameters,
}

impl EnvironmentSection {
    /// The environment of a scenario file with no `[environment]`: the built-in
    /// default's, with the ship of a file that names no model
    /// ([`ShipMotionParameters::named_by_none`]).
    pub fn named_by_none() -> Self {
        Self {
            ship: ShipMotionParameters::named_by_none(),
            ..Self::default()
        }
    }

    /// The ship motion this environment's ship model builds (its `ship` and `seaway`).
    pub fn ship_motion(&self) -> Result<ShipMotion, ParameterError> {
        crate::environment::ship_motion(&self.ship, &self.seaway)
    }

    /// The ship parameters as flown: the RMS of heave, pitch and roll the model gives.
    pub fn resolved_ship(&self) -> Result<ShipMotionParameters, ParameterError> {
        Ok(resolved_ship_parameters(&self.ship, &self.seaway)?.0)
    }

    /// Checks every part of the environment.
    pub fn validate(&self) -> Result<(), ParameterError> {
        self.ship.validate()?;
        crate::environment::validate_seaway(&self.seaway)?;
        // The ship model builds (for the seaway: the fit) or names the key it cannot.
        resolved_ship_parameters(&self.ship, &self.seaway)?;
        self.deck.validate()?;
        self.wind.validate()?;
        self.pitch_noise.validate()?;
        self.ship_sensing.validate()
    }
}

/// The controllers of the cascade (docs/model.md §5).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct ControlSection {
    /// Frame rate of the flight-control computer (Hz): the controllers read the sensors
    /// and set the elevator and thrust commands once per frame, held in between
    /// (docs/model.md §2.6; F/A-18: 80 Hz). `None` updates them every integration step,
    /// as the paper's simulation.
    pub flight_computer_rate_hz: Option<f64>,
    /// Refuse, before the run, a pitch tuning that the stabilator's rate limit cannot
    /// follow: one in which the describing function predicts a rate-limit oscillation
    /// from less than 3× the elevator's travel to the nearer stop (docs/pitch-step.md).
    /// `false` flies it anyway, for studies of that oscillation.
    pub rate_limit_check: bool,
    /// Pitch controller: O-PD (default) or PID.
    pub pitch: PitchControllerParameters,
    /// Roll (bank → aileron) law of the 6-DOF aircraft: O-PD (default) or PID
    /// (docs/lateral-control.md); keys left out take the roll channel's designed tuning.
    #[serde(deserialize_with = "crate::control::lateral::deserialize_roll_law")]
    pub roll: LateralLawParameters,
    /// Yaw (sideslip → rudder) law of the 6-DOF aircraft, as `roll`.
    #[serde(deserialize_with = "crate::control::lateral::deserialize_yaw_law")]
    pub yaw: LateralLawParameters,
    /// Speed (thrust) loop.
    pub speed: SpeedControllerParameters,
    /// Sink-rate (pitch command) loop.
    pub sink_rate: SinkRateControllerParameters,
    /// Guidance (climb-rate command) loop.
    pub guidance: GuidanceParameters,
    /// Glide path and deck-motion compensation.
    pub flight_path: FlightPathParameters,
    /// Automatic wave-off (docs/model.md §9); a file whose `[control]` names no
    /// `wave_off` section flies it without the keys the seaway's recovery brought
    /// ([`WaveOffParameters::named_by_none`]).
    #[serde(default = "WaveOffParameters::named_by_none")]
    pub wave_off: WaveOffParameters,
    /// Direct lift control (docs/model.md §5.9).
    pub direct_lift: DirectLiftParameters,
    /// Arrival timing to a lull of the deck's motion (docs/landing-design.md).
    pub arrival_timing: ArrivalTimingParameters,
}

impl Default for ControlSection {
    fn default() -> Self {
        Self {
            flight_computer_rate_hz: Some(80.0),
            rate_limit_check: true,
            pitch: PitchControllerParameters::default(),
            roll: LateralLawParameters::default_for(LateralChannel::Roll),
            yaw: LateralLawParameters::default_for(LateralChannel::Yaw),
            speed: SpeedControllerParameters::default(),
            sink_rate: SinkRateControllerParameters::default(),
            guidance: GuidanceParameters::default(),
            flight_path: FlightPathParameters::default(),
            wave_off: WaveOffParameters::default(),
            direct_lift: DirectLiftParameters::default(),
            arrival_timing: ArrivalTimingParameters::default(),
        }
    }
}

impl ControlSection {
    /// The section of a file that names no `[control]`: the default's, with the wave-off
    /// of a file that names none ([`WaveOffParameters::named_by_none`]).
    pub fn named_by_none() -> Self {
        Self {
            wave_off: WaveOffParameters::named_by_none(),
            ..Self::default()
        }
    }

    /// Checks every controller.
    pub fn validate(&self) -> Result<(), ParameterError> {
        if let Some(rate) = self.flight_computer_rate_hz {
            Bounds::closed(10.0, 10_000.0).check("control", "flight_computer_rate_hz", rate)?;
        }
        self.pitch.validate()?;
        self.roll.validate(LateralChannel::Roll.section())?;
        self.yaw.validate(LateralChannel::Yaw.section())?;
        self.speed.validate()?;
        self.sink_rate.validate()?;
        self.guidance.validate()?;
        self.flight_path.validate()?;
        self.wave_off.validate()?;
        self.direct_lift.validate()?;
        self.arrival_timing.validate()
    }
}

/// Limits that classify a landing (docs/model.md §7).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct OutcomeLimits {
    /// Touchdown sink rate relative to the deck above which a landing is hard (m/s).
    pub hard_landing_sink_rate_mps: f64,
    /// Airspeed below which the run is declared diverged (m/s).
    pub min_airspeed_mps: f64,
}

impl OutcomeLimits {
    /// Checks the hard-landing limit ((0, 50] m/s) and the airspeed limit ([0, 100] m/s).
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "outcome";
        check_ranges!(SECTION, self, {
            hard_landing_sink_rate_mps: Bounds::positive_up_to(50.0),
            min_airspeed_mps: Bounds::closed(0.0, 100.0),
        });
        Ok(())
    }
}

impl Default for OutcomeLimits {
    fn default() -> Self {
        Self {
            hard_landing_sink_rate_mps: 7.6,
            min_airspeed_mps: 30.0,
        }
    }
}

/// How a pitch-step mission commands its step.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum PitchCommand {
    /// The fastest rest-to-rest pitch trajectory the elevator's rate and travel allow
    /// (jerk- and acceleration-limited), its rate and acceleration fed forward
    /// (docs/model.md §5.2; realistic default).
    #[default]
    JerkLimited,
    /// A step in θ_ref, as the paper (Fig. 10–12).
    Step,
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
        /// How the step is commanded: `jerk_limited` (default) or `step` (the paper).
        #[serde(default)]
        command: PitchCommand,
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
    /// Checks the mission's fields: steps within ±20°, sink rates within ±20 m/s, run
    /// lengths of 0.1–3600 s with the step and the ramp inside them, altitudes of
    /// 30–10000 m, start distances of −10000–20000 m.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "mission";
        let timed = |step_time_s: f64, duration_s: f64, altitude_m: f64| {
            Bounds::closed(0.1, 3600.0).check(SECTION, "duration_s", duration_s)?;
            Bounds::closed(0.0, duration_s).check(SECTION, "step_time_s", step_time_s)?;
            Bounds::closed(30.0, 10_000.0).check(SECTION, "altitude_m", altitude_m)
        };
        match *self {
            Self::Approach => Ok(()),
            Self::PitchStep {
                step_deg,
                step_time_s,
                duration_s,
                start_distance_aft_m,
                altitude_m,
                ..
            } => {
                Bounds::closed(-20.0, 20.0).check(SECTION, "step_deg", step_deg)?;
                Bounds::closed(-10_000.0, 20_000.0).check(
                    SECTION,
                    "start_distance_aft_m",
                    start_distance_aft_m,
                )?;
                timed(step_time_s, duration_s, altitude_m)
            }
            Self::SinkRate {
                sink_rate_mps,
                step_time_s,
                ramp_s,
                duration_s,
                altitude_m,
            } => {
                Bounds::closed(-20.0, 20.0).check(SECTION, "sink_rate_mps", sink_rate_mps)?;
                timed(step_time_s, duration_s, altitude_m)?;
                Bounds::closed(0.0, duration_s).check(SECTION, "ramp_s", ramp_s)
            }
        }
    }

    /// A pitch step of `step_deg` lasting `duration_s`, commanded as `command`, with the
    /// other defaults.
    pub fn pitch_step(step_deg: f64, duration_s: f64, command: PitchCommand) -> Self {
        Self::PitchStep {
            step_deg,
            step_time_s: 1.0,
            duration_s,
            start_distance_aft_m: 1000.0,
            altitude_m: 150.0,
            command,
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

/// A scenario's seed: an integer from 0 to 2⁶³ − 1 (what a TOML integer can hold), and
/// an error that says so (serde's own says "expected u64").
fn deserialize_seed<'de, D: serde::Deserializer<'de>>(deserializer: D) -> Result<u64, D::Error> {
    use serde::de::{Error, Unexpected, Visitor};
    struct Seed;
    impl Visitor<'_> for Seed {
        type Value = u64;
        fn expecting(&self, formatter: &mut std::fmt::Formatter) -> std::fmt::Result {
            formatter.write_str("an integer from 0 to 2⁶³ − 1")
        }
        fn visit_i64<E: Error>(self, value: i64) -> Result<u64, E> {
            u64::try_from(value).map_err(|_| E::invalid_value(Unexpected::Signed(value), &self))
        }
        fn visit_u64<E: Error>(self, value: u64) -> Result<u64, E> {
            if i64::try_from(value).is_ok() {
                Ok(value)
            } else {
                Err(E::invalid_value(Unexpected::Unsigned(value), &self))
            }
        }
    }
    deserializer.deserialize_u64(Seed)
}

/// Every parameter of one run.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scenario {
    /// The hardware set: `realistic` (default) or `paper`; keys left out of a scenario
    /// file take this set's values (docs/model.md §2.6).
    pub hardware: HardwareSet,
    /// Seed of every random stream (docs/model.md §3.4), 0 to 2⁶³ − 1.
    #[serde(deserialize_with = "deserialize_seed")]
    pub seed: u64,
    /// Integration step (s); 1 ms (docs/model.md §6).
    pub time_step_s: f64,
    /// Time limit of an approach (s).
    pub max_time_s: f64,
    /// What the run flies.
    pub mission: Mission,
    /// The aircraft.
    pub aircraft: AircraftSection,
    /// Ship motion, deck geometry, wind and sensor noise; a file with no
    /// `[environment]` names no ship model ([`EnvironmentSection::named_by_none`]).
    #[serde(default = "EnvironmentSection::named_by_none")]
    pub environment: EnvironmentSection,
    /// The controllers; a file that names no `[control]` flies
    /// [`ControlSection::named_by_none`].
    #[serde(default = "ControlSection::named_by_none")]
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
            hardware: HardwareSet::Realistic,
            seed: 1,
            time_step_s: 0.001,
            max_time_s: 60.0,
            mission: Mission::Approach,
            aircraft: AircraftSection::default(),
            environment: EnvironmentSection::default(),
            control: ControlSection::default(),
            approach: ApproachParameters::default(),
            outcome: OutcomeLimits::default(),
            dispersion: DispersionParameters::default(),
        }
    }
}

/// The largest seed: seeds are TOML integers, which are signed 64-bit (2⁶³ − 1).
pub const MAX_SEED: u64 = i64::MAX as u64;

impl Scenario {
    /// Checks every section; the error names the first bad field by its dotted path.
    /// Besides each field's own range, the integration step must resolve the fastest
    /// dynamics it integrates: ω·dt ≤ 0.5 for the elevator actuator and k3·dt/ε ≤ 0.5 for
    /// the O-PD's observer (classical RK4 is stable up to about 2.8).
    pub fn validate(&self) -> Result<(), ParameterError> {
        if self.seed > MAX_SEED {
            return Err(ParameterError::new(
                "",
                "seed",
                self.seed,
                format_args!("an integer in [0, {MAX_SEED}] (2⁶³ − 1)"),
            ));
        }
        Bounds::closed(1e-5, 0.01).check("", "time_step_s", self.time_step_s)?;
        Bounds::closed(1.0, 3600.0).check("", "max_time_s", self.max_time_s)?;
        self.mission.validate()?;
        self.aircraft.validate(self.hardware)?;
        self.environment.validate()?;
        self.control.validate()?;
        self.approach.validate()?;
        self.outcome.validate()?;
        self.dispersion.validate()?;
        self.check_lateral_laws()?;
        self.check_time_step_resolves_the_dynamics()
    }

    /// ω·dt ≤ 0.5 for the actuator and k3·dt/ε ≤ 0.5 for the observer.
    fn check_time_step_resolves_the_dynamics(&self) -> Result<(), ParameterError> {
        let dt = self.time_step_s;
        let omega = self.aircraft.fastest_actuator_rad_s();
        if omega * dt > 0.5 {
            return Err(ParameterError::new(
                "",
                "time_step_s",
                dt,
                format_args!(
                    "at most {:?} s, so that the fastest surface actuator (ω = {omega} \
                     rad/s) is resolved (ω·dt ≤ 0.5)",
                    0.5 / omega
                ),
            ));
        }
        if let PitchControllerParameters::ObserverPd(opd) = &self.control.pitch {
            check_observer_resolved(
                &opd.observer,
                crate::estimation::ObserverParameters::SECTION,
                dt,
            )?;
        }
        Ok(())
    }

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
