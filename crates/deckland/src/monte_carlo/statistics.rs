//! Campaign statistics: outcome rates with Wilson score intervals, and the mean, standard
//! deviation and percentiles of the touchdown point and sink rate.

use serde::Serialize;

use super::calibration::Calibration;
use super::greenie_board::GreenieBoard;
use super::rare_events::{upper_bound, UPPER_BOUND_CONFIDENCE};
use super::record::RunRecord;
use super::row::RunRow;
use crate::simulation::Outcome;

pub use super::rare_events::CONFIDENCE_Z_95;

/// The Wilson score interval (Wilson 1927; Brown, Cai & DasGupta, "Interval estimation
/// for a binomial proportion", Statistical Science 2001) of `successes` out of `trials`
/// at normal quantile `z`: (low, high), within [0, 1] and sensible at 0 and `trials`
/// successes, unlike the Wald interval. (0, 1) when there are no trials.
pub fn wilson_interval(successes: u64, trials: u64, z: f64) -> (f64, f64) {
    if trials == 0 {
        return (0.0, 1.0);
    }
    let n = trials as f64;
    let p = successes as f64 / n;
    let z2 = z * z;
    let centre = (p + z2 / (2.0 * n)) / (1.0 + z2 / n);
    let half = z / (1.0 + z2 / n) * (p * (1.0 - p) / n + z2 / (4.0 * n * n)).sqrt();
    ((centre - half).max(0.0), (centre + half).min(1.0))
}

/// The `p`-th percentile (0–100) of `sorted` (ascending, not empty) by linear
/// interpolation between closest ranks (Hyndman & Fan type 7, NumPy's default).
pub fn percentile(sorted: &[f64], p: f64) -> f64 {
    match sorted.len() {
        0 => f64::NAN,
        1 => sorted[0],
        n => {
            let position = (p / 100.0).clamp(0.0, 1.0) * (n - 1) as f64;
            let below = position.floor() as usize;
            let above = (below + 1).min(n - 1);
            let fraction = position - below as f64;
            sorted[below] + fraction * (sorted[above] - sorted[below])
        }
    }
}

/// How often an outcome happened, with its 95 % Wilson score interval.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Proportion {
    /// Runs with the outcome.
    pub count: u64,
    /// Fraction of the runs (0–1).
    pub rate: f64,
    /// Lower end of the 95 % Wilson score interval of the rate.
    pub ci95_low: f64,
    /// Upper end of the 95 % Wilson score interval of the rate.
    pub ci95_high: f64,
    /// Exact one-sided 95 % upper confidence bound of the rate (Clopper–Pearson): what
    /// the runs show the probability to be below, also when the outcome never happened
    /// ([`super::upper_bound`]).
    pub upper_bound_95: f64,
}

impl Proportion {
    /// `count` out of `runs`, with its interval.
    pub fn new(count: u64, runs: u64) -> Self {
        let (ci95_low, ci95_high) = wilson_interval(count, runs, CONFIDENCE_Z_95);
        Self {
            count,
            rate: if runs == 0 {
                0.0
            } else {
                count as f64 / runs as f64
            },
            ci95_low,
            ci95_high,
            upper_bound_95: upper_bound(count, runs, UPPER_BOUND_CONFIDENCE),
        }
    }
}

/// Mean, sample standard deviation, extremes and percentiles of a set of values.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct Distribution {
    /// Number of values.
    pub count: u64,
    /// Mean.
    pub mean: f64,
    /// Sample standard deviation (n − 1 in the denominator; 0 for one value).
    pub standard_deviation: f64,
    /// Smallest value.
    pub min: f64,
    /// 5th percentile.
    pub p5: f64,
    /// Median.
    pub p50: f64,
    /// 95th percentile.
    pub p95: f64,
    /// Largest value.
    pub max: f64,
}

/// The finite `values` sorted, their mean and their sample standard deviation (n − 1;
/// 0 for one value); `None` if there are none.
pub(crate) fn sorted_mean_and_deviation(
    values: impl IntoIterator<Item = f64>,
) -> Option<(Vec<f64>, f64, f64)> {
    let mut sorted: Vec<f64> = values.into_iter().filter(|v| v.is_finite()).collect();
    if sorted.is_empty() {
        return None;
    }
    sorted.sort_by(f64::total_cmp);
    let n = sorted.len() as f64;
    let mean = sorted.iter().sum::<f64>() / n;
    let variance = if sorted.len() > 1 {
        sorted.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)
    } else {
        0.0
    };
    Some((sorted, mean, variance.sqrt()))
}

impl Distribution {
    /// The distribution of the finite `values`; `None` if there are none.
    pub fn of(values: impl IntoIterator<Item = f64>) -> Option<Self> {
        let (sorted, mean, standard_deviation) = sorted_mean_and_deviation(values)?;
        Some(Self {
            count: sorted.len() as u64,
            mean,
            standard_deviation,
            min: sorted[0],
            p5: percentile(&sorted, 5.0),
            p50: percentile(&sorted, 50.0),
            p95: percentile(&sorted, 95.0),
            max: sorted[sorted.len() - 1],
        })
    }
}

