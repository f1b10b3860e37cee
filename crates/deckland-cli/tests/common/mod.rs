//! Helpers shared by the CLI integration tests (each test file includes this module).

#![allow(dead_code)] // each test file uses only some of the helpers

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The 10° bank step the lateral step tests fly (`step --axis roll --step-deg 10`); a
/// test appends its own arguments.
pub const ROLL_STEP: [&str; 5] = ["step", "--axis", "roll", "--step-deg", "10"];

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

/// The Chromium binary for the browser tests: `$DECKLAND_CHROMIUM`, else `chromium` on the
/// `PATH`. Without it a test fails with how to install it — unless
/// `DECKLAND_SKIP_BROWSER_TESTS=1` is set outside CI, when it returns `None` and the test
/// skips (CI, with `CI` set, never skips: `.ci/run` installs Chromium first).
pub fn chromium() -> Option<PathBuf> {
    let candidate = std::env::var_os("DECKLAND_CHROMIUM")
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("chromium"));
    let found = Command::new(&candidate)
        .arg("--version")
        .output()
        .is_ok_and(|o| o.status.success());
    if found {
        return Some(candidate);
    }
    let in_ci = std::env::var_os("CI").is_some_and(|v| !v.is_empty() && v != "false");
    let skip = std::env::var("DECKLAND_SKIP_BROWSER_TESTS").is_ok_and(|v| v == "1");
    if skip && !in_ci {
        eprintln!(
            "skipping a browser test: {} not found and DECKLAND_SKIP_BROWSER_TESTS=1",
            candidate.display()
        );
        return None;
    }
    panic!(
        "headless Chromium is needed to check report.html but `{}` does not run. Install it \
         with `bash .ci/install-system-packages` (Debian: `apt-get install chromium`), point \
         DECKLAND_CHROMIUM at it, or, outside CI only, set DECKLAND_SKIP_BROWSER_TESTS=1 to \
         skip the browser tests",
        candidate.display()
    );
}

/// Runs headless Chromium on the local file `page` with `mode` (`--dump-dom`, or
/// `--screenshot=…`), from a new empty profile, with no network use of its own; returns
/// its standard output. Fails the test after 120 s.
pub fn headless_chromium(chromium: &Path, page: &Path, mode: &[&str]) -> String {
    let profile = scratch(&format!(
        "chromium-profile-{}",
        page.display().to_string().len() + mode.len()
    ));
    std::fs::create_dir_all(&profile).expect("a profile folder");
    let page = page.canonicalize().expect("the page exists");
    // Output to files, not pipes: a page's DOM overflows a pipe that nobody reads while
    // the test waits.
    let stdout_path = profile.with_extension("stdout");
    let stderr_path = profile.with_extension("stderr");
    let mut child = Command::new(chromium)
        .args([
            "--headless",
            "--no-sandbox",
            "--disable-gpu",
            "--disable-quic",
            "--no-first-run",
            "--disable-background-networking",
            "--disable-component-update",
            "--disable-sync",
        ])
        .arg(format!("--user-data-dir={}", profile.display()))
        .args(mode)
        .arg(format!("file://{}", page.display()))
        .stdout(std::fs::File::create(&stdout_path).expect("a file for chromium's output"))
        .stderr(std::fs::File::create(&stderr_path).expect("a file for chromium's errors"))
        .spawn()
        .expect("chromium starts");
    let started = std::time::Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("chromium runs") {
            break status;
        }
        if started.elapsed() > std::time::Duration::from_secs(120) {
            let _ = child.kill();
            let _ = child.wait();
            panic!(
                "headless chromium did not finish within 120 s on {}",
                page.display()
            );
        }
        std::thread::sleep(std::time::Duration::from_millis(100));
    };
    let stdout = std::fs::read_to_string(&stdout_path).unwrap_or_default();
    let stderr = std::fs::read_to_string(&stderr_path).unwrap_or_default();
    let _ = std::fs::remove_dir_all(&profile);
    let _ = std::fs::remove_file(&stdout_path);
    let _ = std::fs::remove_file(&stderr_path);
    assert!(
        status.success(),
        "chromium failed on {}: {stderr}",
        page.display()
    );
    stdout
}

