//! A shard's `runs.csv` text read back into checked rows: the same columns, the same
//! checks and the same words for every front end (the CLI's `merge`, Python, Dask).

use super::lateral::{LateralRow, LATERAL_RUN_COLUMNS};
use super::limits::{MAX_CONTROLLERS, MAX_RUNS};
use super::merge_error::MergeError;
use super::row::{RowError, RunRow, LSO_RUN_COLUMNS, RUN_COLUMNS};
use super::runs_table::{text_of, ColumnGroup, RunsSchema, RunsTable};
use super::trap_sheet::TRAP_SHEET_RUN_COLUMNS;

/// The text of a campaign's `runs.csv`: the header of the table's schema and one line per
/// row, its fields those of the schema's groups in order; what the CLI writes and a
/// shard carries. [`parse_runs_csv`] reads it back exactly.
pub fn runs_csv_text(table: &RunsTable<'_>) -> Result<String, csv::Error> {
    let mut writer = csv::Writer::from_writer(Vec::new());
    writer.write_record(table.schema.columns())?;
    for index in 0..table.rows.len() {
        writer.write_record(&table.record(index)?)?;
    }
    text_of(writer)
}

/// Reads the rows of a shard's `runs.csv` text (`location` names it in messages) into a
/// table: exactly the columns of one of the schemas a campaign writes
/// ([`RunsSchema::ALL`], the one the header agrees with longest: [`RUN_COLUMNS`], for a
/// 3-D approach campaign those of [`LateralRow`], then [`LSO_RUN_COLUMNS`]; a shard
/// written before the last of them came is refused, naming the columns it lacks) — a
/// last line that ends (a file cut short is refused, even inside a row's text), and
/// every row one a campaign can write ([`RunRow::check`], [`LateralRow::check`]). Every
/// error names the line and the column at fault. Whether the schema is the one the
/// shard's scenario flies is for the merge to check.
pub fn parse_runs_csv(location: &str, text: &str) -> Result<RunsTable<'static>, MergeError> {
    let header = text
        .lines()
        .next()
        .unwrap_or_default()
        .trim_end_matches('\r');
    let columns: Vec<&str> = header.split(',').collect();
    let schema = RunsSchema::of_header(&columns);
    let errors = CsvErrors {
        location,
        width: schema.width(),
    };
    check_header(&errors, &columns, &schema.columns())?;
    if !text.ends_with('\n') {
        let lines = text.lines().count() as u64;
        return Err(errors.at(
            lines,
            "the last line does not end: the file is cut short (truncated?)".to_owned(),
        ));
    }
    let reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(text.as_bytes());
    parse_rows(&errors, schema, reader)
}

/// Most rows a `runs.csv` can hold: every run under every controller.
const MOST_ROWS: u64 = MAX_RUNS * MAX_CONTROLLERS as u64;

/// The errors of one `runs.csv`, each naming it (`location`), its line and column.
struct CsvErrors<'a> {
    /// Where the text comes from.
    location: &'a str,
    /// How many columns a row has.
    width: usize,
}

impl CsvErrors<'_> {
    /// The error at `line` (from 1) saying `problem`.
    fn at(&self, line: u64, problem: String) -> MergeError {
        MergeError::RunsCsv {
            location: self.location.to_owned(),
            line,
            problem,
        }
    }

    /// The error of the csv reader at row `number` (from 1), naming the column.
    fn csv(&self, error: csv::Error, number: u64) -> MergeError {
        let line = error.position().map_or(number + 1, |p| p.line());
        let column = match error.kind() {
            csv::ErrorKind::Deserialize { err, .. } => err
                .field()
                .and_then(|f| RUN_COLUMNS.iter().chain(&LSO_RUN_COLUMNS).nth(f as usize))
                .map(|c| format!("`{c}`: "))
                .unwrap_or_default(),
            _ => String::new(),
        };
        let message = match error.kind() {
            csv::ErrorKind::Deserialize { err, .. } => err.kind().to_string(),
            csv::ErrorKind::UnequalLengths { len, .. } => format!(
                "{len} fields where a campaign writes {}: is the row cut short?",
                self.width
            ),
            _ => error.to_string(),
        };
        self.at(line, format!("{column}{message}"))
    }

    /// Row `number` (from 1) breaks the row schema.
    fn bad_row(&self, number: u64, row: &RunRow, error: RowError) -> MergeError {
        MergeError::BadRow {
            location: self.location.to_owned(),
            row: number,
            run_index: row.run_index,
            controller: row.controller.to_string(),
            error: Box::new(error),
        }
    }

    /// Refuses row `number` (from 1) beyond [`MOST_ROWS`].
    fn check_count(&self, number: u64) -> Result<(), MergeError> {
        if number > MOST_ROWS {
            return Err(self.at(
                number + 1,
                format!("more than {MOST_ROWS} rows: more than a campaign has"),
            ));
        }
        Ok(())
    }
}

