//! The two hardware sets (docs/model.md §2.6): what the paper simulated, and the
//! realistic F/A-18 every other command flies.
//!
//! | | `paper` | `realistic` (default) |
//! |---|---|---|
//! | stabilator rate limit | none | 40 °/s |
//! | air wake | as written: the periodic wake at every distance | within 914 m of the ship |
//! | O-PD | T_2% = 0.3 s, ζ = √2, ε = 0.03, measured θ | T_2% = 1.6 s, ζ = 1, ε = 0.2, estimated θ |
//! | PID | K_P 57.01, K_I 50, K_D 17.19 | K_P 6.25, K_I 0.25, K_D 4.81 |
//! | speed loop | raw airspeed | airspeed filtered at 4 rad/s |
//! | sink-rate loop | K_Ps 0.035, K_Is 0.012 | K_Ps 0.035, K_Is 0.006 |
//! | flight-control computer | every integration step | 80 Hz frames |
//! | pitch-step command | a step | jerk-limited, fed forward |
//! | deck-motion predictor | `oracle` (the ship's true state) | `estimator` (sensed motion, Kalman filter) |
//! | glide path | linear blend, not ramp-aware | smooth blend, ramp-aware, touchdown correction |
//! | automatic wave-off | none | on |
//! | aircraft model | `3dof` | `6dof`: the 3-D approach (docs/three-d-approach.md) |
//! | ship speed | 0 (stationary) | 7.7 m/s (15 kn) |
//!
//! A scenario names its set (`hardware = "paper"`); in a scenario file every key left
//! out takes its set's value ([`super::load_scenario`]).

use serde::{Deserialize, Serialize};

use super::{Mission, PitchCommand, Scenario};
use crate::aircraft::PlantModel;
use crate::control::pitch::LawTuning;
use crate::control::{
    ArrivalTimingParameters, DirectLiftParameters, FlightPathParameters,
    SinkRateControllerParameters, SpeedControllerParameters, WaveOffParameters,
};
use crate::environment::{ShipModelKind, WindParameters};

/// Which hardware a scenario flies.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum HardwareSet {
    /// A real F/A-18: rate-limited stabilator, sampled flight computer, bounded air wake,
    /// controllers designed for them.
    #[default]
    Realistic,
    /// What the paper simulated: an ideal actuator and the paper's gains.
    Paper,
}

impl HardwareSet {
    /// The name as written in files: `realistic` or `paper`.
    pub fn name(self) -> &'static str {
        match self {
            Self::Realistic => "realistic",
            Self::Paper => "paper",
        }
    }

    /// How this set commands a pitch step.
    pub fn pitch_command(self) -> PitchCommand {
        match self {
            Self::Realistic => PitchCommand::JerkLimited,
            Self::Paper => PitchCommand::Step,
        }
    }

    /// The tuning of a pitch law this set flies (a law is chosen by its `type` name).
    pub fn law_tuning(self) -> LawTuning {
        match self {
            Self::Realistic => LawTuning::Realistic,
            Self::Paper => LawTuning::Paper,
        }
    }

    /// The default scenario of this set.
    pub fn scenario(self) -> Scenario {
        match self {
            Self::Realistic => Scenario::default(),
            Self::Paper => Scenario::paper(),
        }
    }
}

impl Scenario {
    /// The paper's scenario: adverse conditions, its hardware and its O-PD design.
    pub fn paper() -> Self {
        let mut scenario = Self {
            hardware: HardwareSet::Paper,
            ..Self::default()
        };
        scenario.aircraft.elevator_actuator.rate_limit_degps = None;
        scenario.environment.ship.model = ShipModelKind::Filters;
        scenario.environment.wind = WindParameters::paper();
        scenario.control.pitch = scenario.control.pitch.paper_tuning();
        scenario.control.speed = SpeedControllerParameters::paper();
        scenario.control.sink_rate = SinkRateControllerParameters::for_ideal_actuator();
        scenario.control.flight_computer_rate_hz = None;
        scenario.control.flight_path = FlightPathParameters::paper();
        scenario.control.wave_off = WaveOffParameters::paper();
        scenario.control.direct_lift = DirectLiftParameters::paper();
        scenario.control.arrival_timing = ArrivalTimingParameters::paper();
        scenario.longitudinal()
    }

