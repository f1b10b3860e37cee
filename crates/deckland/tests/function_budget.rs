//! Every library function fits on a screen: no function in `src/` (outside its test
//! modules) is longer than [`MAX_FUNCTION_LINES`], counted from its `fn` line to its
//! closing brace as `tools/long_functions.py` of the shared folder counts them: a file's
//! lines from its first `#[cfg(test)]` module on are left out, and so are the files of
//! test modules (`tests.rs`) and `tests/` folders; nested functions are counted too.

use std::path::{Path, PathBuf};

/// The longest a library function may be (lines).
const MAX_FUNCTION_LINES: usize = 80;

fn source_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("src")
}

/// The library's `.rs` files under `dir`, without test-module files and `tests/` folders.
fn library_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).expect("readable source folder") {
        let path = entry.expect("readable entry").path();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default();
        if path.is_dir() {
            if !matches!(name, "tests" | "target" | "benches") {
                library_files(&path, out);
            }
        } else if name.ends_with(".rs") && name != "tests.rs" {
            out.push(path);
        }
    }
}

/// `line` without its comment and with string and character literals emptied, so that
/// their braces are not counted.
fn code_of(line: &str) -> String {
    let chars: Vec<char> = line.chars().collect();
    let mut code = String::new();
    let mut i = 0;
    while i < chars.len() {
        match chars[i] {
            '/' if chars.get(i + 1) == Some(&'/') => break,
            '"' => {
                i += 1;
                while i < chars.len() && chars[i] != '"' {
                    i += if chars[i] == '\\' { 2 } else { 1 };
                }
                code.push_str("\"\"");
            }
            // A character literal ('x' or '\x'); a lifetime's quote stays.
            '\'' if chars.get(i + 1) == Some(&'\\') && chars.get(i + 3) == Some(&'\'') => {
                code.push_str("''");
                i += 3;
            }
            '\'' if chars.get(i + 1).is_some_and(|c| *c != '\'' && *c != '\\')
                && chars.get(i + 2) == Some(&'\'') =>
            {
                code.push_str("''");
                i += 2;
            }
            c => code.push(c),
        }
        i += 1;
    }
    code
}

/// The name of the function `code` declares (`pub(crate) const fn name…`), if any.
fn declared_function(code: &str) -> Option<&str> {
    let mut rest = code.trim_start();
    if let Some(after) = rest.strip_prefix("pub") {
        let after = match after.strip_prefix('(') {
            Some(inner) => &inner[inner.find(')')? + 1..],
            None => after,
        };
        if !after.starts_with(char::is_whitespace) {
            return None;
        }
        rest = after.trim_start();
    }
    for qualifier in ["const", "async", "unsafe"] {
        if let Some(after) = rest.strip_prefix(qualifier) {
            if after.starts_with(char::is_whitespace) {
                rest = after.trim_start();
            }
        }
    }
    let after = rest.strip_prefix("fn")?;
    if !after.starts_with(char::is_whitespace) {
        return None;
    }
    let after = after.trim_start();
    let end = after
        .find(|c: char| !(c.is_alphanumeric() || c == '_'))
        .unwrap_or(after.len());
    (end > 0).then(|| &after[..end])
}

/// The lines of the function declared on `lines[start]`, from its `fn` line to its
/// closing brace; 0 for a declaration without a body.
fn function_length(lines: &[String], start: usize) -> usize {
    let mut depth = 0_i64;
    let mut started = false;
    for (j, code) in lines.iter().enumerate().skip(start) {
        if !started && code.contains(';') && !code.contains('{') {
            return 0;
        }
        for c in code.chars() {
            match c {
                '{' => {
                    depth += 1;
                    started = true;
                }
                '}' => depth -= 1,
                _ => {}
            }
        }
        if started && depth <= 0 {
            return j - start + 1;
        }
    }
    if started {
        lines.len() - start
    } else {
        0
    }
}

/// Every function of `text` longer than `budget`: (first line, name, length), the first
/// line counted from 1. Lines from the first `#[cfg(test)]` module on are left out.
fn long_functions(text: &str, budget: usize) -> Vec<(usize, String, usize)> {
    let raw: Vec<&str> = text.split('\n').collect();
    let is_test_attribute = |line: &str| line.trim_start().starts_with("#[cfg(test)]");
    let is_module = |line: &str| {
        let line = line.trim_start();
        line.starts_with("mod ") || line.starts_with("pub mod ")
    };
    let cut = (0..raw.len())
        .find(|&k| k + 1 < raw.len() && is_test_attribute(raw[k]) && is_module(raw[k + 1]))
        .unwrap_or(raw.len());
    let lines: Vec<String> = raw[..cut].iter().map(|line| code_of(line)).collect();
    let mut long = Vec::new();
    for (k, code) in lines.iter().enumerate() {
        if let Some(name) = declared_function(code) {
            let length = function_length(&lines, k);
            if length > budget {
                long.push((k + 1, name.to_owned(), length));
            }
        }
    }
    long
}

#[test]
fn no_library_function_is_longer_than_80_lines() {
    let mut files = Vec::new();
    library_files(&source_dir(), &mut files);
    files.sort();
    let mut long = Vec::new();
    for file in &files {
        let text = std::fs::read_to_string(file).expect("readable file");
        let relative = file.strip_prefix(source_dir()).expect("inside src");
        for (line, name, length) in long_functions(&text, MAX_FUNCTION_LINES) {
            long.push(format!(
                "{}:{line} {name} ({length} lines)",
                relative.display()
            ));
        }
    }
    assert!(
        long.is_empty(),
        "split these functions (at most {MAX_FUNCTION_LINES} lines each):\n{}",
        long.join("\n")
    );
}

#[test]
fn the_counter_finds_a_planted_long_function_and_skips_tests() {
    let body = "    let x = \"{\"; // }\n".repeat(5);
    let text = format!(
        "pub(crate) fn short() {{\n}}\n\nfn long(\n    a: u8,\n) {{\n{body}}}\n\
         fn declared();\n#[cfg(test)]\nmod tests {{\n    fn long_test() {{\n{body}    }}\n}}\n"
    );
    // `long` spans its `fn` line, a parameter, the brace line, 5 body lines and its end.
    assert_eq!(long_functions(&text, 8), vec![(4, "long".to_owned(), 9)]);
    assert!(long_functions(&text, 9).is_empty());
    assert_eq!(declared_function("pub const fn len(&self)"), Some("len"));
    assert_eq!(declared_function("let function = 1;"), None);
    assert_eq!(
        code_of("let c = '{'; let s = \"}\"; // {"),
        "let c = ''; let s = \"\"; "
    );
}
