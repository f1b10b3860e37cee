//! Inside the folders whose modules are peers — the control laws and their design code,
//! the environment — the sub-modules import each other in no circle, so that the generic
//! design code never depends on a concrete law and a new law or model is one more leaf.
//!
//! A folder's sub-modules are its files and sub-folders; its `mod.rs` is the facade that
//! declares them and re-exports their items (and, for the pitch laws, holds the registry
//! that the registry macro generates). A sub-module depends on another when any of its
//! files (code or doc links) names it through the parent — `super::other`,
//! `super::super::other` from a deeper file, or the full `crate::…::other` — or names an
//! item that the facade re-exports from it. An item named through the parent that the
//! facade neither re-exports from a sub-module nor from outside the folder is the
//! facade's own, and then the sub-module depends on the facade, which depends on every
//! sub-module it declares.

mod common;

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// The name under which the facade itself appears in the graph.
const FACADE: &str = "mod.rs";

fn folder(relative: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("src")
        .join(relative)
}

/// Every `.rs` file under `dir`, with its depth below `dir` (0 for `dir/x.rs`).
fn rust_files(dir: &Path, depth: usize, out: &mut Vec<(PathBuf, usize)>) {
    for entry in std::fs::read_dir(dir).expect("readable source folder") {
        let path = entry.expect("readable entry").path();
        if path.is_dir() {
            rust_files(&path, depth + 1, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push((path, depth));
        }
    }
}

fn identifier(text: &str) -> String {
    text.chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// The first path segment of every item of a `{a, b::c, D}` group starting at `text`.
fn group_heads(text: &str) -> Vec<String> {
    let mut heads = Vec::new();
    let mut depth = 0;
    let mut at_item = true;
    for (i, c) in text.char_indices() {
        match c {
            '{' => {
                depth += 1;
                at_item = depth == 1;
            }
            '}' => {
                depth -= 1;
                if depth == 0 {
                    break;
                }
            }
            ',' if depth == 1 => at_item = true,
            c if at_item && depth == 1 && (c.is_ascii_alphanumeric() || c == '_') => {
                heads.push(identifier(&text[i..]));
                at_item = false;
            }
            _ => {}
        }
    }
    heads
}

/// The names `text` reaches through `prefix` (`super::`, `crate::control::pitch::`):
/// `prefix name` and every head of `prefix {…}`.
fn names_after(text: &str, prefix: &str) -> BTreeSet<String> {
    let mut names = BTreeSet::new();
    for (i, _) in text.match_indices(prefix) {
        let rest = &text[i + prefix.len()..];
        // `super::super::x` is not reached through a single `super::`.
        if prefix.starts_with("super::") && text[..i].ends_with("super::") {
            continue;
        }
        if rest.starts_with('{') {
            names.extend(group_heads(rest));
        } else {
            let name = identifier(rest);
            if !name.is_empty() && name != "super" {
                names.insert(name);
            }
        }
    }
    names
}

/// What the facade re-exports: item name → the first segment of its path (a sub-module,
/// `crate`, or another outside path).
fn reexports(facade: &str) -> BTreeMap<String, String> {
    let mut map = BTreeMap::new();
    for (i, _) in facade.match_indices("pub use ") {
        let statement = &facade[i + 8..];
        let statement = &statement[..statement.find(';').unwrap_or(statement.len())];
        let head = identifier(statement);
        let rest = &statement[head.len()..];
        let names: Vec<String> = match rest.find('{') {
            Some(open) => group_heads(&rest[open..]),
            None => vec![identifier(
                rest.rsplit("::").next().unwrap_or_default().trim(),
            )],
        };
        for name in names {
            map.insert(name, head.clone());
        }
    }
    map
}

/// The import graph of the sub-modules of `relative` (e.g. `control/pitch`), whose full
/// module path is `module_path` (e.g. `crate::control::pitch`).
fn graph_of(relative: &str, module_path: &str) -> BTreeMap<String, BTreeSet<String>> {
    let dir = folder(relative);
    let facade = std::fs::read_to_string(dir.join("mod.rs")).expect("a mod.rs");
    let exported = reexports(&facade);
    let mut files = Vec::new();
    rust_files(&dir, 0, &mut files);
    let module_of = |file: &Path| -> String {
        let relative = file.strip_prefix(&dir).expect("inside the folder");
        let first = relative
            .components()
            .next()
            .and_then(|c| c.as_os_str().to_str())
            .expect("a name");
        first.strip_suffix(".rs").unwrap_or(first).to_owned()
    };
    let children: BTreeSet<String> = files
        .iter()
        .map(|(file, _)| module_of(file))
        .filter(|m| m != "mod")
        .collect();
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    graph.insert(FACADE.to_owned(), children.clone());
    for (file, depth) in &files {
        let module = module_of(file);
        if module == "mod" {
            continue;
        }
        let text = std::fs::read_to_string(file).expect("readable file");
        // From `dir/x.rs` and `dir/x/mod.rs` the parent is `super::`; one more `super::`
        // for each folder deeper.
        let in_own_folder_mod = file.file_name().is_some_and(|n| n == "mod.rs");
        let levels = if in_own_folder_mod { *depth } else { depth + 1 };
        let parent = "super::".repeat(levels);
        let mut names = names_after(&text, &format!("{module_path}::"));
        names.extend(names_after(&text, &parent));
        let edges = graph.entry(module.clone()).or_default();
        for name in names {
            let target = if children.contains(&name) {
                Some(name)
            } else {
                match exported.get(&name) {
                    Some(head) if children.contains(head) => Some(head.clone()),
                    Some(_) => None,
                    None => Some(FACADE.to_owned()),
                }
            };
            if let Some(target) = target.filter(|t| *t != module) {
                edges.insert(target);
            }
        }
    }
    graph
}

use common::cycle_from;

fn assert_acyclic(relative: &str, module_path: &str) -> BTreeMap<String, BTreeSet<String>> {
    let graph = graph_of(relative, module_path);
    for module in graph.keys() {
        let cycle = cycle_from(&graph, &mut vec![module.clone()]);
        assert!(
            cycle.is_none(),
            "import circle in {relative}: {}",
            cycle.unwrap_or_default().join(" → ")
        );
    }
    graph
}

#[test]
fn the_pitch_laws_import_each_other_in_no_circle() {
    let graph = assert_acyclic("control/pitch", "crate::control::pitch");
    // The design code is the axes' own module beside the laws, not a pitch module.
    assert!(!graph.contains_key("design"), "{graph:?}");
}

#[test]
fn the_design_code_imports_no_law_and_its_modules_no_circle() {
    assert_acyclic("control/design", "crate::control::design");
    let graph = assert_acyclic("control", "crate::control");
    // The generic design code names no axis's laws.
    let design = &graph["design"];
    for laws in ["pitch", "roll", "yaw", "lateral", FACADE] {
        assert!(!design.contains(laws), "design imports {laws}: {design:?}");
    }
    assert!(graph["pitch"].contains("design"), "{graph:?}");
}

#[test]
fn the_environment_modules_import_each_other_in_no_circle() {
    let graph = assert_acyclic("environment", "crate::environment");
    assert!(graph["turbulence"].contains("wind"), "{graph:?}");
    assert!(graph["wind_model"].contains("turbulence"), "{graph:?}");
}

#[test]
fn the_simulation_modules_import_each_other_in_no_circle() {
    // The loop's parts (issue 41): the closed loop uses the lateral loop, the blocks and
    // the bus; none of them reaches back up to it, and none imports through the facade.
    let graph = assert_acyclic("simulation", "crate::simulation");
    assert!(graph["closed_loop"].contains("lateral"), "{graph:?}");
    assert!(!graph["lateral"].contains("closed_loop"), "{graph:?}");
    assert!(!graph["signals"].contains("lateral"), "{graph:?}");
}

#[test]
fn the_circle_finder_sees_a_group_import_and_a_planted_circle() {
    assert_eq!(
        group_heads("{a, b::{c, d}, E}"),
        ["a".to_owned(), "b".to_owned(), "E".to_owned()]
    );
    let text = "use super::{law::X, design};\nuse super::super::y;";
    let names = names_after(text, "super::");
    assert_eq!(names, ["design", "law"].map(str::to_owned).into());
    let names = names_after(text, "super::super::");
    assert_eq!(names, ["y"].map(str::to_owned).into());
    let graph: BTreeMap<String, BTreeSet<String>> =
        [("a", vec!["b"]), ("b", vec!["c"]), ("c", vec!["a"])]
            .into_iter()
            .map(|(k, v)| (k.to_owned(), v.into_iter().map(str::to_owned).collect()))
            .collect();
    let cycle = cycle_from(&graph, &mut vec!["a".to_owned()]).expect("a cycle");
    assert_eq!(cycle, ["a", "b", "c", "a"]);
}
