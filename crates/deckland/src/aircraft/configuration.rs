//! Aerodynamic configurations: `landing` (flaps and gear down, default) and `clean`
//! (docs/model.md §2.3).

use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};
use std::fmt;
use std::str::FromStr;

/// The named configurations the model knows.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ConfigurationName {
    /// Flaps, leading-edge flaps and gear down: the approach configuration (default).
    #[default]
    Landing,
    /// The polynomial model's own clean configuration: every increment zero.
    Clean,
}

impl fmt::Display for ConfigurationName {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Self::Landing => "landing",
            Self::Clean => "clean",
        })
    }
}

impl FromStr for ConfigurationName {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, Self::Err> {
        match s {
            "landing" => Ok(Self::Landing),
            "clean" => Ok(Self::Clean),
            other => Err(format!(
                "unknown configuration `{other}`: expected `landing` or `clean`"
            )),
        }
    }
}

/// Increments added to the clean polynomial aerodynamics, and the CG position.
///
/// The clean data cannot reproduce the paper's trim (Table 3: V* = 69.1 m/s,
/// α* = 7.1°); the `landing` increments are chosen so that it does (docs/model.md §2.3).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct AerodynamicConfiguration {
    /// Lift-coefficient increment ΔC_L0 (–) from flaps and leading-edge flaps.
    pub lift_coefficient_increment: f64,
    /// Drag-coefficient increment ΔC_D0 (–) from gear and flaps.
    pub drag_coefficient_increment: f64,
    /// Pitching-moment-coefficient increment ΔC_m0 (–).
    pub moment_coefficient_increment: f64,
    /// CG position ahead of the data's moment reference point, in mean chords (–).
    /// The moment about the CG is C_m,cg = C_m − d·C_N, C_N = C_L cos α + C_D sin α.
    pub cg_ahead_of_reference_chords: f64,
}

impl AerodynamicConfiguration {
    /// The approach configuration (docs/model.md §2.3): ΔC_L0 = 0.6938 gives level trim at
    /// 69.1 m/s with α = 7.1° (Table 3); ΔC_D0 = 0.16 gives an approach L/D ≈ 5.5;
    /// the CG 0.0729·c̄ ahead of the reference point gives ∂q̇/∂α = −0.26 s⁻² at trim
    /// (paper Eq. 14).
    pub const LANDING: Self = Self {
        lift_coefficient_increment: 0.6938,
        drag_coefficient_increment: 0.16,
        moment_coefficient_increment: 0.0,
        cg_ahead_of_reference_chords: 0.0729,
    };

    /// The clean polynomial model of Chakraborty, Seiler & Balas (2011) unchanged.
    pub const CLEAN: Self = Self {
        lift_coefficient_increment: 0.0,
        drag_coefficient_increment: 0.0,
        moment_coefficient_increment: 0.0,
        cg_ahead_of_reference_chords: 0.0,
    };

    /// The configuration of a given name.
    pub fn named(name: ConfigurationName) -> Self {
        match name {
            ConfigurationName::Landing => Self::LANDING,
            ConfigurationName::Clean => Self::CLEAN,
        }
    }

    /// Checks that every increment is within ±2 (coefficients) and the CG shift within
    /// ±0.5 chord.
    pub fn validate(&self) -> Result<(), ParameterError> {
        self.validate_in("aircraft.configuration")
    }

    /// As [`AerodynamicConfiguration::validate`], naming the keys under `section`.
    pub fn validate_in(&self, section: &str) -> Result<(), ParameterError> {
        let coefficient = Bounds::closed(-2.0, 2.0);
        coefficient.check(
            section,
            "lift_coefficient_increment",
            self.lift_coefficient_increment,
        )?;
        coefficient.check(
            section,
            "drag_coefficient_increment",
            self.drag_coefficient_increment,
        )?;
        coefficient.check(
            section,
            "moment_coefficient_increment",
            self.moment_coefficient_increment,
        )?;
        check_ranges!(section, self, {
            cg_ahead_of_reference_chords: Bounds::closed(-0.5, 0.5),
        });
        Ok(())
    }
}

impl Default for AerodynamicConfiguration {
    fn default() -> Self {
        Self::LANDING
    }
}
