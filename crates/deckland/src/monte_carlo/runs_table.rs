//! A campaign's runs table: its column schema ([`RunsSchema`], the groups of columns it
//! writes, decided once from the scenario by the plant registry) and its rows
//! ([`RunsTable`]). Every reader, writer and merger of `runs.csv`, `runs.parquet` and the
//! Python table works over the schema: the header is the schema's, a row's width is the
//! schema's, a shard's schema is compared with its scenario's, and each row's fields are
//! its groups' in the schema's order.

use super::lateral::{lateral_row_columns, LateralRow, LateralStatistics, LATERAL_RUN_COLUMNS};
use super::record::RunRecord;
use super::row::{RowError, RunRow, LSO_RUN_COLUMNS, RUN_COLUMNS};
use super::trap_sheet::{TrapSheetStatistics, TRAP_SHEET_RUN_COLUMNS};
use super::CampaignResult;
use crate::aircraft::ApproachOutcome;
use crate::recording::{ColumnError, Columns};
use crate::scenario::{Mission, Scenario};

/// A group of columns of a campaign's runs table.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnGroup {
    /// The columns of every campaign ([`RUN_COLUMNS`]): the run, its longitudinal
    /// outcome, the actuators and the dispersions.
    Longitudinal,
    /// A 3-D approach's lateral touchdown and trap sheet ([`lateral_row_columns`], the
    /// fields of [`LateralRow`]).
    Lateral,
    /// The LSO's grade, the wave-off's criterion, the deck's time within the recovery
    /// limits and the commit point's forecast ([`LSO_RUN_COLUMNS`]), appended last.
    Lso,
}

impl ColumnGroup {
    /// The group's columns, in order.
    pub fn columns(self) -> Vec<&'static str> {
        match self {
            Self::Longitudinal => RUN_COLUMNS.to_vec(),
            Self::Lateral => lateral_row_columns().collect(),
            Self::Lso => LSO_RUN_COLUMNS.to_vec(),
        }
    }

    /// How many columns the group has (without listing them: it is asked per row).
    pub fn width(self) -> usize {
        match self {
            Self::Longitudinal => RUN_COLUMNS.len(),
            Self::Lateral => LATERAL_RUN_COLUMNS.len() + TRAP_SHEET_RUN_COLUMNS.len(),
            Self::Lso => LSO_RUN_COLUMNS.len(),
        }
    }
}

/// The column schema of a campaign's runs table: the groups of columns it writes, in
/// order, as one of the schemas a campaign can have ([`RunsSchema::ALL`], each the
/// schema of what an approach reports, an [`ApproachOutcome`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct RunsSchema {
    /// What the approaches of a campaign of this schema report.
    outcome: ApproachOutcome,
    /// The groups, in the order of the columns.
    groups: &'static [ColumnGroup],
    /// What a table of this schema holds, in words (for a shard's refusal).
    holds: &'static str,
    /// What a scenario of this schema flies, in words (for a shard's refusal).
    flown_by: &'static str,
}

impl RunsSchema {
    /// The longitudinal campaign's: the columns of every campaign, then the LSO's.
    pub const LONGITUDINAL: Self = Self {
        outcome: ApproachOutcome::Longitudinal,
        groups: &[ColumnGroup::Longitudinal, ColumnGroup::Lso],
        holds: "no lateral columns",
        flown_by: "no 3-D approach, whose runs.csv has none",
    };

    /// The 3-D approach campaign's: the columns of every campaign, the lateral touchdown
    /// and trap sheet, then the LSO's.
    pub const WITH_LATERAL: Self = Self {
        outcome: ApproachOutcome::WithLateral,
        groups: &[
            ColumnGroup::Longitudinal,
            ColumnGroup::Lateral,
            ColumnGroup::Lso,
        ],
        holds: "the 3-D approach's lateral columns",
        flown_by: "the 3-D approach, whose runs.csv has them",
    };

    /// Every schema a campaign can write, the plainest first: one for each
    /// [`ApproachOutcome`].
    pub const ALL: [Self; 2] = [Self::LONGITUDINAL, Self::WITH_LATERAL];

    /// The schema of the approaches that report `outcome`.
    pub fn of_outcome(outcome: ApproachOutcome) -> Self {
        Self::ALL
            .into_iter()
            .find(|schema| schema.outcome == outcome)
            .unwrap_or(Self::LONGITUDINAL)
    }

    /// The schema of a campaign of `scenario`: that of what its plant reports on its
    /// approach ([`crate::aircraft::PlantModel::approach_outcome`]), decided once.
    pub fn of(scenario: &Scenario) -> Self {
        let three_dimensional_approach =
            scenario.mission == Mission::Approach && scenario.approach.three_dimensional;
        Self::of_outcome(
            scenario
                .aircraft
                .model
                .approach_outcome(three_dimensional_approach),
        )
    }

