//! Property (fuzz) test of the whole input path: scenario text → parse → validate → set
//! up (trim, linearisation, controller design) → fly a short run (issue 14).
//!
//! Each case starts from the serialised form of one of four scenarios (the default
//! approach, PID pitch control, the pitch-step and the sink-rate missions) and applies
//! one to four edits to random keys — a new value of any type (floats across 600 orders
//! of magnitude and near physical magnitudes, ±1e300, ±∞, NaN, integers, booleans, the
//! names the file accepts and others, arrays, tables), a key's value scaled by a factor
//! near 1 (which keeps many scenarios valid, so that set-up and flight are reached), a
//! key removed, an unknown key added — and, in one case of four, corrupts the text
//! (truncates it or inserts a character). A scenario that sets up is flown for at most
//! [`MAX_STEPS`] steps; in one case of three a command (pitch, elevator or thrust) is
//! replaced from a random step on by NaN, ±∞, 1e13 or −1e300, what a controller with
//! absurd gains would compute. The properties:
//!
//! - nothing panics, aborts or hangs (a panic fails the case; every run is bounded);
//! - a refused file names a field (`ScenarioError::field` is not empty) and a scenario
//!   that cannot be set up says why;
//! - every signal a recorder receives is finite, and so is every number of a run's
//!   summary; an injected command ends the run at the step that first uses it, as
//!   diverged with its reason (issue 14, class 5).
//!
//! Coverage of one run of the default 3000 cases (the counts vary from run to run with
//! proptest's seed; `DECKLAND_FUZZ_CASES` sets the number, `--nocapture` prints them):
//! 628 syntax errors, 1419 structure errors (unknown keys, wrong types, arrays of the
//! wrong length), 480 values out of range, 6 scenarios refused at set-up (trim), 467
//! set up and flown, 141 of them with an injected command; 217 runs ended as diverged.
//! 20 000 cases ran clean as well (47 s; 3179 flown, 1085 injected). The test fails, as it should, when either
//! guard of class 5 is removed (the check of every signal in `Simulation::check_state`,
//! or the refusal to record a diverged step), and when a stage is reached too rarely.
//! It covers the classes 1 (keys without an upper bound: huge values of every
//! key, `compensation_window_s` and `compensation_blend_s` among them), 5 (non-finite
//! values in the file and in commands), 6 (the field named), 7 (wrong types, extra
//! array elements), 8 (accepted scenarios must set up) and 9 (time steps down to
//! 1e-5 s). It takes about 7 s in CI.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use std::sync::atomic::{AtomicUsize, Ordering};

use deckland::control::pitch::{PidParameters, PitchControllerParameters};
use deckland::scenario::{load_scenario, Mission, PitchCommand, Scenario, ScenarioError};
use deckland::simulation::{Outcome, Overrides, Recorder, RunSummary, Signals, Simulation, Stop};
use proptest::prelude::*;
use proptest::sample::Index;
use proptest::test_runner::{Config, TestRunner};
use toml::Value;

/// Most integration steps flown per case.
const MAX_STEPS: usize = 1500;

/// One edit of a scenario table.
#[derive(Debug, Clone)]
enum Edit {
    /// Give the key a new value.
    Set(Index, NewValue),
    /// Multiply a numeric key by a factor.
    Scale(Index, f64),
    /// Remove the key.
    Remove(Index),
    /// Add an unknown key beside it.
    Unknown(Index),
}

/// A value of any TOML type.
#[derive(Debug, Clone)]
enum NewValue {
    Float(f64),
    Integer(i64),
    Bool(bool),
    Text(Index),
    Array(Vec<f64>),
    Table,
}

/// Names the file accepts somewhere, and some it does not.
const TEXTS: [&str; 14] = [
    "approach",
    "pitch_step",
    "sink_rate",
    "observer_pd",
    "pid",
    "landing",
    "clean",
    "measured",
    "observer_estimate",
    "model",
    "filter_lead",
    "",
    "x",
    "1.0",
];

/// A text corruption.
#[derive(Debug, Clone)]
enum Corruption {
    None,
    Truncate(Index),
    Insert(Index, char),
}

/// A command replaced, from a step on, by a value that is not finite or beyond any
/// physical size: what a controller with absurd gains computes.
#[derive(Debug, Clone)]
struct Injection {
    from_step: Index,
    command: Index,
    value: f64,
}

