//! Values between serde and Python: JSON values (summaries, statistics) and TOML values
//! (scenario keys) as Python objects, and Python values as TOML values.

use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};
use serde::Serialize;

use crate::errors::value_error;

/// A JSON value as a Python object: objects are dicts (in their order), arrays lists,
/// numbers int or float, null None.
pub(crate) fn json_to_python(py: Python<'_>, value: &serde_json::Value) -> PyResult<Py<PyAny>> {
    use serde_json::Value;
    Ok(match value {
        Value::Null => py.None(),
        Value::Bool(b) => PyBool::new(py, *b).to_owned().into_any().unbind(),
        Value::Number(n) => {
            if let Some(i) = n.as_i64() {
                i.into_pyobject(py)?.into_any().unbind()
            } else if let Some(u) = n.as_u64() {
                u.into_pyobject(py)?.into_any().unbind()
            } else {
                n.as_f64()
                    .unwrap_or(f64::NAN)
                    .into_pyobject(py)?
                    .into_any()
                    .unbind()
            }
        }
        Value::String(s) => s.into_pyobject(py)?.into_any().unbind(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(json_to_python(py, item)?)?;
            }
            list.into_any().unbind()
        }
        Value::Object(map) => {
            let dict = PyDict::new(py);
            for (key, item) in map {
                dict.set_item(key, json_to_python(py, item)?)?;
            }
            dict.into_any().unbind()
        }
    })
}

/// Any serialisable value as a Python object, through its JSON form (non-finite floats,
/// which JSON cannot hold, become None as in the CLI's JSON files).
pub(crate) fn to_python<T: Serialize>(py: Python<'_>, value: &T) -> PyResult<Py<PyAny>> {
    let json = serde_json::to_value(value).map_err(|e| value_error(e.to_string()))?;
    json_to_python(py, &json)
}

/// A TOML value as a Python object: tables are dicts, arrays lists.
pub(crate) fn toml_to_python(py: Python<'_>, value: &toml::Value) -> PyResult<Py<PyAny>> {
    use toml::Value;
    Ok(match value {
        Value::String(s) => s.into_pyobject(py)?.into_any().unbind(),
        Value::Integer(i) => i.into_pyobject(py)?.into_any().unbind(),
        Value::Float(f) => f.into_pyobject(py)?.into_any().unbind(),
        Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any().unbind(),
        Value::Datetime(d) => d.to_string().into_pyobject(py)?.into_any().unbind(),
        Value::Array(items) => {
            let list = PyList::empty(py);
            for item in items {
                list.append(toml_to_python(py, item)?)?;
            }
            list.into_any().unbind()
        }
        Value::Table(table) => {
            let dict = PyDict::new(py);
            for (key, item) in table {
                dict.set_item(key, toml_to_python(py, item)?)?;
            }
            dict.into_any().unbind()
        }
    })
}

/// A Python value as a TOML value: bool, int (or anything with `__index__`, such as a
/// numpy integer), float (or anything with `__float__`), str, dict with str keys, and
/// list or tuple. `path` names the key in errors.
pub(crate) fn python_to_toml(value: &Bound<'_, PyAny>, path: &str) -> PyResult<toml::Value> {
    use toml::Value;
    if value.is_instance_of::<PyBool>() {
        return Ok(Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(Value::String(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() || value.hasattr("__index__")? {
        return match value.extract::<i64>() {
            Ok(i) => Ok(Value::Integer(i)),
            Err(_) => Err(value_error(format!(
                "field `{path}`: {value} does not fit a signed 64-bit integer"
            ))),
        };
    }
    if value.is_instance_of::<PyFloat>() || value.hasattr("__float__")? {
        return Ok(Value::Float(value.extract()?));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        let mut table = toml::map::Map::new();
        for (key, item) in dict.iter() {
            let key: String = key.extract().map_err(|_| {
                PyTypeError::new_err(format!("field `{path}`: table keys must be str"))
            })?;
            let child = deckland::parameters::join(path, &key);
            table.insert(key, python_to_toml(&item, &child)?);
        }
        return Ok(Value::Table(table));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items = value
            .try_iter()?
            .enumerate()
            .map(|(index, item)| python_to_toml(&item?, &format!("{path}[{index}]")))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(Value::Array(items));
    }
    if value.hasattr("tolist")? {
        // A numpy array: as its list.
        return python_to_toml(&value.call_method0("tolist")?, path);
    }
    Err(PyTypeError::new_err(format!(
        "field `{path}`: a value of type {} cannot be set (expected bool, int, float, str, \
         dict or list)",
        value.get_type().name()?
    )))
}
