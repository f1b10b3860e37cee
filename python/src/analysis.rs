//! `deckland.trim` and `deckland.linearize`: the numbers of `deckland trim --json` and
//! `deckland linearize --json`, as Python objects and numpy arrays.

use deckland::aircraft::{AerodynamicConfiguration, Aircraft, ConfigurationName};
use deckland::analysis::{
    identify_modes, linearize as linearize_about, trim as trim_aircraft, TrimPoint, TrimRequest,
    INPUT_NAMES, INPUT_UNITS, STATE_NAMES, STATE_UNITS,
};
use numpy::{Complex64, PyArray1, PyArray2};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::to_python;
use crate::errors::{argument_error, value_error};

/// A trimmed flight condition: steady straight flight at `speed_mps` and `gamma_deg`.
///
/// Angles in degrees (as `deckland trim` prints them), thrust in N for both engines,
/// `throttle` the thrust as a fraction of their total maximum thrust; `residuals` are the
/// rates left at the solution (V̇ m/s², α̇ rad/s, q̇ rad/s²), `iterations` Newton's.
#[pyclass(name = "Trim", module = "deckland", frozen, get_all)]
#[derive(Debug)]
pub struct Trim {
    /// Aerodynamic configuration: `landing` or `clean`.
    configuration: String,
    /// True airspeed (m/s).
    speed_mps: f64,
    /// Flight-path angle (deg), positive climbing.
    gamma_deg: f64,
    /// Angle of attack α (deg).
    alpha_deg: f64,
    /// Pitch angle θ (deg).
    theta_deg: f64,
    /// Elevator δe (deg), positive trailing edge down.
    elevator_deg: f64,
    /// Total thrust of both engines (N).
    thrust_n: f64,
    /// Thrust as a fraction of the total maximum thrust (–).
    throttle: f64,
    /// Rates left at the solution: airspeed_rate_mps2, alpha_rate_radps,
    /// pitch_acceleration_radps2.
    residuals: Py<PyAny>,
    /// Newton iterations taken.
    iterations: usize,
}

impl Trim {
    fn new(py: Python<'_>, configuration: ConfigurationName, point: &TrimPoint) -> PyResult<Self> {
        // The degrees and names of `deckland trim --json`, from the library.
        let report = point.report(configuration);
        Ok(Self {
            residuals: to_python(py, &report.residuals)?,
            configuration: report.configuration,
            speed_mps: report.speed_mps,
            gamma_deg: report.gamma_deg,
            alpha_deg: report.alpha_deg,
            theta_deg: report.theta_deg,
            elevator_deg: report.elevator_deg,
            thrust_n: report.thrust_n,
            throttle: report.throttle,
            iterations: report.iterations,
        })
    }
}

#[pymethods]
impl Trim {
    /// The trim as a dict, with the keys of `deckland trim --json`.
    fn to_dict<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        dict.set_item("configuration", &self.configuration)?;
        dict.set_item("speed_mps", self.speed_mps)?;
        dict.set_item("gamma_deg", self.gamma_deg)?;
        dict.set_item("alpha_deg", self.alpha_deg)?;
        dict.set_item("theta_deg", self.theta_deg)?;
        dict.set_item("elevator_deg", self.elevator_deg)?;
        dict.set_item("thrust_n", self.thrust_n)?;
        dict.set_item("throttle", self.throttle)?;
        dict.set_item("residuals", self.residuals.bind(py))?;
        dict.set_item("iterations", self.iterations)?;
        Ok(dict)
    }

    fn __repr__(&self) -> String {
        format!(
            "Trim(configuration={:?}, speed_mps={}, gamma_deg={}, alpha_deg={:.4}, \
             theta_deg={:.4}, elevator_deg={:.4}, thrust_n={:.1}, throttle={:.4})",
            self.configuration,
            self.speed_mps,
            self.gamma_deg,
            self.alpha_deg,
            self.theta_deg,
            self.elevator_deg,
            self.thrust_n,
            self.throttle
        )
    }
}

/// The aircraft in `configuration` and the trim point `deckland trim` finds for the same
/// arguments; errors carry the CLI's text.
fn trimmed(
    speed_mps: f64,
    gamma_deg: f64,
    configuration: &str,
) -> PyResult<(Aircraft, ConfigurationName, TrimPoint)> {
    let name: ConfigurationName = configuration
        .parse()
        .map_err(|message: String| argument_error("configuration", configuration, message))?;
    let aircraft = Aircraft::with_configuration(AerodynamicConfiguration::named(name));
    let request = TrimRequest {
        speed_mps,
        flight_path_angle_rad: gamma_deg.to_radians(),
    };
    let point = trim_aircraft(&aircraft, &request).map_err(|error| {
        value_error(format!(
            "cannot trim the {name} configuration at {speed_mps} m/s and γ = {gamma_deg}°: \
             {error}"
        ))
    })?;
    Ok((aircraft, name, point))
}

