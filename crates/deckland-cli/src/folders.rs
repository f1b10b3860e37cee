//! The command line's result folders, written for another front end: the Python package
//! writes an approach's folder (`deckland run`'s) and a campaign's (`deckland campaign`'s
//! and `deckland merge`'s) through these functions, so that both front ends write the
//! same files — the data, the plots and `report.html` — from the same code.
//!
//! A folder is prepared as the command line prepares `--out`: created if missing, refused
//! if it holds files unless `force`, locked while it is written (the folder's manifest
//! names the command that wrote it), each file written whole or not at all.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::Result;
use deckland::experiments::ApproachRun;
use deckland::monte_carlo::RunsTable;
use deckland::rare::RareResult;
use deckland::scenario::Scenario;

use crate::commands::campaign::folder::{self, CampaignFolder};
use crate::commands::campaign::report::write_folder;
use crate::commands::land::{write_approach_folder, Flown};
use crate::output::OutputDir;
use crate::plot::options;

pub use crate::commands::campaign::folder::CampaignReport;
pub use crate::plot::options::{
    FigureOptions, DPI_RANGE, FONT_PT_RANGE, MIN_WIDTH_EMS, WIDTH_MM_RANGE,
};

/// Where a folder goes and how its figures are drawn.
#[derive(Debug, Clone, Copy)]
pub struct FolderRequest<'a> {
    /// The folder.
    pub out: &'a Path,
    /// Replace the results of an earlier command in it.
    pub force: bool,
    /// The figures' size and files (checked here).
    pub figures: FigureOptions,
}

/// The figure options are the process's (the command line sets them once); writers from
/// several threads of one process take turns, each with its own options.
static WRITING: Mutex<()> = Mutex::new(());

impl FolderRequest<'_> {
    /// Prepares the folder and runs `write` into it with the request's figure options.
    fn write(
        &self,
        command: &str,
        write: impl FnOnce(&OutputDir) -> Result<()>,
    ) -> Result<PathBuf> {
        let figures = self.figures.checked()?;
        let output = OutputDir::prepare(command, Some(self.out), self.force)?;
        let _turn = WRITING
            .lock()
            .unwrap_or_else(|poisoned| poisoned.into_inner());
        options::set(figures);
        let written = write(&output);
        options::set(FigureOptions::default());
        written?;
        Ok(output.path().to_path_buf())
    }
}

/// Writes the folder `deckland run` writes for a flown approach: `scenario.toml`,
/// `approach.csv`, `trap_sheet.csv`, `summary.json`, with `plots` the plots (without,
/// as `--no-plots`), with `acmi` `approach.acmi`, and `report.html`. `controller` is the pitch controller's label, `conditions`
/// the scenario's name (the file's name for a file). Returns the folder.
pub fn write_approach(
    request: &FolderRequest,
    run: &ApproachRun,
    scenario: &Scenario,
    controller: &str,
    conditions: &str,
    plots: bool,
    acmi: bool,
) -> Result<PathBuf> {
    let flown = Flown {
        scenario,
        controller,
        conditions,
    };
    request.write("run", |output| {
        write_approach_folder(run, &flown, output, plots, acmi)
    })
}

/// Writes the folder `deckland campaign` (or `merge`) writes: `scenario.toml`, `runs.csv`,
/// `runs.parquet`, `summary.json` (`report`), the plots and `report.html`. `scenario_toml`
/// is the scenario's text as the campaign wrote it (a merge's, its shards'), `table` the
/// runs table of `runs.csv`, its rows sorted by run and controller. Returns the folder.
pub fn write_campaign(
    request: &FolderRequest,
    scenario: &Scenario,
    scenario_toml: &str,
    report: &CampaignReport,
    table: &RunsTable,
) -> Result<PathBuf> {
    let contents = CampaignFolder {
        scenario,
        scenario_toml,
        table,
        report,
        title: folder::title(Path::new(&report.scenario_file), report),
    };
    request.write("campaign", |output| write_folder(&contents, output))
}

/// Writes the folder `deckland rare` writes for an estimate: `scenario.toml`,
/// `summary.json` (the result, `elapsed_s` and the folder), `levels.csv`, the levels'
/// plot, up to `save_flights` flights that reached the event (replayed, each in
/// `event_flights/NN` with its plots) and `report.html`. Returns the folder.
pub fn write_rare(
    request: &FolderRequest,
    scenario: &Scenario,
    result: &RareResult,
    save_flights: usize,
    elapsed_s: f64,
) -> Result<PathBuf> {
    request.write("rare", |output| {
        crate::commands::rare::write_outputs(scenario, result, output, save_flights, elapsed_s)
    })
}
