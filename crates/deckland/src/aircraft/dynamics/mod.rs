//! The 3-DOF longitudinal equations of motion over a flat earth (docs/model.md §2.4).
//!
//! Integrated in body axes on inertial velocities (Stevens & Lewis, *Aircraft Control
//! and Simulation*, Eq. 2.5-32 family, with β = 0 and no lateral motion):
//!
//! ```text
//! u̇ = (X_A + T)/m − g sin θ − q w        ẋ = u cos θ + w sin θ
//! ẇ = Z_A/m + g cos θ + q u              ḣ = u sin θ − w cos θ
//! q̇ = M/J_y                              θ̇ = q
//! X_A = L sin α − D cos α,   Z_A = −L cos α − D sin α
//! ```
//!
//! The aerodynamic forces use the air-relative velocity (u − W_xb, w − W_zb), which gives
//! V_T and α. In still air these are exactly the paper's Eq. (1)–(4) with its misprints
//! corrected (the `q` term and the `/V` on gravity in α̇); a test checks that.

use super::actuator::{ElevatorActuator, ElevatorActuatorParameters};
use super::aerodynamic_data::AerodynamicData;
#[cfg(test)]
use super::aerodynamics::aerodynamic_coefficients;
#[cfg(doc)]
use super::aerodynamics::aerodynamic_coefficients_trig;
use super::aerodynamics::{
    angle_of_attack, coefficients_of, fa18_polynomials_at, polynomials_at, AerodynamicCoefficients,
};
use super::configuration::AerodynamicConfiguration;
use super::engine::{EngineParameters, Engines};
use super::parameters::AircraftParameters;
use super::state::AircraftState;
use crate::environment::Wind;
use crate::integration::OdeSystem;
use crate::parameters::ParameterError;

/// Commands to the plant's actuators.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AircraftCommands {
    /// Elevator command to the actuator (rad), positive trailing edge down.
    pub elevator_rad: f64,
    /// Total thrust command of both engines (N), limited to [0, 2·T_max].
    pub thrust_n: f64,
}

/// Inputs acting directly on the airframe, bypassing the actuator and engine dynamics
/// (used by trim and linearisation).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct AirframeInputs {
    /// Elevator deflection (rad).
    pub elevator_rad: f64,
    /// Total thrust (N).
    pub thrust_n: f64,
}

/// Air data computed from the air-relative velocity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AirData {
    /// True airspeed V_T (m/s).
    pub airspeed_mps: f64,
    /// Angle of attack α (rad).
    pub alpha_rad: f64,
    /// Dynamic pressure q̄ = ½ρV_T² (Pa).
    pub dynamic_pressure_pa: f64,
    /// sin α = w_a/V_T (–).
    pub sin_alpha: f64,
    /// cos α = u_a/V_T (–).
    pub cos_alpha: f64,
}

/// The complete longitudinal F/A-18 plant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Aircraft {
    parameters: AircraftParameters,
    aerodynamics: AerodynamicData,
    /// Whether `aerodynamics` are the F/A-18's, which are then evaluated as constants
    /// ([`Aircraft::coefficients_trig`]).
    aerodynamics_are_fa18: bool,
    configuration: AerodynamicConfiguration,
    engines: Engines,
    actuator: ElevatorActuator,
}

impl Default for Aircraft {
    fn default() -> Self {
        Self {
            parameters: AircraftParameters::default(),
            aerodynamics: AerodynamicData::FA18,
            aerodynamics_are_fa18: true,
            configuration: AerodynamicConfiguration::LANDING,
            engines: Engines::default(),
            actuator: ElevatorActuator::default(),
        }
    }
}

/// Rigid-body derivatives (u̇, ẇ, q̇) plus the air data they were computed from.
struct BodyAccelerations {
    u_dot: f64,
    w_dot: f64,
    q_dot: f64,
}

impl Aircraft {
    /// Builds the plant from validated parameters.
    pub fn new(
        parameters: AircraftParameters,
        configuration: AerodynamicConfiguration,
        engines: EngineParameters,
        actuator: ElevatorActuatorParameters,
    ) -> Result<Self, ParameterError> {
        parameters.validate()?;
        configuration.validate()?;
        Ok(Self {
            parameters,
            aerodynamics: AerodynamicData::FA18,
            aerodynamics_are_fa18: true,
            configuration,
            engines: Engines::new(engines)?,
            actuator: ElevatorActuator::new(actuator)?,
        })
    }

    /// This aircraft with another aircraft's aerodynamic data (the F/A-18's by default),
    /// after checking them.
    pub fn with_aerodynamics(self, aerodynamics: AerodynamicData) -> Result<Self, ParameterError> {
        aerodynamics.validate()?;
        Ok(Self {
            aerodynamics,
            aerodynamics_are_fa18: aerodynamics.is_fa18(),
            ..self
        })
    }

