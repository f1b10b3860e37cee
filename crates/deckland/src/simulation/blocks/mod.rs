//! The blocks of the closed loop and the signal bus they share (docs/model.md §5–6).
//!
//! The loop is an ordered list of blocks, [`BUILT_IN_BLOCKS`]: each declares the
//! registered signals it reads and writes ([`crate::simulation::SIGNALS`]), and its
//! continuous states, which `LoopLayout` lays out in the list's order. At every
//! evaluation the blocks compute their outputs in that order onto the bus (a
//! [`Signals`], every registered signal of one instant), then their state rates. A block
//! only reads what a block before it wrote, or the time, which the loop writes first (a
//! test checks the list), so the order is the signal flow:
//!
//! ```text
//! ship ─► aircraft ─► wind ─►[air mass]─► air_data ─► pitch_sensor ─►[sensors]
//!      ─► wake_feedforward ─► outer_loops ─► pitch_law ─► speed ─► lineup
//!      ─► lateral_laws ─► direct_lift ─►[commands]─► deck_predictor
//! ```
//!
//! A user's own block ([`Block`], a trait object: a disturbance, a sensor filter, a
//! command filter) is inserted at one of the named points in brackets
//! ([`BlockPosition`]), with its own states; see `examples/custom_block.rs`. The built-in
//! blocks are evaluated monomorphically, in the list's order, by
//! `ClosedLoop::evaluate`; without user blocks the bus never leaves registers
//! (no cost over a hand-written loop, BENCHMARKS.md).
//!
//! The discrete parts — the ship's sensing and the deck-motion estimator, the wave-off
//! supervisor, the flight-control computer's frames — run once per step, before the
//! evaluations, in `ClosedLoop::hold`; what they decide reaches the blocks as
//! held inputs (`HeldInputs`) and the run loop as events.

pub(crate) mod arrival_timing;
pub(crate) mod direct_lift;
pub(crate) mod plant;
pub(crate) mod wake_feedforward;

use std::fmt::Debug;
use std::sync::Arc;

use super::layout::Slot;
use super::signals::{SignalId, Signals};
use SignalId::*;

/// One block of the built-in list: its name and the registered signals it reads and
/// writes. Blocks with continuous states declare them when the loop is built (their
/// number depends on the scenario: a PID's one integral, the O-PD's three observer
/// states).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BlockDeclaration {
    /// The block's name (also its name in the state layout).
    pub name: &'static str,
    /// The signals it reads from the bus.
    pub reads: &'static [SignalId],
    /// The signals it writes onto the bus.
    pub writes: &'static [SignalId],
    /// The insertion point for users' blocks right after this block, if any.
    pub followed_by: Option<BlockPosition>,
}

