//! A 3-D approach campaign's trap sheets (docs/model.md §10.8; [`crate::metrics::TrapSheet`]):
//! the columns they add to `runs.csv`, and their statistics per position of the groove.
//!
//! Each run gives, for each of the four positions a landing signal officer grades (the
//! start X, the middle IM, in close IC, at the ramp AR), six deviations: the mean and the
//! peak height above the glide slope (m), and the mean and the peak lineup offset (m, and
//! in degrees as seen from the aim point). A position the run never flew (a wave-off
//! before it, a setup that failed) leaves its six columns empty. The statistics of each
//! deviation over the runs that flew the position are its mean, its sample standard
//! deviation and the 95 % confidence interval of the mean, with the 2.5th and 97.5th
//! percentiles (where 95 % of the passes lie).

use serde::Serialize;

use super::record::RunRecord;
use super::statistics::{percentile, sorted_mean_and_deviation, CONFIDENCE_Z_95};
use crate::metrics::{PositionDeviation, TrapSheet, TrapSheetPosition};

/// The deviations of one position, in column order: (name after the position's stem,
/// what it is in words).
pub const TRAP_SHEET_DEVIATIONS: [(&str, &str); 6] = [
    (
        "glide_slope_mean_m",
        "mean height above the glide slope (m, + high)",
    ),
    (
        "glide_slope_peak_m",
        "peak height above the glide slope (m, + high)",
    ),
    ("lineup_mean_m", "mean lineup offset (m, + right)"),
    ("lineup_peak_m", "peak lineup offset (m, + right)"),
    (
        "lineup_mean_deg",
        "mean lineup error from the aim point (deg, + right)",
    ),
    (
        "lineup_peak_deg",
        "peak lineup error from the aim point (deg, + right)",
    ),
];

/// The columns a 3-D campaign's trap sheets add to `runs.csv` (after the lateral
/// touchdown columns): `trap_<stem>_<deviation>` for each position X, IM, IC, AR in
/// flight order and each of [`TRAP_SHEET_DEVIATIONS`].
pub const TRAP_SHEET_RUN_COLUMNS: [&str; 24] = [
    "trap_x_glide_slope_mean_m",
    "trap_x_glide_slope_peak_m",
    "trap_x_lineup_mean_m",
    "trap_x_lineup_peak_m",
    "trap_x_lineup_mean_deg",
    "trap_x_lineup_peak_deg",
    "trap_im_glide_slope_mean_m",
    "trap_im_glide_slope_peak_m",
    "trap_im_lineup_mean_m",
    "trap_im_lineup_peak_m",
    "trap_im_lineup_mean_deg",
    "trap_im_lineup_peak_deg",
    "trap_ic_glide_slope_mean_m",
    "trap_ic_glide_slope_peak_m",
    "trap_ic_lineup_mean_m",
    "trap_ic_lineup_peak_m",
    "trap_ic_lineup_mean_deg",
    "trap_ic_lineup_peak_deg",
    "trap_ar_glide_slope_mean_m",
    "trap_ar_glide_slope_peak_m",
    "trap_ar_lineup_mean_m",
    "trap_ar_lineup_peak_m",
    "trap_ar_lineup_mean_deg",
    "trap_ar_lineup_peak_deg",
];

/// One run's values of [`TRAP_SHEET_RUN_COLUMNS`] (empty where it did not fly the
/// position).
pub type TrapSheetRunValues = [Option<f64>; 24];

/// The six deviations of `deviation`, in [`TRAP_SHEET_DEVIATIONS`] order.
fn deviations(deviation: &PositionDeviation) -> [f64; 6] {
    [
        deviation.glide_slope_mean_m,
        deviation.glide_slope_peak_m,
        deviation.lineup_mean_m,
        deviation.lineup_peak_m,
        deviation.lineup_mean_deg,
        deviation.lineup_peak_deg,
    ]
}

/// The values of [`TRAP_SHEET_RUN_COLUMNS`] for `record`: those of its trap sheet
/// ([`sheet_values`]), all empty for a run without one.
pub fn trap_sheet_run_values(record: &RunRecord) -> TrapSheetRunValues {
    record
        .result
        .as_ref()
        .ok()
        .and_then(|s| s.trap_sheet.as_ref())
        .map_or([None; 24], sheet_values)
}

