//! Analyses beside the simulation: trim, linearisation, mode identification, loop margins,
//! open-loop step responses of the nonlinear airframe against its linear model, and what
//! the deck's motion leaves unforeseeable (the physics floor and its cost).

mod deck_floor;
mod forecast_study;
mod margins;
mod modes;
mod open_loop;

// Trim and linearisation belong to the aircraft model (the closed loop is built on them);
// they are listed here too, beside the analyses that use them.
pub use crate::aircraft::{
    linearize, trim, LinearModel, TrimError, TrimPoint, TrimRequest, TrimResiduals, INPUT_NAMES,
    INPUT_UNITS, STATE_NAMES, STATE_UNITS,
};
pub use deck_floor::{
    deck_point_floor, deck_point_stationary_sigma, hard_landing_decision_bound,
    ramp_clearance_for_strike_rate, DeckPointFloor, HardLandingBound,
};
pub use forecast_study::{forecast_study, ForecastError, ForecastStudy};
pub use margins::{cascade_margins, LoopMargins};

/// Rate saturation of the elevator: the rate limiter's describing function and the
/// limit cycles it can sustain in a loop (the pitch-law design uses it too).
pub use crate::control::design::rate_limit as rate_saturation;
pub use modes::{identify_modes, Mode, ModeKind};
pub use open_loop::{open_loop_step_responses, InputStep, OpenLoopError, OpenLoopSample};
