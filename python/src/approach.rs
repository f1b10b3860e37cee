//! `deckland.Approach`: an approach stepped one control interval at a time, with the
//! built-in cascade flying or the user replacing its loops; and a Python callable as the
//! pitch law.
//!
//! One control interval is a whole number of integration steps
//! ([`Simulation::step_with`]); the action's commands replace the loops' through
//! [`Overrides`] and are held over the interval. With no action the loop is exactly the
//! one `fly()` integrates, so an approach stepped to the end with `action=None` ends
//! with the same summary, bit for bit.

use std::time::Instant;

use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{
    EndReason, Event, HeldInputs, NoTaps, Overrides, Recorder, RunSummary, Signals, Simulation,
    Stop,
};
use pyo3::exceptions::PyTypeError;
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::errors::{argument_error, value_error};
use crate::flight::{events_list, flight_scenario, summary_dict};
use crate::scenario::{scenario_or_default, Scenario};

/// The longest control interval (s).
const MAX_CONTROL_INTERVAL_S: f64 = 10.0;

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

/// A simulation advanced one control interval at a time.
pub(crate) struct Stepper {
    simulation: Simulation,
    steps_per_interval: u64,
    /// Integration steps taken.
    steps: u64,
    /// The inputs the next step will hold and the signals it starts from.
    held: HeldInputs,
    signals: Signals,
    /// Room for the loop's derivative when evaluating the signals.
    rate: Vec<f64>,
    end: Option<EndReason>,
}

