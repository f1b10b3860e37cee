//! Taps on the cascade: points where a command computed by one loop can be read and
//! replaced before the next loop uses it.
//!
//! The closed loop is generic over its [`Taps`]: a run flies with [`NoTaps`], whose
//! methods are the identity and vanish when inlined, so the hot path carries no analysis
//! code. The stepping API replaces commands with [`Overrides`]; the margin analysis cuts
//! one loop with a [`LoopCut`], which injects a value and records what the loop computed.

use std::cell::Cell;

use super::signals::SignalId;

/// A point where a loop of the cascade can be cut (docs/model.md §5: margins on the
/// linearised cascade) or its command replaced: each is a registered command signal
/// ([`LoopBreak::signal`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopBreak {
    /// The elevator command (rad): the pitch loop.
    ElevatorCommand,
    /// The pitch command θ_ref (rad): the sink-rate loop.
    PitchCommand,
    /// The climb-rate command (m/s): the guidance loop.
    ClimbRateCommand,
    /// The thrust command (N): the speed loop.
    ThrustCommand,
    /// Direct lift control's lift-coefficient command (–): the direct-lift height loop.
    DirectLiftCommand,
    /// The 3-D approach's bank command (rad): the lineup guidance.
    BankCommand,
    /// The 3-D approach's sideslip command (rad, the trim's as computed): the yaw law's
    /// reference. It has no signal of its own: [`LoopBreak::signal`] gives the sideslip
    /// it commands.
    SideslipCommand,
    /// The 3-D approach's aileron command (rad): the roll law.
    AileronCommand,
    /// The 3-D approach's rudder command (rad): the yaw law.
    RudderCommand,
}

impl LoopBreak {
    /// Every tap point, from the outermost loop in (the longitudinal ones, then the 3-D
    /// approach's lateral ones).
    pub const ALL: [LoopBreak; 9] = [
        LoopBreak::ClimbRateCommand,
        LoopBreak::PitchCommand,
        LoopBreak::ElevatorCommand,
        LoopBreak::ThrustCommand,
        LoopBreak::DirectLiftCommand,
        LoopBreak::BankCommand,
        LoopBreak::SideslipCommand,
        LoopBreak::AileronCommand,
        LoopBreak::RudderCommand,
    ];

    /// The command signal at this point (its name and unit are in the registry).
    pub const fn signal(self) -> SignalId {
        match self {
            LoopBreak::ElevatorCommand => SignalId::ElevatorCommand,
            LoopBreak::PitchCommand => SignalId::ThetaRef,
            LoopBreak::ClimbRateCommand => SignalId::ClimbRateCommand,
            LoopBreak::ThrustCommand => SignalId::ThrustCommand,
            LoopBreak::DirectLiftCommand => SignalId::DirectLiftCommand,
            LoopBreak::BankCommand => SignalId::BankCommand,
            LoopBreak::SideslipCommand => SignalId::Sideslip,
            LoopBreak::AileronCommand => SignalId::AileronCommand,
            LoopBreak::RudderCommand => SignalId::RudderCommand,
        }
    }
}

/// What the loop does with the command it computed at each tap point: [`Taps::tap`]
/// returns the value used downstream. The default passes the computed value on.
pub trait Taps {
    /// The command used downstream of `at`, given the one its loop `computed`.
    #[inline(always)]
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        let _ = at;
        computed
    }

    /// Whether tapping a command these taps have already given returns it unchanged, bit
    /// for bit, at every point (`tap(at, tap(at, v)) == tap(at, v)`: a command kept or
    /// replaced by a fixed value), with no side effect (nothing recorded). The run loop
    /// then takes a flight-computer frame's own evaluation, whose commands the step holds,
    /// as the step's (one evaluation instead of two). False unless a type says so.
    #[inline(always)]
    fn idempotent(&self) -> bool {
        false
    }
}

/// No taps: every command is used as computed.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NoTaps;

impl Taps for NoTaps {
    #[inline(always)]
    fn idempotent(&self) -> bool {
        true
    }
}

