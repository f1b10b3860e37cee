//! The interface of an axis's control law, shared by the pitch laws and, next, the roll
//! and yaw laws (docs/model.md §5): the law owns a continuous state, commands its axis's
//! control surface and describes itself in its linear limit for the design code.
//!
//! What differs between axes is only what a law reads at one instant ([`AxisLaw::Inputs`]:
//! `PitchLawInputs` for the pitch axis) and the plant its linear
//! description is formed for. Everything else — its label, its state's names, its initial
//! state, the surface command, the state's derivative, the disturbance estimate and the
//! [`LinearLaw`] — is the same interface on every axis.

use std::fmt;

/// A control law of one axis: the controlled angle's command → the axis's control-surface
/// command. The O-PD, the PID and a user's own law are peers behind this trait.
///
/// A law owns a continuous state of `state_names().len()` numbers, which the simulation
/// integrates with the plant (RK4, all stages): it calls [`AxisLaw::surface_command_rad`]
/// for the actuator command and [`AxisLaw::derivative`] for the state's rate, both with
/// the same state and inputs. Both must be pure functions of their arguments (no interior
/// mutability), so that a run is reproducible.
pub trait AxisLaw: fmt::Debug + Send + Sync {
    /// The signals the law reads at one instant (the axis's own set).
    type Inputs;

    /// Short label for tables and plots, e.g. `O-PD`.
    fn label(&self) -> &str;

    /// Names of the law's continuous states (their number is the state's dimension).
    fn state_names(&self) -> &'static [&'static str];

    /// The state for a start in trim; the default is all zeros.
    fn initial_state(&self, _inputs: &Self::Inputs, state: &mut [f64]) {
        state.fill(0.0);
    }

    /// The control-surface command (rad; for the pitch axis the elevator δe), not
    /// limited: the actuator applies its limits.
    fn surface_command_rad(&self, state: &[f64], inputs: &Self::Inputs) -> f64;

    /// The time derivative of the state, written into `rate`.
    fn derivative(&self, state: &[f64], inputs: &Self::Inputs, rate: &mut [f64]);

    /// The law's estimate of the disturbance of its axis's angular acceleration
    /// (rad/s²), if it has one.
    fn disturbance_estimate_radps2(&self, _state: &[f64]) -> Option<f64> {
        None
    }

    /// The law in its linear limit ([`LinearLaw`]), for the design code's loop model,
    /// margins and rate-limit check; `None` (the default): the law does not describe
    /// itself and is not assessed.
    fn linear_law(&self) -> Option<LinearLaw> {
        None
    }
}

/// A control law in its linear limit about trim, as a state-space system: the data form
/// in which every law — registered or a user's — describes itself to the design code,
/// which never needs to know which law it is.
///
/// ```text
/// ẋ_c = A_c·x_c + B_c·v,   u = C_c·x_c + D_c·v,   v = [r, y, ω, δ]
/// ```
///
/// with the inputs `v` (indices [`LinearLaw::COMMAND`] … [`LinearLaw::SURFACE`]): the
/// command r (rad), the measured angle y = angle + sensor error (rad), the true angular
/// rate ω (rad/s) and the surface's actual position δ (rad); and the output u, the surface
/// command (rad). All are deviations from trim. A law has at most
/// [`LinearLaw::MAX_STATES`] states; one with fewer fills the rest with decoupled, stable
/// placeholders ([`LinearLaw::without_states`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearLaw {
    /// A_c: how each state's rate depends on the states (row: the state whose rate).
    pub state_matrix: [[f64; LinearLaw::MAX_STATES]; LinearLaw::MAX_STATES],
    /// B_c: how each state's rate depends on the inputs `[r, y, ω, δ]`.
    pub input_matrix: [[f64; LinearLaw::INPUTS]; LinearLaw::MAX_STATES],
    /// C_c: the surface command's dependence on the states.
    pub output_states: [f64; LinearLaw::MAX_STATES],
    /// D_c: the surface command's dependence on the inputs `[r, y, ω, δ]`.
    pub output_inputs: [f64; LinearLaw::INPUTS],
}

impl LinearLaw {
    /// The largest number of states a linear law may have.
    pub const MAX_STATES: usize = 3;
    /// The number of inputs, `[r, y, ω, δ]`.
    pub const INPUTS: usize = 4;
    /// Index of the command r (rad).
    pub const COMMAND: usize = 0;
    /// Index of the measured angle y (rad), which carries the sensor error.
    pub const MEASURED_ANGLE: usize = 1;
    /// Index of the true angular rate ω (rad/s).
    pub const RATE: usize = 2;
    /// Index of the surface's actual position δ (rad).
    pub const SURFACE: usize = 3;

    /// A law with no states of its own: every state a decoupled placeholder ẋ = −x, and
    /// no output. A law fills in its own rows and entries from here.
    pub fn without_states() -> Self {
        let mut state_matrix = [[0.0; Self::MAX_STATES]; Self::MAX_STATES];
        for (k, row) in state_matrix.iter_mut().enumerate() {
            row[k] = -1.0;
        }
        Self {
            state_matrix,
            input_matrix: [[0.0; Self::INPUTS]; Self::MAX_STATES],
            output_states: [0.0; Self::MAX_STATES],
            output_inputs: [0.0; Self::INPUTS],
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug)]
    struct Proportional;

    impl AxisLaw for Proportional {
        type Inputs = (f64, f64);
        fn label(&self) -> &str {
            "P"
        }
        fn state_names(&self) -> &'static [&'static str] {
            &[]
        }
        fn surface_command_rad(&self, _: &[f64], (command, measured): &(f64, f64)) -> f64 {
            2.0 * (command - measured)
        }
        fn derivative(&self, _: &[f64], _: &(f64, f64), _: &mut [f64]) {}
    }

    #[test]
    fn a_law_on_any_axis_gets_the_defaults() {
        let law = Proportional;
        assert_eq!(law.surface_command_rad(&[], &(0.3, 0.1)), 2.0 * (0.3 - 0.1));
        assert_eq!(law.disturbance_estimate_radps2(&[]), None);
        assert_eq!(law.linear_law(), None);
        let mut state = [1.0; 2];
        law.initial_state(&(0.0, 0.0), &mut state);
        assert_eq!(state, [0.0; 2]);
    }

    #[test]
    fn a_law_without_states_has_stable_decoupled_placeholders() {
        let law = LinearLaw::without_states();
        for (i, row) in law.state_matrix.iter().enumerate() {
            for (j, &value) in row.iter().enumerate() {
                assert_eq!(value, if i == j { -1.0 } else { 0.0 }, "({i}, {j})");
            }
        }
        assert_eq!(law.output_inputs, [0.0; LinearLaw::INPUTS]);
    }
}