/// The number of integration steps of `control_interval_s`, which must be a whole
/// multiple of the scenario's integration step.
fn steps_per_interval(control_interval_s: f64, time_step_s: f64) -> PyResult<u64> {
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
    /// Sets up `scenario` (an approach) to be flown in steps of `control_interval_s`.
    pub fn new(scenario: &RustScenario, control_interval_s: f64) -> PyResult<Self> {
        let steps_per_interval = steps_per_interval(control_interval_s, scenario.time_step_s)?;
        let simulation = Simulation::new(scenario)
            .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
        let mut stepper = Self {
            rate: vec![0.0; simulation.state().len()],
            simulation,
            steps_per_interval,
            steps: 0,
            held: HeldInputs::default(),
            signals: Signals::default(),
            end: None,
        };
        stepper.look();
        Ok(stepper)
    }

    /// Computes the signals the next step starts from (as `fly()` records them), with
    /// the inputs it will hold; the run is unchanged.
    fn look(&mut self) {
        self.held = self.simulation.next_step_inputs();
        let simulation = &self.simulation;
        self.signals = simulation.system().evaluate(
            simulation.time_s(),
            simulation.state(),
            &self.held,
            &NoTaps,
            &mut self.rate,
        );
    }

    /// Whether the approach has ended.
    pub fn ended(&self) -> bool {
        self.end.is_some()
    }

    /// Advances one control interval (or to the end) with `overrides` held.
    pub fn advance<R: Recorder>(&mut self, recorder: &mut R, overrides: &Overrides) {
        if self.end.is_some() {
            return;
        }
        let target = self.steps + self.steps_per_interval;
        // `Simulation::time_s` is exactly `steps as f64 * dt`.
        let target_time_s = target as f64 * self.simulation.time_step_s();
        loop {
            if let Stop::Ended(reason) = self.simulation.step_with(recorder, overrides) {
                self.end = Some(reason);
                break;
            }
            if self.simulation.time_s() >= target_time_s {
                break;
            }
        }
        self.steps = target;
        self.look();
    }

    /// The overrides of an interval with a Python pitch law flying: the law's elevator
    /// command, unless `action` sets the elevator itself.
    pub fn law_overrides(
        &self,
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
    fn call_law(&self, law: &Bound<'_, PyAny>, pitch_command_rad: Option<f64>) -> PyResult<f64> {
        let py = law.py();
        let s = &self.signals;
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
        inputs.set_item(
            intern!(py, "interval_s"),
            self.steps_per_interval as f64 * self.simulation.time_step_s(),
        )?;
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

/// The action's commands: `None`, or a dict with any of `pitch_command_rad`,
/// `elevator_rad` and `thrust_n` (a value of None leaves that loop in charge).
fn parse_action(action: Option<&Bound<'_, PyAny>>) -> PyResult<Overrides> {
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
            other => {
                return Err(value_error(format!(
                    "action `{other}` is not a command: expected pitch_command_rad, \
                     elevator_rad or thrust_n"
                )))
            }
        };
        if value.is_none() {
            continue;
        }
        let number: f64 = value.extract().map_err(|_| {
            PyTypeError::new_err(format!("action `{key}` must be a float, got {value}"))
        })?;
        if !number.is_finite() {
            return Err(argument_error(
                &format!("action {key}"),
                format_args!("{number:?}"),
                "a finite number",
            ));
        }
        *slot = Some(number);
    }
    Ok(overrides)
}

/// An approach flown one control interval at a time (the stepping API).
///
/// `Approach(scenario=None, seed=None, control_interval_s=0.02, pitch_law=None)` sets up
/// the scenario (the default one when None) with `seed` (else the scenario's own) as an
/// approach. `reset(seed=None)` starts it again (with a new seed when given) and returns
/// the observation; `step(action=None)` advances one control interval (a whole number of
/// the scenario's integration steps, 20 by default) and returns the observation.
///
/// **Actions** (held over the interval):
///
/// - `None`: the built-in cascade flies (glide path → guidance → sink rate → pitch law
///   → elevator, and the speed loop → thrust). Stepped to the end this is `fly()`, bit
///   for bit.
/// - `{"pitch_command_rad": θ}`: replaces the guidance and sink-rate loops; the pitch
///   law tracks θ.
/// - `{"elevator_rad": δe, "thrust_n": T}`: replaces every loop (elevator command in rad,
///   positive trailing edge down; total thrust command of both engines in N). Either key
///   alone replaces only its loop. The actuator and engines still apply their limits
///   and dynamics.
///
/// A replaced loop keeps running in the background on the aircraft's response, so
/// control can be handed back at any interval.
///
/// **Observation** (a dict of floats; angles in rad, SI units):
///
/// - `time_s`: simulated time;
/// - `glide_path_error_m`: h_ref − h_hook, positive when the hook is below the glide
///   path; `glide_path_height_m` the hook's reference height, `hook_height_m` its height;
/// - `sink_rate_mps` (CG, positive down), `hook_sink_rate_mps`, and
///   `sink_rate_command_mps` from guidance;
/// - `theta_rad` (pitch θ), `theta_measured_rad` (with sensor noise),
///   `theta_command_rad` (the cascade's θ_ref), `q_radps` (pitch rate),
///   `alpha_rad` (α), `airspeed_mps` (true airspeed V);
/// - `elevator_rad`, `thrust_n` (actual) and `elevator_command_rad`,
///   `thrust_command_n` (what the built-in loops compute now);
/// - `range_to_go_m`: along the ground from the hook to the landing point;
///   `time_to_go_s`: to touchdown, as the flight-path generator estimates it;
/// - `deck_height_m`: the landing point's height now; `predicted_deck_height_m`: where
///   the deck-motion predictor expects it (the glide path's anchor near the end);
/// - `wind_x_mps`, `wind_z_mps`: the wind at the aircraft (earth axes, x forward, z
///   down);
/// - `done`: whether the approach has ended; then `outcome` (`trap`, `bolter`, `wave_off`,
///   `ramp_strike`, `hard_landing`, `diverged`, `timeout`), `wire` (1–4 for a trap) and
///   `reason` are set (None before).
///
/// The observation at time t is what the next integration step starts from: the
/// signals `fly()` records at t (its time series every 10 ms holds the same numbers),
/// with the commands the built-in loops compute.
///
/// **Your own pitch law**: `pitch_law` is a callable `law(inputs) -> elevator command
/// (rad)`, called once per control interval (a discrete-time law with its output held
/// over the interval, as on a flight computer). `inputs` is a dict: `time_s`,
/// `theta_ref_rad` (the cascade's pitch command, or the action's), `theta_measured_rad`,
/// `pitch_rate_radps`, `elevator_rad` (actual), `theta_trim_rad`, `elevator_trim_rad`,
/// `interval_s`. Keep the law's own state in the callable (a class with `__call__`).
/// An action's `elevator_rad` takes precedence over the law. For full speed, write the
/// law in Rust (`deckland::control::pitch::PitchLaw`).
#[pyclass(name = "Approach", module = "deckland")]
pub struct Approach {
    base: RustScenario,
    name: String,
    seed: u64,
    control_interval_s: f64,
    stepper: Stepper,
    recorder: EventRecorder,
    pitch_law: Option<Py<PyAny>>,
}

impl Approach {
    /// The observation dict at the current state.
    fn observe<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let s = &self.stepper.signals;
        let predicted = self.stepper.held.deck.map_or(f64::NAN, |deck| deck.aim.h_m);
        let obs = PyDict::new(py);
        obs.set_item(intern!(py, "time_s"), s.time_s)?;
        obs.set_item(intern!(py, "glide_path_error_m"), s.glide_path_error_m)?;
        obs.set_item(intern!(py, "glide_path_height_m"), s.path_height_m)?;
        obs.set_item(intern!(py, "hook_height_m"), s.hook_h_m)?;
        obs.set_item(intern!(py, "sink_rate_mps"), -s.climb_rate_mps)?;
        obs.set_item(intern!(py, "hook_sink_rate_mps"), -s.hook_climb_rate_mps)?;
        obs.set_item(
            intern!(py, "sink_rate_command_mps"),
            s.climb_rate_command_mps.map(|c| -c),
        )?;
        obs.set_item(intern!(py, "theta_rad"), s.theta_rad)?;
        obs.set_item(intern!(py, "theta_measured_rad"), s.theta_measured_rad)?;
        obs.set_item(intern!(py, "theta_command_rad"), s.theta_ref_rad)?;
        obs.set_item(intern!(py, "q_radps"), s.q_radps)?;
        obs.set_item(intern!(py, "alpha_rad"), s.alpha_rad)?;
        obs.set_item(intern!(py, "airspeed_mps"), s.airspeed_mps)?;
        obs.set_item(intern!(py, "elevator_rad"), s.elevator_rad)?;
        obs.set_item(intern!(py, "elevator_command_rad"), s.elevator_command_rad)?;
        obs.set_item(intern!(py, "thrust_n"), s.thrust_n)?;
        obs.set_item(intern!(py, "thrust_command_n"), s.thrust_command_n)?;
        obs.set_item(intern!(py, "range_to_go_m"), s.aim_point.x_m - s.hook_x_m)?;
        obs.set_item(intern!(py, "time_to_go_s"), s.time_to_go_s)?;
        obs.set_item(intern!(py, "deck_height_m"), s.aim_point.h_m)?;
        obs.set_item(intern!(py, "predicted_deck_height_m"), predicted)?;
        obs.set_item(intern!(py, "wind_x_mps"), s.wind.x_mps)?;
        obs.set_item(intern!(py, "wind_z_mps"), s.wind.z_mps)?;
        let summary = self.stepper.simulation.summary();
        obs.set_item(intern!(py, "done"), self.stepper.ended())?;
        obs.set_item(intern!(py, "outcome"), summary.map(|s| s.outcome.name()))?;
        obs.set_item(intern!(py, "wire"), summary.and_then(|s| s.wire))?;
        obs.set_item(
            intern!(py, "reason"),
            summary.and_then(|s| s.reason.clone()),
        )?;
        Ok(obs)
    }

    fn summary(&self) -> Option<&RunSummary> {
        self.stepper.simulation.summary()
    }

    fn controller_label(&self, py: Python<'_>) -> PyResult<String> {
        match &self.pitch_law {
            Some(law) => python_law_label(law.bind(py)),
            None => Ok(self.base.control.pitch.label().to_owned()),
        }
    }
}

