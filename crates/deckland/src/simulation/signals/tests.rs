//! Tests of the signal registry.

use super::*;

#[test]
fn signals_out_of_range_are_named_with_their_value() {
    let mut signals = Signals {
        airspeed_mps: 69.1,
        ..Signals::default()
    };
    assert_eq!(signals.first_out_of_range(), None);
    signals.elevator_command_rad = f64::NEG_INFINITY;
    assert_eq!(
        signals.first_out_of_range(),
        Some(("elevator_command_rad", f64::NEG_INFINITY))
    );
    signals.elevator_command_rad = 0.0;
    signals.aim_point.x_m = 2e12;
    assert_eq!(signals.first_out_of_range(), Some(("aim_point.x_m", 2e12)));
    signals.aim_point.x_m = 0.0;
    signals.climb_rate_command_mps = Some(f64::NAN);
    let (name, value) = signals.first_out_of_range().expect("NaN is out of range");
    assert_eq!(name, "climb_rate_command_mps");
    assert!(value.is_nan());
    // A signal that does not apply is not a divergence.
    signals.climb_rate_command_mps = None;
    signals.path_height_m = None;
    assert_eq!(signals.first_out_of_range(), None);
}

#[test]
fn the_registry_names_each_signal_once_in_the_order_of_its_identifiers() {
    let mut names = std::collections::HashSet::new();
    for (index, spec) in SIGNALS.iter().enumerate() {
        assert_eq!(spec.id as usize, index, "{} out of order", spec.name);
        assert!(names.insert(spec.name), "{} registered twice", spec.name);
        assert_eq!(SignalId::from_name(spec.name), Some(spec.id));
        assert!(!spec.unit.is_empty() && !spec.description.is_empty());
    }
    assert_eq!(SignalId::from_name("no_such_signal"), None);
}

/// Every field set to a distinct value, 1 to [`SIGNAL_COUNT`] in the registry's order
/// (the elevator's rate, which is not registered, 0).
fn numbered_signals() -> Signals {
    Signals {
        time_s: 1.0,
        x_m: 2.0,
        h_m: 3.0,
        hook_x_m: 4.0,
        hook_h_m: 5.0,
        hook_climb_rate_mps: 6.0,
        hook_x_rate_mps: 7.0,
        path_height_m: Some(8.0),
        glide_path_error_m: 9.0,
        time_to_go_s: Some(10.0),
        compensation_weight: 11.0,
        airspeed_mps: 12.0,
        alpha_rad: 13.0,
        theta_rad: 14.0,
        theta_measured_rad: 15.0,
        theta_ref_rad: 16.0,
        q_radps: 17.0,
        climb_rate_mps: 18.0,
        climb_rate_command_mps: Some(19.0),
        elevator_rad: 20.0,
        elevator_rate_radps: 0.0,
        elevator_command_rad: 21.0,
        thrust_n: 22.0,
        thrust_command_n: 23.0,
        wind: Wind {
            x_mps: 24.0,
            z_mps: 25.0,
            ..Default::default()
        },
        distance_aft_m: 26.0,
        ship: ShipPose {
            pitch_centre_x_m: 27.0,
            heave_m: 28.0,
            pitch_rad: 29.0,
            ..Default::default()
        },
        ship_rate: ShipPoseRate {
            pitch_centre_x_rate_mps: 30.0,
            heave_rate_mps: 31.0,
            pitch_rate_radps: 32.0,
            ..Default::default()
        },
        aim_point: EarthPoint {
            x_m: 33.0,
            h_m: 34.0,
            ..Default::default()
        },
        disturbance_estimate_radps2: Some(35.0),
        direct_lift_coefficient: Some(36.0),
        direct_lift_command: Some(37.0),
        range_to_go_m: 38.0,
        path_anchor_height_m: Some(39.0),
        y_m: Some(40.0),
        hook_y_m: Some(41.0),
        phi_rad: Some(42.0),
        psi_rad: Some(43.0),
        p_radps: Some(44.0),
        r_radps: Some(45.0),
        beta_rad: Some(46.0),
        aileron_rad: Some(47.0),
        aileron_command_rad: Some(48.0),
        rudder_rad: Some(49.0),
        rudder_command_rad: Some(50.0),
        lateral: crate::simulation::signals::LateralSignals {
            cross_track_m: Some(51.0),
            cross_track_rate_mps: Some(52.0),
            aim_point_y_m: Some(53.0),
            centreline_heading_rad: Some(54.0),
            lineup_error_m: Some(55.0),
            lateral_forecast_m: Some(56.0),
            bank_command_rad: Some(57.0),
            ship_roll_rad: Some(58.0),
            ship_yaw_rad: Some(59.0),
            ship_sway_m: Some(60.0),
            wind_y_mps: Some(61.0),
        },
    }
}

#[test]
fn each_registered_signal_reads_its_own_field() {
    // Each registered accessor must find the value of the field its name names (a
    // swapped accessor would read another).
    let s = numbered_signals();
    let values: Vec<f64> = s
        .named_values()
        .iter()
        .map(|(_, v)| v.expect("set"))
        .collect();
    let expected: Vec<f64> = (1..=SIGNAL_COUNT).map(|i| i as f64).collect();
    assert_eq!(values, expected);
    assert_eq!(s.get(SignalId::WindZ), Some(25.0));
    let mut written = Signals::default();
    for spec in &SIGNALS {
        written.set(spec.id, (spec.value)(&s).expect("set"));
    }
    written.elevator_rate_radps = s.elevator_rate_radps;
    assert_eq!(written, s);
    let column = RecordedColumn::degrees("theta_deg", SignalId::Theta);
    assert_eq!(column.value(&s), Some(14.0_f64.to_degrees()));
    assert_eq!(column.unit(), "deg");
    assert_eq!(RecordedColumn::si("x", SignalId::Thrust).unit(), "N");
    let sink = RecordedColumn::negated("sink_rate_mps", SignalId::ClimbRate);
    assert_eq!((sink.value(&s), sink.unit()), (Some(-18.0), "m/s"));
}
