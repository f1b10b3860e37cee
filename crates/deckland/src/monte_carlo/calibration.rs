//! Calibrated risk (issue 45, item 1): the probabilities the forecast gave at the commit
//! point ([`crate::control::CommitForecast`], the `commit_*_probability` columns of
//! `runs.csv`) held against what the flights did, per criterion — a ramp strike (the
//! outcome `ramp_strike`), a hard landing (`hard_landing`) and, on the 3-D approach, an
//! off-centre touchdown (the `off_centre` column) — over the runs that reached the
//! commit point.
//!
//! - **The count**: if each run's event is an independent Bernoulli draw with the
//!   probability the forecast gave, the number of events is Poisson-binomial, with mean
//!   Σp and variance Σp(1 − p). Its central 95 % interval [L, U] (L the smallest count
//!   whose CDF reaches 2.5 %, U the smallest whose CDF reaches 97.5 %, so that
//!   P(L ≤ X ≤ U) ≥ 95 %) is exact — the distribution by dynamic programming over the
//!   runs ([`poisson_binomial`]), the likely events counted as misses so that each part
//!   stays small, up to a count of [`EXACT_COUNT_LIMIT`] — when the variance is below
//!   [`NORMAL_VARIANCE`], and otherwise from the normal approximation with a continuity
//!   correction, P(X ≤ k) ≈ Φ((k + ½ − Σp)/σ): L = ⌈Σp − zσ − ½⌉, U = ⌈Σp + zσ − ½⌉. The
//!   forecast is *calibrated* on the count when the observed count lies in [L, U].
//! - **Reliability**: the runs binned by their probability on a log scale
//!   ([`CALIBRATION_BIN_EDGES`]: [0, 10⁻⁶), [10⁻⁶, 10⁻⁵), …, [0.1, 1]), each bin with its
//!   runs, mean predicted probability, observed events and the exact two-sided 95 %
//!   (Clopper–Pearson) interval of the observed rate: a calibrated forecast has each
//!   bin's mean probability within its interval.
//! - **The ramp clearance's standardised error** ([`ClearanceError`]): the ramp-strike
//!   probability is Φ(−c/σ_c) of a predicted clearance c with σ_c, so for every run
//!   that crossed the ramp z = (clearance flown − c)/σ_c is normal (0, 1) where it is
//!   calibrated. Its mean and SD test the model on every run, where the strikes alone
//!   are too few to (an SD below 1: the predicted tail is too heavy, the probability
//!   pessimistic).

use serde::Serialize;

use super::rare_events::{binomial_cdf_crossing, upper_bound, CONFIDENCE_Z_95};
use super::record::RunRecord;
use super::row::RunRow;
use crate::simulation::Outcome;

/// The edges of the reliability bins: [e_k, e_k+1), the last closed at 1.
pub const CALIBRATION_BIN_EDGES: [f64; 8] = [0.0, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 0.1, 1.0];

/// The variance Σp(1 − p) from which the count's interval is the normal approximation's.
pub const NORMAL_VARIANCE: f64 = 9.0;

/// The largest count each part of the exact distribution is worked out to
/// (`count_distribution`), the mass beyond it kept at it: the parts' means are below
/// 18 where it is used, so what lies beyond 200 is below 10⁻¹³⁰ (a Poisson count of
/// mean 18, whose tail is the longer, has 2·10⁻¹³² at 200).
pub const EXACT_COUNT_LIMIT: usize = 200;

/// The method of the calibration, in words, for summaries.
pub const CALIBRATION_METHOD: &str = "the probabilities the forecast gave at the commit point \
     (the first step with the time to go at or below decision_time_to_go_s, no wave-off \
     decided before) against the events of the runs that reached it; the expected count is \
     the sum of the probabilities and its central 95 % interval that of the Poisson-binomial \
     count (exact by dynamic programming below a variance of 9, else the normal \
     approximation with a continuity correction); the observed rate of each bin of \
     probability has its exact two-sided 95 % Clopper-Pearson interval";

