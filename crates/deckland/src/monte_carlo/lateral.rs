//! A 3-D approach campaign's lateral outcomes (docs/model.md §10.4; shared model §10.8):
//! the columns a 3-D campaign adds to `runs.csv`, and their statistics — off-centre
//! touchdowns with their Wilson interval, the lateral touchdown scatter, the share of
//! passes within ±0.5° of lineup at the ramp, and the drift and bank at touchdown
//! against their limits — and, with the trap sheets' columns ([`super::trap_sheet`]), the
//! whole of a 3-D run's row beyond the columns of every campaign ([`LateralRow`]). A
//! 3-DOF campaign has none of them.

use serde::ser::{SerializeStruct, Serializer};
use serde::Serialize;

use super::record::RunRecord;
use super::row::RowError;
use super::statistics::{Distribution, Proportion};
use super::trap_sheet::{
    trap_sheet_run_values, TrapSheetRunValues, TrapSheetStatistics, TRAP_SHEET_RUN_COLUMNS,
};
use crate::scenario::Scenario;
use crate::simulation::lateral::touchdown::{
    MAX_OFF_CENTRE_M, MAX_TOUCHDOWN_BANK_DEG, MAX_TOUCHDOWN_DRIFT_MPS,
};
use crate::simulation::lateral::LateralTouchdown;

/// The lineup error at the ramp a landing signal officer accepts in close (deg): about
/// ±0.5° (shared model §10.8).
pub const RAMP_LINEUP_PASS_DEG: f64 = 0.5;

/// The columns a 3-D campaign adds to `runs.csv`, after the others.
pub const LATERAL_RUN_COLUMNS: [&str; 6] = [
    "touchdown_lateral_offset_m",
    "touchdown_drift_rate_mps",
    "touchdown_bank_deg",
    "touchdown_heading_to_centreline_deg",
    "ramp_lineup_error_deg",
    "off_centre",
];

/// One run's values of [`LATERAL_RUN_COLUMNS`] (empty where it did not touch down).
pub type LateralRunValues = (
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<f64>,
    Option<bool>,
);

/// Whether a campaign of `scenario` flies the 3-D approach (the 6-DOF aircraft on an
/// approach with `approach.three_dimensional`): its runs table's schema
/// ([`super::RunsSchema::of`]) then has the columns of [`LateralRow`] after those of
/// every campaign. The plant registry decides it
/// ([`crate::aircraft::PlantModel::approach_outcome`]).
pub fn flies_three_dimensional_approach(scenario: &Scenario) -> bool {
    super::RunsSchema::of(scenario).has(super::ColumnGroup::Lateral)
}

/// What a 3-D approach adds to a run's row: the lateral touchdown
/// ([`LATERAL_RUN_COLUMNS`]) and the trap sheet ([`TRAP_SHEET_RUN_COLUMNS`]), in that
/// order after the columns of every campaign ([`super::RUN_COLUMNS`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LateralRow {
    /// The lateral touchdown's values.
    pub touchdown: LateralRunValues,
    /// The trap sheet's values.
    pub trap_sheet: TrapSheetRunValues,
}

/// The columns of [`LateralRow`], in order.
pub fn lateral_row_columns() -> impl Iterator<Item = &'static str> {
    LATERAL_RUN_COLUMNS
        .into_iter()
        .chain(TRAP_SHEET_RUN_COLUMNS)
}

/// A row's 3-D columns as one flat struct named by [`lateral_row_columns`]: what
/// `runs.csv` holds after the columns of every campaign, and what the Python front end
/// takes apart into named columns.
impl Serialize for LateralRow {
    fn serialize<S: Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let (offset, drift, bank, heading, ramp, off_centre) = self.touchdown;
        let mut row = serializer.serialize_struct(
            "LateralRow",
            LATERAL_RUN_COLUMNS.len() + TRAP_SHEET_RUN_COLUMNS.len(),
        )?;
        let [c0, c1, c2, c3, c4, c5] = LATERAL_RUN_COLUMNS;
        row.serialize_field(c0, &offset)?;
        row.serialize_field(c1, &drift)?;
        row.serialize_field(c2, &bank)?;
        row.serialize_field(c3, &heading)?;
        row.serialize_field(c4, &ramp)?;
        row.serialize_field(c5, &off_centre)?;
        for (column, value) in TRAP_SHEET_RUN_COLUMNS.into_iter().zip(&self.trap_sheet) {
            row.serialize_field(column, value)?;
        }
        row.end()
    }
}

