//! The roll and yaw laws' design at the approach trim (69.1 m/s, level, landing
//! configuration; docs/lateral-control.md): each channel's plant from the 6-DOF
//! linearisation, each registered law's margins on the reduced channel loop (the design
//! code's `assess_loop`) and on the full lateral loop with the other channel closed, both
//! actuators and the 80 Hz computer's delay. Run with
//! `cargo run --release -p deckland --example lateral_margins`.

use deckland::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, SixDofAircraft, SixDofTrimRequest,
};
use deckland::control::design::{assess_loop, LinearActuator, SensorNoise};
use deckland::control::lateral::design::{
    channel_hardware, channel_plants, full_lateral_margins, FLIGHT_COMPUTER_DELAY_S,
};
use deckland::control::lateral::{LateralChannel, LateralDesignContext, LateralLawParameters};

fn format(value: Option<f64>, unit: &str) -> String {
    value.map_or("∞".to_owned(), |v| format!("{v:.1} {unit}"))
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let aircraft = SixDofAircraft::default();
    let trim = trim_six_dof(&aircraft, &SixDofTrimRequest::default())?;
    let model = linearize_six_dof(&aircraft, &trim);
    let (roll, yaw) = channel_plants(&model);
    println!("Approach trim, 69.1 m/s: channel plants from the lateral linearisation");
    println!(
        "  roll (φ, p, δa): L_p = {:.4} 1/s, L_δa = {:.4} 1/s²",
        roll.rate_damping_per_s, roll.control_power_per_s2
    );
    println!(
        "  yaw (β, −r, δr): N_r = {:.4} 1/s, −N_δr = {:.4} 1/s²",
        yaw.rate_damping_per_s, yaw.control_power_per_s2
    );
    println!(
        "  computer delay {:.2} ms (80 Hz: half a frame + one frame)\n",
        FLIGHT_COMPUTER_DELAY_S * 1e3
    );
    let linear = |hardware: &deckland::control::design::AxisHardware| LinearActuator {
        natural_frequency_radps: hardware.actuator.natural_frequency_rad_s,
        damping_ratio: hardware.actuator.damping_ratio,
    };
    let roll_hw = channel_hardware(&aircraft, &model, LateralChannel::Roll);
    let yaw_hw = channel_hardware(&aircraft, &model, LateralChannel::Yaw);
    let quiet = SensorNoise {
        white_sigma_rad: 0.0,
        sample_interval_s: 1.0 / 80.0,
        sinusoid_amplitude_rad: 0.0,
        sinusoid_frequency_radps: 1.0,
    };
    for name in LateralLawParameters::REGISTERED {
        let roll_params =
            LateralLawParameters::registered(name, LateralChannel::Roll).expect("registered");
        let yaw_params =
            LateralLawParameters::registered(name, LateralChannel::Yaw).expect("registered");
        let roll_law = roll_params
            .build_roll(&LateralDesignContext {
                plant: roll,
                actuator: roll_hw.actuator,
            })?
            .linear_law()
            .expect("linear");
        let yaw_law = yaw_params
            .build_yaw(&LateralDesignContext {
                plant: yaw,
                actuator: yaw_hw.actuator,
            })?
            .linear_law()
            .expect("linear");
        println!("{}: roll {:?}", roll_params.label(), roll_params);
        println!("{}: yaw  {:?}", yaw_params.label(), yaw_params);
        for (channel, hardware, law) in [("roll", &roll_hw, &roll_law), ("yaw", &yaw_hw, &yaw_law)]
        {
            let reduced = assess_loop(hardware, &quiet, law, 1.0);
            println!(
                "  {channel:<4} reduced loop: phase margin {} at {}, gain margin {}",
                format(reduced.margins.phase_margin_deg, "°"),
                format(reduced.margins.crossover_radps, "rad/s"),
                format(reduced.margins.gain_margin_db, "dB"),
            );
        }
        let full = full_lateral_margins(
            &model,
            linear(&roll_hw),
            linear(&yaw_hw),
            &roll_law,
            &yaw_law,
            FLIGHT_COMPUTER_DELAY_S,
        );
        for (channel, margins) in [("roll", full.roll), ("yaw", full.yaw)] {
            println!(
                "  {channel:<4} full lateral loop: phase margin {} at {}, gain margin {} at {}",
                format(margins.phase_margin_deg, "°"),
                format(margins.crossover_radps, "rad/s"),
                format(margins.gain_margin_db, "dB"),
                format(margins.phase_crossover_radps, "rad/s"),
            );
        }
        println!(
            "  closed loop without delay: largest real part {:.3} 1/s\n",
            full.closed_loop_max_real_part
        );
    }
    Ok(())
}
