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

/// Runs the `deckland` binary with `args` in the folder `cwd`.
pub fn deckland_in<I, S>(cwd: &Path, args: I) -> Output
where
    I: IntoIterator<Item = S>,
    S: AsRef<OsStr>,
{
    Command::new(env!("CARGO_BIN_EXE_deckland"))
        .current_dir(cwd)
        .args(args)
        .output()
        .expect("the deckland binary runs")
}

/// The command ended with an exit status (no signal), not 101 (a panic), and printed
/// no panic message.
pub fn assert_no_panic(output: &Output) {
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        output.status.code().is_some(),
        "killed by a signal: {stderr}"
    );
    assert_ne!(output.status.code(), Some(101), "panicked: {stderr}");
    assert!(!stderr.contains("panicked"), "panicked: {stderr}");
}

/// The command was refused: status `code`, an `error:` message holding every one of
/// `words`, and no panic.
pub fn assert_refused(output: &Output, code: i32, words: &[&str]) {
    assert_no_panic(output);
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert_eq!(output.status.code(), Some(code), "{stderr}");
    assert!(stderr.contains("error"), "{stderr}");
    for word in words {
        assert!(stderr.contains(word), "no `{word}` in: {stderr}");
    }
}

/// Parses `text` as JSON, refusing a document in which an object repeats a key (which
/// serde_json alone accepts, keeping the last value).
pub fn assert_unique_keys(text: &str) {
    use serde::de::{Deserialize, Deserializer, Error, MapAccess, SeqAccess, Visitor};
    struct Unique;
    struct UniqueVisitor;
    impl<'de> Visitor<'de> for UniqueVisitor {
        type Value = Unique;
        fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
            f.write_str("any JSON value")
        }
        fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<Unique, A::Error> {
            let mut seen = std::collections::HashSet::new();
            while let Some(key) = map.next_key::<String>()? {
                if !seen.insert(key.clone()) {
                    return Err(A::Error::custom(format!("duplicate key `{key}`")));
                }
                map.next_value::<Unique>()?;
            }
            Ok(Unique)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Unique, A::Error> {
            while seq.next_element::<Unique>()?.is_some() {}
            Ok(Unique)
        }
        fn visit_bool<E>(self, _: bool) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_i64<E>(self, _: i64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_u64<E>(self, _: u64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_f64<E>(self, _: f64) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_str<E>(self, _: &str) -> Result<Unique, E> {
            Ok(Unique)
        }
        fn visit_unit<E>(self) -> Result<Unique, E> {
            Ok(Unique)
        }
    }
    impl<'de> Deserialize<'de> for Unique {
        fn deserialize<D: Deserializer<'de>>(deserializer: D) -> Result<Self, D::Error> {
            deserializer.deserialize_any(UniqueVisitor)
        }
    }
    if let Err(error) = serde_json::from_str::<Unique>(text) {
        panic!("not a JSON document with unique keys: {error}\n{text}");
    }
}

/// Every field of the CSV `text` is a finite number, text, or empty: no `NaN`, `inf`.
pub fn assert_finite_csv(text: &str) {
    for (row, line) in text.lines().enumerate() {
        for field in line.split(',') {
            let lower = field.trim().to_ascii_lowercase();
            assert!(
                !matches!(lower.as_str(), "nan" | "inf" | "-inf" | "+inf" | "infinity"),
                "row {row}: non-finite field `{field}` in {line}"
            );
        }
    }
}

/// The names of the temporary files left in `folder`.
pub fn temporary_files(folder: &Path) -> Vec<String> {
    std::fs::read_dir(folder)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|name| name.starts_with(".partial-"))
                .collect()
        })
        .unwrap_or_default()
}
