//! `deckland.trim_six_dof` and `deckland.linearize_six_dof`: the numbers of
//! `deckland trim --model 6dof --json` and `deckland linearize --model 6dof --json`, as
//! Python dictionaries and numpy arrays.

use deckland::aircraft::six_dof::{
    linearize_six_dof as linearize_about, trim_six_dof as trim_aircraft, LateralModesReport,
    LateralParameters, SixDofAircraft, SixDofTrimError, SixDofTrimPoint, SixDofTrimRequest,
    SurfaceActuatorParameters, LATERAL_INPUT_NAMES, LATERAL_INPUT_UNITS, LATERAL_STATE_NAMES,
    LATERAL_STATE_UNITS,
};
use deckland::aircraft::{
    AerodynamicConfiguration, Aircraft, ConfigurationName, TrimRequest, INPUT_NAMES, INPUT_UNITS,
    STATE_NAMES, STATE_UNITS,
};
use deckland::environment::Wind;
use numpy::PyArray2;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::to_python;
use crate::errors::{argument_error, value_error};

/// The 6-DOF aircraft and its trim point for the arguments, with the CLI's messages.
fn trimmed(
    speed_mps: f64,
    gamma_deg: f64,
    sideslip_deg: f64,
    crosswind_mps: f64,
    configuration: &str,
) -> PyResult<(SixDofAircraft, ConfigurationName, SixDofTrimPoint)> {
    let name: ConfigurationName = configuration
        .parse()
        .map_err(|message: String| argument_error("configuration", configuration, message))?;
    if !crosswind_mps.is_finite() {
        return Err(argument_error(
            "crosswind_mps",
            crosswind_mps,
            "a finite crosswind (m/s)",
        ));
    }
    let aircraft = SixDofAircraft::new(
        Aircraft::with_configuration(AerodynamicConfiguration::named(name)),
        LateralParameters::default(),
        SurfaceActuatorParameters::AILERON,
        SurfaceActuatorParameters::RUDDER,
    )
    .map_err(value_error)?;
    let request = SixDofTrimRequest {
        longitudinal: TrimRequest {
            speed_mps,
            flight_path_angle_rad: gamma_deg.to_radians(),
        },
        sideslip_rad: sideslip_deg.to_radians(),
        wind: Wind {
            y_mps: crosswind_mps,
            ..Wind::default()
        },
    };
    let point = trim_aircraft(&aircraft, &request).map_err(|error| match error {
        SixDofTrimError::InvalidSideslip { .. } => argument_error(
            "sideslip_deg",
            sideslip_deg,
            "a sideslip between -30 and +30 degrees",
        ),
        error => value_error(format!(
            "cannot trim the 6-DOF aircraft ({name} configuration) at {speed_mps} m/s, \
             γ = {gamma_deg}°, β = {sideslip_deg}°, crosswind {crosswind_mps} m/s: {error}"
        )),
    })?;
    Ok((aircraft, name, point))
}

/// Trims the 6-DOF F/A-18 for steady straight flight (`deckland trim --model 6dof`):
/// at `speed_mps` (m/s) and `gamma_deg` (deg, positive climbing), in a sideslip
/// `sideslip_deg` (deg, positive with the relative wind from the right; aileron, rudder
/// and bank hold it) or in a crosswind `crosswind_mps` (m/s, positive blowing to the
/// right; the heading crabs into it). Returns the dictionary `--json` prints (angles in
/// degrees). Raises `ValueError` with the CLI's message when no trim exists.
#[pyfunction]
#[pyo3(signature = (speed_mps = 69.1, gamma_deg = 0.0, sideslip_deg = 0.0, crosswind_mps = 0.0, configuration = "landing"))]
pub fn trim_six_dof(
    py: Python<'_>,
    speed_mps: f64,
    gamma_deg: f64,
    sideslip_deg: f64,
    crosswind_mps: f64,
    configuration: &str,
) -> PyResult<Py<PyAny>> {
    let (_, name, point) = trimmed(
        speed_mps,
        gamma_deg,
        sideslip_deg,
        crosswind_mps,
        configuration,
    )?;
    to_python(py, &point.report(name))
}

