//! The 6-DOF rigid-body equations (Stevens & Lewis, *Aircraft Control and Simulation*,
//! 2nd ed., §2.5, flat earth, body axes, Euler angles), and the plant built on the
//! longitudinal model. See the module docs of `six_dof` for the equations.

use super::air_data::{air_velocity_in_wind, SixDofAirData};
use super::kinematics::EulerTrig;
use super::lateral_aerodynamics::{LateralDerivatives, LateralMotion, LateralTable};
use super::parameters::{LateralParameters, SurfaceActuatorParameters};
use super::state::SixDofState;
use crate::aircraft::{Aircraft, ElevatorActuator, Wind};
use crate::integration::OdeSystem;
use crate::parameters::ParameterError;

/// Commands to the 6-DOF plant's actuators and engines.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SixDofCommands {
    /// Elevator command (rad), positive trailing edge down.
    pub elevator_rad: f64,
    /// Total thrust command of both engines (N), limited to [0, 2·T_max].
    pub thrust_n: f64,
    /// Aileron command (rad), positive right wing down.
    pub aileron_rad: f64,
    /// Rudder command (rad), positive trailing edge left.
    pub rudder_rad: f64,
}

/// Surface deflections and thrust acting directly on the airframe (trim, linearisation).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SixDofInputs {
    /// Elevator δe (rad).
    pub elevator_rad: f64,
    /// Total thrust T (N).
    pub thrust_n: f64,
    /// Aileron δa (rad).
    pub aileron_rad: f64,
    /// Rudder δr (rad).
    pub rudder_rad: f64,
}

/// The rigid-body rates of a body state under given airframe inputs: (u̇, v̇, ẇ) in
/// m/s² and (ṗ, q̇, ṙ) in rad/s².
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyRates {
    /// Translational accelerations (u̇, v̇, ẇ) (m/s²).
    pub velocity: [f64; 3],
    /// Angular accelerations (ṗ, q̇, ṙ) (rad/s²).
    pub angular: [f64; 3],
}

/// The 6-DOF F/A-18: the longitudinal plant's aerodynamics, engines and stabilator, plus
/// the lateral data, inertias, aileron and rudder.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SixDofAircraft {
    longitudinal: Aircraft,
    lateral: LateralParameters,
    aileron: ElevatorActuator,
    rudder: ElevatorActuator,
    /// Whether the closed loop's evaluations take the Euler angles' and the sideslip
    /// factor's sines and cosines from [`super::series_sin_cos`], and the sideslip from
    /// atan of v/√(u² + w²) (the 3-D approach), rather than the library's sin, cos and
    /// atan2.
    pub(super) series_trig: bool,
    /// The lateral derivatives' polynomials by power, from the longitudinal plant's
    /// aerodynamic data: built once, evaluated at every derivative.
    lateral_table: LateralTable,
    /// Whether the aerodynamic data are the F/A-18's, whose lateral derivatives are then
    /// evaluated as constants ([`LateralDerivatives::fa18_at`]).
    aerodynamics_are_fa18: bool,
}

impl Default for SixDofAircraft {
    fn default() -> Self {
        Self::new(
            Aircraft::default(),
            LateralParameters::default(),
            SurfaceActuatorParameters::AILERON,
            SurfaceActuatorParameters::RUDDER,
        )
        .expect("the default lateral parameters are valid")
    }
}

/// The air data of the 6-DOF aircraft (`air_data.rs`).
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
        air_velocity_in_wind(velocity, trig, wind)
    }

    /// Air data of an air-relative body velocity (m/s).
    #[inline]
    pub fn air_data(&self, air_velocity: [f64; 3]) -> SixDofAirData {
        SixDofAirData::new(
            air_velocity,
            self.series_trig,
            self.longitudinal().parameters().air_density_kg_m3,
        )
    }
}

impl SixDofAircraft {
    /// Section of the aileron actuator's parameters in a scenario.
    pub const AILERON_SECTION: &'static str = "aircraft.aileron_actuator";
    /// Section of the rudder actuator's parameters in a scenario.
    pub const RUDDER_SECTION: &'static str = "aircraft.rudder_actuator";