    /// The known schema whose columns agree longest with the header `columns` from the
    /// first (the plainest of those that agree as long): the one a header is read and
    /// checked against, so that a column missing or changed is named against it.
    pub fn of_header(columns: &[&str]) -> Self {
        let agreement = |schema: &Self| {
            schema
                .columns()
                .iter()
                .zip(columns)
                .take_while(|(expected, found)| expected == found)
                .count()
        };
        Self::ALL
            .into_iter()
            .rev()
            .max_by_key(agreement)
            .unwrap_or(Self::LONGITUDINAL)
    }

    /// The groups, in the order of the columns.
    pub fn groups(self) -> &'static [ColumnGroup] {
        self.groups
    }

    /// Whether the schema has `group`.
    pub fn has(self, group: ColumnGroup) -> bool {
        self.groups.contains(&group)
    }

    /// The columns, in order: the header of `runs.csv`.
    pub fn columns(self) -> Vec<&'static str> {
        self.groups.iter().flat_map(|g| g.columns()).collect()
    }

    /// How many columns a row has.
    pub fn width(self) -> usize {
        self.groups.iter().map(|g| g.width()).sum()
    }

    /// What a table of this schema holds, in words.
    pub fn holds(self) -> &'static str {
        self.holds
    }

    /// What a scenario of this schema flies, in words.
    pub fn flown_by(self) -> &'static str {
        self.flown_by
    }
}

/// A campaign's runs table: its schema and its rows, with the values of the schema's
/// groups that a [`RunRow`] does not carry (the [`ColumnGroup::Lateral`] group's
/// [`LateralRow`]s, one per row in the same order, exactly when the schema has it;
/// [`RunsTable::check_shape`] checks that).
#[derive(Debug, Clone, PartialEq)]
pub struct RunsTable<'a> {
    /// The column schema.
    pub schema: RunsSchema,
    /// The rows, in the table's order.
    pub rows: Vec<RunRow<'a>>,
    /// The [`ColumnGroup::Lateral`] group's values, one per row; empty when the schema
    /// has no such group.
    pub lateral_rows: Vec<LateralRow>,
}

/// Why a table's values are not one per row for each of its schema's groups.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct ShapeError {
    /// The group's field at fault.
    pub field: &'static str,
    /// Its values as found.
    pub value: String,
    /// What the table holds there.
    pub problem: String,
}

impl<'a> RunsTable<'a> {
    /// A table of `schema` with no row.
    pub fn empty(schema: RunsSchema) -> Self {
        Self {
            schema,
            rows: Vec::new(),
            lateral_rows: Vec::new(),
        }
    }

    /// The table of `records` (their controllers named from `labels`) in `schema`.
    pub fn of_records(schema: RunsSchema, records: &[RunRecord], labels: &'a [String]) -> Self {
        let rows = records.iter().map(|r| RunRow::new(r, labels)).collect();
        let lateral_rows = if schema.has(ColumnGroup::Lateral) {
            records.iter().map(LateralRow::of).collect()
        } else {
            Vec::new()
        };
        Self {
            schema,
            rows,
            lateral_rows,
        }
    }

    /// The table of a campaign's `result` in `schema` (its rows are
    /// [`CampaignResult::rows`]).
    pub fn of_result(schema: RunsSchema, result: &'a CampaignResult) -> Self {
        Self::of_records(schema, &result.records, &result.controller_labels)
    }

    /// The [`ColumnGroup::Lateral`] group's values, one per row; `None` when the schema
    /// has no such group.
    pub fn lateral_rows(&self) -> Option<&[LateralRow]> {
        self.schema
            .has(ColumnGroup::Lateral)
            .then_some(self.lateral_rows.as_slice())
    }

    /// Checks that the table holds each of its schema's groups' values one per row (and
    /// none of a group it does not have).
    pub fn check_shape(&self) -> Result<(), ShapeError> {
        let expected = if self.schema.has(ColumnGroup::Lateral) {
            self.rows.len()
        } else {
            0
        };
        if self.lateral_rows.len() == expected {
            return Ok(());
        }
        Err(ShapeError {
            field: "lateral",
            value: format!("{} rows of lateral columns", self.lateral_rows.len()),
            problem: format!(
                "{}: {} rows",
                if expected == 0 {
                    "none in a table without them"
                } else {
                    "one per row"
                },
                self.rows.len()
            ),
        })
    }

    /// Checks row `index` against the row schema ([`RunRow::check`]) and each group's
    /// values against it ([`LateralRow::check`]).
    pub fn check_row(&self, index: usize) -> Result<(), RowError> {
        let row = &self.rows[index];
        row.check()?;
        self.lateral_rows.get(index).map_or(Ok(()), |values| {
            values.check(row.touchdown_distance_m.is_some(), row.flown())
        })
    }

