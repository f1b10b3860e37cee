//! `runs.parquet`: the rows of `runs.csv` as an Apache Parquet file, for large campaigns
//! read by pandas, polars or pyarrow without parsing text.
//!
//! The columns are those of [`RunRow`] (taken apart by the library's
//! [`Columns`], so the file has exactly the CSV's columns, in its order), with one type
//! each whatever the values of a campaign, so the files of several campaigns concatenate:
//!
//! - `run_index`, `seed`: required 64-bit integers;
//! - `controller`, `outcome`, `reason`, `lso_grade`, `lso_comment`,
//!   `wave_off_criterion`: UTF-8 text (`reason` missing for a trap, the LSO's columns for
//!   a run that never flew, the criterion for a run that did not wave off);
//! - every other column: an optional double (missing where the CSV field is empty; `wire`
//!   too, as pandas reads it from the CSV).
//!
//! A 3-D campaign adds the lateral columns of its `runs.csv` after these
//! ([`LATERAL_RUN_COLUMNS`], then the trap sheet's [`TRAP_SHEET_RUN_COLUMNS`]): optional
//! doubles, and `off_centre` an optional boolean. The columns appended last
//! ([`LSO_RUN_COLUMNS`]: `lso_grade`, `lso_points`, `lso_comment`, `wave_off_criterion`,
//! `deck_within_limits_pct` and the commit point's `commit_ramp_strike_probability`,
//! `commit_hard_landing_probability`, `commit_off_centre_probability`, optional doubles)
//! come last, after the lateral ones, as in `runs.csv`.
//!
//! One row group, Snappy compression (pandas' default). A value that is not finite is
//! refused, naming its run and column: nothing non-finite reaches a file.

use anyhow::{bail, Context, Result};
use deckland::monte_carlo::{
    LateralRow, RunRow, LATERAL_RUN_COLUMNS, LSO_RUN_COLUMNS, TRAP_SHEET_RUN_COLUMNS,
};
use deckland::recording::{Cell, Columns};
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

/// Writes `rows` to a Parquet file at `path` (the caller makes it atomic), with a 3-D
/// campaign's `lateral` values of each row after its columns.
pub fn write_runs(path: &Path, rows: &[RunRow], lateral: Option<&[LateralRow]>) -> Result<()> {
    let mut table = Columns::with_capacity(rows.len());
    for row in rows {
        table.push(row).map_err(|e| anyhow::anyhow!("{e}"))?;
    }
    if table.rows() == 0 {
        // No row names the columns (a campaign stopped before its first run finished).
        bail!("no finished run to write to runs.parquet");
    }
    // The LSO's columns last, after a 3-D campaign's lateral ones, as in `runs.csv`.
    let mut names: Vec<&str> = table
        .names()
        .iter()
        .copied()
        .filter(|n| !LSO_RUN_COLUMNS.contains(n))
        .collect();
    if lateral.is_some() {
        names.extend(LATERAL_RUN_COLUMNS);
        names.extend(TRAP_SHEET_RUN_COLUMNS);
    }
    names.extend(LSO_RUN_COLUMNS);
    let schema =
        Arc::new(parse_message_type(&schema(&names)).context("cannot make the Parquet schema")?);
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
    let (lso, base): (Vec<_>, Vec<_>) = table
        .into_columns()
        .into_iter()
        .partition(|(name, _)| LSO_RUN_COLUMNS.contains(name));
    for (name, cells) in &base {
        write_cells(&mut group, name, cells, &run_indices)?;
    }
    if let Some(lateral) = lateral {
        let write_reals = |group: &mut SerializedRowGroupWriter<'_, std::fs::File>,
                           name: &str,
                           cells: Vec<Option<f64>>|
         -> Result<()> {
            let Some(mut column) = group.next_column()? else {
                bail!("the Parquet schema has no column {name}");
            };
            if let Some(row) = cells.iter().position(|c| c.is_some_and(|v| !v.is_finite())) {
                bail!("run {}: `{name}` is not a finite number", run_indices[row]);
            }
            let present: Vec<i16> = cells.iter().map(|c| i16::from(c.is_some())).collect();
            let values: Vec<f64> = cells.into_iter().flatten().collect();
            column
                .typed::<DoubleType>()
                .write_batch(&values, Some(&present), None)?;
            column.close()?;
            Ok(())
        };
        let reals: [fn(&LateralRow) -> Option<f64>; 5] = [
            |v| v.touchdown.0,
            |v| v.touchdown.1,
            |v| v.touchdown.2,
            |v| v.touchdown.3,
            |v| v.touchdown.4,
        ];
        for (name, value) in LATERAL_RUN_COLUMNS.iter().zip(reals) {
            write_reals(&mut group, name, lateral.iter().map(value).collect())?;
        }
        {
            let Some(mut column) = group.next_column()? else {
                bail!("the Parquet schema has no column off_centre");
            };
            let present: Vec<i16> = lateral
                .iter()
                .map(|v| i16::from(v.touchdown.5.is_some()))
                .collect();
            let values: Vec<bool> = lateral.iter().filter_map(|v| v.touchdown.5).collect();
            column
                .typed::<BoolType>()
                .write_batch(&values, Some(&present), None)?;
            column.close()?;
        }
        for (k, name) in TRAP_SHEET_RUN_COLUMNS.iter().enumerate() {
            write_reals(
                &mut group,
                name,
                lateral.iter().map(|v| v.trap_sheet[k]).collect(),
            )?;
        }
    }
    for (name, cells) in &lso {
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
        Kind::Boolean => bail!("`{name}` is not a boolean column of runs.csv"),
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
        let lateral = schema(&["touchdown_lateral_offset_m", "off_centre"]);
        assert!(parse_message_type(&lateral).is_ok(), "{lateral}");
        assert!(lateral.contains("OPTIONAL DOUBLE touchdown_lateral_offset_m"));
        assert!(lateral.contains("OPTIONAL BOOLEAN off_centre"));
    }
}