    /// Builds the plant on a (validated) longitudinal plant after validating the rest.
    pub fn new(
        longitudinal: Aircraft,
        lateral: LateralParameters,
        aileron: SurfaceActuatorParameters,
        rudder: SurfaceActuatorParameters,
    ) -> Result<Self, ParameterError> {
        lateral.validate()?;
        Ok(Self {
            lateral_table: LateralTable::of(longitudinal.aerodynamics()),
            aerodynamics_are_fa18: longitudinal.aerodynamics().is_fa18(),
            longitudinal,
            lateral,
            aileron: aileron.build(Self::AILERON_SECTION)?,
            rudder: rudder.build(Self::RUDDER_SECTION)?,
            series_trig: false,
        })
    }

    /// This aircraft with the closed loop's sines and cosines by series (`true`, the 3-D
    /// approach: within an ulp of the library's, about a third of the cost) or by the
    /// library (`false`, the default).
    pub fn with_series_trig(self, series_trig: bool) -> Self {
        Self {
            series_trig,
            ..self
        }
    }

    /// The sines and cosines of the Euler angles (φ, θ, ψ) in the closed loop's
    /// evaluations ([`SixDofAircraft::with_series_trig`]).
    #[inline(always)]
    pub fn euler_trig(&self, euler: [f64; 3]) -> EulerTrig {
        if self.series_trig {
            EulerTrig::by_series(euler)
        } else {
            EulerTrig::new(euler)
        }
    }

    /// The longitudinal plant whose aerodynamics, engines and stabilator this one uses.
    pub fn longitudinal(&self) -> &Aircraft {
        &self.longitudinal
    }

    /// Span and inertias.
    pub fn lateral(&self) -> &LateralParameters {
        &self.lateral
    }

    /// Aileron actuator.
    pub fn aileron(&self) -> &ElevatorActuator {
        &self.aileron
    }

    /// Rudder actuator.
    pub fn rudder(&self) -> &ElevatorActuator {
        &self.rudder
    }

    /// Rigid-body rates for inertial body velocity (m/s), body rates (p, q, r) (rad/s),
    /// Euler angles (φ, θ, ψ) (rad), airframe inputs and wind.
    #[inline]
    pub fn body_rates(
        &self,
        velocity: [f64; 3],
        rates: [f64; 3],
        euler: [f64; 3],
        inputs: &SixDofInputs,
        wind: &Wind,
    ) -> BodyRates {
        let trig = EulerTrig::new(euler);
        let air = self.air_velocity_trig(velocity, &trig, wind);
        self.body_rates_in_air(velocity, rates, &trig, air, &self.air_data(air), inputs)
    }