/// The statistics of a 3-D campaign's lateral columns, one [`LateralRow`] per run: the
/// lateral touchdowns' (`None` when no run touched down) and the trap sheets'. The same
/// from the records of a campaign flown whole as from its merged shards' rows.
pub fn lateral_statistics(rows: &[LateralRow]) -> (Option<LateralStatistics>, TrapSheetStatistics) {
    let touchdowns: Vec<LateralRunValues> = rows.iter().map(|r| r.touchdown).collect();
    let sheets: Vec<TrapSheetRunValues> = rows.iter().map(|r| r.trap_sheet).collect();
    (
        LateralStatistics::of_rows(&touchdowns),
        TrapSheetStatistics::of_rows(&sheets),
    )
}

/// Most a lateral distance in a row can be (m): the longest approach's length.
const LATERAL_LENGTH_LIMIT_M: f64 = 20_000.0;

/// Most a lateral speed in a row can be (m/s), as for every speed of a row.
const LATERAL_SPEED_LIMIT_MPS: f64 = 1000.0;

impl LateralRow {
    /// The 3-D columns of `record`.
    pub fn of(record: &RunRecord) -> Self {
        Self {
            touchdown: lateral_run_values(record),
            trap_sheet: trap_sheet_run_values(record),
        }
    }

    /// Checks that a 3-D campaign can have written these values beside a row that
    /// `touched_down` and `flown`: every number finite and within its range, the lateral
    /// touchdown complete with a touchdown and absent without one, `off_centre` true
    /// exactly beyond the limit, and each trap-sheet position all six values or none,
    /// none for a run that never flew.
    pub fn check(&self, touched_down: bool, flown: bool) -> Result<(), RowError> {
        self.check_touchdown(touched_down)?;
        self.check_trap_sheet(flown)
    }

    /// Checks the lateral touchdown's columns ([`LATERAL_RUN_COLUMNS`]) of a row that
    /// `touched_down`: a 3-D run that touched down has its lateral touchdown (a blank
    /// offset there is a column emptied, not a value), one that did not has none.
    fn check_touchdown(&self, touched_down: bool) -> Result<(), RowError> {
        let (offset, drift, bank, heading, ramp, off_centre) = self.touchdown;
        let reals = [
            (LATERAL_RUN_COLUMNS[0], offset, LATERAL_LENGTH_LIMIT_M),
            (LATERAL_RUN_COLUMNS[1], drift, LATERAL_SPEED_LIMIT_MPS),
            (LATERAL_RUN_COLUMNS[2], bank, 180.0),
            (LATERAL_RUN_COLUMNS[3], heading, 180.0),
            (LATERAL_RUN_COLUMNS[4], ramp, 90.0),
        ];
        for (column, value, limit) in reals {
            if value.is_some_and(|v| !v.is_finite() || v.abs() > limit) {
                return Err(row_error(
                    column,
                    value,
                    &format!("a campaign writes a finite number within ±{limit}"),
                ));
            }
        }
        let present = offset.is_some();
        const ALL_OR_NONE: &str =
            "a lateral touchdown has all of offset, drift, bank, heading and off_centre, or none";
        for (column, value, _) in &reals[..4] {
            if value.is_some() != present {
                return Err(row_error(column, *value, ALL_OR_NONE));
            }
        }
        if off_centre.is_some() != present {
            return Err(RowError {
                column: LATERAL_RUN_COLUMNS[5],
                value: off_centre.map_or_else(|| "empty".to_owned(), |v| v.to_string()),
                problem: ALL_OR_NONE.to_owned(),
            });
        }
        if let (Some(offset), Some(off_centre)) = (offset, off_centre) {
            if off_centre != (offset.abs() > MAX_OFF_CENTRE_M) {
                return Err(RowError {
                    column: LATERAL_RUN_COLUMNS[5],
                    value: off_centre.to_string(),
                    problem: format!(
                        "a touchdown {offset} m off the centreline is off centre exactly \
                         beyond {MAX_OFF_CENTRE_M} m"
                    ),
                });
            }
        }
        if touched_down && !present {
            return Err(row_error(
                LATERAL_RUN_COLUMNS[0],
                offset,
                "a 3-D run that touched down has its lateral touchdown (offset, drift, \
                 bank, heading, off_centre)",
            ));
        }
        if (present || ramp.is_some()) && !touched_down {
            let (column, value) = if present {
                (LATERAL_RUN_COLUMNS[0], offset)
            } else {
                (LATERAL_RUN_COLUMNS[4], ramp)
            };
            return Err(row_error(
                column,
                value,
                "only a run that touched down has it",
            ));
        }
        Ok(())
    }

