//! Tests of the scenario's sections: validation by dotted path, defaults, and the
//! independence of the environment's random streams.

use super::*;
use crate::aircraft::PlantModel;
use crate::environment::{ShipMotionSimulator, WindModel};
use crate::random::RandomStreams;
use crate::sensors::PitchSensor;

/// Ship heave and measured pitch from a short run, with turbulence on or off.
fn ship_and_sensor_samples(seed: u64, turbulence: bool) -> (Vec<f64>, Vec<f64>) {
    let streams = RandomStreams::new(seed);
    let environment = EnvironmentSection {
        wind: WindParameters {
            turbulence,
            ..WindParameters::default()
        },
        ..EnvironmentSection::default()
    };
    let mut ship = ShipMotionSimulator::new(environment.ship, &streams, 0.0).expect("valid");
    let mut wind = WindModel::new(environment.wind, 0.0, &streams).expect("valid");
    let mut sensor = PitchSensor::new(environment.pitch_noise, &streams).expect("valid");
    let (mut heave, mut measured) = (Vec::new(), Vec::new());
    for k in 0..500 {
        let t = k as f64 * 0.01;
        wind.advance(0.01, 69.1);
        ship.step(0.01);
        heave.push(ship.outputs().heave_m);
        measured.push(sensor.measure(t, 0.0));
    }
    (heave, measured)
}

#[test]
fn switching_turbulence_off_leaves_ship_and_sensor_samples_unchanged() {
    assert_eq!(
        ship_and_sensor_samples(17, true),
        ship_and_sensor_samples(17, false)
    );
    assert_ne!(
        ship_and_sensor_samples(17, true).0,
        ship_and_sensor_samples(18, true).0
    );
}

#[test]
fn bad_parameters_are_rejected_naming_the_field() {
    type Edit = fn(&mut EnvironmentSection);
    let cases: &[(&str, Edit)] = &[
        ("ship.heave_rms_m", |p| p.ship.heave_rms_m = -1.0),
        ("ship.heave_rms_m", |p| p.ship.heave_rms_m = f64::NAN),
        ("ship.pitch_rms_deg", |p| p.ship.pitch_rms_deg = -0.5),
        ("ship.pitch_rms_deg", |p| {
            p.ship.pitch_rms_deg = f64::INFINITY
        }),
        ("ship.forward_speed_mps", |p| {
            p.ship.forward_speed_mps = f64::NAN
        }),
        ("deck.landing_point_aft_of_pitch_centre_m", |p| {
            p.deck.landing_point_aft_of_pitch_centre_m = f64::NEG_INFINITY
        }),
        ("deck.ramp_aft_of_aim_point_m", |p| {
            p.deck.ramp_aft_of_aim_point_m = 0.0
        }),
        ("deck.deck_height_m", |p| p.deck.deck_height_m = -3.0),
        ("deck.wire_positions_m", |p| {
            p.deck.wire_positions_m[2] = f64::NAN
        }),
        ("wind.wind_over_deck_mps", |p| {
            p.wind.wind_over_deck_mps = -10.0
        }),
        ("wind.turbulence_sigma_u_mps", |p| {
            p.wind.turbulence_sigma_u_mps = -0.1
        }),
        ("wind.turbulence_sigma_w_mps", |p| {
            p.wind.turbulence_sigma_w_mps = f64::NAN
        }),
        ("wind.turbulence_scale_m", |p| {
            p.wind.turbulence_scale_m = 0.0
        }),
        ("wind.turbulence_scale_m", |p| {
            p.wind.turbulence_scale_m = -30.48
        }),
        ("wind.periodic_wake_ship_pitch_rad", |p| {
            p.wind.periodic_wake_ship_pitch_rad = f64::NAN
        }),
        ("wind.periodic_wake_frequency_radps", |p| {
            p.wind.periodic_wake_frequency_radps = -1.25
        }),
        ("pitch_noise.sinusoid_amplitude_rad", |p| {
            p.pitch_noise.sinusoid_amplitude_rad = f64::INFINITY
        }),
        ("pitch_noise.sinusoid_frequency_radps", |p| {
            p.pitch_noise.sinusoid_frequency_radps = -7.0
        }),
        ("pitch_noise.white_noise_sigma_rad", |p| {
            p.pitch_noise.white_noise_sigma_rad = -0.001
        }),
    ];
    assert!(EnvironmentSection::default().validate().is_ok());
    for (field, edit) in cases {
        let mut parameters = EnvironmentSection::default();
        edit(&mut parameters);
        let error = parameters
            .validate()
            .expect_err(&format!("{field} should be rejected"));
        let message = error.to_string();
        assert!(message.contains(field), "{field}: message {message:?}");
        assert_eq!(error.path, format!("environment.{field}"), "{message}");
    }
}

