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
        Self::of(euler.map(f64::sin_cos))
    }

    /// From the (sine, cosine) pairs of φ, θ and ψ.
    #[inline]
    fn of(
        [(sin_phi, cos_phi), (sin_theta, cos_theta), (sin_psi, cos_psi)]: [(f64, f64); 3],
    ) -> Self {
        Self {
            sin_phi,
            cos_phi,
            sin_theta,
            cos_theta,
            sin_psi,
            cos_psi,
        }
    }

    /// [`EulerTrig::new`] by [`series_sin_cos`]: the same values to within an ulp, at
    /// about a third of the cost (the 3-D approach's evaluations).
    #[inline]
    pub fn by_series(euler: [f64; 3]) -> Self {
        Self::of(euler.map(series_sin_cos))
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

/// The angle (rad) up to which [`series_sin_cos`] sums the series: beyond the bank,
/// pitch, heading and sideslip of an approach, where the truncation (the first omitted
/// terms, x¹⁷/17! and x¹⁸/18!, below 5·10⁻¹⁹) is far below the rounding of the result.
pub const SERIES_LIMIT_RAD: f64 = 0.6;

/// sin x and cos x (x in rad): for |x| ≤ [`SERIES_LIMIT_RAD`], their Taylor series to
/// x¹⁵ and x¹⁶, summed by Horner's rule on x² (the leading 1 and x added last), within
/// an ulp of the correctly rounded values; beyond it, the library's. About 40
/// arithmetic instructions where the library's `sincos` takes about 100: it serves the
/// 3-D approach's Euler angles, evaluated four times a step.
#[inline]
pub fn series_sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > SERIES_LIMIT_RAD {
        return x.sin_cos();
    }
    let x2 = x * x;
    // 1/n! for the odd (sine) and even (cosine) terms.
    let sine = -1.0 / 6.0
        + x2 * (1.0 / 120.0
            + x2 * (-1.0 / 5_040.0
                + x2 * (1.0 / 362_880.0
                    + x2 * (-1.0 / 39_916_800.0
                        + x2 * (1.0 / 6_227_020_800.0 + x2 * (-1.0 / 1_307_674_368_000.0))))));
    let cosine = 1.0 / 24.0
        + x2 * (-1.0 / 720.0
            + x2 * (1.0 / 40_320.0
                + x2 * (-1.0 / 3_628_800.0
                    + x2 * (1.0 / 479_001_600.0
                        + x2 * (-1.0 / 87_178_291_200.0 + x2 * (1.0 / 20_922_789_888_000.0))))));
    (x + x * x2 * sine, 1.0 + x2 * (-0.5 + x2 * cosine))
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

    /// The series agree with the library's sine and cosine to within an ulp over the
    /// whole range they serve (1001 angles), exactly at 0, and are the library's beyond.
    #[test]
    fn the_series_sine_and_cosine_are_the_librarys_to_an_ulp() {
        let ulp = |v: f64| f64::EPSILON * v.abs().max(f64::MIN_POSITIVE);
        let mut largest = 0.0_f64;
        for k in -500..=500 {
            let x = SERIES_LIMIT_RAD * f64::from(k) / 500.0;
            let (sin, cos) = series_sin_cos(x);
            let (sin_error, cos_error) = ((sin - x.sin()).abs(), (cos - x.cos()).abs());
            assert!(sin_error <= ulp(x.sin()), "sin {x}: {sin} vs {}", x.sin());
            assert!(cos_error <= ulp(x.cos()), "cos {x}: {cos} vs {}", x.cos());
            largest = largest.max(sin_error).max(cos_error);
        }
        assert!(largest > 0.0, "the series are not the library's calls");
        assert_eq!(series_sin_cos(0.0), (0.0, 1.0));
        assert_eq!(series_sin_cos(0.7), 0.7_f64.sin_cos());
        let trig = EulerTrig::by_series([0.2, -0.05, 0.07]);
        let exact = EulerTrig::new([0.2, -0.05, 0.07]);
        assert!((trig.sin_phi - exact.sin_phi).abs() <= ulp(exact.sin_phi));
        assert!((trig.cos_psi - exact.cos_psi).abs() <= ulp(exact.cos_psi));
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
