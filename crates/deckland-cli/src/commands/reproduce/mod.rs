//! `deckland reproduce`: regenerates the paper's figures (Fig. 4, 6, 7, 8, 10–15) as PNG
//! and SVG and writes `REPORT.md`, which sets every number the paper states beside this
//! implementation's (GitHub issue 7).
//!
//! The studies are the library's (`deckland::experiments::reproduction`); this command
//! flies them in turn, draws their figures with the other commands' figure builders
//! (`environment`, `step`, `sink`, `land`; Fig. 4 and Fig. 6, which no other command
//! draws, in [`figures`]) and formats the report. The report's notes explain the large
//! differences (docs/model.md §2.3 and §8, `docs/paper-errata-and-assumptions.md`).

mod figures;
mod report;

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{anyhow, Result};
use clap::Args;
use deckland::experiments::reproduction::{
    study_adverse_pitch_step, study_approach, study_boarding, study_environment,
    study_ideal_pitch_step, study_linear_model, study_open_loop, study_sink_rate, Reproduction,
    ReproductionLengths, SinkRateStudy, HARDWARE, PITCH_STEP_DEG, PITCH_STEP_SECONDS, SEED,
    SINK_RAMP_S, SINK_RATE_MPS,
};
use deckland::experiments::{PitchStep, PitchStepRun, SinkRateRun};
use indicatif::{ProgressBar, ProgressStyle};

use super::common::{Conditions, ControllerChoice};
use super::environment;
use super::land;
use super::sink;
use super::step;
use super::step::flight::{ControllerRun, StepFlight};
use crate::output::OutputDir;
use crate::plot::Figure;

/// Options of `deckland reproduce`.
#[derive(Debug, Clone, Args)]
pub struct ReproduceArgs {
    /// Figure size on paper, text size, PNG resolution and PDF.
    #[command(flatten)]
    pub figures: crate::plot::FigureArgs,
    /// Output folder (default: a new `runs/reproduce-<UTC time>`).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Overwrite results in an existing `--out` folder.
    #[arg(long)]
    pub force: bool,
    /// Shorter records and fewer seeds (for tests): the figures and the table keep their
    /// shape, some numbers change (the report says which run it is).
    #[arg(long)]
    pub quick: bool,
}

/// A figure written by the report, with what it reproduces.
#[derive(Debug, Clone)]
pub(crate) struct WrittenFigure {
    /// File stem (`<stem>.png`, `<stem>.svg`).
    pub(crate) stem: &'static str,
    /// The paper's figure it corresponds to ("Fig. 7"), or "—" for an extra one.
    pub(crate) paper_figure: &'static str,
    /// One line on what it shows.
    pub(crate) caption: String,
    /// The SVG document, for `report.html`.
    pub(crate) svg: String,
}

impl WrittenFigure {
    /// The heading of its entry: the paper's figure, or "Extra".
    pub(crate) fn heading(&self) -> &'static str {
        if self.paper_figure == "—" {
            "Extra"
        } else {
            self.paper_figure
        }
    }
}

/// What the report formats: the library's studies and the figures drawn from them.
pub(crate) struct Findings {
    /// Whether this is a `--quick` run.
    pub(crate) quick: bool,
    /// Every study, as measured in this run.
    pub(crate) reproduction: Reproduction,
    /// The figures written, in the report's order.
    pub(crate) figures: Vec<WrittenFigure>,
}

/// Progress over the report's steps: a bar on a terminal, one line per step otherwise,
/// both on stderr.
struct Progress {
    bar: Option<ProgressBar>,
    total: usize,
    done: usize,
}

impl Progress {
    fn new(total: usize) -> Self {
        let bar = std::io::stderr().is_terminal().then(|| {
            let bar = ProgressBar::new(total as u64);
            if let Ok(style) =
                ProgressStyle::with_template("{elapsed_precise} [{bar:30}] {pos}/{len} {msg}")
            {
                bar.set_style(style.progress_chars("=> "));
            }
            bar
        });
        Self {
            bar,
            total,
            done: 0,
        }
    }

    /// Announces the next step.
    fn start(&mut self, what: &str) {
        match &self.bar {
            Some(bar) => {
                bar.set_position(self.done as u64);
                bar.set_message(what.to_string());
            }
            None => warnln!("[{}/{}] {what}", self.done + 1, self.total),
        }
        self.done += 1;
    }

    fn finish(&self) {
        if let Some(bar) = &self.bar {
            bar.set_position(self.total as u64);
            bar.finish_and_clear();
        }
    }
}

/// The steps announced to the progress display.
const STEPS: usize = 10;

