//! Tests of the design procedure against hand calculations.

use super::*;
use crate::aircraft::ElevatorActuatorParameters;
use crate::sensors::PitchNoiseParameters;

/// The pitch plant at the approach trim of the landing configuration
/// (`deckland linearize`).
pub(crate) const PLANT: AxisPlantDerivatives = AxisPlantDerivatives {
    rate_damping_per_s: -0.1891,
    control_power_per_s2: -1.9675,
};

/// The default elevator actuator as a linear second-order lag.
pub(crate) const ACTUATOR: LinearActuator = LinearActuator {
    natural_frequency_radps: 30.74,
    damping_ratio: 0.509,
};

/// The approach trim of the landing configuration (`deckland linearize`).
pub(crate) fn hardware(rate_limit_degps: Option<f64>) -> AxisHardware {
    AxisHardware {
        actuator: ElevatorActuatorParameters {
            rate_limit_degps,
            ..ElevatorActuatorParameters::default()
        },
        actuator_keys: ActuatorKeys::ELEVATOR,
        surface_trim_rad: (-8.17f64).to_radians(),
        plant: PLANT,
        coupling: Some(AngleOfAttackCoupling {
            dalphadot_dalpha_per_s: -0.526_839,
            dalphadot_delevator_per_s: -0.066_65,
            dqdot_dalpha_per_s2: -0.259_898,
        }),
        control_delay_s: 0.0,
    }
}

/// The paper's pitch-sensor noise sampled at 1 ms.
pub(crate) fn noise() -> SensorNoise {
    SensorNoise::from_parameters(&PitchNoiseParameters::default(), 0.001)
}

/// Hand calculation: travel to the nearer stop 25° − 8.17° = 16.83° = 0.29374 rad;
/// A = 0.8·1.9675·0.29374 = 0.46235 rad/s²; J = 0.75·0.69813·1.9675 − 0.1891·0.46235
/// = 1.03017 − 0.08743 = 0.94274 rad/s³.
#[test]
fn command_bounds_follow_from_rate_limit_and_travel() {
    let (jerk, acceleration, stop) = command_bounds(&hardware(Some(40.0)), 0.75, 0.8);
    assert!((acceleration - 0.462_35).abs() < 1e-4, "{acceleration}");
    assert!((jerk - 0.942_74).abs() < 1e-4, "{jerk}");
    assert_eq!(stop, "aircraft.elevator_actuator.min_deflection_deg");
}

/// 5° step with the default η = 0.6: J = 0.6·0.69813·1.9675 − 0.1891·0.46235 = 0.82414
/// − 0.08743 = 0.73671 rad/s³; τ_j = (0.087266/(2·0.73671))^(1/3) = 0.38980 s, peak
/// acceleration 0.28717 < A, T = 4τ_j = 1.55919 s; plus the actuator's lag
/// 2·0.509/30.74 = 0.03312 s: 1.59231 s. A request of 1.2 s is refused, naming the
/// rate limit; 2 s is granted with a gentler trajectory.
#[test]
fn settling_time_below_the_rate_limit_minimum_is_refused_by_name() {
    let request = DesignRequest {
        command_settling_time_s: Some(1.2),
        ..DesignRequest::default()
    };
    let error = design_command(&hardware(Some(40.0)), &request).expect_err("too fast");
    let DesignError::SettlingTimeTooShort {
        minimum_s,
        limiting,
        ..
    } = &error
    else {
        panic!("{error:?}");
    };
    assert!((minimum_s - 1.592_31).abs() < 1e-4, "{minimum_s}");
    assert_eq!(*limiting, "aircraft.elevator_actuator.rate_limit_degps");
    assert!(error.to_string().contains("rate_limit_degps"), "{error}");
    let slower = DesignRequest {
        command_settling_time_s: Some(2.0),
        ..DesignRequest::default()
    };
    let (step, settling) = design_command(&hardware(Some(40.0)), &slower).expect("ok");
    assert!((settling - 2.0).abs() < 1e-12);
    assert!((step.duration_s() + 2.0 * 0.509 / 30.74 - 2.0).abs() < 1e-6);
}

/// Without a rate limit the jerk is unbounded and the stop sets the minimum: a 5° step
/// at A = 0.46235 rad/s² needs 2·√(Δθ/A) = 0.86890 s (bang-bang in acceleration),
/// 0.90202 s with the actuator's lag.
#[test]
fn without_rate_limit_the_stop_limits() {
    let request = DesignRequest {
        command_settling_time_s: Some(0.5),
        ..DesignRequest::default()
    };
    let error = design_command(&hardware(None), &request).expect_err("too fast");
    let DesignError::SettlingTimeTooShort {
        minimum_s,
        limiting,
        ..
    } = error
    else {
        panic!("{error:?}");
    };
    assert_eq!(limiting, "aircraft.elevator_actuator.min_deflection_deg");
    assert!(
        (minimum_s - 0.033_12 - 0.868_88).abs() < 1e-4,
        "{minimum_s}"
    );
}

/// Any law given as data is assessed: the ideal PD (no states) closes a stable loop, its
/// noise-driven elevator rate grows in proportion to the sensor's σ, and a silent sensor
/// drives nothing.
#[test]
fn a_law_given_as_data_is_assessed_and_its_noise_scales_with_the_sensor() {
    let hardware = hardware(Some(40.0));
    let md = hardware.plant.control_power_per_s2;
    let (kp, kd) = (6.25, 4.81);
    let mut law = LinearLaw::without_states();
    law.output_inputs = [kp / md, -kp / md, -kd / md, 0.0];
    let noisy = noise();
    let assessed = assess_loop(&hardware, &noisy, &law, 1.2);
    assert!(assessed.closed_loop_max_real_part < 0.0, "{assessed:?}");
    assert!(assessed.margins.phase_margin_deg.expect("pm") > 0.0);
    let twice = SensorNoise {
        white_sigma_rad: 2.0 * noisy.white_sigma_rad,
        ..noisy
    };
    let doubled = assess_loop(&hardware, &twice, &law, 1.2);
    let ratio =
        doubled.noise.white_surface_rate_rms_radps / assessed.noise.white_surface_rate_rms_radps;
    assert!((ratio - 2.0).abs() < 1e-12, "{ratio}");
    let silent = SensorNoise {
        white_sigma_rad: 0.0,
        sinusoid_amplitude_rad: 0.0,
        ..noisy
    };
    let quiet = assess_loop(&hardware, &silent, &law, 1.2);
    assert_eq!(quiet.noise.surface_rate_rms_radps, 0.0);
}
