//! The roll and yaw laws (issue 26 item 4; docs/lateral-control.md): their margins on the
//! full lateral model, the design code's margins against a direct sweep, the bank and
//! sideslip steps of the 6-DOF aircraft, and a user's own roll law in the step.

use deckland::aircraft::six_dof::{linearize_six_dof, SixDofLinearModel};
use deckland::control::design::loop_model::{log_grid, margins_of};
use deckland::control::design::{assess_loop, LinearActuator, SensorNoise};
use deckland::control::lateral::design::{
    channel_hardware, full_lateral_margins, FLIGHT_COMPUTER_DELAY_S,
};
use deckland::control::lateral::{LateralChannel, RollLawInputs};
use deckland::control::AxisLaw;
use deckland::experiments::{
    fly_lateral_step, CrosswindGust, LateralAxis, LateralSetup, LateralStep,
};
use nalgebra::Complex;

fn setup() -> (LateralSetup, SixDofLinearModel) {
    let setup = LateralSetup::approach().expect("the approach trims");
    let model = linearize_six_dof(&setup.aircraft, &setup.trim);
    (setup, model)
}

fn actuator(
    setup: &LateralSetup,
    model: &SixDofLinearModel,
    channel: LateralChannel,
) -> LinearActuator {
    let hardware = channel_hardware(&setup.aircraft, model, channel);
    LinearActuator {
        natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
        damping_ratio: hardware.actuator.damping_ratio,
    }
}

/// Issue 26's stability target: at least 45° and 6 dB on each channel, on the full
/// lateral model with both actuators and the 80 Hz computer's delay, for both laws.
#[test]
fn both_laws_keep_45_degrees_and_6_db_on_each_channel_of_the_full_model() {
    let (setup, model) = setup();
    for name in ["observer_pd", "pid"] {
        let (roll, yaw) = setup.registered_laws(name).expect("registered");
        let margins = full_lateral_margins(
            &model,
            actuator(&setup, &model, LateralChannel::Roll),
            actuator(&setup, &model, LateralChannel::Yaw),
            &roll.linear_law().expect("linear"),
            &yaw.linear_law().expect("linear"),
            FLIGHT_COMPUTER_DELAY_S,
        );
        assert!(
            margins.closed_loop_max_real_part < 0.0,
            "{name}: {margins:?}"
        );
        for (channel, m) in [("roll", margins.roll), ("yaw", margins.yaw)] {
            let pm = m.phase_margin_deg.expect("a crossover");
            let gm = m.gain_margin_db.unwrap_or(f64::INFINITY);
            assert!(pm >= 45.0 && gm >= 6.0, "{name} {channel}: {m:?}");
        }
    }
}

/// The design code's reduced roll loop against an independent closed form: the ideal
/// PD's loop gain with the O-PD's exact observer (no coupling: the observer's model is the
/// plant), L(jω) = (K_P + K_D·jω)/(jω·(jω − L_p)) · ω_a²/((jω)² + 2ζ_a·ω_a·jω + ω_a²) ·
/// e^{−jωτ}, swept by hand: the phase margins agree to 0.2°.
#[test]
fn the_design_codes_roll_margin_matches_a_direct_sweep_of_the_pd_loop() {
    let (setup, model) = setup();
    let (roll, _) = setup.registered_laws("observer_pd").expect("registered");
    let hardware = channel_hardware(&setup.aircraft, &model, LateralChannel::Roll);
    let quiet = SensorNoise {
        white_sigma_rad: 0.0,
        sample_interval_s: 0.0125,
        sinusoid_amplitude_rad: 0.0,
        sinusoid_frequency_radps: 1.0,
    };
    let assessed = assess_loop(&hardware, &quiet, &roll.linear_law().unwrap(), 1.0);
    // The registered roll O-PD: T_2% = 1 s, ζ = 1 → ω_n = 4, K_P = 16, K_D = 8 + L_p.
    let lp = hardware.plant.rate_damping_per_s;
    let (kp, kd) = (16.0, 8.0 + lp);
    let a = actuator(&setup, &model, LateralChannel::Roll);
    let omegas = log_grid(0.05, 100.0, 4000);
    let response: Vec<Complex<f64>> = omegas
        .iter()
        .map(|&w| {
            let s = Complex::new(0.0, w);
            let wa2 = a.natural_frequency_radps.powi(2);
            (kp + kd * s) / (s * (s - lp)) * wa2
                / (s * s + 2.0 * a.damping_ratio * a.natural_frequency_radps * s + wa2)
                * Complex::from_polar(1.0, -w * FLIGHT_COMPUTER_DELAY_S)
        })
        .collect();
    let direct = margins_of(&omegas, &response);
    let (pm, pm_direct) = (
        assessed.margins.phase_margin_deg.unwrap(),
        direct.phase_margin_deg.unwrap(),
    );
    assert!((pm - pm_direct).abs() < 0.2, "{pm} vs {pm_direct}");
    let (gm, gm_direct) = (
        assessed.margins.gain_margin_db.unwrap(),
        direct.gain_margin_db.unwrap(),
    );
    assert!((gm - gm_direct).abs() < 0.1, "{gm} vs {gm_direct}");
}

