//! Errors as Python exceptions: bad input is a `ValueError` whose text is the one the
//! command line prints for the same input (after its `error: `).

use pyo3::exceptions::PyValueError;
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

/// The first line of a parser's message, as the scenario-file errors show it.
pub(crate) fn first_line(message: &str) -> String {
    message.lines().next().unwrap_or("").trim().to_owned()
}
