//! Flight controllers of the landing cascade (MODEL.md §5; paper §4).
//!
//! Cascade: flight-path generator → guidance → sink-rate controller → [`pitch`]
//! controller → elevator; in parallel the speed controller → thrust.

mod loop_controller;
pub mod pitch;

pub use loop_controller::{LoopController, LoopGains};
