//! The flight condition `deckland trim` and `deckland linearize` take (airspeed,
//! flight-path angle, configuration, model, and for the 6-DOF model sideslip and cross
//! wind), shared by their 3-DOF and 6-DOF variants.

use anyhow::{bail, Context, Result};
use clap::Args;
use deckland::aircraft::{AerodynamicConfiguration, Aircraft, ConfigurationName, PlantModel};
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
    #[arg(long, default_value = "3dof", value_parser = super::models::names::plant_model_parser())]
    pub model: PlantModel,
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

impl TrimArgs {
    /// The 3-DOF aircraft in the requested configuration, trimmed as requested; the
    /// lateral options, which the 3-DOF model (it has no lateral axes) cannot take, are
    /// refused.
    pub fn three_dof_trim(&self) -> Result<(Aircraft, TrimPoint)> {
        self.refuse_lateral_options()?;
        let aircraft = self.aircraft();
        let point = self.trim(&aircraft)?;
        Ok((aircraft, point))
    }

    /// Refuses the lateral options.
    fn refuse_lateral_options(&self) -> Result<()> {
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
