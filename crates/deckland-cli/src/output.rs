//! Output folders and atomic file writes, shared by every command.
//!
//! Each run writes into its own folder: by default a new `runs/<command>-<UTC timestamp>`
//! (with `-2`, `-3`, … appended if that exists already); an explicit `--out` folder that
//! already holds files is refused unless `--force`, which then overwrites the files of the
//! same names (other files in it are left alone). Every file is written atomically: to a
//! temporary file in the same folder, flushed to disk, then renamed over the final name,
//! so a crash never leaves a half-written file under a result's name.

use std::fs;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::{SystemTime, UNIX_EPOCH};

use anyhow::{bail, Context, Result};

/// Folder under which runs go when no `--out` is given.
pub const DEFAULT_RUNS_FOLDER: &str = "runs";

/// The folder a run writes its results into.
#[derive(Debug, Clone)]
pub struct OutputDir {
    path: PathBuf,
}

impl OutputDir {
    /// Prepares the output folder of `command`: `explicit` if given (refused if it already
    /// holds files, unless `force`), else a new `runs/<command>-<UTC timestamp>`.
    pub fn prepare(command: &str, explicit: Option<&Path>, force: bool) -> Result<Self> {
        match explicit {
            Some(path) => Self::prepare_explicit(path, force),
            None => {
                Self::prepare_default(Path::new(DEFAULT_RUNS_FOLDER), command, SystemTime::now())
            }
        }
    }

    fn prepare_explicit(path: &Path, force: bool) -> Result<Self> {
        if path.exists() {
            if !path.is_dir() {
                bail!("output path {} exists and is not a folder", path.display());
            }
            let holds_files = fs::read_dir(path)
                .with_context(|| format!("cannot read output folder {}", path.display()))?
                .next()
                .is_some();
            if holds_files && !force {
                bail!(
                    "output folder {} already holds results; choose another with --out or \
                     pass --force to overwrite",
                    path.display()
                );
            }
        }
        fs::create_dir_all(path)
            .with_context(|| format!("cannot create output folder {}", path.display()))?;
        Ok(Self {
            path: path.to_path_buf(),
        })
    }

    fn prepare_default(runs: &Path, command: &str, now: SystemTime) -> Result<Self> {
        fs::create_dir_all(runs)
            .with_context(|| format!("cannot create folder {}", runs.display()))?;
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
                Ok(()) => return Ok(Self { path }),
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
        self.write_with(file_name, |temporary| {
            let mut file = fs::File::create(temporary)?;
            file.write_all(bytes)?;
            Ok(())
        })
    }

    /// Lets `write` create `file_name`'s content at a temporary path in the folder (with the
    /// same extension, for writers that choose the format by it), then flushes it to disk
    /// and renames it into place; the temporary file is removed if `write` fails.
    pub fn write_with(
        &self,
        file_name: &str,
        write: impl FnOnce(&Path) -> Result<()>,
    ) -> Result<PathBuf> {
        let final_path = self.path.join(file_name);
        let temporary = self
            .path
            .join(format!(".partial-{}-{file_name}", std::process::id()));
        let result = write(&temporary).and_then(|()| {
            fs::File::open(&temporary)?.sync_all()?;
            fs::rename(&temporary, &final_path)?;
            Ok(())
        });
        if let Err(error) = result {
            let _ = fs::remove_file(&temporary);
            return Err(error).with_context(|| format!("cannot write {}", final_path.display()));
        }
        Ok(final_path)
    }
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

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

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

    #[test]
    fn explicit_folder_with_results_is_refused_without_force() {
        let path = scratch("explicit");
        let first = OutputDir::prepare("test", Some(&path), false).expect("new folder");
        first.write_bytes("a.csv", b"x\n1\n").expect("written");
        assert!(OutputDir::prepare("test", Some(&path), false).is_err());
        let forced = OutputDir::prepare("test", Some(&path), true).expect("forced");
        forced.write_bytes("a.csv", b"x\n2\n").expect("overwritten");
        assert_eq!(
            fs::read_to_string(path.join("a.csv")).expect("read"),
            "x\n2\n"
        );
        let leftovers: Vec<_> = fs::read_dir(&path)
            .expect("read")
            .filter_map(|e| e.ok())
            .filter(|e| e.file_name().to_string_lossy().starts_with(".partial"))
            .collect();
        assert!(leftovers.is_empty());
        let _ = fs::remove_dir_all(&path);
    }

    #[test]
    fn failed_write_leaves_no_file() {
        let path = scratch("failed");
        let out = OutputDir::prepare("test", Some(&path), false).expect("new folder");
        let result = out.write_with("b.csv", |temporary| {
            fs::write(temporary, b"half")?;
            bail!("simulated crash")
        });
        assert!(result.is_err());
        assert_eq!(fs::read_dir(&path).expect("read").count(), 0);
        let _ = fs::remove_dir_all(&path);
    }

    #[test]
    fn default_folders_are_new_per_run() {
        let runs = scratch("runs");
        let now = SystemTime::now();
        let a = OutputDir::prepare_default(&runs, "environment", now).expect("first");
        let b = OutputDir::prepare_default(&runs, "environment", now).expect("second");
        assert_ne!(a.path(), b.path());
        let name = a
            .path()
            .file_name()
            .map(|n| n.to_string_lossy().into_owned());
        assert!(name.is_some_and(|n| n.starts_with("environment-") && n.ends_with('Z')));
        let _ = fs::remove_dir_all(&runs);
    }
}