/// One case: the base scenario, the edits, the corruption, the injected command.
#[derive(Debug, Clone)]
struct Plan {
    base: Index,
    edits: Vec<Edit>,
    corruption: Corruption,
    injection: Option<Injection>,
}

fn floats() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        (-300i32..300, any::<bool>())
            .prop_map(|(e, negative)| if negative { -1.0 } else { 1.0 } * 10f64.powi(e)),
        // Powers of ten near physical magnitudes: inside many keys' ranges, at their ends.
        (-6i32..7, any::<bool>())
            .prop_map(|(e, negative)| if negative { -1.0 } else { 1.0 } * 10f64.powi(e)),
        -1e4..1e4f64,
        Just(1e300),
        Just(-1e300),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
    ]
}

fn new_value() -> impl Strategy<Value = NewValue> {
    prop_oneof![
        4 => floats().prop_map(NewValue::Float),
        1 => any::<i64>().prop_map(NewValue::Integer),
        1 => any::<bool>().prop_map(NewValue::Bool),
        2 => any::<Index>().prop_map(NewValue::Text),
        1 => prop::collection::vec(-100.0..100.0f64, 0..7).prop_map(NewValue::Array),
        1 => Just(NewValue::Table),
    ]
}

fn edit() -> impl Strategy<Value = Edit> {
    let factor = prop_oneof![
        0.5..2.0f64,
        0.95..1.05f64,
        Just(0.0),
        Just(-1.0),
        Just(10.0),
        Just(0.01),
    ];
    prop_oneof![
        4 => (any::<Index>(), new_value()).prop_map(|(k, v)| Edit::Set(k, v)),
        5 => (any::<Index>(), factor).prop_map(|(k, f)| Edit::Scale(k, f)),
        1 => any::<Index>().prop_map(Edit::Remove),
        1 => any::<Index>().prop_map(Edit::Unknown),
    ]
}

fn plan() -> impl Strategy<Value = Plan> {
    let corruption = prop_oneof![
        6 => Just(Corruption::None),
        1 => any::<Index>().prop_map(Corruption::Truncate),
        1 => (any::<Index>(), any::<char>()).prop_map(|(i, c)| Corruption::Insert(i, c)),
    ];
    let injection = prop_oneof![
        2 => Just(None),
        1 => (
            any::<Index>(),
            any::<Index>(),
            prop_oneof![
                Just(f64::NAN),
                Just(f64::INFINITY),
                Just(f64::NEG_INFINITY),
                Just(1e13),
                Just(-1e300),
            ],
        )
            .prop_map(|(from_step, command, value)| Some(Injection {
                from_step,
                command,
                value,
            })),
    ];
    (
        any::<Index>(),
        prop::collection::vec(edit(), 1..5),
        corruption,
        injection,
    )
        .prop_map(|(base, edits, corruption, injection)| Plan {
            base,
            edits,
            corruption,
            injection,
        })
}

/// The base scenarios as TOML tables.
fn bases() -> Vec<toml::Table> {
    let mut pid = Scenario::default();
    pid.control.pitch = PitchControllerParameters::Pid(PidParameters::default());
    let mut pitch_step = Scenario::default();
    pitch_step.mission = Mission::pitch_step(2.0, 6.0, PitchCommand::JerkLimited);
    let mut paper_step = Scenario::paper();
    paper_step.mission = Mission::pitch_step(2.0, 6.0, PitchCommand::Step);
    let mut sink_rate = Scenario::default();
    sink_rate.mission = Mission::sink_rate(10.0, 5.0, 20.0);
    [
        Scenario::default(),
        pid,
        pitch_step,
        Scenario::paper(),
        paper_step,
        sink_rate,
    ]
    .iter()
    .map(|s| toml::from_str(&toml::to_string(s).unwrap()).unwrap())
    .collect()
}

/// Every key path of `table` (leaves and tables), as lists of names.
fn key_paths(prefix: &[String], table: &toml::Table, out: &mut Vec<Vec<String>>) {
    for (key, value) in table {
        let mut path = prefix.to_vec();
        path.push(key.clone());
        if let Value::Table(inner) = value {
            key_paths(&path, inner, out);
        }
        out.push(path);
    }
}

/// The table that holds the last element of `path`.
fn parent<'a>(table: &'a mut toml::Table, path: &[String]) -> Option<&'a mut toml::Table> {
    let mut cursor = table;
    for part in &path[..path.len() - 1] {
        cursor = cursor.get_mut(part)?.as_table_mut()?;
    }
    Some(cursor)
}

