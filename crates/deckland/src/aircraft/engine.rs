//! Twin F404-GE-400 engines with first-order thrust lag (docs/model.md §2.5, paper §3.6).

use crate::parameters::{check_ranges, Bounds, ParameterError};
use serde::{Deserialize, Serialize};

/// Engine parameters; thrust acts along body x through the CG.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct EngineParameters {
    /// Maximum (military, non-afterburning) thrust of one engine (N); 71172 N
    /// (paper Table 2: F404-GE-400, 16000 lbf).
    pub max_thrust_per_engine_n: f64,
    /// Time constant of the first-order lag from commanded to actual thrust (s);
    /// 0.625 s, the slower non-afterburning value of the paper's reference \[13\].
    pub time_constant_s: f64,
}

impl Default for EngineParameters {
    fn default() -> Self {
        Self {
            max_thrust_per_engine_n: 71_172.0,
            time_constant_s: 0.625,
        }
    }
}

impl EngineParameters {
    /// Checks that the thrust and the time constant are finite and positive.
    pub fn validate(&self) -> Result<(), ParameterError> {
        const SECTION: &str = "aircraft.engines";
        check_ranges!(SECTION, self, {
            max_thrust_per_engine_n: Bounds::positive_up_to(1e6),
            time_constant_s: Bounds::closed(0.05, 30.0),
        });
        Ok(())
    }
}

/// The pair of engines: each a lag 1/(τs + 1) from its commanded to its actual thrust.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Engines {
    parameters: EngineParameters,
    inverse_time_constant: f64,
}

impl Engines {
    /// Number of engines.
    pub const COUNT: usize = 2;

    /// Builds the engine model after validating its parameters.
    pub fn new(parameters: EngineParameters) -> Result<Self, ParameterError> {
        parameters.validate()?;
        Ok(Self {
            parameters,
            inverse_time_constant: 1.0 / parameters.time_constant_s,
        })
    }

    /// The parameters the model was built from.
    pub fn parameters(&self) -> &EngineParameters {
        &self.parameters
    }

    /// Total maximum thrust of both engines (N).
    #[inline]
    pub fn max_total_thrust_n(&self) -> f64 {
        Self::COUNT as f64 * self.parameters.max_thrust_per_engine_n
    }

    /// Commanded total thrust limited to [0, 2·T_max] (N).
    #[inline]
    pub fn limit_total_command(&self, thrust_command_n: f64) -> f64 {
        thrust_command_n.clamp(0.0, self.max_total_thrust_n())
    }

    /// Rate of change of one engine's actual thrust (N/s) given the total command (N),
    /// shared equally between the engines after the limit.
    #[inline]
    pub fn thrust_rate(&self, actual_n: f64, total_command_n: f64) -> f64 {
        let per_engine = self.limit_total_command(total_command_n) / Self::COUNT as f64;
        (per_engine - actual_n) * self.inverse_time_constant
    }
}

impl Default for Engines {
    fn default() -> Self {
        let parameters = EngineParameters::default();
        Self {
            parameters,
            inverse_time_constant: 1.0 / parameters.time_constant_s,
        }
    }
}
