//! Ctrl-C and SIGTERM (and SIGHUP): handled alike, so that a run stopped either way
//! leaves no temporary file behind.
//!
//! By default the first signal removes the temporary files of the writes in progress
//! and exits with status 130. A command that can stop cleanly (a campaign, which writes
//! its finished runs) asks for [`graceful_stop`] instead: the first signal only sets the
//! flag it returns, a second one exits at once (after the same clean-up).
//!
//! There is no window in which a temporary file can be left. The signal handler takes
//! the lock of the list of temporary files, removes every file on the list and exits
//! *without releasing it*; every temporary file is created and renamed into place (or
//! removed) while holding that lock. A file written through its handle
//! ([`create_temporary_file`], [`finish_temporary_file`]) is on the list from its
//! creation to its renaming, so it is either removed by the handler or not yet created
//! (and never will be: its creation waits for the lock until the process has exited);
//! writing on after the handler removed it only fills an unlinked file. A file that a
//! writer opens by its path ([`write_by_path`]: plots, Parquet, CSV writers) is written
//! wholly under the lock, because such a writer could re-create the file after the
//! handler removed it: a signal meanwhile waits for that one file to be renamed into
//! place, then exits.

use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard, PoisonError};

/// Exit status after an interrupt (128 + SIGINT, as shells report Ctrl-C).
pub const INTERRUPTED_STATUS: i32 = 130;

/// Set by the first signal when the command stops gracefully.
static STOP: AtomicBool = AtomicBool::new(false);
/// Whether the command stops gracefully (the first signal only sets [`STOP`]).
static GRACEFUL: AtomicBool = AtomicBool::new(false);
/// The temporary files that exist now (created and not yet renamed or removed).
static TEMPORARY_FILES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The list of temporary files, locked (a poisoned lock still guards a valid list).
fn temporary_files() -> MutexGuard<'static, Vec<PathBuf>> {
    TEMPORARY_FILES
        .lock()
        .unwrap_or_else(PoisonError::into_inner)
}

/// Installs the handler of SIGINT, SIGTERM and SIGHUP. A failure is reported and
/// otherwise ignored: the command runs, with the default signal handling.
pub fn install() {
    if let Err(error) = ctrlc::set_handler(on_signal) {
        warnln!("warning: Ctrl-C and SIGTERM will not stop cleanly: {error}");
    }
}

fn on_signal() {
    let already_stopping = STOP.swap(true, Ordering::SeqCst);
    if GRACEFUL.load(Ordering::SeqCst) && !already_stopping {
        return;
    }
    // Held until the process ends: no temporary file is created or renamed after this.
    let files = temporary_files();
    for path in files.iter() {
        let _ = fs::remove_file(path);
    }
    std::process::exit(INTERRUPTED_STATUS);
}

/// Asks for a graceful stop: the returned flag is set by the first signal, and the
/// command is expected to finish its work in progress and exit with
/// [`INTERRUPTED_STATUS`].
pub fn graceful_stop() -> &'static AtomicBool {
    GRACEFUL.store(true, Ordering::SeqCst);
    &STOP
}

/// Creates the temporary file `path`, which must not exist (`O_CREAT | O_EXCL`: an
/// existing file or a symbolic link planted there is an error, never followed), and puts
/// it on the list the signal handler removes.
pub fn create_temporary_file(path: &Path) -> std::io::Result<fs::File> {
    let mut files = temporary_files();
    let file = fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(path)?;
    files.push(path.to_path_buf());
    Ok(file)
}

/// Creates the temporary file `temporary` new (as [`create_temporary_file`]), lets
/// `fill` write it by its path, flushes it and renames it over `final_path`, all under
/// the lock of the list (see the module's documentation); removes it if anything fails.
pub fn write_by_path(
    temporary: &Path,
    final_path: &Path,
    fill: impl FnOnce(&Path) -> anyhow::Result<()>,
) -> anyhow::Result<()> {
    let _files = temporary_files();
    fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(temporary)?;
    let result = fill(temporary).and_then(|()| {
        fs::File::open(temporary)?.sync_all()?;
        fs::rename(temporary, final_path)?;
        Ok(())
    });
    if result.is_err() {
        let _ = fs::remove_file(temporary);
    }
    result
}

/// Renames the temporary file `temporary` over `final_path` and takes it off the list.
pub fn finish_temporary_file(temporary: &Path, final_path: &Path) -> std::io::Result<()> {
    let mut files = temporary_files();
    let renamed = fs::rename(temporary, final_path);
    if renamed.is_ok() {
        files.retain(|p| p != temporary);
    }
    renamed
}

/// Removes the temporary file `temporary` (a failed write) and takes it off the list.
pub fn discard_temporary_file(temporary: &Path) {
    let mut files = temporary_files();
    if files.iter().any(|p| p == temporary) {
        let _ = fs::remove_file(temporary);
        files.retain(|p| p != temporary);
    }
}
