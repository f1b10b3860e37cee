//! Scenario files: TOML text to a checked [`Scenario`], with errors that name the file,
//! the line and the field, and state what is allowed.
//!
//! Loading takes the text ([`load_scenario`]); the one file-system access is
//! [`read_text_file`], which reads a file with a size limit, regular files only (never a
//! FIFO, a device or `/dev/zero`, which would block or never end), for every front end
//! ([`MAX_SCENARIO_FILE_BYTES`] for scenario files).
//! Three kinds of problem are told apart ([`ScenarioError`]): text that is not TOML,
//! keys or values that do not fit the scenario's structure (unknown keys, wrong types,
//! unknown names), and values outside their allowed range (every check of
//! [`Scenario::validate`]). For the last kind the line is that of the key in the file; a
//! value not set in the file has no line (its default was used).

use std::io::Read;
use std::ops::Range;
use std::path::Path;

use toml_edit::{ImDocument, InlineTable, Item, Table, Value};

use super::{AircraftDefinition, Mission, Scenario};
use crate::parameters::{join, ParameterError};

/// Largest scenario file (bytes): the commented default file is about 10 kB.
pub const MAX_SCENARIO_FILE_BYTES: u64 = 1024 * 1024;

/// Why a file could not be read as text.
#[derive(Debug, thiserror::Error)]
pub enum ReadError {
    /// The file could not be opened or read.
    #[error("cannot read {path}: {source}")]
    Io {
        /// The file.
        path: String,
        /// The system's reason.
        source: std::io::Error,
    },
    /// Not a regular file (a folder, a FIFO, a device such as `/dev/zero`).
    #[error("{path} is {kind}, not a regular file: deckland reads files only")]
    NotAFile {
        /// The file.
        path: String,
        /// What it is instead.
        kind: &'static str,
    },
    /// Larger than the limit.
    #[error("{path} is larger than {limit} bytes, more than a {what} can be")]
    TooLarge {
        /// The file.
        path: String,
        /// The limit (bytes).
        limit: u64,
        /// What the file was read as.
        what: &'static str,
    },
    /// Not UTF-8 text.
    #[error("{path} is not UTF-8 text ({source})")]
    NotText {
        /// The file.
        path: String,
        /// Where the text breaks.
        source: std::string::FromUtf8Error,
    },
}

/// What a file of type `file_type` is, in words.
fn kind_of(file_type: std::fs::FileType) -> &'static str {
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if file_type.is_fifo() {
            return "a FIFO";
        }
        if file_type.is_char_device() || file_type.is_block_device() {
            return "a device";
        }
        if file_type.is_socket() {
            return "a socket";
        }
    }
    if file_type.is_dir() {
        "a folder"
    } else {
        "not a regular file"
    }
}

/// Reads the text of the regular file `path` (following links), of at most `limit`
/// bytes; `what` names it in messages (e.g. `scenario file`). A FIFO, a device or a
/// folder is refused before it is opened (opening a FIFO would wait for a writer), and
/// the file opened is checked again, so a file swapped meanwhile is refused too.
pub fn read_text_file(path: &Path, limit: u64, what: &'static str) -> Result<String, ReadError> {
    let shown = || path.display().to_string();
    let io = |source| ReadError::Io {
        path: shown(),
        source,
    };
    let check = |metadata: std::fs::Metadata| {
        if !metadata.is_file() {
            return Err(ReadError::NotAFile {
                path: shown(),
                kind: kind_of(metadata.file_type()),
            });
        }
        if metadata.len() > limit {
            return Err(ReadError::TooLarge {
                path: shown(),
                limit,
                what,
            });
        }
        Ok(())
    };
    check(std::fs::metadata(path).map_err(io)?)?;
    let file = std::fs::File::open(path).map_err(io)?;
    check(file.metadata().map_err(io)?)?;
    let mut bytes = Vec::new();
    file.take(limit.saturating_add(1))
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > limit {
        return Err(ReadError::TooLarge {
            path: shown(),
            limit,
            what,
        });
    }
    String::from_utf8(bytes).map_err(|source| ReadError::NotText {
        path: shown(),
        source,
    })
}