    /// Checks the trap sheet's columns ([`TRAP_SHEET_RUN_COLUMNS`]) of a row that was
    /// `flown`: each position all six deviations or none, none for a run never flown.
    fn check_trap_sheet(&self, flown: bool) -> Result<(), RowError> {
        for (position, values) in self.trap_sheet.chunks(6).enumerate() {
            let filled = values[0].is_some();
            for (k, value) in values.iter().enumerate() {
                let column = TRAP_SHEET_RUN_COLUMNS[6 * position + k];
                let limit = if column.ends_with("_deg") {
                    90.0
                } else {
                    LATERAL_LENGTH_LIMIT_M
                };
                if value.is_some_and(|v| !v.is_finite() || v.abs() > limit) {
                    return Err(row_error(
                        column,
                        *value,
                        &format!("a campaign writes a finite number within ±{limit}"),
                    ));
                }
                if value.is_some() != filled {
                    return Err(row_error(
                        column,
                        *value,
                        "a position of the trap sheet has all six deviations or none",
                    ));
                }
                if value.is_some() && !flown {
                    return Err(row_error(column, *value, "a run that never flew has none"));
                }
            }
        }
        Ok(())
    }
}

/// The error for `column` of a row holding `value` (`empty` when blank).
fn row_error(column: &'static str, value: Option<f64>, problem: &str) -> RowError {
    RowError {
        column,
        value: value.map_or_else(|| "empty".to_owned(), crate::parameters::readable_number),
        problem: problem.to_owned(),
    }
}

/// The lateral outcome of `record`, if it is a 3-D approach that touched down.
pub fn lateral_touchdown(record: &RunRecord) -> Option<LateralTouchdown> {
    record.lateral_touchdown()
}

/// The values of [`LATERAL_RUN_COLUMNS`] for `record`: all empty where it did not
/// touch down on the 3-D approach.
pub fn lateral_run_values(record: &RunRecord) -> LateralRunValues {
    lateral_touchdown(record).map_or((None, None, None, None, None, None), touchdown_values)
}

/// The values of [`LATERAL_RUN_COLUMNS`] of a lateral touchdown.
fn touchdown_values(l: LateralTouchdown) -> LateralRunValues {
    (
        Some(l.offset_m),
        Some(l.drift_rate_mps),
        Some(l.bank_deg),
        Some(l.heading_to_centreline_deg),
        l.ramp_lineup_error_deg,
        Some(l.off_centre),
    )
}

/// The lateral statistics of a 3-D campaign's touchdowns.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LateralStatistics {
    /// Touchdowns with a lateral outcome.
    pub touchdowns: u64,
    /// Off-centre touchdowns (beyond `max_off_centre_m`), a share of the touchdowns.
    pub off_centre: Proportion,
    /// The off-centre limit (m).
    pub max_off_centre_m: f64,
    /// Lateral offset of the hook from the centreline at touchdown (m).
    pub lateral_offset_m: Option<Distribution>,
    /// Drift across the centreline relative to the deck at touchdown (m/s).
    pub drift_rate_mps: Option<Distribution>,
    /// Bank at touchdown (deg).
    pub bank_deg: Option<Distribution>,
    /// Heading to the centreline at touchdown (deg).
    pub heading_to_centreline_deg: Option<Distribution>,
    /// Lineup error at the ramp (deg).
    pub ramp_lineup_error_deg: Option<Distribution>,
    /// Passes within ±[`RAMP_LINEUP_PASS_DEG`] at the ramp, a share of those that
    /// crossed it.
    pub ramp_lineup_within_half_degree: Proportion,
    /// Touchdowns with |drift| beyond the limit.
    pub drift_beyond_limit: Proportion,
    /// The drift limit at touchdown (m/s).
    pub max_drift_rate_mps: f64,
    /// Touchdowns with |bank| beyond the limit.
    pub bank_beyond_limit: Proportion,
    /// The bank limit at touchdown (deg).
    pub max_bank_deg: f64,
}

impl LateralStatistics {
    /// The statistics of `records`' lateral touchdowns; `None` when none has one (a
    /// 3-DOF campaign).
    pub fn of(records: &[RunRecord]) -> Option<Self> {
        let values: Vec<LateralRunValues> = records.iter().map(lateral_run_values).collect();
        Self::of_rows(&values)
    }