/// Flies `step` with the registered O-PD roll and yaw laws on the approach setup.
fn fly_opd(step: &LateralStep) -> deckland::experiments::LateralStepRun {
    let (setup, _) = setup();
    let (roll, yaw) = setup.registered_laws("observer_pd").expect("registered");
    fly_lateral_step(&setup, step, roll.as_ref(), yaw.as_ref()).expect("flies")
}

/// Issue 26's ideal bank step: 10° settles to ±5 % in at most 2 s with the O-PD, the
/// sideslip stays within ±1°, and the aileron's rate stays off its limit.
#[test]
fn the_opd_settles_an_ideal_10_degree_bank_step_within_2_s_coordinated() {
    let run = fly_opd(&LateralStep::new(LateralAxis::Roll, 10.0, 8.0));
    let r = &run.response;
    eprintln!("{r:#?}");
    assert!(r.settled, "{r:?}");
    assert!(r.settling_time_s.unwrap() <= 2.0, "{r:?}");
    assert!(r.max_sideslip_error_deg <= 1.0, "{r:?}");
    assert!(r.aileron_rate_rms_degps <= 50.0, "{r:?}");
    assert!(r.aileron_rate_limited_fraction <= 0.05, "{r:?}");
    // It banks the right way: positive aileron rolls right wing down.
    let last = run.samples.last().unwrap();
    assert!((last.bank_deg - 10.0).abs() < 0.5, "{last:?}");
}

/// A 5 m/s 1 − cos crosswind gust with the wings held level: the yaw law keeps β within
/// ±1° (the gust's duration, 4 s, is an assumption).
#[test]
fn the_yaw_law_holds_sideslip_through_a_5_m_s_crosswind_gust() {
    let step = LateralStep {
        gust: Some(CrosswindGust {
            peak_mps: 5.0,
            start_s: 1.0,
            duration_s: 4.0,
        }),
        ..LateralStep::new(LateralAxis::Roll, 0.0, 8.0)
    };
    let run = fly_opd(&step);
    eprintln!("{:#?}", run.response);
    assert_eq!(run.response.outcome, "completed");
    assert!(
        run.response.max_sideslip_error_deg <= 1.0,
        "{:?}",
        run.response
    );
}

/// A user's own roll law, a proportional-derivative one written here, flies the bank
/// step beside the registered yaw law.
#[derive(Debug)]
struct OwnRollLaw;

impl AxisLaw for OwnRollLaw {
    type Inputs = RollLawInputs;
    fn label(&self) -> &str {
        "own PD"
    }
    fn state_names(&self) -> &'static [&'static str] {
        &[]
    }
    fn surface_command_rad(&self, _: &[f64], inputs: &RollLawInputs) -> f64 {
        let c = &inputs.0;
        // δa = δa* + (K_P·(φ_r − φ) − K_D·p)/L_δa with K_P = 9, K_D = 5 and L_δa ≈ 5.7.
        c.surface_trim_rad
            + (9.0 * (c.command_rad - c.measured_rad) - 5.0 * c.rate_measured_radps) / 5.7
    }
    fn derivative(&self, _: &[f64], _: &RollLawInputs, _: &mut [f64]) {}
}

#[test]
fn a_users_own_roll_law_flies_the_bank_step() {
    let (setup, _) = setup();
    let (_, yaw) = setup.registered_laws("observer_pd").expect("registered");
    let run = fly_lateral_step(
        &setup,
        &LateralStep::new(LateralAxis::Roll, 10.0, 8.0),
        &OwnRollLaw,
        yaw.as_ref(),
    )
    .expect("flies");
    assert_eq!(run.response.controller, "own PD");
    let last = run.samples.last().unwrap();
    assert!((last.bank_deg - 10.0).abs() < 1.0, "{last:?}");
}

/// A sideslip step: the yaw law reaches the commanded β and the bank stays near level.
#[test]
fn the_opd_flies_a_sideslip_step() {
    let run = fly_opd(&LateralStep::new(LateralAxis::Yaw, 2.0, 10.0));
    eprintln!("{:#?}", run.response);
    assert!(run.response.settled, "{:?}", run.response);
    let last = run.samples.last().unwrap();
    assert!((last.sideslip_deg - 2.0).abs() < 0.1, "{last:?}");
}

#[test]
fn a_step_out_of_range_is_refused_by_name() {
    let (setup, _) = setup();
    let (roll, yaw) = setup.registered_laws("pid").expect("registered");
    let error = fly_lateral_step(
        &setup,
        &LateralStep::new(LateralAxis::Roll, 45.0, 8.0),
        roll.as_ref(),
        yaw.as_ref(),
    )
    .expect_err("45° is too far");
    assert!(error.to_string().contains("step_deg"), "{error}");
    let unknown = setup.registered_laws("lqr").expect_err("not registered");
    assert!(unknown.to_string().contains("control.roll"), "{unknown}");
}