fn apply(table: &mut toml::Table, edit: &Edit) {
    let mut paths = Vec::new();
    key_paths(&[], table, &mut paths);
    if paths.is_empty() {
        return;
    }
    let index = match edit {
        Edit::Set(i, _) | Edit::Scale(i, _) | Edit::Remove(i) | Edit::Unknown(i) => i,
    };
    let path = &paths[index.index(paths.len())];
    let last = path.last().unwrap().clone();
    let Some(holder) = parent(table, path) else {
        return;
    };
    match edit {
        Edit::Set(_, value) => {
            let value = match value {
                NewValue::Float(v) => Value::Float(*v),
                NewValue::Integer(v) => Value::Integer(*v),
                NewValue::Bool(v) => Value::Boolean(*v),
                NewValue::Text(i) => Value::String(TEXTS[i.index(TEXTS.len())].to_owned()),
                NewValue::Array(items) => {
                    Value::Array(items.iter().map(|v| Value::Float(*v)).collect())
                }
                NewValue::Table => {
                    let mut inner = toml::Table::new();
                    inner.insert("a".to_owned(), Value::Integer(1));
                    Value::Table(inner)
                }
            };
            holder.insert(last, value);
        }
        Edit::Scale(_, factor) => match holder.get_mut(&last) {
            Some(Value::Float(v)) => *v *= factor,
            Some(Value::Integer(v)) => *v = (*v as f64 * factor) as i64,
            Some(Value::Array(items)) => {
                for item in items {
                    if let Value::Float(v) = item {
                        *v *= factor;
                    }
                }
            }
            _ => {}
        },
        Edit::Remove(_) => {
            holder.remove(&last);
        }
        Edit::Unknown(_) => {
            holder.insert("unknown_key".to_owned(), Value::Integer(1));
        }
    }
}

fn corrupt(text: &str, corruption: &Corruption) -> String {
    let boundaries: Vec<usize> = text
        .char_indices()
        .map(|(i, _)| i)
        .chain([text.len()])
        .collect();
    match corruption {
        Corruption::None => text.to_owned(),
        Corruption::Truncate(i) => text[..boundaries[i.index(boundaries.len())]].to_owned(),
        Corruption::Insert(i, c) => {
            let at = boundaries[i.index(boundaries.len())];
            format!("{}{c}{}", &text[..at], &text[at..])
        }
    }
}

/// Keeps the first recorded signal that is not finite.
#[derive(Default)]
struct FiniteCheck {
    samples: usize,
    non_finite: Option<(&'static str, f64, f64)>,
}

impl Recorder for FiniteCheck {
    fn sample_interval_s(&self) -> Option<f64> {
        Some(0.0) // every step
    }

