//! The 3-D environment's lateral half (`deckland/CarrierLanding3D-v0`): the roll and yaw
//! commands added to each control mode's action, the lateral observation entries, and
//! the lateral taps. The longitudinal half is the 2-D environment's, unchanged.
//! [`LateralHalf`] gathers what the half adds as lists, empty in the 2-D environment, so
//! that the environment's code maps over them without asking which environment it is.

use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{LoopBreak, LoopCut, SignalId, Signals, Simulation};
use pyo3::prelude::*;

use super::control::{AgentTaps, Control};
use super::reward::EndInfo;
use super::spec::ObservationSpec;
use crate::errors::{argument_error, value_error};

const DEG: f64 = std::f64::consts::PI / 180.0;

/// The number of lateral observation entries.
pub(crate) const LATERAL_ENTRIES: usize = 9;

/// The lateral observation entries, appended after the 2-D ones (offsets:
/// [`LateralConfig::offsets`]).
pub(crate) const LATERAL_OBSERVATIONS: [ObservationSpec; LATERAL_ENTRIES] = [
    ObservationSpec { name: "cross_track_m", unit: "m", source: "hook's offset right of the moving landing centreline (signal cross_track_m)", scale: 5.0, low: -200.0, high: 200.0 },
    ObservationSpec { name: "cross_track_rate_mps", unit: "m/s", source: "rate of that offset relative to the deck, right positive (signal cross_track_rate_mps)", scale: 2.0, low: -30.0, high: 30.0 },
    ObservationSpec { name: "bank_rad", unit: "rad", source: "bank angle φ, right wing down positive (signal phi_rad); offset: the trim's", scale: 10.0 * DEG, low: -90.0 * DEG, high: 90.0 * DEG },
    ObservationSpec { name: "heading_to_centreline_rad", unit: "rad", source: "heading relative to the landing centreline, nose right positive (signal psi_rad minus centreline_heading_rad)", scale: 5.0 * DEG, low: -90.0 * DEG, high: 90.0 * DEG },
    ObservationSpec { name: "sideslip_rad", unit: "rad", source: "sideslip β, relative wind from the right positive (signal beta_rad); offset: the trim's", scale: 5.0 * DEG, low: -30.0 * DEG, high: 30.0 * DEG },
    ObservationSpec { name: "roll_rate_radps", unit: "rad/s", source: "roll rate p (signal p_radps)", scale: 10.0 * DEG, low: -3.0, high: 3.0 },
    ObservationSpec { name: "yaw_rate_radps", unit: "rad/s", source: "yaw rate r (signal r_radps)", scale: 5.0 * DEG, low: -3.0, high: 3.0 },
    ObservationSpec { name: "aileron_rad", unit: "rad", source: "aileron position, right wing down positive (signal aileron_rad); offset: the trim's", scale: 10.0 * DEG, low: -45.0 * DEG, high: 45.0 * DEG },
    ObservationSpec { name: "rudder_rad", unit: "rad", source: "rudder position, trailing edge left positive (signal rudder_rad); offset: the trim's", scale: 10.0 * DEG, low: -45.0 * DEG, high: 45.0 * DEG },
];

/// The 3-D environment's lateral configuration: the action spans and the trim.
#[derive(Debug, Clone, Copy)]
pub(crate) struct LateralConfig {
    /// Action spans (rad): bank command, sideslip command, aileron, rudder.
    pub bank_span_rad: f64,
    pub sideslip_span_rad: f64,
    pub aileron_span_rad: f64,
    pub rudder_span_rad: f64,
    /// Trim (rad): bank, sideslip (the yaw law's reference), aileron, rudder.
    pub trim_bank_rad: f64,
    pub trim_sideslip_rad: f64,
    pub trim_aileron_rad: f64,
    pub trim_rudder_rad: f64,
}

/// One lateral command of the 3-D environment's action: the loop break where it replaces
/// the built-in loop's, the signal of that loop's command (the autopilot's action; `None`:
/// the trim, the action 0), its trim and its span (rad).
#[derive(Debug, Clone, Copy)]
pub(crate) struct LateralCommand {
    pub name: &'static str,
    pub at: LoopBreak,
    pub built_in: Option<SignalId>,
    pub trim_rad: f64,
    pub span_rad: f64,
}

impl LateralCommand {
    /// The command of the action entry `action` (in [−1, 1]).
    #[inline]
    fn command(&self, action: f64) -> f64 {
        self.trim_rad + action * self.span_rad
    }