/// The statistics of one controller's runs in a campaign. Rates are fractions of the
/// finished runs (`runs`), with 95 % Wilson score intervals; the outcome classes are
/// exclusive and add up to `runs`.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CampaignStatistics {
    /// The pitch controller's label.
    pub controller: String,
    /// Finished runs the statistics count.
    pub runs: u64,
    /// Traps: the hook caught a wire within the sink-rate limit.
    pub boarding: Proportion,
    /// Touchdown beyond the last wire, or fly-over.
    pub bolter: Proportion,
    /// Hook below the deck at the ramp.
    pub ramp_strike: Proportion,
    /// Touchdown sink rate above the limit.
    pub hard_landing: Proportion,
    /// The aircraft decided not to land and climbed away (docs/model.md §9): safe, not
    /// one of the failures.
    pub wave_off: Proportion,
    /// The simulation left the model's validity.
    pub divergence: Proportion,
    /// No touchdown within the time limit.
    pub timeout: Proportion,
    /// The dispersed scenario could not be set up (invalid value or untrimmable).
    pub invalid: Proportion,
    /// Traps per wire (wires 1–4, from aft).
    pub traps_per_wire: [u64; 4],
    /// Touchdown point along the deck from the aim point (m, positive forward), over
    /// the runs that touched down.
    pub touchdown_distance_m: Option<Distribution>,
    /// Hook sink rate relative to the deck at touchdown (m/s), over the same runs.
    pub touchdown_sink_rate_mps: Option<Distribution>,
    /// The hook's height above the ramp as it crossed it (m), the ramp-strike margin,
    /// over the runs that crossed it (a ramp strike's is below 0).
    pub ramp_clearance_m: Option<Distribution>,
    /// RMS glide-path error of each flown run (m).
    pub glide_path_error_rms_m: Option<Distribution>,
    /// Elevator-rate RMS of each flown run (deg/s).
    pub elevator_rate_rms_degps: Option<Distribution>,
    /// Share of each flown run with the elevator on its rate limit (%).
    pub time_on_rate_limit_pct: Option<Distribution>,
    /// Share of each flown run with the elevator on a position stop (%).
    pub time_on_stops_pct: Option<Distribution>,
    /// Total elevator travel of each flown run (deg).
    pub elevator_travel_deg: Option<Distribution>,
    /// Thrust-rate RMS of each flown run (kN/s).
    pub thrust_rate_rms_knps: Option<Distribution>,
    /// Share of each flown run with the true deck within every recovery limit (%).
    pub deck_within_limits_pct: Option<Distribution>,
    /// The landing signal officer's greenie board of the runs.
    pub greenie_board: GreenieBoard,
    /// The probabilities the forecast gave at the commit point against what the runs did
    /// (issue 45, item 1; [`Calibration`]).
    pub calibration: Calibration,
}

impl CampaignStatistics {
    /// The statistics of the records of controller `controller` labelled `label`.
    pub fn of(records: &[RunRecord], controller: usize, label: &str) -> Self {
        let own: Vec<&RunRecord> = records
            .iter()
            .filter(|r| r.controller == controller)
            .collect();
        let rows: Vec<RunRow> = own
            .iter()
            .map(|r| RunRow::with_controller(r, label))
            .collect();
        Self::of_rows_observed(&rows, Some(&Calibration::off_centre_of(&own)), label)
    }

    /// The statistics of `rows`, the rows of one controller labelled `label`: the same
    /// numbers as [`Self::of`] on the records the rows were made from, so a campaign
    /// merged from its shards' `runs.csv` has the statistics of the campaign flown whole
    /// — but for the calibration of the off-centre probability, which needs the rows'
    /// `off_centre` column ([`Self::of_rows_observed`]).
    pub fn of_rows(rows: &[RunRow], label: &str) -> Self {
        Self::of_rows_observed(rows, None, label)
    }