    /// Appends the rows of `other` (of the same schema) with their groups' values.
    pub fn append(&mut self, other: RunsTable<'a>) {
        self.rows.extend(other.rows);
        self.lateral_rows.extend(other.lateral_rows);
    }

    /// Sorts the rows (with their groups' values) by `key`, keeping the order of rows
    /// with equal keys.
    pub fn sort_by_key<K: Ord>(&mut self, mut key: impl FnMut(&RunRow<'a>) -> K) {
        let mut order: Vec<usize> = (0..self.rows.len()).collect();
        order.sort_by_key(|&k| key(&self.rows[k]));
        let mut rows: Vec<Option<RunRow<'a>>> = std::mem::take(&mut self.rows)
            .into_iter()
            .map(Some)
            .collect();
        self.rows = order.iter().filter_map(|&k| rows[k].take()).collect();
        let values = std::mem::take(&mut self.lateral_rows);
        self.lateral_rows = order
            .iter()
            .filter_map(|&k| values.get(k).copied())
            .collect();
    }

    /// The fields of row `index` in the schema's order, as one CSV record.
    pub(crate) fn record(&self, index: usize) -> Result<csv::StringRecord, csv::Error> {
        let run = record_of(&self.rows[index])?;
        let mut run_fields = run.iter();
        let mut fields = csv::StringRecord::new();
        for &group in self.schema.groups() {
            match group {
                // A row's fields are those of these two groups, in this order.
                ColumnGroup::Longitudinal | ColumnGroup::Lso => {
                    fields.extend(run_fields.by_ref().take(group.width()));
                }
                ColumnGroup::Lateral => fields.extend(&record_of(&self.lateral_rows[index])?),
            }
        }
        Ok(fields)
    }

    /// The table's columns in the schema's order, each with its cells (for the columnar
    /// front ends: `runs.parquet`, the Python table); no column for a table with no row.
    pub fn columns(&self) -> Result<Columns, ColumnError> {
        let mut run = Columns::with_capacity(self.rows.len());
        for row in &self.rows {
            run.push(row)?;
        }
        let mut others = Columns::with_capacity(self.lateral_rows.len());
        for values in &self.lateral_rows {
            others.push(values)?;
        }
        let mut cells = run.into_columns();
        cells.extend(others.into_columns());
        Ok(self
            .schema
            .columns()
            .into_iter()
            .filter_map(|name| {
                let position = cells.iter().position(|(n, _)| *n == name)?;
                Some(cells.swap_remove(position))
            })
            .collect())
    }

    /// The statistics of the [`ColumnGroup::Lateral`] group's values: the lateral
    /// touchdowns' (when a run touched down) and the trap sheets'; both `None` when the
    /// schema has no such group.
    pub fn lateral_statistics(&self) -> (Option<LateralStatistics>, Option<TrapSheetStatistics>) {
        self.lateral_rows().map_or((None, None), |rows| {
            let (lateral, trap_sheet) = super::lateral::lateral_statistics(rows);
            (lateral, Some(trap_sheet))
        })
    }

    /// Each row's `off_centre` column, in the rows' order; `None` when the schema has no
    /// [`ColumnGroup::Lateral`] group.
    pub fn off_centre(&self) -> Option<Vec<Option<bool>>> {
        self.lateral_rows()
            .map(|rows| rows.iter().map(|row| row.touchdown.5).collect())
    }
}

/// The fields `value` serialises to, as one CSV record.
pub(crate) fn record_of(value: &impl serde::Serialize) -> Result<csv::StringRecord, csv::Error> {
    let mut line = csv::WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    line.serialize(value)?;
    let text = text_of(line)?;
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(text.as_bytes());
    reader
        .records()
        .next()
        .unwrap_or_else(|| Ok(csv::StringRecord::new()))
}

/// What a CSV writer into memory wrote, as text (the fields are numbers and UTF-8 text).
pub(crate) fn text_of(writer: csv::Writer<Vec<u8>>) -> Result<String, csv::Error> {
    let bytes = writer
        .into_inner()
        .map_err(|e| csv::Error::from(std::io::Error::other(e.to_string())))?;
    String::from_utf8(bytes).map_err(|e| csv::Error::from(std::io::Error::other(e.to_string())))
}

#[cfg(test)]
mod tests {
    use super::super::merge::{merge_shards, ShardIdentity, ShardRows};
    use super::super::runs_csv::parse_runs_csv;
    use super::super::shard::Shard;
    use super::*;

    #[test]
    fn each_group_is_as_wide_as_its_list_of_columns() {
        for group in [
            ColumnGroup::Longitudinal,
            ColumnGroup::Lateral,
            ColumnGroup::Lso,
        ] {
            assert_eq!(group.width(), group.columns().len(), "{group:?}");
        }
    }
    use crate::aircraft::PlantModel;

