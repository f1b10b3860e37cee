//! Every code block of README.md, python/README.md and docs/*.md runs in a test as
//! written, or says by its info string what it is (issue 46, item 2). The blocks are read
//! from the files when the test runs, never copied into it. The info strings:
//!
//! - ```` ```sh ````: commands, each line run here (the rules below).
//! - ```` ```sh synopsis ````: a command's usage (`[--option VALUE]`, `a|b`, placeholders
//!   in capitals), not run: the command must exist, each option must be one of its
//!   `--help`, and each value written out (no capital letter; `a|b` gives each) must be
//!   accepted: `deckland COMMAND --option VALUE --help` succeeds, which parses the value.
//! - ```` ```sh record ````: the commands behind published figures, some on files that the
//!   text describes but no block writes. Run as ```` ```sh ````, except a `deckland` line
//!   whose scenario is a bare file name (no `/`) that neither exists nor was written by an
//!   earlier line of the document: that line is checked as a synopsis.
//! - ```` ```toml ````: a scenario or a fragment of one, checked with
//!   `deckland scenario --check` (an aircraft `definition = "FILE"` that it names is
//!   written first, as `deckland aircraft --print-default` prints the F/A-18).
//! - ```` ```python ````, ```` ```python synopsis ````: run by
//!   python/tests/test_doc_blocks.py.
//! - ```` ```text ````: output, tables, equations, diagrams and listings, not run (the
//!   README's example outputs are compared with the binary by docs_match_the_binary.rs).
//!   A text block may not hold a command line (one starting `deckland ` or `cargo `).
//!
//! A shell line runs so:
//!
//! 1. Lines ending in `\` are joined to the next; blank lines and `#` lines are skipped,
//!    a trailing `# comment` is dropped. A trailing comment `# N = 3, 4, 6` (a word in
//!    capitals, then values) runs the line once per value with the word replaced.
//! 2. `cargo run --release -- COMMAND` is `deckland COMMAND`, the binary of these tests;
//!    a timing prefix `/usr/bin/time ` is dropped (not every machine has it).
//! 3. The placeholders of [`PLACEHOLDERS`] are replaced (whole words).
//! 4. Runs are shrunk by a fixed rule, never by editing a document: the value of
//!    `--runs N`, `--max-runs N` and `--calibrate-score N` becomes min(N, [`RUNS_CAP`]);
//!    a `rare` line also gets `--particles` min(P, [`RUNS_CAP`]) (P is 100 when the line
//!    gives none), and may end on the budget so shrunk ("cannot estimate the rate within
//!    --max-runs"): the arguments, the scenario and the event were accepted and the
//!    splitting started.
//! 5. It runs with `sh -c` (pipes and redirections as written) in a scratch folder of its
//!    document, in which `scenarios/` is the repository's and earlier lines' files are,
//!    with the binary's folder first on `PATH`; it must succeed.
//! 6. A line that is not a `deckland` command (installation, the test suites, the
//!    library's examples, Python scripts) is not run here: a rule of [`SKIPPED`] must
//!    name it (by its start, after `NAME=value` assignments), with the reason; a line
//!    that no rule names fails. A skipped line is still checked: the
//!    repository paths it names exist, its `--example NAME` is one of
//!    crates/deckland/examples/, the test that `cargo test … NAME` names is a `fn NAME`
//!    of the package.
//!
//! A failure names the document and the line of the command (or of the block's fence).

#![allow(clippy::unwrap_used)] // tests fail loudly by design

mod common;

use common::{deckland, deckland_in, scratch};
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

/// The most runs a command of a document flies here (`--runs`, `--max-runs`,
/// `--particles`).
const RUNS_CAP: u64 = 8;

/// Placeholders of shell lines and their values: `DIR` an output folder (in the scratch
/// folder); `EVENT` and `X` those of the first row of docs/rare-events.md's table
/// (`ramp_strike --threshold -2.5`).
const PLACEHOLDERS: &[(&str, &str)] =
    &[("DIR", "doc-out"), ("EVENT", "ramp_strike"), ("X", "-2.5")];