    /// [`SixDofAircraft::body_rates`] from the Euler angles' sines and cosines, the
    /// air-relative body velocity `air` (m/s) and its air data `data`.
    #[inline]
    pub fn body_rates_in_air(
        &self,
        velocity: [f64; 3],
        rates: [f64; 3],
        trig: &EulerTrig,
        air: [f64; 3],
        data: &SixDofAirData,
        inputs: &SixDofInputs,
    ) -> BodyRates {
        let p = self.longitudinal.parameters();
        let config = self.longitudinal.configuration();
        let lat = &self.lateral;
        let [u, v, w] = velocity;
        let [roll_rate, q, r] = rates;
        let (sin_phi, cos_phi) = (trig.sin_phi, trig.cos_phi);
        let (sin_t, cos_t) = (trig.sin_theta, trig.cos_theta);
        let [ua, _, wa] = air;
        let airspeed = data.airspeed_mps;
        let in_plane = (ua * ua + wa * wa).sqrt();
        let (sin_a, cos_a) = if in_plane > 0.0 {
            (wa / in_plane, ua / in_plane)
        } else {
            (0.0, 1.0)
        };
        let cos_b = if airspeed > 0.0 {
            in_plane / airspeed
        } else {
            1.0
        };
        let beta = data.beta_rad;
        let q_hat = q * p.mean_chord_m / (2.0 * airspeed);
        let c = self.longitudinal.coefficients_trig(
            (data.alpha_rad, sin_a, cos_a),
            inputs.elevator_rad,
            q_hat,
            config,
        );
        // The source's sideslip factors; both are exactly 1 at β = 0.
        let lift_factor = if self.series_trig {
            super::series_sin_cos(2.0 * beta / 3.0).1
        } else {
            (2.0 * beta / 3.0).cos()
        };
        let drag_factor = cos_b;
        let lift_coefficient = c.lift * lift_factor;
        let drag_coefficient = c.drag * drag_factor;
        // The CG transfer of the pitching moment acts on the normal force the factors
        // leave; at β = 0 the correction is exactly zero.
        let normal_change =
            c.lift * (lift_factor - 1.0) * cos_a + c.drag * (drag_factor - 1.0) * sin_a;
        let pitch_coefficient = c.moment - config.cg_ahead_of_reference_chords * normal_change;
        let half_span_over_speed = lat.span_m / (2.0 * airspeed);
        let derivatives = if self.aerodynamics_are_fa18 {
            LateralDerivatives::fa18_at(data.alpha_rad)
        } else {
            self.lateral_table.at(data.alpha_rad)
        };
        let l = derivatives.coefficients(LateralMotion {
            beta,
            aileron: inputs.aileron_rad,
            rudder: inputs.rudder_rad,
            p_hat: roll_rate * half_span_over_speed,
            r_hat: r * half_span_over_speed,
        });
        let qs = data.dynamic_pressure_pa * p.wing_area_m2;
        let lift = qs * lift_coefficient;
        let drag = qs * drag_coefficient;
        let side = qs * l.side;
        // Lift and drag in the plane of symmetry (stability axes: drag along −x_s, lift
        // along −z_s), side force along body y, thrust along body x.
        let force_x = lift * sin_a - drag * cos_a + inputs.thrust_n;
        let force_y = side;
        let force_z = -lift * cos_a - drag * sin_a;
        let m = p.mass_kg;
        let g = p.gravity_mps2;
        let u_dot = force_x / m - g * sin_t - q * w + r * v;
        let v_dot = force_y / m + g * (sin_phi * cos_t) - r * u + roll_rate * w;
        let w_dot = force_z / m + g * (cos_phi * cos_t) + q * u - roll_rate * v;
        // Moments about the CG; the CG is ahead of the data's reference point by
        // d·c̄ (docs/model.md §2.3), so the side force there yaws the nose left.
        let roll_moment = qs * lat.span_m * l.roll;
        let yaw_moment = qs
            * (lat.span_m * l.yaw - config.cg_ahead_of_reference_chords * p.mean_chord_m * l.side);
        let pitch_moment = qs * p.mean_chord_m * pitch_coefficient;
        let (ix, iy, iz, ixz) = (
            lat.roll_inertia_kg_m2,
            p.pitch_inertia_kg_m2,
            lat.yaw_inertia_kg_m2,
            lat.product_of_inertia_xz_kg_m2,
        );
        let gamma = ix * iz - ixz * ixz;
        // Stevens & Lewis §2.5, the rate equations solved for ṗ, q̇, ṙ (their c1…c9),
        // written out; the module docs give the same form.
        let p_dot = (((iy - iz) * iz - ixz * ixz) * r * q
            + (ix - iy + iz) * ixz * roll_rate * q
            + iz * roll_moment
            + ixz * yaw_moment)
            / gamma;
        let q_dot =
            (pitch_moment + (iz - ix) * roll_rate * r - ixz * (roll_rate * roll_rate - r * r)) / iy;
        let r_dot = ((ix * (ix - iy) + ixz * ixz) * roll_rate * q - (ix - iy + iz) * ixz * r * q
            + ixz * roll_moment
            + ix * yaw_moment)
            / gamma;
        BodyRates {
            velocity: [u_dot, v_dot, w_dot],
            angular: [p_dot, q_dot, r_dot],
        }
    }