/// Why a scenario file was rejected. Every variant names the file, the line (when the
/// offending key is in the file) and the field, and says what is allowed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum ScenarioError {
    /// The text is not valid TOML.
    #[error("{file}, {}, near field `{field}`: malformed TOML: {message}", line_text(*.line))]
    Syntax {
        /// The file's name as given to [`load_scenario`].
        file: String,
        /// Line of the error (1-based).
        line: Option<usize>,
        /// The key on or before the error, as a dotted path (`?` if none).
        field: String,
        /// The parser's message.
        message: String,
    },
    /// A key that the scenario does not have, a value of the wrong type, or an unknown
    /// name (the message lists what is accepted).
    #[error("{file}, {}, field `{field}`: {message}", line_text(*.line))]
    Structure {
        /// The file's name as given to [`load_scenario`].
        file: String,
        /// Line of the key or value (1-based).
        line: Option<usize>,
        /// The field's dotted path, e.g. `approach.start_range_m`.
        field: String,
        /// What was wrong and what is expected.
        message: String,
    },
    /// A value outside its allowed range, or physically meaningless (negative mass, NaN).
    #[error(
        "{file}, {}, field `{}`: {} is not allowed: expected {}",
        line_text(*.line),
        .problem.path,
        .problem.value,
        .problem.allowed
    )]
    OutOfRange {
        /// The file's name as given to [`load_scenario`].
        file: String,
        /// Line of the key (1-based); `None` if the key is not in the file.
        line: Option<usize>,
        /// The check that failed: the dotted path, the value and the allowed range.
        problem: ParameterError,
    },
}

impl ScenarioError {
    /// The line of the problem in the file (1-based), if known.
    pub fn line(&self) -> Option<usize> {
        match self {
            Self::Syntax { line, .. }
            | Self::Structure { line, .. }
            | Self::OutOfRange { line, .. } => *line,
        }
    }

    /// The dotted path of the field at fault.
    pub fn field(&self) -> &str {
        match self {
            Self::Syntax { field, .. } | Self::Structure { field, .. } => field,
            Self::OutOfRange { problem, .. } => &problem.path,
        }
    }
}

fn line_text(line: Option<usize>) -> String {
    match line {
        Some(line) => format!("line {line}"),
        None => "no line (not set in the file; its default was used)".to_owned(),
    }
}

/// Parses the scenario file `file_name` whose content is `text` and checks every value.
/// Keys left out take their defaults (docs/model.md); unknown keys are errors. An
/// aircraft definition the file names (`[aircraft] definition = "FILE"`) is read
/// relative to the working folder: [`load_scenario_in`] reads it relative to the
/// scenario's own folder.
pub fn load_scenario(text: &str, file_name: &str) -> Result<Scenario, ScenarioError> {
    load_scenario_in(text, file_name, Path::new(""))
}

/// As [`load_scenario`], reading an aircraft definition file that the scenario names
/// relative to `folder` (the scenario file's folder).
pub fn load_scenario_in(
    text: &str,
    file_name: &str,
    folder: &Path,
) -> Result<Scenario, ScenarioError> {
    let index = index_of(text, file_name)?;
    let definition = match index.keys.iter().find(|k| k.path == DEFINITION_KEY) {
        Some(key) => Some(read_definition(text, file_name, folder, key, &index)?),
        None => None,
    };
    // The definition's key is the loader's, not the scenario structure's: blank it out
    // (byte for byte, so every other line and span stays where it was).
    let text = &match &definition {
        Some((_, span)) => blank(text, span.clone()),
        None => text.to_owned(),
    };
    let mut scenario: Scenario = deserialize_located(text, file_name, &index)?;
    if let Some((definition, _)) = &definition {
        definition.apply_to(&mut scenario.aircraft);
    }
    let in_file = |path: &str| {
        index.keys.iter().any(|k| k.path == path)
            || definition.is_some() && AircraftDefinition::holds(path)
    };
    finish_scenario(scenario, text, file_name, &index, in_file)
}

/// The scenario key that names an aircraft definition file.
const DEFINITION_KEY: &str = "aircraft.definition";

/// Largest aircraft definition file (bytes): the F/A-18's is about 8 kB.
pub const MAX_AIRCRAFT_FILE_BYTES: u64 = 1024 * 1024;

/// Parses the aircraft definition file `file_name` whose content is `text` (the format
/// `deckland aircraft --print-default` prints) and checks every value; errors name the
/// definition's file, line and key.
pub fn load_aircraft_definition(
    text: &str,
    file_name: &str,
) -> Result<AircraftDefinition, ScenarioError> {
    let index = index_of(text, file_name)?;
    let definition: AircraftDefinition = deserialize_located(text, file_name, &index)?;
    definition.validate().map_err(|mut problem| {
        // The checks name the scenario's keys (`aircraft.parameters.mass_kg`); in the
        // definition file the key is `parameters.mass_kg`.
        if let Some(own) = problem.path.strip_prefix("aircraft.") {
            problem.path = own.to_owned();
        }
        out_of_range(problem, text, file_name, &index)
    })?;
    Ok(definition)
}