#[pymethods]
impl Approach {
    #[new]
    #[pyo3(signature = (scenario = None, seed = None, control_interval_s = 0.02, pitch_law = None))]
    fn new(
        scenario: Option<PyRef<'_, Scenario>>,
        seed: Option<i128>,
        control_interval_s: f64,
        pitch_law: Option<Bound<'_, PyAny>>,
    ) -> PyResult<Self> {
        let base = scenario_or_default(scenario);
        let flown = flight_scenario(&base.scenario, seed, false)?;
        if let Some(law) = &pitch_law {
            python_law_label(law)?;
        }
        Ok(Self {
            base: flown,
            name: base.name,
            seed: flown.seed,
            control_interval_s,
            stepper: Stepper::new(&flown, control_interval_s)?,
            recorder: EventRecorder::default(),
            pitch_law: pitch_law.map(Bound::unbind),
        })
    }

    /// Starts the approach again from its start (with `seed` when given, else the same
    /// seed: the same episode) and returns the observation.
    #[pyo3(signature = (seed = None))]
    fn reset<'py>(&mut self, py: Python<'py>, seed: Option<i128>) -> PyResult<Bound<'py, PyDict>> {
        let scenario = crate::scenario::with_seed(self.base, seed.or(Some(self.seed.into())))?;
        self.stepper = Stepper::new(&scenario, self.control_interval_s)?;
        self.base = scenario;
        self.seed = scenario.seed;
        self.recorder = EventRecorder::default();
        self.observe(py)
    }

    /// Advances one control interval with `action` (see the class doc) and returns the
    /// observation. After the end it returns the final observation again.
    #[pyo3(signature = (action = None))]
    fn step<'py>(
        &mut self,
        py: Python<'py>,
        action: Option<&Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyDict>> {
        let mut overrides = parse_action(action)?;
        if let Some(law) = &self.pitch_law {
            overrides = self.stepper.law_overrides(law.bind(py), Some(overrides))?;
        }
        self.stepper.advance(&mut self.recorder, &overrides);
        self.observe(py)
    }

    /// The observation at the current state (without stepping).
    fn observation<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        self.observe(py)
    }

    /// Whether the approach has ended.
    #[getter]
    fn done(&self) -> bool {
        self.stepper.ended()
    }

    /// The outcome once ended (`trap`, `bolter`, …), else None.
    #[getter]
    fn outcome(&self) -> Option<&'static str> {
        self.summary().map(|s| s.outcome.name())
    }

    /// The summary once ended (a dict, as `summary.json`), else None.
    #[getter(summary)]
    fn summary_dict(&self, py: Python<'_>) -> PyResult<Option<Py<PyAny>>> {
        let Some(summary) = self.summary() else {
            return Ok(None);
        };
        let label = self.controller_label(py)?;
        Ok(Some(summary_dict(
            py, summary, &label, &self.name, self.seed,
        )?))
    }

    /// The events so far (ramp crossing, touchdown, passing the last wire, the wave-off
    /// decision), as dicts.
    #[getter]
    fn events<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        events_list(py, &self.recorder.events)
    }

    /// Simulated time (s).
    #[getter]
    fn time_s(&self) -> f64 {
        self.stepper.simulation.time_s()
    }

    /// The seed of the current episode.
    #[getter]
    fn seed(&self) -> u64 {
        self.seed
    }

    /// The control interval (s).
    #[getter]
    fn control_interval_s(&self) -> f64 {
        self.control_interval_s
    }

    /// The integration step (s).
    #[getter]
    fn time_step_s(&self) -> f64 {
        self.stepper.simulation.time_step_s()
    }

    /// The scenario flown (a copy; its seed is the episode's).
    #[getter]
    fn scenario(&self) -> Scenario {
        Scenario {
            scenario: self.base,
            name: self.name.clone(),
        }
    }

    /// The trim the controllers were designed at: `alpha_rad`, `theta_rad`,
    /// `elevator_rad`, `thrust_n`, and `max_thrust_n` (both engines).
    #[getter]
    fn trim<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let system = self.stepper.simulation.system();
        let trim = system.trim();
        let dict = PyDict::new(py);
        dict.set_item("alpha_rad", trim.alpha_rad)?;
        dict.set_item("theta_rad", trim.theta_rad)?;
        dict.set_item("elevator_rad", trim.elevator_rad)?;
        dict.set_item("thrust_n", trim.thrust_n)?;
        dict.set_item(
            "max_thrust_n",
            system.aircraft().engines().max_total_thrust_n(),
        )?;
        Ok(dict)
    }

    /// The Python pitch law (None: the scenario's own law flies).
    #[getter]
    fn get_pitch_law(&self, py: Python<'_>) -> Option<Py<PyAny>> {
        self.pitch_law.as_ref().map(|law| law.clone_ref(py))
    }

    #[setter]
    fn set_pitch_law(&mut self, law: Option<Bound<'_, PyAny>>) -> PyResult<()> {
        if let Some(law) = &law {
            python_law_label(law)?;
        }
        self.pitch_law = law.map(Bound::unbind);
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!(
            "Approach(scenario={:?}, seed={}, control_interval_s={}, time_s={:.3}, done={})",
            self.name,
            self.seed,
            self.control_interval_s,
            self.stepper.simulation.time_s(),
            self.stepper.ended()
        )
    }
}

