//! Scenario files: the shipped scenarios load and fly; every class of bad input is
//! rejected with the file, the line and the field named.

#![allow(clippy::unwrap_used)] // tests fail loudly by design

use deckland::environment::ShipModelKind;
use deckland::recording::SummaryRecorder;
use deckland::scenario::{load_scenario, Scenario, ScenarioError, DEFAULT_SCENARIO_TOML};
use deckland::simulation::{Outcome, Simulation};
use std::path::PathBuf;

fn scenarios_folder() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../scenarios")
}

fn load_shipped(name: &str) -> Scenario {
    let path = scenarios_folder().join(name);
    let text = std::fs::read_to_string(&path).unwrap();
    load_scenario(&text, name).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn paper_adverse_is_the_papers_scenario_and_the_template_the_realistic_default() {
    assert_eq!(load_shipped("paper-adverse.toml"), Scenario::paper());
    assert_eq!(
        load_scenario(DEFAULT_SCENARIO_TOML, "default").unwrap(),
        Scenario::default()
    );
}

/// A file on the paper's hardware that leaves everything else out is the paper's
/// scenario; one that sets a key keeps it; the realistic set is the default.
#[test]
fn keys_left_out_take_the_values_of_the_files_hardware_set() {
    let paper = load_scenario("hardware = \"paper\"\n", "p.toml").unwrap();
    assert_eq!(paper, Scenario::paper());
    let limited = load_scenario(
        "hardware = \"paper\"\n[aircraft.elevator_actuator]\nrate_limit_degps = 60.0\n",
        "p.toml",
    )
    .unwrap();
    assert_eq!(
        limited.aircraft.elevator_actuator.rate_limit_degps,
        Some(60.0)
    );
    assert_eq!(limited.control.flight_computer_rate_hz, None);
    let pid = load_scenario(
        "hardware = \"paper\"\n[control.pitch]\ntype = \"pid\"\nintegral_per_s3 = 7.0\n",
        "p.toml",
    )
    .unwrap();
    let deckland::control::pitch::PitchControllerParameters::Pid(gains) = pid.control.pitch else {
        panic!("{:?}", pid.control.pitch);
    };
    // The paper's PID gains for what is left out, the file's for what it sets.
    assert_eq!(gains.proportional_per_s2, 57.01);
    assert_eq!(gains.integral_per_s3, 7.0);
    // A realistic file that names no `[control]` takes the default's, but for the
    // wave-off keys that came with the recovery limits (a file must name them).
    // Nor a ship model: a file without `[environment.ship]`, or without `[environment]`,
    // flies the paper's filter ship, as one whose section names no `model` does (the files
    // written before the seaway became the default).
    let mut realistic = Scenario::default();
    realistic.control.wave_off = deckland::control::WaveOffParameters::named_by_none();
    realistic.environment.ship.model = ShipModelKind::Filters;
    assert_eq!(load_scenario("", "r.toml").unwrap(), realistic);
    for text in [
        "[environment.wind]\nturbulence = true\n",
        "[environment.ship]\nforward_speed_mps = 7.7\n",
    ] {
        let flown = load_scenario(text, "r.toml").unwrap();
        assert_eq!(
            flown.environment.ship.model,
            ShipModelKind::Filters,
            "{text}"
        );
    }
    let seaway = load_scenario("[environment.ship]\nmodel = \"seaway\"\n", "r.toml").unwrap();
    assert_eq!(seaway.environment.ship.model, ShipModelKind::Seaway);
    assert_eq!(
        Scenario::default().environment.ship.model,
        ShipModelKind::Seaway
    );
}

#[test]
fn every_shipped_scenario_loads_and_flies_one_approach() {
    let mut names: Vec<String> = std::fs::read_dir(scenarios_folder())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".toml"))
        .collect();
    names.sort();
    assert_eq!(
        names,
        [
            "calm.toml",
            "crosswind.toml",
            "heavy-sea.toml",
            "moderate-sea.toml",
            "paper-adverse.toml",
            "sea-state-3.toml",
            "sea-state-4.toml",
            "sea-state-5.toml",
            "sea-state-6.toml"
        ]
    );
    for name in &names {
        let scenario = load_shipped(name);
        let summary = Simulation::new(&scenario)
            .unwrap_or_else(|e| panic!("{name}: {e}"))
            .run(&mut SummaryRecorder);
        assert!(
            summary.touchdown.is_some()
                || matches!(
                    summary.outcome,
                    Outcome::Bolter | Outcome::RampStrike | Outcome::WaveOff
                ),
            "{name}: {summary:?}"
        );
    }
    let calm = load_shipped("calm.toml");
    assert_eq!(calm, Scenario::papers_sea().ideal());
    let heavy = load_shipped("heavy-sea.toml");
    assert_eq!(heavy.environment.ship.heave_rms_m, 3.0);
    assert!(!heavy.dispersion.is_none());
    let moderate = load_shipped("moderate-sea.toml");
    assert_eq!(
        (
            moderate.environment.ship.heave_rms_m,
            moderate.environment.ship.pitch_rms_deg
        ),
        (1.0, 0.75)
    );
    assert_eq!(
        moderate.control.flight_path.deck_motion_predictor,
        deckland::control::DeckPredictorKind::Estimator
    );
}

/// One bad input: its text, and the line, field and words of the allowed range or
/// expected form the message must hold.
struct Case {
    what: &'static str,
    text: &'static str,
    line: usize,
    field: &'static str,
    allowed: &'static str,
}