/// A matrix of `rows` × `columns` entries `at(i, j)` as a numpy array.
fn array<'py>(
    py: Python<'py>,
    (rows, columns): (usize, usize),
    at: impl Fn(usize, usize) -> f64,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let rows: Vec<Vec<f64>> = (0..rows)
        .map(|i| (0..columns).map(|j| at(i, j)).collect())
        .collect();
    PyArray2::from_vec2(py, &rows).map_err(value_error)
}

/// Linearises the 6-DOF airframe about its trim (`deckland linearize --model 6dof`), with
/// the arguments of [`trim_six_dof`]. Returns a dictionary: `trim` (as `trim_six_dof`),
/// `lateral_a` (4×4) and `lateral_b` (4×2) numpy arrays over `lateral_state_names`
/// (sideslip rad, roll rate rad/s, yaw rate rad/s, bank angle rad) and
/// `lateral_input_names` (aileron rad, rudder rad) with their units, `lateral_modes` (Dutch
/// roll ω_n and ζ, roll subsidence and spiral; `None` if the roots are not one pair and
/// two reals), and the longitudinal block `longitudinal_a`, `longitudinal_b` in the 3-DOF
/// model's names.
#[pyfunction]
#[pyo3(signature = (speed_mps = 69.1, gamma_deg = 0.0, sideslip_deg = 0.0, crosswind_mps = 0.0, configuration = "landing"))]
pub fn linearize_six_dof<'py>(
    py: Python<'py>,
    speed_mps: f64,
    gamma_deg: f64,
    sideslip_deg: f64,
    crosswind_mps: f64,
    configuration: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let (aircraft, name, point) = trimmed(
        speed_mps,
        gamma_deg,
        sideslip_deg,
        crosswind_mps,
        configuration,
    )?;
    let model = linearize_about(&aircraft, &point);
    let modes = model.lateral_modes().as_ref().map(LateralModesReport::from);
    let dict = PyDict::new(py);
    dict.set_item("trim", to_python(py, &point.report(name))?)?;
    let (lateral_a, lateral_b) = (model.lateral_a(), model.lateral_b());
    let (longitudinal_a, longitudinal_b) = (model.longitudinal_a(), model.longitudinal_b());
    let blocks = [
        (
            "lateral",
            [LATERAL_STATE_NAMES, LATERAL_STATE_UNITS],
            [LATERAL_INPUT_NAMES, LATERAL_INPUT_UNITS],
            array(py, lateral_a.shape(), |i, j| lateral_a[(i, j)])?,
            array(py, lateral_b.shape(), |i, j| lateral_b[(i, j)])?,
        ),
        (
            "longitudinal",
            [STATE_NAMES, STATE_UNITS],
            [INPUT_NAMES, INPUT_UNITS],
            array(py, longitudinal_a.shape(), |i, j| longitudinal_a[(i, j)])?,
            array(py, longitudinal_b.shape(), |i, j| longitudinal_b[(i, j)])?,
        ),
    ];
    for (block, [state_names, state_units], [input_names, input_units], a, b) in blocks {
        dict.set_item(format!("{block}_state_names"), state_names.to_vec())?;
        dict.set_item(format!("{block}_state_units"), state_units.to_vec())?;
        dict.set_item(format!("{block}_input_names"), input_names.to_vec())?;
        dict.set_item(format!("{block}_input_units"), input_units.to_vec())?;
        dict.set_item(format!("{block}_a"), a)?;
        dict.set_item(format!("{block}_b"), b)?;
    }
    dict.set_item("lateral_modes", to_python(py, &modes)?)?;
    Ok(dict)
}