    /// The aerodynamic data: the coefficient polynomials and the configurations.
    pub fn aerodynamics(&self) -> &AerodynamicData {
        &self.aerodynamics
    }

    /// The coefficients of this aircraft's data in `configuration` at the angle of
    /// attack α (rad) with its sine and cosine, `(α, sin α, cos α)`, the elevator δe (rad)
    /// and q̂ (–), as [`aerodynamic_coefficients_trig`]; the F/A-18's data are read as
    /// constants and summed over their given terms only, the same to the bit and
    /// cheaper.
    #[inline(always)]
    pub fn coefficients_trig(
        &self,
        (alpha, sin_a, cos_a): (f64, f64, f64),
        elevator: f64,
        q_hat: f64,
        configuration: &AerodynamicConfiguration,
    ) -> AerodynamicCoefficients {
        let data = &self.aerodynamics;
        let polynomials = if self.aerodynamics_are_fa18 {
            fa18_polynomials_at(alpha)
        } else {
            polynomials_at(data, alpha)
        };
        coefficients_of(
            data,
            polynomials,
            (sin_a, cos_a, elevator, q_hat),
            configuration,
        )
    }

    /// The default aircraft in a given aerodynamic configuration.
    pub fn with_configuration(configuration: AerodynamicConfiguration) -> Self {
        Self {
            configuration,
            ..Self::default()
        }
    }

    /// Mass, geometry and atmosphere.
    pub fn parameters(&self) -> &AircraftParameters {
        &self.parameters
    }

    /// Aerodynamic configuration.
    pub fn configuration(&self) -> &AerodynamicConfiguration {
        &self.configuration
    }

    /// Engine model.
    pub fn engines(&self) -> &Engines {
        &self.engines
    }

    /// Elevator actuator model.
    pub fn actuator(&self) -> &ElevatorActuator {
        &self.actuator
    }

    /// Air data (V_T, α, q̄) for inertial body velocities `u`, `w` (m/s), pitch `theta`
    /// (rad) and the wind.
    #[inline]
    pub fn air_data(&self, u: f64, w: f64, theta: f64, wind: &Wind) -> AirData {
        let (sin_t, cos_t) = theta.sin_cos();
        self.air_data_trig(u, w, sin_t, cos_t, wind)
    }

    /// As [`Aircraft::air_data`], with sin θ and cos θ already computed.
    #[inline]
    pub fn air_data_trig(&self, u: f64, w: f64, sin_t: f64, cos_t: f64, wind: &Wind) -> AirData {
        let wind_xb = wind.x_mps * cos_t - wind.z_mps * sin_t;
        let wind_zb = wind.x_mps * sin_t + wind.z_mps * cos_t;
        let ua = u - wind_xb;
        let wa = w - wind_zb;
        let airspeed = (ua * ua + wa * wa).sqrt();
        let (sin_alpha, cos_alpha) = if airspeed > 0.0 {
            (wa / airspeed, ua / airspeed)
        } else {
            (0.0, 1.0)
        };
        AirData {
            airspeed_mps: airspeed,
            alpha_rad: angle_of_attack(ua, wa),
            dynamic_pressure_pa: 0.5 * self.parameters.air_density_kg_m3 * airspeed * airspeed,
            sin_alpha,
            cos_alpha,
        }
    }

    /// Air data of a state.
    #[inline]
    pub fn state_air_data(&self, state: &AircraftState, wind: &Wind) -> AirData {
        self.air_data(state.u_mps, state.w_mps, state.theta_rad, wind)
    }

    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn body_accelerations_from(
        &self,
        u: f64,
        w: f64,
        q: f64,
        sin_t: f64,
        cos_t: f64,
        inputs: &AirframeInputs,
        air: &AirData,
        lift_coefficient_increment: f64,
    ) -> BodyAccelerations {
        let p = &self.parameters;
        let q_hat = q * p.mean_chord_m / (2.0 * air.airspeed_mps);
        let (sin_a, cos_a) = (air.sin_alpha, air.cos_alpha);
        let c = self.coefficients_trig(
            (air.alpha_rad, sin_a, cos_a),
            inputs.elevator_rad,
            q_hat,
            &self.configuration,
        );
        let qs = air.dynamic_pressure_pa * p.wing_area_m2;
        // Direct lift control's increment acts as the wing's own lift does, normal to the
        // air-relative velocity (docs/model.md §5.9).
        let lift = qs * (c.lift + lift_coefficient_increment);
        let drag = qs * c.drag;
        let force_x = lift * sin_a - drag * cos_a + inputs.thrust_n;
        let force_z = -lift * cos_a - drag * sin_a;
        BodyAccelerations {
            u_dot: force_x / p.mass_kg - p.gravity_mps2 * sin_t - q * w,
            w_dot: force_z / p.mass_kg + p.gravity_mps2 * cos_t + q * u,
            q_dot: qs * p.mean_chord_m * c.moment / p.pitch_inertia_kg_m2,
        }
    }

