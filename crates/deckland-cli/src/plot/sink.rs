//! `sink_rate`: tracking a commanded sink rate (paper Fig. 13).

use deckland::experiments::SinkRateSample as Row;

use crate::commands::sink::report::{outcome_text, SinkRun};
use crate::plot::{Figure, Panel};

/// The sink-rate figure (paper Fig. 13): sink rate and command, error, altitude; the
/// title says how the command came in and how the run ended, the note why.
pub(crate) fn figure(run: &SinkRun) -> Figure {
    let report = &run.report;
    let rows = &run.rows;
    let points =
        |f: &dyn Fn(&Row) -> f64| rows.iter().map(|r| (r.time_s, f(r))).collect::<Vec<_>>();
    let command = if report.ramp_s > 0.0 {
        format!(
            "{} m/s ramped in over {} s",
            report.sink_rate_command_mps, report.ramp_s
        )
    } else {
        format!("{} m/s as a step", report.sink_rate_command_mps)
    };
    let title = format!(
        "Sink-rate command {command} (cf. paper Fig. 13) — {}, {}: {}",
        report.controller,
        report.conditions,
        outcome_text(run)
    );
    let mut sink = Panel::new("Sink rate", "time (s)", "sink rate (m/s, positive down)")
        .dashed_series("command", points(&|r| r.sink_rate_command_mps))
        .series("sink rate", points(&|r| r.sink_rate_mps));
    if let Some(reason) = &report.reason {
        sink = sink.note(format!("{}: {reason}", report.outcome));
    }
    Figure::new()
        .title(title)
        .panel(sink)
        .panel(
            Panel::new("Sink-rate error", "time (s)", "error (m/s)")
                .series("command − sink rate", points(&|r| r.sink_rate_error_mps))
                .reference_line("zero", 0.0),
        )
        .panel(
            Panel::new("Trajectory", "time (s)", "altitude (m)")
                .series("altitude", points(&|r| r.altitude_m)),
        )
}