/// Lines that are not `deckland` commands, by their start, and why each is not run here.
const SKIPPED: &[(&str, &str)] = &[
    (
        "./test",
        "the project's test command: it runs this test (recursion)",
    ),
    (
        "bash python/ci.sh",
        "the Python package's CI, which ./test runs",
    ),
    ("pytest", "the Python suite, which python/ci.sh runs"),
    (
        "cargo test ",
        "a test of the library, which `cargo test --workspace` runs (it must exist)",
    ),
    (
        "cargo build ",
        "builds the binary that these tests run (cargo built it for them)",
    ),
    (
        "cargo run --release -p deckland --example ",
        "an example of the library: cargo gives a test no example's binary (`cargo test \
         --workspace` builds them), and a nested cargo would wait on this build's lock \
         (it must exist)",
    ),
    (
        "pip install ",
        "installs the Python package, as python/ci.sh does before its tests",
    ),
    (
        "python -m venv ",
        "makes a virtual environment for the Python package (python/ci.sh makes its own)",
    ),
    (
        "python ",
        "a Python script (benchmark, training): it needs the installed package, which only \
         python/ci.sh's environment has (the script must exist)",
    ),
];

/// The repository's root.
fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../..")
        .canonicalize()
        .unwrap()
}

/// The documents whose blocks are checked, relative to the root: README.md,
/// python/README.md and every docs/*.md.
fn documents() -> Vec<String> {
    let mut docs: Vec<String> = std::fs::read_dir(root().join("docs"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(".md"))
        .map(|name| format!("docs/{name}"))
        .collect();
    docs.sort();
    let mut all = vec!["README.md".to_owned(), "python/README.md".to_owned()];
    all.append(&mut docs);
    all
}

/// What a block is, by its info string.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
enum Class {
    Shell,
    Synopsis,
    Record,
    Toml,
    Python,
    PythonSynopsis,
    Text,
}

impl Class {
    const INFO: [(&'static str, Class); 7] = [
        ("sh", Class::Shell),
        ("sh synopsis", Class::Synopsis),
        ("sh record", Class::Record),
        ("toml", Class::Toml),
        ("python", Class::Python),
        ("python synopsis", Class::PythonSynopsis),
        ("text", Class::Text),
    ];

    fn of(info: &str) -> Option<Class> {
        Self::INFO
            .iter()
            .find(|(name, _)| *name == info)
            .map(|(_, class)| *class)
    }

    fn name(self) -> &'static str {
        Self::INFO.iter().find(|(_, c)| *c == self).unwrap().0
    }
}

/// A fenced code block of a document.
#[derive(Debug, Clone)]
struct Block {
    /// The document, relative to the root.
    file: String,
    /// The line of the opening fence (from 1).
    line: usize,
    /// The info string, trimmed.
    info: String,
    /// The lines inside the fence with their line numbers, the fence's indent removed.
    lines: Vec<(usize, String)>,
}

impl Block {
    fn class(&self) -> Option<Class> {
        Class::of(&self.info)
    }
}

/// The fenced code blocks of `text`, the document `file`.
fn blocks_of(file: &str, text: &str) -> Vec<Block> {
    let mut blocks = Vec::new();
    let mut lines = text.lines().enumerate();
    while let Some((index, line)) = lines.next() {
        let indent = line.len() - line.trim_start_matches(' ').len();
        let Some(info) = line[indent..].strip_prefix("```") else {
            continue;
        };
        let mut body = Vec::new();
        let mut closed = false;
        for (inner_index, inner) in lines.by_ref() {
            if inner.trim() == "```" {
                closed = true;
                break;
            }
            let spaces = inner.len() - inner.trim_start_matches(' ').len();
            body.push((inner_index + 1, inner[spaces.min(indent)..].to_owned()));
        }
        assert!(closed, "{file}:{}: a code block is not closed", index + 1);
        blocks.push(Block {
            file: file.to_owned(),
            line: index + 1,
            info: info.trim().to_owned(),
            lines: body,
        });
    }
    blocks
}

fn blocks_of_document(file: &str) -> Vec<Block> {
    let text = std::fs::read_to_string(root().join(file))
        .unwrap_or_else(|e| panic!("cannot read {file}: {e}"));
    blocks_of(file, &text)
}

/// The commands of a block with the line each starts on: `\` continues a line, as does a
/// line starting with `[` (a synopsis' options); blank and `#` lines are left out.
fn logical_lines(block: &Block) -> Vec<(usize, String)> {
    let mut out: Vec<(usize, String)> = Vec::new();
    let mut continued = false;
    for (number, line) in &block.lines {
        let line = line.trim();
        let joins = continued || (line.starts_with('[') && !out.is_empty());
        let (text, continues) = match line.strip_suffix('\\') {
            Some(text) => (text.trim_end(), true),
            None => (line, false),
        };
        if joins {
            let last = &mut out.last_mut().unwrap().1;
            last.push(' ');
            last.push_str(text);
        } else if !text.is_empty() && !text.starts_with('#') {
            out.push((*number, text.to_owned()));
        }
        continued = continues;
    }
    out
}

/// `line` without its trailing `# comment` (outside quotes), and the comment.
fn split_comment(line: &str) -> (&str, Option<&str>) {
    let mut quote = None;
    let mut previous = ' ';
    for (at, c) in line.char_indices() {
        match (quote, c) {
            (None, '\'' | '"') => quote = Some(c),
            (Some(q), _) if c == q => quote = None,
            (None, '#') if previous.is_whitespace() => {
                return (line[..at].trim_end(), Some(line[at + 1..].trim()));
            }
            _ => {}
        }
        previous = c;
    }
    (line.trim_end(), None)
}

/// `text` with each whole-word `word` (not next to a letter, digit or `_`) replaced.
fn replace_word(text: &str, word: &str, with: &str) -> String {
    let is_word = |c: Option<char>| c.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_');
    let mut out = String::new();
    let mut from = 0;
    for (at, _) in text.match_indices(word) {
        let before = text[..at].chars().next_back();
        let after = text[at + word.len()..].chars().next();
        if at >= from && !is_word(before) && !is_word(after) {
            out.push_str(&text[from..at]);
            out.push_str(with);
            from = at + word.len();
        }
    }
    out.push_str(&text[from..]);
    out
}

/// The line once per value of a trailing comment `# N = 3, 4, 6`, else once.
fn expanded(command: &str, comment: Option<&str>) -> Vec<String> {
    let expansion = comment
        .and_then(|c| c.split_once(" = "))
        .filter(|(name, _)| {
            !name.is_empty() && name.chars().all(|c| c.is_ascii_uppercase() || c == '_')
        });
    match expansion {
        Some((name, values)) => values
            .split(',')
            .map(|value| replace_word(command, name, value.trim()))
            .collect(),
        None => vec![command.to_owned()],
    }
}

/// The `deckland` command of a line (`cargo run --release -- ` mapped, `/usr/bin/time `
/// dropped), or `None` for another program.
fn as_deckland(command: &str) -> Option<String> {
    let command = command.strip_prefix("/usr/bin/time ").unwrap_or(command);
    if let Some(rest) = command.strip_prefix("cargo run --release -- ") {
        Some(format!("deckland {rest}"))
    } else if command.starts_with("deckland ") {
        Some(command.to_owned())
    } else {
        None
    }
}

/// The value of the whole-word option `option` in `text` set to min(value, `cap`), if
/// the option has a whole-number value; whether it was there.
fn shrink_option(text: &str, option: &str, cap: u64) -> (String, bool) {
    for (at, _) in text.match_indices(option) {
        let before = text[..at].chars().next_back();
        let rest = &text[at + option.len()..];
        if before.is_some_and(|c| !c.is_whitespace()) || !rest.starts_with(' ') {
            continue;
        }
        let value_start = at + option.len() + (rest.len() - rest.trim_start().len());
        let digits = text[value_start..]
            .chars()
            .take_while(|c| c.is_ascii_digit() || *c == '_')
            .count();
        let Ok(value) = text[value_start..value_start + digits]
            .replace('_', "")
            .parse::<u64>()
        else {
            continue;
        };
        let shrunk = format!(
            "{}{}{}",
            &text[..value_start],
            value.min(cap),
            &text[value_start + digits..]
        );
        return (shrunk, true);
    }
    (text.to_owned(), false)
}

/// A `deckland` line as it runs here: placeholders replaced, runs shrunk (the module's
/// rules 3 and 4); whether it is a `rare` line.
fn prepared(command: &str) -> (String, bool) {
    let mut text = command.to_owned();
    for (word, value) in PLACEHOLDERS {
        text = replace_word(&text, word, value);
    }
    for option in ["--runs", "--max-runs", "--calibrate-score"] {
        text = shrink_option(&text, option, RUNS_CAP).0;
    }
    let rare = text.split_whitespace().nth(1) == Some("rare");
    if rare {
        let (shrunk, given) = shrink_option(&text, "--particles", RUNS_CAP);
        text = if given {
            shrunk
        } else {
            text.replacen(
                "deckland rare ",
                &format!("deckland rare --particles {RUNS_CAP} "),
                1,
            )
        };
    }
    (text, rare)
}

/// The long options of `deckland COMMAND --help`, each with whether it takes a value;
/// `None` if there is no such command.
fn options_of(command: &str) -> Option<BTreeMap<String, bool>> {
    let output = deckland([command, "--help"]);
    if !output.status.success() {
        return None;
    }
    let help = String::from_utf8(output.stdout).unwrap();
    let mut options = BTreeMap::new();
    for line in help.lines().filter(|l| l.trim_start().starts_with('-')) {
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .collect();
        for (i, word) in words.iter().enumerate() {
            if word.starts_with("--") && word.len() > 2 {
                let takes_value = words.get(i + 1).is_some_and(|w| w.starts_with('<'));
                options.insert((*word).to_owned(), takes_value);
            }
        }
    }
    Some(options)
}

/// Checks a `deckland` line as a synopsis (the module's ```` ```sh synopsis ````).
fn check_usage(command: &str, at: &str, errors: &mut Vec<String>) {
    let text = command.replace(['[', ']'], " ");
    let words: Vec<&str> = text.split_whitespace().collect();
    let Some(sub) = words.get(1).copied() else {
        errors.push(format!("{at}: `{command}` names no command"));
        return;
    };
    let Some(options) = options_of(sub) else {
        errors.push(format!("{at}: `deckland {sub}`: there is no such command"));
        return;
    };
    let mut i = 2;
    while i < words.len() {
        let word = words[i];
        i += 1;
        if !word.starts_with("--") {
            continue; // a positional argument (a placeholder) or a value
        }
        match options.get(word) {
            None => errors.push(format!(
                "{at}: `{word}` is not an option of `deckland {sub}` (its --help)"
            )),
            Some(false) => {}
            Some(true) => {
                let value = words.get(i).copied().unwrap_or("");
                i += 1;
                if value.is_empty() || value.chars().any(|c| c.is_ascii_uppercase()) {
                    continue; // a placeholder
                }
                for alternative in value.split('|') {
                    let output = deckland([sub, word, alternative, "--help"]);
                    if !output.status.success() {
                        errors.push(format!(
                            "{at}: `deckland {sub} {word} {alternative}` is refused: {}",
                            String::from_utf8_lossy(&output.stderr).trim()
                        ));
                    }
                }
            }
        }
    }
}

/// The repository paths that a skipped line names (`./x`, or a path whose first part is
/// in the root), not those it redirects output to.
fn repository_paths(command: &str) -> Vec<String> {
    let root = root();
    let mut paths = Vec::new();
    let mut words = command.split_whitespace();
    while let Some(word) = words.next() {
        if word.starts_with('>') {
            words.next();
            continue;
        }
        let word = word.trim_matches(|c| c == '"' || c == '\'');
        let word = word.split('[').next().unwrap(); // "./python[test]"
        let path = match word.strip_prefix("./") {
            Some(path) => path,
            None if word.contains('/') && !word.starts_with('-') => {
                let first = word.split('/').next().unwrap();
                if first.is_empty() || !root.join(first).exists() {
                    continue;
                }
                word
            }
            None => continue,
        };
        paths.push(path.to_owned());
    }
    paths
}

/// Whether `fn name` is written in a `.rs` file under `folder`.
fn defines_fn(folder: &Path, name: &str) -> bool {
    let wanted = format!("fn {name}(");
    std::fs::read_dir(folder).unwrap().any(|entry| {
        let path = entry.unwrap().path();
        if path.is_dir() {
            defines_fn(&path, name)
        } else {
            path.extension().is_some_and(|e| e == "rs")
                && std::fs::read_to_string(&path).is_ok_and(|t| t.contains(&wanted))
        }
    })
}

/// Checks a line that is not run: a rule of [`SKIPPED`] names it, and what it names
/// exists.
fn check_skipped(command: &str, at: &str, errors: &mut Vec<String>) {
    let program = command
        .split_whitespace()
        .skip_while(|w| {
            w.split_once('=').is_some_and(|(name, _)| {
                !name.is_empty() && name.chars().all(|c| c.is_ascii_uppercase() || c == '_')
            })
        })
        .collect::<Vec<_>>()
        .join(" ");
    let Some((rule, _)) = SKIPPED
        .iter()
        .find(|(start, _)| program == start.trim_end() || program.starts_with(start))
    else {
        errors.push(format!(
            "{at}: `{command}` is neither a deckland command nor skipped by a rule of \
             SKIPPED in {}: run it, or add a rule",
            file!()
        ));
        return;
    };
    let root = root();
    for path in repository_paths(command) {
        if !root.join(&path).exists() {
            errors.push(format!(
                "{at}: `{command}` names {path}, which does not exist"
            ));
        }
    }
    let words: Vec<&str> = program.split_whitespace().collect();
    if rule.contains("--example") {
        let example = words[words.iter().position(|w| *w == "--example").unwrap() + 1];
        let file = root.join(format!("crates/deckland/examples/{example}.rs"));
        if !file.exists() {
            errors.push(format!("{at}: there is no example `{example}`"));
        }
    }
    if *rule == "cargo test " {
        let package = words
            .iter()
            .position(|w| *w == "-p")
            .map_or("deckland", |i| words[i + 1]);
        let end = words.iter().position(|w| *w == "--").unwrap_or(words.len());
        let name = words[..end]
            .iter()
            .rev()
            .find(|w| !w.starts_with('-'))
            .unwrap();
        if !defines_fn(&root.join("crates").join(package), name) {
            errors.push(format!(
                "{at}: package `{package}` has no test `fn {name}` for `{command}`"
            ));
        }
    }
}

/// Runs `command` with `sh -c` in `dir`, the binary's folder first on `PATH`.
fn sh(dir: &Path, command: &str) -> Output {
    let binary_dir = Path::new(env!("CARGO_BIN_EXE_deckland")).parent().unwrap();
    let path = std::env::var_os("PATH").unwrap_or_default();
    let mut paths = vec![binary_dir.to_path_buf()];
    paths.extend(std::env::split_paths(&path));
    Command::new("sh")
        .arg("-c")
        .arg(command)
        .current_dir(dir)
        .env("PATH", std::env::join_paths(paths).unwrap())
        .stdin(Stdio::null())
        .output()
        .expect("sh runs")
}

/// The last lines of a command's standard error, for a failure's message.
fn tail(bytes: &[u8]) -> String {
    let text = String::from_utf8_lossy(bytes);
    let lines: Vec<&str> = text.lines().collect();
    lines[lines.len().saturating_sub(12)..].join("\n")
}

/// Runs (or checks) the commands of `blocks` — the ```` ```sh ````, ```` ```sh record ````
/// and ```` ```sh synopsis ```` blocks, in order — in the scratch folder `name`; the
/// failures, each naming its document and line.
fn run_shell_blocks(blocks: &[Block], name: &str) -> Vec<String> {
    let dir = scratch(name);
    std::fs::create_dir_all(&dir).unwrap();
    std::os::unix::fs::symlink(root().join("scenarios"), dir.join("scenarios")).unwrap();
    let mut errors = Vec::new();
    for block in blocks {
        let class = block.class();
        if !matches!(class, Some(Class::Shell | Class::Record | Class::Synopsis)) {
            continue;
        }
        for (line, text) in logical_lines(block) {
            let at = format!("{}:{line}", block.file);
            let (command, comment) = split_comment(&text);
            for command in expanded(command, comment) {
                let Some(deckland) = as_deckland(&command) else {
                    eprintln!("{at}: not run (a rule of SKIPPED): {command}");
                    check_skipped(&command, &at, &mut errors);
                    continue;
                };
                if class == Some(Class::Synopsis) {
                    eprintln!("{at}: checked as a synopsis: {deckland}");
                    check_usage(&deckland, &at, &mut errors);
                    continue;
                }
                if deckland.contains('[') {
                    errors.push(format!(
                        "{at}: `{command}` is a synopsis in a ```{} block: mark the block \
                         ```sh synopsis",
                        block.info
                    ));
                    continue;
                }
                let words: Vec<&str> = deckland.split_whitespace().collect();
                let scenario = match words.get(1) {
                    Some(&"run" | &"campaign" | &"rare") => words.get(2).copied(),
                    _ => None,
                };
                let described_only = scenario.is_some_and(|s| {
                    !s.starts_with('-') && !s.contains('/') && !dir.join(s).exists()
                });
                if class == Some(Class::Record) && described_only {
                    eprintln!("{at}: a file no line writes, checked as a synopsis: {deckland}");
                    check_usage(&deckland, &at, &mut errors);
                    continue;
                }
                let (run, rare) = prepared(&deckland);
                let started = std::time::Instant::now();
                let output = sh(&dir, &run);
                eprintln!("{at}: {run} ({:.1} s)", started.elapsed().as_secs_f64());
                let stopped_on_budget = rare
                    && String::from_utf8_lossy(&output.stderr).contains(&format!(
                        "cannot estimate the rate within --max-runs {RUNS_CAP}"
                    ));
                if !output.status.success() && !stopped_on_budget {
                    errors.push(format!(
                        "{at}: `{command}` failed (run as `{run}` in {}): {}\n{}",
                        dir.display(),
                        output.status,
                        tail(&output.stderr)
                    ));
                }
            }
        }
    }
    if errors.is_empty() {
        let _ = std::fs::remove_dir_all(&dir);
    }
    errors
}

/// Fails with every error, one a paragraph.
fn assert_none(errors: &[String]) {
    assert!(
        errors.is_empty(),
        "{} failed:\n\n{}",
        errors.len(),
        errors.join("\n\n")
    );
}

/// The shell blocks of the documents `files`, in the scratch folder `name`, one each.
fn run_shell_blocks_of(files: &[String]) {
    let mut errors = Vec::new();
    for file in files {
        let name = format!("doc-blocks-{}", file.replace(['/', '.'], "-"));
        errors.extend(run_shell_blocks(&blocks_of_document(file), &name));
    }
    assert_none(&errors);
}

/// The errors of `blocks`' info strings: each must be one of [`Class::INFO`], and a
/// ```` ```text ```` block may hold no command.
fn info_string_errors(blocks: &[Block]) -> Vec<String> {
    let mut errors = Vec::new();
    for block in blocks {
        match block.class() {
            None => errors.push(format!(
                "{}:{}: info string `{}`: expected one of {:?}",
                block.file,
                block.line,
                block.info,
                Class::INFO.map(|(name, _)| name)
            )),
            Some(Class::Text) => {
                for (line, text) in &block.lines {
                    let text = text.trim_start();
                    if text.starts_with("deckland ") || text.starts_with("cargo ") {
                        errors.push(format!(
                            "{}:{line}: a command in a ```text block: mark the block ```sh \
                             (or ```sh record, ```sh synopsis)",
                            block.file
                        ));
                    }
                }
            }
            Some(_) => {}
        }
    }
    errors
}

/// Every block says what it is (an info string of [`Class::INFO`]; a ```` ```text ````
/// block holds no command). Prints the blocks of each document by class.
#[test]
fn every_block_says_what_it_is() {
    let mut errors = Vec::new();
    let mut total = BTreeMap::new();
    for file in documents() {
        let blocks = blocks_of_document(&file);
        errors.extend(info_string_errors(&blocks));
        let mut counts: BTreeMap<Class, usize> = BTreeMap::new();
        for class in blocks.iter().filter_map(Block::class) {
            *counts.entry(class).or_default() += 1;
            *total.entry(class).or_insert(0) += 1;
        }
        let listed: Vec<String> = counts
            .iter()
            .map(|(class, n)| format!("{n} {}", class.name()))
            .collect();
        eprintln!("{file}: {} blocks ({})", blocks.len(), listed.join(", "));
    }
    let listed: Vec<String> = total
        .iter()
        .map(|(class, n)| format!("{n} {}", class.name()))
        .collect();
    eprintln!(
        "in all: {} blocks ({})",
        total.values().sum::<usize>(),
        listed.join(", ")
    );
    assert_none(&errors);
    for class in [
        Class::Shell,
        Class::Synopsis,
        Class::Toml,
        Class::Python,
        Class::Text,
    ] {
        assert!(total.contains_key(&class), "no ```{} block", class.name());
    }
}

/// The README's shell blocks run as written (the module's rules).
#[test]
fn the_readmes_commands_run() {
    run_shell_blocks_of(&["README.md".to_owned()]);
}

/// python/README.md's shell blocks: installation and development, each skipped by a rule.
#[test]
fn the_python_readmes_commands_run() {
    run_shell_blocks_of(&["python/README.md".to_owned()]);
}

/// docs/*.md's shell blocks run as written (the module's rules).
#[test]
fn the_docs_commands_run() {
    let docs: Vec<String> = documents()
        .into_iter()
        .filter(|d| d.starts_with("docs/"))
        .collect();
    run_shell_blocks_of(&docs);
}

/// Every ```` ```toml ```` block is a scenario (or a fragment) that the loader accepts.
#[test]
fn every_toml_block_is_a_scenario_the_loader_accepts() {
    let mut errors = Vec::new();
    let mut checked = 0;
    for file in documents() {
        for block in blocks_of_document(&file) {
            if block.class() != Some(Class::Toml) {
                continue;
            }
            checked += 1;
            let dir = scratch(&format!("doc-toml-{checked}"));
            std::fs::create_dir_all(&dir).unwrap();
            let text: Vec<&str> = block.lines.iter().map(|(_, l)| l.as_str()).collect();
            let text = text.join("\n") + "\n";
            for line in text.lines() {
                let line = split_comment(line).0;
                if let Some((key, value)) = line.split_once('=') {
                    if key.trim() == "definition" {
                        let aircraft = deckland(["aircraft", "--print-default"]);
                        assert!(aircraft.status.success());
                        let name = value.trim().trim_matches('"');
                        std::fs::write(dir.join(name), aircraft.stdout).unwrap();
                    }
                }
            }
            std::fs::write(dir.join("doc-block.toml"), &text).unwrap();
            let output = deckland_in(&dir, ["scenario", "--check", "doc-block.toml"]);
            if output.status.success() {
                let _ = std::fs::remove_dir_all(&dir);
            } else {
                errors.push(format!(
                    "{}:{}: the ```toml block is not a valid scenario: {}",
                    block.file,
                    block.line,
                    tail(&output.stderr)
                ));
            }
        }
    }
    assert!(checked > 0, "no ```toml block");
    assert_none(&errors);
}

/// The checks can fail, naming the document and the line: a command that fails, a
/// synopsis with an option the command does not have or a value it refuses, a command
/// in a text block, a line no rule names, an example that does not exist.
#[test]
fn a_broken_block_fails_naming_its_document_and_line() {
    let text = "# Broken\n\
                \n\
                ```sh\n\
                deckland campaign scenarios/no-such-sea.toml --runs 100 --seed 1\n\
                cargo run --release -p deckland --example no_such_example\n\
                make everything\n\
                ```\n\
                \n\
                ```sh synopsis\n\
                cargo run --release -- land [--controller opd|lqr]\n\
                \x20   [--no-such-option] [--seed N]\n\
                ```\n\
                \n\
                ```text\n\
                deckland campaign scenarios/sea-state-5.toml --runs 3\n\
                ```\n";
    let blocks = blocks_of("broken.md", text);
    let mut errors = run_shell_blocks(&blocks, "doc-blocks-broken");
    errors.extend(info_string_errors(&blocks));
    let expected = [
        ("broken.md:4:", "no-such-sea.toml"),
        ("broken.md:5:", "no example `no_such_example`"),
        ("broken.md:6:", "neither a deckland command nor skipped"),
        ("broken.md:10:", "--controller lqr"),
        ("broken.md:10:", "`--no-such-option` is not an option"),
        ("broken.md:15:", "a command in a ```text block"),
    ];
    for (at, words) in expected {
        assert!(
            errors
                .iter()
                .any(|e| e.starts_with(at) && e.contains(words)),
            "no error `{at} … {words}` among {errors:#?}"
        );
    }
    assert_eq!(errors.len(), expected.len(), "{errors:#?}");
    let _ = std::fs::remove_dir_all(scratch("doc-blocks-broken"));
}

/// The rules that rewrite a line before it runs.
#[test]
fn the_rules_rewrite_lines_as_documented() {
    assert_eq!(
        prepared("deckland campaign a.toml --runs 30000 --seed 7 --shard 0/3 --out shard-0").0,
        "deckland campaign a.toml --runs 8 --seed 7 --shard 0/3 --out shard-0"
    );
    assert_eq!(
        prepared("deckland campaign a.toml --runs 3 --out DIR --force").0,
        "deckland campaign a.toml --runs 3 --out doc-out --force"
    );
    assert_eq!(
        prepared("deckland rare a.toml --event EVENT --max-runs 20000 --calibrate-score 100").0,
        "deckland rare --particles 8 a.toml --event ramp_strike --max-runs 8 --calibrate-score 8"
    );
    assert_eq!(
        prepared("deckland rare a.toml --event EVENT --threshold X --max-runs 20000"),
        (
            "deckland rare --particles 8 a.toml --event ramp_strike --threshold -2.5 \
             --max-runs 8"
                .to_owned(),
            true
        )
    );
    assert_eq!(
        as_deckland("/usr/bin/time deckland trim").as_deref(),
        Some("deckland trim")
    );
    assert_eq!(
        as_deckland("cargo run --release -- land").as_deref(),
        Some("deckland land")
    );
    assert_eq!(
        as_deckland("cargo run --release -p deckland --example x"),
        None
    );
    let (command, comment) =
        split_comment("deckland campaign scenarios/sea-state-N.toml --runs 3   # N = 3, 4, 6");
    assert_eq!(
        expanded(command, comment),
        [3, 4, 6].map(|n| format!("deckland campaign scenarios/sea-state-{n}.toml --runs 3"))
    );
    assert_eq!(
        split_comment("sed 's/#x/y/' > a # note"),
        ("sed 's/#x/y/' > a", Some("note"))
    );
    let paths: BTreeSet<String> =
        repository_paths("pip install maturin && pip install -e \"./python[test]\" > .venv/x")
            .into_iter()
            .collect();
    assert_eq!(paths, BTreeSet::from(["python".to_owned()]));
}
