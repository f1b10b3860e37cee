//! Rows of a CSV file as columns of numpy arrays.
//!
//! The CLI writes `approach.csv` and `runs.csv` by serialising one row struct per line
//! (`deckland::experiments::ApproachRow`, `deckland::monte_carlo::RunRow`); the library's
//! [`Columns`] takes the same structs apart into columns, so the Python tables have
//! exactly the CSV's columns, in its order, from the one definition. A column becomes (by
//! its values):
//!
//! - `int64` for integers that are always there (run index, seed);
//! - `float64` for real numbers and for optional numbers (NaN where the CSV field is
//!   empty: `wire`, touchdown, the O-PD's disturbance estimate), whatever the values;
//! - `object` (Python `str` or `None`) for text (outcome, controller, reason).
//!
//! A column with no value at all (every run trapped: no `reason`) is `float64` NaN, as
//! `pandas.read_csv` reads an empty column.

use deckland::recording::Cell;
pub(crate) use deckland::recording::Columns;
use numpy::PyArray1;
use pyo3::prelude::*;
use pyo3::types::PyDict;

/// The columns of `table` as a dict of numpy arrays, in the order of the row's fields.
pub(crate) fn into_dict(table: Columns, py: Python<'_>) -> PyResult<Bound<'_, PyDict>> {
    let dict = PyDict::new(py);
    for (name, cells) in table.into_columns() {
        dict.set_item(name, column_array(py, cells)?)?;
    }
    Ok(dict)
}

/// One column's cells as a numpy array (see the module's doc for the types).
fn column_array(py: Python<'_>, cells: Vec<Cell>) -> PyResult<Bound<'_, PyAny>> {
    if cells.iter().all(|c| matches!(c, Cell::Integer(_))) && !cells.is_empty() {
        let values: Vec<i64> = cells
            .iter()
            .map(|c| match c {
                Cell::Integer(v) => *v,
                _ => 0,
            })
            .collect();
        return Ok(PyArray1::from_vec(py, values).into_any());
    }
    if cells
        .iter()
        .all(|c| matches!(c, Cell::Integer(_) | Cell::Float(_) | Cell::Missing))
    {
        let values: Vec<f64> = cells
            .iter()
            .map(|c| match c {
                Cell::Integer(v) => *v as f64,
                Cell::Float(v) => *v,
                _ => f64::NAN,
            })
            .collect();
        return Ok(PyArray1::from_vec(py, values).into_any());
    }
    let objects: Vec<Py<PyAny>> = cells
        .into_iter()
        .map(|c| -> PyResult<Py<PyAny>> {
            Ok(match c {
                Cell::Missing => py.None(),
                Cell::Integer(v) => v.into_pyobject(py)?.into_any().unbind(),
                Cell::Float(v) => v.into_pyobject(py)?.into_any().unbind(),
                Cell::Text(v) => v.into_pyobject(py)?.into_any().unbind(),
            })
        })
        .collect::<PyResult<_>>()?;
    Ok(PyArray1::from_vec(py, objects).into_any())
}
