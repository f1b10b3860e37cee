//! Progress of long work on stderr, whatever stdout is: a bar (or a spinner) on a
//! terminal, and where stderr is a pipe or a file a plain line at each tenth of the work
//! (or at each message of work of unknown length), so that a piped, logged or `--json`
//! run is never silent for minutes. Errors writing to stderr are ignored: a closed
//! stderr stops the lines, not the work.

use std::fmt::Write as _;
use std::io::{IsTerminal, Write as _};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressState, ProgressStyle};

/// Progress on stderr (module docs).
pub struct Progress {
    bar: ProgressBar,
    lines: Option<Lines>,
}

/// The plain lines of a stderr that is not a terminal.
struct Lines {
    /// What the work is, first on each line (`campaign`, `rare`).
    label: &'static str,
    /// Its size in units, if known.
    total: Option<u64>,
    /// The unit counted (`runs`).
    unit: &'static str,
    done: AtomicU64,
    /// The last tenth reported (0 before any).
    tenth: AtomicU64,
    started: Instant,
}

impl Progress {
    /// Work of `total` `unit`s (`runs`) labelled `label`: a bar on a terminal, a line at
    /// each tenth elsewhere.
    pub fn counted(label: &'static str, total: u64, unit: &'static str) -> Self {
        if !std::io::stderr().is_terminal() {
            return Self::lines(label, Some(total), unit);
        }
        let bar = ProgressBar::with_draw_target(Some(total), ProgressDrawTarget::stderr());
        let template = format!(
            "{{elapsed_precise}} [{{bar:40}}] {{pos}}/{{len}} {unit}, {{rate}}, ETA {{eta}}"
        );
        let style = ProgressStyle::with_template(&template)
            .map(|s| {
                s.progress_chars("=> ").with_key(
                    "rate",
                    move |state: &ProgressState, w: &mut dyn std::fmt::Write| {
                        let _ = write!(w, "{:.0} {unit}/s", state.per_sec());
                    },
                )
            })
            .unwrap_or_else(|_| ProgressStyle::default_bar());
        bar.set_style(style);
        Self { bar, lines: None }
    }

    /// Work of unknown length labelled `label`: a spinner with the latest message on a
    /// terminal, each message as a line elsewhere.
    pub fn spinner(label: &'static str) -> Self {
        if !std::io::stderr().is_terminal() {
            return Self::lines(label, None, "");
        }
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        if let Ok(style) = ProgressStyle::with_template("{elapsed_precise} {spinner} {msg}") {
            bar.set_style(style);
        }
        bar.enable_steady_tick(std::time::Duration::from_millis(200));
        Self { bar, lines: None }
    }

    fn lines(label: &'static str, total: Option<u64>, unit: &'static str) -> Self {
        Self {
            bar: ProgressBar::with_draw_target(total, ProgressDrawTarget::hidden()),
            lines: Some(Lines {
                label,
                total,
                unit,
                done: AtomicU64::new(0),
                tenth: AtomicU64::new(0),
                started: Instant::now(),
            }),
        }
    }

    /// `n` more units done (from any thread).
    pub fn inc(&self, n: u64) {
        self.bar.inc(n);
        if let Some(lines) = &self.lines {
            lines.inc(n);
        }
    }

    /// The latest news of work of unknown length.
    pub fn message(&self, text: String) {
        match &self.lines {
            Some(lines) => line(&format!("{}: {text}", lines.label)),
            None => self.bar.set_message(text),
        }
    }

    /// Clears the bar (the lines stay, as a log).
    pub fn finish_and_clear(&self) {
        self.bar.finish_and_clear();
    }
}

impl Lines {
    /// Counts `n` units and writes a line when the count enters a new tenth of the
    /// total (each tenth once, whichever thread gets there first).
    fn inc(&self, n: u64) {
        let done = self.done.fetch_add(n, Ordering::Relaxed) + n;
        let Some(total) = self.total.filter(|&t| t > 0) else {
            return;
        };
        let tenth = (done.min(total) * 10 / total).min(10);
        let reported = self.tenth.fetch_max(tenth, Ordering::Relaxed);
        if tenth > reported {
            let elapsed_s = self.started.elapsed().as_secs_f64();
            let mut text = format!(
                "{}: {done}/{total} {} ({} %), {elapsed_s:.0} s",
                self.label,
                self.unit,
                tenth * 10
            );
            if done < total && done > 0 {
                let _ = write!(
                    text,
                    ", about {:.0} s to go",
                    elapsed_s * (total - done) as f64 / done as f64
                );
            }
            line(&text);
        }
    }
}

/// One line on stderr; a failed write is ignored (module docs).
fn line(text: &str) {
    let _ = writeln!(std::io::stderr().lock(), "{text}");
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each tenth is reported once, however the units arrive: 25 runs in steps of 1
    /// cross the tenths at 3, 5, 8, 10, 13, 15, 18, 20, 23 and 25 runs.
    #[test]
    fn each_tenth_is_reported_once() {
        let progress = Progress::lines("campaign", Some(25), "runs");
        let lines = progress.lines.as_ref().expect("lines");
        let mut crossed = Vec::new();
        for run in 1..=25 {
            let before = lines.tenth.load(Ordering::Relaxed);
            progress.inc(1);
            if lines.tenth.load(Ordering::Relaxed) > before {
                crossed.push(run);
            }
        }
        assert_eq!(crossed, [3, 5, 8, 10, 13, 15, 18, 20, 23, 25]);
        progress.inc(5);
        assert_eq!(lines.tenth.load(Ordering::Relaxed), 10);
    }
}
