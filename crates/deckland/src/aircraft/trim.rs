//! Trim: steady straight flight at a given airspeed and flight-path angle (paper §3.2.1,
//! generalised from level flight to any γ).
//!
//! Unknowns α, δe and total thrust T; θ = α + γ, q = 0, still air. The residuals
//! (V̇, α̇, q̇) are driven to zero by Newton's method with a central-difference Jacobian and
//! a backtracking line search. The result is then checked against the model's limits:
//! α inside the polynomials' range, δe within the actuator's limits, T within [0, 2·T_max].

use super::central_difference::{newton_with_backtracking, NotConverged};
use super::{Aircraft, AircraftState, AirframeInputs, Wind, ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use nalgebra::Vector3;
use serde::Serialize;

/// What to trim for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrimRequest {
    /// True airspeed V_T (m/s).
    pub speed_mps: f64,
    /// Flight-path angle γ (rad), positive climbing.
    pub flight_path_angle_rad: f64,
}

impl Default for TrimRequest {
    /// The paper's Table 3: 69.1 m/s, level flight.
    fn default() -> Self {
        Self {
            speed_mps: 69.1,
            flight_path_angle_rad: 0.0,
        }
    }
}

/// Residual derivatives at the trim solution.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct TrimResiduals {
    /// Airspeed rate V̇_T (m/s²).
    pub airspeed_rate_mps2: f64,
    /// Angle-of-attack rate α̇ (rad/s).
    pub alpha_rate_radps: f64,
    /// Pitch acceleration q̇ (rad/s²).
    pub pitch_acceleration_radps2: f64,
}

impl TrimResiduals {
    /// Largest absolute residual.
    pub fn max_abs(&self) -> f64 {
        self.airspeed_rate_mps2
            .abs()
            .max(self.alpha_rate_radps.abs())
            .max(self.pitch_acceleration_radps2.abs())
    }
}

/// A trim point as the front ends write it (`deckland trim --json`, Python's
/// `Trim.to_dict()`): angles in degrees, names carrying their units.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct TrimReport {
    /// Aerodynamic configuration: `landing` or `clean`.
    pub configuration: String,
    /// True airspeed (m/s).
    pub speed_mps: f64,
    /// Flight-path angle (deg), positive climbing.
    pub gamma_deg: f64,
    /// Angle of attack α (deg).
    pub alpha_deg: f64,
    /// Pitch angle θ (deg).
    pub theta_deg: f64,
    /// Elevator δe (deg), positive trailing edge down.
    pub elevator_deg: f64,
    /// Total thrust of both engines (N).
    pub thrust_n: f64,
    /// Thrust as a fraction of the total maximum thrust (–).
    pub throttle: f64,
    /// Rates left at the solution.
    pub residuals: TrimResiduals,
    /// Newton iterations taken.
    pub iterations: usize,
}

/// A trimmed flight condition.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TrimPoint {
    /// True airspeed V_T (m/s).
    pub speed_mps: f64,
    /// Flight-path angle γ (rad).
    pub flight_path_angle_rad: f64,
    /// Angle of attack α (rad).
    pub alpha_rad: f64,
    /// Pitch angle θ = α + γ (rad).
    pub theta_rad: f64,
    /// Elevator deflection δe (rad).
    pub elevator_rad: f64,
    /// Total thrust of both engines T (N).
    pub thrust_n: f64,
    /// Throttle δT: thrust as a fraction of the total maximum thrust (–).
    pub throttle: f64,
    /// Residual derivatives at the solution.
    pub residuals: TrimResiduals,
    /// Newton iterations taken.
    pub iterations: usize,
}

impl TrimPoint {
    /// This trim point as the front ends write it, for the aerodynamic `configuration`.
    pub fn report(&self, configuration: impl std::fmt::Display) -> TrimReport {
        TrimReport {
            configuration: configuration.to_string(),
            speed_mps: self.speed_mps,
            gamma_deg: self.flight_path_angle_rad.to_degrees(),
            alpha_deg: self.alpha_rad.to_degrees(),
            theta_deg: self.theta_rad.to_degrees(),
            elevator_deg: self.elevator_rad.to_degrees(),
            thrust_n: self.thrust_n,
            throttle: self.throttle,
            residuals: self.residuals,
            iterations: self.iterations,
        }
    }

