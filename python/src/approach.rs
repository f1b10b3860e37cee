//! `deckland.Approach`: an approach stepped one control interval at a time, with the
//! built-in cascade flying or the user replacing its loops (the stepping itself is
//! [`crate::stepping`]'s).

use std::time::Instant;

use deckland::experiments::OBSERVATION_COLUMNS;
use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{Overrides, RunSummary};
use pyo3::intern;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString};

use crate::outputs::{events_list, summary_dict};
use crate::scenario::{flown_scenario, scenario_or_default, with_seed, Scenario};
use crate::stepping::{parse_action, python_law_label, EventRecorder, Stepper};

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
///   alone replaces only its loop. The actuator and engines still apply their
///   dynamics.
///
/// - In a 3-D approach (`aircraft.model = "6dof"` with `approach.three_dimensional`),
///   the lateral loops too, as the 3-D environment's taps replace them:
///   `{"bank_command_rad": φ}` replaces the lineup guidance (the roll law tracks φ),
///   `{"sideslip_command_rad": β}` the yaw law's reference (zero sideslip: coordinated),
///   `{"aileron_rad": δa}` the roll law and `{"rudder_rad": δr}` the yaw law (absolute
///   deflections, right wing down and trailing edge left positive). A 3-DOF approach
///   refuses them (`ValueError`).
///
/// Each key has a physical range (`action_ranges`): `pitch_command_rad` within ±π/2
/// (the pitch attitude's range), `elevator_rad` within the stabilator's travel
/// (`aircraft.elevator_actuator`, −25° to +10° by default), `thrust_n` from 0 to the
/// maximum thrust of both engines; `bank_command_rad` within ±π/2, `sideslip_command_rad`
/// within ±30°, `aileron_rad` and `rudder_rad` within their travel
/// (`aircraft.aileron_actuator.travel_deg`, 25°; `aircraft.rudder_actuator.travel_deg`,
/// 30°). A value beyond its range, or not finite, raises `ValueError` naming the key, the
/// value and the range.
/// The built-in law's `elevator_command_rad` can lie beyond the travel (the actuator
/// saturates it): limit it to the range before sending it back as an action.
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
/// - in a 3-D approach also the lineup, the lateral states and surfaces under
///   `approach.csv`'s names (`cross_track_m`, `bank_deg`, `sideslip_deg`, `aileron_deg`,
///   `rudder_deg`, …; degrees where the name says so);
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
    fn observe<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let look = self.stepper.look();
        let s = &look.signals;
        let obs = PyDict::new(py);
        // The registered signals the observation shows (deckland::experiments), in order.
        for column in &OBSERVATION_COLUMNS {
            obs.set_item(PyString::intern(py, column.name), column.value(s))?;
        }
        // The loop's parts' columns after them (as `approach.csv`'s): a 3-D approach's
        // lineup, lateral states and surfaces.
        for column in self.stepper.simulation().lateral_columns() {
            obs.set_item(PyString::intern(py, column.name), column.value(s))?;
        }
        let summary = self.stepper.simulation().summary();
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
        self.stepper.simulation().summary()
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
        let flown = flown_scenario(&base.scenario, seed, false)?;
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
        let scenario = with_seed(self.base, seed.or(Some(self.seed.into())))?;
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
        let mut overrides = parse_action(action, self.stepper.ranges())?;
        if let Some(law) = &self.pitch_law {
            overrides = self.stepper.law_overrides(law.bind(py), Some(overrides))?;
        }
        self.stepper.advance(&mut self.recorder, &overrides);
        self.observe(py)
    }

    /// The observation at the current state (without stepping).
    fn observation<'py>(&mut self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
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
        self.stepper.simulation().time_s()
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
        self.stepper.simulation().time_step_s()
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
        let system = self.stepper.simulation().system();
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

    /// The physical range of each action key, `{key: (low, high)}`: `pitch_command_rad`
    /// the pitch attitude's range (±π/2 rad), `elevator_rad` the stabilator's travel
    /// (rad), `thrust_n` from none to the maximum total thrust of both engines (N).
    #[getter]
    fn action_ranges<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (key, range, ..) in self.stepper.ranges().described() {
            dict.set_item(key, range)?;
        }
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
            self.stepper.simulation().time_s(),
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
    let flown = flown_scenario(&base.scenario, seed, false)?;
    let mut stepper = Stepper::new(&flown, control_interval_s)?;
    Ok(py.detach(|| {
        let mut recorder = EventRecorder::default();
        let overrides = Overrides::default();
        let started = Instant::now();
        let mut intervals = 0;
        while !stepper.ended() {
            intervals += 1;
            stepper.advance(&mut recorder, &overrides);
        }
        (intervals, started.elapsed().as_secs_f64())
    }))
}