/// The built-in blocks, in the order the loop evaluates them.
pub const BUILT_IN_BLOCKS: [BlockDeclaration; 13] = [
    BlockDeclaration {
        name: "ship",
        reads: &[],
        writes: &[
            ShipX,
            ShipHeave,
            ShipPitch,
            ShipXRate,
            ShipHeaveRate,
            ShipPitchRate,
            AimX,
            AimHeight,
            AimY,
            CentrelineHeading,
            ShipRoll,
            ShipYaw,
            ShipSway,
        ],
        followed_by: None,
    },
    BlockDeclaration {
        name: "aircraft",
        reads: &[
            ShipX,
            AimX,
            ElevatorCommand,
            ThrustCommand,
            DirectLiftCoefficient,
            AileronCommand,
            RudderCommand,
        ],
        writes: &[
            RangeToGo,
            X,
            Altitude,
            HookX,
            HookHeight,
            HookClimbRate,
            HookXRate,
            Theta,
            PitchRate,
            ClimbRate,
            Elevator,
            Thrust,
            DistanceAft,
            Y,
            HookY,
            Bank,
            Heading,
            RollRate,
            YawRate,
            Aileron,
            Rudder,
        ],
        followed_by: None,
    },
    BlockDeclaration {
        name: "wind",
        reads: &[DistanceAft],
        writes: &[WindX, WindZ, WindY],
        followed_by: Some(BlockPosition::AirMass),
    },
    BlockDeclaration {
        name: "air_data",
        reads: &[WindX, WindZ, Theta],
        writes: &[Airspeed, Alpha, Sideslip],
        followed_by: None,
    },
    BlockDeclaration {
        name: "pitch_sensor",
        reads: &[Theta],
        writes: &[ThetaMeasured],
        followed_by: Some(BlockPosition::Sensors),
    },
    BlockDeclaration {
        name: "wake_feedforward",
        reads: &[DistanceAft, ShipXRate, Airspeed],
        writes: &[],
        followed_by: None,
    },
    BlockDeclaration {
        name: "outer_loops",
        reads: &[
            Time,
            ClimbRate,
            Theta,
            Alpha,
            HookX,
            HookHeight,
            HookXRate,
            HookClimbRate,
        ],
        writes: &[
            PathHeight,
            GlidePathError,
            TimeToGo,
            CompensationWeight,
            ThetaRef,
            ClimbRateCommand,
            PathAnchorHeight,
        ],
        followed_by: None,
    },
    BlockDeclaration {
        name: "pitch_law",
        reads: &[ThetaRef, ThetaMeasured, PitchRate, Elevator],
        writes: &[ElevatorCommand, DisturbanceEstimate],
        followed_by: None,
    },
    BlockDeclaration {
        name: "speed",
        reads: &[Airspeed],
        writes: &[ThrustCommand],
        followed_by: None,
    },
    BlockDeclaration {
        name: "lineup",
        reads: &[
            Time,
            HookY,
            AimY,
            CentrelineHeading,
            TimeToGo,
            CompensationWeight,
        ],
        writes: &[
            CrossTrack,
            CrossTrackRate,
            LineupError,
            LateralForecast,
            BankCommand,
        ],
        followed_by: None,
    },
    BlockDeclaration {
        name: "lateral_laws",
        reads: &[
            BankCommand,
            Bank,
            RollRate,
            Sideslip,
            YawRate,
            Aileron,
            Rudder,
        ],
        writes: &[AileronCommand, RudderCommand],
        followed_by: None,
    },
    BlockDeclaration {
        name: "direct_lift",
        reads: &[GlidePathError, HookClimbRate],
        writes: &[DirectLiftCommand, DirectLiftCoefficient],
        followed_by: Some(BlockPosition::Commands),
    },
    BlockDeclaration {
        name: "deck_predictor",
        reads: &[AimHeight],
        writes: &[],
        followed_by: None,
    },
];

/// Where a user's block sits in the list.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BlockPosition {
    /// After the wind at the aircraft is sampled, before the air data are computed in
    /// it: disturbances of the air mass (a gust on `wind.x_mps`, `wind.z_mps`).
    AirMass,
    /// After the pitch sensor, before the laws read it: sensor filters and faults
    /// (`theta_measured_rad`).
    Sensors,
    /// After the laws, before the actuators take their commands: command filters, faults
    /// (`elevator_command_rad`, `thrust_command_n`).
    Commands,
}

impl BlockPosition {
    /// The built-in block this position follows.
    pub fn after(self) -> &'static str {
        BUILT_IN_BLOCKS
            .iter()
            .find(|block| block.followed_by == Some(self))
            .map_or("", |block| block.name)
    }

    /// The signals written by the built-in blocks up to this position.
    pub fn available(self) -> Vec<SignalId> {
        let mut written = vec![Time];
        for block in &BUILT_IN_BLOCKS {
            written.extend_from_slice(block.writes);
            if block.followed_by == Some(self) {
                break;
            }
        }
        written
    }
}

/// A user's own block on the bus: a disturbance, a sensor or command filter, a fault.
/// It reads and writes registered signals ([`Signals::get`], [`Signals::set`]), and may
/// have continuous states, which the loop integrates with its own.
pub trait Block: Debug + Send + Sync {
    /// The block's name (its states are `name.state` in the layout).
    fn name(&self) -> &'static str;

    /// The names of its continuous states (none by default).
    fn state_names(&self) -> &'static [&'static str] {
        &[]
    }

    /// Its state at the start of a run (zero by default).
    fn initial_state(&self, state: &mut [f64]) {
        state.fill(0.0);
    }

    /// The signals it reads: each must be written by a block before it.
    fn reads(&self) -> &'static [SignalId];

    /// The signals it writes.
    fn writes(&self) -> &'static [SignalId];

    /// Reads its inputs from `bus` and writes its outputs onto it, at `time_s` with its
    /// `state`.
    fn outputs(&self, time_s: f64, state: &[f64], bus: &mut Signals);

    /// The rate of its state (written into `rate`, one entry per state; nothing by
    /// default, for a block without states).
    fn derivative(&self, time_s: f64, state: &[f64], bus: &Signals, rate: &mut [f64]) {
        let _ = (time_s, state, bus);
        rate.fill(0.0);
    }
}