    /// The action entry that commands what the built-in loop computes now (unclipped).
    #[inline]
    fn autopilot(&self, s: &Signals) -> f64 {
        let built_in = self.built_in.and_then(|id| s.get(id));
        (built_in.unwrap_or(self.trim_rad) - self.trim_rad) / self.span_rad
    }
}

/// What the 3-D environment adds to the 2-D one, each part a list of entries: all empty
/// in the 2-D environment (the `Default`), so that the code stepping either maps over
/// them alike.
#[derive(Debug, Clone, Default)]
pub(crate) struct LateralHalf {
    /// The lateral commands of the action, after the longitudinal entries (the wave-off
    /// last).
    pub commands: Vec<LateralCommand>,
    /// The lateral observation entries, after the longitudinal ones, and their offsets.
    pub observations: &'static [ObservationSpec],
    pub offsets: Vec<f64>,
    /// The built-in lateral loops whose commands reach the aircraft.
    pub loops: &'static [&'static str],
    /// The signals whose squares the tracking error adds to the glide path error's.
    pub tracking: &'static [SignalId],
    /// What a step's `info` adds at an episode's end.
    pub end_info: &'static [EndInfo],
    /// The lateral spans and trim, by their keys in the description.
    pub spans: Vec<(&'static str, f64)>,
    pub trim: Vec<(&'static str, f64)>,
}

impl LateralHalf {
    /// The 3-D environment's lateral half in `control` mode, of `lateral`.
    pub(crate) fn new(lateral: &LateralConfig, control: Control) -> Self {
        Self {
            commands: lateral.commands(control),
            observations: &LATERAL_OBSERVATIONS,
            offsets: lateral.offsets().to_vec(),
            loops: built_in_loops(control),
            tracking: &[SignalId::CrossTrack],
            end_info: &[EndInfo::OffCentre],
            spans: vec![
                ("bank_command_span_rad", lateral.bank_span_rad),
                ("sideslip_command_span_rad", lateral.sideslip_span_rad),
                ("aileron_span_rad", lateral.aileron_span_rad),
                ("rudder_span_rad", lateral.rudder_span_rad),
            ],
            trim: vec![
                ("bank_rad", lateral.trim_bank_rad),
                ("sideslip_rad", lateral.trim_sideslip_rad),
                ("aileron_rad", lateral.trim_aileron_rad),
                ("rudder_rad", lateral.trim_rudder_rad),
            ],
        }
    }

    /// Each lateral observation entry's (offset, scale, raw range), in order.
    pub(crate) fn scaling(&self) -> impl Iterator<Item = (f64, f64, (f64, f64))> + '_ {
        let entries = self.observations.iter().zip(&self.offsets);
        entries.map(|(o, &offset)| (offset, o.scale, (o.low, o.high)))
    }

    /// Gives `taps` the commands of the lateral action entries `action` (checked, in
    /// [−1, 1]; the entries after the commands' are ignored).
    #[inline]
    pub(crate) fn set_taps(&self, taps: &mut AgentTaps, action: &[f64]) {
        for (command, &a) in self.commands.iter().zip(action) {
            taps.set(command.at, command.command(a));
        }
    }

    /// The lateral entries of the autopilot's action, written to `action` through
    /// `clipped` (the entries after the commands' are left).
    #[inline]
    pub(crate) fn autopilot(&self, s: &Signals, action: &mut [f32], clipped: impl Fn(f64) -> f32) {
        for (out, command) in action.iter_mut().zip(&self.commands) {
            *out = clipped(command.autopilot(s));
        }
    }

    /// The raw lateral entries of `s` (NaN where a signal is missing) written to `raw`
    /// (as many as it holds: none in the 2-D environment).
    #[inline]
    pub(crate) fn raw(s: &Signals, raw: &mut [f64]) {
        let value = |v: Option<f64>| v.unwrap_or(f64::NAN);
        let values = [
            value(s.lateral.cross_track_m),
            value(s.lateral.cross_track_rate_mps),
            value(s.phi_rad),
            value(s.psi_rad) - value(s.lateral.centreline_heading_rad),
            value(s.beta_rad),
            value(s.p_radps),
            value(s.r_radps),
            value(s.aileron_rad),
            value(s.rudder_rad),
        ];
        for (out, value) in raw.iter_mut().zip(values) {
            *out = value;
        }
    }
}

