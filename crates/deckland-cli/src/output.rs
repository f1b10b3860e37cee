//! Output folders, atomic file writes and standard output, shared by every command.
//!
//! Each run writes into its own folder: by default a new `runs/<command>-<UTC timestamp>`
//! (with `-2`, `-3`, … appended if that exists already), or the `--out` folder, which
//! must be a folder the user owns and either be new, be empty, or (with `--force`) hold
//! the results of an earlier deckland run. Every output folder holds a list of the files
//! deckland wrote there ([`MANIFEST`]); `--force` replaces exactly those — the files of
//! the earlier run are removed, so no other command's results stay mixed with the new
//! ones — and never touches a file deckland did not write. A folder that holds files but
//! no list (`/dev`, a home folder, results of another tool) is refused even with
//! `--force`. Every listed name is checked before any is removed ([`earlier_results`]):
//! a refused `--force` removes nothing. A command holds an exclusive lock on its folder
//! for its life ([`lock_folder`]): a second command writing the same folder is refused.
//!
//! Every file is written atomically: to a temporary file
//! `.partial-<pid>-<token>.deckland-<name>` in the same folder (`<token>` 16 random hex
//! digits), flushed to disk, then renamed over the final name, so a crash never leaves a
//! half-written file under a result's name. The temporary file is created new
//! (`O_CREAT | O_EXCL`): a file or a symbolic link planted under its name makes the write
//! fail, and is never followed. The name of every file is put on the folder's list
//! before it is written.
//!
//! A temporary file left by a killed run (SIGKILL cannot be caught) is removed by the
//! next run that uses the folder ([`remove_stale_temporary_files`]), and only if it is
//! ours: named exactly as above, for a file on the folder's list, in a folder with our
//! list, and its process gone (or older than an hour). A folder that is refused is left
//! exactly as it was. Ctrl-C and SIGTERM remove the current temporary file before
//! exiting, with no window ([`crate::interrupt`]).
//!
//! Standard output is written with [`print_stdout`] (through `outln!` and `out!`), which
//! returns an error instead of panicking: a closed pipe ends the command quietly (see
//! `main`), a full device ends it with a message.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, SystemTime, UNIX_EPOCH};

use anyhow::{bail, Context, Result};

/// Folder under which runs go when no `--out` is given.
pub const DEFAULT_RUNS_FOLDER: &str = "runs";

/// The list of the files deckland wrote into an output folder: its first line names the
/// command, each further line one file.
pub const MANIFEST: &str = ".deckland-outputs";

/// Prefix of the temporary files of atomic writes.
const TEMPORARY_PREFIX: &str = ".partial-";

/// What separates a temporary file's process and token from the final name.
const TEMPORARY_MARK: &str = ".deckland-";

/// Largest manifest read back (bytes): one line per file written.
const MAX_MANIFEST_BYTES: u64 = 1024 * 1024;

/// A temporary file older than this is stale whatever its process (s): a write takes
/// seconds, never an hour.
const STALE_AFTER: Duration = Duration::from_secs(3600);

/// Writes `args` to standard output and flushes it. A closed pipe or a full device is an
/// error ([`StdoutError`]), never a panic as with `print!`.
pub fn print_stdout(args: std::fmt::Arguments) -> Result<(), StdoutError> {
    let mut stdout = std::io::stdout().lock();
    stdout
        .write_fmt(args)
        .and_then(|()| stdout.flush())
        .map_err(StdoutError)
}

/// Writes `args` to standard error, ignoring failure: a message about a problem must not
/// itself become one (`eprint!` panics when standard error is closed).
pub fn print_stderr(args: std::fmt::Arguments) {
    let mut stderr = std::io::stderr().lock();
    let _ = stderr.write_fmt(args).and_then(|()| stderr.flush());
}

/// Standard output could not be written.
#[derive(Debug)]
pub struct StdoutError(pub std::io::Error);

impl std::fmt::Display for StdoutError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "cannot write to standard output: {}", self.0)
    }
}

impl std::error::Error for StdoutError {}

impl StdoutError {
    /// Whether the reader went away (a closed pipe, as in `deckland trim | head -1`).
    pub fn is_closed_pipe(&self) -> bool {
        self.0.kind() == std::io::ErrorKind::BrokenPipe
    }
}

