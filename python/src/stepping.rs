//! An approach flown one control interval at a time, by the library's own step
//! ([`Simulation::step_with`]); the actions it takes, checked against their physical
//! ranges; and a Python callable as the pitch law.
//!
//! One control interval is a whole number of integration steps; the action's commands
//! replace the loops' through [`Overrides`] and are held over the interval. With no
//! action the loop is exactly the one `fly()` integrates, so an approach stepped to the
//! end with no action ends with the same summary, bit for bit. What the next step starts
//! from is the library's [`Simulation::signals`], with the inputs it will hold drawn
//! early by [`Simulation::next_step_inputs`] (the same draws in the same order).

use std::f64::consts::FRAC_PI_2;

use deckland::control::DeckReference;
use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{
    EndReason, Event, Overrides, Recorder, Signals, Simulation, Stop, Taps,
};
use pyo3::exceptions::PyTypeError;
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyString};

use crate::errors::{argument_error, value_error};

/// The longest control interval (s).
const MAX_CONTROL_INTERVAL_S: f64 = 10.0;

/// The pitch command's envelope (rad): the range of the pitch attitude θ, ±90°. The
/// sink-rate loop, the wake feed-forward and the wave-off command within it; beyond it a
/// command is no pitch attitude (and a law fed 10³⁰⁸ rad overflows to ∞).
pub(crate) const PITCH_COMMAND_RANGE_RAD: (f64, f64) = (-FRAC_PI_2, FRAC_PI_2);

/// Keeps the events of a run (no signals).
#[derive(Debug, Default)]
pub(crate) struct EventRecorder {
    pub events: Vec<Event>,
}

impl Recorder for EventRecorder {
    fn event(&mut self, event: &Event) {
        self.events.push(*event);
    }
}

/// The bank command's envelope (rad): the bank angle's range, ±90°.
pub(crate) const BANK_COMMAND_RANGE_RAD: (f64, f64) = (-FRAC_PI_2, FRAC_PI_2);

/// The sideslip command's envelope (rad): ±30°, the range the 3-D environment observes.
pub(crate) const SIDESLIP_COMMAND_RANGE_RAD: (f64, f64) =
    (-0.523_598_775_598_298_8, 0.523_598_775_598_298_8);

/// The lateral keys of an action: a 3-D approach's (docs/model.md §10).
const LATERAL_KEYS: [&str; 4] = [
    "bank_command_rad",
    "sideslip_command_rad",
    "aileron_rad",
    "rudder_rad",
];

/// The physical range of each action key, from the aircraft flown.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct ActionRanges {
    /// The pitch command's envelope (rad): [`PITCH_COMMAND_RANGE_RAD`].
    pub pitch_command_rad: (f64, f64),
    /// The stabilator's travel (rad): its actuator's deflection limits.
    pub elevator_rad: (f64, f64),
    /// The total thrust command (N): from none to the maximum of both engines.
    pub thrust_n: (f64, f64),
    /// A 3-D approach's aileron and rudder travel (rad), either side of neutral; `None`
    /// for a 3-DOF approach, which takes no lateral key.
    pub lateral_travel_rad: Option<(f64, f64)>,
}

impl ActionRanges {
    /// The ranges of the aircraft `simulation` flies, from its built loop.
    fn of(simulation: &Simulation) -> Self {
        let aircraft = simulation.system().aircraft();
        let actuator = aircraft.actuator();
        Self {
            pitch_command_rad: PITCH_COMMAND_RANGE_RAD,
            elevator_rad: (actuator.min_rad(), actuator.max_rad()),
            thrust_n: (0.0, aircraft.engines().max_total_thrust_n()),
            lateral_travel_rad: simulation.lateral_surface_travel_rad(),
        }
    }

    /// Each key with its range, unit and what the range is, in the order of the keys
    /// (the lateral keys only in a 3-D approach).
    pub fn described(&self) -> Vec<(&'static str, (f64, f64), &'static str, &'static str)> {
        let mut keys = vec![
            (
                "pitch_command_rad",
                self.pitch_command_rad,
                "rad",
                "the pitch attitude's range, ±90°",
            ),
            (
                "elevator_rad",
                self.elevator_rad,
                "rad",
                "the stabilator's travel, aircraft.elevator_actuator.min_deflection_deg \
                 to max_deflection_deg",
            ),
            (
                "thrust_n",
                self.thrust_n,
                "N",
                "no thrust to the maximum of both engines, \
                 2 × aircraft.engines.max_thrust_per_engine_n",
            ),
        ];
        if let Some((aileron, rudder)) = self.lateral_travel_rad {
            keys.extend([
                (
                    "bank_command_rad",
                    BANK_COMMAND_RANGE_RAD,
                    "rad",
                    "the bank angle's range, ±90°",
                ),
                (
                    "sideslip_command_rad",
                    SIDESLIP_COMMAND_RANGE_RAD,
                    "rad",
                    "±30°, the sideslip the 3-D environment observes",
                ),
                (
                    "aileron_rad",
                    (-aileron, aileron),
                    "rad",
                    "the aileron's travel, ±aircraft.aileron_actuator.travel_deg",
                ),
                (
                    "rudder_rad",
                    (-rudder, rudder),
                    "rad",
                    "the rudder's travel, ±aircraft.rudder_actuator.travel_deg",
                ),
            ]);
        }
        keys
    }

