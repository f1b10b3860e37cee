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
//! - [`control`]: the control modes and the agent's taps (its command at each loop
//!   break);
//! - [`reward`]: the outcomes, the rewards and the info's entries at an episode's end;
//! - [`lateral`]: the 3-D environment's lateral half: its commands, observation entries,
//!   spans and trim, each a list (all empty in the 2-D environment);
//! - [`config`]: what every environment of one configuration shares, built from the
//!   Python arguments (`_EnvConfig`, which `_Env` and `_VecEnv` take): the one place
//!   that chooses the 2-D or the 3-D lateral half, and the lists of the action, the
//!   observation and the info made from it, which the modules below map over;
//! - [`observation`]: the observation's entries and their normalisation;
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

pub use config::Config;
pub use single::Env;
pub use vector::VecEnv;
