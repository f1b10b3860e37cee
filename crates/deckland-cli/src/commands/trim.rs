//! `deckland trim`: steady straight flight at a given airspeed and flight-path angle.

use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use deckland::aircraft::{AerodynamicConfiguration, Aircraft, ConfigurationName};
use deckland::analysis::{trim, TrimError, TrimPoint, TrimRequest};

/// Options shared by `trim` and `linearize`.
#[derive(Debug, Clone, Args)]
pub struct TrimArgs {
    /// True airspeed (m/s).
    #[arg(
        long = "speed",
        value_name = "M_S",
        default_value_t = 69.1,
        allow_negative_numbers = true
    )]
    pub speed_mps: f64,
    /// Flight-path angle (deg), positive climbing; a 3.5° glide slope is -3.5.
    #[arg(
        long = "gamma",
        value_name = "DEG",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    pub gamma_deg: f64,
    /// Aerodynamic configuration.
    #[arg(
        long = "config",
        value_name = "landing|clean",
        default_value = "landing"
    )]
    pub configuration: ConfigurationName,
    /// Aircraft model: the paper's longitudinal 3-DOF model, or the 6-DOF model with
    /// the lateral-directional axes (docs/six-dof.md).
    #[arg(long, value_enum, default_value = "3dof")]
    pub model: AircraftModel,
    /// Sideslip β (deg), positive with the relative wind from the right; 6-DOF only.
    #[arg(
        long = "sideslip",
        value_name = "DEG",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    pub sideslip_deg: f64,
    /// Steady crosswind W_y (m/s), positive blowing to the right (from the left); the
    /// trim heading crabs into it. 6-DOF only.
    #[arg(
        long = "crosswind",
        value_name = "M_S",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    pub crosswind_mps: f64,
    /// Print one JSON document on stdout instead of a table.
    #[arg(long)]
    pub json: bool,
}

/// The aircraft model `trim` and `linearize` work on.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum AircraftModel {
    /// The longitudinal model of the paper (u, w, q, θ).
    #[value(name = "3dof")]
    ThreeDof,
    /// The rigid-body 6-DOF model with the lateral-directional axes.
    #[value(name = "6dof")]
    SixDof,
}

impl TrimArgs {
    /// Refuses the lateral options with the 3-DOF model, which has no lateral axes.
    pub fn check_model_options(&self) -> Result<()> {
        if self.model == AircraftModel::ThreeDof {
            if self.sideslip_deg != 0.0 {
                bail!(
                    "--sideslip {:?} needs --model 6dof: the 3-DOF model has no sideslip",
                    self.sideslip_deg
                );
            }
            if self.crosswind_mps != 0.0 {
                bail!(
                    "--crosswind {:?} needs --model 6dof: the 3-DOF model has no lateral wind",
                    self.crosswind_mps
                );
            }
        }
        Ok(())
    }

    /// The aircraft in the requested configuration.
    pub fn aircraft(&self) -> Aircraft {
        Aircraft::with_configuration(AerodynamicConfiguration::named(self.configuration))
    }

    /// Trims the aircraft as requested.
    pub fn trim(&self, aircraft: &Aircraft) -> Result<TrimPoint> {
        let request = TrimRequest {
            speed_mps: self.speed_mps,
            flight_path_angle_rad: self.gamma_deg.to_radians(),
        };
        trim(aircraft, &request).or_else(|error| match error {
            // A request out of the solver's range is an option out of range: name it.
            TrimError::InvalidRequest {
                field, expected, ..
            } => {
                let (option, value) = if field == "speed_mps" {
                    ("--speed", self.speed_mps)
                } else {
                    ("--gamma", self.gamma_deg)
                };
                bail!("{option} {value:?} is not allowed: expected {expected}")
            }
            error => Err(error).with_context(|| {
                format!(
                    "cannot trim the {} configuration at {} m/s and γ = {}°",
                    self.configuration, self.speed_mps, self.gamma_deg
                )
            }),
        })
    }
}

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

/// Runs `deckland trim`.
pub fn run(args: &TrimArgs) -> Result<()> {
    args.check_model_options()?;
    if args.model == AircraftModel::SixDof {
        return super::six_dof::run_trim(args);
    }
    let aircraft = args.aircraft();
    let point = args.trim(&aircraft)?;
    if args.json {
        outln!(
            "{}",
            serde_json::to_string_pretty(&point.report(args.configuration))?
        )?;
    } else {
        print_trim_table(
            args.configuration,
            &point,
            aircraft.engines().max_total_thrust_n(),
        )?;
    }
    Ok(())
}
