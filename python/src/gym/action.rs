//! The agent's action: read, checked, turned into the taps, and the autopilot's.

use deckland::simulation::{LoopBreak, Signals};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyComplex};

use super::config::EnvConfig;
use super::control::{AgentTaps, Control};
use crate::errors::argument_error;

impl EnvConfig {
    pub(super) fn action_len(&self) -> usize {
        self.action_names.len()
    }

    /// The number of the longitudinal entries of the action, first (the lateral commands
    /// follow them, the wave-off last).
    fn longitudinal_actions(&self) -> usize {
        self.control.action_names().len() - 1
    }

    /// The taps of `action` (checked: every entry in [−1, 1]).
    pub(super) fn taps(&self, action: &[f64], waved_off: bool) -> AgentTaps {
        let mut taps = AgentTaps::default();
        let thrust =
            |a: f64| (self.thrust_trim_n + a * self.thrust_span_n).clamp(0.0, self.max_thrust_n);
        let (low, high) = self.elevator_range_rad;
        match self.control {
            Control::Surfaces => {
                let elevator = self.elevator_trim_rad + action[0] * self.elevator_span_rad;
                taps.set(LoopBreak::ElevatorCommand, elevator.clamp(low, high));
                taps.set(LoopBreak::ThrustCommand, thrust(action[1]));
                let direct_lift = action[2] * self.max_direct_lift;
                taps.set(LoopBreak::DirectLiftCommand, direct_lift);
            }
            Control::Attitude => {
                let pitch = self.theta_trim_rad + action[0] * self.pitch_span_rad;
                taps.set(LoopBreak::PitchCommand, pitch);
                taps.set(LoopBreak::ThrustCommand, thrust(action[1]));
                taps.set(LoopBreak::DirectLiftCommand, 0.0);
            }
            Control::Guidance => {
                let climb_rate = self.climb_rate_trim_mps + action[0] * self.climb_rate_span_mps;
                taps.set(LoopBreak::ClimbRateCommand, climb_rate);
                if waved_off {
                    taps.set(LoopBreak::ThrustCommand, self.max_thrust_n);
                }
                taps.set(LoopBreak::DirectLiftCommand, 0.0);
            }
        }
        let lateral_actions = &action[self.longitudinal_actions()..];
        self.lateral.set_taps(&mut taps, lateral_actions);
        taps
    }

    /// The action that commands what the built-in loops compute now (the autopilot as a
    /// policy; it never waves off), clipped to the action space.
    pub(super) fn autopilot_action(&self, s: &Signals, action: &mut [f32]) {
        let values: [f64; 3] = match self.control {
            Control::Surfaces => [
                (s.elevator_command_rad - self.elevator_trim_rad) / self.elevator_span_rad,
                (s.thrust_command_n - self.thrust_trim_n) / self.thrust_span_n,
                if self.max_direct_lift > 0.0 {
                    s.direct_lift_command.unwrap_or(0.0) / self.max_direct_lift
                } else {
                    0.0
                },
            ],
            Control::Attitude => [
                (s.theta_ref_rad - self.theta_trim_rad) / self.pitch_span_rad,
                (s.thrust_command_n - self.thrust_trim_n) / self.thrust_span_n,
                0.0,
            ],
            Control::Guidance => [
                (s.climb_rate_command_mps.unwrap_or(self.climb_rate_trim_mps)
                    - self.climb_rate_trim_mps)
                    / self.climb_rate_span_mps,
                0.0,
                0.0,
            ],
        };
        let clipped = |value: f64| {
            let value = if value.is_nan() { 0.0 } else { value };
            value.clamp(-1.0, 1.0) as f32
        };
        let (commands, wave_off) = action.split_at_mut(action.len() - 1);
        let (longitudinal, lateral) = commands.split_at_mut(self.longitudinal_actions());
        for (out, value) in longitudinal.iter_mut().zip(values) {
            *out = clipped(value);
        }
        self.lateral.autopilot(s, lateral, clipped);
        wave_off[0] = -1.0;
    }

    /// Whether `action` is `len` finite numbers in [−1, 1].
    pub(super) fn action_allowed(&self, action: &[f64]) -> bool {
        action.len() == self.action_len() && action.iter().all(|a| (-1.0..=1.0).contains(a))
    }

    /// `action` checked: `len` finite numbers in [−1, 1], else `ValueError` naming it.
    pub(super) fn check_action(&self, action: &[f64], which: &str) -> PyResult<()> {
        let len = self.action_len();
        if self.action_allowed(action) {
            return Ok(());
        }
        Err(argument_error(
            which,
            format_args!("{action:?}"),
            format_args!(
                "{len} numbers in [-1, 1] (the action space: {})",
                self.action_names.join(", ")
            ),
        ))
    }
}

/// Reads an action (a 1-d array of float32 or float64, or a sequence of numbers).
pub(super) fn action_values(action: &Bound<'_, PyAny>) -> PyResult<Vec<f64>> {
    if let Ok(a) = action.cast::<PyArray1<f32>>() {
        if let Ok(values) = a.to_vec() {
            return Ok(values.into_iter().map(f64::from).collect());
        }
    }
    if let Ok(a) = action.cast::<PyArray1<f64>>() {
        if let Ok(values) = a.to_vec() {
            return Ok(values);
        }
    }
    let refused = || {
        argument_error(
            "action",
            action
                .repr()
                .map_or_else(|_| "?".to_owned(), |r| r.to_string()),
            "an array of real numbers in [-1, 1] (floats or ints: not complex, bool or text)",
        )
    };
    // Anything else converts entry by entry: refuse what only a lossy conversion makes a
    // number (a complex loses its imaginary part, a bool becomes 0 or 1; issue 45, R9).
    if !is_real_number_kind(action)? {
        return Err(refused());
    }
    let mut values = Vec::new();
    for item in action.try_iter().map_err(|_| refused())? {
        let item = item?;
        if item.is_instance_of::<PyBool>()
            || item.is_instance_of::<PyComplex>()
            || !is_real_number_kind(&item)?
        {
            return Err(refused());
        }
        values.push(item.extract::<f64>().map_err(|_| refused())?);
    }
    Ok(values)
}

/// Whether `value`'s numpy dtype, if it has one, holds real numbers (float, int or
/// unsigned int); an object without a dtype is left to the caller.
fn is_real_number_kind(value: &Bound<'_, PyAny>) -> PyResult<bool> {
    let Ok(dtype) = value.getattr("dtype") else {
        return Ok(true);
    };
    let kind: String = dtype.getattr("kind")?.extract()?;
    Ok(matches!(kind.as_str(), "f" | "i" | "u"))
}