    /// The plant state at this trim point at position (`x_m`, `h_m`), flying in a steady
    /// uniform `wind`: the air-relative velocity is the trim's, the inertial velocity is
    /// that plus the wind; engines and actuator sit at their trim values.
    pub fn state(&self, x_m: f64, h_m: f64, wind: &Wind) -> AircraftState {
        let (sin_t, cos_t) = self.theta_rad.sin_cos();
        let wind_xb = wind.x_mps * cos_t - wind.z_mps * sin_t;
        let wind_zb = wind.x_mps * sin_t + wind.z_mps * cos_t;
        AircraftState {
            u_mps: self.speed_mps * self.alpha_rad.cos() + wind_xb,
            w_mps: self.speed_mps * self.alpha_rad.sin() + wind_zb,
            q_radps: 0.0,
            theta_rad: self.theta_rad,
            x_m,
            h_m,
            engine_thrust_n: [0.5 * self.thrust_n; 2],
            elevator_rad: self.elevator_rad,
            elevator_rate_radps: 0.0,
        }
    }
}

/// Why a trim could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum TrimError {
    /// The request itself is outside the physical range.
    #[error("trim request `{field}` = {} is invalid: expected {expected}", crate::parameters::readable_number(*value))]
    InvalidRequest {
        /// The request field.
        field: &'static str,
        /// The offending value.
        value: f64,
        /// The allowed range, in words.
        expected: &'static str,
    },
    /// Newton's method did not converge.
    #[error(
        "trim did not converge after {iterations} iterations (largest residual {residual:.3e}); \
         the speed may be below the stall speed or the flight path too steep"
    )]
    NoConvergence {
        /// Iterations taken.
        iterations: usize,
        /// Largest residual at the last iterate.
        residual: f64,
    },
    /// The solution's α lies outside the polynomials' range.
    #[error(
        "trim needs angle of attack {alpha_deg:.2}°, outside the aerodynamic model's range \
         {min_deg:.1}°…{max_deg:.1}° by {exceeded_by_deg:.2}°"
    )]
    AlphaOutOfRange {
        /// Required α (deg).
        alpha_deg: f64,
        /// Lowest valid α (deg).
        min_deg: f64,
        /// Highest valid α (deg).
        max_deg: f64,
        /// Distance outside the range (deg).
        exceeded_by_deg: f64,
    },
    /// The solution's elevator lies beyond a position limit.
    #[error(
        "trim needs elevator {required_deg:.2}°, beyond the {limit_name} limit {limit_deg:.1}° \
         by {exceeded_by_deg:.2}°"
    )]
    ElevatorLimit {
        /// Required deflection (deg).
        required_deg: f64,
        /// The limit passed (deg).
        limit_deg: f64,
        /// `"lower"` or `"upper"`.
        limit_name: &'static str,
        /// Distance beyond the limit (deg).
        exceeded_by_deg: f64,
    },
    /// The solution's thrust lies outside [0, 2·T_max].
    #[error(
        "trim needs total thrust {required_n:.0} N, beyond the {limit_name} limit {limit_n:.0} N \
         by {exceeded_by_n:.0} N"
    )]
    ThrustLimit {
        /// Required total thrust (N).
        required_n: f64,
        /// The limit passed (N).
        limit_n: f64,
        /// `"lower"` (idle, 0 N) or `"upper"` (2·T_max).
        limit_name: &'static str,
        /// Distance beyond the limit (N).
        exceeded_by_n: f64,
    },
}

const TOLERANCE: f64 = 1e-12;

/// Residuals (V̇, α̇, q̇) for unknowns (α, δe, T) at speed `v` and path angle `gamma`.
fn residual(aircraft: &Aircraft, v: f64, gamma: f64, unknowns: &Vector3<f64>) -> Vector3<f64> {
    let (alpha, elevator, thrust) = (unknowns[0], unknowns[1], unknowns[2]);
    let (u, w) = (v * alpha.cos(), v * alpha.sin());
    let inputs = AirframeInputs {
        elevator_rad: elevator,
        thrust_n: thrust,
    };
    let (u_dot, w_dot, q_dot) =
        aircraft.airframe_accelerations(u, w, 0.0, alpha + gamma, &inputs, &Wind::default());
    Vector3::new(
        (u * u_dot + w * w_dot) / v,
        (u * w_dot - w * u_dot) / (v * v),
        q_dot,
    )
}