    fn sample(&mut self, signals: &Signals) {
        self.samples += 1;
        if self.non_finite.is_none() {
            self.non_finite = signals
                .named_values()
                .into_iter()
                .find_map(|(name, value)| {
                    value
                        .filter(|v| !v.is_finite())
                        .map(|v| (name, v, signals.time_s))
                });
        }
    }
}

fn summary_is_finite(summary: &RunSummary) -> bool {
    let mut numbers = vec![Some(summary.end_time_s)];
    numbers.extend([
        summary.ramp_clearance_m,
        summary.glide_path_error_rms_m,
        summary.glide_path_error_max_m,
    ]);
    if let Some(t) = summary.touchdown {
        numbers.extend([
            Some(t.time_s),
            Some(t.distance_from_aim_m),
            Some(t.sink_rate_mps),
            Some(t.pitch_deg),
            Some(t.airspeed_mps),
        ]);
    }
    numbers.into_iter().flatten().all(f64::is_finite)
}

/// What became of the cases.
#[derive(Default)]
struct Counts {
    syntax: AtomicUsize,
    structure: AtomicUsize,
    out_of_range: AtomicUsize,
    set_up_refused: AtomicUsize,
    flown: AtomicUsize,
    injected: AtomicUsize,
    diverged: AtomicUsize,
    ended_otherwise: AtomicUsize,
}

fn count(counter: &AtomicUsize) {
    counter.fetch_add(1, Ordering::Relaxed);
}

#[test]
fn any_scenario_text_is_refused_clearly_or_set_up_and_flown_finitely() {
    let cases: u32 = std::env::var("DECKLAND_FUZZ_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(3000);
    let bases = bases();
    let counts = Counts::default();
    let mut runner = TestRunner::new(Config {
        cases,
        max_shrink_iters: 200,
        // Failures are printed with the case; CI keeps no regression files.
        failure_persistence: None,
        ..Config::default()
    });
    let result = runner.run(&plan(), |plan| {
        let mut table = bases[plan.base.index(bases.len())].clone();
        for edit in &plan.edits {
            apply(&mut table, edit);
        }
        let Ok(text) = toml::to_string(&table) else {
            return Ok(()); // not writable as TOML: nothing to read
        };
        let text = corrupt(&text, &plan.corruption);
        let scenario = match load_scenario(&text, "fuzz.toml") {
            Ok(scenario) => scenario,
            Err(error) => {
                prop_assert!(!error.field().is_empty(), "no field named: {error}");
                prop_assert!(!error.to_string().is_empty());
                count(match error {
                    ScenarioError::Syntax { .. } => &counts.syntax,
                    ScenarioError::Structure { .. } => &counts.structure,
                    ScenarioError::OutOfRange { .. } => &counts.out_of_range,
                });
                return Ok(());
            }
        };
        let mut simulation = match Simulation::new(&scenario) {
            Ok(simulation) => simulation,
            Err(error) => {
                prop_assert!(!error.to_string().is_empty());
                count(&counts.set_up_refused);
                return Ok(());
            }
        };
        count(&counts.flown);
        let mut check = FiniteCheck::default();
        let (from_step, injected) = match &plan.injection {
            None => (MAX_STEPS, Overrides::default()),
            Some(injection) => {
                let value = Some(injection.value);
                let overrides = match injection.command.index(3) {
                    0 => Overrides {
                        pitch_command_rad: value,
                        ..Overrides::default()
                    },
                    1 => Overrides {
                        elevator_rad: value,
                        ..Overrides::default()
                    },
                    _ => Overrides {
                        thrust_n: value,
                        ..Overrides::default()
                    },
                };
                (injection.from_step.index(MAX_STEPS / 2), overrides)
            }
        };
        let mut ended_at = None;
        for step in 0..MAX_STEPS {
            let taps = if step >= from_step {
                injected
            } else {
                Overrides::default()
            };
            if let Stop::Ended(_) = simulation.step_with(&mut check, &taps) {
                ended_at = Some(step);
                break;
            }
        }
        if plan.injection.is_some() {
            count(&counts.injected);
            // The step that evaluates the injected command ends the run, unless it had
            // ended before (an event, or another divergence).
            prop_assert!(
                ended_at.is_some_and(|step| step <= from_step),
                "the injected command did not end the run at step {from_step}: {ended_at:?}"
            );
        }
        prop_assert!(
            check.non_finite.is_none(),
            "a non-finite signal was recorded: {:?}",
            check.non_finite
        );
        if let Some(summary) = simulation.summary() {
            prop_assert!(summary_is_finite(summary), "{summary:?}");
            if summary.outcome == Outcome::Diverged {
                prop_assert!(summary.reason.is_some(), "diverged without a reason");
                count(&counts.diverged);
            } else {
                count(&counts.ended_otherwise);
            }
        }
        Ok(())
    });
    let load = |c: &AtomicUsize| c.load(Ordering::Relaxed);
    eprintln!(
        "{cases} cases: syntax {}, structure {}, out of range {}, set-up refused {}, \
         flown {} (with a non-finite or absurd command injected {}; diverged {}, ended \
         otherwise {})",
        load(&counts.syntax),
        load(&counts.structure),
        load(&counts.out_of_range),
        load(&counts.set_up_refused),
        load(&counts.flown),
        load(&counts.injected),
        load(&counts.diverged),
        load(&counts.ended_otherwise),
    );
    if let Err(failure) = result {
        panic!("{failure}");
    }
    // The test must reach every stage, or it tests nothing.
    let total = cases as usize;
    for (stage, counter, at_least) in [
        ("syntax errors", &counts.syntax, total / 50),
        ("structure errors", &counts.structure, total / 20),
        ("range errors", &counts.out_of_range, total / 10),
        ("flown scenarios", &counts.flown, total / 10),
        ("injected commands", &counts.injected, total / 40),
    ] {
        assert!(
            load(counter) >= at_least.max(1),
            "only {} {stage} in {cases} cases",
            load(counter)
        );
    }
}
