//! The core of the Gymnasium environments `deckland/CarrierLanding-v1` and (with the
//! lateral half, [`lateral`]) `deckland/CarrierLanding3D-v0`, in Rust: the
//! control modes and the authority each gives the agent ([`Control`], [`AgentTaps`]),
//! the normalised observation ([`OBSERVATIONS`]), the reward and the outcome, for one
//! environment (`_Env`) and for many stepped in one call over threads (`_VecEnv`).
//!
//! One step is one control interval of [`Stepper`]; the agent's commands replace the
//! built-in loops' through [`deckland::simulation::Taps`] and are held over the interval.
//! The automatic wave-off is off in every mode: the wave-off is the agent's action, and
//! the outcome is the physics' (ramp crossing, touchdown, the wires).
//!
//! The modules, each using only those above it:
//! - [`control`]: the control modes and the agent's taps;
//! - [`reward`]: the outcomes and the rewards;
//! - [`config`]: what every environment of one configuration shares, built from the
//!   Python arguments;
//! - [`observation`]: the observation's entries and their normalisation;
//! - [`lateral`]: the 3-D environment's lateral commands, observation entries and taps;
//! - [`action`]: the action read, checked and turned into taps, and the autopilot's;
//! - [`episode`]: one environment's episode, stepped;
//! - [`describe`]: the description of a configuration;
//! - [`parallel`]: work spread over threads, the calling thread taking part;
//! - [`single`] (`_Env`) and [`vector`] (`_VecEnv`): the Python classes.
//!
//! [`Control`]: control::Control
//! [`AgentTaps`]: control::AgentTaps
//! [`OBSERVATIONS`]: observation::OBSERVATIONS
//! [`Stepper`]: crate::stepping::Stepper

mod action;
mod config;
mod control;
mod describe;
mod episode;
mod lateral;
mod observation;
mod parallel;
mod reward;
mod single;
mod spec;
mod vector;

pub use single::Env;
pub use vector::VecEnv;