/// Checks that the header's `columns` are the `expected` ones, naming the first that
/// differs.
fn check_header(errors: &CsvErrors, columns: &[&str], expected: &[&str]) -> Result<(), MergeError> {
    if columns == expected {
        return Ok(());
    }
    // The columns appended last, one release after another: a shard without the last
    // of them was written by an older deckland.
    let appended = expected.len() - LSO_RUN_COLUMNS.len();
    if columns.len() >= appended && columns.len() < expected.len() && expected.starts_with(columns)
    {
        let missing = &expected[columns.len()..];
        return Err(errors.at(
            1,
            format!(
                "the column{} `{}` {} missing: the shard was written by a deckland that did \
                 not grade passes, name wave-off criteria, share the deck's time within the \
                 recovery limits or keep the forecast at the commit point yet; fly it again \
                 with this version",
                if missing.len() == 1 { "" } else { "s" },
                missing.join("`, `"),
                if missing.len() == 1 { "is" } else { "are" }
            ),
        ));
    }
    let position = expected
        .iter()
        .zip(columns)
        .position(|(a, b)| a != b)
        .unwrap_or(columns.len().min(expected.len()));
    let problem = match (expected.get(position), columns.get(position)) {
        (Some(expected), Some(found)) => {
            format!(
                "column {} is `{found}` where a campaign writes `{expected}`",
                position + 1
            )
        }
        (Some(expected), None) => format!("the column `{expected}` is missing"),
        (None, Some(found)) => format!("`{found}` is not a column of a campaign"),
        (None, None) => "no header".to_owned(),
    };
    Err(errors.at(
        1,
        format!("{problem} (the header is `{}`)", expected.join(",")),
    ))
}

/// The rows of a `runs.csv` of `schema`, each checked.
fn parse_rows(
    errors: &CsvErrors,
    schema: RunsSchema,
    mut reader: csv::Reader<&[u8]>,
) -> Result<RunsTable<'static>, MergeError> {
    let headers: csv::StringRecord = RUN_COLUMNS.into_iter().chain(LSO_RUN_COLUMNS).collect();
    let mut table = RunsTable::empty(schema);
    for (position, record) in reader.records().enumerate() {
        let number = position as u64 + 1;
        errors.check_count(number)?;
        let record = record.map_err(|error| errors.csv(error, number))?;
        let line = record.position().map_or(number + 1, |p| p.line());
        // Each group's fields: a row's own ([`RunRow`]) and the others'.
        let mut run = csv::StringRecord::new();
        let mut lateral = None;
        let mut fields = record.iter();
        for &group in schema.groups() {
            let group_fields: Vec<&str> = fields.by_ref().take(group.width()).collect();
            match group {
                ColumnGroup::Longitudinal | ColumnGroup::Lso => run.extend(group_fields),
                ColumnGroup::Lateral => lateral = Some(group_fields),
            }
        }
        let row: RunRow<'static> = run
            .deserialize(Some(&headers))
            .map_err(|error| errors.csv(error, line - 1))?;
        if let Some(group_fields) = lateral {
            let values =
                lateral_values(&group_fields).map_err(|problem| errors.at(line, problem))?;
            table.lateral_rows.push(values);
        }
        table.rows.push(row);
        let index = table.rows.len() - 1;
        if let Err(error) = table.check_row(index) {
            return Err(errors.bad_row(number, &table.rows[index], error));
        }
    }
    Ok(table)
}

/// The [`LateralRow`] of the fields of a row's [`ColumnGroup::Lateral`] group: numbers
/// or empty, `off_centre` `true`, `false` or empty; the error names the column.
fn lateral_values(fields: &[&str]) -> Result<LateralRow, String> {
    let field = |k: usize| fields.get(k).copied().unwrap_or_default();
    let number = |k: usize, column: &str| -> Result<Option<f64>, String> {
        let text = field(k);
        if text.is_empty() {
            return Ok(None);
        }
        text.parse::<f64>()
            .map(Some)
            .map_err(|_| format!("`{column}`: `{text}` is not a number"))
    };
    let mut reals = [None; 5];
    for (k, slot) in reals.iter_mut().enumerate() {
        *slot = number(k, LATERAL_RUN_COLUMNS[k])?;
    }
    let off_centre = match field(5) {
        "" => None,
        "true" => Some(true),
        "false" => Some(false),
        other => {
            return Err(format!(
                "`{}`: `{other}` is not true, false or empty",
                LATERAL_RUN_COLUMNS[5]
            ))
        }
    };
    let mut trap_sheet = [None; 24];
    for (k, slot) in trap_sheet.iter_mut().enumerate() {
        *slot = number(LATERAL_RUN_COLUMNS.len() + k, TRAP_SHEET_RUN_COLUMNS[k])?;
    }
    Ok(LateralRow {
        touchdown: (reals[0], reals[1], reals[2], reals[3], reals[4], off_centre),
        trap_sheet,
    })
}

