//! `deckland reproduce`: regenerates the paper's figures (Fig. 4, 6, 7, 8, 10–15) as PNG
//! and SVG and writes `REPORT.md`, which sets every number the paper states beside this
//! implementation's (GitHub issue 7).
//!
//! Every figure comes from the other commands' figure builders (`environment`, `step`,
//! `sink`, `land`) except Fig. 4 and Fig. 6, which no other command draws. The numbers
//! are measured here, in this run; the report's notes explain the large differences
//! (docs/model.md §2.3 and §8, `docs/paper-errata-and-assumptions.md`).

mod figures;
mod paper;
mod report;

use std::io::IsTerminal;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{anyhow, Context, Result};
use clap::Args;
use deckland::aircraft::{AerodynamicConfiguration, Aircraft};
use deckland::analysis::{
    identify_modes, linearize, open_loop_step_responses, trim, InputStep, LinearModel, Mode,
    OpenLoopSample, TrimPoint, TrimRequest,
};
use deckland::control::pitch::ObserverPdGains;
use deckland::experiments::{
    fly_approach, fly_pitch_step, fly_seeds, record_environment, EnvironmentRecord, OutcomeCounts,
    PitchStep, SinkRateTracking,
};
use deckland::scenario::{EnvironmentSection, HardwareSet, Scenario};
use deckland::simulation::RunSummary;
use indicatif::{ProgressBar, ProgressStyle};
use nalgebra::SMatrix;

use super::common::{Conditions, ControllerChoice};
use super::environment;
use super::land;
use super::sink;
use super::step::{self, ControllerResult, StepFlight};
use crate::output::OutputDir;
use crate::plot::Figure;

