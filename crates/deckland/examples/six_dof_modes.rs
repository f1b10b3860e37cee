//! Trim and lateral modes of the 6-DOF F/A-18 at the approach condition (69.1 m/s,
//! landing configuration): straight and level (and the modes on a −3.5° path), a 5°
//! steady sideslip, and the crab in a 5 m/s crosswind from the left. Run with
//! `cargo run --release -p deckland --example six_dof_modes`.

use deckland::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, SixDofAircraft, SixDofTrimPoint, SixDofTrimRequest,
    LATERAL_INPUT_NAMES, LATERAL_INPUT_UNITS, LATERAL_STATE_NAMES, LATERAL_STATE_UNITS,
};
use deckland::aircraft::TrimRequest;
use deckland::environment::Wind;

fn print_trim(title: &str, point: &SixDofTrimPoint) {
    println!("{title}");
    println!(
        "  V = {:.1} m/s  γ = {:.2}°  β = {:.2}°  α = {:.3}°  θ = {:.3}°  φ = {:.3}°  ψ = {:.3}°",
        point.speed_mps,
        point.flight_path_angle_rad.to_degrees(),
        point.sideslip_rad.to_degrees(),
        point.alpha_rad.to_degrees(),
        point.theta_rad.to_degrees(),
        point.phi_rad.to_degrees(),
        point.psi_rad.to_degrees(),
    );
    println!(
        "  δe = {:.3}°  δa = {:.3}°  δr = {:.3}°  T = {:.0} N  (residual {:.1e}, {} iterations)",
        point.elevator_rad.to_degrees(),
        point.aileron_rad.to_degrees(),
        point.rudder_rad.to_degrees(),
        point.thrust_n,
        point.residual,
        point.iterations,
    );
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let aircraft = SixDofAircraft::default();
    let level = SixDofTrimRequest::default();
    let trim = trim_six_dof(&aircraft, &level)?;
    print_trim("Straight and level, 69.1 m/s, landing configuration", &trim);

    let model = linearize_six_dof(&aircraft, &trim);
    let a = model.lateral_a();
    let b = model.lateral_b();
    println!("\nLateral model ẋ = A x + B u");
    let inputs: Vec<String> = LATERAL_INPUT_NAMES
        .iter()
        .zip(LATERAL_INPUT_UNITS)
        .map(|(n, u)| format!("{n} [{u}]"))
        .collect();
    println!("  inputs: {}", inputs.join(", "));
    for i in 0..4 {
        let row: Vec<String> = (0..4).map(|j| format!("{:>10.5}", a[(i, j)])).collect();
        let input: Vec<String> = (0..2).map(|j| format!("{:>10.5}", b[(i, j)])).collect();
        println!(
            "  d {:<10} [{:<5}]/dt: A {}   B {}",
            LATERAL_STATE_NAMES[i],
            LATERAL_STATE_UNITS[i],
            row.join(""),
            input.join("")
        );
    }
    let modes = model
        .lateral_modes()
        .ok_or("the lateral eigenvalues are not one oscillatory pair and two real roots")?;
    let dutch = modes.dutch_roll;
    println!("\nLateral modes");
    println!(
        "  Dutch roll:      λ = {:.4} ± {:.4}i 1/s, ω_n = {:.4} rad/s, ζ = {:.4}",
        dutch.eigenvalue.re,
        dutch.eigenvalue.im,
        dutch.natural_frequency_radps,
        dutch.damping_ratio
    );
    for (name, mode) in [
        ("Roll subsidence", modes.roll_subsidence),
        ("Spiral", modes.spiral),
    ] {
        println!(
            "  {:<16} λ = {:.4} 1/s, τ = {:.3} s, time to {} = {:.2} s",
            format!("{name}:"),
            mode.eigenvalue_per_s,
            mode.time_constant_s,
            if mode.stable { "half" } else { "double" },
            mode.time_to_half_or_double_s,
        );
    }

    let glide = SixDofTrimRequest {
        longitudinal: TrimRequest {
            speed_mps: 69.1,
            flight_path_angle_rad: (-3.5f64).to_radians(),
        },
        ..level
    };
    let glide_trim = trim_six_dof(&aircraft, &glide)?;
    if let Some(modes) = linearize_six_dof(&aircraft, &glide_trim).lateral_modes() {
        println!(
            "  On a -3.5° path: Dutch roll ω_n = {:.4} rad/s, ζ = {:.4}; roll τ = {:.3} s; \
             spiral τ = {:.3} s",
            modes.dutch_roll.natural_frequency_radps,
            modes.dutch_roll.damping_ratio,
            modes.roll_subsidence.time_constant_s,
            modes.spiral.time_constant_s,
        );
    }

    let sideslip = SixDofTrimRequest {
        sideslip_rad: 5f64.to_radians(),
        ..level
    };
    println!();
    print_trim(
        "Steady sideslip β = 5° (wind from the right)",
        &trim_six_dof(&aircraft, &sideslip)?,
    );

    let crab = SixDofTrimRequest {
        wind: Wind {
            y_mps: 5.0,
            ..Wind::default()
        },
        longitudinal: TrimRequest::default(),
        ..level
    };
    println!();
    print_trim(
        "Crab in a 5 m/s crosswind from the left (W_y = +5 m/s)",
        &trim_six_dof(&aircraft, &crab)?,
    );
    Ok(())
}
