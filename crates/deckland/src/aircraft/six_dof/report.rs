//! The 6-DOF trim point and lateral modes as reports: the numbers, angles in degrees,
//! that `deckland trim --model 6dof --json`, `deckland linearize --model 6dof --json`
//! and the Python package give.

use serde::Serialize;

use super::linearize::{LateralModes, RealMode};
use super::trim::SixDofTrimPoint;

/// A 6-DOF trim point as `deckland trim --model 6dof --json` and Python give it: angles
/// in degrees.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SixDofTrimReport {
    /// The model: `6dof`.
    pub model: &'static str,
    /// Aerodynamic configuration: `landing` or `clean`.
    pub configuration: String,
    /// True airspeed (m/s).
    pub speed_mps: f64,
    /// Air-relative flight-path angle (deg), positive climbing.
    pub gamma_deg: f64,
    /// Sideslip β (deg), positive with the relative wind from the right.
    pub sideslip_deg: f64,
    /// Crosswind W_y (m/s), positive blowing to the right.
    pub crosswind_mps: f64,
    /// Angle of attack α (deg).
    pub alpha_deg: f64,
    /// Pitch angle θ (deg).
    pub theta_deg: f64,
    /// Bank φ (deg), right wing down positive.
    pub phi_deg: f64,
    /// Heading ψ from the final bearing (deg), nose right positive.
    pub psi_deg: f64,
    /// Elevator δe (deg), trailing edge down positive.
    pub elevator_deg: f64,
    /// Aileron δa (deg), right-wing-down rolling moment positive.
    pub aileron_deg: f64,
    /// Rudder δr (deg), trailing edge left positive.
    pub rudder_deg: f64,
    /// Total thrust of both engines (N).
    pub thrust_n: f64,
    /// Thrust as a fraction of the total maximum thrust (–).
    pub throttle: f64,
    /// Largest residual rate at the solution (m/s², rad/s² or –).
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
}

impl SixDofTrimPoint {
    /// This trim point as a report, in `configuration`.
    pub fn report(&self, configuration: impl std::fmt::Display) -> SixDofTrimReport {
        let point = self;
        SixDofTrimReport {
            model: "6dof",
            configuration: configuration.to_string(),
            speed_mps: point.speed_mps,
            gamma_deg: point.flight_path_angle_rad.to_degrees(),
            sideslip_deg: point.sideslip_rad.to_degrees(),
            crosswind_mps: point.wind.y_mps,
            alpha_deg: point.alpha_rad.to_degrees(),
            theta_deg: point.theta_rad.to_degrees(),
            phi_deg: point.phi_rad.to_degrees(),
            psi_deg: point.psi_rad.to_degrees(),
            elevator_deg: point.elevator_rad.to_degrees(),
            aileron_deg: point.aileron_rad.to_degrees(),
            rudder_deg: point.rudder_rad.to_degrees(),
            thrust_n: point.thrust_n,
            throttle: point.throttle,
            residual: point.residual,
            iterations: point.iterations,
        }
    }
}

/// A real lateral mode as a report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RealModeReport {
    /// The eigenvalue λ (1/s).
    pub eigenvalue_per_s: f64,
    /// Time constant τ = −1/λ (s).
    pub time_constant_s: f64,
    /// Whether λ < 0.
    pub stable: bool,
    /// Time to half amplitude when stable, to double when not (s).
    pub time_to_half_s: Option<f64>,
    /// Time to double amplitude when unstable (s).
    pub time_to_double_s: Option<f64>,
}

impl From<&RealMode> for RealModeReport {
    fn from(mode: &RealMode) -> Self {
        Self {
            eigenvalue_per_s: mode.eigenvalue_per_s,
            time_constant_s: mode.time_constant_s,
            stable: mode.stable,
            time_to_half_s: mode.stable.then_some(mode.time_to_half_or_double_s),
            time_to_double_s: (!mode.stable).then_some(mode.time_to_half_or_double_s),
        }
    }
}

/// The lateral modes as a report.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct LateralModesReport {
    /// The Dutch roll eigenvalue with positive imaginary part, [re, im] (1/s).
    pub dutch_roll_eigenvalue: [f64; 2],
    /// Dutch roll natural frequency ω_n (rad/s).
    pub dutch_roll_natural_frequency_radps: f64,
    /// Dutch roll damping ratio ζ (–).
    pub dutch_roll_damping_ratio: f64,
    /// Roll subsidence.
    pub roll_subsidence: RealModeReport,
    /// Spiral.
    pub spiral: RealModeReport,
}

impl From<&LateralModes> for LateralModesReport {
    fn from(modes: &LateralModes) -> Self {
        let dutch = &modes.dutch_roll;
        Self {
            dutch_roll_eigenvalue: [dutch.eigenvalue.re, dutch.eigenvalue.im],
            dutch_roll_natural_frequency_radps: dutch.natural_frequency_radps,
            dutch_roll_damping_ratio: dutch.damping_ratio,
            roll_subsidence: (&modes.roll_subsidence).into(),
            spiral: (&modes.spiral).into(),
        }
    }
}