/// How a count's interval was worked out.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum IntervalMethod {
    /// The exact Poisson-binomial distribution.
    Exact,
    /// The normal approximation with a continuity correction.
    Normal,
}

/// The central 95 % interval of an event count: P(low ≤ X ≤ high) ≥ 95 %.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub struct CountInterval {
    /// The smallest count whose CDF reaches 2.5 %.
    pub low: u64,
    /// The smallest count whose CDF reaches 97.5 %.
    pub high: u64,
    /// How it was worked out.
    pub method: IntervalMethod,
}

/// The distribution of the number of events among independent runs with event
/// probabilities `probabilities` (Poisson-binomial), by dynamic programming over the
/// runs: P(X = k) for k below the last entry, and in the last, of index
/// K = min(runs with p > 0, `max_count`), P(X ≥ K) (P(X = K) when K is every such run).
/// O(n·K).
pub fn poisson_binomial(probabilities: &[f64], max_count: usize) -> Vec<f64> {
    let live = probabilities.iter().filter(|p| **p > 0.0);
    let top = live.clone().count().min(max_count);
    let mut mass = vec![0.0; top + 1];
    mass[0] = 1.0;
    if top == 0 {
        return mass;
    }
    for (i, &p) in live.enumerate() {
        let p = p.min(1.0);
        // The last entry keeps the counts at and beyond it; below it, after i + 1 runs
        // no count beyond i + 1 has mass.
        mass[top] += mass[top - 1] * p;
        for k in (1..=(i + 1).min(top - 1)).rev() {
            mass[k] = mass[k] * (1.0 - p) + mass[k - 1] * p;
        }
        mass[0] *= 1.0 - p;
    }
    mass
}

/// The central 95 % interval of the number of events among runs with event
/// probabilities `probabilities` (module docs).
pub fn count_interval(probabilities: &[f64]) -> CountInterval {
    let variance: f64 = probabilities.iter().map(|p| p * (1.0 - p)).sum();
    if variance < NORMAL_VARIANCE {
        let (offset, mass) = count_distribution(probabilities);
        return CountInterval {
            low: offset + quantile(&mass, 0.025) as u64,
            high: offset + quantile(&mass, 0.975) as u64,
            method: IntervalMethod::Exact,
        };
    }
    let mean: f64 = probabilities.iter().sum();
    let sigma = variance.sqrt();
    let runs = probabilities.len() as f64;
    let point = |z: f64| (mean + z * sigma - 0.5).ceil().clamp(0.0, runs) as u64;
    CountInterval {
        low: point(-CONFIDENCE_Z_95),
        high: point(CONFIDENCE_Z_95),
        method: IntervalMethod::Normal,
    }
}

/// The distribution of the number of events among runs with event probabilities
/// `probabilities`: (c, P) with P[j] = P(X = c + j). Worked out as X = m + A − B, m the
/// runs with p > ½, A the events of the others and B the non-events of those m, each
/// Poisson-binomial ([`poisson_binomial`], to [`EXACT_COUNT_LIMIT`]) with a mean of
/// Σ min(p, 1 − p) ≤ 2·Σp(1 − p): below 18 where the distribution is used (a variance
/// below 9), so that the mass beyond the limit is negligible (it is kept at the limit).
fn count_distribution(probabilities: &[f64]) -> (u64, Vec<f64>) {
    let (likely, unlikely): (Vec<f64>, Vec<f64>) = probabilities
        .iter()
        .map(|p| p.clamp(0.0, 1.0))
        .partition(|p| *p > 0.5);
    let misses: Vec<f64> = likely.iter().map(|p| 1.0 - p).collect();
    let events = poisson_binomial(&unlikely, EXACT_COUNT_LIMIT);
    let missed = poisson_binomial(&misses, EXACT_COUNT_LIMIT);
    // X = m − (missed.len() − 1) + j: j = i + (missed.len() − 1 − k) for A = i, B = k.
    let shift = missed.len() - 1;
    let mut mass = vec![0.0; events.len() + shift];
    for (i, a) in events.iter().enumerate() {
        for (k, b) in missed.iter().enumerate() {
            mass[i + shift - k] += a * b;
        }
    }
    ((likely.len() - shift) as u64, mass)
}

