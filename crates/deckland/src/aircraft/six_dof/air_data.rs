//! The 6-DOF aircraft's air data: the air-relative body velocity in a wind and the
//! airspeed, angle of attack, sideslip and dynamic pressure it gives.

use super::kinematics::EulerTrig;
use crate::aircraft::aerodynamics::angle_of_attack;
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

impl SixDofAirData {
    /// Air data of an air-relative body velocity (m/s) in air of `air_density_kg_m3`
    /// (kg/m³); with `series_trig` (the 3-D approach), β by atan of the quotient (when
    /// the velocity has a part in the symmetry plane): within an ulp of atan2, at half
    /// its cost.
    #[inline]
    pub fn new(air_velocity: [f64; 3], series_trig: bool, air_density_kg_m3: f64) -> Self {
        let [ua, va, wa] = air_velocity;
        let airspeed = (ua * ua + va * va + wa * wa).sqrt();
        let in_symmetry_plane = (ua * ua + wa * wa).sqrt();
        Self {
            airspeed_mps: airspeed,
            alpha_rad: angle_of_attack(ua, wa),
            beta_rad: if series_trig && in_symmetry_plane > 0.0 {
                (va / in_symmetry_plane).atan()
            } else {
                va.atan2(in_symmetry_plane)
            },
            dynamic_pressure_pa: 0.5 * air_density_kg_m3 * airspeed * airspeed,
        }
    }
}

/// The air-relative velocity in body axes for inertial body velocity (u, v, w), the
/// Euler angles' sines and cosines `trig` and an earth-axis wind: (u, v, w) − R(φ, θ, ψ)·W.
#[inline]
pub fn air_velocity_in_wind(velocity: [f64; 3], trig: &EulerTrig, wind: &Wind) -> [f64; 3] {
    let wind_body = trig.earth_to_body([wind.x_mps, wind.y_mps, wind.z_mps]);
    [
        velocity[0] - wind_body[0],
        velocity[1] - wind_body[1],
        velocity[2] - wind_body[2],
    ]
}