/// Reads the definition named at `key` of the scenario `text`: the definition and the
/// byte span of the key and its value in the scenario.
fn read_definition(
    text: &str,
    file_name: &str,
    folder: &Path,
    key: &KeyLocation,
    index: &KeyIndex,
) -> Result<(AircraftDefinition, Range<usize>), ScenarioError> {
    let structure = |message: String| ScenarioError::Structure {
        file: file_name.to_owned(),
        line: Some(line_of(text, key.span.start)),
        field: DEFINITION_KEY.to_owned(),
        message,
    };
    let document = ImDocument::parse(text).map_err(|e| structure(e.message().to_owned()))?;
    let aircraft = document.as_table().get("aircraft");
    let Some(name) = aircraft
        .and_then(|a| a.get("definition"))
        .and_then(|d| d.as_str())
    else {
        return Err(structure(
            "expected the aircraft definition file's path as a string, e.g. \
             definition = \"my-aircraft.toml\""
                .to_owned(),
        ));
    };
    if let Some(data) = index.keys.iter().find(|k| {
        k.path
            .strip_prefix("aircraft.")
            .is_some_and(|rest| AircraftDefinition::holds(&format!("aircraft.{rest}")))
    }) {
        return Err(ScenarioError::Structure {
            file: file_name.to_owned(),
            line: Some(line_of(text, data.span.start)),
            field: data.path.clone(),
            message: format!(
                "the scenario names the aircraft definition `{name}`, which holds the \
                 aircraft's data: set this key in that file, or leave out `definition`"
            ),
        });
    }
    let path = folder.join(name);
    let definition_text = read_text_file(&path, MAX_AIRCRAFT_FILE_BYTES, "aircraft definition")
        .map_err(|error| structure(format!("cannot read the aircraft definition: {error}")))?;
    let definition = load_aircraft_definition(&definition_text, &path.display().to_string())?;
    Ok((definition, key_value_span(text, key.span.clone())))
}

/// The span to blank for the key and value at `span`: from the start of its line when
/// only the key's dotted prefix stands before it, else (an inline table) with one comma
/// beside it.
fn key_value_span(text: &str, span: Range<usize>) -> Range<usize> {
    let line_start = text[..span.start].rfind('\n').map_or(0, |i| i + 1);
    let before = &text[line_start..span.start];
    if before
        .chars()
        .all(|c| c.is_whitespace() || c.is_alphanumeric() || "._-\"'".contains(c))
    {
        return line_start..span.end;
    }
    let after = &text[span.end..];
    let skipped = after.len() - after.trim_start_matches([' ', '\t']).len();
    if after[skipped..].starts_with(',') {
        return span.start..span.end + skipped + 1;
    }
    let trimmed = before.trim_end_matches([' ', '\t']);
    if trimmed.ends_with(',') {
        return line_start + trimmed.len() - 1..span.end;
    }
    span
}

/// `text` with the characters of `span` replaced by as many spaces as they have bytes
/// (newlines kept), so that every other byte stays at its offset.
fn blank(text: &str, span: Range<usize>) -> String {
    let mut out = String::with_capacity(text.len());
    out.push_str(&text[..span.start]);
    for c in text[span.clone()].chars() {
        if c == '\n' {
            out.push(c);
        } else {
            out.extend(std::iter::repeat_n(' ', c.len_utf8()));
        }
    }
    out.push_str(&text[span.end..]);
    out
}

/// Every key of the TOML `text`, located; a syntax error names its line and key.
fn index_of(text: &str, file_name: &str) -> Result<KeyIndex, ScenarioError> {
    let document = ImDocument::parse(text).map_err(|error| {
        let line = error.span().map(|span| line_of(text, span.start));
        ScenarioError::Syntax {
            file: file_name.to_owned(),
            line,
            field: line.map_or_else(|| "?".to_owned(), |l| key_near_line(text, l)),
            message: first_line(error.message()),
        }
    })?;
    let mut keys = Vec::new();
    index_table("", document.as_table(), &mut keys);
    Ok(KeyIndex { keys })
}