    /// `value` of action `key` if within the key's range, else `ValueError` naming the
    /// key, the value and the range (a non-finite value is never within it).
    fn check(&self, key: &str, value: f64) -> PyResult<f64> {
        let Some((_, (low, high), unit, what)) =
            self.described().into_iter().find(|(name, ..)| *name == key)
        else {
            if LATERAL_KEYS.contains(&key) {
                return Err(value_error(format!(
                    "action `{key}` needs a 3-D approach (aircraft.model = \"6dof\" with \
                     approach.three_dimensional = true): this approach has no lateral loops"
                )));
            }
            return Err(unknown_action(key));
        };
        if (low..=high).contains(&value) {
            return Ok(value);
        }
        Err(argument_error(
            &format!("action {key}"),
            format_args!("{value:?}"),
            format_args!("a number in [{low}, {high}] {unit} ({what})"),
        ))
    }
}

/// The error of an action key that is none of the commands.
fn unknown_action(key: &str) -> PyErr {
    value_error(format!(
        "action `{key}` is not a command: expected pitch_command_rad, elevator_rad, thrust_n \
         or, in a 3-D approach, bank_command_rad, sideslip_command_rad, aileron_rad, rudder_rad"
    ))
}

/// The action's commands: `None`, or a dict with any of `pitch_command_rad`,
/// `elevator_rad` and `thrust_n` and, in a 3-D approach, `bank_command_rad`,
/// `sideslip_command_rad`, `aileron_rad` and `rudder_rad` (a value of None leaves that
/// loop in charge), each within its range of `ranges`.
pub(crate) fn parse_action(
    action: Option<&Bound<'_, PyAny>>,
    ranges: &ActionRanges,
) -> PyResult<Overrides> {
    let mut overrides = Overrides::default();
    let Some(action) = action.filter(|a| !a.is_none()) else {
        return Ok(overrides);
    };
    let dict = action.cast::<PyDict>().map_err(|_| {
        PyTypeError::new_err(
            "action must be None or a dict with any of pitch_command_rad, elevator_rad, thrust_n",
        )
    })?;
    for (key, value) in dict.iter() {
        let key = key.cast::<PyString>().map_err(|_| {
            PyTypeError::new_err(
                "action keys must be str: pitch_command_rad, elevator_rad, thrust_n",
            )
        })?;
        let key = key.to_str()?;
        let slot = match key {
            "pitch_command_rad" => &mut overrides.pitch_command_rad,
            "elevator_rad" => &mut overrides.elevator_rad,
            "thrust_n" => &mut overrides.thrust_n,
            "bank_command_rad" => &mut overrides.bank_command_rad,
            "sideslip_command_rad" => &mut overrides.sideslip_command_rad,
            "aileron_rad" => &mut overrides.aileron_rad,
            "rudder_rad" => &mut overrides.rudder_rad,
            other => return Err(unknown_action(other)),
        };
        if value.is_none() {
            continue;
        }
        let number: f64 = value.extract().map_err(|_| {
            PyTypeError::new_err(format!("action `{key}` must be a float, got {value}"))
        })?;
        *slot = Some(ranges.check(key, number)?);
    }
    Ok(overrides)
}

/// What the next integration step starts from.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Look {
    /// The signals at the current state, with the inputs the next step holds (as
    /// `fly()` records them at this time).
    pub signals: Signals,
    /// The deck reference the guidance computer holds over the next step (with the
    /// deck forecast, from predictors that forecast), `None` outside an approach.
    pub deck: Option<DeckReference>,
}

/// A simulation advanced one control interval at a time.
pub(crate) struct Stepper {
    simulation: Simulation,
    steps_per_interval: u64,
    /// Integration steps of the intervals advanced.
    steps: u64,
    end: Option<EndReason>,
    /// What the next step starts from, once looked at.
    look: Option<Look>,
    ranges: ActionRanges,
}

/// The number of integration steps of `control_interval_s`, which must be a whole
/// multiple of the scenario's integration step.
pub(crate) fn steps_per_interval(control_interval_s: f64, time_step_s: f64) -> PyResult<u64> {
    let steps = (control_interval_s / time_step_s).round();
    let whole = (steps * time_step_s - control_interval_s).abs() <= 1e-9 * control_interval_s;
    if !(control_interval_s.is_finite()
        && control_interval_s > 0.0
        && control_interval_s <= MAX_CONTROL_INTERVAL_S
        && steps >= 1.0
        && whole)
    {
        return Err(argument_error(
            "control_interval_s",
            format_args!("{control_interval_s:?}"),
            format_args!(
                "a whole multiple of the integration step time_step_s = {time_step_s} s, \
                 at most {MAX_CONTROL_INTERVAL_S} s"
            ),
        ));
    }
    Ok(steps as u64)
}

