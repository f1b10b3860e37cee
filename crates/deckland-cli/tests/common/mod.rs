//! Helpers shared by the CLI integration tests (each test file includes this module).

#![allow(dead_code)] // each test file uses only some of the helpers

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs the `deckland` binary built for these tests with `args`.
pub fn deckland<I, S>(args: I) -> Output
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    Command::new(env!("CARGO_BIN_EXE_deckland"))
        .args(args)
        .output()
        .expect("the deckland binary runs")
}

/// A fresh, not yet existing scratch folder for this test process.
pub fn scratch(name: &str) -> PathBuf {
    let path = std::env::temp_dir().join(format!("deckland-test-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&path);
    path
}

/// Size of a file in bytes, 0 when it does not exist.
pub fn file_size(path: &Path) -> u64 {
    std::fs::metadata(path).map(|m| m.len()).unwrap_or(0)
}
