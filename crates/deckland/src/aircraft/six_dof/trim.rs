//! Trim of the 6-DOF aircraft (docs/six-dof.md): steady straight flight at a given
//! airspeed, air-relative flight-path angle and sideslip, and the heading that holds the
//! track along the final bearing in a steady wind (the crab).
//!
//! Unknowns α, θ, δe, T, δa, δr, φ with p = q = r = 0 and β given; residuals u̇, v̇, ẇ,
//! ṗ, q̇, ṙ and the flight-path condition ḣ_air/V_T − sin γ, driven to zero by Newton's
//! method (central-difference Jacobian, backtracking), started from the longitudinal
//! trim. A steady uniform wind does not change the forces on the air-relative motion,
//! so the attitude and surfaces are trimmed in still air; the heading ψ then turns the
//! air-relative velocity so that the ground track has no y component (β = 0 gives the
//! crab, nose into the wind). The result is checked against α's range, the three
//! surfaces' travel and the thrust range; a failure names the limit and the excess.

use super::dynamics::{SixDofAircraft, SixDofInputs};
use super::kinematics::body_to_earth;
use super::state::SixDofState;
use crate::aircraft::central_difference::{newton_with_backtracking, NotConverged};
use crate::aircraft::{trim, TrimError, TrimRequest, ALPHA_MAX_RAD, ALPHA_MIN_RAD};
use crate::environment::Wind;
use nalgebra::SVector;

/// What to trim for.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SixDofTrimRequest {
    /// True airspeed V_T (m/s) and air-relative flight-path angle γ (rad).
    pub longitudinal: TrimRequest,
    /// Sideslip β (rad), positive with the relative wind from the right; 0 by default.
    pub sideslip_rad: f64,
    /// Steady wind in earth axes (m/s); only sets the heading ψ (the crab).
    pub wind: Wind,
}

/// A trimmed straight flight of the 6-DOF aircraft.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixDofTrimPoint {
    /// True airspeed V_T (m/s).
    pub speed_mps: f64,
    /// Air-relative flight-path angle γ (rad).
    pub flight_path_angle_rad: f64,
    /// Sideslip β (rad).
    pub sideslip_rad: f64,
    /// Angle of attack α (rad).
    pub alpha_rad: f64,
    /// Pitch angle θ (rad).
    pub theta_rad: f64,
    /// Bank angle φ (rad).
    pub phi_rad: f64,
    /// Heading ψ (rad) from the final bearing that keeps the track on it.
    pub psi_rad: f64,
    /// Elevator δe (rad).
    pub elevator_rad: f64,
    /// Aileron δa (rad).
    pub aileron_rad: f64,
    /// Rudder δr (rad).
    pub rudder_rad: f64,
    /// Total thrust T (N).
    pub thrust_n: f64,
    /// Thrust as a fraction of the total maximum thrust (–).
    pub throttle: f64,
    /// The wind the heading was found for.
    pub wind: Wind,
    /// Largest residual left (m/s², rad/s² or –).
    pub residual: f64,
    /// Newton iterations taken.
    pub iterations: usize,
}

impl SixDofTrimPoint {
    /// Air-relative velocity in body axes (m/s).
    pub fn air_velocity_body(&self) -> [f64; 3] {
        air_velocity_body(self.speed_mps, self.alpha_rad, self.sideslip_rad)
    }

    /// The plant state at this trim point at (`x_m`, `y_m`, `h_m`): inertial velocity =
    /// air-relative velocity + the wind, engines and surfaces at their trim values.
    pub fn state(&self, x_m: f64, y_m: f64, h_m: f64) -> SixDofState {
        let euler = [self.phi_rad, self.theta_rad, self.psi_rad];
        let wind = super::kinematics::earth_to_body(
            euler,
            [self.wind.x_mps, self.wind.y_mps, self.wind.z_mps],
        );
        let air = self.air_velocity_body();
        SixDofState {
            u_mps: air[0] + wind[0],
            v_mps: air[1] + wind[1],
            w_mps: air[2] + wind[2],
            phi_rad: self.phi_rad,
            theta_rad: self.theta_rad,
            psi_rad: self.psi_rad,
            x_m,
            y_m,
            h_m,
            engine_thrust_n: [0.5 * self.thrust_n; 2],
            elevator_rad: self.elevator_rad,
            aileron_rad: self.aileron_rad,
            rudder_rad: self.rudder_rad,
            ..SixDofState::default()
        }
    }
}

