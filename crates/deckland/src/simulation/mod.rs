//! The closed-loop simulation (MODEL.md §6): [`Simulation`] owns the loop, integrates the
//! [`ClosedLoop`] with RK4 at a fixed step, finds events inside the step, and hands
//! signals and events to a [`crate::recording::Recorder`].

mod closed_loop;
mod outcome;
mod runner;
pub(crate) mod setup;

pub use closed_loop::{
    ClosedLoop, HeldInputs, LoopBreak, LoopMode, LoopState, Signals, LOOP_DIMENSION,
};
pub use outcome::{Event, Outcome, RunSummary, Touchdown};
pub use runner::Simulation;
pub use setup::{approach_flight_path_angle, SimulationError};