/// The values of [`TRAP_SHEET_RUN_COLUMNS`] of `sheet`: a position is filled when the
/// pass flew it and all six of its deviations are finite, else empty.
pub fn sheet_values(sheet: &TrapSheet) -> TrapSheetRunValues {
    let mut values = [None; 24];
    for (index, position) in TrapSheetPosition::ALL.into_iter().enumerate() {
        let Some(deviation) = sheet.at(position) else {
            continue;
        };
        let numbers = deviations(deviation);
        if numbers.iter().all(|v| v.is_finite()) {
            for (slot, value) in values[6 * index..6 * index + 6].iter_mut().zip(numbers) {
                *slot = Some(value);
            }
        }
    }
    values
}

/// The values of one position in `values`, if the run flew it.
pub fn position_values(
    values: &TrapSheetRunValues,
    position: TrapSheetPosition,
) -> [Option<f64>; 6] {
    let start = 6 * position as usize;
    let mut out = [None; 6];
    out.copy_from_slice(&values[start..start + 6]);
    out
}

/// Mean, standard deviation and 95 % intervals of one deviation over the passes.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DeviationStatistics {
    /// Passes that flew the position.
    pub count: u64,
    /// Mean over the passes.
    pub mean: f64,
    /// Sample standard deviation (n − 1; 0 for one pass).
    pub standard_deviation: f64,
    /// Lower end of the 95 % confidence interval of the mean, mean − z·σ/√n (normal
    /// approximation, z = 1.96).
    pub mean_ci95_low: f64,
    /// Upper end of the 95 % confidence interval of the mean.
    pub mean_ci95_high: f64,
    /// 2.5th percentile: with the 97.5th, the interval 95 % of the passes lie in.
    pub p2_5: f64,
    /// 97.5th percentile.
    pub p97_5: f64,
}

impl DeviationStatistics {
    /// The statistics of the finite `values`; `None` if there are none.
    pub fn of(values: impl IntoIterator<Item = f64>) -> Option<Self> {
        let (sorted, mean, standard_deviation) = sorted_mean_and_deviation(values)?;
        let n = sorted.len() as f64;
        let half = CONFIDENCE_Z_95 * standard_deviation / n.sqrt();
        Some(Self {
            count: sorted.len() as u64,
            mean,
            standard_deviation,
            mean_ci95_low: mean - half,
            mean_ci95_high: mean + half,
            p2_5: percentile(&sorted, 2.5),
            p97_5: percentile(&sorted, 97.5),
        })
    }
}

/// The statistics of one position of the trap sheet over a campaign's passes.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PositionStatistics {
    /// Which position.
    pub position: TrapSheetPosition,
    /// The LSO's shorthand (X, IM, IC, AR).
    pub shorthand: &'static str,
    /// Outer edge of the window, distance to the ramp (m).
    pub from_m: f64,
    /// Inner edge of the window (m).
    pub to_m: f64,
    /// Passes that flew the position.
    pub passes: u64,
    /// Mean height above the glide slope in the window (m, + high).
    pub glide_slope_mean_m: Option<DeviationStatistics>,
    /// Peak height above the glide slope (m, + high).
    pub glide_slope_peak_m: Option<DeviationStatistics>,
    /// Mean lineup offset (m, + right).
    pub lineup_mean_m: Option<DeviationStatistics>,
    /// Peak lineup offset (m, + right).
    pub lineup_peak_m: Option<DeviationStatistics>,
    /// Mean lineup error seen from the aim point (deg, + right).
    pub lineup_mean_deg: Option<DeviationStatistics>,
    /// Peak lineup error seen from the aim point (deg, + right).
    pub lineup_peak_deg: Option<DeviationStatistics>,
}

impl PositionStatistics {
    /// The six deviations' statistics in [`TRAP_SHEET_DEVIATIONS`] order.
    pub fn deviations(&self) -> [Option<DeviationStatistics>; 6] {
        [
            self.glide_slope_mean_m,
            self.glide_slope_peak_m,
            self.lineup_mean_m,
            self.lineup_peak_m,
            self.lineup_mean_deg,
            self.lineup_peak_deg,
        ]
    }
}

/// The statistics of a 3-D campaign's trap sheets, every controller's passes together.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrapSheetStatistics {
    /// How the intervals are computed, in words.
    pub intervals: &'static str,
    /// The four positions in flight order (X, IM, IC, AR).
    pub positions: Vec<PositionStatistics>,
}

/// The intervals of [`DeviationStatistics`], in words.
pub const TRAP_SHEET_INTERVALS: &str = "per deviation over the passes that flew the \
     position: 95 % confidence interval of the mean (mean ± 1.96·σ/√n), and the 2.5th and \
     97.5th percentiles (Hyndman & Fan type 7) that 95 % of the passes lie between";

