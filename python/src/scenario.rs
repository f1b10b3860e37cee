//! `deckland.Scenario`: every parameter of a run, read and set by dotted path.
//!
//! A `Scenario` is always valid: every change is checked at once by the library's own
//! checks ([`deckland::scenario::Scenario::validate`]), and a bad value leaves the
//! scenario as it was and raises `ValueError` with the text the command line prints for
//! the same value in a scenario file, from `field` on (the CLI puts the file and line
//! before it); `from_toml` and `from_file` raise the CLI's text whole.

use std::path::PathBuf;

use deckland::monte_carlo::dispersed_run_scenario;
use deckland::parameters::join;
use deckland::scenario::{load_scenario, load_scenario_in, Mission, Scenario as RustScenario};
use pyo3::exceptions::{PyFileNotFoundError, PyKeyError, PyOSError};
use pyo3::prelude::*;
use pyo3::types::{PyTuple, PyType};

use crate::convert::{python_to_toml, toml_to_python};
use crate::errors::{first_line, value_error};

/// The label of the default scenario in summaries (`conditions`), as `deckland land`
/// writes it.
pub(crate) const DEFAULT_NAME: &str = "adverse";

/// Every parameter of one run (the scenario file, as an object).
///
/// `Scenario.default()` is the default scenario: adverse conditions (wind, air wake,
/// turbulence, sensor noise, deck motion), O-PD pitch control, seed 1: what
/// `deckland land` flies. `Scenario.from_toml(text)` and `Scenario.from_file(path)` read
/// a scenario file (`deckland scenario --print-default` prints a commented template);
/// keys left out take their defaults.
///
/// Keys are read and set by dotted path, as in the file:
/// `s["environment.ship.heave_rms_m"] = 1.0`. A value out of range, of the wrong type or
/// an unknown key raises `ValueError` and leaves the scenario unchanged. A tagged
/// section is switched whole: `s["control.pitch"] = {"type": "pid"}`.
///
/// `name` is the label written as `conditions` in a flight's summary (as the CLI does):
/// `adverse` for the default scenario, the file's name for a file.
#[pyclass(name = "Scenario", module = "deckland", from_py_object)]
#[derive(Debug, Clone, PartialEq)]
pub struct Scenario {
    pub(crate) scenario: RustScenario,
    /// The label written as `conditions` in a flight's summary.
    #[pyo3(get, set)]
    pub(crate) name: String,
}

impl Scenario {
    /// The scenario's values as a TOML table.
    fn tree(&self) -> PyResult<toml::Value> {
        toml::Value::try_from(self.scenario).map_err(|e| value_error(e.to_string()))
    }

    /// The value at `path`, if there is one.
    fn lookup(&self, path: &str) -> PyResult<Option<toml::Value>> {
        let mut node = self.tree()?;
        if path.is_empty() {
            return Ok(Some(node));
        }
        for key in path.split('.') {
            node = match node {
                toml::Value::Table(mut table) => match table.remove(key) {
                    Some(child) => child,
                    None => return Ok(None),
                },
                _ => return Ok(None),
            };
        }
        Ok(Some(node))
    }
}

/// The default scenario as the Python object.
pub(crate) fn default_scenario() -> Scenario {
    Scenario {
        scenario: RustScenario::default(),
        name: DEFAULT_NAME.to_owned(),
    }
}

/// The scenario of an optional argument: the default when `None`.
pub(crate) fn scenario_or_default(scenario: Option<PyRef<'_, Scenario>>) -> Scenario {
    scenario.map_or_else(default_scenario, |s| s.clone())
}

/// The scenario with `seed` when given, checked against the seed's range.
pub(crate) fn with_seed(scenario: RustScenario, seed: Option<i128>) -> PyResult<RustScenario> {
    let Some(seed) = seed else {
        return Ok(scenario);
    };
    let max = deckland::scenario::MAX_SEED;
    match u64::try_from(seed) {
        Ok(seed) if seed <= max => Ok(RustScenario { seed, ..scenario }),
        _ => Err(crate::errors::argument_error(
            "seed",
            seed,
            format_args!("an integer in [0, {max}] (2⁶³ − 1)"),
        )),
    }
}

/// The scenario a flight flies, as an approach: with `seed` (else the scenario's own),
/// and when `disperse`, with the dispersions the campaign run of that seed draws
/// ([`dispersed_run_scenario`]).
pub(crate) fn flown_scenario(
    scenario: &RustScenario,
    seed: Option<i128>,
    disperse: bool,
) -> PyResult<RustScenario> {
    let mut scenario = with_seed(*scenario, seed)?;
    if disperse {
        scenario = dispersed_run_scenario(&scenario, scenario.seed).0;
    }
    Ok(RustScenario {
        mission: Mission::Approach,
        ..scenario
    })
}