/// Why a 6-DOF trim could not be found.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
pub enum SixDofTrimError {
    /// The longitudinal start (speed, flight path) failed; see the inner error.
    #[error(transparent)]
    Longitudinal(#[from] TrimError),
    /// The sideslip asked for is outside ±30°.
    #[error(
        "trim request `sideslip_rad` = {value} is invalid: expected a sideslip between \
         -30° and +30°"
    )]
    InvalidSideslip {
        /// The offending value (rad).
        value: f64,
    },
    /// The crosswind is at least the horizontal airspeed: no heading holds the track.
    #[error(
        "trim request `wind.y_mps` = {crosswind_mps} cannot be crabbed: the horizontal \
         airspeed is only {horizontal_airspeed_mps:.2} m/s"
    )]
    CrosswindTooStrong {
        /// Crosswind W_y (m/s).
        crosswind_mps: f64,
        /// Horizontal air-relative speed (m/s).
        horizontal_airspeed_mps: f64,
    },
    /// Newton's method did not converge.
    #[error(
        "6-DOF trim did not converge after {iterations} iterations (largest residual \
         {residual:.3e})"
    )]
    NoConvergence {
        /// Iterations taken.
        iterations: usize,
        /// Largest residual at the last iterate.
        residual: f64,
    },
    /// α outside the polynomials' range.
    #[error(
        "trim needs angle of attack {alpha_deg:.2}°, outside the aerodynamic model's range \
         by {exceeded_by_deg:.2}°"
    )]
    AlphaOutOfRange {
        /// Required α (deg).
        alpha_deg: f64,
        /// Distance outside the range (deg).
        exceeded_by_deg: f64,
    },
    /// A surface beyond its travel.
    #[error(
        "trim needs {surface} {required_deg:.2}°, beyond its {limit_deg:.1}° limit by \
         {exceeded_by_deg:.2}°"
    )]
    SurfaceLimit {
        /// `"elevator"`, `"aileron"` or `"rudder"`.
        surface: &'static str,
        /// Required deflection (deg).
        required_deg: f64,
        /// The limit passed (deg).
        limit_deg: f64,
        /// Distance beyond the limit (deg).
        exceeded_by_deg: f64,
    },
    /// Thrust outside [0, 2·T_max].
    #[error("trim needs total thrust {required_n:.0} N, beyond the limit {limit_n:.0} N")]
    ThrustLimit {
        /// Required total thrust (N).
        required_n: f64,
        /// The limit passed (N).
        limit_n: f64,
    },
}

const TOLERANCE: f64 = 1e-11;

fn air_velocity_body(speed: f64, alpha: f64, beta: f64) -> [f64; 3] {
    let (sin_a, cos_a) = alpha.sin_cos();
    let (sin_b, cos_b) = beta.sin_cos();
    [speed * cos_a * cos_b, speed * sin_b, speed * sin_a * cos_b]
}

type Unknowns = SVector<f64, 7>;

/// Residuals for unknowns (α, θ, δe, T, δa, δr, φ).
fn residual(aircraft: &SixDofAircraft, request: &SixDofTrimRequest, x: &Unknowns) -> Unknowns {
    let v = request.longitudinal.speed_mps;
    let velocity = air_velocity_body(v, x[0], request.sideslip_rad);
    let euler = [x[6], x[1], 0.0];
    let inputs = SixDofInputs {
        elevator_rad: x[2],
        thrust_n: x[3],
        aileron_rad: x[4],
        rudder_rad: x[5],
    };
    let rates = aircraft.body_rates(velocity, [0.0; 3], euler, &inputs, &Wind::default());
    let earth = body_to_earth(euler, velocity);
    Unknowns::from([
        rates.velocity[0],
        rates.velocity[1],
        rates.velocity[2],
        rates.angular[0],
        rates.angular[1],
        rates.angular[2],
        -earth[2] / v - request.longitudinal.flight_path_angle_rad.sin(),
    ])
}