/// Options of `deckland reproduce`.
#[derive(Debug, Clone, Args)]
pub struct ReproduceArgs {
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

/// Lengths of the runs: the full report or the `--quick` one.
#[derive(Debug, Clone, Copy)]
pub(crate) struct RunLengths {
    /// Open-loop throttle step (s).
    pub(crate) open_loop_s: f64,
    /// Environment record (s).
    pub(crate) environment_s: f64,
    /// Sink-rate runs (s).
    pub(crate) sink_s: f64,
    /// Seeds of the boarding statistics (1..=N).
    pub(crate) boarding_seeds: u64,
    /// Seeds of the pitch-step studies behind the notes (1..=N).
    pub(crate) study_seeds: u64,
    /// Seeds of the environment records whose median peaks the notes give (1..=N).
    pub(crate) peak_seeds: u64,
}

impl RunLengths {
    fn new(quick: bool) -> Self {
        if quick {
            Self {
                open_loop_s: 20.0,
                environment_s: 20.0,
                sink_s: 16.0,
                boarding_seeds: 3,
                study_seeds: 2,
                peak_seeds: 3,
            }
        } else {
            Self {
                open_loop_s: 60.0,
                environment_s: 60.0,
                sink_s: 20.0,
                boarding_seeds: 50,
                study_seeds: 5,
                peak_seeds: 20,
            }
        }
    }
}

/// The throttle step of Fig. 6: 1 % of the total maximum thrust (about 1.4 kN). The paper
/// does not give its size; small enough for the linear model to hold.
pub(crate) const THROTTLE_STEP: f64 = 0.01;
/// Pitch step of Fig. 10–12 (deg); the paper does not give its size.
pub(crate) const PITCH_STEP_DEG: f64 = 2.0;
/// Length of the pitch-step runs (s), as `deckland step`'s default.
const PITCH_STEP_SECONDS: f64 = 6.0;
/// The paper's commanded sink rate (m/s, Fig. 13).
pub(crate) const SINK_RATE_MPS: f64 = 10.0;
/// Ramp of the sink-rate command that this plant can follow (s).
pub(crate) const SINK_RAMP_S: f64 = 5.0;
/// Seed of the single adverse runs.
pub(crate) const SEED: u64 = 1;
/// Distance aft of the ship's pitch centre where Fig. 8 samples the wind (m).
pub(crate) const WIND_DISTANCE_AFT_M: f64 = 400.0;

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

/// Everything the report measures.
pub(crate) struct Findings {
    pub(crate) quick: bool,
    pub(crate) lengths: RunLengths,
    pub(crate) aircraft: Aircraft,
    pub(crate) trim: TrimPoint,
    pub(crate) model: LinearModel,
    pub(crate) modes: Vec<Mode>,
    pub(crate) clean_trim: std::result::Result<TrimPoint, String>,
    pub(crate) paper_a_modes: Vec<Mode>,
    pub(crate) gains: ObserverPdGains,
    /// Worst |nonlinear − linear| over the throttle step, relative to the largest
    /// nonlinear excursion, per state.
    pub(crate) open_loop_relative_error: [f64; 4],
    pub(crate) open_loop_excursion: [f64; 4],
    pub(crate) environment: EnvironmentSection,
    pub(crate) heave_peak_m: f64,
    pub(crate) ship_pitch_peak_deg: f64,
    /// Peak |heave| of each environment record of seeds 1..=N (m).
    pub(crate) heave_peaks_m: Vec<f64>,
    /// Peak |ship pitch| of each environment record of seeds 1..=N (deg).
    pub(crate) pitch_peaks_deg: Vec<f64>,
    pub(crate) landing_point_peak_m: f64,
    pub(crate) wind_x_range_mps: (f64, f64),
    pub(crate) step_ideal: Vec<ControllerResult>,
    pub(crate) step_adverse: Vec<ControllerResult>,
    /// RMS of θ − target over the last second of the adverse O-PD step (deg).
    pub(crate) adverse_opd_tracking_rms_deg: f64,
    /// The adverse O-PD step without sensor noise, seeds 1..=N.
    pub(crate) adverse_opd_noiseless: Vec<ControllerResult>,
    /// The adverse PID step, seeds 1..=N.
    pub(crate) adverse_pid_seeds: Vec<ControllerResult>,
    pub(crate) sink_step: sink::SinkReport,
    pub(crate) sink_ramp: sink::SinkReport,
    pub(crate) approach: RunSummary,
    /// An approach with the paper's sink-rate and guidance gains: ideal, and adverse with
    /// seed [`SEED`].
    pub(crate) paper_gains_approaches: [RunSummary; 2],
    pub(crate) pitch_tracking_rms_deg: f64,
    pub(crate) boarded: usize,
    pub(crate) boarding_runs: usize,
    pub(crate) figures: Vec<WrittenFigure>,
}

impl Findings {
    /// The lag of the flight path behind pitch (s): 1/|∂α̇/∂α| of the linear model.
    pub(crate) fn flight_path_lag_s(&self) -> f64 {
        1.0 / self.model.a[(2, 2)].abs()
    }
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

/// Writes `figure` as `<stem>.png` and `.svg` and records it.
fn save(
    output: &OutputDir,
    written: &mut Vec<WrittenFigure>,
    figure: &Figure,
    stem: &'static str,
    paper_figure: &'static str,
    caption: String,
) -> Result<()> {
    let (_, svg) = figure.save_with_svg(output, stem)?;
    written.push(WrittenFigure {
        stem,
        paper_figure,
        caption,
        svg,
    });
    Ok(())
}

/// Picks the figure called `stem` from a builder's list.
fn pick(figures: &[(&'static str, Figure)], stem: &str) -> Result<Figure> {
    figures
        .iter()
        .find(|(name, _)| *name == stem)
        .map(|(_, figure)| figure.clone())
        .ok_or_else(|| anyhow!("the figure builder made no `{stem}` figure"))
}

/// The hardware every run of the reproduction flies: the paper's.
const HARDWARE: HardwareSet = HardwareSet::Paper;

/// The paper's scenario in `conditions` with `seed`, flying `choice`.
fn paper_scenario(conditions: Conditions, seed: u64, choice: ControllerChoice) -> Scenario {
    let mut scenario = conditions.scenario(HARDWARE, seed);
    scenario.control.pitch = choice.parameters(HARDWARE);
    scenario
}

/// The pitch step of Fig. 10–12 in `conditions`.
fn step_flight(conditions: Conditions) -> StepFlight {
    StepFlight {
        base: HARDWARE.scenario(),
        conditions,
        seed: SEED,
        step: PitchStep::new(PITCH_STEP_DEG, PITCH_STEP_SECONDS),
        epsilon: None,
    }
}

/// The sink-rate command of Fig. 13, ramped in over `ramp_s`.
fn sink_tracking(ramp_s: f64, seconds: f64) -> SinkRateTracking {
    SinkRateTracking {
        sink_rate_mps: SINK_RATE_MPS,
        ramp_s,
        seconds,
    }
}

/// RMS of θ − θ_ref over the last second of a pitch-step run (deg).
fn last_second_rms_deg(samples: &[deckland::simulation::Signals]) -> f64 {
    let end_s = samples.last().map_or(0.0, |s| s.time_s);
    let errors: Vec<f64> = samples
        .iter()
        .filter(|s| s.time_s >= end_s - 1.0)
        .map(|s| (s.theta_rad - s.theta_ref_rad).to_degrees())
        .collect();
    let n = errors.len().max(1) as f64;
    (errors.iter().map(|e| e * e).sum::<f64>() / n).sqrt()
}

/// The adverse pitch step of Fig. 11 with `choice` over `seeds`, without the pitch
/// sensor's noise if `noiseless`.
fn step_study(
    choice: ControllerChoice,
    seeds: &[u64],
    noiseless: bool,
) -> Result<Vec<ControllerResult>> {
    seeds
        .iter()
        .map(|&seed| {
            let mut scenario = paper_scenario(Conditions::Adverse, seed, choice);
            if noiseless {
                scenario.environment.pitch_noise.enabled = false;
            }
            let step = PitchStep::new(PITCH_STEP_DEG, PITCH_STEP_SECONDS);
            Ok(fly_pitch_step(&scenario, &step)
                .with_context(|| format!("cannot fly the {} step of seed {seed}", choice.label()))?
                .response)
        })
        .collect()
}

/// Worst relative error and largest excursion of each state over the open-loop step.
fn open_loop_agreement(samples: &[OpenLoopSample]) -> ([f64; 4], [f64; 4]) {
    let mut error = [0.0_f64; 4];
    let mut excursion = [0.0_f64; 4];
    for sample in samples {
        for i in 0..4 {
            error[i] = error[i].max((sample.nonlinear[i] - sample.linear[i]).abs());
            excursion[i] = excursion[i].max(sample.nonlinear[i].abs());
        }
    }
    let relative = std::array::from_fn(|i| {
        if excursion[i] > 0.0 {
            error[i] / excursion[i]
        } else {
            0.0
        }
    });
    (relative, excursion)
}

/// Runs the command.
pub fn run(args: &ReproduceArgs) -> Result<()> {
    let started = Instant::now();
    let lengths = RunLengths::new(args.quick);
    let output = OutputDir::prepare("reproduce", args.out.as_deref(), args.force)?;
    let mut progress = Progress::new(STEPS);
    let mut written = Vec::new();

    // Trim, linearisation, gains (Table 3, Eq. 14, §4.2.2).
    progress.start("trim and linearisation (Table 3, Eq. 14)");
    let aircraft = Aircraft::default();
    let trim_point =
        trim(&aircraft, &TrimRequest::default()).context("cannot trim the landing aircraft")?;
    let model = linearize(&aircraft, &trim_point);
    let modes = identify_modes(&model.eigenvalues());
    let clean_trim = trim(
        &Aircraft::with_configuration(AerodynamicConfiguration::CLEAN),
        &TrimRequest::default(),
    )
    .map_err(|e| e.to_string());
    let paper_a = SMatrix::<f64, 4, 4>::from_fn(|i, j| paper::PAPER_A[i][j]);
    let paper_a_modes = identify_modes(
        &paper_a
            .complex_eigenvalues()
            .iter()
            .copied()
            .collect::<Vec<_>>(),
    );
    let opd = deckland::control::pitch::ObserverPdParameters::paper();
    let gains = ObserverPdGains::design(
        opd.settling_time_s,
        opd.damping_ratio,
        model.pitch_damping_per_s(),
    )
    .context("cannot design the O-PD gains")?;

    // Fig. 4.
    progress.start("Fig. 4 aerodynamic coefficients");
    save(
        &output,
        &mut written,
        &figures::aerodynamic_coefficients_figure(),
        "fig04_aerodynamic_coefficients",
        "Fig. 4",
        "C_L, C_D, C_m against α at δe = q = 0, clean data and the landing configuration"
            .to_string(),
    )?;

    // Fig. 6.
    progress.start("Fig. 6 nonlinear against linear throttle step");
    let step = InputStep {
        elevator_rad: 0.0,
        throttle: THROTTLE_STEP,
    };
    let (_, samples) = open_loop_step_responses(
        &aircraft,
        &trim_point,
        step,
        lengths.open_loop_s,
        0.001,
        0.05,
    )
    .context("cannot fly the open-loop throttle step")?;
    let (open_loop_relative_error, open_loop_excursion) = open_loop_agreement(&samples);
    save(
        &output,
        &mut written,
        &figures::open_loop_step(&samples, THROTTLE_STEP, &aircraft),
        "fig06_throttle_step",
        "Fig. 6",
        format!(
            "open-loop throttle step of {:.0} % of the total maximum thrust from level trim: \
             nonlinear airframe against the linear model of Eq. 14 (ours)",
            THROTTLE_STEP * 100.0
        ),
    )?;

    // Fig. 7, 8.
    progress.start("Fig. 7, 8 ship motion and wind");
    let environment_parameters = HARDWARE.scenario().environment;
    environment_parameters.validate()?;
    let environment_record = EnvironmentRecord {
        seconds: lengths.environment_s,
        seed: SEED,
        distance_aft_m: WIND_DISTANCE_AFT_M,
        airspeed_mps: trim_point.speed_mps,
    };
    let rows = record_environment(&environment_parameters, &environment_record)?;
    let peak = |f: &dyn Fn(&environment::Row) -> f64| {
        rows.iter().map(|r| f(r).abs()).fold(0.0_f64, f64::max)
    };
    let heave_peak_m = peak(&|r| r.heave_m);
    let ship_pitch_peak_deg = peak(&|r| r.pitch_deg);
    let landing_point_peak_m = peak(&|r| r.landing_point_height_m);
    let wind_x_range_mps = rows
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), r| {
            (lo.min(r.wind_x_mps), hi.max(r.wind_x_mps))
        });
    let mut heave_peaks_m = Vec::new();
    let mut pitch_peaks_deg = Vec::new();
    for seed in 1..=lengths.peak_seeds {
        let record = EnvironmentRecord {
            seed,
            ..environment_record
        };
        let rows = record_environment(&environment_parameters, &record)?;
        let peak = |f: &dyn Fn(&environment::Row) -> f64| {
            rows.iter().map(|r| f(r).abs()).fold(0.0_f64, f64::max)
        };
        heave_peaks_m.push(peak(&|r| r.heave_m));
        pitch_peaks_deg.push(peak(&|r| r.pitch_deg));
    }
    let environment_figures =
        environment::figures(&rows, &environment_record, &environment_parameters);
    save(
        &output,
        &mut written,
        &pick(&environment_figures, "landing_point_motion")?,
        "fig07_landing_point_motion",
        "Fig. 7",
        format!(
            "vertical motion of the landing point 81 m aft of the pitch centre, {} s, seed {SEED}",
            lengths.environment_s
        ),
    )?;
    save(
        &output,
        &mut written,
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
    let both = [ControllerChoice::Opd, ControllerChoice::Pid];
    let ideal_flight = step_flight(Conditions::Ideal);
    let ideal_runs = ideal_flight.fly(&both)?;
    let ideal_figures = step::figures(&ideal_runs, &ideal_flight);
    save(
        &output,
        &mut written,
        &pick(&ideal_figures, "step_pitch")?,
        "fig10_pitch_step_ideal",
        "Fig. 10",
        format!("{PITCH_STEP_DEG}° pitch step without noise or wind, O-PD and PID"),
    )?;
    progress.start("Fig. 11, 12 pitch step, adverse");
    let adverse_flight = step_flight(Conditions::Adverse);
    let adverse_runs = adverse_flight.fly(&both)?;
    let adverse_figures = step::figures(&adverse_runs, &adverse_flight);
    let adverse_opd_tracking_rms_deg = adverse_runs
        .first()
        .map_or(f64::NAN, |run| last_second_rms_deg(&run.samples));
    let study_seeds: Vec<u64> = (1..=lengths.study_seeds).collect();
    let adverse_opd_noiseless = step_study(ControllerChoice::Opd, &study_seeds, true)?;
    let adverse_pid_seeds = step_study(ControllerChoice::Pid, &study_seeds, false)?;
    save(
        &output,
        &mut written,
        &pick(&adverse_figures, "step_pitch")?,
        "fig11_pitch_step_adverse",
        "Fig. 11",
        format!("{PITCH_STEP_DEG}° pitch step with noise and wind, seed {SEED}, O-PD and PID"),
    )?;
    save(
        &output,
        &mut written,
        &pick(&adverse_figures, "step_elevator")?,
        "fig12_elevator_adverse",
        "Fig. 12",
        format!("elevator during the adverse {PITCH_STEP_DEG}° step, seed {SEED}"),
    )?;

    // Fig. 13.
    progress.start("Fig. 13 sink-rate tracking");
    let fly_sink = |ramp_s| {
        sink::fly_tracking(
            &HARDWARE.scenario(),
            ControllerChoice::Opd,
            Conditions::Ideal,
            SEED,
            &sink_tracking(ramp_s, lengths.sink_s),
        )
    };
    let sink_step_run = fly_sink(0.0)?;
    let sink_ramp_run = fly_sink(SINK_RAMP_S)?;
    save(
        &output,
        &mut written,
        &sink::figure(&sink_ramp_run),
        "fig13_sink_rate",
        "Fig. 13",
        format!(
            "constant sink-rate command of {SINK_RATE_MPS} m/s ramped in over {SINK_RAMP_S} s, \
             O-PD, ideal conditions"
        ),
    )?;
    save(
        &output,
        &mut written,
        &sink::figure(&sink_step_run),
        "fig13_sink_rate_step",
        "Fig. 13",
        format!(
            "the paper's step of {SINK_RATE_MPS} m/s: α leaves the model's range and the run \
             stops"
        ),
    )?;

    // Fig. 14, 15.
    progress.start("Fig. 14, 15 approach and landing");
    let scenario = paper_scenario(Conditions::Adverse, SEED, ControllerChoice::Opd);
    let approach_run = fly_approach(&scenario).context("cannot set up the approach")?;
    let approach = approach_run.summary.clone();
    let approach_samples = &approach_run.samples;
    let pitch_tracking_rms_deg = {
        let n = approach_samples.len().max(1) as f64;
        (approach_samples
            .iter()
            .map(|s| (s.theta_rad - s.theta_ref_rad).to_degrees().powi(2))
            .sum::<f64>()
            / n)
            .sqrt()
    };
    let fly_paper_gains = |conditions: Conditions| -> Result<RunSummary> {
        let mut scenario = paper_scenario(conditions, SEED, ControllerChoice::Opd);
        (
            scenario.control.sink_rate.proportional_rad_per_mps,
            scenario.control.sink_rate.integral_rad_per_m,
        ) = paper::PAPER_SINK_GAINS;
        (
            scenario.control.guidance.proportional_per_s,
            scenario.control.guidance.integral_per_s2,
            scenario.control.guidance.derivative,
        ) = paper::PAPER_GUIDANCE_GAINS;
        Ok(fly_approach(&scenario)
            .context("cannot fly the approach with the paper's gains")?
            .summary)
    };
    let paper_gains_approaches = [
        fly_paper_gains(Conditions::Ideal)?,
        fly_paper_gains(Conditions::Adverse)?,
    ];
    let title = format!("O-PD, adverse, seed {SEED}");
    let approach_figures = land::figures(&approach_run, &scenario, &title);
    save(
        &output,
        &mut written,
        &pick(&approach_figures, "glide_path_error")?,
        "fig14_glide_path_error",
        "Fig. 14",
        format!("position error to the ideal glide path, adverse conditions, seed {SEED}"),
    )?;
    save(
        &output,
        &mut written,
        &pick(&approach_figures, "pitch")?,
        "fig15_pitch_approach",
        "Fig. 15",
        format!("pitch and pitch command on the approach, adverse conditions, seed {SEED}"),
    )?;
    save(
        &output,
        &mut written,
        &pick(&approach_figures, "altitude")?,
        "approach_altitude",
        "—",
        format!("hook height against the glide path and the moving deck, seed {SEED}"),
    )?;

    // Boarding statistics (not in the paper).
    progress.start("boarding statistics");
    let base = paper_scenario(Conditions::Adverse, SEED, ControllerChoice::Opd);
    let seeds: Vec<u64> = (1..=lengths.boarding_seeds).collect();
    let boarding = OutcomeCounts::of(
        &fly_seeds(&base, &seeds).context("cannot set up the boarding statistics")?,
    );
    let boarded = boarding.trap;

    progress.start("REPORT.md");
    let findings = Findings {
        quick: args.quick,
        lengths,
        aircraft,
        trim: trim_point,
        model,
        modes,
        clean_trim,
        paper_a_modes,
        gains,
        open_loop_relative_error,
        open_loop_excursion,
        environment: environment_parameters,
        heave_peak_m,
        ship_pitch_peak_deg,
        heave_peaks_m,
        pitch_peaks_deg,
        landing_point_peak_m,
        wind_x_range_mps,
        step_ideal: ideal_runs.into_iter().map(|r| r.result).collect(),
        step_adverse: adverse_runs.into_iter().map(|r| r.result).collect(),
        adverse_opd_tracking_rms_deg,
        adverse_opd_noiseless,
        adverse_pid_seeds,
        sink_step: sink_step_run.report,
        sink_ramp: sink_ramp_run.report,
        approach,
        paper_gains_approaches,
        pitch_tracking_rms_deg,
        boarded,
        boarding_runs: usize::try_from(lengths.boarding_seeds).unwrap_or(usize::MAX),
        figures: written,
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
