//! The 6-DOF aircraft's state vector, as a named struct.

/// State of the 6-DOF plant: rigid body, engines and the three surface actuators.
///
/// Velocities are *inertial* (earth-relative) components in body axes (x forward,
/// y right wing, z down), so that wind enters the aerodynamics only through the
/// air-relative velocity. Euler angles in the 3-2-1 order (ψ, then θ, then φ). Earth
/// position: x along the approach's final bearing, y to the right, altitude h = −z.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SixDofState {
    /// Inertial velocity along body x, u (m/s).
    pub u_mps: f64,
    /// Inertial velocity along body y (right wing), v (m/s).
    pub v_mps: f64,
    /// Inertial velocity along body z (down), w (m/s).
    pub w_mps: f64,
    /// Roll rate p (rad/s), positive right wing down.
    pub p_radps: f64,
    /// Pitch rate q (rad/s), positive nose-up.
    pub q_radps: f64,
    /// Yaw rate r (rad/s), positive nose right.
    pub r_radps: f64,
    /// Bank angle φ (rad), positive right wing down.
    pub phi_rad: f64,
    /// Pitch angle θ (rad), positive nose-up.
    pub theta_rad: f64,
    /// Heading ψ (rad) from the final bearing, positive nose right.
    pub psi_rad: f64,
    /// Earth x position (m) along the final bearing.
    pub x_m: f64,
    /// Earth y position (m), positive to the right of the final bearing.
    pub y_m: f64,
    /// Altitude h = −z (m), positive up.
    pub h_m: f64,
    /// Actual thrust of each engine (N).
    pub engine_thrust_n: [f64; 2],
    /// Elevator (stabilator) position δe (rad), positive trailing edge down.
    pub elevator_rad: f64,
    /// Elevator rate δ̇e (rad/s).
    pub elevator_rate_radps: f64,
    /// Aileron position δa (rad), positive gives a right-wing-down rolling moment.
    pub aileron_rad: f64,
    /// Aileron rate δ̇a (rad/s).
    pub aileron_rate_radps: f64,
    /// Rudder position δr (rad), positive trailing edge left (nose-left moment).
    pub rudder_rad: f64,
    /// Rudder rate δ̇r (rad/s).
    pub rudder_rate_radps: f64,
}

impl SixDofState {
    /// Number of scalar states.
    pub const DIMENSION: usize = 20;

    /// Names of the states, in the order of [`SixDofState::to_array`].
    pub const NAMES: [&'static str; 20] = [
        "u_mps",
        "v_mps",
        "w_mps",
        "p_radps",
        "q_radps",
        "r_radps",
        "phi_rad",
        "theta_rad",
        "psi_rad",
        "x_m",
        "y_m",
        "h_m",
        "engine_1_thrust_n",
        "engine_2_thrust_n",
        "elevator_rad",
        "elevator_rate_radps",
        "aileron_rad",
        "aileron_rate_radps",
        "rudder_rad",
        "rudder_rate_radps",
    ];

    /// The state as an array for the integrator, in the order of [`SixDofState::NAMES`].
    #[inline]
    pub fn to_array(&self) -> [f64; Self::DIMENSION] {
        [
            self.u_mps,
            self.v_mps,
            self.w_mps,
            self.p_radps,
            self.q_radps,
            self.r_radps,
            self.phi_rad,
            self.theta_rad,
            self.psi_rad,
            self.x_m,
            self.y_m,
            self.h_m,
            self.engine_thrust_n[0],
            self.engine_thrust_n[1],
            self.elevator_rad,
            self.elevator_rate_radps,
            self.aileron_rad,
            self.aileron_rate_radps,
            self.rudder_rad,
            self.rudder_rate_radps,
        ]
    }

    /// The state from an integrator array (inverse of [`SixDofState::to_array`]).
    #[inline]
    pub fn from_array(x: &[f64; Self::DIMENSION]) -> Self {
        Self {
            u_mps: x[0],
            v_mps: x[1],
            w_mps: x[2],
            p_radps: x[3],
            q_radps: x[4],
            r_radps: x[5],
            phi_rad: x[6],
            theta_rad: x[7],
            psi_rad: x[8],
            x_m: x[9],
            y_m: x[10],
            h_m: x[11],
            engine_thrust_n: [x[12], x[13]],
            elevator_rad: x[14],
            elevator_rate_radps: x[15],
            aileron_rad: x[16],
            aileron_rate_radps: x[17],
            rudder_rad: x[18],
            rudder_rate_radps: x[19],
        }
    }

    /// Total actual thrust of both engines (N).
    #[inline]
    pub fn total_thrust_n(&self) -> f64 {
        self.engine_thrust_n[0] + self.engine_thrust_n[1]
    }

    /// The 6-DOF state of a longitudinal state: wings level on the final bearing, no
    /// sideslip, the lateral surfaces at rest at neutral.
    pub fn from_longitudinal(state: &crate::aircraft::AircraftState) -> Self {
        Self {
            u_mps: state.u_mps,
            w_mps: state.w_mps,
            q_radps: state.q_radps,
            theta_rad: state.theta_rad,
            x_m: state.x_m,
            h_m: state.h_m,
            engine_thrust_n: state.engine_thrust_n,
            elevator_rad: state.elevator_rad,
            elevator_rate_radps: state.elevator_rate_radps,
            ..Self::default()
        }
    }

    /// The longitudinal part (u, w, q, θ, x, h, engines, elevator) as a 3-DOF state.
    pub fn longitudinal(&self) -> crate::aircraft::AircraftState {
        crate::aircraft::AircraftState {
            u_mps: self.u_mps,
            w_mps: self.w_mps,
            q_radps: self.q_radps,
            theta_rad: self.theta_rad,
            x_m: self.x_m,
            h_m: self.h_m,
            engine_thrust_n: self.engine_thrust_n,
            elevator_rad: self.elevator_rad,
            elevator_rate_radps: self.elevator_rate_radps,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn array_round_trip_keeps_every_field() {
        let mut x = [0.0; SixDofState::DIMENSION];
        for (i, value) in x.iter_mut().enumerate() {
            *value = i as f64 + 1.0;
        }
        let state = SixDofState::from_array(&x);
        assert_eq!(state.to_array(), x);
        assert_eq!(state.v_mps, 2.0);
        assert_eq!(state.psi_rad, 9.0);
        assert_eq!(state.rudder_rate_radps, 20.0);
        assert_eq!(SixDofState::NAMES[18], "rudder_rad");
    }

    #[test]
    fn longitudinal_round_trip() {
        let mut x = [0.0; SixDofState::DIMENSION];
        for (i, value) in x.iter_mut().enumerate() {
            *value = i as f64 + 1.0;
        }
        let state = SixDofState::from_array(&x);
        let back = SixDofState::from_longitudinal(&state.longitudinal());
        assert_eq!(back.u_mps, state.u_mps);
        assert_eq!(back.elevator_rate_radps, state.elevator_rate_radps);
        assert_eq!(back.v_mps, 0.0);
    }
}