#[cfg(test)]
mod tests {
    use super::super::lateral::lateral_row_columns;
    use super::*;

    #[test]
    fn a_three_d_header_needs_every_lateral_and_trap_sheet_column() {
        let full = format!("{}\n", RunsSchema::WITH_LATERAL.columns().join(","));
        let parsed = parse_runs_csv("s1/runs.csv", &full).expect("a 3-D header");
        assert_eq!(parsed, RunsTable::empty(RunsSchema::WITH_LATERAL));
        // One lateral column too few: the first one missing is named.
        let cut = format!("{},{}\n", RUN_COLUMNS.join(","), LATERAL_RUN_COLUMNS[0]);
        let error = parse_runs_csv("s1/runs.csv", &cut).unwrap_err().to_string();
        assert!(error.contains("s1/runs.csv"), "{error}");
        assert!(
            error.contains("the column `touchdown_drift_rate_mps` is missing"),
            "{error}"
        );
        // The lateral columns without the trap sheet's (an older 3-D shard).
        let old = format!(
            "{},{}\n",
            RUN_COLUMNS.join(","),
            LATERAL_RUN_COLUMNS.join(",")
        );
        let error = parse_runs_csv("s1/runs.csv", &old).unwrap_err().to_string();
        assert!(
            error.contains("`trap_x_glide_slope_mean_m` is missing"),
            "{error}"
        );
    }

    #[test]
    fn a_shard_without_the_lso_columns_is_refused_by_name() {
        let old = format!("{}\n", RUN_COLUMNS.join(","));
        let error = parse_runs_csv("s1/runs.csv", &old).unwrap_err().to_string();
        assert!(
            error.contains(
                "`lso_grade`, `lso_points`, `lso_comment`, `wave_off_criterion`, \
                 `deck_within_limits_pct`, `commit_ramp_strike_probability`, \
                 `commit_hard_landing_probability`, `commit_off_centre_probability`, \
                 `commit_ramp_clearance_m`, `commit_ramp_clearance_sigma_m` are missing"
            ),
            "{error}"
        );
        let new = format!("{},{}\n", RUN_COLUMNS.join(","), LSO_RUN_COLUMNS.join(","));
        assert!(parse_runs_csv("s1/runs.csv", &new).is_ok());
    }

    /// The 3-DOF and the 3-D header of a deckland whose last columns were `last`.
    fn headers_of_a_deckland_ending_with(last: &[&'static str]) -> [String; 2] {
        let three_dof = format!("{},{}\n", RUN_COLUMNS.join(","), last.join(","));
        let three_d: Vec<&str> = RUN_COLUMNS
            .into_iter()
            .chain(lateral_row_columns())
            .chain(last.iter().copied())
            .collect();
        [three_dof, format!("{}\n", three_d.join(","))]
    }

    /// A shard of the deckland before the deck's share within the recovery limits (its
    /// four LSO and wave-off columns last), before the commit point's forecast (issue 45,
    /// item 1: the deck's share last) or before its clearance (the off-centre probability
    /// last), 3-DOF or 3-D, is refused on its header, naming the columns it lacks.
    #[test]
    fn a_shard_without_the_columns_that_came_later_is_refused_by_name() {
        let cases = [
            (4, "the columns `deck_within_limits_pct`, `commit_"),
            (
                5,
                "the columns `commit_ramp_strike_probability`, \
                 `commit_hard_landing_probability`, `commit_off_centre_probability`, \
                 `commit_ramp_clearance_m`, `commit_ramp_clearance_sigma_m` are missing",
            ),
            (
                8,
                "the columns `commit_ramp_clearance_m`, `commit_ramp_clearance_sigma_m` are \
                 missing",
            ),
        ];
        for (kept, missing) in cases {
            for old in headers_of_a_deckland_ending_with(&LSO_RUN_COLUMNS[..kept]) {
                let error = parse_runs_csv("s1/runs.csv", &old).unwrap_err().to_string();
                assert!(
                    error.contains("line 1")
                        && error.contains(missing)
                        && error.contains("fly it again with this version"),
                    "{error}"
                );
            }
        }
    }
}
