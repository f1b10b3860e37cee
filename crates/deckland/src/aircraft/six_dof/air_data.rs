//! The 6-DOF aircraft's air data: the air-relative body velocity in a wind and the
//! airspeed, angle of attack, sideslip and dynamic pressure it gives.

use super::dynamics::SixDofAircraft;
use super::kinematics::EulerTrig;
use crate::aircraft::Wind;

/// Air data from the air-relative body velocity (u_a, v_a, w_a).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixDofAirData {
    /// True airspeed V_T (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack α = atan(w_a/u_a) (rad).
    pub alpha_rad: f64,
    /// Sideslip β = asin(v_a/V_T) (rad), positive with the relative wind from the right.
    pub beta_rad: f64,
    /// Dynamic pressure q̄ = ½ρV_T² (Pa).
    pub dynamic_pressure_pa: f64,
}

impl SixDofAircraft {
    /// The air-relative velocity in body axes for inertial body velocity (u, v, w), Euler
    /// angles (φ, θ, ψ) and an earth-axis wind: (u, v, w) − R(φ, θ, ψ)·W.
    #[inline]
    pub fn air_velocity(&self, velocity: [f64; 3], euler: [f64; 3], wind: &Wind) -> [f64; 3] {
        self.air_velocity_trig(velocity, &EulerTrig::new(euler), wind)
    }

    /// [`SixDofAircraft::air_velocity`] with the Euler angles' sines and cosines.
    #[inline]
    pub fn air_velocity_trig(&self, velocity: [f64; 3], trig: &EulerTrig, wind: &Wind) -> [f64; 3] {
        let wind_body = trig.earth_to_body([wind.x_mps, wind.y_mps, wind.z_mps]);
        [
            velocity[0] - wind_body[0],
            velocity[1] - wind_body[1],
            velocity[2] - wind_body[2],
        ]
    }

    /// Air data of an air-relative body velocity (m/s).
    #[inline]
    pub fn air_data(&self, air_velocity: [f64; 3]) -> SixDofAirData {
        let [ua, va, wa] = air_velocity;
        let airspeed = (ua * ua + va * va + wa * wa).sqrt();
        let in_symmetry_plane = (ua * ua + wa * wa).sqrt();
        SixDofAirData {
            airspeed_mps: airspeed,
            alpha_rad: if ua > 0.0 {
                (wa / ua).atan()
            } else {
                wa.atan2(ua)
            },
            // With series trig (the 3-D approach), atan of the quotient (in_symmetry_plane
            // > 0): within an ulp of atan2, at half its cost.
            beta_rad: if self.series_trig && in_symmetry_plane > 0.0 {
                (va / in_symmetry_plane).atan()
            } else {
                va.atan2(in_symmetry_plane)
            },
            dynamic_pressure_pa: 0.5
                * self.longitudinal().parameters().air_density_kg_m3
                * airspeed
                * airspeed,
        }
    }
}