    /// As [`Self::of_rows`], with each row's `off_centre` column (a 3-D campaign's
    /// [`super::LateralRow`], in the same order) for the calibration of the off-centre
    /// probability at the commit point.
    pub fn of_rows_observed(
        rows: &[RunRow],
        off_centre: Option<&[Option<bool>]>,
        label: &str,
    ) -> Self {
        let runs = rows.len() as u64;
        let count =
            |outcome: Outcome| rows.iter().filter(|r| r.outcome == outcome.name()).count() as u64;
        let flown: Vec<&RunRow> = rows.iter().filter(|r| r.flown()).collect();
        let touchdowns: Vec<(f64, f64)> = flown
            .iter()
            .filter_map(|r| r.touchdown_distance_m.zip(r.touchdown_sink_rate_mps))
            .collect();
        let mut traps_per_wire = [0; 4];
        for row in flown.iter().filter(|r| r.outcome == Outcome::Trap.name()) {
            if let Some(wire) = row.wire.filter(|w| (1..=4).contains(w)) {
                traps_per_wire[usize::from(wire - 1)] += 1;
            }
        }
        Self {
            controller: label.to_owned(),
            runs,
            boarding: Proportion::new(count(Outcome::Trap), runs),
            bolter: Proportion::new(count(Outcome::Bolter), runs),
            ramp_strike: Proportion::new(count(Outcome::RampStrike), runs),
            hard_landing: Proportion::new(count(Outcome::HardLanding), runs),
            wave_off: Proportion::new(count(Outcome::WaveOff), runs),
            divergence: Proportion::new(count(Outcome::Diverged), runs),
            timeout: Proportion::new(count(Outcome::Timeout), runs),
            invalid: Proportion::new(runs - flown.len() as u64, runs),
            traps_per_wire,
            touchdown_distance_m: Distribution::of(touchdowns.iter().map(|t| t.0)),
            touchdown_sink_rate_mps: Distribution::of(touchdowns.iter().map(|t| t.1)),
            ramp_clearance_m: Distribution::of(flown.iter().filter_map(|r| r.ramp_clearance_m)),
            glide_path_error_rms_m: Distribution::of(
                flown.iter().filter_map(|r| r.glide_path_error_rms_m),
            ),
            elevator_rate_rms_degps: Distribution::of(
                flown.iter().filter_map(|r| r.elevator_rate_rms_degps),
            ),
            time_on_rate_limit_pct: Distribution::of(
                flown.iter().filter_map(|r| r.time_on_rate_limit_pct),
            ),
            time_on_stops_pct: Distribution::of(flown.iter().filter_map(|r| r.time_on_stops_pct)),
            elevator_travel_deg: Distribution::of(
                flown.iter().filter_map(|r| r.elevator_travel_deg),
            ),
            thrust_rate_rms_knps: Distribution::of(
                flown.iter().filter_map(|r| r.thrust_rate_rms_knps),
            ),
            deck_within_limits_pct: Distribution::of(
                flown.iter().filter_map(|r| r.deck_within_limits_pct),
            ),
            greenie_board: GreenieBoard::of_rows(rows),
            calibration: Calibration::of_rows(rows, off_centre),
        }
    }

    /// Every outcome class with its rate, by its key in `summary.json`, in order — for
    /// code that treats the classes alike (rare-event tables). A test keeps it equal to
    /// the [`Proportion`] fields of this struct, so a new class cannot be left out.
    pub fn rates(&self) -> Vec<(&'static str, Proportion)> {
        vec![
            ("boarding", self.boarding),
            ("bolter", self.bolter),
            ("wave_off", self.wave_off),
            ("ramp_strike", self.ramp_strike),
            ("hard_landing", self.hard_landing),
            ("divergence", self.divergence),
            ("timeout", self.timeout),
            ("invalid", self.invalid),
        ]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wilson_interval_matches_published_values() {
        // Brown, Cai & DasGupta (2001) / Newcombe (1998) example: 81 of 263 → (0.2553, 0.3662).
        let (low, high) = wilson_interval(81, 263, CONFIDENCE_Z_95);
        assert!(
            (low - 0.2553).abs() < 5e-4 && (high - 0.3662).abs() < 5e-4,
            "{low} {high}"
        );
        // All successes: the upper end is 1, the lower end n/(n + z²).
        let (low, high) = wilson_interval(20, 20, CONFIDENCE_Z_95);
        assert_eq!(high, 1.0);
        assert!((low - 20.0 / (20.0 + CONFIDENCE_Z_95.powi(2))).abs() < 1e-12);
        assert_eq!(wilson_interval(0, 0, CONFIDENCE_Z_95), (0.0, 1.0));
    }

    #[test]
    fn percentiles_interpolate_between_ranks() {
        let values = [1.0, 2.0, 3.0, 4.0, 5.0];
        assert_eq!(percentile(&values, 50.0), 3.0);
        assert_eq!(percentile(&values, 0.0), 1.0);
        assert_eq!(percentile(&values, 100.0), 5.0);
        assert!((percentile(&values, 5.0) - 1.2).abs() < 1e-12);
        let d = Distribution::of([2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]).expect("values");
        assert_eq!(d.mean, 5.0);
        assert!((d.standard_deviation - (32.0f64 / 7.0).sqrt()).abs() < 1e-12);
        assert!(Distribution::of([f64::NAN]).is_none());
    }

    #[test]
    fn rates_lists_every_proportion_of_the_statistics() {
        let statistics = CampaignStatistics::of_rows(&[], "O-PD");
        let json = serde_json::to_value(&statistics).expect("serialises");
        let proportions: Vec<String> = json
            .as_object()
            .expect("an object")
            .iter()
            .filter(|(_, v)| v.get("ci95_low").is_some())
            .map(|(k, _)| k.clone())
            .collect();
        let listed: Vec<&str> = statistics.rates().iter().map(|(k, _)| *k).collect();
        let mut sorted = listed.clone();
        sorted.sort_unstable();
        let mut expected = proportions.clone();
        expected.sort_unstable();
        assert_eq!(
            sorted, expected,
            "CampaignStatistics::rates() misses a class"
        );
    }
}