    /// Time derivative of the full plant state for actuator commands and wind.
    #[inline]
    pub fn derivative(
        &self,
        state: &SixDofState,
        commands: &SixDofCommands,
        wind: &Wind,
    ) -> SixDofState {
        let trig = EulerTrig::new([state.phi_rad, state.theta_rad, state.psi_rad]);
        let air = self.air_velocity_trig([state.u_mps, state.v_mps, state.w_mps], &trig, wind);
        self.derivative_in_air(state, &trig, air, &self.air_data(air), commands)
    }

    /// [`SixDofAircraft::derivative`] from the Euler angles' sines and cosines `trig`,
    /// the air-relative body velocity `air` (m/s) and its air data `data` (those of the
    /// state in the wind: the closed loop has them already).
    #[inline]
    pub fn derivative_in_air(
        &self,
        state: &SixDofState,
        trig: &EulerTrig,
        air: [f64; 3],
        data: &SixDofAirData,
        commands: &SixDofCommands,
    ) -> SixDofState {
        let velocity = [state.u_mps, state.v_mps, state.w_mps];
        let rates = [state.p_radps, state.q_radps, state.r_radps];
        let inputs = SixDofInputs {
            elevator_rad: state.elevator_rad,
            thrust_n: state.total_thrust_n(),
            aileron_rad: state.aileron_rad,
            rudder_rad: state.rudder_rad,
        };
        let body = self.body_rates_in_air(velocity, rates, trig, air, data, &inputs);
        let [phi_dot, theta_dot, psi_dot] = trig.euler_rates(rates);
        let [x_dot, y_dot, z_dot] = trig.body_to_earth(velocity);
        let engines = self.longitudinal.engines();
        let (elevator_rate, elevator_acceleration) = self.longitudinal.actuator().derivative(
            state.elevator_rad,
            state.elevator_rate_radps,
            commands.elevator_rad,
        );
        let (aileron_rate, aileron_acceleration) = self.aileron.derivative(
            state.aileron_rad,
            state.aileron_rate_radps,
            commands.aileron_rad,
        );
        let (rudder_rate, rudder_acceleration) = self.rudder.derivative(
            state.rudder_rad,
            state.rudder_rate_radps,
            commands.rudder_rad,
        );
        SixDofState {
            u_mps: body.velocity[0],
            v_mps: body.velocity[1],
            w_mps: body.velocity[2],
            p_radps: body.angular[0],
            q_radps: body.angular[1],
            r_radps: body.angular[2],
            phi_rad: phi_dot,
            theta_rad: theta_dot,
            psi_rad: psi_dot,
            x_m: x_dot,
            y_m: y_dot,
            h_m: -z_dot,
            engine_thrust_n: [
                engines.thrust_rate(state.engine_thrust_n[0], commands.thrust_n),
                engines.thrust_rate(state.engine_thrust_n[1], commands.thrust_n),
            ],
            elevator_rad: elevator_rate,
            elevator_rate_radps: elevator_acceleration,
            aileron_rad: aileron_rate,
            aileron_rate_radps: aileron_acceleration,
            rudder_rad: rudder_rate,
            rudder_rate_radps: rudder_acceleration,
        }
    }

    /// Applies the three actuators' position and rate limits after an integration step.
    #[inline]
    pub fn constrain(&self, state: &mut SixDofState) {
        self.longitudinal
            .actuator()
            .constrain(&mut state.elevator_rad, &mut state.elevator_rate_radps);
        self.aileron
            .constrain(&mut state.aileron_rad, &mut state.aileron_rate_radps);
        self.rudder
            .constrain(&mut state.rudder_rad, &mut state.rudder_rate_radps);
    }
}

/// The 6-DOF plant flown with fixed commands in a fixed wind: an [`OdeSystem`].
#[derive(Debug, Clone, Copy)]
pub struct OpenLoopSixDof {
    /// The plant.
    pub aircraft: SixDofAircraft,
    /// Commands held constant.
    pub commands: SixDofCommands,
    /// Wind held constant.
    pub wind: Wind,
}

