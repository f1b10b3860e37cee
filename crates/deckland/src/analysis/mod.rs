//! Analyses beside the simulation: trim, linearisation, mode identification, loop margins
//! and open-loop step responses of the nonlinear airframe against its linear model.

mod linearize;
mod margins;
mod modes;
mod open_loop;
mod trim;

pub use linearize::{linearize, LinearModel, INPUT_NAMES, INPUT_UNITS, STATE_NAMES, STATE_UNITS};
pub use margins::{cascade_margins, LoopMargins};
pub use modes::{identify_modes, Mode, ModeKind};
pub use open_loop::{open_loop_step_responses, InputStep, OpenLoopError, OpenLoopSample};
pub use trim::{trim, TrimError, TrimPoint, TrimRequest, TrimResiduals};
