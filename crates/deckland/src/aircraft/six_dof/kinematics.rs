//! Euler-angle kinematics and the rotation between earth and body axes (Stevens & Lewis,
//! *Aircraft Control and Simulation*, 2nd ed., §1.3–1.4): earth x along the final
//! bearing, y right, z down; body x forward, y right wing, z down; 3-2-1 Euler angles
//! (ψ, θ, φ).

/// The sines and cosines of the Euler angles (φ, θ, ψ), evaluated once per state so that
/// the rotations, the Euler rates and the air data of one evaluation share them (the
/// results are those of the functions taking the angles, to the bit).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EulerTrig {
    /// sin φ.
    pub sin_phi: f64,
    /// cos φ.
    pub cos_phi: f64,
    /// sin θ.
    pub sin_theta: f64,
    /// cos θ.
    pub cos_theta: f64,
    /// sin ψ.
    pub sin_psi: f64,
    /// cos ψ.
    pub cos_psi: f64,
}

impl EulerTrig {
    /// The sines and cosines of `euler` = (φ, θ, ψ) (rad).
    #[inline]
    pub fn new(euler: [f64; 3]) -> Self {
        let (sin_phi, cos_phi) = euler[0].sin_cos();
        let (sin_theta, cos_theta) = euler[1].sin_cos();
        let (sin_psi, cos_psi) = euler[2].sin_cos();
        Self {
            sin_phi,
            cos_phi,
            sin_theta,
            cos_theta,
            sin_psi,
            cos_psi,
        }
    }

    /// Euler-angle rates (φ̇, θ̇, ψ̇) from body rates (p, q, r): [`euler_rates`].
    #[inline]
    pub fn euler_rates(&self, rates: [f64; 3]) -> [f64; 3] {
        let [p, q, r] = rates;
        let (sin_phi, cos_phi, sin_t, cos_t) =
            (self.sin_phi, self.cos_phi, self.sin_theta, self.cos_theta);
        let turn = q * sin_phi + r * cos_phi;
        [
            p + sin_t / cos_t * turn,
            q * cos_phi - r * sin_phi,
            turn / cos_t,
        ]
    }

    /// The direction cosines R(φ, θ, ψ) from earth to body axes (3-2-1 rotation), row by
    /// row.
    #[inline]
    fn direction_cosines(&self) -> [[f64; 3]; 3] {
        let (sf, cf) = (self.sin_phi, self.cos_phi);
        let (st, ct) = (self.sin_theta, self.cos_theta);
        let (ss, cs) = (self.sin_psi, self.cos_psi);
        [
            [ct * cs, ct * ss, -st],
            [sf * st * cs - cf * ss, sf * st * ss + cf * cs, sf * ct],
            [cf * st * cs + sf * ss, cf * st * ss - sf * cs, cf * ct],
        ]
    }

    /// An earth-axis vector (x forward, y right, z down) in body axes: [`earth_to_body`].
    #[inline]
    pub fn earth_to_body(&self, earth: [f64; 3]) -> [f64; 3] {
        let m = self.direction_cosines();
        [0, 1, 2].map(|i| m[i][0] * earth[0] + m[i][1] * earth[1] + m[i][2] * earth[2])
    }

    /// A body-axis vector in earth axes (x forward, y right, z down): [`body_to_earth`].
    #[inline]
    pub fn body_to_earth(&self, body: [f64; 3]) -> [f64; 3] {
        let m = self.direction_cosines();
        [0, 1, 2].map(|j| m[0][j] * body[0] + m[1][j] * body[1] + m[2][j] * body[2])
    }
}

/// Euler-angle rates (φ̇, θ̇, ψ̇) from body rates (p, q, r) (Stevens & Lewis Eq. 1.4-4):
/// φ̇ = p + tan θ (q sin φ + r cos φ), θ̇ = q cos φ − r sin φ,
/// ψ̇ = (q sin φ + r cos φ)/cos θ. Singular at θ = ±90°, far outside an approach.
#[inline]
pub fn euler_rates(rates: [f64; 3], euler: [f64; 3]) -> [f64; 3] {
    EulerTrig::new(euler).euler_rates(rates)
}

/// An earth-axis vector (x forward, y right, z down) in body axes, by the direction
/// cosines R(φ, θ, ψ) from earth to body axes (3-2-1 rotation).
#[inline]
pub fn earth_to_body(euler: [f64; 3], earth: [f64; 3]) -> [f64; 3] {
    EulerTrig::new(euler).earth_to_body(earth)
}

/// A body-axis vector in earth axes (x forward, y right, z down).
#[inline]
pub fn body_to_earth(euler: [f64; 3], body: [f64; 3]) -> [f64; 3] {
    EulerTrig::new(euler).body_to_earth(body)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Nose right (ψ = 90°) flies along earth +y; right wing down (φ > 0) points the
    /// right wing (body y) down (earth +z); nose up (θ > 0) climbs (earth −z).
    #[test]
    fn euler_angles_turn_the_axes_the_documented_way() {
        let half_pi = std::f64::consts::FRAC_PI_2;
        let along = body_to_earth([0.0, 0.0, half_pi], [1.0, 0.0, 0.0]);
        assert!((along[1] - 1.0).abs() < 1e-15 && along[0].abs() < 1e-15);
        let wing = body_to_earth([0.3, 0.0, 0.0], [0.0, 1.0, 0.0]);
        assert!((wing[2] - 0.3f64.sin()).abs() < 1e-15);
        let nose = body_to_earth([0.0, 0.2, 0.0], [1.0, 0.0, 0.0]);
        assert!((nose[2] + 0.2f64.sin()).abs() < 1e-15);
        // The two rotations are each other's inverse.
        let euler = [0.4, -0.3, 2.0];
        let back = earth_to_body(euler, body_to_earth(euler, [1.0, -2.0, 3.0]));
        for (a, b) in back.iter().zip([1.0, -2.0, 3.0]) {
            assert!((a - b).abs() < 1e-14);
        }
    }

    /// A pure body yaw rate r at bank φ and θ = 0 turns the heading at r cos φ and
    /// pitches the nose down at −r sin φ.
    #[test]
    fn euler_rates_of_a_yaw_rate_at_bank() {
        let phi: f64 = 0.5;
        let [phi_dot, theta_dot, psi_dot] = euler_rates([0.0, 0.0, 0.1], [phi, 0.0, 0.0]);
        assert!(phi_dot.abs() < 1e-15);
        assert!((theta_dot + 0.1 * phi.sin()).abs() < 1e-15);
        assert!((psi_dot - 0.1 * phi.cos()).abs() < 1e-15);
    }
}
