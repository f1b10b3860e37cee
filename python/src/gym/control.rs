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

/// The agent's commands for one interval, replacing the loops' at their taps.
#[derive(Debug, Clone, Copy)]
pub(crate) struct AgentTaps {
    pub(super) control: Control,
    /// Surfaces: elevator (rad); attitude: pitch command (rad); guidance: climb-rate
    /// command (m/s).
    pub(super) first: f64,
    /// Surfaces and attitude: total thrust command (N).
    pub(super) thrust_n: f64,
    /// Surfaces: direct lift's lift-coefficient command (–).
    pub(super) direct_lift: f64,
    /// Guidance: the agent has waved off (full thrust).
    pub(super) full_thrust_n: Option<f64>,
    /// The 3-D environment's lateral commands (none in the 2-D environment).
    pub(super) lateral: LateralTaps,
}

impl Taps for AgentTaps {
    #[inline]
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        use Control::{Attitude, Guidance, Surfaces};
        match (self.control, at) {
            (Surfaces, LoopBreak::ElevatorCommand) | (Attitude, LoopBreak::PitchCommand) => {
                self.first
            }
            (Guidance, LoopBreak::ClimbRateCommand) => self.first,
            (Surfaces | Attitude, LoopBreak::ThrustCommand) => self.thrust_n,
            (Guidance, LoopBreak::ThrustCommand) => self.full_thrust_n.unwrap_or(computed),
            (Surfaces, LoopBreak::DirectLiftCommand) => self.direct_lift,
            (Attitude | Guidance, LoopBreak::DirectLiftCommand) => 0.0,
            (
                _,
                LoopBreak::BankCommand
                | LoopBreak::SideslipCommand
                | LoopBreak::AileronCommand
                | LoopBreak::RudderCommand,
            ) => self.lateral.at(at).unwrap_or(computed),
            _ => computed,
        }
    }

    /// Every point is kept or replaced by a value fixed over the interval.
    #[inline(always)]
    fn idempotent(&self) -> bool {
        true
    }
}

/// The agent's lateral commands for one interval (`None`: the built-in loop's).
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct LateralTaps {
    pub bank_command_rad: Option<f64>,
    pub sideslip_command_rad: Option<f64>,
    pub aileron_rad: Option<f64>,
    pub rudder_rad: Option<f64>,
}

impl LateralTaps {
    /// The agent's command at `at`, if it gives one there.
    #[inline]
    pub(crate) fn at(&self, at: LoopBreak) -> Option<f64> {
        match at {
            LoopBreak::BankCommand => self.bank_command_rad,
            LoopBreak::SideslipCommand => self.sideslip_command_rad,
            LoopBreak::AileronCommand => self.aileron_rad,
            LoopBreak::RudderCommand => self.rudder_rad,
            _ => None,
        }
    }
}