#[pymethods]
impl Scenario {
    /// The default scenario (same as `Scenario.default()`).
    #[new]
    fn new() -> Self {
        default_scenario()
    }

    /// The default scenario: the realistic hardware (40 °/s stabilator, 80 Hz flight
    /// computer, controllers designed for them), adverse conditions, O-PD pitch control,
    /// seed 1.
    #[staticmethod]
    fn default() -> Self {
        default_scenario()
    }

    /// The paper's hardware set: ideal actuator, continuous control, the paper's gains;
    /// adverse conditions, O-PD pitch control, seed 1 (`deckland land --hardware paper`).
    #[staticmethod]
    fn paper() -> Self {
        Self {
            scenario: RustScenario::paper(),
            name: DEFAULT_NAME.to_owned(),
        }
    }

    /// A scenario from the text of a scenario file (TOML); `name` is the file name used
    /// in error messages and as the summary's `conditions`.
    #[staticmethod]
    #[pyo3(signature = (text, name = "scenario.toml"))]
    fn from_toml(text: &str, name: &str) -> PyResult<Self> {
        let scenario = load_scenario(text, name).map_err(value_error)?;
        Ok(Self {
            scenario,
            name: name.to_owned(),
        })
    }

    /// A scenario from a scenario file; errors name the file, the line and the field as
    /// `deckland run` does.
    #[staticmethod]
    fn from_file(path: PathBuf) -> PyResult<Self> {
        let shown = path.display().to_string();
        let text = std::fs::read_to_string(&path).map_err(|error| {
            let message = format!("cannot read the scenario file {shown}: {error}");
            if error.kind() == std::io::ErrorKind::NotFound {
                PyFileNotFoundError::new_err(message)
            } else {
                PyOSError::new_err(message)
            }
        })?;
        // An aircraft definition the file names is read relative to the file's folder.
        let folder = path.parent().unwrap_or(std::path::Path::new(""));
        let scenario = load_scenario_in(&text, &shown, folder).map_err(value_error)?;
        let name = path
            .file_name()
            .map_or(shown, |n| n.to_string_lossy().into_owned());
        Ok(Self { scenario, name })
    }

    /// The value at a dotted path: a number, bool or str for a key, a dict for a section.
    fn __getitem__(&self, py: Python<'_>, path: &str) -> PyResult<Py<PyAny>> {
        match self.lookup(path)? {
            Some(value) => toml_to_python(py, &value),
            None => Err(PyKeyError::new_err(format!(
                "the scenario has no key `{path}`"
            ))),
        }
    }

    /// Sets the value at a dotted path, checking it (and the whole scenario) at once.
    fn __setitem__(&mut self, path: &str, value: &Bound<'_, PyAny>) -> PyResult<()> {
        if path.is_empty() || path.split('.').any(str::is_empty) {
            return Err(value_error(format!(
                "field `{path}`: not a dotted path of the scenario"
            )));
        }
        let new_value = python_to_toml(value, path)?;
        let mut tree = self.tree()?;
        let mut node = &mut tree;
        let keys: Vec<&str> = path.split('.').collect();
        for (depth, key) in keys.iter().enumerate() {
            let toml::Value::Table(table) = node else {
                let parent = keys[..depth].join(".");
                return Err(value_error(format!(
                    "field `{path}`: `{parent}` is a value, not a section"
                )));
            };
            if depth + 1 == keys.len() {
                table.insert((*key).to_owned(), new_value);
                break;
            }
            node = table
                .entry((*key).to_owned())
                .or_insert_with(|| toml::Value::Table(toml::map::Map::new()));
        }
        // A tagged section set whole is named by its tag in errors about the variant,
        // as the file loader names it (`control.pitch.type`, `mission.kind`).
        let tag = match value.cast::<pyo3::types::PyDict>() {
            Ok(dict) => ["type", "kind"]
                .into_iter()
                .find(|key| dict.contains(*key).unwrap_or(false)),
            Err(_) => None,
        };
        let scenario = check_tree(tree, path, tag)?;
        self.scenario = scenario;
        Ok(())
    }

    fn __contains__(&self, path: &str) -> PyResult<bool> {
        Ok(self.lookup(path)?.is_some())
    }

