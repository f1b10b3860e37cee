//! `deckland trim`: steady straight flight at a given airspeed and flight-path angle.

use anyhow::Result;
use deckland::aircraft::ConfigurationName;
use deckland::analysis::TrimPoint;

use super::flight_condition::TrimArgs;

/// Prints a trim point as a readable table.
pub fn print_trim_table(
    configuration: ConfigurationName,
    point: &TrimPoint,
    max_thrust_n: f64,
) -> Result<()> {
    outln!(
        "Trim — {configuration} configuration, V_T = {:.2} m/s, γ = {:.2}°",
        point.speed_mps,
        point.flight_path_angle_rad.to_degrees()
    )?;
    outln!(
        "  angle of attack α   {:>10.3} °",
        point.alpha_rad.to_degrees()
    )?;
    outln!(
        "  pitch angle θ       {:>10.3} °",
        point.theta_rad.to_degrees()
    )?;
    outln!(
        "  elevator δe         {:>10.3} °   (positive trailing edge down)",
        point.elevator_rad.to_degrees()
    )?;
    outln!(
        "  thrust T            {:>10.0} N   (throttle {:.3} of {:.0} N, both engines)",
        point.thrust_n,
        point.throttle,
        max_thrust_n
    )?;
    let r = &point.residuals;
    outln!(
        "  residuals           V̇ {:.1e} m/s², α̇ {:.1e} rad/s, q̇ {:.1e} rad/s²  ({} Newton iterations)",
        r.airspeed_rate_mps2, r.alpha_rate_radps, r.pitch_acceleration_radps2, point.iterations
    )?;
    Ok(())
}

/// `deckland trim --model 3dof`.
pub fn run_three_dof(args: &TrimArgs) -> Result<()> {
    let (aircraft, point) = args.three_dof_trim()?;
    super::common::print_json_or(
        args.json,
        || point.report(args.configuration),
        || {
            print_trim_table(
                args.configuration,
                &point,
                aircraft.engines().max_total_thrust_n(),
            )
        },
    )
}