/// The value of type `T` in the TOML `text`; a structure error names its line and key.
fn deserialize_located<T: serde::de::DeserializeOwned>(
    text: &str,
    file_name: &str,
    index: &KeyIndex,
) -> Result<T, ScenarioError> {
    toml::from_str(text).map_err(|error| {
        let (line, field) = match error.span() {
            Some(span) => (
                Some(line_of(text, span.start)),
                index
                    .innermost(&span)
                    .map_or_else(|| "?".to_owned(), |k| k.path.clone()),
            ),
            None => (None, "?".to_owned()),
        };
        let message = first_line(error.message());
        // An unknown key is reported at the key itself: name it in the path.
        let field = match unknown_field_name(&message) {
            Some(name) if !field.ends_with(name) => join(&field, name),
            _ => field,
        };
        // Tagged sections (mission, control.pitch) lose the key's own span: find it.
        let line = index
            .keys
            .iter()
            .find(|k| k.path == field)
            .map(|k| line_of(text, k.span.start))
            .or(line);
        ScenarioError::Structure {
            file: file_name.to_owned(),
            line,
            field,
            message,
        }
    })
}

/// The checks after the structure: a unit mission's extra keys, the hardware set's
/// defaults for keys not `in_file`, and every value's range.
fn finish_scenario(
    scenario: Scenario,
    text: &str,
    file_name: &str,
    index: &KeyIndex,
    in_file: impl Fn(&str) -> bool,
) -> Result<Scenario, ScenarioError> {
    // serde ignores extra keys beside the tag of a unit variant: check them here.
    if matches!(scenario.mission, Mission::Approach) {
        if let Some(extra) = index
            .keys
            .iter()
            .find(|k| k.path.starts_with("mission.") && k.path != "mission.kind")
        {
            return Err(ScenarioError::Structure {
                file: file_name.to_owned(),
                line: Some(line_of(text, extra.span.start)),
                field: extra.path.clone(),
                message: "unknown field: an `approach` mission takes only `kind`".to_owned(),
            });
        }
    }

    refuse_keys_set_elsewhere(&scenario, text, file_name, index, &in_file)?;

    // A file on the paper's hardware takes the paper's values for what it leaves out.
    let scenario = match scenario.with_set_defaults(in_file) {
        Ok(scenario) => scenario,
        Err(message) => {
            // The set's defaults pass through JSON, which holds no infinity or NaN: a
            // value out of range is the file's fault, named by its key.
            scenario
                .validate()
                .map_err(|problem| out_of_range(problem, text, file_name, index))?;
            return Err(ScenarioError::Structure {
                file: file_name.to_owned(),
                line: None,
                field: "hardware".to_owned(),
                message,
            });
        }
    };
    scenario
        .validate()
        .map_err(|problem| out_of_range(problem, text, file_name, index))?;
    Ok(scenario)
}

/// Keys that something else in the file sets, refused when written beside it (the file
/// would say one sea and fly another): the RMS a ship model derives (the seaway's), and
/// H_s and T_p beside a sea-state number.
fn refuse_keys_set_elsewhere(
    scenario: &Scenario,
    text: &str,
    file_name: &str,
    index: &KeyIndex,
    in_file: &impl Fn(&str) -> bool,
) -> Result<(), ScenarioError> {
    let refuse = |section: &str, keys: &[&str], message: String| {
        let Some(key) = keys
            .iter()
            .map(|key| format!("{section}.{key}"))
            .find(|path| in_file(path))
        else {
            return Ok(());
        };
        let line = index
            .keys
            .iter()
            .find(|k| k.path == key)
            .map(|k| line_of(text, k.span.start));
        Err(ScenarioError::Structure {
            file: file_name.to_owned(),
            line,
            field: key,
            message,
        })
    };
    let model = scenario.environment.ship.model;
    refuse(
        "environment.ship",
        model.derived_keys(),
        format!(
            "set by the ship model `{}`: leave it out (the seaway's spectrum and hull set it; \
             change `environment.seaway.significant_wave_height_m` instead)",
            model.name()
        ),
    )?;
    if in_file("environment.seaway.sea_state") {
        refuse(
            "environment.seaway",
            &["significant_wave_height_m", "peak_period_s"],
            "set by `environment.seaway.sea_state` from the sea-state table: leave one of \
             them out"
                .to_owned(),
        )?;
    }
    Ok(())
}

/// The range error `problem`, at the line of its key in `text` if the key is there.
fn out_of_range(
    problem: ParameterError,
    text: &str,
    file_name: &str,
    index: &KeyIndex,
) -> ScenarioError {
    let line = index
        .keys
        .iter()
        .find(|k| k.path == problem.path)
        .map(|k| line_of(text, k.span.start));
    ScenarioError::OutOfRange {
        file: file_name.to_owned(),
        line,
        problem,
    }
}

