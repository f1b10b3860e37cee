//! The 6-DOF aircraft as a plant of the closed loop ([`Plant`]): its 20 named states,
//! three surfaces, the hook in three dimensions and its air data with sideslip.
//!
//! Its rate is [`SixDofAircraft::derivative`]'s; direct lift control's increment ΔC_L
//! adds a lift force q̄S·ΔC_L normal to the air-relative velocity in the plane of
//! symmetry, as in the longitudinal model (docs/model.md §5.9), without a sideslip
//! factor. With the lateral states at rest it flies the longitudinal plant's trajectory
//! (`tests/six_dof_closed_loop.rs`).

use super::air_data::SixDofAirData;
use super::dynamics::{SixDofAircraft, SixDofCommands};
use super::kinematics::EulerTrig;
use super::state::SixDofState;
use crate::aircraft::plant::{
    LateralKinematics, Plant, PlantAirData, PlantCommands, PlantKinematics, PlantModel,
};
use crate::aircraft::{AircraftParameters, AircraftState, ElevatorActuator, Engines, HookGeometry};
use crate::environment::{EarthPoint, EarthVelocity, Wind};

/// The 6-DOF plant's kinematics beside its outputs.
#[derive(Debug, Clone, Copy)]
pub struct SixDofKinematic {
    /// The state.
    pub state: SixDofState,
    /// The sines and cosines of its Euler angles.
    pub trig: EulerTrig,
}

/// The 6-DOF plant's air data beside its outputs: the wind they were computed in and the
/// air-relative body velocity.
#[derive(Debug, Clone, Copy)]
pub struct SixDofAir {
    /// The wind at the aircraft (earth axes).
    pub wind: Wind,
    /// Air-relative velocity in body axes (u_a, v_a, w_a) (m/s).
    pub air_velocity: [f64; 3],
    /// The air data.
    pub data: SixDofAirData,
}

/// ω × r for body rates ω and a body-axis offset r.
#[inline(always)]
fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

impl Plant for SixDofAircraft {
    type State = SixDofState;
    type Kinematic = SixDofKinematic;
    type Air = SixDofAir;