/// Trims `aircraft` for steady straight flight as `request` asks.
pub fn trim_six_dof(
    aircraft: &SixDofAircraft,
    request: &SixDofTrimRequest,
) -> Result<SixDofTrimPoint, SixDofTrimError> {
    let beta = request.sideslip_rad;
    if !(beta.is_finite() && beta.abs() <= 30f64.to_radians()) {
        return Err(SixDofTrimError::InvalidSideslip { value: beta });
    }
    // The longitudinal trim validates speed and flight path and gives the start.
    let start = trim(aircraft.longitudinal(), &request.longitudinal)?;
    let initial = Unknowns::from([
        start.alpha_rad,
        start.theta_rad,
        start.elevator_rad,
        start.thrust_n,
        0.0,
        0.0,
        0.0,
    ]);
    let (x, r, iterations) = newton_with_backtracking(
        initial,
        &[1e-6, 1e-6, 1e-6, 1e-2, 1e-6, 1e-6, 1e-6],
        TOLERANCE,
        |x| residual(aircraft, request, x),
        |candidate| {
            candidate[0] = candidate[0].clamp(-0.5, 1.2);
            candidate[6] = candidate[6].clamp(-1.4, 1.4);
        },
    )
    .map_err(|failure: NotConverged| SixDofTrimError::NoConvergence {
        iterations: failure.iterations,
        residual: failure.residual,
    })?;
    let mut point = SixDofTrimPoint {
        speed_mps: request.longitudinal.speed_mps,
        flight_path_angle_rad: request.longitudinal.flight_path_angle_rad,
        sideslip_rad: beta,
        alpha_rad: x[0],
        theta_rad: x[1],
        phi_rad: x[6],
        psi_rad: 0.0,
        elevator_rad: x[2],
        aileron_rad: x[4],
        rudder_rad: x[5],
        thrust_n: x[3],
        throttle: x[3] / aircraft.longitudinal().engines().max_total_thrust_n(),
        wind: request.wind,
        residual: r.amax(),
        iterations,
    };
    check_limits(aircraft, &point)?;
    point.psi_rad = crab_heading(&point, &request.wind)?;
    Ok(point)
}

/// The heading ψ at which the ground track has no y component: with the air-relative
/// velocity (a_x, a_y) in the earth's horizontal plane at ψ = 0, a_x sin ψ + a_y cos ψ
/// = −W_y, so ψ = asin(−W_y/R) − atan2(a_y, a_x), R = √(a_x² + a_y²).
fn crab_heading(point: &SixDofTrimPoint, wind: &Wind) -> Result<f64, SixDofTrimError> {
    let air = body_to_earth(
        [point.phi_rad, point.theta_rad, 0.0],
        point.air_velocity_body(),
    );
    let horizontal = air[0].hypot(air[1]);
    if !(wind.y_mps.is_finite() && wind.y_mps.abs() < horizontal) {
        return Err(SixDofTrimError::CrosswindTooStrong {
            crosswind_mps: wind.y_mps,
            horizontal_airspeed_mps: horizontal,
        });
    }
    Ok((-wind.y_mps / horizontal).asin() - air[1].atan2(air[0]))
}

fn check_limits(aircraft: &SixDofAircraft, point: &SixDofTrimPoint) -> Result<(), SixDofTrimError> {
    let alpha = point.alpha_rad;
    if !(ALPHA_MIN_RAD..=ALPHA_MAX_RAD).contains(&alpha) {
        let exceeded = (ALPHA_MIN_RAD - alpha).max(alpha - ALPHA_MAX_RAD);
        return Err(SixDofTrimError::AlphaOutOfRange {
            alpha_deg: alpha.to_degrees(),
            exceeded_by_deg: exceeded.to_degrees(),
        });
    }
    let surfaces = [
        (
            "elevator",
            point.elevator_rad,
            aircraft.longitudinal().actuator(),
        ),
        ("aileron", point.aileron_rad, aircraft.aileron()),
        ("rudder", point.rudder_rad, aircraft.rudder()),
    ];
    for (surface, deflection, actuator) in surfaces {
        let limit = if deflection < actuator.min_rad() {
            actuator.min_rad()
        } else if deflection > actuator.max_rad() {
            actuator.max_rad()
        } else {
            continue;
        };
        return Err(SixDofTrimError::SurfaceLimit {
            surface,
            required_deg: deflection.to_degrees(),
            limit_deg: limit.to_degrees(),
            exceeded_by_deg: (deflection - limit).abs().to_degrees(),
        });
    }
    let max_thrust = aircraft.longitudinal().engines().max_total_thrust_n();
    if !(0.0..=max_thrust).contains(&point.thrust_n) {
        return Err(SixDofTrimError::ThrustLimit {
            required_n: point.thrust_n,
            limit_n: point.thrust_n.clamp(0.0, max_thrust),
        });
    }
    Ok(())
}