fn first_line(message: &str) -> String {
    message.lines().next().unwrap_or("").trim().to_owned()
}

/// The field named in serde's "unknown field `name`, expected …" message.
fn unknown_field_name(message: &str) -> Option<&str> {
    let rest = message.strip_prefix("unknown field `")?;
    rest.split('`').next()
}

/// The line (1-based) of byte `offset` in `text`.
fn line_of(text: &str, offset: usize) -> usize {
    let end = offset.min(text.len());
    text.as_bytes()[..end]
        .iter()
        .filter(|&&b| b == b'\n')
        .count()
        + 1
}

/// For text that does not parse: the dotted path of the key on `line`, read from the
/// raw text (the table header above it and the word before `=`).
fn key_near_line(text: &str, line: usize) -> String {
    // A table header may carry a comment after it: `[aircraft.hook]  # docs/model.md §2.7`.
    let lines: Vec<&str> = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or(""))
        .collect();
    let current = lines.get(line.saturating_sub(1)).copied().unwrap_or("");
    let header = lines[..line.saturating_sub(1).min(lines.len())]
        .iter()
        .rev()
        .map(|l| l.trim())
        .find(|l| l.starts_with('[') && l.ends_with(']'))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim().to_owned())
        .unwrap_or_default();
    match current.split_once('=') {
        Some((key, _)) if !key.trim().is_empty() => join(&header, key.trim()),
        _ if !header.is_empty() => header,
        _ => "?".to_owned(),
    }
}

/// Where one key (or table) of the file is: its dotted path and byte span.
#[derive(Debug, Clone)]
struct KeyLocation {
    path: String,
    span: Range<usize>,
}

/// Every key and table of a parsed file with its span.
struct KeyIndex {
    keys: Vec<KeyLocation>,
}

impl KeyIndex {
    /// The smallest key or table whose span holds the start of `span`.
    fn innermost(&self, span: &Range<usize>) -> Option<&KeyLocation> {
        self.keys
            .iter()
            .filter(|k| k.span.start <= span.start && span.start < k.span.end.max(k.span.start + 1))
            .min_by_key(|k| k.span.end - k.span.start)
    }
}

fn index_table(prefix: &str, table: &Table, out: &mut Vec<KeyLocation>) {
    let first = out.len();
    for (key, item) in table.iter() {
        let path = join(prefix, key);
        let key_span = table.key(key).and_then(|k| k.span());
        index_item(&path, key_span, item, out);
    }
    if let Some(header) = table.span() {
        let end = out[first..]
            .iter()
            .map(|k| k.span.end)
            .max()
            .unwrap_or(header.end)
            .max(header.end);
        out.push(KeyLocation {
            path: prefix.to_owned(),
            span: header.start..end,
        });
    }
}

fn index_inline(prefix: &str, table: &InlineTable, out: &mut Vec<KeyLocation>) {
    for (key, value) in table.iter() {
        let path = join(prefix, key);
        let key_span = table.key(key).and_then(|k| k.span());
        index_value(&path, key_span, value, out);
    }
}

fn index_item(path: &str, key_span: Option<Range<usize>>, item: &Item, out: &mut Vec<KeyLocation>) {
    match item {
        Item::Table(table) => index_table(path, table, out),
        Item::Value(value) => index_value(path, key_span, value, out),
        Item::None | Item::ArrayOfTables(_) => {}
    }
}

