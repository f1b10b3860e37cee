//! Rows of a table as columns: the one definition of a file's rows (a serde struct, such
//! as `monte_carlo::RunRow` or `experiments::ApproachRow`, which depend on this module) taken apart
//! into typed columns, for columnar front ends (the CLI's `runs.parquet`, the Python
//! package's numpy arrays) that must have exactly the CSV's columns, in its order.
//!
//! [`Columns`] serialises the row structs with a small serde serialiser that keeps each
//! field's values in a column of [`Cell`]s: integers, real numbers (an optional integer
//! is a real number, so a column that can be missing is real), text, or missing.

use serde::ser::{self, Impossible, Serialize, SerializeStruct, Serializer};
use std::fmt;

/// One value of a row.
#[derive(Debug, Clone, PartialEq)]
pub enum Cell {
    /// No value (`None`: an empty CSV field).
    Missing,
    /// A whole number that is always there (run index, seed).
    Integer(i64),
    /// A real number, or an optional whole number.
    Float(f64),
    /// Text.
    Text(String),
}

/// Why a row could not be taken apart into cells (a row type this module does not
/// support: the rows are flat structs of numbers, text and options).
#[derive(Debug, Clone, PartialEq)]
pub struct ColumnError(String);

impl fmt::Display for ColumnError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for ColumnError {}

impl ser::Error for ColumnError {
    fn custom<T: fmt::Display>(message: T) -> Self {
        Self(message.to_string())
    }
}

/// A table built row by row from serialisable structs.
#[derive(Debug, Default)]
pub struct Columns {
    names: Vec<&'static str>,
    cells: Vec<Vec<Cell>>,
    rows: usize,
    /// Rows expected, to size the columns when the first row names them.
    hint: usize,
}

impl Columns {
    /// An empty table with room for `rows` rows.
    pub fn with_capacity(rows: usize) -> Self {
        Self {
            hint: rows,
            ..Self::default()
        }
    }

    /// Appends one row: a struct whose fields are the columns.
    pub fn push<T: Serialize>(&mut self, row: &T) -> Result<(), ColumnError> {
        row.serialize(RowSerializer { table: self })?;
        self.rows += 1;
        Ok(())
    }

    /// The column names, in the order of the struct's fields.
    pub fn names(&self) -> &[&'static str] {
        &self.names
    }

    /// How many rows the table holds.
    pub fn rows(&self) -> usize {
        self.rows
    }

    /// The columns with their names, in the order of the struct's fields.
    pub fn into_columns(self) -> Vec<(&'static str, Vec<Cell>)> {
        self.names.into_iter().zip(self.cells).collect()
    }

    fn cell(&mut self, field: usize, name: &'static str, cell: Cell) -> Result<(), ColumnError> {
        if self.rows == 0 {
            if field != self.names.len() {
                return Err(ColumnError(format!("field `{name}` out of order")));
            }
            self.names.push(name);
            self.cells.push(Vec::with_capacity(self.hint));
        } else if self.names.get(field) != Some(&name) {
            return Err(ColumnError(format!(
                "field `{name}` is not column {field} of the first row"
            )));
        }
        self.cells[field].push(cell);
        Ok(())
    }
}

/// A table of named columns of cells, in the order given (all of one length: the rows).
impl FromIterator<(&'static str, Vec<Cell>)> for Columns {
    fn from_iter<I: IntoIterator<Item = (&'static str, Vec<Cell>)>>(columns: I) -> Self {
        let (names, cells): (Vec<_>, Vec<_>) = columns.into_iter().unzip();
        Self {
            rows: cells.first().map_or(0, Vec::len),
            names,
            cells,
            hint: 0,
        }
    }
}

/// Serialises one row struct into the table.
struct RowSerializer<'a> {
    table: &'a mut Columns,
}

/// The fields of one row, in order.
struct RowFields<'a> {
    table: &'a mut Columns,
    field: usize,
}

impl SerializeStruct for RowFields<'_> {
    type Ok = ();
    type Error = ColumnError;

    fn serialize_field<T: ?Sized + Serialize>(
        &mut self,
        key: &'static str,
        value: &T,
    ) -> Result<(), ColumnError> {
        let cell = value.serialize(CellSerializer)?;
        self.table.cell(self.field, key, cell)?;
        self.field += 1;
        Ok(())
    }

    fn end(self) -> Result<(), ColumnError> {
        Ok(())
    }
}