/// The built-in lateral loops whose commands reach the aircraft in each mode.
fn built_in_loops(control: Control) -> &'static [&'static str] {
    match control {
        Control::Surfaces => &[],
        Control::Attitude => &[
            "roll_law: bank command -> aileron command",
            "yaw_law: sideslip command -> rudder command",
        ],
        Control::Guidance => &[
            "roll_law: bank command -> aileron command",
            "yaw_law: the trim's sideslip -> rudder command (coordinated flight)",
        ],
    }
}

impl LateralConfig {
    /// The configuration of the 3-D environment flying `flown` (a 3-D approach), with
    /// `spans` (bank command, sideslip command, aileron, rudder; rad) checked.
    pub(crate) fn new(flown: &RustScenario, spans: (f64, f64, f64, f64)) -> PyResult<Self> {
        let (bank, sideslip, aileron, rudder) = spans;
        for (name, value, most) in [
            ("bank_command_span_rad", bank, 60.0 * DEG),
            ("sideslip_command_span_rad", sideslip, 20.0 * DEG),
            ("aileron_span_rad", aileron, 45.0 * DEG),
            ("rudder_span_rad", rudder, 45.0 * DEG),
        ] {
            if !(value.is_finite() && value > 0.0 && value <= most) {
                return Err(argument_error(
                    name,
                    format_args!("{value:?}"),
                    format_args!("a positive number of radians, at most {most:?}"),
                ));
            }
        }
        let mut simulation = Simulation::new(flown)
            .map_err(|error| value_error(format!("cannot set up the approach: {error}")))?;
        let start = simulation.signals();
        let (Some(bank_rad), Some(aileron_rad), Some(rudder_rad), Some(_)) = (
            start.phi_rad,
            start.aileron_rad,
            start.rudder_rad,
            start.lateral.cross_track_m,
        ) else {
            return Err(value_error(
                "`scenario` is not a 3-D approach: the 3-D environment needs \
                 aircraft.model = \"6dof\" with approach.three_dimensional = true",
            ));
        };
        // The yaw law's reference sideslip, read at its tap.
        let held = simulation.next_step_inputs();
        let cut = LoopCut::new(LoopBreak::SideslipCommand, 0.0);
        let mut rate = vec![0.0; simulation.state().len()];
        simulation.system().evaluate(
            simulation.time_s(),
            simulation.state(),
            &held,
            &cut,
            &mut rate,
        );
        Ok(Self {
            bank_span_rad: bank,
            sideslip_span_rad: sideslip,
            aileron_span_rad: aileron,
            rudder_span_rad: rudder,
            trim_bank_rad: bank_rad,
            trim_sideslip_rad: cut.computed(),
            trim_aileron_rad: aileron_rad,
            trim_rudder_rad: rudder_rad,
        })
    }

    /// The offset of each lateral entry (raw units).
    pub(crate) fn offsets(&self) -> [f64; LATERAL_ENTRIES] {
        let mut offsets = [0.0; LATERAL_ENTRIES];
        offsets[2] = self.trim_bank_rad;
        offsets[4] = self.trim_sideslip_rad;
        offsets[7] = self.trim_aileron_rad;
        offsets[8] = self.trim_rudder_rad;
        offsets
    }

    /// The lateral commands of `control`'s action, in order: the surfaces' aileron and
    /// rudder, the attitude's bank and sideslip commands, the guidance's bank command.
    fn commands(&self, control: Control) -> Vec<LateralCommand> {
        let bank = LateralCommand {
            name: "bank_command",
            at: LoopBreak::BankCommand,
            built_in: Some(SignalId::BankCommand),
            trim_rad: self.trim_bank_rad,
            span_rad: self.bank_span_rad,
        };
        let sideslip = LateralCommand {
            name: "sideslip_command",
            at: LoopBreak::SideslipCommand,
            // The yaw law's reference is the trim's: the autopilot's action is 0.
            built_in: None,
            trim_rad: self.trim_sideslip_rad,
            span_rad: self.sideslip_span_rad,
        };
        let aileron = LateralCommand {
            name: "aileron",
            at: LoopBreak::AileronCommand,
            built_in: Some(SignalId::AileronCommand),
            trim_rad: self.trim_aileron_rad,
            span_rad: self.aileron_span_rad,
        };
        let rudder = LateralCommand {
            name: "rudder",
            at: LoopBreak::RudderCommand,
            built_in: Some(SignalId::RudderCommand),
            trim_rad: self.trim_rudder_rad,
            span_rad: self.rudder_span_rad,
        };
        match control {
            Control::Surfaces => vec![aileron, rudder],
            Control::Attitude => vec![bank, sideslip],
            Control::Guidance => vec![bank],
        }
    }
}