    const MODEL: PlantModel = PlantModel::SixDof;
    const STATE_NAMES: &'static [&'static str] = &SixDofState::NAMES;
    const STATE_UNITS: &'static [&'static str] = &[
        "m/s", "m/s", "m/s", "rad/s", "rad/s", "rad/s", "rad", "rad", "rad", "m", "m", "m", "N",
        "N", "rad", "rad/s", "rad", "rad/s", "rad", "rad/s",
    ];
    const SURFACES: &'static [&'static str] = &["elevator", "aileron", "rudder"];

    #[inline(always)]
    fn state_at(x: &[f64], offset: usize) -> SixDofState {
        let mut array = [0.0; SixDofState::DIMENSION];
        array.copy_from_slice(&x[offset..offset + SixDofState::DIMENSION]);
        SixDofState::from_array(&array)
    }

    #[inline(always)]
    fn write_state_at(state: &SixDofState, x: &mut [f64], offset: usize) {
        x[offset..offset + SixDofState::DIMENSION].copy_from_slice(&state.to_array());
    }

    fn from_longitudinal(state: &AircraftState) -> SixDofState {
        SixDofState::from_longitudinal(state)
    }

    #[inline(always)]
    fn longitudinal_state(state: &SixDofState) -> AircraftState {
        state.longitudinal()
    }

    #[inline(always)]
    fn parameters(&self) -> &AircraftParameters {
        self.longitudinal().parameters()
    }

    #[inline(always)]
    fn engines(&self) -> &Engines {
        self.longitudinal().engines()
    }

    #[inline(always)]
    fn stabilator(&self) -> &ElevatorActuator {
        self.longitudinal().actuator()
    }

    fn surface_actuator(&self, index: usize) -> Option<&ElevatorActuator> {
        match index {
            0 => Some(self.longitudinal().actuator()),
            1 => Some(self.aileron()),
            2 => Some(self.rudder()),
            _ => None,
        }
    }

    /// Neutral: the symmetric trim's aileron and rudder (no lateral law flies yet).
    #[inline(always)]
    fn held_lateral_commands(&self) -> Option<(f64, f64)> {
        Some((0.0, 0.0))
    }

    #[inline(always)]
    fn kinematics(
        &self,
        hook: &HookGeometry,
        state: SixDofState,
    ) -> (SixDofKinematic, PlantKinematics) {
        let trig = self.euler_trig([state.phi_rad, state.theta_rad, state.psi_rad]);
        let rates = [state.p_radps, state.q_radps, state.r_radps];
        let [x_rate, y_rate, z_rate] = trig.body_to_earth([state.u_mps, state.v_mps, state.w_mps]);
        // The hook's offset from the CG in body axes (x forward, z down) and its velocity
        // relative to the CG, ω × r.
        let offset = [-hook.aft_of_cg_m, 0.0, hook.below_cg_m];
        let [hook_dx, hook_dy, hook_dz] = trig.body_to_earth(offset);
        let [hook_vx, hook_vy, hook_vz] = trig.body_to_earth(cross(rates, offset));
        let outputs = PlantKinematics {
            position: EarthPoint {
                x_m: state.x_m,
                y_m: state.y_m,
                h_m: state.h_m,
            },
            velocity: EarthVelocity {
                x_mps: x_rate,
                y_mps: y_rate,
                h_mps: -z_rate,
            },
            hook: EarthPoint {
                x_m: state.x_m + hook_dx,
                y_m: state.y_m + hook_dy,
                h_m: state.h_m - hook_dz,
            },
            hook_velocity: EarthVelocity {
                x_mps: x_rate + hook_vx,
                y_mps: y_rate + hook_vy,
                h_mps: -(z_rate + hook_vz),
            },
            theta_rad: state.theta_rad,
            q_radps: state.q_radps,
            elevator_rad: state.elevator_rad,
            elevator_rate_radps: state.elevator_rate_radps,
            thrust_n: state.total_thrust_n(),
            lateral: Some(LateralKinematics {
                phi_rad: state.phi_rad,
                psi_rad: state.psi_rad,
                p_radps: state.p_radps,
                r_radps: state.r_radps,
                aileron_rad: state.aileron_rad,
                rudder_rad: state.rudder_rad,
            }),
        };
        (SixDofKinematic { state, trig }, outputs)
    }

    #[inline(always)]
    fn air_data(&self, kinematic: &SixDofKinematic, wind: &Wind) -> (SixDofAir, PlantAirData) {
        let s = &kinematic.state;
        let air_velocity =
            self.air_velocity_trig([s.u_mps, s.v_mps, s.w_mps], &kinematic.trig, wind);
        let data = SixDofAircraft::air_data(self, air_velocity);
        let outputs = PlantAirData {
            airspeed_mps: data.airspeed_mps,
            alpha_rad: data.alpha_rad,
            beta_rad: Some(data.beta_rad),
            dynamic_pressure_pa: data.dynamic_pressure_pa,
        };
        let air = SixDofAir {
            wind: *wind,
            air_velocity,
            data,
        };
        (air, outputs)
    }

    #[inline(always)]
    fn derivative(
        &self,
        kinematic: &SixDofKinematic,
        air: &SixDofAir,
        commands: &PlantCommands,
    ) -> SixDofState {
        let mut rate = self.derivative_in_air(
            &kinematic.state,
            &kinematic.trig,
            air.air_velocity,
            &air.data,
            &SixDofCommands {
                elevator_rad: commands.elevator_rad,
                thrust_n: commands.thrust_n,
                aileron_rad: commands.aileron_rad,
                rudder_rad: commands.rudder_rad,
            },
        );
        if commands.lift_coefficient_increment != 0.0 {
            // Direct lift: q̄S·ΔC_L normal to the air-relative velocity in the plane of
            // symmetry (along −z of the stability axes).
            let [ua, _, wa] = air.air_velocity;
            let in_plane = (ua * ua + wa * wa).sqrt();
            let (sin_a, cos_a) = if in_plane > 0.0 {
                (wa / in_plane, ua / in_plane)
            } else {
                (0.0, 1.0)
            };
            let p = self.longitudinal().parameters();
            let lift =
                air.data.dynamic_pressure_pa * p.wing_area_m2 * commands.lift_coefficient_increment;
            rate.u_mps += lift * sin_a / p.mass_kg;
            rate.w_mps -= lift * cos_a / p.mass_kg;
        }
        rate
    }

    #[inline]
    fn constrain(&self, x: &mut [f64]) {
        let mut state = Self::state_at(x, 0);
        SixDofAircraft::constrain(self, &mut state);
        Self::write_state_at(&state, x, 0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::Plant;

    /// At wings level on the bearing with no lateral motion, the kinematics are the
    /// longitudinal plant's: the same hook, CG velocity and hook velocity.
    #[test]
    fn wings_level_kinematics_are_the_longitudinal_plants() {
        let longitudinal = AircraftState {
            u_mps: 68.0,
            w_mps: 6.0,
            q_radps: 0.05,
            theta_rad: 0.1,
            x_m: -800.0,
            h_m: 60.0,
            engine_thrust_n: [20_000.0, 20_000.0],
            ..AircraftState::default()
        };
        let hook = HookGeometry::default();
        let six = SixDofAircraft::default();
        let (_, a) = Plant::kinematics(six.longitudinal(), &hook, longitudinal);
        let (_, b) = six.kinematics(&hook, SixDofAircraft::from_longitudinal(&longitudinal));
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-12 * (1.0 + y.abs());
        assert!(
            close(b.hook.x_m, a.hook.x_m) && close(b.hook.h_m, a.hook.h_m),
            "{b:?}"
        );
        assert!(close(b.hook_velocity.x_mps, a.hook_velocity.x_mps));
        assert!(close(b.hook_velocity.h_mps, a.hook_velocity.h_mps));
        assert!(close(b.velocity.h_mps, a.velocity.h_mps) && b.hook.y_m.abs() < 1e-15);
        assert_eq!(
            SixDofAircraft::STATE_NAMES.len(),
            SixDofAircraft::STATE_UNITS.len()
        );
    }

    /// Banked right (φ > 0) the hook, below the CG, swings to the left (y < 0); yawing
    /// right (r > 0) the hook, aft of the CG, moves to the left.
    #[test]
    fn the_hook_moves_with_bank_and_yaw() {
        let hook = HookGeometry::default();
        let six = SixDofAircraft::default();
        let state = SixDofState {
            u_mps: 68.0,
            phi_rad: 0.2,
            r_radps: 0.1,
            ..SixDofState::default()
        };
        let (_, k) = six.kinematics(&hook, state);
        assert!((k.hook.y_m + hook.below_cg_m * 0.2_f64.sin()).abs() < 1e-12);
        // ω × r = (0, 0, r) × (−aft, 0, below) = (0, −r·aft, 0) in body axes.
        let expected_vy = 0.2_f64.cos() * (-0.1 * hook.aft_of_cg_m);
        assert!((k.hook_velocity.y_mps - expected_vy).abs() < 1e-12, "{k:?}");
    }
}
