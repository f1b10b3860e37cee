//! `runs.parquet`: the rows of `runs.csv` as an Apache Parquet file, for large campaigns
//! read by pandas, polars or pyarrow without parsing text.
//!
//! The columns are those of [`RunRow`] (taken apart by the library's
//! [`Columns`], so the file has exactly the CSV's columns, in its order), with one type
//! each whatever the values of a campaign, so the files of several campaigns concatenate:
//!
//! - `run_index`, `seed`: required 64-bit integers;
//! - `controller`, `outcome`, `reason`: UTF-8 text (`reason` missing for a trap);
//! - every other column: an optional double (missing where the CSV field is empty; `wire`
//!   too, as pandas reads it from the CSV).
//!
//! One row group, Snappy compression (pandas' default). A value that is not finite is
//! refused, naming its run and column: nothing non-finite reaches a file.

use anyhow::{bail, Context, Result};
use deckland::monte_carlo::RunRow;
use deckland::recording::{Cell, Columns};
use parquet::basic::Compression;
use parquet::data_type::{ByteArray, ByteArrayType, DoubleType, Int64Type};
use parquet::file::properties::WriterProperties;
use parquet::file::writer::SerializedFileWriter;
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
}

/// The columns' kinds by name; a column not listed here is [`Kind::Real`].
const COLUMN_KINDS: [(&str, Kind); 5] = [
    ("run_index", Kind::Integer),
    ("seed", Kind::Integer),
    ("controller", Kind::Text),
    ("outcome", Kind::Text),
    ("reason", Kind::Text),
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
        });
    }
    message.push('}');
    message
}

/// Writes `rows` to a Parquet file at `path` (the caller makes it atomic).
pub fn write_runs(path: &Path, rows: &[RunRow]) -> Result<()> {
    let mut table = Columns::with_capacity(rows.len());
    for row in rows {
        table.push(row).map_err(|e| anyhow::anyhow!("{e}"))?;
    }
    if table.rows() == 0 {
        // No row names the columns (a campaign stopped before its first run finished).
        bail!("no finished run to write to runs.parquet");
    }
    let schema = Arc::new(
        parse_message_type(&schema(table.names())).context("cannot make the Parquet schema")?,
    );
    let properties = Arc::new(
        WriterProperties::builder()
            .set_compression(Compression::SNAPPY)
            .set_created_by(format!("deckland {}", env!("CARGO_PKG_VERSION")))
            .build(),
    );
    let run_indices: Vec<String> = rows.iter().map(|r| r.run_index.to_string()).collect();
    let file = std::fs::File::create(path)?;
    let mut writer = SerializedFileWriter::new(file, schema, properties)?;
    let mut group = writer.next_row_group()?;
    for (name, cells) in table.into_columns() {
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
                let mut values = Vec::with_capacity(cells.len());
                for (row, cell) in cells.iter().enumerate() {
                    match cell {
                        Cell::Missing => {}
                        Cell::Float(v) if v.is_finite() => values.push(*v),
                        Cell::Integer(v) => values.push(*v as f64),
                        other => bail!(
                            "run {}: `{name}` is {other:?}, not a finite number",
                            run_indices[row]
                        ),
                    }
                }
                column
                    .typed::<DoubleType>()
                    .write_batch(&values, Some(&present), None)?;
            }
            Kind::Text => {
                let mut values = Vec::with_capacity(cells.len());
                for (row, cell) in cells.iter().enumerate() {
                    match cell {
                        Cell::Missing => {}
                        Cell::Text(text) => values.push(ByteArray::from(text.as_str())),
                        other => {
                            bail!("run {}: `{name}` is {other:?}, not text", run_indices[row])
                        }
                    }
                }
                column
                    .typed::<ByteArrayType>()
                    .write_batch(&values, Some(&present), None)?;
            }
        }
        column.close()?;
    }
    group.close()?;
    writer.close()?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_schema_gives_each_column_its_kind() {
        let message = schema(&["run_index", "wire", "reason"]);
        assert!(parse_message_type(&message).is_ok(), "{message}");
        assert!(message.contains("REQUIRED INT64 run_index"));
        assert!(message.contains("OPTIONAL DOUBLE wire"));
        assert!(message.contains("OPTIONAL BYTE_ARRAY reason (UTF8)"));
    }
}