/// The smallest index whose cumulative sum of `mass` reaches `level` (to rounding).
fn quantile(mass: &[f64], level: f64) -> usize {
    let mut cumulative = 0.0;
    for (k, m) in mass.iter().enumerate() {
        cumulative += m;
        if cumulative >= level - 1e-12 {
            return k;
        }
    }
    mass.len() - 1
}

/// The exact two-sided 95 % (Clopper–Pearson) interval of a rate seen `events` times in
/// `runs` runs: (0, 1) without runs.
pub fn clopper_pearson_interval(events: u64, runs: u64) -> (f64, f64) {
    if runs == 0 {
        return (0.0, 1.0);
    }
    let high = upper_bound(events, runs, 0.975);
    if events == 0 {
        return (0.0, high);
    }
    // The low end: the p at which `events` or more events have probability 2.5 %,
    // P(X ≤ events − 1 | p) = 97.5 %; the CDF falls with p (bisection, as `upper_bound`).
    let (low, _) = binomial_cdf_crossing(events - 1, runs, 0.975);
    (low, high)
}

/// The runs whose predicted probability lies in one reliability bin.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ReliabilityBin {
    /// The bin's lowest probability (inclusive).
    pub p_low: f64,
    /// Its highest (exclusive, but for the last bin's 1).
    pub p_high: f64,
    /// Runs in the bin.
    pub runs: u64,
    /// Their mean predicted probability; `None` for an empty bin.
    pub mean_predicted: Option<f64>,
    /// Events among them.
    pub observed_events: u64,
    /// The observed rate, events / runs; `None` for an empty bin.
    pub observed_rate: Option<f64>,
    /// The exact two-sided 95 % (Clopper–Pearson) interval of the observed rate.
    pub ci95_low: f64,
    /// Its upper end.
    pub ci95_high: f64,
}

/// The calibration of one criterion (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CriterionCalibration {
    /// Runs with a probability (those that reached the commit point).
    pub runs: u64,
    /// The expected number of events, Σp.
    pub expected_events: f64,
    /// Its standard deviation under the forecast, √(Σp(1 − p)).
    pub expected_events_sd: f64,
    /// The events the runs had.
    pub observed_events: u64,
    /// The central 95 % interval of the count the probabilities imply.
    pub interval_95: CountInterval,
    /// Whether the observed count lies in it.
    pub calibrated: bool,
    /// Observed over expected events; `None` when none were expected.
    pub observed_to_expected: Option<f64>,
    /// The reliability bins ([`CALIBRATION_BIN_EDGES`]), every one, empty or not.
    pub bins: Vec<ReliabilityBin>,
}

impl CriterionCalibration {
    /// The calibration of (probability, whether the event happened) pairs, one per run;
    /// `None` without any.
    pub fn of(pairs: &[(f64, bool)]) -> Option<Self> {
        if pairs.is_empty() {
            return None;
        }
        let probabilities: Vec<f64> = pairs.iter().map(|(p, _)| p.clamp(0.0, 1.0)).collect();
        let expected_events: f64 = probabilities.iter().sum();
        let variance: f64 = probabilities.iter().map(|p| p * (1.0 - p)).sum();
        let observed_events = pairs.iter().filter(|(_, event)| *event).count() as u64;
        let interval_95 = count_interval(&probabilities);
        Some(Self {
            runs: pairs.len() as u64,
            expected_events,
            expected_events_sd: variance.sqrt(),
            observed_events,
            interval_95,
            calibrated: (interval_95.low..=interval_95.high).contains(&observed_events),
            observed_to_expected: Some(observed_events as f64 / expected_events)
                .filter(|r| expected_events > 0.0 && r.is_finite()),
            bins: reliability_bins(pairs),
        })
    }
}

/// The index of the reliability bin of probability `p`.
fn bin_of(p: f64) -> usize {
    let last = CALIBRATION_BIN_EDGES.len() - 2;
    CALIBRATION_BIN_EDGES[1..=last]
        .iter()
        .position(|edge| p < *edge)
        .unwrap_or(last)
}