    #[test]
    fn the_schema_is_decided_from_the_scenario_by_the_plant() {
        let mut scenario = Scenario::default();
        scenario.aircraft.model = PlantModel::SixDof;
        scenario.approach.three_dimensional = true;
        assert_eq!(RunsSchema::of(&scenario), RunsSchema::WITH_LATERAL);
        scenario.approach.three_dimensional = false;
        assert_eq!(RunsSchema::of(&scenario), RunsSchema::LONGITUDINAL);
        scenario.approach.three_dimensional = true;
        scenario.aircraft.model = PlantModel::ThreeDof;
        assert_eq!(RunsSchema::of(&scenario), RunsSchema::LONGITUDINAL);
        let columns = RunsSchema::WITH_LATERAL.columns();
        assert_eq!(columns.len(), RunsSchema::WITH_LATERAL.width());
        assert_eq!(columns[RUN_COLUMNS.len()], "touchdown_lateral_offset_m");
        assert_eq!(columns.last(), LSO_RUN_COLUMNS.last());
        for outcome in [ApproachOutcome::Longitudinal, ApproachOutcome::WithLateral] {
            assert_eq!(RunsSchema::of_outcome(outcome).outcome, outcome);
        }
    }

    #[test]
    fn a_header_is_read_against_the_schema_it_agrees_with_longest() {
        let lateral = RunsSchema::WITH_LATERAL.columns();
        assert_eq!(RunsSchema::of_header(&lateral), RunsSchema::WITH_LATERAL);
        // Only the columns of every campaign: the plainest schema.
        assert_eq!(
            RunsSchema::of_header(&RUN_COLUMNS),
            RunsSchema::LONGITUDINAL
        );
        // One lateral column missing: read against the lateral schema, which names it.
        let mut cut = lateral.clone();
        cut.remove(RUN_COLUMNS.len() + 2);
        assert_eq!(RunsSchema::of_header(&cut), RunsSchema::WITH_LATERAL);
        let error = parse_runs_csv("s1/runs.csv", &format!("{}\n", cut.join(",")))
            .unwrap_err()
            .to_string();
        assert!(
            error.contains("s1/runs.csv")
                && error.contains("where a campaign writes `touchdown_bank_deg`"),
            "{error}"
        );
    }

    #[test]
    fn a_shard_whose_schema_is_not_its_scenarios_is_refused() {
        let text = format!("{}\n", RunsSchema::WITH_LATERAL.columns().join(","));
        let table = parse_runs_csv("s0/runs.csv", &text).unwrap();
        assert_eq!(table.schema, RunsSchema::WITH_LATERAL);
        let mut scenario = Scenario::default();
        scenario.aircraft.model = PlantModel::ThreeDof;
        let shard = ShardRows {
            identity: ShardIdentity {
                source: "s0".to_owned(),
                scenario_toml: toml::to_string(&scenario).unwrap(),
                campaign_seed: 1,
                requested_runs: 1,
                controllers: vec!["O-PD".to_owned()],
                shard: Shard::WHOLE,
                partial: false,
            },
            table,
        };
        let error = merge_shards(vec![shard]).unwrap_err().to_string();
        assert!(
            error.contains("s0")
                && error.contains("runs.csv columns")
                && error.contains("the 3-D approach's lateral columns")
                && error.contains("`aircraft.model` = \"3dof\""),
            "{error}"
        );
    }

    #[test]
    fn a_table_keeps_each_groups_values_with_their_row() {
        let labels = ["O-PD".to_owned()];
        let row = |k: u64| RunRow::unmeasured(k, &labels[0], "invalid");
        let blank = |k: u64| LateralRow {
            touchdown: (Some(k as f64), None, None, None, None, None),
            trap_sheet: [None; 24],
        };
        let mut table = RunsTable {
            schema: RunsSchema::WITH_LATERAL,
            rows: vec![row(2), row(0), row(1)],
            lateral_rows: vec![blank(2), blank(0), blank(1)],
        };
        assert_eq!(table.check_shape(), Ok(()));
        table.sort_by_key(|r| r.run_index);
        assert_eq!(table.lateral_rows, [blank(0), blank(1), blank(2)]);
        let record = table.record(1).unwrap();
        assert_eq!(record.len(), RunsSchema::WITH_LATERAL.width());
        assert_eq!(&record[0], "1");
        assert_eq!(&record[RUN_COLUMNS.len()], "1.0");
        let columns = table.columns().unwrap();
        assert_eq!(columns.names(), RunsSchema::WITH_LATERAL.columns());
        // A value missing for a row is refused, naming the group.
        table.lateral_rows.pop();
        let error = table.check_shape().unwrap_err();
        assert_eq!(error.field, "lateral");
        assert!(error.problem.contains("one per row"), "{error:?}");
    }
}