fn index_value(
    path: &str,
    key_span: Option<Range<usize>>,
    value: &Value,
    out: &mut Vec<KeyLocation>,
) {
    let value_span = value.span();
    let span = match (key_span, value_span.clone()) {
        (Some(k), Some(v)) => k.start.min(v.start)..k.end.max(v.end),
        (Some(s), None) | (None, Some(s)) => s,
        (None, None) => return,
    };
    out.push(KeyLocation {
        path: path.to_owned(),
        span,
    });
    if let Value::InlineTable(table) = value {
        index_inline(path, table, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Regression (issue 28, D9): `/dev/zero` grew to 4.2 GB, a FIFO blocked forever.
    #[cfg(unix)]
    #[test]
    fn regression_reads_are_bounded_and_of_regular_files_only() {
        let error =
            read_text_file(Path::new("/dev/zero"), 1024, "scenario file").expect_err("refused");
        assert!(
            matches!(
                error,
                ReadError::NotAFile {
                    kind: "a device",
                    ..
                }
            ),
            "{error}"
        );
        let error = read_text_file(Path::new("/"), 1024, "scenario file").expect_err("refused");
        assert!(error.to_string().contains("a folder"), "{error}");
        let folder = std::env::temp_dir().join(format!("deckland-read-{}", std::process::id()));
        std::fs::create_dir_all(&folder).expect("folder");
        let big = folder.join("big.toml");
        std::fs::write(&big, vec![b'#'; 2048]).expect("written");
        let error = read_text_file(&big, 1024, "scenario file").expect_err("refused");
        assert_eq!(
            error.to_string(),
            format!(
                "{} is larger than 1024 bytes, more than a scenario file can be",
                big.display()
            )
        );
        assert_eq!(
            read_text_file(&big, 2048, "scenario file")
                .expect("read")
                .len(),
            2048
        );
        let _ = std::fs::remove_dir_all(&folder);
    }

    /// An empty file is the default scenario, but for what came with the seaway and
    /// after, which a file must name (every file written before it flies as it did): the
    /// filter ship, the early check off, no airspeed limit in the wave-off, the
    /// ramp-strike probability on the forecast's clearance, no commit gate. Naming them
    /// gives the default itself.
    #[test]
    fn an_empty_file_is_the_default_scenario_but_for_the_seaway_and_its_recovery_keys() {
        let mut expected = Scenario::default();
        expected.environment.ship.model = crate::environment::ShipModelKind::Filters;
        expected.control.wave_off.recovery.foul_deck_time_to_go_s = 0.0;
        expected.control.wave_off.recovery.foul_deck_model = crate::control::FoulDeckModel::Linear;
        expected.control.wave_off.climb_out_airspeed_margin_mps = 0.0;
        expected.control.wave_off.ramp_strike_model = crate::control::RampStrikeModel::Forecast;
        expected.control.wave_off.hard_landing_model = crate::control::HardLandingModel::Forecast;
        expected.control.wave_off.touchdown_sink_rate_sigma_mps = 1.0;
        expected.control.wave_off.max_commit_ramp_strike_probability = 0.0;
        assert_eq!(load_scenario("", "empty.toml"), Ok(expected));
        // A [control.wave_off] section that names other keys but not the model: the
        // probability as it first came.
        let other = load_scenario(
            "[control.wave_off]\nmax_ramp_strike_probability = 0.1\n",
            "o.toml",
        )
        .expect("valid");
        assert_eq!(
            other.control.wave_off.ramp_strike_model,
            crate::control::RampStrikeModel::Forecast
        );
        let named = "[environment.ship]\nmodel = \"seaway\"\n\
                     [control.wave_off]\nclimb_out_airspeed_margin_mps = 10.0\n\
                     ramp_strike_model = \"closed_loop_lift\"\n\
                     hard_landing_model = \"closed_loop\"\n\
                     touchdown_sink_rate_sigma_mps = 0.6\n\
                     max_commit_ramp_strike_probability = 7e-4\n\
                     [control.wave_off.recovery]\nfoul_deck_time_to_go_s = 10.0\n\
                     foul_deck_model = \"stationary\"\n";
        assert_eq!(load_scenario(named, "named.toml"), Ok(Scenario::default()));
    }

    #[test]
    fn keys_are_located_by_line() {
        let text = "seed = 3\n\n[approach]\nstart_range_m = 1\n";
        let error = load_scenario(text, "a.toml").expect_err("range too short");
        assert_eq!(error.line(), Some(4));
        assert_eq!(error.field(), "approach.start_range_m");
    }

    #[test]
    fn the_key_near_a_syntax_error_is_read_from_the_text() {
        let text = "[approach]\nstart_range_m = 1500 m\n";
        assert_eq!(key_near_line(text, 2), "approach.start_range_m");
    }

    /// Regression: a table header followed by a comment was skipped, so a syntax error
    /// in `[aircraft.hook]  # …` was reported near `aircraft.<key>`.
    #[test]
    fn regression_commented_table_headers_name_the_syntax_error_section() {
        let text = "[aircraft]\nconfiguration = \"landing\"\n\n[aircraft.hook]   # hook point\naft_of_cg_m = 7 m\n";
        assert_eq!(key_near_line(text, 5), "aircraft.hook.aft_of_cg_m");
        let error = load_scenario(text, "a.toml").expect_err("syntax");
        assert_eq!(error.field(), "aircraft.hook.aft_of_cg_m");
    }
}
