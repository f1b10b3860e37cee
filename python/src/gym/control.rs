//! The control modes and the authority each gives the agent.

use deckland::simulation::{LoopBreak, Taps};
use pyo3::prelude::*;

use crate::errors::argument_error;

/// Who flies what: the control mode of the environment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Control {
    /// The agent commands the stabilator, the thrust and direct lift; no built-in loop
    /// reaches a surface or the engines.
    Surfaces,
    /// The agent commands the pitch attitude and the thrust; the built-in pitch law flies
    /// the stabilator.
    Attitude,
    /// The agent commands the climb rate; the sink-rate loop, the pitch law and the
    /// speed loop fly the rest.
    Guidance,
}

/// The modes by name, in the order of the documentation.
const CONTROLS: [(&str, Control); 3] = [
    ("surfaces", Control::Surfaces),
    ("attitude", Control::Attitude),
    ("guidance", Control::Guidance),
];

impl Control {
    pub(super) fn parse(name: &str) -> PyResult<Self> {
        CONTROLS
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, c)| *c)
            .ok_or_else(|| {
                argument_error(
                    "control",
                    format_args!("{name:?}"),
                    "\"surfaces\", \"attitude\" or \"guidance\"",
                )
            })
    }

    /// The action's entries, in order (each in [−1, 1]; the last is the wave-off).
    pub(super) fn action_names(self) -> &'static [&'static str] {
        match self {
            Control::Surfaces => &["elevator", "thrust", "direct_lift", "wave_off"],
            Control::Attitude => &["pitch_command", "thrust", "wave_off"],
            Control::Guidance => &["climb_rate_command", "wave_off"],
        }
    }

    /// The built-in loops whose commands reach the aircraft in this mode.
    pub(super) fn built_in_loops(self) -> &'static [&'static str] {
        match self {
            Control::Surfaces => &[],
            Control::Attitude => &["pitch_law: pitch command -> stabilator command"],
            Control::Guidance => &[
                "sink_rate: climb-rate command -> pitch command",
                "wake_feedforward: pitch fed forward against the carrier's air wake",
                "pitch_law: pitch command -> stabilator command",
                "speed: airspeed -> thrust command (full thrust once the agent waves off)",
            ],
        }
    }
}

/// The agent's commands for one interval, replacing the loops' at their taps: one per
/// loop break, indexed by it (`None`: the built-in loop's command stays).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct AgentTaps {
    commands: [Option<f64>; LoopBreak::ALL.len()],
}

// Every loop break indexes the commands.
const _: () = assert!(LoopBreak::RudderCommand as usize + 1 == LoopBreak::ALL.len());

impl AgentTaps {
    /// Gives the agent's command `value` at `at` for the interval.
    #[inline]
    pub(crate) fn set(&mut self, at: LoopBreak, value: f64) {
        self.commands[at as usize] = Some(value);
    }
}

impl Taps for AgentTaps {
    #[inline]
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        self.commands[at as usize].unwrap_or(computed)
    }

    /// Every point is kept or replaced by a value fixed over the interval.
    #[inline(always)]
    fn idempotent(&self) -> bool {
        true
    }
}