/// `println!` that returns a [`StdoutError`] instead of panicking.
macro_rules! outln {
    () => {
        $crate::output::print_stdout(format_args!("\n"))
    };
    ($($arg:tt)*) => {
        $crate::output::print_stdout(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// `print!` that returns a [`StdoutError`] instead of panicking.
macro_rules! out {
    ($($arg:tt)*) => {
        $crate::output::print_stdout(format_args!($($arg)*))
    };
}

/// `eprintln!` that never panics.
macro_rules! warnln {
    ($($arg:tt)*) => {
        $crate::output::print_stderr(format_args!("{}\n", format_args!($($arg)*)))
    };
}

/// The folder a run writes its results into.
#[derive(Debug)]
pub struct OutputDir {
    path: PathBuf,
    command: String,
    /// The files written by this run, in order (the manifest's lines).
    written: Mutex<Vec<String>>,
    /// The folder, held open with an exclusive lock for the command's life
    /// ([`lock_folder`]); `None` where the file system has no locks.
    _lock: Option<FolderLock>,
}

impl OutputDir {
    /// Prepares the output folder of `command`: `explicit` if given, else a new
    /// `runs/<command>-<UTC timestamp>`. An explicit folder must be new, empty, or — with
    /// `force` — hold an earlier deckland run's results, which are removed; it must be
    /// a folder the user owns. Stale temporary files of killed runs are removed.
    pub fn prepare(command: &str, explicit: Option<&Path>, force: bool) -> Result<Self> {
        let output = match explicit {
            Some(path) => Self::prepare_explicit(command, path, force)?,
            None => {
                Self::prepare_default(command, Path::new(DEFAULT_RUNS_FOLDER), SystemTime::now())?
            }
        };
        output.write_manifest()?;
        Ok(output)
    }

    fn new(command: &str, path: PathBuf, lock: Option<FolderLock>) -> Self {
        Self {
            path,
            command: command.to_owned(),
            written: Mutex::new(Vec::new()),
            _lock: lock,
        }
    }

    fn prepare_explicit(command: &str, path: &Path, force: bool) -> Result<Self> {
        let shown = path.display();
        let metadata = match fs::metadata(path) {
            Ok(metadata) => metadata,
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => {
                fs::create_dir_all(path)
                    .with_context(|| format!("cannot create output folder {shown}"))?;
                // Another command may have created it meanwhile: the lock decides.
                let lock = lock_folder(path)?;
                if fs::read_dir(path).is_ok_and(|mut e| e.next().is_none()) {
                    return Ok(Self::new(command, path.to_path_buf(), lock));
                }
                return Self::prepare_existing(command, path, force, lock);
            }
            Err(error) => {
                return Err(error).with_context(|| format!("cannot use --out {shown}"));
            }
        };
        if !metadata.is_dir() {
            bail!("--out {shown} exists and is not a folder");
        }
        check_owned_by_user(path, &metadata)?;
        let lock = lock_folder(path)?;
        Self::prepare_existing(command, path, force, lock)
    }

    /// Accepts the existing folder `path`, locked by this command: empty, or (with
    /// `force`) holding an earlier deckland run's results, which are removed.
    fn prepare_existing(
        command: &str,
        path: &Path,
        force: bool,
        lock: Option<FolderLock>,
    ) -> Result<Self> {
        let shown = path.display();
        // Nothing is changed in the folder until it is accepted.
        let stale = stale_temporary_files(path);
        let entries: Vec<String> = fs::read_dir(path)
            .with_context(|| format!("cannot read output folder {shown}"))?
            .filter_map(|entry| entry.ok())
            .map(|entry| entry.file_name().to_string_lossy().into_owned())
            .filter(|name| !stale.iter().any(|s| s.file_name() == Some(name.as_ref())))
            .collect();
        // Empty, or holding only the list of a run that wrote nothing: use it.
        if entries.iter().all(|name| name == MANIFEST) {
            remove_files(&stale);
            return Ok(Self::new(command, path.to_path_buf(), lock));
        }
        let Some((previous_command, previous_files)) = read_manifest(path) else {
            bail!(
                "--out {shown} holds files that deckland did not write (it has no {MANIFEST} \
                 list), and --force replaces only an earlier deckland run's results; choose a \
                 new or empty folder"
            );
        };
        if !force {
            bail!(
                "output folder {shown} already holds the results of `deckland \
                 {previous_command}`; choose another with --out or pass --force to replace them"
            );
        }
        // Every name is checked before any is removed: a refused --force removes nothing.
        let earlier = earlier_results(path, &previous_files)?;
        remove_files(&stale);
        // Remove the earlier run's own files (and only those): its results must not stay
        // mixed with the new ones.
        for file in &earlier {
            match fs::remove_file(file) {
                Ok(()) => {}
                Err(error) if error.kind() == std::io::ErrorKind::NotFound => {}
                Err(error) => {
                    return Err(error).with_context(|| {
                        format!("cannot remove the earlier result {}", file.display())
                    })
                }
            }
        }
        Ok(Self::new(command, path.to_path_buf(), lock))
    }

    fn prepare_default(command: &str, runs: &Path, now: SystemTime) -> Result<Self> {
        fs::create_dir_all(runs)
            .with_context(|| format!("cannot create folder {}", runs.display()))?;
        // Temporary files of runs killed earlier, in their own folders.
        if let Ok(entries) = fs::read_dir(runs) {
            for entry in entries.filter_map(|e| e.ok()) {
                if entry.file_type().is_ok_and(|t| t.is_dir()) {
                    remove_stale_temporary_files(&entry.path());
                }
            }
        }
        let stem = format!("{command}-{}", utc_timestamp(now));
        for attempt in 1..1000 {
            let name = if attempt == 1 {
                stem.clone()
            } else {
                format!("{stem}-{attempt}")
            };
            let path = runs.join(name);
            // create_dir (not create_dir_all) fails if the folder exists: a fresh folder
            // even when two runs start within the same second.
            match fs::create_dir(&path) {
                Ok(()) => {
                    let lock = lock_folder(&path)?;
                    return Ok(Self::new(command, path, lock));
                }
                Err(error) if error.kind() == std::io::ErrorKind::AlreadyExists => continue,
                Err(error) => {
                    return Err(error)
                        .with_context(|| format!("cannot create folder {}", path.display()))
                }
            }
        }
        bail!(
            "cannot find a free run folder name {stem}-N under {}",
            runs.display()
        )
    }

    /// The folder's path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Writes `bytes` to `file_name` in the folder atomically; returns the final path.
    pub fn write_bytes(&self, file_name: &str, bytes: &[u8]) -> Result<PathBuf> {
        let final_path = self.path.join(file_name);
        self.record_written(file_name)?;
        let temporary = self.path.join(temporary_name(file_name));
        write_through_handle(&temporary, &final_path, bytes, true)
            .with_context(|| format!("cannot write {}", final_path.display()))?;
        Ok(final_path)
    }

    /// Lets `write` fill `file_name`'s content at a temporary path in the folder (a new,
    /// empty file of ours, with the same extension, for writers that choose the format by
    /// it), then flushes it to disk and renames it into place; the temporary file is
    /// removed if `write` fails. An interrupt meanwhile waits for the rename
    /// ([`crate::interrupt::write_by_path`]). The name is put on the folder's list first,
    /// so that a temporary file a killed run leaves is known as ours.
    pub fn write_with(
        &self,
        file_name: &str,
        write: impl FnOnce(&Path) -> Result<()>,
    ) -> Result<PathBuf> {
        let final_path = self.path.join(file_name);
        self.record_written(file_name)?;
        let temporary = self.path.join(temporary_name(file_name));
        crate::interrupt::write_by_path(&temporary, &final_path, write)
            .with_context(|| format!("cannot write {}", final_path.display()))?;
        Ok(final_path)
    }

    /// Adds `file_name` to the folder's list of deckland's files.
    fn record_written(&self, file_name: &str) -> Result<()> {
        {
            let mut written = self
                .written
                .lock()
                .map_err(|_| anyhow::anyhow!("the list of written files is poisoned"))?;
            if !written.iter().any(|n| n == file_name) {
                written.push(file_name.to_owned());
            }
        }
        self.write_manifest()
    }

    /// Writes the list of the files written so far (atomically, like every result).
    fn write_manifest(&self) -> Result<()> {
        let written = self
            .written
            .lock()
            .map_err(|_| anyhow::anyhow!("the list of written files is poisoned"))?
            .clone();
        let mut text = format!("deckland {}\n", self.command);
        for name in &written {
            text.push_str(name);
            text.push('\n');
        }
        let final_path = self.path.join(MANIFEST);
        let temporary = self.path.join(temporary_name(MANIFEST));
        write_through_handle(&temporary, &final_path, text.as_bytes(), false)
            .with_context(|| format!("cannot write {}", final_path.display()))
    }
}

/// Writes `bytes` to the new temporary file `temporary` through its handle (flushed to
/// disk if `sync`) and renames it over `final_path`; removes it if anything fails. An
/// interrupt removes it meanwhile ([`crate::interrupt`]).
fn write_through_handle(
    temporary: &Path,
    final_path: &Path,
    bytes: &[u8],
    sync: bool,
) -> std::io::Result<()> {
    let mut file = crate::interrupt::create_temporary_file(temporary)?;
    let result = file
        .write_all(bytes)
        .and_then(|()| if sync { file.sync_all() } else { Ok(()) })
        .and_then(|()| {
            drop(file);
            crate::interrupt::finish_temporary_file(temporary, final_path)
        });
    if result.is_err() {
        crate::interrupt::discard_temporary_file(temporary);
    }
    result
}

/// A fresh temporary name for `file_name`: `.partial-<pid>-<token>.deckland-<file_name>`,
/// with 16 random hex digits (std's per-process random hash keys, a counter and the
/// clock), so that no planted file or link can be expected under it.
fn temporary_name(file_name: &str) -> String {
    use std::hash::{BuildHasher, Hasher};
    use std::sync::atomic::{AtomicU64, Ordering};
    static COUNTER: AtomicU64 = AtomicU64::new(0);
    let mut hasher = std::collections::hash_map::RandomState::new().build_hasher();
    hasher.write_u64(COUNTER.fetch_add(1, Ordering::Relaxed));
    let nanos = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    hasher.write_u128(nanos);
    format!(
        "{TEMPORARY_PREFIX}{}-{:016x}{TEMPORARY_MARK}{file_name}",
        std::process::id(),
        hasher.finish()
    )
}

/// The process id and the final name of the temporary file `name`, if it is named as
/// ours ([`temporary_name`]).
fn parse_temporary_name(name: &str) -> Option<(u32, &str)> {
    let rest = name.strip_prefix(TEMPORARY_PREFIX)?;
    let (pid, rest) = rest.split_once('-')?;
    if pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let token = rest.get(..16)?;
    let file_name = rest.get(16..)?.strip_prefix(TEMPORARY_MARK)?;
    if !token.bytes().all(|b| b.is_ascii_hexdigit()) || file_name.is_empty() {
        return None;
    }
    Some((pid.parse().ok()?, file_name))
}

/// Removes `files`, ignoring failures (a file that cannot be removed is no worse than
/// before).
fn remove_files(files: &[PathBuf]) {
    for file in files {
        let _ = fs::remove_file(file);
    }
}

/// The command and the files listed in `folder`'s manifest, if it has one (a regular
/// file of bounded size).
fn read_manifest(folder: &Path) -> Option<(String, Vec<String>)> {
    let text = deckland::scenario::read_text_file(
        &folder.join(MANIFEST),
        MAX_MANIFEST_BYTES,
        "list of deckland's files",
    )
    .ok()?;
    let mut lines = text.lines();
    let command = lines.next()?.strip_prefix("deckland ")?.to_owned();
    Some((command, lines.map(str::to_owned).collect()))
}

/// Opens `folder` and takes an exclusive lock on it (`flock`, released by the system
/// when the command ends, even killed), so that two commands never write one folder: the
/// second is refused, naming it. `None` where the file system has no locks.
#[cfg(unix)]
fn lock_folder(folder: &Path) -> Result<Option<FolderLock>> {
    use nix::errno::Errno;
    use nix::fcntl::{Flock, FlockArg};
    let handle = fs::File::open(folder)
        .with_context(|| format!("cannot open output folder {}", folder.display()))?;
    match Flock::lock(handle, FlockArg::LockExclusiveNonblock) {
        Ok(lock) => Ok(Some(lock)),
        Err((_, Errno::EWOULDBLOCK)) => bail!(
            "output folder {} is in use by another deckland command (it holds the folder's \
             lock); wait for it to end or choose another --out",
            folder.display()
        ),
        Err((_, Errno::ENOTSUP | Errno::ENOLCK)) => Ok(None),
        Err((_, errno)) => Err(std::io::Error::from(errno))
            .with_context(|| format!("cannot lock output folder {}", folder.display())),
    }
}

/// An output folder held open with its lock.
#[cfg(unix)]
type FolderLock = nix::fcntl::Flock<fs::File>;

/// No lock off Unix.
#[cfg(not(unix))]
type FolderLock = ();

/// Folders are not locked off Unix (a folder cannot be opened as a file there).
#[cfg(not(unix))]
fn lock_folder(_folder: &Path) -> Result<Option<FolderLock>> {
    Ok(None)
}

/// Extensions of the files deckland writes (results, tables, plots, pages).
const OUTPUT_EXTENSIONS: [&str; 9] = [
    "csv", "toml", "json", "html", "parquet", "png", "svg", "pdf", "md",
];

/// Whether `name` is named as a file deckland writes: a stem of ASCII letters, digits,
/// `_` and `-`, and one of [`OUTPUT_EXTENSIONS`]. A name a tampered list adds
/// (`notes.txt`) is not.
fn is_output_file_name(name: &str) -> bool {
    let Some((stem, extension)) = name.rsplit_once('.') else {
        return false;
    };
    !stem.is_empty()
        && stem
            .bytes()
            .all(|b| b.is_ascii_alphanumeric() || b == b'_' || b == b'-')
        && OUTPUT_EXTENSIONS.contains(&extension)
}

/// The files of the earlier run in `folder` that `--force` replaces: each name on its
/// list that exists must be a regular file (or a link, which is removed itself and never
/// followed) named as deckland's outputs are ([`is_output_file_name`]); anything else
/// (a folder such as a partitioned `runs.parquet`, a user's file added to the list)
/// refuses the whole command, before any file is removed. Names that are gone are
/// skipped.
fn earlier_results(folder: &Path, listed: &[String]) -> Result<Vec<PathBuf>> {
    let mut files = Vec::new();
    for name in listed.iter().filter(|n| is_plain_file_name(n)) {
        let file = folder.join(name);
        let metadata = match fs::symlink_metadata(&file) {
            Ok(metadata) => metadata,
            Err(error) if error.kind() == std::io::ErrorKind::NotFound => continue,
            Err(error) => {
                return Err(error).with_context(|| format!("cannot inspect {}", file.display()))
            }
        };
        // A link is removed itself, never followed (issue 28, D7): its target is safe.
        if !metadata.is_file() && !metadata.is_symlink() {
            bail!(
                "--force refused, nothing removed: {} is listed in {MANIFEST} as an earlier \
                 result but is not a file (a folder, a device, a pipe); move it away or \
                 choose another --out",
                file.display()
            );
        }
        if !is_output_file_name(name) {
            bail!(
                "--force refused, nothing removed: {} is listed in {MANIFEST} but is not \
                 named as a file deckland writes (.{}); move it away or choose another --out",
                file.display(),
                OUTPUT_EXTENSIONS.join(", .")
            );
        }
        files.push(file);
    }
    Ok(files)
}

/// Whether `name` is a bare file name (no separator, not `.` or `..`): a manifest line
/// never reaches outside its folder.
fn is_plain_file_name(name: &str) -> bool {
    !name.is_empty()
        && name != "."
        && name != ".."
        && name != MANIFEST
        && !name.contains('/')
        && !name.contains('\\')
}

/// Refuses a folder that belongs to another user.
#[cfg(unix)]
fn check_owned_by_user(path: &Path, metadata: &fs::Metadata) -> Result<()> {
    use std::os::unix::fs::MetadataExt;
    let user = nix::unistd::geteuid().as_raw();
    if metadata.uid() != user {
        bail!(
            "--out {} belongs to user id {}, not to you (user id {user}); choose a folder \
             of your own",
            path.display(),
            metadata.uid()
        );
    }
    Ok(())
}

/// Refuses a folder that belongs to another user (not checked off Unix).
#[cfg(not(unix))]
fn check_owned_by_user(_path: &Path, _metadata: &fs::Metadata) -> Result<()> {
    Ok(())
}

/// The temporary files in `folder` that runs killed earlier left, and only those that
/// are ours: named as ours ([`temporary_name`]), for a file on the folder's list (or
/// the list itself), not a folder, and whose process no longer runs or that are older
/// than an hour. A folder without our list has none.
fn stale_temporary_files(folder: &Path) -> Vec<PathBuf> {
    let Some((_, listed)) = read_manifest(folder) else {
        return Vec::new();
    };
    let Ok(entries) = fs::read_dir(folder) else {
        return Vec::new();
    };
    let mut stale = Vec::new();
    for entry in entries.filter_map(|e| e.ok()) {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some((pid, file_name)) = parse_temporary_name(&name) else {
            continue;
        };
        if file_name != MANIFEST && !listed.iter().any(|l| l == file_name) {
            continue;
        }
        // The entry itself, not what a link points to: a link is removed, never followed.
        let Ok(metadata) = fs::symlink_metadata(entry.path()) else {
            continue;
        };
        if metadata.is_dir() {
            continue;
        }
        let old = metadata
            .modified()
            .ok()
            .and_then(|modified| modified.elapsed().ok())
            .is_some_and(|age| age > STALE_AFTER);
        let orphaned = pid != std::process::id() && !process_is_running(pid);
        if old || orphaned {
            stale.push(entry.path());
        }
    }
    stale
}

/// Removes the temporary files in `folder` left by runs that were killed, if they are
/// ours ([`stale_temporary_files`]). Failures are ignored (a file that cannot be removed
/// is no worse than before).
pub fn remove_stale_temporary_files(folder: &Path) {
    remove_files(&stale_temporary_files(folder));
}

/// Whether a process `pid` runs (signal 0 probes without sending anything).
#[cfg(unix)]
fn process_is_running(pid: u32) -> bool {
    use nix::errno::Errno;
    let Ok(raw) = i32::try_from(pid) else {
        return false;
    };
    match nix::sys::signal::kill(nix::unistd::Pid::from_raw(raw), None) {
        Ok(()) => true,
        Err(Errno::ESRCH) => false,
        Err(_) => true, // EPERM: it runs, as another user
    }
}

/// Whether a process `pid` runs: unknown off Unix, so only age makes a file stale.
#[cfg(not(unix))]
fn process_is_running(_pid: u32) -> bool {
    true
}

/// `time` as a compact UTC timestamp, e.g. `20261121T084316Z`.
pub fn utc_timestamp(time: SystemTime) -> String {
    let seconds = time
        .duration_since(UNIX_EPOCH)
        .map(|d| d.as_secs())
        .unwrap_or(0);
    let days = i64::try_from(seconds / 86_400).unwrap_or(0);
    let of_day = seconds % 86_400;
    let (year, month, day) = civil_from_days(days);
    format!(
        "{year:04}{month:02}{day:02}T{:02}{:02}{:02}Z",
        of_day / 3600,
        (of_day % 3600) / 60,
        of_day % 60
    )
}

/// The proleptic Gregorian date (year, month 1–12, day 1–31) of `days` since 1970-01-01
/// (H. Hinnant, "chrono-compatible low-level date algorithms", `civil_from_days`).
pub fn civil_from_days(days: i64) -> (i64, u32, u32) {
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let day_of_era = z.rem_euclid(146_097); // [0, 146096]
    let year_of_era =
        (day_of_era - day_of_era / 1460 + day_of_era / 36_524 - day_of_era / 146_096) / 365;
    let day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
    let month_index = (5 * day_of_year + 2) / 153; // March = 0
    let day = day_of_year - (153 * month_index + 2) / 5 + 1;
    let month = if month_index < 10 {
        month_index + 3
    } else {
        month_index - 9
    };
    let year = year_of_era + era * 400 + i64::from(month <= 2);
    (year, month as u32, day as u32)
}

/// `value` with `digits` decimals, and no minus sign on a value that rounds to zero
/// ("0.000000", never "-0.000000").
pub(crate) fn fixed(value: f64, digits: usize) -> String {
    let text = format!("{value:.digits$}");
    match text.strip_prefix('-') {
        Some(magnitude) if magnitude.chars().all(|c| c == '0' || c == '.') => magnitude.to_owned(),
        _ => text,
    }
}

/// The rows of the matrix `m`, for a JSON report.
pub(crate) fn rows<const R: usize, const C: usize>(
    m: &nalgebra::SMatrix<f64, R, C>,
) -> Vec<Vec<f64>> {
    (0..R)
        .map(|i| (0..C).map(|j| m[(i, j)]).collect())
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn civil_from_days_matches_known_dates() {
        assert_eq!(civil_from_days(0), (1970, 1, 1));
        assert_eq!(civil_from_days(11_016), (2000, 2, 29)); // leap day of a century leap year
        assert_eq!(civil_from_days(-1), (1969, 12, 31));
        assert_eq!(civil_from_days(20_513), (2026, 3, 1));
    }

    #[test]
    fn timestamp_is_compact_utc() {
        // 2026-11-21 08:43:16 UTC = 1 795 250 596 s after the epoch.
        let time = UNIX_EPOCH + Duration::from_secs(1_795_250_596);
        assert_eq!(utc_timestamp(time), "20261121T084316Z");
    }

    fn scratch(name: &str) -> PathBuf {
        let path =
            std::env::temp_dir().join(format!("deckland-output-{}-{name}", std::process::id()));
        let _ = fs::remove_dir_all(&path);
        path
    }

    fn names(path: &Path) -> Vec<String> {
        let mut names: Vec<String> = fs::read_dir(path)
            .expect("read")
            .filter_map(|e| e.ok())
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
    }

    #[test]
    fn explicit_folder_with_results_is_refused_without_force() {
        let path = scratch("explicit");
        let first = OutputDir::prepare("test", Some(&path), false).expect("new folder");
        first.write_bytes("a.csv", b"x\n1\n").expect("written");
        // While the first command holds the folder, no other may use it.
        let error = OutputDir::prepare("test", Some(&path), true).expect_err("in use");
        assert!(error.to_string().contains("in use"), "{error}");
        drop(first);
        assert!(OutputDir::prepare("test", Some(&path), false).is_err());
        let forced = OutputDir::prepare("test", Some(&path), true).expect("forced");
        forced.write_bytes("a.csv", b"x\n2\n").expect("overwritten");
        assert_eq!(
            fs::read_to_string(path.join("a.csv")).expect("read"),
            "x\n2\n"
        );
        assert_eq!(names(&path), [MANIFEST, "a.csv"]);
        let _ = fs::remove_dir_all(&path);
    }

    /// Regression (issue 14, class 11): `--force` left another command's outputs mixed
    /// with the new ones, and wrote into any folder (`/dev` as root).
    #[test]
    fn regression_force_replaces_only_the_earlier_runs_own_files() {
        let path = scratch("force");
        let first = OutputDir::prepare("campaign", Some(&path), false).expect("new");
        first.write_bytes("runs.csv", b"a\n").expect("written");
        first.write_bytes("summary.json", b"{}").expect("written");
        drop(first);
        fs::write(path.join("notes.txt"), b"mine").expect("user file");
        let second = OutputDir::prepare("land", Some(&path), true).expect("forced");
        second
            .write_bytes("summary.json", b"{\"x\":1}")
            .expect("written");
        assert_eq!(names(&path), [MANIFEST, "notes.txt", "summary.json"]);
        assert_eq!(
            fs::read_to_string(path.join(MANIFEST)).expect("manifest"),
            "deckland land\nsummary.json\n"
        );
        drop(second);
        // A folder with files but no list is not deckland's: refused even with --force.
        fs::remove_file(path.join(MANIFEST)).expect("removed");
        let error = OutputDir::prepare("land", Some(&path), true).expect_err("refused");
        assert!(error.to_string().contains("did not write"), "{error}");
        assert!(path.join("notes.txt").exists() && path.join("summary.json").exists());
        let _ = fs::remove_dir_all(&path);
    }

    #[test]
    fn a_manifest_never_reaches_outside_its_folder() {
        for name in ["../x", "/etc/passwd", ".", "..", "", "a/b", MANIFEST] {
            assert!(!is_plain_file_name(name), "{name}");
        }
        assert!(is_plain_file_name("approach.csv"));
    }

    #[test]
    fn failed_write_leaves_no_file() {
        let path = scratch("failed");
        let out = OutputDir::prepare("test", Some(&path), false).expect("new folder");
        let result = out.write_with("b.csv", |temporary| {
            fs::write(temporary, b"half")?;
            Err(std::io::Error::from(std::io::ErrorKind::StorageFull).into())
        });
        let error = result.expect_err("disk full");
        assert!(format!("{error:#}").contains("cannot write"), "{error:#}");
        assert_eq!(names(&path), [MANIFEST]);
        let _ = fs::remove_dir_all(&path);
    }

    /// Regression (issue 14, class 10): temporary files of killed runs stayed forever.
    #[test]
    fn regression_stale_temporary_files_are_removed_at_the_next_run() {
        let path = scratch("stale");
        let first = OutputDir::prepare("test", Some(&path), false).expect("new folder");
        first.write_bytes("approach.csv", b"x\n").expect("written");
        // A process id that cannot run (above the kernel's maximum of 2^22).
        let ours = |pid: u32, name: &str| {
            path.join(format!(
                "{TEMPORARY_PREFIX}{pid}-0123456789abcdef{TEMPORARY_MARK}{name}"
            ))
        };
        let dead = ours(4_294_967, "approach.csv");
        let dead_manifest = ours(4_294_967, MANIFEST);
        let live = ours(std::process::id(), "approach.csv");
        let unlisted = ours(4_294_967, "notes.txt");
        for file in [&dead, &dead_manifest, &live, &unlisted] {
            fs::write(file, b"half").expect("written");
        }
        remove_stale_temporary_files(&path);
        assert!(!dead.exists() && !dead_manifest.exists());
        assert!(live.exists(), "a running process's file is kept");
        assert!(
            unlisted.exists(),
            "a file for a name not on the list is not ours"
        );
        let _ = fs::remove_dir_all(&path);
    }

    /// Regression (issue 28, D6): a user's `.partial-notes.txt` was deleted, without
    /// `--force`, in a folder that was then refused.
    #[test]
    fn regression_a_refused_folder_is_left_exactly_as_it_was() {
        let path = scratch("refused");
        fs::create_dir_all(&path).expect("folder");
        let user_files = [
            ".partial-notes.txt",
            ".partial-1-approach.csv",
            ".partial-4294967-0123456789abcdef.deckland-approach.csv",
            "t",
        ];
        for name in user_files {
            fs::write(path.join(name), b"mine").expect("user file");
        }
        for force in [false, true] {
            let error = OutputDir::prepare("land", Some(&path), force).expect_err("refused");
            assert!(error.to_string().contains("did not write"), "{error}");
            assert_eq!(names(&path), {
                let mut sorted = user_files.map(str::to_owned).to_vec();
                sorted.sort();
                sorted
            });
        }
        // With our list but a run of another command, without --force: refused, untouched.
        fs::write(path.join(MANIFEST), "deckland campaign\nrun.csv\n").expect("list");
        let before = names(&path);
        assert!(OutputDir::prepare("land", Some(&path), false).is_err());
        assert_eq!(names(&path), before);
        let _ = fs::remove_dir_all(&path);
    }

    /// Regression (issue 28, D7): a planted link named as a temporary file redirected a
    /// write outside the folder.
    #[cfg(unix)]
    #[test]
    fn regression_temporary_files_never_follow_a_planted_link() {
        let path = scratch("link");
        fs::create_dir_all(&path).expect("folder");
        let victim = scratch("link-victim");
        fs::write(&victim, b"precious").expect("victim");
        let link = path.join(temporary_name("summary.json"));
        std::os::unix::fs::symlink(&victim, &link).expect("link");
        let error = crate::interrupt::create_temporary_file(&link).expect_err("refused");
        assert_eq!(error.kind(), std::io::ErrorKind::AlreadyExists);
        assert_eq!(fs::read(&victim).expect("victim"), b"precious");
        // A dangling link is not followed either (O_EXCL does not create its target).
        let dangling = path.join(temporary_name("runs.csv"));
        let target = scratch("link-target");
        std::os::unix::fs::symlink(&target, &dangling).expect("link");
        assert!(crate::interrupt::create_temporary_file(&dangling).is_err());
        assert!(!target.exists());
        // Names are fresh on every call: a link planted under one is never met again.
        assert_ne!(temporary_name("a.csv"), temporary_name("a.csv"));
        let _ = fs::remove_dir_all(&path);
        let _ = fs::remove_file(&victim);
    }

    #[test]
    fn temporary_names_read_back_and_user_names_do_not() {
        let name = temporary_name("touchdown_dispersion.png");
        assert_eq!(
            parse_temporary_name(&name),
            Some((std::process::id(), "touchdown_dispersion.png"))
        );
        assert!(
            name.ends_with(".png"),
            "the writer chooses the format by it"
        );
        for user in [
            ".partial-notes.txt",
            ".partial-12-approach.csv",
            ".partial-12-0123456789abcdeg.deckland-a.csv",
            ".partial-x-0123456789abcdef.deckland-a.csv",
            ".partial-12-0123456789abcdef.deckland-",
            "partial-12-0123456789abcdef.deckland-a.csv",
        ] {
            assert_eq!(parse_temporary_name(user), None, "{user}");
        }
    }

    #[test]
    fn default_folders_are_new_per_run() {
        let runs = scratch("runs");
        let now = SystemTime::now();
        let a = OutputDir::prepare_default("environment", &runs, now).expect("first");
        let b = OutputDir::prepare_default("environment", &runs, now).expect("second");
        assert_ne!(a.path(), b.path());
        let name = a
            .path()
            .file_name()
            .map(|n| n.to_string_lossy().into_owned());
        assert!(name.is_some_and(|n| n.starts_with("environment-") && n.ends_with('Z')));
        let _ = fs::remove_dir_all(&runs);
    }

    #[cfg(unix)]
    #[test]
    fn a_folder_of_another_user_is_refused() {
        use std::os::unix::fs::MetadataExt;
        // /dev and / belong to root; as root, a folder given away to "nobody" is used.
        let path = scratch("other-user");
        fs::create_dir_all(&path).expect("folder");
        let foreign = if nix::unistd::geteuid().is_root() {
            let nobody = nix::unistd::Uid::from_raw(65_534);
            std::os::unix::fs::chown(&path, Some(nobody.as_raw()), None).expect("chown as root");
            path.clone()
        } else {
            PathBuf::from("/")
        };
        assert_ne!(
            fs::metadata(&foreign).expect("exists").uid(),
            nix::unistd::geteuid().as_raw()
        );
        let error = OutputDir::prepare("land", Some(&foreign), true).expect_err("refused");
        assert!(error.to_string().contains("not to you"), "{error}");
        let _ = fs::remove_dir_all(&path);
    }

    #[test]
    fn values_that_round_to_zero_have_no_sign() {
        assert_eq!(fixed(-1e-9, 6), "0.000000");
        assert_eq!(fixed(-0.0, 4), "0.0000");
        assert_eq!(fixed(-0.0000006, 6), "-0.000001");
        assert_eq!(fixed(-0.526839, 6), "-0.526839");
        assert_eq!(fixed(f64::NAN, 2), "NaN");
    }
}
