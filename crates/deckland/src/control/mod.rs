//! Controllers of the landing cascade (paper §4, MODEL.md §5).

mod loop_controller;

pub use loop_controller::{LoopController, LoopGains};
