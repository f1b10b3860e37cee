//! The paired comparison of `campaign --compare`: both controllers fly every run with the
//! same seed, so the same dispersions, turbulence and sea; the difference run by run
//! (second controller − first) shows how differently they fly even when the outcome counts
//! agree.

use deckland::monte_carlo::{Distribution, RunRow};

/// One paired quantity: its name and the distribution of its per-run differences.
#[derive(Debug, Clone)]
pub struct PairedDifference {
    /// The quantity and its unit, e.g. "touchdown from the aim point (m)".
    pub name: &'static str,
    /// The distribution of (second − first) over the runs where both have the value.
    pub difference: Option<Distribution>,
    /// The largest |difference|.
    pub largest_abs: Option<f64>,
}

/// The paired comparison of two controllers over the runs both flew.
#[derive(Debug, Clone)]
pub struct PairedComparison {
    /// The first controller (subtracted).
    pub first: String,
    /// The second controller.
    pub second: String,
    /// Runs both controllers finished.
    pub pairs: u64,
    /// Of those, runs where the outcome differs (for a trap, the wire too).
    pub different_outcomes: u64,
    /// Touchdown point, sink rate and elevator activity, in that order.
    pub differences: Vec<PairedDifference>,
}

/// What one row contributes to a paired quantity.
type Quantity = fn(&RunRow) -> Option<f64>;

/// The quantities compared run by run.
const QUANTITIES: [(&str, Quantity); 3] = [
    ("touchdown from the aim point (m)", |r| {
        r.touchdown_distance_m
    }),
    ("touchdown sink rate (m/s)", |r| r.touchdown_sink_rate_mps),
    ("elevator rate RMS (deg/s)", |r| r.elevator_rate_rms_degps),
];

impl PairedComparison {
    /// The paired comparison of the first two controllers of `rows` (sorted by run index
    /// and controller), or `None` with fewer than two controllers.
    pub fn of(rows: &[RunRow], controllers: &[&str]) -> Option<Self> {
        let [first, second, ..] = controllers else {
            return None;
        };
        let find = |controller: &str, run: u64| {
            rows.iter()
                .find(|r| r.run_index == run && r.controller == controller)
        };
        let pairs: Vec<(&RunRow, &RunRow)> = rows
            .iter()
            .filter(|r| r.controller == *first)
            .filter_map(|a| find(second, a.run_index).map(|b| (a, b)))
            .collect();
        let different_outcomes = pairs
            .iter()
            .filter(|(a, b)| a.outcome != b.outcome || a.wire != b.wire)
            .count() as u64;
        let differences = QUANTITIES
            .iter()
            .map(|&(name, get)| {
                let values: Vec<f64> = pairs
                    .iter()
                    .filter_map(|(a, b)| get(a).zip(get(b)).map(|(x, y)| y - x))
                    .filter(|d| d.is_finite())
                    .collect();
                PairedDifference {
                    name,
                    largest_abs: values.iter().map(|d| d.abs()).reduce(f64::max),
                    difference: Distribution::of(values),
                }
            })
            .collect();
        Some(Self {
            first: (*first).to_owned(),
            second: (*second).to_owned(),
            pairs: pairs.len() as u64,
            different_outcomes,
            differences,
        })
    }

    /// One line saying what is compared: "PID − O-PD, run by run (same seed): 200 pairs,
    /// outcome differs in 3".
    pub fn heading(&self) -> String {
        format!(
            "paired differences {} − {}, run by run on the same seed: {} {}, outcome or wire differs in {}",
            self.second,
            self.first,
            self.pairs,
            if self.pairs == 1 { "pair" } else { "pairs" },
            self.different_outcomes
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(run_index: u64, controller: &'static str, touchdown: f64, wire: u8) -> RunRow<'static> {
        RunRow {
            wire: Some(wire),
            touchdown_distance_m: Some(touchdown),
            touchdown_sink_rate_mps: Some(3.0),
            ..RunRow::unmeasured(run_index, controller, "trap")
        }
    }

    #[test]
    fn differences_pair_runs_by_index_and_count_different_outcomes() {
        // Run 0: B lands 1.5 m further on the same wire; run 1: 0.5 m shorter, another
        // wire; run 2 flown by A only: not a pair.
        let rows = [
            row(0, "A", 2.0, 3),
            row(0, "B", 3.5, 3),
            row(1, "A", 1.0, 3),
            row(1, "B", 0.5, 2),
            row(2, "A", 9.0, 4),
        ];
        let paired = PairedComparison::of(&rows, &["A", "B"]).expect("two controllers");
        assert_eq!(paired.pairs, 2);
        assert_eq!(paired.different_outcomes, 1);
        let touchdown = &paired.differences[0];
        let d = touchdown.difference.expect("two differences");
        assert_eq!((d.count, d.min, d.max), (2, -0.5, 1.5));
        assert_eq!(touchdown.largest_abs, Some(1.5));
        assert_eq!(paired.differences[1].difference.map(|d| d.max), Some(0.0));
        assert!(paired.differences[2].difference.is_none());
        assert!(PairedComparison::of(&rows, &["A"]).is_none());
    }
}