/// Trims the F/A-18 for steady straight flight (`deckland trim`): unknowns α, δe and
/// thrust, θ = α + γ, still air.
///
/// `speed_mps` is the true airspeed (m/s), `gamma_deg` the flight-path angle (deg,
/// positive climbing: a 3.5° glide slope is −3.5), `configuration` `"landing"` or
/// `"clean"`. Raises `ValueError` when no trim exists (the CLI's message).
#[pyfunction]
#[pyo3(signature = (speed_mps = 69.1, gamma_deg = 0.0, configuration = "landing"))]
pub fn trim(py: Python<'_>, speed_mps: f64, gamma_deg: f64, configuration: &str) -> PyResult<Trim> {
    let (_, name, point) = trimmed(speed_mps, gamma_deg, configuration)?;
    Trim::new(py, name, &point)
}

/// A linear model ẋ = A x + B u about a trim point (paper Eq. 14 form), as
/// `deckland linearize` prints it.
///
/// States x = (ΔV_T m/s, Δθ rad, Δα rad, Δq rad/s), inputs u = (Δδe rad, Δthrottle as a
/// fraction of the total maximum thrust), in the order of `state_names` and
/// `input_names`. `c` (identity) and `d` (zeros) make every state an output, so
/// `control.ss(lin.a, lin.b, lin.c, lin.d, states=lin.state_names,
/// inputs=lin.input_names)` is the model in python-control.
#[pyclass(name = "LinearModel", module = "deckland", frozen)]
#[derive(Debug)]
pub struct LinearModel {
    a: Vec<Vec<f64>>,
    b: Vec<Vec<f64>>,
    eigenvalues: Vec<(f64, f64)>,
    /// The trim point linearised about.
    #[pyo3(get)]
    trim: Py<Trim>,
    /// The modes (short period, phugoid, …) with their eigenvalue, natural frequency,
    /// damping ratio, period and time to half or double, as `deckland linearize --json`.
    #[pyo3(get)]
    modes: Py<PyAny>,
}

#[pymethods]
impl LinearModel {
    /// State matrix A (4×4).
    #[getter]
    fn a<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        PyArray2::from_vec2(py, &self.a).map_err(value_error)
    }

    /// Input matrix B (4×2).
    #[getter]
    fn b<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        PyArray2::from_vec2(py, &self.b).map_err(value_error)
    }

    /// Output matrix C: the identity (every state is an output).
    #[getter]
    fn c<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<Vec<f64>> = (0..STATE_NAMES.len())
            .map(|i| {
                (0..STATE_NAMES.len())
                    .map(|j| if i == j { 1.0 } else { 0.0 })
                    .collect()
            })
            .collect();
        PyArray2::from_vec2(py, &rows).map_err(value_error)
    }

    /// Feed-through matrix D: zeros (4×2).
    #[getter]
    fn d<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = vec![vec![0.0; INPUT_NAMES.len()]; STATE_NAMES.len()];
        PyArray2::from_vec2(py, &rows).map_err(value_error)
    }

    /// Eigenvalues of A (1/s), complex, in the order `deckland linearize --json` lists
    /// them.
    #[getter]
    fn eigenvalues<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<Complex64>> {
        let values: Vec<Complex64> = self
            .eigenvalues
            .iter()
            .map(|&(re, im)| Complex64::new(re, im))
            .collect();
        PyArray1::from_vec(py, values)
    }

    /// Names of the states, in order.
    #[getter]
    fn state_names(&self) -> Vec<&'static str> {
        STATE_NAMES.to_vec()
    }

    /// Units of the states, in order.
    #[getter]
    fn state_units(&self) -> Vec<&'static str> {
        STATE_UNITS.to_vec()
    }

    /// Names of the inputs, in order.
    #[getter]
    fn input_names(&self) -> Vec<&'static str> {
        INPUT_NAMES.to_vec()
    }

    /// Units of the inputs, in order (throttle: fraction of the total maximum thrust).
    #[getter]
    fn input_units(&self) -> Vec<&'static str> {
        INPUT_UNITS.to_vec()
    }

    fn __repr__(&self) -> String {
        format!(
            "LinearModel(states={:?}, inputs={:?}, eigenvalues={:?})",
            STATE_NAMES, INPUT_NAMES, self.eigenvalues
        )
    }
}

/// Linearises the F/A-18 about the trim `deckland.trim` finds for the same arguments
/// (`deckland linearize`): the airframe alone, in still air, by central differences.
#[pyfunction]
#[pyo3(signature = (speed_mps = 69.1, gamma_deg = 0.0, configuration = "landing"))]
pub fn linearize(
    py: Python<'_>,
    speed_mps: f64,
    gamma_deg: f64,
    configuration: &str,
) -> PyResult<LinearModel> {
    let (aircraft, name, point) = trimmed(speed_mps, gamma_deg, configuration)?;
    let model = linearize_about(&aircraft, &point);
    let rows = |m: &dyn Fn(usize, usize) -> f64, columns: usize| -> Vec<Vec<f64>> {
        (0..STATE_NAMES.len())
            .map(|i| (0..columns).map(|j| m(i, j)).collect())
            .collect()
    };
    let eigenvalues = model.eigenvalues();
    let modes = identify_modes(&eigenvalues);
    Ok(LinearModel {
        a: rows(&|i, j| model.a[(i, j)], STATE_NAMES.len()),
        b: rows(&|i, j| model.b[(i, j)], INPUT_NAMES.len()),
        eigenvalues: eigenvalues.iter().map(|l| (l.re, l.im)).collect(),
        trim: Py::new(py, Trim::new(py, name, &point)?)?,
        modes: to_python(py, &modes)?,
    })
}