impl OdeSystem<{ SixDofState::DIMENSION }> for OpenLoopSixDof {
    fn derivative(
        &self,
        _t: f64,
        x: &[f64; SixDofState::DIMENSION],
    ) -> [f64; SixDofState::DIMENSION] {
        let state = SixDofState::from_array(x);
        self.aircraft
            .derivative(&state, &self.commands, &self.wind)
            .to_array()
    }

    fn constrain(&self, x: &mut [f64; SixDofState::DIMENSION]) {
        let mut state = SixDofState::from_array(x);
        self.aircraft.constrain(&mut state);
        *x = state.to_array();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::aircraft::six_dof::{lateral_coefficients, LateralMotion};
    use nalgebra::{Matrix3, Vector3};

    /// The rate equations against Euler's equations in matrix form, J ω̇ = M − ω × Jω
    /// with J = [[I_x, 0, −I_xz], [0, I_y, 0], [−I_xz, 0, I_z]] (Stevens & Lewis §1.3,
    /// §2.4), solved here by nalgebra; the moments are computed by hand from the
    /// coefficients at β = 0 (v_a = 0), where the moment is the data's.
    #[test]
    fn rate_equations_are_eulers_equations_with_the_product_of_inertia() {
        let aircraft = SixDofAircraft::default();
        let p = aircraft.longitudinal().parameters();
        let lat = aircraft.lateral();
        let config = aircraft.longitudinal().configuration();
        let (u, w) = (68.0, 8.0);
        let omega = Vector3::new(0.3, -0.1, 0.2);
        let inputs = SixDofInputs {
            elevator_rad: -0.1,
            thrust_n: 30_000.0,
            aileron_rad: 0.05,
            rudder_rad: -0.07,
        };
        let rates = aircraft.body_rates(
            [u, 0.0, w],
            [omega.x, omega.y, omega.z],
            [0.1, 0.05, 0.3],
            &inputs,
            &Wind::default(),
        );
        let speed = f64::hypot(u, w);
        let alpha = (w / u).atan();
        let qs = 0.5 * p.air_density_kg_m3 * speed * speed * p.wing_area_m2;
        let k = lat.span_m / (2.0 * speed);
        let c = lateral_coefficients(
            &crate::aircraft::AerodynamicData::FA18,
            alpha,
            LateralMotion {
                beta: 0.0,
                aileron: 0.05,
                rudder: -0.07,
                p_hat: omega.x * k,
                r_hat: omega.z * k,
            },
        );
        let m = crate::aircraft::aerodynamic_coefficients(
            alpha,
            -0.1,
            omega.y * p.mean_chord_m / (2.0 * speed),
            config,
        );
        let d = config.cg_ahead_of_reference_chords * p.mean_chord_m;
        let moments = Vector3::new(
            qs * lat.span_m * c.roll,
            qs * p.mean_chord_m * m.moment,
            qs * (lat.span_m * c.yaw - d * c.side),
        );
        let ixz = lat.product_of_inertia_xz_kg_m2;
        let inertia = Matrix3::new(
            lat.roll_inertia_kg_m2,
            0.0,
            -ixz,
            0.0,
            p.pitch_inertia_kg_m2,
            0.0,
            -ixz,
            0.0,
            lat.yaw_inertia_kg_m2,
        );
        let expected = inertia
            .lu()
            .solve(&(moments - omega.cross(&(inertia * omega))))
            .expect("J is invertible");
        for i in 0..3 {
            assert!(
                (rates.angular[i] - expected[i]).abs() < 1e-12,
                "{i}: {} vs {}",
                rates.angular[i],
                expected[i]
            );
        }
    }

    /// Wind from the left (W_y > 0) seen by an aircraft on the bearing is relative wind
    /// from the left: β < 0.
    #[test]
    fn crosswind_from_the_left_is_negative_sideslip() {
        let aircraft = SixDofAircraft::default();
        let wind = Wind {
            y_mps: 5.0,
            ..Wind::default()
        };
        let air = aircraft.air_velocity([69.0, 0.0, 8.0], [0.0, 0.12, 0.0], &wind);
        assert!(aircraft.air_data(air).beta_rad < 0.0);
    }
}