/// The text of an HTML document: tags removed, entities `&amp;` `&lt;` `&gt;` `&quot;`
/// `&#39;` decoded, runs of white space made one space.
pub fn page_text(html: &str) -> String {
    let mut text = String::with_capacity(html.len());
    let mut in_tag = false;
    for c in html.chars() {
        match c {
            '<' => in_tag = true,
            '>' if in_tag => {
                in_tag = false;
                text.push(' ');
            }
            _ if !in_tag => text.push(c),
            _ => {}
        }
    }
    let decoded = text
        .replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&#39;", "'")
        .replace("&amp;", "&");
    decoded.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// Whether `text` holds a non-finite number as Rust or JavaScript writes it: `NaN`, `inf`
/// or `Infinity` standing alone.
pub fn has_non_finite(text: &str) -> bool {
    text.split(|c: char| !c.is_ascii_alphanumeric())
        .any(|word| matches!(word, "NaN" | "nan" | "inf" | "Infinity"))
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
    // Rust's panic message; `panicked` alone is also the name of an outcome.
    assert!(!stderr.contains("panicked at"), "panicked: {stderr}");
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

/// A short (500 m) adverse approach with every dispersion on, written to `dir/short.toml`;
/// returns its path. It flies the 3-DOF behind a stationary ship, the approach the tests
/// that use it were written for (the default is the 3-D approach).
pub fn short_dispersed_scenario(dir: &Path) -> String {
    std::fs::create_dir_all(dir).expect("scratch folder");
    let path = dir.join("short.toml");
    std::fs::write(
        &path,
        "[aircraft]\nmodel = \"3dof\"\n\n[environment.ship]\nforward_speed_mps = 0.0\n\n\
         [approach]\nstart_range_m = 500.0\n\n[dispersion]\nstart_height_offset_sd_m = 1.0\n\
         airspeed_error_sd_mps = 1.0\nsea_state_log_sd = 0.2\nwind_over_deck_sd_mps = 2.0\n",
    )
    .expect("scenario file");
    path.display().to_string()
}

/// Fails with the command's standard error unless it succeeded.
pub fn assert_success(output: &Output) {
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// The JSON document a command printed on standard output; fails the test with the
/// command's standard error unless it succeeded.
pub fn succeeded_json(output: &Output) -> serde_json::Value {
    assert_success(output);
    serde_json::from_slice(&output.stdout).expect("stdout is one JSON document")
}

/// The `summary.json` a command wrote into `folder`.
pub fn summary_json(folder: &Path) -> serde_json::Value {
    let text = std::fs::read_to_string(folder.join("summary.json")).expect("summary.json");
    serde_json::from_str(&text).expect("summary.json is JSON")
}

/// A campaign too long to finish (100 000 runs of `scenario` on two threads, into
/// `out`), as a command to spawn and stop with a signal.
pub fn endless_campaign(scenario: &str, out: &Path) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_deckland"));
    command.args([
        "campaign",
        scenario,
        "--runs",
        "100000",
        "--threads",
        "2",
        "--out",
        out.to_str().expect("a UTF-8 path"),
    ]);
    command
}

/// Sends `signal` (`"INT"`, `"TERM"`, …) to a running `child` after `after_ms`
/// milliseconds, as a user or a scheduler would, and waits for it to end.
pub fn signal_after(child: std::process::Child, signal: &str, after_ms: u64) -> Output {
    std::thread::sleep(std::time::Duration::from_millis(after_ms));
    let sent = Command::new("kill")
        .args([format!("-{signal}"), child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(sent.success(), "kill -{signal} failed");
    child.wait_with_output().expect("the child ends")
}
