//! A run's outcome in words, for the terminal and the figures' titles.

use deckland::simulation::{Outcome, RunSummary};

/// The outcome in words, with what decided it: "trap on wire 4", "ramp strike: hook
/// 3.29 m below the ramp".
pub(crate) fn outcome_text(summary: &RunSummary) -> String {
    let name = summary.outcome.name().replace('_', " ");
    match (summary.outcome, summary.wire, &summary.reason) {
        (Outcome::Trap, Some(wire), _) => format!("trap on wire {wire}"),
        (_, _, Some(reason)) => format!("{name}: {reason}"),
        _ => name,
    }
}