    /// The realistic default in the paper's sea: the filter ship of docs/model.md §3.1 at
    /// 2.0 m heave and 1.5° pitch RMS (roll 1.0°), as the default flew before the carrier
    /// in a seaway became it, and as every file that names no ship model flies (without
    /// the early foul-deck wave-off and the wave-off's airspeed limit, which came with
    /// the seaway's recovery limits: that sea is beyond them). The
    /// tests of mechanisms that a rough deck exercises (wave-offs, late aborts, the
    /// deck-motion compensation) fly it.
    pub fn papers_sea() -> Self {
        let mut scenario = Self::default();
        scenario.environment.ship.model = ShipModelKind::Filters;
        scenario.control.wave_off = WaveOffParameters::named_by_none();
        scenario
    }

    /// This scenario flown by the longitudinal 3-DOF aircraft behind a stationary ship
    /// (the paper's approach geometry): what the longitudinal laws' design checks,
    /// `deckland step` (pitch) and `deckland sink`, fly on a hardware set's default, and
    /// the environment `deckland environment` records.
    pub fn longitudinal(mut self) -> Self {
        self.aircraft.model = PlantModel::ThreeDof;
        self.environment.ship.forward_speed_mps = 0.0;
        self
    }

    /// The default scenario of `set` flying this scenario's pitch law (with the set's
    /// tuning of it) and mission (with the set's pitch command).
    fn defaults_for(&self, set: HardwareSet) -> Self {
        let mut base = set.scenario();
        base.control.pitch = self.control.pitch.retuned(set.law_tuning());
        base.mission = self.mission;
        if let Mission::PitchStep { command, .. } = &mut base.mission {
            *command = set.pitch_command();
        }
        base
    }

    /// This scenario with every key for which `in_file` is false, and whose value differs
    /// between the two sets, set to its value in this scenario's set. A scenario read
    /// from a file takes its defaults from the realistic set; this gives a file that says
    /// `hardware = "paper"` the paper's values for what it leaves out.
    pub fn with_set_defaults(&self, in_file: impl Fn(&str) -> bool) -> Result<Self, String> {
        if self.hardware == HardwareSet::Realistic {
            return Ok(*self);
        }
        // JSON values, not TOML: a `None` (the paper's "no rate limit") must survive as
        // `null`, which TOML cannot write.
        let to_value = |s: &Scenario| serde_json::to_value(s).map_err(|e| e.to_string());
        let own = to_value(&self.defaults_for(self.hardware))?;
        let other = to_value(&self.defaults_for(HardwareSet::Realistic))?;
        let mut value = to_value(self)?;
        let mut paths = Vec::new();
        leaf_paths("", &own, &mut paths);
        leaf_paths("", &other, &mut paths);
        paths.sort();
        paths.dedup();
        for path in paths {
            let wanted = lookup(&own, &path);
            if in_file(&path) || wanted == lookup(&other, &path) {
                continue;
            }
            set(&mut value, &path, wanted.cloned());
        }
        serde_json::from_value(value).map_err(|e| e.to_string())
    }
}

/// Every leaf key of `value` as a dotted path.
fn leaf_paths(prefix: &str, value: &serde_json::Value, out: &mut Vec<String>) {
    match value {
        serde_json::Value::Object(table) => {
            for (key, item) in table {
                leaf_paths(&crate::parameters::join(prefix, key), item, out);
            }
        }
        _ => out.push(prefix.to_owned()),
    }
}

/// The value at a dotted path.
fn lookup<'a>(value: &'a serde_json::Value, path: &str) -> Option<&'a serde_json::Value> {
    path.split('.')
        .try_fold(value, |v, key| v.as_object().and_then(|t| t.get(key)))
}

/// Sets the value at a dotted path (`null` where the set has none), creating objects on
/// the way.
fn set(value: &mut serde_json::Value, path: &str, new: Option<serde_json::Value>) {
    let mut keys: Vec<&str> = path.split('.').collect();
    let Some(last) = keys.pop() else {
        return;
    };
    let mut table = value;
    for key in keys {
        let Some(t) = table.as_object_mut() else {
            return;
        };
        table = t
            .entry(key)
            .or_insert_with(|| serde_json::Value::Object(serde_json::Map::new()));
    }
    if let Some(t) = table.as_object_mut() {
        t.insert(last.to_owned(), new.unwrap_or(serde_json::Value::Null));
    }
}
