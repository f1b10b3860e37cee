//! The 3-D environment's lateral half (`deckland/CarrierLanding3D-v0`): the roll and yaw
//! commands added to each control mode's action, the lateral observation entries, and
//! the lateral taps. The longitudinal half is the 2-D environment's, unchanged.

use deckland::scenario::Scenario as RustScenario;
use deckland::simulation::{LoopBreak, LoopCut, Signals, Simulation};
use pyo3::prelude::*;

use super::control::{AgentTaps, Control};
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

/// The action's entries of the 3-D environment, in order (the 2-D mode's longitudinal
/// entries, the lateral ones, the wave-off last).
pub(crate) fn action_names(control: Control) -> &'static [&'static str] {
    match control {
        Control::Surfaces => &[
            "elevator",
            "thrust",
            "direct_lift",
            "aileron",
            "rudder",
            "wave_off",
        ],
        Control::Attitude => &[
            "pitch_command",
            "thrust",
            "bank_command",
            "sideslip_command",
            "wave_off",
        ],
        Control::Guidance => &["climb_rate_command", "bank_command", "wave_off"],
    }
}

/// The built-in lateral loops whose commands reach the aircraft in each mode.
pub(crate) fn built_in_loops(control: Control) -> &'static [&'static str] {
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

    /// The raw lateral entries of `s` (NaN where a signal is missing).
    pub(crate) fn raw(s: &Signals, raw: &mut [f64]) {
        let value = |v: Option<f64>| v.unwrap_or(f64::NAN);
        let heading = match (s.psi_rad, s.lateral.centreline_heading_rad) {
            (Some(psi), Some(centreline)) => psi - centreline,
            _ => f64::NAN,
        };
        let values = [
            value(s.lateral.cross_track_m),
            value(s.lateral.cross_track_rate_mps),
            value(s.phi_rad),
            heading,
            value(s.beta_rad),
            value(s.p_radps),
            value(s.r_radps),
            value(s.aileron_rad),
            value(s.rudder_rad),
        ];
        raw.copy_from_slice(&values);
    }

    /// Gives `taps` the commands of the lateral action entries `action` (checked, in
    /// [−1, 1]).
    pub(crate) fn set_taps(&self, control: Control, taps: &mut AgentTaps, action: &[f64]) {
        let bank = self.trim_bank_rad + action[0] * self.bank_span_rad;
        match control {
            Control::Surfaces => {
                let aileron = self.trim_aileron_rad + action[0] * self.aileron_span_rad;
                let rudder = self.trim_rudder_rad + action[1] * self.rudder_span_rad;
                taps.set(LoopBreak::AileronCommand, aileron);
                taps.set(LoopBreak::RudderCommand, rudder);
            }
            Control::Attitude => {
                let sideslip = self.trim_sideslip_rad + action[1] * self.sideslip_span_rad;
                taps.set(LoopBreak::BankCommand, bank);
                taps.set(LoopBreak::SideslipCommand, sideslip);
            }
            Control::Guidance => taps.set(LoopBreak::BankCommand, bank),
        }
    }

    /// The lateral entries of the autopilot's action: what the built-in lineup guidance
    /// and laws command now (unclipped).
    pub(crate) fn autopilot(&self, control: Control, s: &Signals) -> [f64; 2] {
        let bank = (s.lateral.bank_command_rad.unwrap_or(self.trim_bank_rad) - self.trim_bank_rad)
            / self.bank_span_rad;
        match control {
            Control::Surfaces => [
                (s.aileron_command_rad.unwrap_or(self.trim_aileron_rad) - self.trim_aileron_rad)
                    / self.aileron_span_rad,
                (s.rudder_command_rad.unwrap_or(self.trim_rudder_rad) - self.trim_rudder_rad)
                    / self.rudder_span_rad,
            ],
            Control::Attitude => [bank, 0.0],
            Control::Guidance => [bank, 0.0],
        }
    }
}