fn validate_request(request: &TrimRequest) -> Result<(), TrimError> {
    let v = request.speed_mps;
    if !(v.is_finite() && (20.0..=250.0).contains(&v)) {
        return Err(TrimError::InvalidRequest {
            field: "speed_mps",
            value: v,
            expected: "an airspeed between 20 and 250 m/s",
        });
    }
    let gamma = request.flight_path_angle_rad;
    if !(gamma.is_finite() && gamma.abs() <= 30f64.to_radians()) {
        return Err(TrimError::InvalidRequest {
            field: "flight_path_angle_rad",
            value: gamma,
            expected: "a flight-path angle between -30° and +30°",
        });
    }
    Ok(())
}

/// Trims `aircraft` for steady straight flight as `request` asks.
pub fn trim(aircraft: &Aircraft, request: &TrimRequest) -> Result<TrimPoint, TrimError> {
    validate_request(request)?;
    let v = request.speed_mps;
    let gamma = request.flight_path_angle_rad;
    let weight = aircraft.parameters().mass_kg * aircraft.parameters().gravity_mps2;
    let start = Vector3::new(0.1, -0.1, 0.2 * weight);
    // Backtracking keeps α within a plausible band so the polynomials are not evaluated
    // far from their data.
    let (unknowns, r, iterations) = newton_with_backtracking(
        start,
        &[1e-6, 1e-6, 1e-2],
        TOLERANCE,
        |unknowns| residual(aircraft, v, gamma, unknowns),
        |candidate| candidate[0] = candidate[0].clamp(-0.5, 1.2),
    )
    .map_err(|failure: NotConverged| TrimError::NoConvergence {
        iterations: failure.iterations,
        residual: failure.residual,
    })?;
    let point = TrimPoint {
        speed_mps: v,
        flight_path_angle_rad: gamma,
        alpha_rad: unknowns[0],
        theta_rad: unknowns[0] + gamma,
        elevator_rad: unknowns[1],
        thrust_n: unknowns[2],
        throttle: unknowns[2] / aircraft.engines().max_total_thrust_n(),
        residuals: TrimResiduals {
            airspeed_rate_mps2: r[0],
            alpha_rate_radps: r[1],
            pitch_acceleration_radps2: r[2],
        },
        iterations,
    };
    check_limits(aircraft, &point)?;
    Ok(point)
}

fn check_limits(aircraft: &Aircraft, point: &TrimPoint) -> Result<(), TrimError> {
    let alpha = point.alpha_rad;
    if !(ALPHA_MIN_RAD..=ALPHA_MAX_RAD).contains(&alpha) {
        let exceeded = if alpha < ALPHA_MIN_RAD {
            ALPHA_MIN_RAD - alpha
        } else {
            alpha - ALPHA_MAX_RAD
        };
        return Err(TrimError::AlphaOutOfRange {
            alpha_deg: alpha.to_degrees(),
            min_deg: ALPHA_MIN_RAD.to_degrees(),
            max_deg: ALPHA_MAX_RAD.to_degrees(),
            exceeded_by_deg: exceeded.to_degrees(),
        });
    }
    let actuator = aircraft.actuator();
    let elevator = point.elevator_rad;
    if elevator < actuator.min_rad() || elevator > actuator.max_rad() {
        let (limit, name) = if elevator < actuator.min_rad() {
            (actuator.min_rad(), "lower")
        } else {
            (actuator.max_rad(), "upper")
        };
        return Err(TrimError::ElevatorLimit {
            required_deg: elevator.to_degrees(),
            limit_deg: limit.to_degrees(),
            limit_name: name,
            exceeded_by_deg: (elevator - limit).abs().to_degrees(),
        });
    }
    let max_thrust = aircraft.engines().max_total_thrust_n();
    let thrust = point.thrust_n;
    if !(0.0..=max_thrust).contains(&thrust) {
        let (limit, name) = if thrust < 0.0 {
            (0.0, "lower")
        } else {
            (max_thrust, "upper")
        };
        return Err(TrimError::ThrustLimit {
            required_n: thrust,
            limit_n: limit,
            limit_name: name,
            exceeded_by_n: (thrust - limit).abs(),
        });
    }
    Ok(())
}