/// For the benchmarks: flies the approach `Approach` would fly, by bare integration
/// steps in Rust (no observation, no Python), and returns (control intervals, seconds
/// spent stepping). The difference to stepping `Approach` is the cost `Approach.step`
/// adds on top of the simulation.
#[pyfunction]
#[pyo3(name = "_bench_stepping", signature = (scenario = None, seed = None, control_interval_s = 0.02))]
pub fn bench_stepping(
    py: Python<'_>,
    scenario: Option<PyRef<'_, Scenario>>,
    seed: Option<i128>,
    control_interval_s: f64,
) -> PyResult<(u64, f64)> {
    let base = scenario_or_default(scenario);
    let flown = flight_scenario(&base.scenario, seed, false)?;
    let per_interval = steps_per_interval(control_interval_s, flown.time_step_s)?;
    let mut simulation = Simulation::new(&flown)
        .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
    Ok(py.detach(|| {
        let mut recorder = EventRecorder::default();
        let overrides = Overrides::default();
        let started = Instant::now();
        let mut intervals = 0;
        'run: loop {
            intervals += 1;
            let target_time_s = (intervals * per_interval) as f64 * simulation.time_step_s();
            loop {
                if let Stop::Ended(_) = simulation.step_with(&mut recorder, &overrides) {
                    break 'run;
                }
                if simulation.time_s() >= target_time_s {
                    break;
                }
            }
        }
        (intervals, started.elapsed().as_secs_f64())
    }))
}