    /// Every key's dotted path, in the order of the scenario file.
    fn keys(&self) -> PyResult<Vec<String>> {
        fn walk(prefix: &str, value: &toml::Value, out: &mut Vec<String>) {
            match value {
                toml::Value::Table(table) => {
                    for (key, child) in table {
                        walk(&join(prefix, key), child, out);
                    }
                }
                _ => out.push(prefix.to_owned()),
            }
        }
        let mut keys = Vec::new();
        walk("", &self.tree()?, &mut keys);
        Ok(keys)
    }

    /// The scenario as a scenario file (TOML), as the CLI writes `scenario.toml`.
    fn to_toml(&self) -> PyResult<String> {
        toml::to_string(&self.scenario).map_err(|e| value_error(e.to_string()))
    }

    /// The scenario as nested dicts.
    fn to_dict(&self, py: Python<'_>) -> PyResult<Py<PyAny>> {
        toml_to_python(py, &self.tree()?)
    }

    /// A copy (scenarios are values: changing the copy leaves this one alone).
    fn copy(&self) -> Self {
        self.clone()
    }

    fn __copy__(&self) -> Self {
        self.clone()
    }

    fn __deepcopy__(&self, _memo: &Bound<'_, PyAny>) -> Self {
        self.clone()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<Scenario>()
            .is_ok_and(|o| o.borrow().scenario == self.scenario)
    }

    fn __repr__(&self) -> String {
        format!(
            "Scenario(name={:?}, seed={}, pitch_law={:?})",
            self.name,
            self.scenario.seed,
            self.scenario.control.pitch.label()
        )
    }

    /// Pickling (for multiprocessing and Dask): rebuilt from its TOML text.
    fn __reduce__<'py>(
        slf: &Bound<'py, Self>,
    ) -> PyResult<(Bound<'py, PyAny>, Bound<'py, PyTuple>)> {
        let py = slf.py();
        let this = slf.borrow();
        let class: Bound<'py, PyType> = slf.get_type();
        let constructor = class.getattr("from_toml")?;
        let arguments = PyTuple::new(py, [this.to_toml()?, this.name.clone()])?;
        Ok((constructor, arguments))
    }
}

/// The scenario a changed tree describes, checked; errors name the field as the CLI's
/// scenario-file errors do.
fn check_tree(tree: toml::Value, path: &str, tag: Option<&str>) -> PyResult<RustScenario> {
    let approach_extras = match &tree {
        toml::Value::Table(root) => match root.get("mission") {
            Some(toml::Value::Table(mission)) => mission
                .keys()
                .find(|key| key.as_str() != "kind")
                .map(|key| format!("mission.{key}")),
            _ => None,
        },
        _ => None,
    };
    let scenario: RustScenario = tree.try_into().map_err(|error: toml::de::Error| {
        let message = first_line(error.message());
        // An unknown key is named by its own path: the part of `path` up to it.
        let keys: Vec<&str> = path.split('.').collect();
        let field = match unknown_field_name(&message)
            .and_then(|name| keys.iter().position(|key| *key == name))
        {
            Some(index) => keys[..=index].join("."),
            None => match tag {
                Some(tag) if message.starts_with("unknown variant") => join(path, tag),
                _ => path.to_owned(),
            },
        };
        value_error(format!("field `{field}`: {message}"))
    })?;
    // A key the ship model sets itself (the seaway's RMS) cannot be set: as the file
    // loader refuses it written beside the model.
    let model = scenario.environment.ship.model;
    if let Some(key) = path.strip_prefix("environment.ship.") {
        if model.derived_keys().contains(&key) {
            return Err(value_error(format!(
                "field `{path}`: set by the ship model `{}`: change \
                 `environment.seaway.significant_wave_height_m` instead, or set \
                 `environment.ship.model` = \"filters\" first",
                model.name()
            )));
        }
    }
    // serde ignores extra keys beside the tag of a unit variant: as the file loader.
    if let (Mission::Approach, Some(extra)) = (scenario.mission, approach_extras) {
        return Err(value_error(format!(
            "field `{extra}`: unknown field: an `approach` mission takes only `kind`"
        )));
    }
    scenario.validate().map_err(|problem| {
        value_error(format!(
            "field `{}`: {} is not allowed: expected {}",
            problem.path, problem.value, problem.allowed
        ))
    })?;
    Ok(scenario)
}

/// The field named in serde's "unknown field `name`, expected …" message.
fn unknown_field_name(message: &str) -> Option<&str> {
    let rest = message.strip_prefix("unknown field `")?;
    rest.split('`').next()
}