/// Commands given from outside (the stepping API), each replacing what its loop
/// computed; `None` leaves the loop in charge. A replaced loop keeps running in the
/// background on the aircraft's actual response (its integrator stays within its
/// anti-windup limits), so handing control back is possible.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Overrides {
    /// Pitch command θ_ref (rad), replacing guidance and the sink-rate loop.
    pub pitch_command_rad: Option<f64>,
    /// Elevator command (rad), replacing the pitch law (and everything above it).
    pub elevator_rad: Option<f64>,
    /// Total thrust command (N), replacing the speed loop.
    pub thrust_n: Option<f64>,
    /// 3-D approach: bank command (rad), replacing the lineup guidance.
    pub bank_command_rad: Option<f64>,
    /// 3-D approach: sideslip command (rad), replacing the yaw law's trim sideslip.
    pub sideslip_command_rad: Option<f64>,
    /// 3-D approach: aileron command (rad), replacing the roll law.
    pub aileron_rad: Option<f64>,
    /// 3-D approach: rudder command (rad), replacing the yaw law.
    pub rudder_rad: Option<f64>,
}

impl Taps for Overrides {
    #[inline]
    fn tap(&self, at: LoopBreak, computed: f64) -> f64 {
        let replacement = match at {
            LoopBreak::PitchCommand => self.pitch_command_rad,
            LoopBreak::ElevatorCommand => self.elevator_rad,
            LoopBreak::ThrustCommand => self.thrust_n,
            LoopBreak::BankCommand => self.bank_command_rad,
            LoopBreak::SideslipCommand => self.sideslip_command_rad,
            LoopBreak::AileronCommand => self.aileron_rad,
            LoopBreak::RudderCommand => self.rudder_rad,
            LoopBreak::ClimbRateCommand | LoopBreak::DirectLiftCommand => None,
        };
        replacement.unwrap_or(computed)
    }

    #[inline(always)]
    fn idempotent(&self) -> bool {
        true
    }
}

/// One loop cut for analysis: downstream of `at` the loop uses `injected`, and the value
/// the loop computed there is kept ([`LoopCut::computed`]).
#[derive(Debug, Clone)]
pub struct LoopCut {
    /// Where the loop is cut.
    pub at: LoopBreak,
    /// The value used downstream of the cut.
    pub injected: f64,
    computed: Cell<f64>,
}

impl LoopCut {
    /// A cut at `at` injecting `injected`.
    pub fn new(at: LoopBreak, injected: f64) -> Self {
        Self {
            at,
            injected,
            computed: Cell::new(f64::NAN),
        }
    }

    /// The value the loop computed at the cut in the last evaluation (NaN before any).
    pub fn computed(&self) -> f64 {
        self.computed.get()
    }
}

impl Taps for LoopCut {
    fn tap(&self, here: LoopBreak, computed: f64) -> f64 {
        if self.at == here {
            self.computed.set(computed);
            self.injected
        } else {
            computed
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_injects_at_its_point_only_and_records_the_computed_value() {
        let cut = LoopCut::new(LoopBreak::PitchCommand, 0.5);
        assert_eq!(cut.tap(LoopBreak::ClimbRateCommand, 1.0), 1.0);
        assert_eq!(cut.tap(LoopBreak::PitchCommand, 0.1), 0.5);
        assert_eq!(cut.computed(), 0.1);
        assert_eq!(cut.tap(LoopBreak::ElevatorCommand, -0.2), -0.2);
    }

    #[test]
    fn overrides_replace_only_what_they_set() {
        let overrides = Overrides {
            thrust_n: Some(1000.0),
            ..Overrides::default()
        };
        assert_eq!(overrides.tap(LoopBreak::ThrustCommand, 5.0), 1000.0);
        assert_eq!(overrides.tap(LoopBreak::PitchCommand, 0.1), 0.1);
        assert_eq!(NoTaps.tap(LoopBreak::ElevatorCommand, 0.3), 0.3);
    }

    #[test]
    fn every_tap_point_is_a_registered_command_signal() {
        for point in LoopBreak::ALL {
            let spec = point.signal().spec();
            assert!(
                spec.name.contains("command")
                    || spec.name == "theta_ref_rad"
                    || (point == LoopBreak::SideslipCommand && spec.name == "beta_rad"),
                "{point:?}"
            );
        }
    }
}