/// The figures written so far, in the report's order.
struct Figures<'a> {
    output: &'a OutputDir,
    written: Vec<WrittenFigure>,
}

impl Figures<'_> {
    /// Writes `figure` as `<stem>.png` and `.svg` and records it.
    fn save(
        &mut self,
        figure: &Figure,
        stem: &'static str,
        paper_figure: &'static str,
        caption: String,
    ) -> Result<()> {
        let (_, svg) = figure.save_with_svg(self.output, stem)?;
        self.written.push(WrittenFigure {
            stem,
            paper_figure,
            caption,
            svg,
        });
        Ok(())
    }
}

/// Picks the figure called `stem` from a builder's list.
fn pick(figures: &[(&'static str, Figure)], stem: &str) -> Result<Figure> {
    figures
        .iter()
        .find(|(name, _)| *name == stem)
        .map(|(_, figure)| figure.clone())
        .ok_or_else(|| anyhow!("the figure builder made no `{stem}` figure"))
}

/// The pitch step of Fig. 10–12 in `conditions`, as `deckland step` describes it.
fn step_flight(conditions: Conditions) -> StepFlight {
    StepFlight {
        base: HARDWARE.scenario(),
        conditions,
        seed: SEED,
        step: PitchStep::new(PITCH_STEP_DEG, PITCH_STEP_SECONDS),
        epsilon: None,
    }
}

/// The O-PD's and the PID's runs of a pitch step, as `deckland step` draws them.
fn controller_runs(runs: &[PitchStepRun; 2]) -> Vec<ControllerRun> {
    [ControllerChoice::Opd, ControllerChoice::Pid]
        .into_iter()
        .zip(runs)
        .map(|(choice, run)| ControllerRun {
            choice,
            samples: run.samples.clone(),
            result: run.response.clone(),
        })
        .collect()
}

/// A sink-rate run of the study ramped in over `ramp_s`, as `deckland sink` draws it.
fn sink_run(run: &SinkRateRun, ramp_s: f64, seconds: f64) -> sink::report::SinkRun {
    sink::sink_run(
        run.clone(),
        ControllerChoice::Opd,
        Conditions::Ideal,
        SEED,
        &SinkRateStudy::tracking(ramp_s, seconds),
    )
}

/// Runs the command.
pub fn run(args: &ReproduceArgs) -> Result<()> {
    let started = Instant::now();
    let lengths = if args.quick {
        ReproductionLengths::quick()
    } else {
        ReproductionLengths::full()
    };
    let output = OutputDir::prepare("reproduce", args.out.as_deref(), args.force)?;
    let mut progress = Progress::new(STEPS);
    let mut drawn = Figures {
        output: &output,
        written: Vec::new(),
    };

    // Trim, linearisation, gains (Table 3, Eq. 14, §4.2.2).
    progress.start("trim and linearisation (Table 3, Eq. 14)");
    let linear_model = study_linear_model()?;

    // Fig. 4.
    progress.start("Fig. 4 aerodynamic coefficients");
    drawn.save(
        &figures::aerodynamic_coefficients_figure(),
        "fig04_aerodynamic_coefficients",
        "Fig. 4",
        "C_L, C_D, C_m against α at δe = q = 0, clean data and the landing configuration"
            .to_string(),
    )?;

    // Fig. 6.
    progress.start("Fig. 6 nonlinear against linear throttle step");
    let open_loop = study_open_loop(&linear_model, lengths.open_loop_s)?;
    drawn.save(
        &figures::open_loop_step(
            &open_loop.samples,
            open_loop.throttle_step,
            &linear_model.aircraft,
        ),
        "fig06_throttle_step",
        "Fig. 6",
        format!(
            "open-loop throttle step of {:.0} % of the total maximum thrust from level trim: \
             nonlinear airframe against the linear model of Eq. 14 (ours)",
            open_loop.throttle_step * 100.0
        ),
    )?;

    // Fig. 7, 8.
    progress.start("Fig. 7, 8 ship motion and wind");
    let environment_study = study_environment(&linear_model.trim, &lengths)?;
    let environment_figures = environment::figures(
        &environment_study.samples,
        &environment_study.record,
        &environment_study.parameters,
    );
    drawn.save(
        &pick(&environment_figures, "landing_point_motion")?,
        "fig07_landing_point_motion",
        "Fig. 7",
        format!(
            "vertical motion of the landing point 81 m aft of the pitch centre, {} s, seed {SEED}",
            lengths.environment_s
        ),
    )?;
    drawn.save(
        &pick(&environment_figures, "wind_x")?,
        "fig08_wind_x_400m",
        "Fig. 8",
        format!(
            "x-axis wind 400 m aft of the ship's pitch centre, {} s, seed {SEED}",
            lengths.environment_s
        ),
    )?;

    // Fig. 10–12.
    progress.start("Fig. 10 pitch step, ideal");
    let ideal_pitch_step = study_ideal_pitch_step()?;
    let ideal_figures = step::figures(
        &controller_runs(&ideal_pitch_step),
        &step_flight(Conditions::Ideal),
    );
    drawn.save(
        &pick(&ideal_figures, "step_pitch")?,
        "fig10_pitch_step_ideal",
        "Fig. 10",
        format!("{PITCH_STEP_DEG}° pitch step without noise or wind, O-PD and PID"),
    )?;
    progress.start("Fig. 11, 12 pitch step, adverse");
    let adverse_pitch_step = study_adverse_pitch_step(lengths.study_seeds)?;
    let adverse_figures = step::figures(
        &controller_runs(&adverse_pitch_step.runs),
        &step_flight(Conditions::Adverse),
    );
    drawn.save(
        &pick(&adverse_figures, "step_pitch")?,
        "fig11_pitch_step_adverse",
        "Fig. 11",
        format!("{PITCH_STEP_DEG}° pitch step with noise and wind, seed {SEED}, O-PD and PID"),
    )?;
    drawn.save(
        &pick(&adverse_figures, "step_elevator")?,
        "fig12_elevator_adverse",
        "Fig. 12",
        format!("elevator during the adverse {PITCH_STEP_DEG}° step, seed {SEED}"),
    )?;

    // Fig. 13.
    progress.start("Fig. 13 sink-rate tracking");
    let sink_rate = study_sink_rate(lengths.sink_s)?;
    drawn.save(
        &sink::figure(&sink_run(&sink_rate.ramp, SINK_RAMP_S, lengths.sink_s)),
        "fig13_sink_rate",
        "Fig. 13",
        format!(
            "constant sink-rate command of {SINK_RATE_MPS} m/s ramped in over {SINK_RAMP_S} s, \
             O-PD, ideal conditions"
        ),
    )?;
    drawn.save(
        &sink::figure(&sink_run(&sink_rate.step, 0.0, lengths.sink_s)),
        "fig13_sink_rate_step",
        "Fig. 13",
        format!(
            "the paper's step of {SINK_RATE_MPS} m/s: α leaves the model's range and the run \
             stops"
        ),
    )?;

    // Fig. 14, 15.
    progress.start("Fig. 14, 15 approach and landing");
    let approach = study_approach()?;
    let title = format!("O-PD, adverse, seed {SEED}");
    let approach_figures = land::figures(&approach.run, &approach.scenario, &title);
    drawn.save(
        &pick(&approach_figures, "glide_path_error")?,
        "fig14_glide_path_error",
        "Fig. 14",
        format!("position error to the ideal glide path, adverse conditions, seed {SEED}"),
    )?;
    drawn.save(
        &pick(&approach_figures, "pitch")?,
        "fig15_pitch_approach",
        "Fig. 15",
        format!("pitch and pitch command on the approach, adverse conditions, seed {SEED}"),
    )?;
    drawn.save(
        &pick(&approach_figures, "altitude")?,
        "approach_altitude",
        "—",
        format!("hook height against the glide path and the moving deck, seed {SEED}"),
    )?;

    // Boarding statistics (not in the paper).
    progress.start("boarding statistics");
    let boarding = study_boarding(lengths.boarding_seeds)?;

    progress.start("REPORT.md");
    let findings = Findings {
        quick: args.quick,
        reproduction: Reproduction {
            lengths,
            linear_model,
            open_loop,
            environment: environment_study,
            ideal_pitch_step,
            adverse_pitch_step,
            sink_rate,
            approach,
            boarding,
        },
        figures: drawn.written,
    };
    let sections = report::sections(&findings);
    output.write_bytes(
        "REPORT.md",
        report::markdown(&findings, &sections).as_bytes(),
    )?;
    output.write_bytes("report.html", report::html(&findings, &sections).as_bytes())?;
    progress.finish();

    let rows: usize = sections.iter().map(|s| s.rows.len()).sum();
    outln!(
        "Reproduced {} figures and a table of {rows} numbers in {:.1} s{}",
        findings.figures.len(),
        started.elapsed().as_secs_f64(),
        if args.quick { " (quick run)" } else { "" }
    )?;
    outln!(
        "  report                {}",
        output.path().join("REPORT.md").display()
    )?;
    outln!(
        "  the same as one page  {}",
        output.path().join("report.html").display()
    )?;
    Ok(())
}
