//! The closed-loop simulation (docs/model.md §6).
//!
//! - [`ClosedLoop`]: the loop as a composition of blocks (plant, ship motion, wind,
//!   pitch sensor, deck-motion predictor, pitch law, speed loop, outer loops), each with
//!   its own slot of the state vector ([`LoopLayout`]); the held inputs of a step are
//!   passed explicitly ([`HeldInputs`]); commands can be tapped ([`Taps`]).
//! - [`Simulation`]: owns the loop and integrates it with RK4 at a fixed step;
//!   [`Simulation::step`] returns why it stopped ([`Stop`]): still running, an event
//!   found and interpolated inside the step, or the end with its typed reason
//!   ([`EndReason`]). Recorders watch through [`Recorder`].
//! - [`LandingRules`]: turn events into an outcome (docs/model.md §7), outside the
//!   integration loop.

mod activity;
mod alpha_floor;
mod anchor_shaping;
pub mod blocks;
mod closed_loop;
mod commit;
mod deck_limits;
pub mod deck_predictor;
mod events;
mod flight_computer;
mod held;
mod hold;
mod hold_lateral;
pub mod lateral;
mod layout;
mod lso;
mod outcome;
mod outer_loop_signals;
mod outer_loops;
mod pitch_setup;
mod recorder;
mod runner;
mod setup;
mod signals;
mod taps;
mod wave_off;
mod wave_off_flight;

pub use activity::ActuatorActivity;
pub use alpha_floor::AlphaFloor;
pub use blocks::{Block, BlockDeclaration, BlockPlacementError, BlockPosition, BUILT_IN_BLOCKS};
pub use closed_loop::{ClosedLoop, HeldInputs, LoopLayout, StepStreams};
pub use deck_limits::DECK_SAMPLE_INTERVAL_S;
pub use deck_predictor::{BuiltDeckPredictor, DeckPredictor, DeckQuery, DeckView, HookTrack};
pub use events::PROBE_RANGE_AFT_OF_RAMP_M;
pub use flight_computer::HeldCommands;
pub use layout::{BlockStates, Slot, StateLayout};
pub use outcome::{Divergence, EndReason, Event, LandingRules, Outcome, RunSummary, Touchdown};
pub use outer_loops::approach_flight_path_angle;
pub use outer_loops::{LateAbort, OuterLoops, WaveOffFlight};
pub use recorder::{GlidePathStatistics, Recorder};
pub use runner::{Simulation, SimulationBuilder, Stop};
pub use setup::{PitchLawFactory, SetupError};
pub use signals::{
    Conversion, RecordedColumn, SignalId, SignalSpec, Signals, SIGNALS, SIGNAL_COUNT,
    SIGNAL_MAGNITUDE_LIMIT,
};
pub use taps::{LoopBreak, LoopCut, NoTaps, Overrides, Taps};
