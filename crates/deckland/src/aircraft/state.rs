//! The aircraft's state vector, as a named struct.

/// State of the longitudinal plant: rigid body, engines and elevator actuator.
///
/// Velocities are *inertial* (earth-relative) components in body axes, so that wind
/// enters the aerodynamics only through the air-relative velocity (docs/model.md §2.4).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AircraftState {
    /// Inertial velocity along body x, u (m/s).
    pub u_mps: f64,
    /// Inertial velocity along body z (down), w (m/s).
    pub w_mps: f64,
    /// Pitch rate q (rad/s), positive nose-up.
    pub q_radps: f64,
    /// Pitch angle θ (rad), positive nose-up.
    pub theta_rad: f64,
    /// Earth x position (m), positive in the direction of flight.
    pub x_m: f64,
    /// Altitude h (m), positive up.
    pub h_m: f64,
    /// Actual thrust of each engine (N).
    pub engine_thrust_n: [f64; 2],
    /// Elevator actuator position δe (rad), positive trailing edge down.
    pub elevator_rad: f64,
    /// Elevator actuator rate δ̇e (rad/s).
    pub elevator_rate_radps: f64,
}

impl AircraftState {
    /// Number of scalar states.
    pub const DIMENSION: usize = 10;

    /// Names of the states, in the order of [`AircraftState::to_array`].
    pub const NAMES: [&'static str; 10] = [
        "u_mps",
        "w_mps",
        "q_radps",
        "theta_rad",
        "x_m",
        "h_m",
        "engine_1_thrust_n",
        "engine_2_thrust_n",
        "elevator_rad",
        "elevator_rate_radps",
    ];

    /// Position of the elevator's position δe in [`AircraftState::to_array`].
    pub const ELEVATOR_INDEX: usize = 8;
    /// Position of the elevator's rate δ̇e in [`AircraftState::to_array`].
    pub const ELEVATOR_RATE_INDEX: usize = 9;

    /// The state from a slice of at least 10 numbers (as [`AircraftState::from_array`]).
    #[inline(always)]
    pub fn from_slice(x: &[f64]) -> Self {
        Self {
            u_mps: x[0],
            w_mps: x[1],
            q_radps: x[2],
            theta_rad: x[3],
            x_m: x[4],
            h_m: x[5],
            engine_thrust_n: [x[6], x[7]],
            elevator_rad: x[8],
            elevator_rate_radps: x[9],
        }
    }

    /// The state as an array for the integrator (order: u, w, q, θ, x, h, T₁, T₂, δe, δ̇e).
    #[inline]
    pub fn to_array(&self) -> [f64; Self::DIMENSION] {
        [
            self.u_mps,
            self.w_mps,
            self.q_radps,
            self.theta_rad,
            self.x_m,
            self.h_m,
            self.engine_thrust_n[0],
            self.engine_thrust_n[1],
            self.elevator_rad,
            self.elevator_rate_radps,
        ]
    }

    /// The state from an integrator array (inverse of [`AircraftState::to_array`]).
    #[inline]
    pub fn from_array(x: &[f64; Self::DIMENSION]) -> Self {
        Self::from_slice(x)
    }

    /// Total actual thrust of both engines (N).
    #[inline]
    pub fn total_thrust_n(&self) -> f64 {
        self.engine_thrust_n[0] + self.engine_thrust_n[1]
    }

    /// Earth-axis inertial velocity (ẋ, ḣ) in m/s.
    #[inline]
    pub fn earth_velocity_mps(&self) -> (f64, f64) {
        let (sin_t, cos_t) = self.theta_rad.sin_cos();
        self.earth_velocity_trig(sin_t, cos_t)
    }

    /// As [`AircraftState::earth_velocity_mps`], with sin θ and cos θ already computed.
    #[inline]
    pub fn earth_velocity_trig(&self, sin_t: f64, cos_t: f64) -> (f64, f64) {
        (
            self.u_mps * cos_t + self.w_mps * sin_t,
            self.u_mps * sin_t - self.w_mps * cos_t,
        )
    }

    /// Inertial flight-path angle γ = atan2(ḣ, ẋ) (rad).
    #[inline]
    pub fn flight_path_angle_rad(&self) -> f64 {
        let (x_dot, h_dot) = self.earth_velocity_mps();
        h_dot.atan2(x_dot)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn array_round_trip_keeps_every_field() {
        let state = AircraftState {
            u_mps: 1.0,
            w_mps: 2.0,
            q_radps: 3.0,
            theta_rad: 4.0,
            x_m: 5.0,
            h_m: 6.0,
            engine_thrust_n: [7.0, 8.0],
            elevator_rad: 9.0,
            elevator_rate_radps: 10.0,
        };
        assert_eq!(AircraftState::from_array(&state.to_array()), state);
        assert_eq!(state.to_array(), [1., 2., 3., 4., 5., 6., 7., 8., 9., 10.]);
    }
}