impl Stepper {
    /// Sets up `scenario` (flown as it is: an approach) to be flown in steps of
    /// `control_interval_s`.
    pub fn new(scenario: &RustScenario, control_interval_s: f64) -> PyResult<Self> {
        let steps_per_interval = steps_per_interval(control_interval_s, scenario.time_step_s)?;
        let simulation = Simulation::new(scenario)
            .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
        Ok(Self {
            ranges: ActionRanges::of(&simulation),
            simulation,
            steps_per_interval,
            steps: 0,
            end: None,
            look: None,
        })
    }

    /// The simulation flown.
    pub fn simulation(&self) -> &Simulation {
        &self.simulation
    }

    /// The physical range of each action key.
    pub fn ranges(&self) -> &ActionRanges {
        &self.ranges
    }

    /// The control interval (s).
    pub fn interval_s(&self) -> f64 {
        self.steps_per_interval as f64 * self.simulation.time_step_s()
    }

    /// Whether the approach has ended.
    pub fn ended(&self) -> bool {
        self.end.is_some()
    }

    /// What the next step starts from; the run is unchanged.
    pub fn look(&mut self) -> Look {
        if let Some(look) = self.look {
            return look;
        }
        // Drawn now for the next step (the same draws it would make), so that the signals
        // are those the step starts from.
        let held = self.simulation.next_step_inputs();
        let look = Look {
            signals: self.simulation.signals(),
            deck: held.deck,
        };
        self.look = Some(look);
        look
    }

    /// Why the approach ended, once it has.
    pub fn end_reason(&self) -> Option<&EndReason> {
        self.end.as_ref()
    }

    /// Advances one control interval (or to the end) with `taps` (for example the
    /// action's [`Overrides`]) held.
    pub fn advance<R: Recorder, T: Taps>(&mut self, recorder: &mut R, taps: &T) {
        if self.end.is_some() {
            return;
        }
        self.look = None;
        let target = self.steps + self.steps_per_interval;
        // `Simulation::time_s` is exactly `steps as f64 * dt`.
        let target_time_s = target as f64 * self.simulation.time_step_s();
        loop {
            if let Stop::Ended(reason) = self.simulation.step_with(recorder, taps) {
                self.end = Some(reason);
                break;
            }
            if self.simulation.time_s() >= target_time_s {
                break;
            }
        }
        self.steps = target;
    }

    /// The overrides of an interval with a Python pitch law flying: the law's elevator
    /// command, unless `action` sets the elevator itself.
    pub fn law_overrides(
        &mut self,
        law: &Bound<'_, PyAny>,
        action: Option<Overrides>,
    ) -> PyResult<Overrides> {
        let mut overrides = action.unwrap_or_default();
        if overrides.elevator_rad.is_none() && !self.ended() {
            overrides.elevator_rad = Some(self.call_law(law, overrides.pitch_command_rad)?);
        }
        Ok(overrides)
    }

    /// Calls the Python pitch law once with the signals at the current state.
    fn call_law(
        &mut self,
        law: &Bound<'_, PyAny>,
        pitch_command_rad: Option<f64>,
    ) -> PyResult<f64> {
        let py = law.py();
        let s = self.look().signals;
        let trim = self.simulation.system().trim();
        let inputs = PyDict::new(py);
        inputs.set_item(intern!(py, "time_s"), s.time_s)?;
        inputs.set_item(
            intern!(py, "theta_ref_rad"),
            pitch_command_rad.unwrap_or(s.theta_ref_rad),
        )?;
        inputs.set_item(intern!(py, "theta_measured_rad"), s.theta_measured_rad)?;
        inputs.set_item(intern!(py, "pitch_rate_radps"), s.q_radps)?;
        inputs.set_item(intern!(py, "elevator_rad"), s.elevator_rad)?;
        inputs.set_item(intern!(py, "theta_trim_rad"), trim.theta_rad)?;
        inputs.set_item(intern!(py, "elevator_trim_rad"), trim.elevator_rad)?;
        inputs.set_item(intern!(py, "interval_s"), self.interval_s())?;
        let command = law.call1((inputs,))?;
        let command: f64 = command.extract().map_err(|_| {
            PyTypeError::new_err(format!(
                "the pitch law returned {}, expected the elevator command in rad (a float)",
                command
                    .repr()
                    .map_or_else(|_| "?".to_owned(), |r| r.to_string())
            ))
        })?;
        if !command.is_finite() {
            return Err(argument_error(
                "pitch law elevator command",
                format_args!("{command:?}"),
                "a finite number (rad)",
            ));
        }
        Ok(command)
    }
}

/// The label of a Python pitch law in summaries: its `label` attribute, else its
/// `__name__`, else `python`.
pub(crate) fn python_law_label(law: &Bound<'_, PyAny>) -> PyResult<String> {
    if !law.is_callable() {
        return Err(PyTypeError::new_err(
            "pitch_law must be callable: inputs dict -> elevator command (rad)",
        ));
    }
    for attribute in ["label", "__name__"] {
        if let Ok(value) = law.getattr(attribute) {
            if let Ok(text) = value.extract::<String>() {
                return Ok(text);
            }
        }
    }
    Ok("python".to_owned())
}