/// The reliability bins of (probability, event) `pairs`.
pub fn reliability_bins(pairs: &[(f64, bool)]) -> Vec<ReliabilityBin> {
    let count = CALIBRATION_BIN_EDGES.len() - 1;
    let mut sums = vec![(0_u64, 0.0_f64, 0_u64); count];
    for &(p, event) in pairs {
        let bin = &mut sums[bin_of(p)];
        bin.0 += 1;
        bin.1 += p.clamp(0.0, 1.0);
        bin.2 += u64::from(event);
    }
    sums.into_iter()
        .enumerate()
        .map(|(k, (runs, sum, events))| {
            let (ci95_low, ci95_high) = clopper_pearson_interval(events, runs);
            let share = |x: f64| (runs > 0).then(|| x / runs as f64);
            ReliabilityBin {
                p_low: CALIBRATION_BIN_EDGES[k],
                p_high: CALIBRATION_BIN_EDGES[k + 1],
                runs,
                mean_predicted: share(sum),
                observed_events: events,
                observed_rate: share(events as f64),
                ci95_low,
                ci95_high,
            }
        })
        .collect()
}

/// The calibration of a controller's runs at the commit point, per criterion (`None`
/// where no run has its probability: no run reached the commit point, or for the
/// off-centre touchdown a longitudinal approach or no lateral columns to read).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Calibration {
    /// How it is worked out ([`CALIBRATION_METHOD`]).
    pub method: &'static str,
    /// Runs that reached the commit point.
    pub runs_at_commit: u64,
    /// Of them, runs that waved off after it (on a lateral criterion, whose window
    /// runs on its own time to go): they count as runs without an event.
    pub waved_off_after_commit: u64,
    /// The ramp strike's probability against the outcome `ramp_strike`.
    pub ramp_strike: Option<CriterionCalibration>,
    /// The hard landing's probability against the outcome `hard_landing`.
    pub hard_landing: Option<CriterionCalibration>,
    /// The off-centre touchdown's probability against the `off_centre` column.
    pub off_centre: Option<CriterionCalibration>,
    /// The ramp clearance's standardised error over the runs that reached the commit
    /// point and crossed the ramp (`None` with fewer than two).
    pub ramp_clearance_error: Option<ClearanceError>,
}

/// The standardised error z = (flown − c)/σ_c of the hook-to-ramp clearance that the
/// ramp-strike probability is taken on (module docs): its mean and SD over the runs,
/// each with a 95 % interval — the mean's x̄ ± 1.96·s/√n, the SD's s·exp(∓1.96/√(2(n −
/// 1))) (the normal approximation of ln s, good from some tens of runs).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct ClearanceError {
    /// Runs with a clearance predicted at the commit point and one flown at the ramp.
    pub runs: u64,
    /// The mean of z (0 where calibrated; above 0, the hook crosses higher than c).
    pub mean: f64,
    /// The lower end of its 95 % interval.
    pub mean_ci95_low: f64,
    /// Its upper end.
    pub mean_ci95_high: f64,
    /// The SD of z (1 where calibrated; below 1, σ_c too wide).
    pub sd: f64,
    /// The lower end of its 95 % interval.
    pub sd_ci95_low: f64,
    /// Its upper end.
    pub sd_ci95_high: f64,
    /// Whether the mean's interval holds 0 and the SD's 1.
    pub calibrated: bool,
}

