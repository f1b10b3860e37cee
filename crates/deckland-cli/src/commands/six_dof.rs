//! `deckland trim --model 6dof` and `deckland linearize --model 6dof`: the 6-DOF
//! aircraft's trim in sideslip or in a crosswind (the crab), its lateral-directional
//! linear model with names and units, and the lateral modes (docs/six-dof.md).

use anyhow::{bail, Context, Result};
use deckland::aircraft::six_dof::{
    linearize_six_dof, trim_six_dof, LateralModesReport, LateralParameters, RealMode,
    SixDofAircraft, SixDofLinearModel, SixDofTrimError, SixDofTrimPoint, SixDofTrimReport,
    SixDofTrimRequest, SurfaceActuatorParameters, LATERAL_INPUT_NAMES, LATERAL_INPUT_UNITS,
    LATERAL_STATE_NAMES, LATERAL_STATE_UNITS,
};
use deckland::aircraft::TrimRequest;
use deckland::analysis::{INPUT_NAMES, INPUT_UNITS, STATE_NAMES, STATE_UNITS};
use deckland::environment::Wind;
use serde::Serialize;

use super::flight_condition::TrimArgs;
use super::linearize::{labelled, print_matrix};
use crate::output::{fixed, rows};

/// `linearize --model 6dof --json`: the trim, both blocks with names and units, the modes.
#[derive(Debug, Serialize)]
struct SixDofLinearizeReport {
    trim: SixDofTrimReport,
    lateral_state_names: [&'static str; 4],
    lateral_state_units: [&'static str; 4],
    lateral_input_names: [&'static str; 2],
    lateral_input_units: [&'static str; 2],
    lateral_a: Vec<Vec<f64>>,
    lateral_b: Vec<Vec<f64>>,
    lateral_modes: Option<LateralModesReport>,
    longitudinal_state_names: [&'static str; 4],
    longitudinal_state_units: [&'static str; 4],
    longitudinal_input_names: [&'static str; 2],
    longitudinal_input_units: [&'static str; 2],
    longitudinal_a: Vec<Vec<f64>>,
    longitudinal_b: Vec<Vec<f64>>,
}

/// The 6-DOF aircraft in the requested configuration, with the default lateral data and
/// aileron and rudder actuators (docs/six-dof.md).
fn aircraft(args: &TrimArgs) -> Result<SixDofAircraft> {
    SixDofAircraft::new(
        args.aircraft(),
        LateralParameters::default(),
        SurfaceActuatorParameters::AILERON,
        SurfaceActuatorParameters::RUDDER,
    )
    .context("the 6-DOF aircraft's default parameters")
}

/// Trims the 6-DOF aircraft as `args` ask, naming the option at fault.
fn trim(args: &TrimArgs, aircraft: &SixDofAircraft) -> Result<SixDofTrimPoint> {
    let request = SixDofTrimRequest {
        longitudinal: TrimRequest {
            speed_mps: args.speed_mps,
            flight_path_angle_rad: args.gamma_deg.to_radians(),
        },
        sideslip_rad: args.sideslip_deg.to_radians(),
        wind: Wind {
            y_mps: args.crosswind_mps,
            ..Wind::default()
        },
    };
    if !args.crosswind_mps.is_finite() {
        bail!(
            "--crosswind {:?} is not allowed: expected a finite crosswind (m/s)",
            args.crosswind_mps
        );
    }
    match trim_six_dof(aircraft, &request) {
        Ok(point) => Ok(point),
        Err(SixDofTrimError::InvalidSideslip { .. }) => bail!(
            "--sideslip {:?} is not allowed: expected a sideslip between -30 and +30 degrees",
            args.sideslip_deg
        ),
        Err(error @ SixDofTrimError::CrosswindTooStrong { .. }) => {
            bail!("--crosswind {:?} is refused: {error}", args.crosswind_mps)
        }
        Err(SixDofTrimError::Longitudinal(error)) => {
            // The longitudinal start names the speed or the flight path: the 3-DOF trim
            // gives the same message with the option.
            args.trim(&args.aircraft())?;
            Err(error).context("the 6-DOF trim's longitudinal start failed")
        }
        Err(error) => Err(error).with_context(|| {
            format!(
                "cannot trim the 6-DOF aircraft ({} configuration) at {} m/s, γ = {}°, \
                 β = {}°, crosswind {} m/s",
                args.configuration,
                args.speed_mps,
                args.gamma_deg,
                args.sideslip_deg,
                args.crosswind_mps
            )
        }),
    }
}

fn print_trim(args: &TrimArgs, point: &SixDofTrimPoint) -> Result<()> {
    outln!(
        "Trim, 6-DOF — {} configuration, V_T = {:.2} m/s, γ = {:.2}°, β = {:.2}°, crosswind W_y = {:.2} m/s",
        args.configuration,
        point.speed_mps,
        point.flight_path_angle_rad.to_degrees(),
        point.sideslip_rad.to_degrees(),
        point.wind.y_mps
    )?;
    let rows = [
        ("angle of attack α", point.alpha_rad, ""),
        ("pitch angle θ", point.theta_rad, ""),
        ("bank angle φ", point.phi_rad, "(right wing down positive)"),
        (
            "heading ψ",
            point.psi_rad,
            "(from the final bearing, nose right positive)",
        ),
        (
            "elevator δe",
            point.elevator_rad,
            "(positive trailing edge down)",
        ),
        (
            "aileron δa",
            point.aileron_rad,
            "(positive: right-wing-down moment)",
        ),
        (
            "rudder δr",
            point.rudder_rad,
            "(positive trailing edge left)",
        ),
    ];
    for (name, value_rad, note) in rows {
        let value = fixed(value_rad.to_degrees(), 3);
        if note.is_empty() {
            outln!("  {name:<20}{value:>10} °")?;
        } else {
            outln!("  {name:<20}{value:>10} °   {note}")?;
        }
    }
    outln!(
        "  thrust T            {:>10.0} N   (throttle {:.3})",
        point.thrust_n,
        point.throttle
    )?;
    outln!(
        "  largest residual    {:.1e}  ({} Newton iterations)",
        point.residual,
        point.iterations
    )?;
    Ok(())
}

/// Runs `deckland trim --model 6dof`.
pub fn run_trim(args: &TrimArgs) -> Result<()> {
    let aircraft = aircraft(args)?;
    let point = trim(args, &aircraft)?;
    super::common::print_json_or(
        args.json,
        || point.report(args.configuration),
        || print_trim(args, &point),
    )
}

fn print_real_mode(name: &str, mode: &RealMode) -> Result<()> {
    outln!(
        "  {name:<16}{:>12} 1/s   τ = {:>8} s   {} {:.2} s",
        fixed(mode.eigenvalue_per_s, 4),
        fixed(mode.time_constant_s, 3),
        if mode.stable {
            "time to half"
        } else {
            "time to double"
        },
        mode.time_to_half_or_double_s
    )?;
    Ok(())
}

fn print_linear(args: &TrimArgs, model: &SixDofLinearModel) -> Result<()> {
    print_trim(args, &model.trim)?;
    outln!()?;
    outln!("Lateral-directional linear model ẋ = A x + B u (airframe, still air)")?;
    let states = labelled(&LATERAL_STATE_NAMES, &LATERAL_STATE_UNITS);
    let inputs = labelled(&LATERAL_INPUT_NAMES, &LATERAL_INPUT_UNITS);
    print_matrix("A", &model.lateral_a(), &LATERAL_STATE_NAMES, &states, 24)?;
    print_matrix("B", &model.lateral_b(), &LATERAL_STATE_NAMES, &inputs, 24)?;
    outln!()?;
    outln!("Lateral modes")?;
    match model.lateral_modes() {
        Some(modes) => {
            let dutch = &modes.dutch_roll;
            outln!(
                "  {:<16}{:>12} ± {}i 1/s   ω_n = {:.4} rad/s   ζ = {:.4}",
                "Dutch roll",
                fixed(dutch.eigenvalue.re, 4),
                fixed(dutch.eigenvalue.im, 4),
                dutch.natural_frequency_radps,
                dutch.damping_ratio
            )?;
            print_real_mode("roll subsidence", &modes.roll_subsidence)?;
            print_real_mode("spiral", &modes.spiral)?;
        }
        None => outln!(
            "  the lateral eigenvalues are not one oscillatory pair and two real roots: {:?}",
            model.lateral_a().complex_eigenvalues().as_slice()
        )?,
    }
    outln!()?;
    outln!("Longitudinal block (as `deckland linearize --model 3dof`)")?;
    let states = labelled(&STATE_NAMES, &STATE_UNITS);
    let inputs = labelled(&INPUT_NAMES, &INPUT_UNITS);
    print_matrix("A", &model.longitudinal_a(), &STATE_NAMES, &states, 24)?;
    print_matrix("B", &model.longitudinal_b(), &STATE_NAMES, &inputs, 24)?;
    Ok(())
}

/// Runs `deckland linearize --model 6dof`.
pub fn run_linearize(args: &TrimArgs) -> Result<()> {
    let aircraft = aircraft(args)?;
    let point = trim(args, &aircraft)?;
    let model = linearize_six_dof(&aircraft, &point);
    if args.json {
        let report = SixDofLinearizeReport {
            trim: point.report(args.configuration),
            lateral_state_names: LATERAL_STATE_NAMES,
            lateral_state_units: LATERAL_STATE_UNITS,
            lateral_input_names: LATERAL_INPUT_NAMES,
            lateral_input_units: LATERAL_INPUT_UNITS,
            lateral_a: rows(&model.lateral_a()),
            lateral_b: rows(&model.lateral_b()),
            lateral_modes: model.lateral_modes().as_ref().map(Into::into),
            longitudinal_state_names: STATE_NAMES,
            longitudinal_state_units: STATE_UNITS,
            longitudinal_input_names: INPUT_NAMES,
            longitudinal_input_units: INPUT_UNITS,
            longitudinal_a: rows(&model.longitudinal_a()),
            longitudinal_b: rows(&model.longitudinal_b()),
        };
        outln!("{}", serde_json::to_string_pretty(&report)?)?;
    } else {
        print_linear(args, &model)?;
    }
    Ok(())
}