#[test]
fn parameters_round_trip_through_json_and_fill_defaults() {
    let parameters = EnvironmentSection::default();
    let json = serde_json::to_string(&parameters).expect("serialisable");
    let back: EnvironmentSection = serde_json::from_str(&json).expect("deserialisable");
    assert_eq!(back, parameters);
    let partial: EnvironmentSection =
        serde_json::from_str(r#"{"ship": {"heave_rms_m": 1.0}}"#).expect("partial");
    assert_eq!(partial.ship.heave_rms_m, 1.0);
    assert_eq!(partial.ship.pitch_rms_deg, 1.5);
    assert!(serde_json::from_str::<EnvironmentSection>(r#"{"ship": {"heave": 1.0}}"#).is_err());
}

/// `[control.roll]` and `[control.yaw]`: a law by name, keys left out taking the
/// channel's designed tuning, read back through the one accessor the loop uses.
#[test]
fn lateral_laws_are_read_from_their_sections() {
    use crate::control::lateral::{LateralChannel, LateralLawParameters, LateralPidParameters};
    let (roll, yaw) = Scenario::default().lateral_laws();
    assert_eq!(
        roll,
        LateralLawParameters::default_for(LateralChannel::Roll)
    );
    assert_eq!(yaw, LateralLawParameters::default_for(LateralChannel::Yaw));
    assert_ne!(roll, yaw, "the channels' designed tunings differ");
    let text = "[control.roll]\ntype = \"pid\"\nderivative_per_s = 5.0\n\n\
                [control.yaw.observer]\nepsilon = 0.5\n";
    let scenario = load_scenario(text, "lateral.toml").expect("valid");
    let (roll, yaw) = scenario.lateral_laws();
    assert_eq!(
        roll,
        LateralLawParameters::Pid(LateralPidParameters {
            proportional_per_s2: 16.0,
            integral_per_s3: 2.0,
            derivative_per_s: 5.0,
        })
    );
    let LateralLawParameters::ObserverPd(opd) = yaw else {
        panic!("the yaw O-PD: {yaw:?}")
    };
    assert_eq!(
        (opd.settling_time_s, opd.observer.epsilon, opd.observer.k3),
        (2.0, 0.5, 3.0)
    );
    // Through a TOML round trip (what `land` writes next to its outputs).
    let written = toml::to_string(&scenario).expect("serialises");
    assert_eq!(load_scenario(&written, "written.toml"), Ok(scenario));
}

#[test]
fn bad_lateral_keys_are_named_with_their_line() {
    let cases: &[(&str, &str, usize)] = &[
        (
            "[control.roll]\nsettling_time_s = 0.0\n",
            "control.roll.settling_time_s",
            2,
        ),
        (
            "[control.yaw]\n\ndamping_ratio = 9.0\n",
            "control.yaw.damping_ratio",
            3,
        ),
        (
            "[control.yaw.observer]\nepsilon = 1.5\n",
            "control.yaw.observer.epsilon",
            2,
        ),
        (
            "[control.roll]\ntype = \"pid\"\nproportional_per_s2 = -1.0\n",
            "control.roll.proportional_per_s2",
            3,
        ),
        (
            "[control.roll]\ntype = \"pid\"\nintegral_per_s3 = nan\n",
            "control.roll.integral_per_s3",
            3,
        ),
        // The observer must be resolved by the 1 ms step: ε ≥ k3·dt/0.5 = 0.006.
        (
            "[control.roll.observer]\nepsilon = 0.002\n",
            "control.roll.observer.epsilon",
            2,
        ),
    ];
    for (text, field, line) in cases {
        let error = load_scenario(text, "bad.toml").expect_err(text);
        assert!(
            matches!(error, ScenarioError::OutOfRange { .. }),
            "{text}: {error}"
        );
        assert_eq!(
            (error.field(), error.line()),
            (*field, Some(*line)),
            "{error}"
        );
    }
    let structure: &[(&str, &str, &str)] = &[
        ("[control.roll]\ntype = \"lqr\"\n", "control.roll", "`lqr`"),
        (
            "[control.yaw]\nsettling_time = 2.0\n",
            "control.yaw.settling_time",
            "unknown field",
        ),
        (
            "[control.roll]\ntype = \"pid\"\ndamping_ratio = 1.0\n",
            "control.roll.damping_ratio",
            "unknown field",
        ),
        (
            "[control.yaw.observer]\nk4 = 1.0\n",
            "control.yaw.observer.k4",
            "unknown field",
        ),
    ];
    for (text, field, words) in structure {
        let error = load_scenario(text, "bad.toml").expect_err(text);
        let message = error.to_string();
        assert!(
            matches!(error, ScenarioError::Structure { .. }) && message.contains(words),
            "{text}: {message}"
        );
        assert!(error.field().starts_with(field), "{text}: {message}");
    }
}

/// The paper's set flies the 3-DOF model: a lateral law other than the designed one is
/// refused, naming the section and its line; the designed values (a paper scenario
/// written to TOML) are accepted.
#[test]
fn the_paper_set_refuses_a_lateral_law() {
    let text = "hardware = \"paper\"\n\n[control.yaw]\nsettling_time_s = 3.0\n";
    let error = load_scenario(text, "paper.toml").expect_err("paper with a yaw law");
    assert_eq!(
        (error.field(), error.line()),
        ("control.yaw", Some(3)),
        "{error}"
    );
    assert!(
        error.to_string().contains("hardware = \"paper\""),
        "{error}"
    );
    let written = toml::to_string(&Scenario::paper()).expect("serialises");
    assert_eq!(load_scenario(&written, "paper.toml"), Ok(Scenario::paper()));
    let mut scenario = Scenario::paper();
    scenario.control.roll = crate::control::lateral::LateralLawParameters::registered(
        "pid",
        crate::control::lateral::LateralChannel::Roll,
    )
    .expect("registered");
    let error = scenario.validate().expect_err("paper with a roll PID");
    assert_eq!(error.path, "control.roll", "{error}");
}

/// Issue 27, item 7: the realistic default is the 3-D approach (the 6-DOF aircraft on the
/// 9° angled deck of a ship at 15 kn = 7.7 m/s that rolls, yaws and sways); the paper's
/// set stays the 3-DOF behind a stationary ship, from a file too; a file's ship section
/// that leaves the speed out keeps its set's.
#[test]
fn the_realistic_default_is_the_3d_approach_and_the_papers_set_the_3dof() {
    let realistic = Scenario::default();
    assert_eq!(realistic.aircraft.model, PlantModel::SixDof);
    assert!(realistic.approach.three_dimensional);
    let ship = realistic.environment.ship;
    assert_eq!(ship.forward_speed_mps, 7.7);
    assert_eq!(realistic.environment.deck.deck_angle_deg, 9.0);
    assert_eq!(
        (ship.roll_rms_deg, ship.yaw_rms_deg, ship.sway_rms_m),
        (1.0, 0.3, 0.5)
    );
    assert_eq!(HardwareSet::Realistic.scenario(), realistic);

    let paper = Scenario::paper();
    assert_eq!(paper.aircraft.model, PlantModel::ThreeDof);
    assert_eq!(paper.environment.ship.forward_speed_mps, 0.0);

    let section_only = "[environment.ship]\nheave_rms_m = 1.0\n";
    let steaming = load_scenario(section_only, "r.toml").expect("valid");
    assert_eq!(steaming.environment.ship.forward_speed_mps, 7.7);
    assert_eq!(steaming.aircraft.model, PlantModel::SixDof);
    let paper_file = format!("hardware = \"paper\"\n{section_only}");
    let stationary = load_scenario(&paper_file, "p.toml").expect("valid");
    assert_eq!(stationary.environment.ship.forward_speed_mps, 0.0);
    assert_eq!(stationary.aircraft.model, PlantModel::ThreeDof);

    // The longitudinal design checks' scenario changes exactly these two keys.
    let longitudinal = realistic.longitudinal();
    assert_eq!(longitudinal.aircraft.model, PlantModel::ThreeDof);
    assert_eq!(longitudinal.environment.ship.forward_speed_mps, 0.0);
    let mut back = longitudinal;
    back.aircraft.model = PlantModel::SixDof;
    back.environment.ship.forward_speed_mps = 7.7;
    assert_eq!(back, realistic);
}