impl ClearanceError {
    /// The statistics of the standardised errors `z`; `None` with fewer than two.
    pub fn of(z: &[f64]) -> Option<Self> {
        if z.len() < 2 {
            return None;
        }
        let n = z.len() as f64;
        let mean = z.iter().sum::<f64>() / n;
        let sd = (z.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
        let half = CONFIDENCE_Z_95 * sd / n.sqrt();
        let spread = (CONFIDENCE_Z_95 / (2.0 * (n - 1.0)).sqrt()).exp();
        let (mean_ci95_low, mean_ci95_high) = (mean - half, mean + half);
        let (sd_ci95_low, sd_ci95_high) = (sd / spread, sd * spread);
        Some(Self {
            runs: z.len() as u64,
            mean,
            mean_ci95_low,
            mean_ci95_high,
            sd,
            sd_ci95_low,
            sd_ci95_high,
            calibrated: (mean_ci95_low..=mean_ci95_high).contains(&0.0)
                && (sd_ci95_low..=sd_ci95_high).contains(&1.0),
        })
    }

    /// The standardised error of each row that has a clearance and its σ (above 0) at
    /// the commit point and a clearance flown at the ramp.
    pub fn of_rows(rows: &[RunRow]) -> Option<Self> {
        let z: Vec<f64> = rows
            .iter()
            .filter_map(|r| {
                let sigma_m = r.commit_ramp_clearance_sigma_m.filter(|s| *s > 0.0)?;
                Some((r.ramp_clearance_m? - r.commit_ramp_clearance_m?) / sigma_m)
            })
            .collect();
        Self::of(&z)
    }
}

impl Calibration {
    /// The calibration of `rows` (one controller's); `off_centre` is each row's
    /// `off_centre` column (a 3-D campaign's, in the same order), without which the
    /// off-centre probability is not calibrated.
    pub fn of_rows(rows: &[RunRow], off_centre: Option<&[Option<bool>]>) -> Self {
        let pairs = |probability: fn(&RunRow) -> Option<f64>, outcome: Outcome| {
            rows.iter()
                .filter_map(|r| Some((probability(r)?, r.outcome == outcome.name())))
                .collect::<Vec<_>>()
        };
        let ramp = pairs(|r| r.commit_ramp_strike_probability, Outcome::RampStrike);
        let hard = pairs(|r| r.commit_hard_landing_probability, Outcome::HardLanding);
        let off_centre = off_centre
            .filter(|o| o.len() == rows.len())
            .map(|observed| {
                rows.iter()
                    .zip(observed)
                    .filter_map(|(r, o)| Some((r.commit_off_centre_probability?, *o == Some(true))))
                    .collect::<Vec<_>>()
            });
        Self {
            method: CALIBRATION_METHOD,
            runs_at_commit: ramp.len() as u64,
            waved_off_after_commit: rows
                .iter()
                .filter(|r| {
                    r.commit_ramp_strike_probability.is_some()
                        && r.outcome == Outcome::WaveOff.name()
                })
                .count() as u64,
            ramp_strike: CriterionCalibration::of(&ramp),
            hard_landing: CriterionCalibration::of(&hard),
            off_centre: off_centre.and_then(|pairs| CriterionCalibration::of(&pairs)),
            ramp_clearance_error: ClearanceError::of_rows(rows),
        }
    }