impl TrapSheetStatistics {
    /// The statistics of the runs' trap-sheet values (one per run, any order).
    pub fn of_rows(rows: &[TrapSheetRunValues]) -> Self {
        let positions = TrapSheetPosition::ALL
            .into_iter()
            .map(|position| {
                let values: Vec<[Option<f64>; 6]> = rows
                    .iter()
                    .map(|row| position_values(row, position))
                    .collect();
                let column = |k: usize| DeviationStatistics::of(values.iter().filter_map(|v| v[k]));
                let (from_m, to_m) = position.window_m();
                PositionStatistics {
                    position,
                    shorthand: position.shorthand(),
                    from_m,
                    to_m,
                    passes: values.iter().filter(|v| v[0].is_some()).count() as u64,
                    glide_slope_mean_m: column(0),
                    glide_slope_peak_m: column(1),
                    lineup_mean_m: column(2),
                    lineup_peak_m: column(3),
                    lineup_mean_deg: column(4),
                    lineup_peak_deg: column(5),
                }
            })
            .collect();
        Self {
            intervals: TRAP_SHEET_INTERVALS,
            positions,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_columns_are_each_position_stem_then_each_deviation() {
        for (p, position) in TrapSheetPosition::ALL.into_iter().enumerate() {
            for (d, (deviation, _)) in TRAP_SHEET_DEVIATIONS.iter().enumerate() {
                assert_eq!(
                    TRAP_SHEET_RUN_COLUMNS[6 * p + d],
                    format!("trap_{}_{deviation}", position.stem())
                );
            }
        }
    }

    #[test]
    fn a_wave_off_leaves_the_positions_it_never_flew_empty() {
        // Flown from 1400 m to 700 m, then waved off (the recorder takes no more samples).
        let mut recorder = crate::metrics::TrapSheetRecorder::new(60.0, 0.12);
        let mut d = 1400.0;
        while d > 700.0 {
            recorder.sample(d, 0.5, -1.0, 0.12);
            d -= 10.0;
        }
        let values = sheet_values(&recorder.sheet());
        assert_eq!(values[0], Some(0.5));
        assert_eq!(values[3], Some(-1.0));
        assert!(values[..12].iter().all(Option::is_some), "X and IM flown");
        assert!(
            values[12..].iter().all(Option::is_none),
            "IC and AR never flown"
        );
        // A deviation that is not finite empties its position rather than reach a file.
        let mut sheet = recorder.sheet();
        sheet.positions[1].lineup_peak_deg = f64::INFINITY;
        let values = sheet_values(&sheet);
        assert!(values[6..12].iter().all(Option::is_none));
        assert!(values[..6].iter().all(Option::is_some));
    }

    #[test]
    fn statistics_skip_the_positions_a_pass_never_flew() {
        // Three passes; the third waved off before the middle.
        let mut rows = [[None; 24]; 3];
        for (row, glide) in rows.iter_mut().zip([1.0, 2.0, 3.0]) {
            for slot in row[..6].iter_mut() {
                *slot = Some(glide);
            }
        }
        for row in rows[..2].iter_mut() {
            for slot in row[6..].iter_mut() {
                *slot = Some(-0.5);
            }
        }
        let statistics = TrapSheetStatistics::of_rows(&rows);
        let start = &statistics.positions[0];
        assert_eq!(start.passes, 3);
        let glide = start.glide_slope_mean_m.unwrap();
        // Mean 2, σ 1, half-width 1.96/√3 = 1.13161.
        assert_eq!((glide.mean, glide.standard_deviation), (2.0, 1.0));
        assert!((glide.mean_ci95_high - 2.0 - 1.959_964 / 3f64.sqrt()).abs() < 1e-6);
        // Type 7: position 0.025·2 = 0.05 between 1 and 2.
        assert!((glide.p2_5 - 1.05).abs() < 1e-12);
        let at_ramp = &statistics.positions[3];
        assert_eq!((at_ramp.shorthand, at_ramp.passes), ("AR", 2));
        assert_eq!(at_ramp.lineup_peak_deg.unwrap().standard_deviation, 0.0);
        let none = TrapSheetStatistics::of_rows(&[[None; 24]]);
        assert!(none
            .positions
            .iter()
            .all(|p| p.passes == 0 && p.lineup_mean_m.is_none()));
    }
}