    /// Rigid-body derivatives (u̇, ẇ, q̇) in m/s², m/s², rad/s² for airframe inputs
    /// applied directly (no actuator or engine dynamics).
    #[inline]
    pub fn airframe_accelerations(
        &self,
        u: f64,
        w: f64,
        q: f64,
        theta: f64,
        inputs: &AirframeInputs,
        wind: &Wind,
    ) -> (f64, f64, f64) {
        let (sin_t, cos_t) = theta.sin_cos();
        let air = self.air_data_trig(u, w, sin_t, cos_t, wind);
        let a = self.body_accelerations_from(u, w, q, sin_t, cos_t, inputs, &air, 0.0);
        (a.u_dot, a.w_dot, a.q_dot)
    }

    /// Time derivative of the full plant state for actuator commands and wind.
    #[inline]
    pub fn derivative(
        &self,
        state: &AircraftState,
        commands: &AircraftCommands,
        wind: &Wind,
    ) -> AircraftState {
        let (sin_t, cos_t) = state.theta_rad.sin_cos();
        let air = self.air_data_trig(state.u_mps, state.w_mps, sin_t, cos_t, wind);
        self.derivative_with_direct_lift(state, commands, &air, sin_t, cos_t, 0.0)
    }

    /// As [`Aircraft::derivative`], with the air data (computed with the same wind) and
    /// sin θ, cos θ already at hand (the closed loop needs them for its own signals too),
    /// and a lift-coefficient increment ΔC_L (–) from direct lift control added to the
    /// wing's (docs/model.md §5.9; 0 without it).
    #[inline(always)]
    pub fn derivative_with_direct_lift(
        &self,
        state: &AircraftState,
        commands: &AircraftCommands,
        air: &AirData,
        sin_t: f64,
        cos_t: f64,
        lift_coefficient_increment: f64,
    ) -> AircraftState {
        let inputs = AirframeInputs {
            elevator_rad: state.elevator_rad,
            thrust_n: state.total_thrust_n(),
        };
        let body = self.body_accelerations_from(
            state.u_mps,
            state.w_mps,
            state.q_radps,
            sin_t,
            cos_t,
            &inputs,
            air,
            lift_coefficient_increment,
        );
        let (x_dot, h_dot) = state.earth_velocity_trig(sin_t, cos_t);
        let (elevator_rate, elevator_acceleration) = self.actuator.derivative(
            state.elevator_rad,
            state.elevator_rate_radps,
            commands.elevator_rad,
        );
        AircraftState {
            u_mps: body.u_dot,
            w_mps: body.w_dot,
            q_radps: body.q_dot,
            theta_rad: state.q_radps,
            x_m: x_dot,
            h_m: h_dot,
            engine_thrust_n: [
                self.engines
                    .thrust_rate(state.engine_thrust_n[0], commands.thrust_n),
                self.engines
                    .thrust_rate(state.engine_thrust_n[1], commands.thrust_n),
            ],
            elevator_rad: elevator_rate,
            elevator_rate_radps: elevator_acceleration,
        }
    }

    /// Applies the actuator's position limits after an integration step.
    #[inline]
    pub fn constrain(&self, state: &mut AircraftState) {
        self.actuator
            .constrain(&mut state.elevator_rad, &mut state.elevator_rate_radps);
    }
}

/// The plant flown with fixed commands in a fixed wind: an [`OdeSystem`] for open-loop
/// runs and tests.
#[derive(Debug, Clone, Copy)]
pub struct OpenLoopAircraft {
    /// The plant.
    pub aircraft: Aircraft,
    /// Commands held constant.
    pub commands: AircraftCommands,
    /// Wind held constant.
    pub wind: Wind,
}

impl OdeSystem<{ AircraftState::DIMENSION }> for OpenLoopAircraft {
    fn derivative(
        &self,
        _t: f64,
        x: &[f64; AircraftState::DIMENSION],
    ) -> [f64; AircraftState::DIMENSION] {
        let state = AircraftState::from_array(x);
        self.aircraft
            .derivative(&state, &self.commands, &self.wind)
            .to_array()
    }

    fn constrain(&self, x: &mut [f64; AircraftState::DIMENSION]) {
        let mut state = AircraftState::from_array(x);
        self.aircraft.constrain(&mut state);
        *x = state.to_array();
    }
}

#[cfg(test)]
mod tests;