#[test]
fn each_class_of_bad_input_names_the_file_line_and_field() {
    let cases = [
        Case {
            what: "unknown key",
            text: "[approach]\nstart_range_m = 1500.0\nstart_rnage_m = 3.0\n",
            line: 3,
            field: "approach.start_rnage_m",
            allowed: "expected one of `start_range_m`",
        },
        Case {
            what: "unknown section",
            text: "seed = 2\n\n[aproach]\nstart_range_m = 900.0\n",
            line: 3,
            field: "aproach",
            allowed: "expected one of",
        },
        Case {
            what: "unknown key beside an approach mission's kind",
            text: "[mission]\nkind = \"approach\"\nstep_deg = 2.0\n",
            line: 3,
            field: "mission.step_deg",
            allowed: "takes only `kind`",
        },
        Case {
            what: "unknown key in a tagged section",
            text: "[control.pitch]\ntype = \"pid\"\nproportional = 50.0\n",
            line: 3,
            field: "control.pitch.proportional",
            allowed: "expected one of `proportional_per_s2`",
        },
        Case {
            what: "unknown controller type",
            text: "[control.pitch]\ntype = \"lqr\"\n",
            line: 2,
            field: "control.pitch.type",
            allowed: "`observer_pd` or `pid`",
        },
        Case {
            what: "wrong type (string for a number)",
            text: "[environment.ship]\nheave_rms_m = \"high\"\n",
            line: 2,
            field: "environment.ship.heave_rms_m",
            allowed: "expected f64",
        },
        Case {
            what: "wrong type (negative seed)",
            text: "# comment\nseed = -3\n",
            line: 2,
            field: "seed",
            allowed: "an integer from 0 to 2⁶³ − 1",
        },
        Case {
            what: "unknown name",
            text: "[aircraft]\nconfiguration = \"cruise\"\n",
            line: 2,
            field: "aircraft.configuration",
            allowed: "`landing` or `clean`",
        },
        Case {
            what: "out of range",
            text: "[approach]\nstart_range_m = 50.0\n",
            line: 2,
            field: "approach.start_range_m",
            allowed: "[200, 10000]",
        },
        Case {
            what: "out of range in the environment",
            text: "[environment.wind]\nmean_wind = true\nwind_over_deck_mps = 80.0\n",
            line: 3,
            field: "environment.wind.wind_over_deck_mps",
            allowed: "[0, 40]",
        },
        Case {
            what: "NaN",
            text: "[environment.ship]\n\nheave_rms_m = nan\n",
            line: 3,
            field: "environment.ship.heave_rms_m",
            allowed: "[0, 50]",
        },
        Case {
            what: "infinity",
            text: "max_time_s = inf\n",
            line: 1,
            field: "max_time_s",
            allowed: "[1, 3600]",
        },
        Case {
            what: "negative mass",
            text: "[aircraft.parameters]\nmass_kg = -15000.0\n",
            line: 2,
            field: "aircraft.parameters.mass_kg",
            allowed: "[1000, 100000]",
        },
        Case {
            what: "negative controller design value",
            text: "[control.speed]\ndamping_ratio = -1.0\n",
            line: 2,
            field: "control.speed.damping_ratio",
            allowed: "[0.1, 5]",
        },
        Case {
            what: "unstable observer gain",
            text: "[control.pitch]\ntype = \"observer_pd\"\n[control.pitch.observer]\nk2 = 0.1\n",
            line: 4,
            field: "control.pitch.observer.k2",
            allowed: "above (4/π)·k1/k3 = 0.4244 for stability",
        },
        Case {
            what: "negative PID gain",
            text: "[control.pitch]\ntype = \"pid\"\nintegral_per_s3 = -5.0\n",
            line: 3,
            field: "control.pitch.integral_per_s3",
            allowed: "[0, 10000]",
        },
        Case {
            what: "negative dispersion",
            text: "[dispersion]\nsea_state_log_sd = -0.1\n",
            line: 2,
            field: "dispersion.sea_state_log_sd",
            allowed: "[0, 1]",
        },
        Case {
            what: "malformed TOML (a unit after a number)",
            text: "seed = 1\n[approach]\nstart_range_m = 1500 m\n",
            line: 3,
            field: "approach.start_range_m",
            allowed: "malformed TOML",
        },
        Case {
            what: "malformed TOML (unclosed table header)",
            text: "seed = 1\n[approach\n",
            line: 2,
            field: "",
            allowed: "malformed TOML",
        },
    ];
    for case in &cases {
        let error: ScenarioError = load_scenario(case.text, "bad.toml")
            .err()
            .unwrap_or_else(|| panic!("{}: accepted", case.what));
        let message = error.to_string();
        assert!(
            message.starts_with("bad.toml, "),
            "{}: {message}",
            case.what
        );
        assert!(
            message.contains(&format!("line {}", case.line)),
            "{}: {message}",
            case.what
        );
        assert_eq!(error.line(), Some(case.line), "{}: {message}", case.what);
        if !case.field.is_empty() {
            assert_eq!(error.field(), case.field, "{}: {message}", case.what);
            assert!(
                message.contains(&format!("`{}`", case.field)),
                "{}: {message}",
                case.what
            );
        }
        assert!(message.contains(case.allowed), "{}: {message}", case.what);
    }
}
