//! Ctrl-C and SIGTERM (and SIGHUP): handled alike, so that a run stopped either way
//! leaves no temporary file behind.
//!
//! By default the first signal removes the temporary files of the writes in progress
//! and exits with status 130. A command that can stop cleanly (a campaign, which writes
//! its finished runs) asks for [`graceful_stop`] instead: the first signal only sets the
//! flag it returns, a second one exits at once (after the same clean-up).

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Mutex;

/// Exit status after an interrupt (128 + SIGINT, as shells report Ctrl-C).
pub const INTERRUPTED_STATUS: i32 = 130;

/// Set by the first signal when the command stops gracefully.
static STOP: AtomicBool = AtomicBool::new(false);
/// Whether the command stops gracefully (the first signal only sets [`STOP`]).
static GRACEFUL: AtomicBool = AtomicBool::new(false);
/// The temporary files being written now.
static TEMPORARY_FILES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

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
    remove_temporary_files();
    std::process::exit(INTERRUPTED_STATUS);
}

/// Asks for a graceful stop: the returned flag is set by the first signal, and the
/// command is expected to finish its work in progress and exit with
/// [`INTERRUPTED_STATUS`].
pub fn graceful_stop() -> &'static AtomicBool {
    GRACEFUL.store(true, Ordering::SeqCst);
    &STOP
}

/// Remembers a temporary file being written, to remove it on a signal.
pub fn register_temporary_file(path: &Path) {
    if let Ok(mut files) = TEMPORARY_FILES.lock() {
        files.push(path.to_path_buf());
    }
}

/// Forgets a temporary file once it has been renamed or removed.
pub fn unregister_temporary_file(path: &Path) {
    if let Ok(mut files) = TEMPORARY_FILES.lock() {
        files.retain(|p| p != path);
    }
}

fn remove_temporary_files() {
    if let Ok(files) = TEMPORARY_FILES.lock() {
        for path in files.iter() {
            let _ = std::fs::remove_file(path);
        }
    }
}
