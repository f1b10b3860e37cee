//! A flown sink-rate run and its report: what `deckland sink` writes and prints, and
//! what its figure draws.

use deckland::experiments::SinkRateSample as Row;
use deckland::metrics::StepResponseMetrics;
use serde::Serialize;

/// The summary of a sink-rate run (`summary.json`).
#[derive(Debug, Serialize)]
pub(crate) struct SinkReport {
    pub(crate) controller: &'static str,
    pub(crate) conditions: &'static str,
    pub(crate) seed: u64,
    pub(crate) sink_rate_command_mps: f64,
    pub(crate) ramp_s: f64,
    pub(crate) outcome: &'static str,
    pub(crate) reason: Option<String>,
    /// Sink-rate response metrics (2 % band of the command).
    pub(crate) metrics: Option<StepResponseMetrics>,
    /// Largest pitch-attitude deviation from level trim (deg).
    pub(crate) max_pitch_change_deg: f64,
    pub(crate) altitude_lost_m: f64,
}

/// A flown sink-rate run: the rows recorded every 10 ms and the report.
pub(crate) struct SinkRun {
    /// The recorded rows.
    pub(crate) rows: Vec<Row>,
    /// The summary, as in `summary.json`.
    pub(crate) report: SinkReport,
}

/// How the run ended, in words: "settled (±2 %) 12.54 s after the command", "diverged at
/// t = 2.008 s".
pub(crate) fn outcome_text(run: &SinkRun) -> String {
    let report = &run.report;
    let end_s = run.rows.last().map_or(f64::NAN, |r| r.time_s);
    match (&report.metrics, report.outcome) {
        (_, "diverged") => format!("diverged at t = {end_s:.3} s"),
        (Some(m), _) => match (m.settled, m.settling_time_s) {
            (true, Some(t)) => format!("settled (±2 %) {t:.2} s after the command"),
            _ => format!(
                "not settled: {}",
                m.not_settled_reason.as_deref().unwrap_or("no reason given")
            ),
        },
        (None, outcome) => outcome.replace('_', " "),
    }
}
