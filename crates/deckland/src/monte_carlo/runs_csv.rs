//! A shard's `runs.csv` text read back into checked rows: the same columns, the same
//! checks and the same words for every front end (the CLI's `merge`, Python, Dask).

use super::lateral::LATERAL_RUN_COLUMNS;
use super::limits::{MAX_CONTROLLERS, MAX_RUNS};
use super::merge_error::MergeError;
use super::row::{RunRow, RUN_COLUMNS};

/// Reads the rows of a shard's `runs.csv` text (`location` names it in messages):
/// exactly the columns of [`RUN_COLUMNS`] in order, a last line that ends (a file cut
/// short is refused, even inside a row's text), and every row one a campaign can write
/// ([`RunRow::check`]). Every error names the line and the column at fault.
pub fn parse_runs_csv(location: &str, text: &str) -> Result<Vec<RunRow<'static>>, MergeError> {
    let at = |line: u64, problem: String| MergeError::RunsCsv {
        location: location.to_owned(),
        line,
        problem,
    };
    let header = text
        .lines()
        .next()
        .unwrap_or_default()
        .trim_end_matches('\r');
    let columns: Vec<&str> = header.split(',').collect();
    if columns.len() == RUN_COLUMNS.len() + LATERAL_RUN_COLUMNS.len()
        && columns[..RUN_COLUMNS.len()] == RUN_COLUMNS
        && columns[RUN_COLUMNS.len()..] == LATERAL_RUN_COLUMNS
    {
        return Err(at(
            1,
            "a 3-D approach campaign's shard (its lateral columns): merging those is not \
             supported yet; fly the 3-D campaign whole (`deckland campaign` without `--shard`)"
                .to_owned(),
        ));
    }
    if columns != RUN_COLUMNS {
        let position = RUN_COLUMNS
            .iter()
            .zip(&columns)
            .position(|(a, b)| a != b)
            .unwrap_or(columns.len().min(RUN_COLUMNS.len()));
        let problem = match (RUN_COLUMNS.get(position), columns.get(position)) {
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
        return Err(at(
            1,
            format!("{problem} (the header is `{}`)", RUN_COLUMNS.join(",")),
        ));
    }
    if !text.ends_with('\n') {
        let lines = text.lines().count() as u64;
        return Err(at(
            lines,
            "the last line does not end: the file is cut short (truncated?)".to_owned(),
        ));
    }
    let most_rows = MAX_RUNS * MAX_CONTROLLERS as u64;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .from_reader(text.as_bytes());
    let mut rows = Vec::new();
    for (position, row) in reader.deserialize::<RunRow<'static>>().enumerate() {
        let number = position as u64 + 1;
        if number > most_rows {
            return Err(at(
                number + 1,
                format!("more than {most_rows} rows: more than a campaign has"),
            ));
        }
        let row = row.map_err(|error| {
            let line = error.position().map_or(number + 1, |p| p.line());
            let column = match error.kind() {
                csv::ErrorKind::Deserialize { err, .. } => err
                    .field()
                    .and_then(|f| RUN_COLUMNS.get(f as usize))
                    .map(|c| format!("`{c}`: "))
                    .unwrap_or_default(),
                _ => String::new(),
            };
            let message = match error.kind() {
                csv::ErrorKind::Deserialize { err, .. } => err.kind().to_string(),
                csv::ErrorKind::UnequalLengths { len, .. } => format!(
                    "{len} fields where a campaign writes {}: is the row cut short?",
                    RUN_COLUMNS.len()
                ),
                _ => error.to_string(),
            };
            at(line, format!("{column}{message}"))
        })?;
        if let Err(error) = row.check() {
            return Err(MergeError::BadRow {
                location: location.to_owned(),
                row: number,
                run_index: row.run_index,
                controller: row.controller.to_string(),
                error: Box::new(error),
            });
        }
        rows.push(row);
    }
    Ok(rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_three_d_shard_is_refused_by_name() {
        let header = format!(
            "{},{}\n",
            RUN_COLUMNS.join(","),
            LATERAL_RUN_COLUMNS.join(",")
        );
        let error = parse_runs_csv("s1/runs.csv", &header)
            .unwrap_err()
            .to_string();
        assert!(error.contains("3-D approach campaign"), "{error}");
        assert!(error.contains("s1/runs.csv"), "{error}");
        // One lateral column too few is an unknown header, as before.
        let cut = format!("{},{}\n", RUN_COLUMNS.join(","), LATERAL_RUN_COLUMNS[0]);
        let error = parse_runs_csv("s1/runs.csv", &cut).unwrap_err().to_string();
        assert!(error.contains("is not a column of a campaign"), "{error}");
    }
}
