//! `runs.parquet`: the rows of `runs.csv` as an Apache Parquet file, for large campaigns
//! read by pandas, polars or pyarrow without parsing text.
//!
//! The columns are those of the runs table's schema ([`RunsTable::columns`]: the fields
//! of [`RunRow`] and of the schema's other groups taken apart by the library's
//! [`Columns`], so the file has exactly the CSV's columns, in its order), with one type
//! each whatever the values of a campaign, so the files of several campaigns concatenate:
//!
//! - `run_index`, `seed`: required 64-bit integers;
//! - `controller`, `outcome`, `reason`, `lso_grade`, `lso_comment`,
//!   `wave_off_criterion`: UTF-8 text (`reason` missing for a trap, the LSO's columns for
//!   a run that never flew, the criterion for a run that did not wave off);
//! - `off_centre`: an optional boolean;
//! - every other column: an optional double (missing where the CSV field is empty; `wire`
//!   too, as pandas reads it from the CSV).
//!
//! A 3-D campaign's schema has the lateral columns of its `runs.csv` after those of
//! every campaign ([`LATERAL_RUN_COLUMNS`], then the trap sheet's
//! [`TRAP_SHEET_RUN_COLUMNS`]). The columns appended last ([`LSO_RUN_COLUMNS`]:
//! `lso_grade`, `lso_points`, `lso_comment`, `wave_off_criterion`,
//! `deck_within_limits_pct` and the commit point's `commit_ramp_strike_probability`,
//! `commit_hard_landing_probability`, `commit_off_centre_probability`,
//! `commit_ramp_clearance_m`, `commit_ramp_clearance_sigma_m`, optional doubles)
//! come last, after the lateral ones, as in `runs.csv`.
//!
//! One row group, Snappy compression (pandas' default). A value that is not finite is
//! refused, naming its run and column: nothing non-finite reaches a file.
//!
//! [`RunRow`]: deckland::monte_carlo::RunRow
//! [`Columns`]: deckland::recording::Columns
//! [`LATERAL_RUN_COLUMNS`]: deckland::monte_carlo::LATERAL_RUN_COLUMNS
//! [`TRAP_SHEET_RUN_COLUMNS`]: deckland::monte_carlo::TRAP_SHEET_RUN_COLUMNS
//! [`LSO_RUN_COLUMNS`]: deckland::monte_carlo::LSO_RUN_COLUMNS

use anyhow::{bail, Context, Result};
use deckland::monte_carlo::RunsTable;
use deckland::recording::Cell;
use parquet::basic::Compression;
use parquet::data_type::{BoolType, ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::{SerializedFileWriter, SerializedRowGroupWriter};
use parquet::schema::parser::parse_message_type;
use std::path::Path;
use std::sync::Arc;

/// How a column is stored.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Kind {
    /// A required 64-bit integer.
    Integer,
    /// An optional double.
    Real,
    /// Optional UTF-8 text.
    Text,
    /// An optional boolean.
    Boolean,
}

/// The columns' kinds by name; a column not listed here is [`Kind::Real`].
const COLUMN_KINDS: [(&str, Kind); 9] = [
    ("run_index", Kind::Integer),
    ("seed", Kind::Integer),
    ("controller", Kind::Text),
    ("outcome", Kind::Text),
    ("reason", Kind::Text),
    ("off_centre", Kind::Boolean),
    ("lso_grade", Kind::Text),
    ("lso_comment", Kind::Text),
    ("wave_off_criterion", Kind::Text),
];

fn kind_of(name: &str) -> Kind {
    COLUMN_KINDS
        .iter()
        .find(|(n, _)| *n == name)
        .map_or(Kind::Real, |(_, kind)| *kind)
}

/// The Parquet schema of `names`.
fn schema(names: &[&str]) -> String {
    let mut message = String::from("message runs {\n");
    for name in names {
        message.push_str(&match kind_of(name) {
            Kind::Integer => format!("  REQUIRED INT64 {name};\n"),
            Kind::Real => format!("  OPTIONAL DOUBLE {name};\n"),
            Kind::Text => format!("  OPTIONAL BYTE_ARRAY {name} (UTF8);\n"),
            Kind::Boolean => format!("  OPTIONAL BOOLEAN {name};\n"),
        });
    }
    message.push('}');
    message
}

