//! Analyses beside the simulation: trim, linearisation and mode identification.

mod linearize;
mod margins;
mod modes;
mod trim;

pub use linearize::{linearize, LinearModel, INPUT_NAMES, INPUT_UNITS, STATE_NAMES, STATE_UNITS};
pub use margins::{cascade_margins, LoopMargins};
pub use modes::{identify_modes, Mode, ModeKind};
pub use trim::{trim, TrimError, TrimPoint, TrimRequest, TrimResiduals};
