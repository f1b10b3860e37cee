//! Errors as Python exceptions: bad input is a `ValueError` whose text is the one the
//! command line prints for the same input (after its `error: `).

use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBool;
use pyo3::PyErr;

/// A `ValueError` with `message`.
pub(crate) fn value_error(message: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(message.to_string())
}

/// The error for an argument `name` = `value` outside what is allowed, in the shape of
/// the library's parameter errors.
pub(crate) fn argument_error(
    name: &str,
    value: impl std::fmt::Display,
    allowed: impl std::fmt::Display,
) -> PyErr {
    value_error(format!(
        "`{name}` = {value} is not allowed: expected {allowed}"
    ))
}

/// A whole-number argument `name` as given, refusing what Python would convert to one
/// without saying so: `True`/`False` (a bool is an int to Python) and anything that is not
/// an integer (`1.5`, `"3"`), each a `TypeError` naming the argument (issue 45, R9).
pub(crate) fn strict_integer(name: &str, value: &Bound<'_, PyAny>) -> PyResult<i128> {
    let refused = || {
        PyTypeError::new_err(format!(
            "`{name}` = {} is not allowed: expected a whole number (an int, not a bool, \
             float or string)",
            value
                .repr()
                .map_or_else(|_| "?".to_owned(), |r| r.to_string())
        ))
    };
    if value.is_instance_of::<PyBool>() {
        return Err(refused());
    }
    value.extract::<i128>().map_err(|_| refused())
}

/// The first line of a parser's message, as the scenario-file errors show it.
pub(crate) fn first_line(message: &str) -> String {
    message.lines().next().unwrap_or("").trim().to_owned()
}