/// A user's block in the loop: where it sits and its slot of the state vector.
#[derive(Debug, Clone)]
pub(crate) struct PlacedBlock {
    pub position: BlockPosition,
    pub block: Arc<dyn Block>,
    pub slot: Slot,
}

/// Why a user's block cannot be placed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error(
    "block `{block}` at {position:?} (after `{after}`) reads `{signal}`, which no block \
     before it writes"
)]
pub struct BlockPlacementError {
    /// The user's block.
    pub block: String,
    /// Where it was to sit.
    pub position: BlockPosition,
    /// The built-in block it follows.
    pub after: &'static str,
    /// The signal it reads too early.
    pub signal: &'static str,
}

/// Checks that every signal `block` reads is written before `position`, by the built-in
/// blocks or by the users' blocks placed there before it.
pub(crate) fn check_placement(
    block: &dyn Block,
    position: BlockPosition,
    earlier_users: &[PlacedBlock],
) -> Result<(), BlockPlacementError> {
    let mut available = position.available();
    for placed in earlier_users {
        available.extend_from_slice(placed.block.writes());
    }
    match block.reads().iter().find(|id| !available.contains(id)) {
        None => Ok(()),
        Some(id) => Err(BlockPlacementError {
            block: block.name().to_string(),
            position,
            after: position.after(),
            signal: id.spec().name,
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_built_in_block_reads_only_what_an_earlier_block_wrote() {
        // The aircraft's rates read the commands of this step, written after its
        // outputs: the derivatives are evaluated after every block's outputs.
        let derivative_inputs = [
            ElevatorCommand,
            ThrustCommand,
            DirectLiftCoefficient,
            AileronCommand,
            RudderCommand,
        ];
        let mut written: Vec<SignalId> = vec![Time];
        for block in &BUILT_IN_BLOCKS {
            for read in block.reads {
                assert!(
                    written.contains(read)
                        || (block.name == "aircraft" && derivative_inputs.contains(read)),
                    "`{}` reads `{}` before any block writes it",
                    block.name,
                    read.spec().name
                );
            }
            written.extend_from_slice(block.writes);
        }
        for input in derivative_inputs {
            assert!(written.contains(&input));
        }
    }

    #[test]
    fn every_registered_signal_is_written_by_exactly_one_built_in_block() {
        for spec in crate::simulation::SIGNALS.iter().filter(|s| s.id != Time) {
            let writers: Vec<_> = BUILT_IN_BLOCKS
                .iter()
                .filter(|b| b.writes.contains(&spec.id))
                .map(|b| b.name)
                .collect();
            assert_eq!(
                writers.len(),
                1,
                "`{}` is written by {writers:?}",
                spec.name
            );
        }
    }

    #[derive(Debug)]
    struct ReadsElevatorCommand;
    impl Block for ReadsElevatorCommand {
        fn name(&self) -> &'static str {
            "early"
        }
        fn reads(&self) -> &'static [SignalId] {
            &[ElevatorCommand]
        }
        fn writes(&self) -> &'static [SignalId] {
            &[]
        }
        fn outputs(&self, _: f64, _: &[f64], _: &mut Signals) {}
    }

    #[test]
    fn a_block_reading_a_signal_not_yet_written_is_refused_naming_it() {
        let error = check_placement(&ReadsElevatorCommand, BlockPosition::AirMass, &[])
            .expect_err("the elevator command comes later");
        assert_eq!(error.signal, "elevator_command_rad");
        assert_eq!(error.after, "wind");
        assert!(BlockPosition::AirMass.available().contains(&DistanceAft));
        assert!(!BlockPosition::AirMass.available().contains(&Airspeed));
        assert!(check_placement(&ReadsElevatorCommand, BlockPosition::Commands, &[]).is_ok());
        assert_eq!(BlockPosition::Sensors.after(), "pitch_sensor");
    }
}