/// Writes the runs `table` to a Parquet file at `path` (the caller makes it atomic): its
/// columns in its schema's order, as in `runs.csv`.
pub fn write_runs(path: &Path, table: &RunsTable) -> Result<()> {
    let columns = table.columns().map_err(|e| anyhow::anyhow!("{e}"))?;
    if columns.rows() == 0 {
        // No row names the columns (a campaign stopped before its first run finished).
        bail!("no finished run to write to runs.parquet");
    }
    let schema = Arc::new(
        parse_message_type(&schema(columns.names())).context("cannot make the Parquet schema")?,
    );
    let properties = Arc::new(
        WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_created_by(format!("deckland {}", env!("CARGO_PKG_VERSION")))
            .build(),
    );
    let run_indices: Vec<String> = table.rows.iter().map(|r| r.run_index.to_string()).collect();
    let file = std::fs::File::create(path)?;
    let mut writer = SerializedFileWriter::new(file, schema, properties)?;
    let mut group = writer.next_row_group()?;
    for (name, cells) in &columns.into_columns() {
        write_cells(&mut group, name, cells, &run_indices)?;
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

/// Writes the next column of `group`, `name` with its `cells` (`run_indices` name the
/// rows in errors).
fn write_cells(
    group: &mut SerializedRowGroupWriter<'_, std::fs::File>,
    name: &str,
    cells: &[Cell],
    run_indices: &[String],
) -> Result<()> {
    let Some(mut column) = group.next_column()? else {
        bail!("the Parquet schema has no column {name}");
    };
    let present: Vec<i16> = cells
        .iter()
        .map(|c| i16::from(!matches!(c, Cell::Missing)))
        .collect();
    match kind_of(name) {
        Kind::Integer => {
            let values = cells
                .iter()
                .enumerate()
                .map(|(row, cell)| match cell {
                    Cell::Integer(v) => Ok(*v),
                    other => bail!(
                        "run {}: `{name}` is {other:?}, not a whole number",
                        run_indices[row]
                    ),
                })
                .collect::<Result<Vec<i64>>>()?;
            column
                .typed::<Int64Type>()
                .write_batch(&values, None, None)?;
        }
        Kind::Real => {
            let values =
                present_values(
                    name,
                    cells,
                    run_indices,
                    "a finite number",
                    |cell| match cell {
                        Cell::Float(v) if v.is_finite() => Some(*v),
                        Cell::Integer(v) => Some(*v as f64),
                        _ => None,
                    },
                )?;
            column
                .typed::<DoubleType>()
                .write_batch(&values, Some(&present), None)?;
        }
        Kind::Boolean => {
            let values = present_values(name, cells, run_indices, "true or false", |cell| {
                // A boolean is taken apart as 0 or 1 (an optional one as a real).
                match cell {
                    Cell::Integer(v @ (0 | 1)) => Some(*v == 1),
                    Cell::Float(v) if *v == 0.0 || *v == 1.0 => Some(*v == 1.0),
                    _ => None,
                }
            })?;
            column
                .typed::<BoolType>()
                .write_batch(&values, Some(&present), None)?;
        }
        Kind::Text => {
            let values = present_values(name, cells, run_indices, "text", |cell| match cell {
                Cell::Text(text) => Some(ByteArray::from(text.as_str())),
                _ => None,
            })?;
            column
                .typed::<ByteArrayType>()
                .write_batch(&values, Some(&present), None)?;
        }
    }
    column.close()?;
    Ok(())
}

/// The values of column `name`'s present `cells`, each taken by `value`; a cell it
/// refuses is an error naming the run (`run_indices`) and what the cell is `not`.
fn present_values<T>(
    name: &str,
    cells: &[Cell],
    run_indices: &[String],
    not: &str,
    value: impl Fn(&Cell) -> Option<T>,
) -> Result<Vec<T>> {
    let mut values = Vec::with_capacity(cells.len());
    for (row, cell) in cells.iter().enumerate() {
        if matches!(cell, Cell::Missing) {
            continue;
        }
        match value(cell) {
            Some(v) => values.push(v),
            None => bail!("run {}: `{name}` is {cell:?}, not {not}", run_indices[row]),
        }
    }
    Ok(values)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn present_cells_are_taken_and_a_refused_one_names_its_run() {
        let runs = ["7".to_string(), "8".to_string(), "9".to_string()];
        let real = |cell: &Cell| match cell {
            Cell::Float(v) if v.is_finite() => Some(*v),
            Cell::Integer(v) => Some(*v as f64),
            _ => None,
        };
        let cells = [Cell::Float(1.5), Cell::Missing, Cell::Integer(2)];
        let values = present_values("wire", &cells, &runs, "a finite number", real).unwrap();
        assert_eq!(values, [1.5, 2.0]);
        let cells = [Cell::Missing, Cell::Float(f64::NAN), Cell::Float(1.0)];
        let error = present_values("wire", &cells, &runs, "a finite number", real)
            .unwrap_err()
            .to_string();
        assert_eq!(error, "run 8: `wire` is Float(NaN), not a finite number");
    }

    #[test]
    fn the_schema_gives_each_column_its_kind() {
        let message = schema(&["run_index", "wire", "reason"]);
        assert!(parse_message_type(&message).is_ok(), "{message}");
        assert!(message.contains("REQUIRED INT64 run_index"));
        assert!(message.contains("OPTIONAL DOUBLE wire"));
        assert!(message.contains("OPTIONAL BYTE_ARRAY reason (UTF8)"));
        let lateral = schema(&["touchdown_lateral_offset_m", "off_centre"]);
        assert!(parse_message_type(&lateral).is_ok(), "{lateral}");
        assert!(lateral.contains("OPTIONAL DOUBLE touchdown_lateral_offset_m"));
        assert!(lateral.contains("OPTIONAL BOOLEAN off_centre"));
    }
}