    /// The `off_centre` column of each record's row (`None` where it has none).
    pub fn off_centre_of(records: &[&RunRecord]) -> Vec<Option<bool>> {
        records
            .iter()
            .map(|r| r.lateral_touchdown().map(|l| l.off_centre))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::monte_carlo::rare_events::binomial_cdf;

    /// P(X = k) of a binomial count from its CDF (`rare_events::binomial_cdf`).
    fn binomial_pmf(k: u64, n: u64, p: f64) -> f64 {
        binomial_cdf(k, n, p)
            - if k == 0 {
                0.0
            } else {
                binomial_cdf(k - 1, n, p)
            }
    }

    /// Three runs at ½: P(X = k) = C(3, k)/8 = 1/8, 3/8, 3/8, 1/8, whose CDF (⅛, ½, ⅞
    /// and 1) reaches 2.5 % at 0 and 97.5 % only at 3. Three runs at 0.1, 0.2, 0.5, by
    /// hand: P(0) = 0.9·0.8·0.5 = 0.36, P(1) = 0.1·0.8·0.5 + 0.9·0.2·0.5 + 0.9·0.8·0.5 =
    /// 0.49, P(2) = 0.1·0.2·0.5 + 0.1·0.8·0.5 + 0.9·0.2·0.5 = 0.14 and P(3) = 0.01: a CDF
    /// of 0.36, 0.85, 0.99 and 1, and the interval [0, 2]. Cut at a count of 1, the last
    /// entry holds P(X ≥ 1) = 0.64.
    #[test]
    fn the_poisson_binomial_of_three_runs_is_the_hand_worked_one() {
        let halves = poisson_binomial(&[0.5; 3], EXACT_COUNT_LIMIT);
        assert_eq!(halves, vec![0.125, 0.375, 0.375, 0.125]);
        let interval = count_interval(&[0.5; 3]);
        assert_eq!(
            (interval.low, interval.high, interval.method),
            (0, 3, IntervalMethod::Exact)
        );
        let mixed = poisson_binomial(&[0.1, 0.2, 0.5], EXACT_COUNT_LIMIT);
        for (got, want) in mixed.iter().zip([0.36, 0.49, 0.14, 0.01]) {
            assert!((got - want).abs() < 1e-15, "{mixed:?}");
        }
        let interval = count_interval(&[0.1, 0.2, 0.5]);
        assert_eq!((interval.low, interval.high), (0, 2));
        let cut = poisson_binomial(&[0.1, 0.2, 0.5], 1);
        assert!((cut[0] - 0.36).abs() < 1e-15 && (cut[1] - 0.64).abs() < 1e-15);
        // Runs with p = 0 add nothing; no run at all is a count of 0 for certain.
        assert_eq!(poisson_binomial(&[0.0, 0.5, 0.0], 10), vec![0.5, 0.5]);
        assert_eq!(poisson_binomial(&[], 10), vec![1.0]);
        let none = count_interval(&[0.0; 5]);
        assert_eq!((none.low, none.high), (0, 0));
    }

    /// With every p alike the count is binomial: the distribution agrees with the
    /// binomial's (from the incomplete beta function) and the interval with its 2.5 % and
    /// 97.5 % points, worked out from the binomial's CDF (in Python: 0–6 for 40 runs at
    /// 0.07, 0–7 for 1000 at 0.003, 8–12 for 12 at 0.9, 299–300 for 300 at 0.9999, whose
    /// mean of 299.97 goes far beyond the exact distribution's limit of 200).
    #[test]
    fn with_equal_probabilities_the_count_is_binomial() {
        for (n, p, low, high) in [
            (40_u64, 0.07, 0, 6),
            (1000, 0.003, 0, 7),
            (12, 0.9, 8, 12),
            (300, 0.9999, 299, 300),
        ] {
            let probabilities = vec![p; n as usize];
            let interval = count_interval(&probabilities);
            assert_eq!(interval.method, IntervalMethod::Exact, "{n} at {p}");
            assert_eq!((interval.low, interval.high), (low, high), "{n} at {p}");
            let cdf_low = binomial_cdf(low, n, p);
            assert!(cdf_low >= 0.025 && (low == 0 || binomial_cdf(low - 1, n, p) < 0.025));
            assert!(binomial_cdf(high, n, p) >= 0.975 && binomial_cdf(high - 1, n, p) < 0.975);
        }
        let mass = poisson_binomial(&[0.07; 40], EXACT_COUNT_LIMIT);
        for (k, m) in mass.iter().enumerate() {
            assert!((m - binomial_pmf(k as u64, 40, 0.07)).abs() < 1e-13, "{k}");
        }
    }

    /// From a variance of 9 the normal approximation with a continuity correction: 2000
    /// runs at 0.01 (mean 20, σ = 4.4497), [⌈20 − 8.7213 − ½⌉, ⌈20 + 8.7213 − ½⌉] =
    /// [11, 29], where the binomial's own points are 12 and 29.
    #[test]
    fn a_large_variance_takes_the_normal_approximation() {
        let interval = count_interval(&[0.01; 2000]);
        assert_eq!(
            (interval.low, interval.high, interval.method),
            (11, 29, IntervalMethod::Normal)
        );
    }

    /// Clopper–Pearson, worked out in Python by bisection on exact binomial sums:
    /// 3 of 10 → [0.066740, 0.652453]; 1 of 20 → [0.0012651, 0.248733]; 0 of 10 →
    /// [0, 1 − 0.025^(1/10)]; 10 of 10 → [0.025^(1/10), 1]; no run → [0, 1].
    #[test]
    fn the_clopper_pearson_intervals_are_the_exact_ones() {
        let close = |(low, high): (f64, f64), (a, b): (f64, f64)| {
            assert!(
                (low - a).abs() < 1e-9 && (high - b).abs() < 1e-9,
                "{low} {high}"
            );
        };
        close(
            clopper_pearson_interval(3, 10),
            (0.066_739_511_177_734_4, 0.652_452_850_059_997_2),
        );
        close(
            clopper_pearson_interval(1, 20),
            (0.001_265_089_497_949_845, 0.248_732_762_772_027_77),
        );
        close(
            clopper_pearson_interval(0, 10),
            (0.0, 0.308_497_107_818_760_7),
        );
        close(
            clopper_pearson_interval(10, 10),
            (0.691_502_892_181_239_2, 1.0),
        );
        assert_eq!(clopper_pearson_interval(0, 0), (0.0, 1.0));
    }

    /// Six (p, event) pairs, binned by hand: 0 and 5·10⁻⁷ in [0, 10⁻⁶) (none happened),
    /// 10⁻⁶ (the edge belongs to the bin above) in [10⁻⁶, 10⁻⁵), 0.003 (happened) in
    /// [10⁻³, 10⁻²), 0.1 and 1 in [0.1, 1] (one happened): mean p 0.55 there.
    #[test]
    fn the_bins_hold_the_hand_made_pairs() {
        let pairs = [
            (0.0, false),
            (5e-7, false),
            (1e-6, false),
            (0.003, true),
            (0.1, false),
            (1.0, true),
        ];
        let bins = reliability_bins(&pairs);
        assert_eq!(bins.len(), 7);
        let runs: Vec<u64> = bins.iter().map(|b| b.runs).collect();
        assert_eq!(runs, [2, 1, 0, 0, 1, 0, 2]);
        let events: Vec<u64> = bins.iter().map(|b| b.observed_events).collect();
        assert_eq!(events, [0, 0, 0, 0, 1, 0, 1]);
        assert_eq!(bins[0].mean_predicted, Some(2.5e-7));
        assert_eq!((bins[0].p_low, bins[0].p_high), (0.0, 1e-6));
        assert_eq!((bins[6].p_low, bins[6].p_high), (0.1, 1.0));
        assert!((bins[6].mean_predicted.unwrap() - 0.55).abs() < 1e-15);
        assert_eq!(bins[6].observed_rate, Some(0.5));
        assert_eq!(
            (bins[2].mean_predicted, bins[2].observed_rate),
            (None, None)
        );
        assert_eq!((bins[2].ci95_low, bins[2].ci95_high), (0.0, 1.0));
        assert_eq!(
            (bins[4].ci95_low, bins[4].ci95_high),
            clopper_pearson_interval(1, 1)
        );
        // The whole: 1.103 expected events (the run at p = 1 certain), 2 observed, within
        // [1, 2] (exact).
        let calibration = CriterionCalibration::of(&pairs).unwrap();
        assert!((calibration.expected_events - 1.103_001_5).abs() < 1e-12);
        assert_eq!(calibration.observed_events, 2);
        assert_eq!(
            (calibration.interval_95.low, calibration.interval_95.high),
            (1, 2)
        );
        assert!(calibration.calibrated);
        assert!(CriterionCalibration::of(&[]).is_none());
    }

    /// A forecast far too sure: 1000 runs at 10⁻⁴ (0.1 events expected, [0, 1]) with 10
    /// events is not calibrated, 100 times too optimistic.
    #[test]
    fn ten_events_where_a_tenth_was_expected_is_not_calibrated() {
        let pairs: Vec<(f64, bool)> = (0..1000).map(|k| (1e-4, k % 111 == 0)).collect();
        let calibration = CriterionCalibration::of(&pairs).unwrap();
        assert_eq!(calibration.observed_events, 10);
        assert_eq!(
            (calibration.interval_95.low, calibration.interval_95.high),
            (0, 1)
        );
        assert!(!calibration.calibrated);
        assert!((calibration.observed_to_expected.unwrap() - 100.0).abs() < 1e-9);
    }

    /// Four errors worked by hand: z = −1, 0, 1, 2 have mean ½ and SD √(5/3) =
    /// 1.290994; the mean's interval ½ ± 1.959964·1.290994/2 = [−0.765151, 1.765151]
    /// holds 0, the SD's, 1.290994·e^(∓1.959964/√6) = [0.579993, 2.873598], holds 1.
    #[test]
    fn the_clearance_error_of_four_runs_is_the_hand_worked_one() {
        let e = ClearanceError::of(&[-1.0, 0.0, 1.0, 2.0]).unwrap();
        let close = |a: f64, b: f64| (a - b).abs() < 1e-6;
        assert_eq!(e.runs, 4);
        assert!(close(e.mean, 0.5) && close(e.sd, 1.290_994), "{e:?}");
        assert!(close(e.mean_ci95_low, -0.765_151) && close(e.mean_ci95_high, 1.765_151));
        assert!(close(e.sd_ci95_low, 0.579_993) && close(e.sd_ci95_high, 2.873_598));
        assert!(e.calibrated);
        assert!(ClearanceError::of(&[0.3]).is_none());
    }

    /// 2000 errors at the normal's quantiles Φ⁻¹((k − ½)/2000) are calibrated; the same
    /// with the moderate sea's measured shape (mean +0.18, SD 0.83: the hook crosses
    /// higher and nearer its prediction than σ_c says) are not, and neither is a
    /// forecast too sure (SD 1.2).
    #[test]
    fn normal_errors_are_calibrated_and_a_narrower_or_wider_spread_is_not() {
        let n = 2000;
        let z: Vec<f64> = (1..=n)
            .map(|k| {
                let p = (f64::from(k) - 0.5) / f64::from(n);
                -crate::control::risk::normal_upper_quantile(p)
            })
            .collect();
        let calibrated = ClearanceError::of(&z).unwrap();
        assert!(calibrated.mean.abs() < 1e-9 && (calibrated.sd - 1.0).abs() < 2e-3);
        assert!(calibrated.calibrated, "{calibrated:?}");
        let moderate: Vec<f64> = z.iter().map(|x| 0.18 + 0.83 * x).collect();
        let narrow = ClearanceError::of(&moderate).unwrap();
        assert!(
            !narrow.calibrated && narrow.sd_ci95_high < 1.0,
            "{narrow:?}"
        );
        let wide: Vec<f64> = z.iter().map(|x| 1.2 * x).collect();
        let wide = ClearanceError::of(&wide).unwrap();
        assert!(!wide.calibrated && wide.sd_ci95_low > 1.0, "{wide:?}");
    }

    /// The rows' errors: a run with a clearance predicted and flown counts, one that
    /// never crossed the ramp, one with no commit point and one with σ_c = 0 do not.
    #[test]
    fn only_runs_with_a_prediction_and_a_crossing_have_a_clearance_error() {
        let row = |predicted: Option<(f64, f64)>, flown: Option<f64>| RunRow {
            commit_ramp_clearance_m: predicted.map(|p| p.0),
            commit_ramp_clearance_sigma_m: predicted.map(|p| p.1),
            ramp_clearance_m: flown,
            ..RunRow::unmeasured(1, "O-PD", "trap")
        };
        let rows = [
            row(Some((3.0, 1.0)), Some(2.0)),
            row(Some((3.0, 0.5)), Some(4.0)),
            row(Some((3.0, 1.0)), None),
            row(None, Some(2.0)),
            row(Some((3.0, 0.0)), Some(2.0)),
        ];
        let e = ClearanceError::of_rows(&rows).unwrap();
        // z = −1 and +2.
        assert_eq!(e.runs, 2);
        assert!((e.mean - 0.5).abs() < 1e-12);
        assert!((e.sd - 4.5_f64.sqrt()).abs() < 1e-12);
    }
}