    /// The statistics of the lateral touchdowns of `rows` (the values of
    /// [`LATERAL_RUN_COLUMNS`], one per run, as `runs.csv` holds them): the same as
    /// [`Self::of`] on the records they were made from, so a 3-D campaign merged from its
    /// shards has those of the campaign flown whole. `None` when no row has one.
    pub fn of_rows(rows: &[LateralRunValues]) -> Option<Self> {
        let touchdowns: Vec<LateralTouchdown> = rows
            .iter()
            .filter_map(|&(offset, drift, bank, heading, ramp, off_centre)| {
                Some(LateralTouchdown {
                    offset_m: offset?,
                    drift_rate_mps: drift?,
                    bank_deg: bank?,
                    heading_to_centreline_deg: heading?,
                    ramp_lineup_error_deg: ramp,
                    off_centre: off_centre?,
                })
            })
            .collect();
        if touchdowns.is_empty() {
            return None;
        }
        let n = touchdowns.len() as u64;
        let count = |test: &dyn Fn(&LateralTouchdown) -> bool| {
            touchdowns.iter().filter(|t| test(t)).count() as u64
        };
        let ramp: Vec<f64> = touchdowns
            .iter()
            .filter_map(|t| t.ramp_lineup_error_deg)
            .collect();
        let within = ramp
            .iter()
            .filter(|e| e.abs() <= RAMP_LINEUP_PASS_DEG)
            .count() as u64;
        Some(Self {
            touchdowns: n,
            off_centre: Proportion::new(count(&|t| t.off_centre), n),
            max_off_centre_m: MAX_OFF_CENTRE_M,
            lateral_offset_m: Distribution::of(touchdowns.iter().map(|t| t.offset_m)),
            drift_rate_mps: Distribution::of(touchdowns.iter().map(|t| t.drift_rate_mps)),
            bank_deg: Distribution::of(touchdowns.iter().map(|t| t.bank_deg)),
            heading_to_centreline_deg: Distribution::of(
                touchdowns.iter().map(|t| t.heading_to_centreline_deg),
            ),
            ramp_lineup_error_deg: Distribution::of(ramp.iter().copied()),
            ramp_lineup_within_half_degree: Proportion::new(within, ramp.len() as u64),
            drift_beyond_limit: Proportion::new(
                count(&|t| t.drift_rate_mps.abs() > MAX_TOUCHDOWN_DRIFT_MPS),
                n,
            ),
            max_drift_rate_mps: MAX_TOUCHDOWN_DRIFT_MPS,
            bank_beyond_limit: Proportion::new(
                count(&|t| t.bank_deg.abs() > MAX_TOUCHDOWN_BANK_DEG),
                n,
            ),
            max_bank_deg: MAX_TOUCHDOWN_BANK_DEG,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn touched_down() -> LateralRow {
        let mut trap_sheet = [None; 24];
        for slot in trap_sheet[..12].iter_mut() {
            *slot = Some(0.25);
        }
        LateralRow {
            touchdown: (
                Some(0.4),
                Some(-0.2),
                Some(1.0),
                Some(-3.0),
                Some(0.1),
                Some(false),
            ),
            trap_sheet,
        }
    }

    #[test]
    fn a_row_a_campaign_writes_passes_and_edits_are_refused_by_column() {
        assert_eq!(touched_down().check(true, true), Ok(()));
        let refused = |row: LateralRow, touched: bool, flown: bool| {
            row.check(touched, flown).unwrap_err().column
        };
        // A lateral touchdown without a touchdown.
        assert_eq!(
            refused(touched_down(), false, true),
            "touchdown_lateral_offset_m"
        );
        // Not finite.
        let mut row = touched_down();
        row.touchdown.1 = Some(f64::NAN);
        assert_eq!(refused(row, true, true), "touchdown_drift_rate_mps");
        // Off centre at 0.4 m from the centreline.
        let mut row = touched_down();
        row.touchdown.5 = Some(true);
        assert_eq!(refused(row, true, true), "off_centre");
        // Beyond 6.1 m and not off centre.
        let mut row = touched_down();
        row.touchdown.0 = Some(-7.0);
        assert_eq!(refused(row, true, true), "off_centre");
        // Half a touchdown.
        let mut row = touched_down();
        row.touchdown.3 = None;
        assert_eq!(
            refused(row, true, true),
            "touchdown_heading_to_centreline_deg"
        );
        // Half a position of the trap sheet.
        let mut row = touched_down();
        row.trap_sheet[9] = None;
        assert_eq!(refused(row, true, true), "trap_im_lineup_peak_m");
        // A trap sheet for a run that never flew.
        let mut row = touched_down();
        row.touchdown = (None, None, None, None, None, None);
        assert_eq!(refused(row, false, false), "trap_x_glide_slope_mean_m");
        // A lineup angle beyond 90°.
        let mut row = touched_down();
        row.trap_sheet[4] = Some(120.0);
        assert_eq!(refused(row, true, true), "trap_x_lineup_mean_deg");
    }
}