/// Everything but a struct is refused as a row.
macro_rules! refuse {
    ($what:literal; $($method:ident($($arg:ty),*) -> $ok:ty;)*) => {
        $(
            fn $method(self, $(_: $arg),*) -> Result<$ok, ColumnError> {
                Err(ColumnError(format!("a {} cannot be {}", stringify!($method), $what)))
            }
        )*
    };
}

/// The serialiser methods of the compound values, which neither a row's fields nor a
/// cell can be: sequences, tuples, maps, and enum variants with data
/// (`$newtype_variant` the message of a newtype variant's).
macro_rules! refuse_compounds {
    ($what:literal, $ok:ty, $newtype_variant:literal) => {
        refuse! { $what;
            serialize_seq(Option<usize>) -> Self::SerializeSeq;
            serialize_tuple(usize) -> Self::SerializeTuple;
            serialize_tuple_struct(&'static str, usize) -> Self::SerializeTupleStruct;
            serialize_tuple_variant(&'static str, u32, &'static str, usize) -> Self::SerializeTupleVariant;
            serialize_map(Option<usize>) -> Self::SerializeMap;
            serialize_struct_variant(&'static str, u32, &'static str, usize) -> Self::SerializeStructVariant;
        }

        fn serialize_newtype_variant<T: ?Sized + Serialize>(
            self,
            _: &'static str,
            _: u32,
            _: &'static str,
            _: &T,
        ) -> Result<$ok, ColumnError> {
            Err(ColumnError($newtype_variant.to_owned()))
        }
    };
}

impl<'a> Serializer for RowSerializer<'a> {
    type Ok = ();
    type Error = ColumnError;
    type SerializeSeq = Impossible<(), ColumnError>;
    type SerializeTuple = Impossible<(), ColumnError>;
    type SerializeTupleStruct = Impossible<(), ColumnError>;
    type SerializeTupleVariant = Impossible<(), ColumnError>;
    type SerializeMap = Impossible<(), ColumnError>;
    type SerializeStruct = RowFields<'a>;
    type SerializeStructVariant = Impossible<(), ColumnError>;

    fn serialize_struct(self, _: &'static str, _: usize) -> Result<RowFields<'a>, ColumnError> {
        Ok(RowFields {
            table: self.table,
            field: 0,
        })
    }

    refuse! { "a row";
        serialize_bool(bool) -> ();
        serialize_i8(i8) -> ();
        serialize_i16(i16) -> ();
        serialize_i32(i32) -> ();
        serialize_i64(i64) -> ();
        serialize_u8(u8) -> ();
        serialize_u16(u16) -> ();
        serialize_u32(u32) -> ();
        serialize_u64(u64) -> ();
        serialize_f32(f32) -> ();
        serialize_f64(f64) -> ();
        serialize_char(char) -> ();
        serialize_str(&str) -> ();
        serialize_bytes(&[u8]) -> ();
        serialize_none() -> ();
        serialize_unit() -> ();
        serialize_unit_struct(&'static str) -> ();
        serialize_unit_variant(&'static str, u32, &'static str) -> ();
    }
    refuse_compounds!("a row", (), "an enum cannot be a row");

    fn serialize_some<T: ?Sized + Serialize>(self, _: &T) -> Result<(), ColumnError> {
        Err(ColumnError("an option cannot be a row".to_owned()))
    }

    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        _: &T,
    ) -> Result<(), ColumnError> {
        Err(ColumnError("a newtype cannot be a row".to_owned()))
    }
}

/// Serialiser methods whose value converts losslessly into an integer cell (`bool` as 0
/// or 1).
macro_rules! integer_cells {
    ($($method:ident($ty:ty);)*) => {
        $(
            fn $method(self, v: $ty) -> Result<Cell, ColumnError> {
                Ok(Cell::Integer(v.into()))
            }
        )*
    };
}

/// Serialises one field's value into a cell.
struct CellSerializer;

impl Serializer for CellSerializer {
    type Ok = Cell;
    type Error = ColumnError;
    type SerializeSeq = Impossible<Cell, ColumnError>;
    type SerializeTuple = Impossible<Cell, ColumnError>;
    type SerializeTupleStruct = Impossible<Cell, ColumnError>;
    type SerializeTupleVariant = Impossible<Cell, ColumnError>;
    type SerializeMap = Impossible<Cell, ColumnError>;
    type SerializeStruct = Impossible<Cell, ColumnError>;
    type SerializeStructVariant = Impossible<Cell, ColumnError>;

    integer_cells! {
        serialize_bool(bool);
        serialize_i8(i8);
        serialize_i16(i16);
        serialize_i32(i32);
        serialize_i64(i64);
        serialize_u8(u8);
        serialize_u16(u16);
        serialize_u32(u32);
    }
    fn serialize_u64(self, v: u64) -> Result<Cell, ColumnError> {
        // Seeds and counts stay below 2⁶³ (a scenario's seeds are TOML integers).
        i64::try_from(v)
            .map(Cell::Integer)
            .map_err(|_| ColumnError(format!("{v} does not fit a signed 64-bit column")))
    }
    fn serialize_f32(self, v: f32) -> Result<Cell, ColumnError> {
        Ok(Cell::Float(v.into()))
    }
    fn serialize_f64(self, v: f64) -> Result<Cell, ColumnError> {
        Ok(Cell::Float(v))
    }
    fn serialize_char(self, v: char) -> Result<Cell, ColumnError> {
        Ok(Cell::Text(v.to_string()))
    }
    fn serialize_str(self, v: &str) -> Result<Cell, ColumnError> {
        Ok(Cell::Text(v.to_owned()))
    }
    fn serialize_none(self) -> Result<Cell, ColumnError> {
        Ok(Cell::Missing)
    }
    fn serialize_some<T: ?Sized + Serialize>(self, value: &T) -> Result<Cell, ColumnError> {
        // An optional number can be missing: its column is float (NaN when missing),
        // whatever the values of one table happen to be.
        Ok(match value.serialize(self)? {
            Cell::Integer(v) => Cell::Float(v as f64),
            cell => cell,
        })
    }
    fn serialize_unit(self) -> Result<Cell, ColumnError> {
        Ok(Cell::Missing)
    }
    fn serialize_unit_variant(
        self,
        _: &'static str,
        _: u32,
        variant: &'static str,
    ) -> Result<Cell, ColumnError> {
        Ok(Cell::Text(variant.to_owned()))
    }
    fn serialize_newtype_struct<T: ?Sized + Serialize>(
        self,
        _: &'static str,
        value: &T,
    ) -> Result<Cell, ColumnError> {
        value.serialize(self)
    }

    refuse! { "a cell";
        serialize_bytes(&[u8]) -> Cell;
        serialize_unit_struct(&'static str) -> Cell;
        serialize_struct(&'static str, usize) -> Self::SerializeStruct;
    }
    refuse_compounds!("a cell", Cell, "an enum with data cannot be a cell");
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(serde::Serialize)]
    struct Row<'a> {
        index: u64,
        value: Option<f64>,
        label: &'a str,
    }

    #[test]
    fn rows_become_columns_in_field_order() {
        let mut table = Columns::default();
        table
            .push(&Row {
                index: 0,
                value: Some(1.5),
                label: "a",
            })
            .expect("row");
        table
            .push(&Row {
                index: 1,
                value: None,
                label: "b",
            })
            .expect("row");
        assert_eq!(table.names, ["index", "value", "label"]);
        assert_eq!(table.cells[0], [Cell::Integer(0), Cell::Integer(1)]);
        assert_eq!(table.cells[1], [Cell::Float(1.5), Cell::Missing]);
        assert_eq!(
            table.cells[2],
            [Cell::Text("a".to_owned()), Cell::Text("b".to_owned())]
        );
    }

    #[test]
    fn optional_integers_are_float_cells() {
        #[derive(serde::Serialize)]
        struct Wire {
            wire: Option<u8>,
        }
        let mut table = Columns::default();
        table.push(&Wire { wire: Some(3) }).expect("row");
        assert_eq!(table.cells[0], [Cell::Float(3.0)]);
    }

    #[test]
    fn a_value_that_is_not_a_struct_is_refused_as_a_row() {
        let error = Columns::default().push(&1.0).expect_err("not a row");
        assert!(error.to_string().contains("serialize_f64"), "{error}");
    }
}
